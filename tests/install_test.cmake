# Installs genbsp from an existing build tree into a temporary prefix, then
# configures and builds an outside project against that prefix and runs it:
#
#   CHECK=consumer (the default): tests/consumer, one small program;
#   CHECK=bsp: tests/consumer_bsp, the generic tree alone (genbsp::bsp), with
#              Boost and PkgConfig made unfindable;
#   CHECK=examples: examples/, every example program, each checking its own
#                   result (any non-zero exit status fails the test).
#
#   cmake -DSOURCE_DIR=<genbsp source> -DBINARY_DIR=<genbsp build>
#         [-DCHECK=consumer|examples] [-DGENERATOR=<generator>]
#         [-DCXX_COMPILER=<compiler>] [-DCONFIG=<build type>]
#         -P tests/install_test.cmake
#
# The builds use the build tool's default parallelism; set the environment
# variable CMAKE_BUILD_PARALLEL_LEVEL to limit it.
cmake_minimum_required(VERSION 3.25)

foreach(var SOURCE_DIR BINARY_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "install_test.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT DEFINED CHECK OR CHECK STREQUAL "")
  set(CHECK consumer)
endif()
if(CHECK STREQUAL "consumer")
  set(project_dir ${SOURCE_DIR}/tests/consumer)
elseif(CHECK STREQUAL "bsp")
  set(project_dir ${SOURCE_DIR}/tests/consumer_bsp)
elseif(CHECK STREQUAL "examples")
  set(project_dir ${SOURCE_DIR}/examples)
else()
  message(FATAL_ERROR "install_test.cmake: -DCHECK=${CHECK}: expected consumer, bsp or examples")
endif()

# One work folder per check, so that both can run at once (ctest -j).
set(work ${BINARY_DIR}/install_test/${CHECK})
set(prefix ${work}/prefix)
set(project_build ${work}/build)
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
# outside project is built in the same one.
set(install_args)
if(DEFINED CONFIG AND NOT CONFIG STREQUAL "")
  list(APPEND install_args --config ${CONFIG})
else()
  set(CONFIG Release)
endif()

if(CHECK STREQUAL "bsp")
  # Any hidden dependency of genbsp::bsp on Boost or GMP fails here.
  list(APPEND configure_args -DCMAKE_DISABLE_FIND_PACKAGE_Boost=ON -DCMAKE_DISABLE_FIND_PACKAGE_PkgConfig=ON
       -DGENBSP_TESTS_DIR=${SOURCE_DIR}/tests)
endif()

run(install ${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${prefix} ${install_args})
run("configure ${CHECK}" ${CMAKE_COMMAND} -S ${project_dir} -B ${project_build} ${configure_args}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${CONFIG})
run("build ${CHECK}" ${CMAKE_COMMAND} --build ${project_build} --config ${CONFIG})

# The programs to run: the consumer, or one per examples/*.cpp (named after it).
if(CHECK STREQUAL "consumer")
  set(programs consumer)
elseif(CHECK STREQUAL "bsp")
  set(programs consumer_bsp)
else()
  file(GLOB sources RELATIVE ${project_dir} ${project_dir}/*.cpp)
  list(TRANSFORM sources REPLACE "\\.cpp$" "")
  list(SORT sources)
  set(programs ${sources})
  if(NOT programs)
    message(FATAL_ERROR "install_test: no examples in ${project_dir}")
  endif()
endif()
foreach(program IN LISTS programs)
  find_program(exe_${program} ${program} PATHS ${project_build} PATH_SUFFIXES ${CONFIG} NO_DEFAULT_PATH
               NO_CACHE REQUIRED)
  run("run ${program}" ${exe_${program}})
endforeach()

file(REMOVE_RECURSE ${work})
