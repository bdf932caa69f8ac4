# Fails if a test named KnownGap* lacks the known_gap label (see verve_discover_tests).
# Usage: cmake -DCTEST=ctest -DBUILD_DIR=<build> -P known_gap_labels.cmake
function(count_tests out)
  execute_process(COMMAND ${CTEST} --test-dir ${BUILD_DIR} -N ${ARGN} OUTPUT_VARIABLE text RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0 OR NOT text MATCHES "Total Tests: ([0-9]+)")
    message(FATAL_ERROR "ctest -N ${ARGN} failed:\n${text}")
  endif()
  set(${out} ${CMAKE_MATCH_1} PARENT_SCOPE)
endfunction()

count_tests(named -R ^KnownGap)
count_tests(labelled -R ^KnownGap -L ^known_gap$)
message(STATUS "${named} tests named KnownGap*, ${labelled} of them labelled known_gap")
if(NOT named EQUAL labelled)
  execute_process(COMMAND ${CTEST} --test-dir ${BUILD_DIR} -N -R ^KnownGap -LE ^known_gap$)
  message(FATAL_ERROR "the tests above are named KnownGap* but not labelled known_gap")
endif()
