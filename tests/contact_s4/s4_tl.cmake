# S4b-TL: S4b with KINTYP Tot_Lagr and neo-Hookean material (docs/verification/s4.md, S4b-TL).
# Checks: the run reaches u_x = 0.5; N = 720 and R_x + sum t_x A = 0 (equilibrium); R_x <= mu N;
# Newton orders q >= 1.8 wherever the contact status has settled; the last 10 increments
# converge in <= 6 iterations without cut-back. About 20 s.
add_test(NAME contact_s4b_tl
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/contact_s4/s4_tl_run.sh ${FRIX_BIN}
                 ${PROJECT_SOURCE_DIR}/inputs/s4_block/s4b_block_tl.dck)
set_tests_properties(contact_s4b_tl PROPERTIES LABELS "regression;contact;long")
