# Creates the Wine prefix the Windows tests run in. A first wineboot on a fresh machine can fix up
# its temporary directory, ask to be run again and fail; it is retried up to twice.
#   cmake -DEMULATOR=<the emulator, a list> -P wine_prefix.cmake
foreach(attempt 1 2 3)
  execute_process(COMMAND ${EMULATOR} wineboot --init RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(rc EQUAL 0 AND NOT out MATCHES "try running the same command again")
    message(STATUS "Wine prefix ready (attempt ${attempt})")
    return()
  endif()
  message(STATUS "wineboot attempt ${attempt} failed (${rc}): ${out}")
endforeach()
message(FATAL_ERROR "wineboot could not create the Wine prefix")
