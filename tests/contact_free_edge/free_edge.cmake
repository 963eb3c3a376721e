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
