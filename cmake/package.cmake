# Installing satviz: the CMake package that find_package(satviz) reads. The install rules of the libraries,
# headers, programs and scenes are beside their targets (core/, render/, app/, tutorials/), in two components:
# Development (headers, static libraries, this package) and Runtime (the programs and share/satviz, the lessons
# and their scenes).
include(CMakePackageConfigHelpers)

set(SATVIZ_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/satviz)
install(EXPORT satvizTargets NAMESPACE satviz:: DESTINATION ${SATVIZ_CMAKE_DIR} COMPONENT Development)

# What the installed libraries need from their users' systems, found by the config before it loads the targets.
set(SATVIZ_PACKAGE_SCENE OFF)
if(TARGET satviz_scene)
  set(SATVIZ_PACKAGE_SCENE ON)
endif()
set(SATVIZ_PACKAGE_DRAW_IMGUI OFF)
if(TARGET satviz_draw_imgui)
  set(SATVIZ_PACKAGE_DRAW_IMGUI ON)
endif()
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/satvizConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/package/satvizConfig.cmake INSTALL_DESTINATION ${SATVIZ_CMAKE_DIR})
# 0.x: a new minor version may change the interface.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/package/satvizConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/package/satvizConfig.cmake ${PROJECT_BINARY_DIR}/package/satvizConfigVersion.cmake
        DESTINATION ${SATVIZ_CMAKE_DIR} COMPONENT Development)
