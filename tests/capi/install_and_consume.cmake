# Installs the build into a fresh prefix, then builds and runs consumers against the installed
# tree only: with find_package(verve) (C and C++ targets) and with pkg-config (C).
# Usage: cmake -DBUILD_DIR=.. -DCONSUMER=.. -DWORK=.. -DGENERATOR=.. -DC_COMPILER=.. -DPKG_CONFIG=..
#              [-DC_FLAGS=.. -DCXX_FLAGS=.. -DLINK_FLAGS=..] -P install_and_consume.cmake
# The flags are the tested build's own (a sanitizer build's consumers must be instrumented too).
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "failed (${rc}): ${command}\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
  set(run_output "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK}/prefix)
file(REMOVE_RECURSE ${WORK})
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

foreach(f include/verve_c.h include/verve/agent.hpp include/verve/io.hpp)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
file(GLOB_RECURSE pc_files ${prefix}/*/verve.pc)
file(GLOB_RECURSE libs ${prefix}/*/libverve.so)
if(NOT pc_files OR NOT libs)
  message(FATAL_ERROR "verve.pc or libverve.so missing under ${prefix}")
endif()
list(GET pc_files 0 pc_file)
get_filename_component(pc_dir ${pc_file} DIRECTORY)
list(GET libs 0 lib)
get_filename_component(lib_dir ${lib} DIRECTORY)

# 1. find_package(verve COMPONENTS cpp): verve::verve (C) and verve::verve_cpp (C++).
run(${CMAKE_COMMAND} -S ${CONSUMER} -B ${WORK}/build -G ${GENERATOR} -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_BUILD_TYPE=Release "-DCMAKE_C_FLAGS=${C_FLAGS}" "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}"
    "-DCMAKE_EXE_LINKER_FLAGS=${LINK_FLAGS}")
run(${CMAKE_COMMAND} --build ${WORK}/build)
run(${WORK}/build/consumer_c)
if(NOT run_output MATCHES "consumer_c: ok")
  message(FATAL_ERROR "consumer_c did not report ok")
endif()
run(${WORK}/build/consumer_cpp)
if(NOT run_output MATCHES "consumer_cpp: ok")
  message(FATAL_ERROR "consumer_cpp did not report ok")
endif()

# 2. pkg-config, with the installed tree moved elsewhere (verve.pc is relocatable).
if(NOT PKG_CONFIG)
  message(FATAL_ERROR "pkg-config not found")
endif()
set(moved ${WORK}/moved)
file(RENAME ${prefix} ${moved})
string(REPLACE ${prefix} ${moved} pc_dir ${pc_dir})
string(REPLACE ${prefix} ${moved} lib_dir ${lib_dir})
set(ENV{PKG_CONFIG_PATH} ${pc_dir})
run(${PKG_CONFIG} --cflags verve)
string(STRIP "${run_output}" cflags)
run(${PKG_CONFIG} --libs verve)
string(STRIP "${run_output}" libs_flags)
separate_arguments(cflags UNIX_COMMAND "${cflags}")
separate_arguments(libs_flags UNIX_COMMAND "${libs_flags}")
separate_arguments(build_flags UNIX_COMMAND "${C_FLAGS} ${LINK_FLAGS}")
run(${C_COMPILER} -std=c99 -Wall -Wextra -pedantic -Werror ${build_flags} ${cflags} ${CONSUMER}/consumer.c
    ${libs_flags} -o ${WORK}/consumer_pkgconfig)
run(${CMAKE_COMMAND} -E env LD_LIBRARY_PATH=${lib_dir} ${WORK}/consumer_pkgconfig)
if(NOT run_output MATCHES "consumer_c: ok")
  message(FATAL_ERROR "the pkg-config consumer did not report ok")
endif()
file(REMOVE_RECURSE ${WORK})
