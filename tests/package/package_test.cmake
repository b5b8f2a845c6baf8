# The package test (tests/CMakeLists.txt): installs the build into a fresh
# prefix, configures tests/package/consumer against it with find_package
# (same generator and compiler as the build), builds it and runs it. Any step
# that fails fails the test. Everything goes under WORK_DIR, emptied first,
# so a rerun (or an interrupted run) starts from nothing.
#   cmake -DBUILD_DIR=... -DCONSUMER_DIR=... -DWORK_DIR=... -DGENERATOR=...
#         [-DGENERATOR_PLATFORM=...] [-DMAKE_PROGRAM=...] -DCXX_COMPILER=...
#         [-DTOOLCHAIN_FILE=...] [-DCONFIG=...] -P package_test.cmake
foreach(var BUILD_DIR CONSUMER_DIR WORK_DIR GENERATOR CXX_COMPILER)
  if(NOT ${var})
    message(FATAL_ERROR "package_test.cmake: -D${var}= is required")
  endif()
endforeach()
if(NOT CONFIG)
  set(CONFIG Release)
endif()
set(prefix ${WORK_DIR}/prefix)
set(consumer_build ${WORK_DIR}/consumer)

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "package test: ${what} failed (${result})")
  endif()
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
run_step("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} --config ${CONFIG})

set(generator_args -G ${GENERATOR})
if(GENERATOR_PLATFORM)
  list(APPEND generator_args -A ${GENERATOR_PLATFORM})
endif()
if(MAKE_PROGRAM)
  list(APPEND generator_args -DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM})
endif()
if(TOOLCHAIN_FILE)  # vcpkg's, on Windows: the consumer finds the same dependencies
  list(APPEND generator_args -DCMAKE_TOOLCHAIN_FILE=${TOOLCHAIN_FILE})
endif()
# No package registry: the consumer must find the package in the prefix.
run_step("configuring the consumer"
  ${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${consumer_build} ${generator_args}
  -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_BUILD_TYPE=${CONFIG} -DCMAKE_PREFIX_PATH=${prefix}
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
file(STRINGS ${consumer_build}/CMakeCache.txt penumbra_dir REGEX "^Penumbra_DIR:")
string(FIND "${penumbra_dir}" "${prefix}/" at)
if(NOT at GREATER -1)
  message(FATAL_ERROR "package test: the consumer found Penumbra outside ${prefix} (${penumbra_dir})")
endif()
run_step("building the consumer" ${CMAKE_COMMAND} --build ${consumer_build} --config ${CONFIG})

# Single- and multi-config generators put the executable in different places.
find_program(consumer penumbra_consumer PATHS ${consumer_build} ${consumer_build}/${CONFIG} NO_DEFAULT_PATH
             NO_CACHE)
if(NOT consumer)
  message(FATAL_ERROR "package test: no penumbra_consumer in ${consumer_build}")
endif()
run_step("running the consumer" ${consumer})
