# Kinematic couplings (COUPLINGS section, docs/couplings.md): closed forms of a cantilever
# pulled, loaded, bent and twisted through its coupled end, a free block moved rigidly through
# a coupled face (tests/coupling/check_coupling.sh), and a restart bit-identical to the
# uninterrupted run with the coupling (plastic pull, then bending).
add_test(NAME coupling_closed_forms COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/coupling/check_coupling.sh ${FRIX_BIN}
         ${CMAKE_CURRENT_SOURCE_DIR}/coupling)
add_test(NAME restart_coupling COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_test.sh ${FRIX_BIN}
         ${CMAKE_CURRENT_SOURCE_DIR}/coupling/restart_coupled.dck 1.2 1.3)
set_tests_properties(coupling_closed_forms restart_coupling PROPERTIES LABELS regression)
