# cmake -DBUILD=<build dir> -DLIST=<long_tests.cmake> -P check_long_tests.cmake: fails when a name
# in LIST is not a test of the build, so a renamed test cannot lose its `long` label silently
# (set_tests_properties in ctest's include files ignores unknown names).
file(STRINGS ${LIST} lines REGEX "^  [A-Za-z0-9_]+\\.[A-Za-z0-9_]+$")
list(LENGTH lines named)
execute_process(COMMAND ${CMAKE_CTEST_COMMAND} --test-dir ${BUILD} -N -L long
                OUTPUT_VARIABLE out RESULT_VARIABLE rc)
string(REGEX MATCH "Total Tests: ([0-9]+)" _ "${out}")
if(NOT rc EQUAL 0 OR NOT CMAKE_MATCH_1 EQUAL named)
  message(FATAL_ERROR "long_tests.cmake names ${named} tests, ctest labels ${CMAKE_MATCH_1} long:\n${out}")
endif()
message(STATUS "${named} tests labelled long")
