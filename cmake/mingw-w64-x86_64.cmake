# Toolchain: Windows x64 with Debian's MinGW-w64, the posix-threads variant (std::thread, std::mutex).
# Used by the mingw-release preset (docs/platforms.md). Programs are linked statically, so the only
# DLL a test program loads is verve.dll; CTest runs them under Wine.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CMAKE_C_COMPILER x86_64-w64-mingw32-gcc-posix)
set(CMAKE_CXX_COMPILER x86_64-w64-mingw32-g++-posix)
set(CMAKE_RC_COMPILER x86_64-w64-mingw32-windres)
set(CMAKE_EXE_LINKER_FLAGS_INIT -static)

set(CMAKE_FIND_ROOT_PATH /usr/x86_64-w64-mingw32)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# Eigen is headers only: the host's copy serves.
set(Eigen3_DIR /usr/share/eigen3/cmake CACHE PATH "Eigen's CMake package")

# Wine (Debian's wine64 keeps its binary out of PATH) with a private prefix in the build tree,
# quiet, and without the Mono/Gecko installers a fresh prefix would offer.
find_program(VERVE_WINE NAMES wine64 wine HINTS /usr/lib/wine)
if(VERVE_WINE)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${CMAKE_COMMAND} -E env WINEPREFIX=${CMAKE_BINARY_DIR}/wine-prefix
    WINEDEBUG=-all WINEDLLOVERRIDES=mscoree,mshtml= ${VERVE_WINE})
endif()
