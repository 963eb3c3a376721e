# S4 / S4b: block pressed and pulled on a rigid foundation (docs/verification/s4.md).
set(s4_dir ${CMAKE_CURRENT_SOURCE_DIR}/contact_s4)
set(s4_inputs ${PROJECT_SOURCE_DIR}/inputs/s4_block)
# S4: every interface node sticks after both steps, largest |tau|/(mu p) below 1, creep ~1e-2.
add_test(NAME contact_s4_stick
         COMMAND bash ${s4_dir}/run_check.sh ${FRIX_BIN} ${s4_inputs}/s4_block.dck s4)
# S4b: displacement-controlled pull, the horizontal reaction levels off at mu N = 360 (1 %).
add_test(NAME contact_s4b_plateau
         COMMAND bash ${s4_dir}/run_check.sh ${FRIX_BIN} ${s4_inputs}/s4b_block.dck s4b)
set_tests_properties(contact_s4_stick contact_s4b_plateau PROPERTIES LABELS "regression;contact")
