# The AVX2 kernels' object may define one external function, avx2KernelTable: any other (a template
# or inline function from a shared header, emitted weak) could be picked by the linker for the whole
# library, and its AVX2 code would then run, and crash, on CPUs without AVX2 (src/core/kernels_avx2.cpp).
# Shared data (type descriptors a sanitizer emits) holds no instructions and is allowed.
# Usage: cmake -DNM=nm -DOBJECTS="<verve_core's objects>" -P check_avx2_object.cmake
set(object "")
foreach(o IN LISTS OBJECTS)
  if(o MATCHES "kernels_avx2\\.cpp\\.o(bj)?$")
    set(object ${o})
  endif()
endforeach()
if(NOT object)
  message(FATAL_ERROR "no kernels_avx2 object among: ${OBJECTS}")
endif()
execute_process(COMMAND ${NM} --defined-only ${object} OUTPUT_VARIABLE listing RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${NM} --defined-only ${object} failed (${rc})")
endif()
string(REPLACE "\n" ";" lines "${listing}")
set(shared "")
foreach(line IN LISTS lines)
  # "address type name": code the linker may share is T (global), W/w (weak), u (unique), i (ifunc).
  if(line MATCHES "^[0-9a-fA-F]* ([TWwui]) (.+)$")
    set(name ${CMAKE_MATCH_2})
    if(NOT name MATCHES "avx2KernelTable")
      list(APPEND shared ${name})
    endif()
  endif()
endforeach()
if(shared)
  message(FATAL_ERROR "kernels_avx2 defines code other files may link to: ${shared}")
endif()
message(STATUS "kernels_avx2 shares only avx2KernelTable")
