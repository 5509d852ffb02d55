# Installs the package into a scratch prefix, then configures, builds and runs a
# tiny project that only knows find_package(Intrinsic_reflectional_symmetry_3).
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
foreach(step
    "configure;${CMAKE_COMMAND};-S;${SOURCE_DIR};-B;${WORK_DIR}/pkg;-G;${GENERATOR};-DIRS_BUILD_TESTS=OFF;-DIRS_BUILD_EXAMPLES=OFF;-DIRS_BUILD_BENCHMARKS=OFF;-DIRS_BUILD_CLI=OFF;-DCMAKE_INSTALL_PREFIX=${prefix}"
    "install;${CMAKE_COMMAND};--install;${WORK_DIR}/pkg"
    "consumer-configure;${CMAKE_COMMAND};-S;${SOURCE_DIR}/test/Intrinsic_reflectional_symmetry_3/downstream;-B;${WORK_DIR}/consumer;-G;${GENERATOR};-DCMAKE_PREFIX_PATH=${prefix};-DCMAKE_BUILD_TYPE=Release"
    "consumer-build;${CMAKE_COMMAND};--build;${WORK_DIR}/consumer"
    "consumer-run;${WORK_DIR}/consumer/downstream_consumer")
  list(POP_FRONT step name)
  execute_process(COMMAND ${step} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "downstream step '${name}' failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "downstream step '${name}' ok")
endforeach()
