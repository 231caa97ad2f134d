# Installs genbsp from an existing build tree into a temporary prefix, then
# configures, builds and runs tests/consumer against that prefix.
#
#   cmake -DSOURCE_DIR=<genbsp source> -DBINARY_DIR=<genbsp build>
#         [-DGENERATOR=<generator>] [-DCXX_COMPILER=<compiler>] [-DCONFIG=<build type>]
#         -P tests/install_test.cmake
cmake_minimum_required(VERSION 3.25)

foreach(var SOURCE_DIR BINARY_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "install_test.cmake: -D${var}=... is required")
  endif()
endforeach()

set(work ${BINARY_DIR}/install_test)
set(prefix ${work}/prefix)
set(consumer_build ${work}/consumer)
file(REMOVE_RECURSE ${work})
file(MAKE_DIRECTORY ${work})

# run(STEP COMMAND...): runs COMMAND, stops with its output if it fails.
function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "install_test: ${step} failed (${result}):\n${out}")
  endif()
  message(STATUS "install_test: ${step}: ok")
endfunction()

set(configure_args)
if(DEFINED GENERATOR AND NOT GENERATOR STREQUAL "")
  list(APPEND configure_args -G ${GENERATOR})
endif()
if(DEFINED CXX_COMPILER AND NOT CXX_COMPILER STREQUAL "")
  list(APPEND configure_args -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
endif()

# CONFIG is the configuration of the genbsp build (what $<CONFIG> gives); the
# consumer is built in the same one.
set(install_args)
if(DEFINED CONFIG AND NOT CONFIG STREQUAL "")
  list(APPEND install_args --config ${CONFIG})
else()
  set(CONFIG Release)
endif()

run(install ${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${prefix} ${install_args})
run(configure ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer -B ${consumer_build} ${configure_args}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${CONFIG})
run(build ${CMAKE_COMMAND} --build ${consumer_build} --config ${CONFIG})

find_program(consumer_exe consumer PATHS ${consumer_build} PATH_SUFFIXES ${CONFIG} NO_DEFAULT_PATH
             NO_CACHE REQUIRED)
run(run ${consumer_exe})

file(REMOVE_RECURSE ${work})
