# Toolchain: WebAssembly with Debian's emscripten package (emcc 3.1.6, clang 14), or an emsdk's when
# EMSDK is set. Used by the web-release preset (docs/web.md): verve_core, verve_io and the C ABI are
# compiled to one wasm module with its JS glue (bindings/web/CMakeLists.txt).
set(VERVE_EMSCRIPTEN_ROOTS /usr/share/emscripten /usr/lib/emscripten)
if(DEFINED ENV{EMSDK})
  list(PREPEND VERVE_EMSCRIPTEN_ROOTS $ENV{EMSDK}/upstream/emscripten)
endif()
find_file(VERVE_EMSCRIPTEN_TOOLCHAIN cmake/Modules/Platform/Emscripten.cmake PATHS ${VERVE_EMSCRIPTEN_ROOTS}
  NO_DEFAULT_PATH)
if(NOT VERVE_EMSCRIPTEN_TOOLCHAIN)
  message(FATAL_ERROR "Emscripten not found: apt-get install emscripten (or ./scripts/setup.sh --test)")
endif()
include(${VERVE_EMSCRIPTEN_TOOLCHAIN})

# C++ exceptions carry every error to the C ABI's catch (src/capi/capi_guard.hpp): Emscripten
# ignores them by default. WebAssembly's own exceptions (Chrome 95, Firefox 100, Safari 15.2,
# Node.js 17) cost nothing until one is thrown, unlike the JS-emulated ones.
set(CMAKE_C_FLAGS_INIT "-fwasm-exceptions")
set(CMAKE_CXX_FLAGS_INIT "-fwasm-exceptions")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-fwasm-exceptions")

# Eigen is headers only: the host's copy serves.
set(Eigen3_DIR /usr/share/eigen3/cmake CACHE PATH "Eigen's CMake package")

# Debian's emcc runs its JS optimiser with the node on PATH and expects Debian's node-acorn, which
# NodeSource's (or any other non-Debian) node does not look for in /usr/share/nodejs.
if(EXISTS /usr/share/nodejs/acorn)
  set(CMAKE_CXX_LINKER_LAUNCHER ${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs)
  set(CMAKE_C_LINKER_LAUNCHER ${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs)
endif()
