# Installing satviz: the CMake package that find_package(satviz) reads, and the Debian package of the tools that
# cpack builds in the build directory. The install rules of the libraries, headers, programs and scenes are beside
# their targets (core/, render/, app/, tutorials/), in two components: Development (headers, static libraries,
# this package) and Runtime (the programs and share/satviz, the lessons and their scenes).
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

# `cpack` in the build directory: satviz_VERSION-1_ARCH.deb with the Runtime component, installed under /usr.
set(SATVIZ_DEB_MAINTAINER "satviz maintainers <maintainers@users.noreply.h-seed-3103f039.example>"
    CACHE STRING "Maintainer field of the Debian package")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME satviz)
set(CPACK_PACKAGE_VENDOR satviz)
set(CPACK_PACKAGE_CONTACT "${SATVIZ_DEB_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${SATVIZ_DEB_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Separating Axis Theorem for 2D collisions: an app that steps through it, a renderer and a query tool")
set(CPACK_PACKAGE_DESCRIPTION
    "satviz-query prints the collision results of JSON scenes. satviz-render draws a scene and each step of the \
test to PNG without a display. satviz, the interactive app, steps through the test axis by axis, with lessons. \
The lessons and their scenes are in /usr/share/satviz.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_INSTALL_CMAKE_PROJECTS "${PROJECT_BINARY_DIR};satviz;Runtime;/")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_STRIP_FILES ON)
# The Debian 12 packages of the shared libraries the programs link (as dpkg-shlibdeps finds them), of libGL, which
# GLFW loads for its OpenGL context, and of the fonts the figures are drawn in.
set(satviz_deb_depends "libc6 (>= 2.35)" "libgcc-s1 (>= 3.0)" "libstdc++6 (>= 11)")
if(TARGET satviz-render)
  list(APPEND satviz_deb_depends "libosmesa6 (>= 10.2~)" libstb0 fonts-dejavu-core)
endif()
if(TARGET satviz)
  list(APPEND satviz_deb_depends "libglfw3 (>= 3.1)" libopengl0 libgl1 "libmd4c0 (>= 0.2.7)" libstb0 fonts-dejavu-core)
endif()
list(REMOVE_DUPLICATES satviz_deb_depends)
list(JOIN satviz_deb_depends ", " CPACK_DEBIAN_PACKAGE_DEPENDS)
# Inside another project (add_subdirectory), its own packaging stays its own.
if(PROJECT_IS_TOP_LEVEL)
  include(CPack)
endif()
