# TET4 (4-node tetrahedron): the patch test on 48 tetrahedra of the unit cube (check_patch.py).
set(tet4_run bash ${CMAKE_CURRENT_SOURCE_DIR}/inp/run_inp_case.sh ${FRIX_BIN})
add_test(NAME tet4_patch COMMAND ${tet4_run} ../tet4/check_patch.py ../tet4/patch.dck)
set_tests_properties(tet4_patch PROPERTIES LABELS regression TIMEOUT ${scaled_60})
