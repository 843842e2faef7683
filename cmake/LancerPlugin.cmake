# lancer_add_integrator(<name> <sources>...): builds an integrator plugin as a
# shared module named <name>.so, the name `lancer render -i <name>` uses.
#
# The same file serves the source tree (plugins/*/CMakeLists.txt) and plugins
# written out of tree against an installed lancer (`find_package(lancer)`
# includes it). In tree, plugins land in build/lib/lancer/plugins and install
# beside liblancer.so; out of tree they build in the project's own binary
# folder and install to <prefix>/lib/lancer/plugins (put that folder in
# LANCER_PLUGIN_PATH, or install into lancer's own prefix).
#
# A project that sets no CMAKE_BUILD_TYPE (with a single-configuration
# generator such as Ninja or Makefiles) builds its plugins in Release: an
# unoptimised integrator is many times slower, and lancer itself is built in
# Release by default too. Pass -DCMAKE_BUILD_TYPE=Debug (or any other) to
# choose; in lancer's own tree the top-level CMakeLists.txt has already set it.
include_guard(GLOBAL)
include(GNUInstallDirs)

get_property(lancer_multi_config GLOBAL PROPERTY GENERATOR_IS_MULTI_CONFIG)
if(NOT CMAKE_BUILD_TYPE AND NOT lancer_multi_config)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type (lancer plugins default to Release)" FORCE)
  message(STATUS "lancer: CMAKE_BUILD_TYPE not set, building plugins in Release")
endif()

function(lancer_add_integrator name)
  add_library(lancer_integrator_${name} MODULE ${ARGN})
  target_link_libraries(lancer_integrator_${name} PRIVATE lancer::render)
  # Hidden visibility: the plugin exports lancer_integrator_descriptor and
  # nothing else, so two plugins never clash over internal names.
  set_target_properties(lancer_integrator_${name} PROPERTIES
    OUTPUT_NAME ${name} PREFIX "" SUFFIX ".so"
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  if(LANCER_PLUGIN_OUTPUT_DIR)
    set_target_properties(lancer_integrator_${name} PROPERTIES
      LIBRARY_OUTPUT_DIRECTORY ${LANCER_PLUGIN_OUTPUT_DIR})
  endif()
  # Every plugin target, so tests/ can build after all of them (the golden
  # and plugin tests dlopen the built plugins).
  set_property(GLOBAL APPEND PROPERTY LANCER_INTEGRATOR_TARGETS lancer_integrator_${name})
  if(LANCER_PLUGIN_INSTALL_DIR)
    # Installed in tree: <prefix>/lib/lancer/plugins, two levels below liblancer.so.
    set_target_properties(lancer_integrator_${name} PROPERTIES INSTALL_RPATH "$ORIGIN/../..")
    install(TARGETS lancer_integrator_${name} LIBRARY DESTINATION ${LANCER_PLUGIN_INSTALL_DIR})
  else()
    if(LANCER_LIBRARY_DIR)
      set_target_properties(lancer_integrator_${name} PROPERTIES INSTALL_RPATH "${LANCER_LIBRARY_DIR}")
    endif()
    install(TARGETS lancer_integrator_${name}
      LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/lancer/plugins)
  endif()
endfunction()
