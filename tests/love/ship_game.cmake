# Ships samples/love the way docs/lua.md says: install, then verve.so and libverve.so.0 beside the
# game's .love archive (a zip of main.lua and conf.lua).
# Usage: cmake -DBUILD_DIR=.. -DLIBDIR=lib -DSTAGE=.. -DGAME_SOURCE=.. -DGAME_DIR=.. -P ship_game.cmake
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "failed (${rc}): ${command}\n${out}\n${err}")
  endif()
endfunction()

file(REMOVE_RECURSE ${STAGE} ${GAME_DIR})
file(MAKE_DIRECTORY ${GAME_DIR})
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${STAGE})
# file(COPY) would copy libverve.so.0 as the symlink it is; the game needs the file.
run(${CMAKE_COMMAND} -E copy ${STAGE}/${LIBDIR}/lua/5.1/verve.so ${STAGE}/${LIBDIR}/libverve.so.0 ${GAME_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} -E tar cf ${GAME_DIR}/verve-npcs.love --format=zip main.lua conf.lua
                WORKING_DIRECTORY ${GAME_SOURCE} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "could not zip ${GAME_SOURCE} into ${GAME_DIR}/verve-npcs.love")
endif()
message(STATUS "shipped: ${GAME_DIR}/verve-npcs.love, verve.so, libverve.so.0")
