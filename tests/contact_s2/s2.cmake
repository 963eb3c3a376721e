# S2 column flange T-stub of an extended end-plate joint on a rigid end plate
# (docs/verification/s2.md). Included from tests/cases.cmake (FRIX_BIN defined there). Each test
# runs one deck of inputs/s2_end_plate with tests/harness/run_deck_check.sh and checks it with check_s2.py: the web
# displacement of 2 mm reached; statics at every increment (web force = bolt force - prying
# force, 1e-6; the contact resultant normal to the plate, 1e-9); the plastic resistance
# (tangent intersection) between EN 1993-1-8 mode 1 (Method 1) and mode 2 with the model's
# bolts; for the EAS decks the initial stiffness within 20 % of the beam estimate with the web
# in series; the history at u = 0.5, 1 and 2 mm against the frix regression values in
# reference.txt (1e-6).
set(s2_dir ${CMAKE_CURRENT_SOURCE_DIR}/contact_s2)
set(s2_decks ${PROJECT_SOURCE_DIR}/inputs/s2_end_plate)

# Default run: the coarse mesh (707 HEX8), EAS 9, the seed's penalties; 20 increments, about
# 100 Newton iterations, 15-20 s on the 2-core VM (shared).
add_test(NAME contact_s2_eas9
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${s2_decks}/s2_eas9.dck ${s2_dir}/check_s2.py --stiffness
                 --reference ${s2_dir}/reference.txt)
set_tests_properties(contact_s2_eas9 PROPERTIES LABELS "regression;contact;plasticity"
                     TIMEOUT ${scaled_300})

# Slow: the fine mesh (5656 HEX8, 3.5-4.5 minutes), EAS 3 (the seed's Hexa8-E3) and plain HEX8 on
# the coarse mesh (HEX8 locks in bending: 21 % stiffer than the beam estimate, so without the
# stiffness check; it needs the friction continuation in its first increment), and the bolt
# preloaded by the turn of the nut before the pull (no stiffness check: the preload stiffens
# the joint until the flange lifts off; 25-45 s).
foreach(variant eas9_fine eas3 hex8 eas9_preload)
  if(variant STREQUAL "hex8" OR variant STREQUAL "eas9_preload")
    set(options "")
  else()
    set(options "--stiffness")
  endif()
  add_test(NAME contact_s2_${variant}
           COMMAND bash ${run_deck_check} ${FRIX_BIN} ${s2_decks}/s2_${variant}.dck ${s2_dir}/check_s2.py ${options}
                   --reference ${s2_dir}/reference.txt)
  if(variant STREQUAL "eas9_fine")
    math(EXPR timeout "900 * ${FRIX_TIMEOUT_SCALE}")   # 3.5-4.5 min alone on the loaded VM
  else()
    set(timeout ${scaled_600})
  endif()
  set_tests_properties(contact_s2_${variant} PROPERTIES LABELS "regression;contact;plasticity;slow"
                       TIMEOUT ${timeout})
endforeach()
