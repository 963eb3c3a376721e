# Ironing (docs/verification/ironing.md): a stiff die with a cylindrical bottom pressed 1.4 into a
# soft neo-Hookean slab and dragged 4.0 along it, MU 0.3 (decks: inputs/ironing, written by
# generate_ironing.py). Included by tests/cases.cmake, which defines FRIX_BIN and run_deck_check.
# Node-to-segment contact with smoothed master normals, and mortar contact through the pressing (it
# does not finish the sliding: docs/verification/ironing.md). check_ironing.py compares the whole die's reaction
# forces Fx (drag) and Fz (pressing) at sample times with reference_*.txt (values, tolerances
# and their source in the files' comments) and, while the die slides, Fx/Fz >= mu.
set(ironing_dir ${CMAKE_CURRENT_SOURCE_DIR}/contact_ironing)
set(ironing_decks ${PROJECT_SOURCE_DIR}/inputs/ironing)

# Default run: the coarse mesh (h = 1.0, 78 HEX8), 67 increments, 9 cut-backs, about 7 s CPU.
add_test(NAME contact_ironing_nts_coarse
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${ironing_decks}/ironing_nts_h1.0.dck ${ironing_dir}/check_ironing.py
                 ${ironing_dir}/reference_h1.0.txt --sliding 1.3 1.9 0.3)
set_tests_properties(contact_ironing_nts_coarse PROPERTIES LABELS "regression;contact" TIMEOUT ${scaled_300})

# Slow: the h = 0.5 mesh (592 HEX8).
math(EXPR ironing_timeout "1800 * ${FRIX_TIMEOUT_SCALE}")
add_test(NAME contact_ironing_nts_h0.5
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${ironing_decks}/ironing_nts_h0.5.dck ${ironing_dir}/check_ironing.py
                 ${ironing_dir}/reference_h0.5.txt --sliding 1.3 1.9 0.3)
set_tests_properties(contact_ironing_nts_h0.5 PROPERTIES LABELS "regression;contact;slow" TIMEOUT ${ironing_timeout})

# Mortar contact (DISCRETIZATION Mortar), the h = 1.0 mesh. Default run: the first quarter of
# the pressing with friction (7 increments, 50 Newton iterations, about 7 s CPU; 47 s wall under
# load), where the mortar rows' first-order tangent failed at the onset of contact.
add_test(NAME contact_ironing_mortar_onset
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${ironing_dir}/ironing_mortar_onset_h1.0.dck
                 ${ironing_dir}/check_ironing.py ${ironing_dir}/reference_mortar_onset_h1.0.txt --end 1)
set_tests_properties(contact_ironing_mortar_onset PROPERTIES LABELS "regression;contact" TIMEOUT ${scaled_300})
# Slow: the whole pressing (depth 1.4), 27 increments, 10 cut-backs, about 2 min CPU (15 min wall under load).
add_test(NAME contact_ironing_mortar_pressing
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${ironing_dir}/ironing_mortar_pressing_h1.0.dck
                 ${ironing_dir}/check_ironing.py ${ironing_dir}/reference_mortar_pressing_h1.0.txt --end 1)
set_tests_properties(contact_ironing_mortar_pressing PROPERTIES LABELS "regression;contact;slow"
                     TIMEOUT ${ironing_timeout})
