# S4 / S4b: block pressed and pulled on a rigid foundation (docs/verification/s4.md).
set(s4_dir ${CMAKE_CURRENT_SOURCE_DIR}/contact_s4)
set(s4_inputs ${PROJECT_SOURCE_DIR}/inputs/s4_block)
# S4: every interface node sticks after both steps, largest |tau|/(mu p) below 1, creep ~1e-2.
add_test(NAME contact_s4_stick
         COMMAND bash ${s4_dir}/run_check.sh ${FRIX_BIN} ${s4_inputs}/s4_block.dck s4)
# S4b: displacement-controlled pull, the horizontal reaction levels off at mu N = 360 (1 %).
add_test(NAME contact_s4b_plateau
         COMMAND bash ${s4_dir}/run_check.sh ${FRIX_BIN} ${s4_inputs}/s4b_block.dck s4b)
# S4 with augmented Lagrangian normal contact and friction (METHOD Augmented, TMETHOD
# Augmented, the same EPSN 1e8 and EPST 1e4): every node sticks, and the stuck nodes no longer
# creep by |t| / EPST (1.3e-2) but by less than the stick tolerance (docs/verification/penalty.md).
add_test(NAME contact_s4_stick_augmented
         COMMAND bash ${s4_dir}/run_check.sh ${FRIX_BIN} ${s4_inputs}/s4_block_augmented.dck s4 --augmented)
# The same at EPST 1e3: without the penalty growth of the augmented law every increment ends at
# MAXAUG 20 with the stuck nodes creeping by 5e-5, beyond the stick tolerance 3.09e-6; with it
# they meet it (docs/verification/penalty.md, S4).
add_test(NAME contact_s4_stick_augmented_epst1e3
         COMMAND bash ${s4_dir}/run_check.sh ${FRIX_BIN} ${s4_inputs}/s4_block_augmented_epst1e3.dck s4 --augmented)
set_tests_properties(contact_s4_stick contact_s4b_plateau contact_s4_stick_augmented
                     contact_s4_stick_augmented_epst1e3 PROPERTIES LABELS "regression;contact")
