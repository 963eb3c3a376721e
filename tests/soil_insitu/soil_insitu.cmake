# The initial (in-situ) stress (INITIAL STRESS, docs/verification/soil_insitu.md): a soil block
# under gravity with its geostatic stress stays put (u = 0, no Newton iteration, stresses and
# reactions of the closed form), then takes a surcharge by the oedometric closed form: elastic
# HEX8, Mohr-Coulomb HEX8-EAS9, two layers tied, two layers in augmented contact; and a
# Mohr-Coulomb block from K0 to the active limit (every point on the edge of the closed form).
# Restarts inside both steps end bit for bit where the full runs end.
foreach(deck insitu_elastic insitu_mohr_coulomb insitu_layers insitu_layers_contact insitu_mohr_coulomb_active)
  add_test(NAME soil_insitu_${deck} COMMAND bash ${run_deck_check} ${FRIX_BIN}
           ${CMAKE_CURRENT_SOURCE_DIR}/soil_insitu/${deck}.dck ${CMAKE_CURRENT_SOURCE_DIR}/soil_insitu/check_insitu.py)
  set_tests_properties(soil_insitu_${deck} PROPERTIES LABELS "regression;plasticity" TIMEOUT ${scaled_60})
endforeach()
foreach(deck insitu_mohr_coulomb insitu_layers_contact)
  add_test(NAME restart_${deck} COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_test.sh ${FRIX_BIN}
           ${CMAKE_CURRENT_SOURCE_DIR}/soil_insitu/${deck}.dck 1.1 1.2 2.1)
  set_tests_properties(restart_${deck} PROPERTIES LABELS "regression;plasticity" TIMEOUT ${scaled_60})
endforeach()
# in plastic loading: restarted at the end of step 1, and where some and where all points yielded
add_test(NAME restart_insitu_mohr_coulomb_active COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_test.sh
         ${FRIX_BIN} ${CMAKE_CURRENT_SOURCE_DIR}/soil_insitu/insitu_mohr_coulomb_active.dck 1.2 2.1 2.3)
set_tests_properties(restart_insitu_mohr_coulomb_active PROPERTIES LABELS "regression;plasticity" TIMEOUT ${scaled_60})
# frix --check lists the initial stress (docs/deck-format.md, "Checking a deck").
add_test(NAME check_summary_insitu COMMAND ${FRIX_BIN} --check ${CMAKE_CURRENT_SOURCE_DIR}/soil_insitu/insitu_layers.dck)
set_tests_properties(check_summary_insitu PROPERTIES LABELS regression PASS_REGULAR_EXPRESSION
                     "body forces.*initial stress: 2 lines, on 16 elements.*steps: 2")
