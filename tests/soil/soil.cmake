# Soil plasticity (Mohr-Coulomb, Drucker-Prager) on decks: a true triaxial test of a
# Mohr-Coulomb sample (EAS 9) and a conventional one of a Drucker-Prager sample (EAS 21) against
# their closed forms in every increment; each run restarted inside its steps, before yield and
# in plastic loading, ending bit for bit where the uninterrupted run ends.
foreach(law mohr_coulomb drucker_prager)
  add_test(NAME soil_triaxial_${law} COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/soil/check_triaxial.py
           ${FRIX_BIN} ${CMAKE_CURRENT_SOURCE_DIR}/soil/triaxial_${law}.dck)
  set_tests_properties(soil_triaxial_${law} PROPERTIES LABELS "regression;plasticity" TIMEOUT ${scaled_60})
endforeach()
add_test(NAME restart_triaxial_mohr_coulomb COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_test.sh ${FRIX_BIN}
         ${CMAKE_CURRENT_SOURCE_DIR}/soil/triaxial_mohr_coulomb.dck 1.1 2.4 2.6)
set_tests_properties(restart_triaxial_mohr_coulomb PROPERTIES LABELS "regression;plasticity" TIMEOUT ${scaled_60})
add_test(NAME restart_triaxial_drucker_prager COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_test.sh ${FRIX_BIN}
         ${CMAKE_CURRENT_SOURCE_DIR}/soil/triaxial_drucker_prager.dck 1.1 2.4 2.8)
set_tests_properties(restart_triaxial_drucker_prager PROPERTIES LABELS "regression;plasticity" TIMEOUT ${scaled_60})
# Soil properties out of range: every one reported at its line and column, no crash.
add_test(NAME soil_error_properties COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/errors/check_error_case.sh ${FRIX_BIN}
         ${CMAKE_CURRENT_SOURCE_DIR}/soil/error_mohr_coulomb_properties.dck)
set_tests_properties(soil_error_properties PROPERTIES LABELS errors)
