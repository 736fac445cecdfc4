# What `cmake --install` puts where (GNUInstallDirs), and the .deb that
# `cpack -G DEB` makes of it. The filters' libraries and headers install
# through vtk_module_build (CMakeLists.txt), the programs in
# app/CMakeLists.txt, the Python module in python/CMakeLists.txt.
include(CMakePackageConfigHelpers)

# The data: the material table, the scene schema, the demo mesh (the
# teapot that meshes/ makes at build time) and the example scenes, which
# name it as ../teapot.obj.
set(SHADELAB_DATA_DIR "${CMAKE_INSTALL_DATADIR}/shadelab")
install(FILES data/materials.json data/scene.schema.json "${SHADELAB_MESHES}/teapot.obj"
  DESTINATION "${SHADELAB_DATA_DIR}" COMPONENT runtime)
install(DIRECTORY data/scenes DESTINATION "${SHADELAB_DATA_DIR}" COMPONENT runtime)

# The CMake package: find_package(shadelab) gives shadelab::filters.
# vtk_module_build installs the targets (shadelab-targets.cmake) and their
# VTK module properties (shadelab-vtk-module-properties.cmake, which
# vtk_module_autoinit and VTK's wrapping read); the config file loads both.
set(cmake_dir "${CMAKE_INSTALL_LIBDIR}/cmake/shadelab")
# The VTK modules the filters link publicly (filters/vtk.module), for find_dependency.
set(SHADELAB_FILTERS_VTK_COMPONENTS CommonCore CommonDataModel CommonExecutionModel IOCore
  RenderingCore RenderingOpenGL2)
string(REPLACE ";" " " SHADELAB_FILTERS_VTK_COMPONENTS "${SHADELAB_FILTERS_VTK_COMPONENTS}")
configure_package_config_file(cmake/shadelabConfig.cmake.in
  "${CMAKE_CURRENT_BINARY_DIR}/shadelabConfig.cmake" INSTALL_DESTINATION "${cmake_dir}")
write_basic_package_version_file("${CMAKE_CURRENT_BINARY_DIR}/shadelabConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion)
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/shadelabConfig.cmake"
  "${CMAKE_CURRENT_BINARY_DIR}/shadelabConfigVersion.cmake"
  DESTINATION "${cmake_dir}" COMPONENT development)

# The .deb: everything above in one package, installed under /usr. Its
# Depends come from dpkg-shlibdeps on the binaries, plus what the Python
# module imports.
set(CPACK_PACKAGE_NAME shadelab)
set(CPACK_PACKAGE_VENDOR shadelab)
set(CPACK_PACKAGE_CONTACT "shadelab <shadelab@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "Triangle meshes under the lecture's illumination model, headless or in a window")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
# dpkg-shlibdeps finds our own libraries in the package through the
# binaries' relative run paths, and leaves them out of Depends.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
if(SHADELAB_PYTHON)
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3, python3-vtk9")
endif()
include(CPack)
