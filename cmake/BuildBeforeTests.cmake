# Script mode, run by ctest before any test (CTEST_CUSTOM_PRE_TEST of the build's CTestCustom.cmake):
# builds what is out of date, the test programs among them, so that README's test command builds
# the tests it runs while scripts/setup.sh builds only the aerobreak program (what README's main
# command runs). AEROBREAK_TEST_NO_BUILD=1 skips it, for a developer who has built the test programs
# they run. Called with -DBUILD_DIR=<the build folder>.
if(NOT "$ENV{AEROBREAK_TEST_NO_BUILD}" STREQUAL "" AND NOT "$ENV{AEROBREAK_TEST_NO_BUILD}" STREQUAL "0")
  return()
endif()
cmake_host_system_information(RESULT cores QUERY NUMBER_OF_LOGICAL_CORES)
message(STATUS "ctest: building what is out of date in ${BUILD_DIR}, the tests among them (${cores} jobs; "
               "AEROBREAK_TEST_NO_BUILD=1 skips this)")
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${BUILD_DIR}" --parallel ${cores} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "ctest: the build failed, so no test is run")
endif()
