# Tests that the installed package works for outside projects: each installs
# genbsp into its own temporary prefix, then builds and runs a project against
# it with tests/install_test.cmake.
# Included from tests/CMakeLists.txt.
function(genbsp_install_test name check)
  add_test(NAME ${name}
           COMMAND ${CMAKE_COMMAND}
                   "-DSOURCE_DIR=${PROJECT_SOURCE_DIR}"
                   "-DBINARY_DIR=${PROJECT_BINARY_DIR}"
                   "-DCHECK=${check}"
                   "-DGENERATOR=${CMAKE_GENERATOR}"
                   "-DCXX_COMPILER=${CMAKE_CXX_COMPILER}"
                   "-DCONFIG=$<CONFIG>"
                   -P "${CMAKE_CURRENT_LIST_DIR}/install_test.cmake")
endfunction()

# tests/consumer: one small program.
genbsp_install_test(install_and_consume consumer)
# tests/consumer_bsp: the generic tree alone, without Boost or GMP.
genbsp_install_test(install_and_consume_bsp bsp)
# examples/: every example, each checking its own result.
genbsp_install_test(examples_against_install examples)
