# Test that the installed package works for an outside project: install into a
# temporary prefix, then build and run tests/consumer against it.
# Included from tests/CMakeLists.txt.
add_test(NAME install_and_consume
         COMMAND ${CMAKE_COMMAND}
                 "-DSOURCE_DIR=${PROJECT_SOURCE_DIR}"
                 "-DBINARY_DIR=${PROJECT_BINARY_DIR}"
                 "-DGENERATOR=${CMAKE_GENERATOR}"
                 "-DCXX_COMPILER=${CMAKE_CXX_COMPILER}"
                 "-DCONFIG=$<CONFIG>"
                 -P "${CMAKE_CURRENT_LIST_DIR}/install_test.cmake")
