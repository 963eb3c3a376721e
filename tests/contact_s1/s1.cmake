# Benchmark S1 (elastic block on a frictional base, Hird & Russell): included by
# tests/cases.cmake, which defines FRIX_BIN. Every case runs in about 1-3 s (labels
# regression;contact). docs/verification/s1.md gives the numbers.
set(s1_tests ${CMAKE_CURRENT_SOURCE_DIR}/contact_s1)
set(s1_decks ${PROJECT_SOURCE_DIR}/inputs/s1_block)

# postproc/s1_analytical.py against an independent finite-difference solution, and its CLI.
add_test(NAME contact_s1_analytical COMMAND /usr/bin/python3 ${s1_tests}/test_s1_analytical.py)

# The variants: (a) rigid plane, (b) deformable base, (c) x = 0 fully held (step-2 gains),
# (d) refined 60 x 1 x 2; (b) refined too.
# The deformable base with augmented Lagrangian normal contact (EPSN 1e5 and 1e4, EPST = k_s
# kept): the same checks (docs/verification/penalty.md).
foreach(case "rigid_plane;rigid" "deformable_base;base" "fixed_end;fixed" "refined;refined"
             "deformable_base_refined;base_refined" "deformable_base_augmented;base"
             "deformable_base_augmented_eps1e4;base")
  list(GET case 0 deck)
  list(GET case 1 variant)
  add_test(NAME contact_s1_${deck}
           COMMAND bash ${s1_tests}/run_s1.sh ${FRIX_BIN} ${s1_decks}/s1_${deck}.dck ${variant})
  list(APPEND s1_names contact_s1_${deck})
endforeach()

# The README example (scripts/example_s1.sh) with this build's frix, into a scratch folder.
add_test(NAME contact_s1_example
         COMMAND bash ${s1_tests}/check_example.sh ${FRIX_BIN} ${PROJECT_SOURCE_DIR}/scripts/example_s1.sh)

# Friction in the first increment for nodes touching at t = 0 (first_increment_friction.dck):
# a block held sideways only by friction sticks with u_x = F/(eps_T A). This failed (singular
# matrix) until slip anchors started at the reference foot points.
add_test(NAME contact_s1_first_increment_friction
         COMMAND bash ${s1_tests}/check_first_increment.sh ${FRIX_BIN})

set_tests_properties(contact_s1_analytical ${s1_names} contact_s1_example
                     contact_s1_first_increment_friction
                     PROPERTIES LABELS "regression;contact")
