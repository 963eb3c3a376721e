# Tetrahedra (tests/tet4). TET4 (4-node tetrahedron): the patch test on 48 tetrahedra of the unit cube
# (check_patch.py), the cantilever meshed by gmsh at three sizes against the closed form of
# pure bending and against HEX8 EAS 9 (run_cantilever.py), and a restart of a plastic total
# Lagrangian TET4 run bit-identical to the uninterrupted one.
set(tet4_run bash ${CMAKE_CURRENT_SOURCE_DIR}/inp/run_inp_case.sh ${FRIX_BIN})
add_test(NAME tet4_patch COMMAND ${tet4_run} ../tet4/check_patch.py ../tet4/patch.dck)
add_test(NAME tet4_cantilever COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/tet4/run_cantilever.py ${FRIX_BIN})
add_test(NAME restart_tet4 COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_test.sh ${FRIX_BIN}
         ${CMAKE_CURRENT_SOURCE_DIR}/tet4/restart_tet4.dck 1.2 1.3)
set_tests_properties(tet4_patch tet4_cantilever restart_tet4 PROPERTIES LABELS regression TIMEOUT ${scaled_60})
# frix --check names each block's cell type.
add_test(NAME check_summary_tet4 COMMAND ${FRIX_BIN} --check ${CMAKE_CURRENT_SOURCE_DIR}/tet4/patch.dck)
set_tests_properties(check_summary_tet4 PROPERTIES LABELS regression PASS_REGULAR_EXPRESSION
  "block 1: 48 elements TET4 \\(Geo_Lin\\) on TET4 cells, material 1 MAT_Struct_LinearElastic")
# TET10 (10-node tetrahedron): the patch test on the 48 tetrahedra as C3D10, the interior
# corner node moved (check_patch.py), the cantilever at order 2 against the closed form of pure
# bending and HEX8 EAS 9 (run_cantilever.py ... 10), and a restart of a plastic total
# Lagrangian TET10 run bit-identical to the uninterrupted one.
add_test(NAME tet10_patch COMMAND ${tet4_run} ../tet4/check_patch.py ../tet4/patch10.dck)
add_test(NAME tet10_cantilever COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/tet4/run_cantilever.py ${FRIX_BIN} 10)
add_test(NAME restart_tet10 COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_test.sh ${FRIX_BIN}
         ${CMAKE_CURRENT_SOURCE_DIR}/tet4/restart_tet10.dck 1.2 1.3)
set_tests_properties(tet10_patch tet10_cantilever restart_tet10 PROPERTIES LABELS regression TIMEOUT ${scaled_60})
# Pressure on tetrahedron faces (TRI3 of TET4, TRI6 of TET10; dead and follower): the clamp's
# reactions sum to p A, and the uniaxial state of nu = 0 is exact (run_pressure.py).
add_test(NAME tet_pressure COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/tet4/run_pressure.py ${FRIX_BIN})
set_tests_properties(tet_pressure PROPERTIES LABELS regression TIMEOUT ${scaled_60})
# A TET10 on a deck element line (10 node ids): frix --check names its block's cell.
add_test(NAME check_summary_tet10 COMMAND ${FRIX_BIN} --check ${CMAKE_CURRENT_SOURCE_DIR}/tet4/inline10.dck)
set_tests_properties(check_summary_tet10 PROPERTIES LABELS regression PASS_REGULAR_EXPRESSION
  "block 1: 1 elements TET10 \\(Geo_Lin\\) on TET10 cells, material 1 MAT_Struct_LinearElastic")
