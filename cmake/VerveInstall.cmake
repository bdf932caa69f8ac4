# Install rules and the package exports:
#   find_package(verve)                    -> verve::verve      (libverve.so, the C ABI)
#   find_package(verve COMPONENTS cpp)     -> verve::verve_cpp  (static C++ libraries; needs Eigen3)
#   pkg-config verve                       -> the C ABI
# The C target is exported apart from the C++ ones, so a C host does not need Eigen. pugixml is
# inside libverve and, for C++ users, installed as the static libverve_pugixml.a next to verve_io.
include(CMakePackageConfigHelpers)

set(VERVE_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/verve)

add_library(verve_cpp INTERFACE)
target_link_libraries(verve_cpp INTERFACE verve_io verve_core)
target_compile_features(verve_cpp INTERFACE cxx_std_17)

install(TARGETS verve EXPORT verveTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS verve_core verve_io verve_pugixml verve_cpp EXPORT verveCppTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(FILES ${PROJECT_SOURCE_DIR}/include/verve_c.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/verve DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.hpp")
install(EXPORT verveTargets NAMESPACE verve:: DESTINATION ${VERVE_CMAKE_DIR})
install(EXPORT verveCppTargets NAMESPACE verve:: DESTINATION ${VERVE_CMAKE_DIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/verveConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/verveConfig.cmake INSTALL_DESTINATION ${VERVE_CMAKE_DIR})
# 0.x: a minor release may change the ABI, so only the same minor version is compatible.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/verveConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/verveConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/verveConfigVersion.cmake
  DESTINATION ${VERVE_CMAKE_DIR})

# verve.pc finds its prefix relative to itself, so the installed tree can be moved.
set(VERVE_PC_DIR ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
file(RELATIVE_PATH VERVE_PC_TO_PREFIX /prefix/${VERVE_PC_DIR} /prefix)
configure_file(${PROJECT_SOURCE_DIR}/cmake/verve.pc.in ${CMAKE_CURRENT_BINARY_DIR}/verve.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/verve.pc DESTINATION ${VERVE_PC_DIR})
