# The Lua module for Windows x64 (the mingw-release preset with -DVERVE_BUILD_LUA=ON): verve.dll for
# LuaJIT 2.1, against LuaJIT cross-built with MinGW from Debian's source (scripts/build_luajit_windows.sh,
# which gives the folder holding lua.h and lua51.dll as VERVE_LUAJIT_DIR).
# `require "verve"` looks for verve.dll, the name of the C library too, and Windows loads one module
# per name: so this module carries the library inside (verve_capi_objects, linked like verve.dll)
# instead of importing it. The Lua suite runs under Wine with luajit.exe.
set(VERVE_LUAJIT_DIR "" CACHE PATH "LuaJIT built for Windows: the folder with lua.h and lua51.dll")
if(NOT EXISTS "${VERVE_LUAJIT_DIR}/lua.h" OR NOT EXISTS "${VERVE_LUAJIT_DIR}/lua51.dll")
  message(STATUS "Lua module for Windows skipped: no LuaJIT in VERVE_LUAJIT_DIR='${VERVE_LUAJIT_DIR}' "
                 "(./scripts/build_luajit_windows.sh builds it)")
  return()
endif()

set(VERVE_LUA_OUTPUT_DIR ${CMAKE_BINARY_DIR}/lua/jit)
add_library(verve_lua_jit MODULE src/verve_lua.c src/lua_descriptor.c src/lua_warnings.c src/lua_recording.c src/lua_actions.c src/lua_batch.c
  ${PROJECT_SOURCE_DIR}/bindings/shared/warning_queue.c $<TARGET_OBJECTS:verve_capi_objects>)
target_include_directories(verve_lua_jit PRIVATE ${VERVE_LUAJIT_DIR} ${PROJECT_SOURCE_DIR}/include
  ${PROJECT_SOURCE_DIR}/bindings/shared)
# The C ABI is defined in this DLL, not imported (VERVE_API is dllexport while building the library).
target_compile_definitions(verve_lua_jit PRIVATE VERVE_BUILDING_LIBRARY)
target_link_libraries(verve_lua_jit PRIVATE verve_io verve_core ${VERVE_LUAJIT_DIR}/lua51.dll)
target_compile_options(verve_lua_jit PRIVATE ${VERVE_WARNINGS})
target_link_options(verve_lua_jit PRIVATE -static -static-libgcc -static-libstdc++ "LINKER:--gc-sections"
  $<$<CONFIG:Release>:-s>)
set_target_properties(verve_lua_jit PROPERTIES PREFIX "" OUTPUT_NAME verve
  C_STANDARD 99 C_STANDARD_REQUIRED ON C_VISIBILITY_PRESET hidden
  LIBRARY_OUTPUT_DIRECTORY ${VERVE_LUA_OUTPUT_DIR})
add_custom_command(TARGET verve_lua_jit POST_BUILD  # luajit.exe and lua51.dll beside the module
  COMMAND ${CMAKE_COMMAND} -E copy_if_different ${VERVE_LUAJIT_DIR}/luajit.exe ${VERVE_LUAJIT_DIR}/lua51.dll
          ${VERVE_LUA_OUTPUT_DIR})
install(TARGETS verve_lua_jit LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/lua/5.1)

if(NOT VERVE_BUILD_TESTS OR NOT CMAKE_CROSSCOMPILING_EMULATOR)
  return()
endif()
# The same scripts as on Linux (CMakeLists.txt beside this file), with luajit.exe under Wine; the
# folder holding the module is the working directory: Lua's default cpath starts with .\?.dll.
set(VERVE_LUA_TESTS module descriptor agent errors close persistence learning policy crowd warnings sensor_groups action_branches
  continuous_actions)
set(paths "package.path=[[${CMAKE_CURRENT_SOURCE_DIR}/tests/?.lua;${PROJECT_SOURCE_DIR}/samples/lua/?.lua]]")
foreach(name IN LISTS VERVE_LUA_TESTS)
  add_test(NAME lua.jit.${name} COMMAND ${CMAKE_CROSSCOMPILING_EMULATOR} ${VERVE_LUA_OUTPUT_DIR}/luajit.exe
    -e "${paths}" ${CMAKE_CURRENT_SOURCE_DIR}/tests/test_${name}.lua WORKING_DIRECTORY ${VERVE_LUA_OUTPUT_DIR})
endforeach()
add_test(NAME lua.jit.sample_hot_plate COMMAND ${CMAKE_CROSSCOMPILING_EMULATOR} ${VERVE_LUA_OUTPUT_DIR}/luajit.exe
  -e "${paths}" ${PROJECT_SOURCE_DIR}/samples/lua/train_hot_plate.lua --runs 2 --trials 20
  WORKING_DIRECTORY ${VERVE_LUA_OUTPUT_DIR})
set_tests_properties(lua.jit.sample_hot_plate PROPERTIES PASS_REGULAR_EXPRESSION "# value by position: ")
get_property(lua_tests DIRECTORY PROPERTY TESTS)
set_tests_properties(${lua_tests} PROPERTIES FIXTURES_REQUIRED wine)
