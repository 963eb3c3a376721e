# Strip footing on a weightless c-phi soil against Prandtl's limit pressure
# (docs/verification/strip_footing.md). Included from tests/cases.cmake (FRIX_BIN defined
# there). Each test runs one deck of inputs/strip_footing with tests/harness/run_deck_check.sh and checks with
# check_footing.py: the settlement reached, a plateau of the footing pressure over the last
# quarter (collapse), the limit pressure within the tolerance of c N_c (Prandtl), footing and
# bottom reactions balanced to 1e-6.
set(footing_dir ${CMAKE_CURRENT_SOURCE_DIR}/footing)
set(footing_decks ${PROJECT_SOURCE_DIR}/inputs/strip_footing)

# One test per (deck, phi, tolerance, labels).
function(footing_test deck phi tolerance labels timeout)
  add_test(NAME ${deck}
           COMMAND bash ${run_deck_check} ${FRIX_BIN} ${footing_decks}/${deck}.dck ${footing_dir}/check_footing.py
                   ${phi} ${tolerance})
  set_tests_properties(${deck} PROPERTIES LABELS "${labels}" TIMEOUT ${timeout})
endfunction()

# Default run: phi = 20 degrees, smooth, coarse mesh (384 HEX8 EAS 3), 40 increments, about 350
# Newton iterations, 12 s CPU; within 5 % of Prandtl (measured +4.83 %).
footing_test(footing_phi20_smooth 20 0.05 "regression;plasticity;long" ${scaled_300})

# Slow: the other coarse smooth decks (measured +4.97 % at phi = 0 with 33 cut-backs, 28 s;
# +4.87 % at phi = 30, 13 s) and the fine smooth decks (960 HEX8; measured +2.54 %, +2.54 %,
# +2.59 %; 155 s at phi = 0, about 40 s else) within 3 %.
footing_test(footing_phi0_smooth 0 0.05 "regression;plasticity;slow" ${scaled_600})
footing_test(footing_phi30_smooth 30 0.05 "regression;plasticity;slow" ${scaled_600})
foreach(phi 0 20 30)
  footing_test(footing_phi${phi}_smooth_fine ${phi} 0.03 "regression;plasticity;slow" ${scaled_600})
endforeach()

# Slow: rough footings, which converge more slowly (docs/verification/strip_footing.md):
# phi = 0 on the fine mesh (measured +4.20 %, 91 s CPU, 38 cut-backs) and phi = 30 on the finer
# mesh (2048 HEX8; measured +3.85 %, 250 s CPU), within 5 %.
footing_test(footing_phi0_rough_fine 0 0.05 "regression;plasticity;slow" ${scaled_600})
math(EXPR footing_finer_timeout "1200 * ${FRIX_TIMEOUT_SCALE}")
footing_test(footing_phi30_rough_finer 30 0.05 "regression;plasticity;slow" ${footing_finer_timeout})
