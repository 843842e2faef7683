# What `cmake --install` adds beyond each target's own install rule: the CMake
# package (lancerConfig.cmake, its version file, the exported targets and
# LancerPlugin.cmake) so that out-of-tree plugins build with
#   find_package(lancer REQUIRED)
#   lancer_add_integrator(myplugin myplugin.cpp)
# Included once from the top-level CMakeLists.txt after every target exists.
include(CMakePackageConfigHelpers)

# Exported as lancer::render and lancer::scene_graph.
set_target_properties(lancer_render PROPERTIES EXPORT_NAME render)
set_target_properties(lancer_scene_graph PROPERTIES EXPORT_NAME scene_graph)
# lancer is C++20 throughout; a plugin compiling its headers must be too.
set_property(TARGET lancer_render APPEND PROPERTY INTERFACE_COMPILE_FEATURES cxx_std_20)

set(LANCER_CMAKE_INSTALL_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/lancer")
install(EXPORT lancerTargets NAMESPACE lancer:: FILE lancerTargets.cmake
  DESTINATION ${LANCER_CMAKE_INSTALL_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/lancerConfig.cmake.in
  ${CMAKE_BINARY_DIR}/lancerConfig.cmake
  INSTALL_DESTINATION ${LANCER_CMAKE_INSTALL_DIR}
  PATH_VARS CMAKE_INSTALL_INCLUDEDIR CMAKE_INSTALL_LIBDIR LANCER_PLUGIN_INSTALL_DIR)
# The plugin ABI may change between minor versions; refuse a mismatched one early.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/lancerConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES
  ${CMAKE_BINARY_DIR}/lancerConfig.cmake
  ${CMAKE_BINARY_DIR}/lancerConfigVersion.cmake
  ${CMAKE_CURRENT_LIST_DIR}/LancerPlugin.cmake
  DESTINATION ${LANCER_CMAKE_INSTALL_DIR})
