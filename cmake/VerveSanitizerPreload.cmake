# verve_sanitizer_preload(<out_var>): in a sanitizer build, the environment entry that lets a host
# program that is not instrumented (the Lua interpreters, Godot) load instrumented plugins: the
# sanitizer runtime must be preloaded (it has to come first), with libstdc++ so that its
# interceptors find __cxa_throw (C hosts load libstdc++ only later, with libverve). Empty otherwise.
function(verve_sanitizer_preload out_var)
  set(env "")
  foreach(sanitizer address thread)
    if(CMAKE_C_FLAGS MATCHES "-fsanitize=[a-z,]*${sanitizer}")
      string(REPLACE "address" "asan" runtime ${sanitizer})
      string(REPLACE "thread" "tsan" runtime ${runtime})
      execute_process(COMMAND ${CMAKE_C_COMPILER} -print-file-name=lib${runtime}.so
        OUTPUT_VARIABLE runtime_path OUTPUT_STRIP_TRAILING_WHITESPACE)
      execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libstdc++.so
        OUTPUT_VARIABLE stdcxx_path OUTPUT_STRIP_TRAILING_WHITESPACE)
      set(env "LD_PRELOAD=${runtime_path}:${stdcxx_path}")
    endif()
  endforeach()
  set(${out_var} "${env}" PARENT_SCOPE)
endfunction()
