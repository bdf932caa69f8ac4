# pugixml, compiled into Verve from Debian's source package, so that libverve.so and verve.dll carry
# it inside (position-independent, symbols hidden) instead of needing libpugixml.so.1 on a player's
# machine. ./scripts/setup.sh fetches the source into third_party/ (gitignored) with
# scripts/fetch_source.sh; VERVE_PUGIXML_SOURCE_DIR points at another copy.
set(VERVE_PUGIXML_SOURCE_DIR ${PROJECT_SOURCE_DIR}/third_party/pugixml CACHE PATH
  "pugixml's source tree (fetched by ./scripts/setup.sh)")
if(NOT EXISTS ${VERVE_PUGIXML_SOURCE_DIR}/src/pugixml.cpp)
  message(FATAL_ERROR "pugixml's source is not in ${VERVE_PUGIXML_SOURCE_DIR}.\n"
    "Run ./scripts/setup.sh once (it fetches Debian's pugixml source into third_party/), or "
    "./scripts/fetch_source.sh pugixml third_party, or pass -DVERVE_PUGIXML_SOURCE_DIR=<pugixml tree>.")
endif()

add_library(verve_pugixml STATIC ${VERVE_PUGIXML_SOURCE_DIR}/src/pugixml.cpp)
target_include_directories(verve_pugixml SYSTEM PUBLIC $<BUILD_INTERFACE:${VERVE_PUGIXML_SOURCE_DIR}/src>)
set_target_properties(verve_pugixml PROPERTIES POSITION_INDEPENDENT_CODE ON
  CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
# Code written against Debian's package keeps linking pugixml::pugixml: it gets this build.
add_library(pugixml::pugixml ALIAS verve_pugixml)
