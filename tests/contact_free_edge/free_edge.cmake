# A slave block overhanging the free edge of its master surface (docs/contact.md "Edges and
# corners"), included by tests/cases.cmake, which defines FRIX_BIN. About 0.4 s.
# The slave nodes more than the extension zone (0.1 x the master face's length across the edge)
# beyond the edge are open, those 0.03 beyond (inside the zone, 0.05) and over the master are
# pressed, and the load is carried (check_overhang.py). Before the free-edge rule the column
# 0.155 beyond the edge was pressed (p = 114-141 against 100 applied), so this test failed.
add_test(NAME contact_free_edge_overhang
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/contact_free_edge/run_overhang.sh ${FRIX_BIN}
                 ${CMAKE_CURRENT_SOURCE_DIR}/contact_free_edge/overhang.dck)
set_tests_properties(contact_free_edge_overhang PROPERTIES LABELS "regression;contact")

# The same with a soft slab (E = 1e3, EPSN 1e6, 10 increments; soft_overhang.dck): the column
# inside the extension zone is clamped onto the free edge, where the frictionless tangent is
# unsymmetric. Factorized as symmetric (CHOLMOD reads one triangle) increment 2 converged
# linearly (contraction 0.86-0.9) and was cut back without end; with UMFPACK wherever such a
# node is in contact every increment takes 4-9 iterations. Equilibrium to 1e-6. About 1 s.
add_test(NAME contact_free_edge_soft_overhang
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/contact_free_edge/run_overhang.sh ${FRIX_BIN}
                 ${CMAKE_CURRENT_SOURCE_DIR}/contact_free_edge/soft_overhang.dck
                 --window 0.03 --tolerance 1e-6 --increments 10 --max-iterations 10)
set_tests_properties(contact_free_edge_soft_overhang PROPERTIES LABELS "regression;contact")
