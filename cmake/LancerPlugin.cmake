# lancer_add_integrator(<name> <sources>...): builds an integrator plugin as a
# shared module named <name>.so, the name `lancer render -i <name>` uses.
function(lancer_add_integrator name)
  add_library(lancer_integrator_${name} MODULE ${ARGN})
  target_link_libraries(lancer_integrator_${name} PRIVATE lancer::render)
  set_target_properties(lancer_integrator_${name} PROPERTIES
    OUTPUT_NAME ${name} PREFIX ""
    CXX_VISIBILITY_PRESET hidden)
  if(LANCER_PLUGIN_OUTPUT_DIR)
    set_target_properties(lancer_integrator_${name} PROPERTIES
      LIBRARY_OUTPUT_DIRECTORY ${LANCER_PLUGIN_OUTPUT_DIR})
  endif()
  if(LANCER_PLUGIN_INSTALL_DIR)
    install(TARGETS lancer_integrator_${name} LIBRARY DESTINATION ${LANCER_PLUGIN_INSTALL_DIR})
  endif()
endfunction()
