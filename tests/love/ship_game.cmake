# Ships samples/love the way docs/lua.md says: install, then verve.so and libverve.so.0 beside the
# game's .love archive (a zip of the game's Lua files: main.lua, conf.lua and any modules beside them).
# Usage: cmake -DBUILD_DIR=.. -DLIBDIR=lib -DSTAGE=.. -DGAME_SOURCE=.. -DGAME_DIR=.. [-DGAME_NAME=verve-npcs]
#        -P ship_game.cmake
if(NOT GAME_NAME)
  set(GAME_NAME verve-npcs)
endif()
file(REMOVE_RECURSE ${STAGE} ${GAME_DIR})
file(MAKE_DIRECTORY ${GAME_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${STAGE}
                OUTPUT_QUIET COMMAND_ERROR_IS_FATAL ANY)
# `cmake -E copy` copies what a symlink points to: libverve.so.0 must be the library itself.
execute_process(COMMAND ${CMAKE_COMMAND} -E copy ${STAGE}/${LIBDIR}/lua/5.1/verve.so
                        ${STAGE}/${LIBDIR}/libverve.so.0 ${GAME_DIR} COMMAND_ERROR_IS_FATAL ANY)
file(GLOB game_files RELATIVE ${GAME_SOURCE} ${GAME_SOURCE}/*.lua)
execute_process(COMMAND ${CMAKE_COMMAND} -E tar cf ${GAME_DIR}/${GAME_NAME}.love --format=zip ${game_files}
                WORKING_DIRECTORY ${GAME_SOURCE} COMMAND_ERROR_IS_FATAL ANY)
message(STATUS "shipped: ${GAME_DIR}/${GAME_NAME}.love, verve.so, libverve.so.0")
