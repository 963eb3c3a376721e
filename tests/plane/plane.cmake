# Plane strain and axisymmetric elements (tests/plane; docs/verification/two-d.md).
set(plane_dir ${CMAKE_CURRENT_SOURCE_DIR}/plane)
set(plane_check ${plane_dir}/check_plane.py)
# Patch tests on the 5 distorted quadrilaterals of MacNeal & Harder: the exact linear field and
# its constant stress to 1e-10 (check_plane.py patch).
add_test(NAME plane_patch_plane_strain
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${plane_dir}/patch_plane.dck ${plane_check}
                 patch --gradient 1e-3 5e-4 5e-4 1e-3 --young 1e6 --poisson 0.25)
add_test(NAME plane_patch_axisymmetric
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${plane_dir}/patch_axisym.dck ${plane_check}
                 patch --gradient 1e-3 0 0 -0.0005 --young 1e6 --poisson 0.25 --axisymmetric)
# The plane strain cantilever against the same model of plain HEX8 with u_z = 0: the same
# bilinear field, the same tip displacement and clamp reaction to round-off.
add_test(NAME plane_beam_against_slab
         COMMAND bash ${plane_dir}/run_pair.sh ${FRIX_BIN} ${plane_dir}/beam_plane.dck ${plane_dir}/beam_slab.dck
                 1e-9 u2_n105 u1_n105)
# V4 thick cylinder, elastic: plane strain on the in-plane nodes of the HEX8 quarter ring
# against the plain HEX8 slab (same numbers) and Lame (Timoshenko & Goodier ch. 4: within the
# 0.5 % of docs/benchmarks.md V4); axisymmetric against Lame and the axial force 60 pi.
add_test(NAME plane_ring_against_slab
         COMMAND bash ${plane_dir}/run_pair.sh ${FRIX_BIN} ${plane_dir}/ring_plane_elastic.dck
                 ${PROJECT_SOURCE_DIR}/inputs/verification/v4_thick_cylinder/cylinder_elastic_hex8.dck
                 1e-9 u1_n1 u1_n21 u2_n169 u2_n189)
add_test(NAME plane_ring_lame
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${plane_dir}/ring_plane_elastic.dck ${plane_check}
                 history u1_n1=9.079365e-4:5e-3 u1_n21=5.777778e-4:5e-3)
add_test(NAME plane_tube_axisymmetric_lame
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${plane_dir}/tube_axisym_elastic.dck ${plane_check}
                 history u1_n1=9.079365e-4:5e-3 u1_n21=5.777778e-4:5e-3 r2_sum_tube_ymin=-188.4955592:5e-3)
set_tests_properties(plane_patch_plane_strain plane_patch_axisymmetric plane_beam_against_slab
                     plane_ring_against_slab plane_ring_lame plane_tube_axisymmetric_lame
                     PROPERTIES LABELS regression TIMEOUT ${scaled_60})
# S6(a) the seed's pipe, axisymmetric, elastic-plastic with hardening: Lame at p = 9 and the
# independent 1D solution at p = 90 (docs/verification/s6a_pipe.md) within 0.1 %.
add_test(NAME plane_s6a_axisymmetric
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${plane_dir}/s6a_axisym.dck ${plane_check} history
                 u1_n1@1=1.661977672e-4:1e-3 u1_n5@1=1.639279950e-4:1e-3 u1_n1@2=4.674524e-3:1e-3 u1_n5@2=4.541972e-3:1e-3)
set_tests_properties(plane_s6a_axisymmetric PROPERTIES LABELS "regression;plasticity" TIMEOUT ${scaled_60})
# S1 in plane strain on a rigid line (RIGID_PLANE with a normal in the x-y plane): against the
# plain HEX8 slab with u_z = 0 on the same nodes (same numbers) and against Hird & Russell.
add_test(NAME plane_s1_against_slab
         COMMAND bash ${plane_dir}/run_pair.sh ${FRIX_BIN} ${plane_dir}/s1_plane.dck ${plane_dir}/s1_slab.dck
                 1e-9 u1_n31 u2_n31 u1_n16 r1_sum_block_xmin)
add_test(NAME plane_s1_hird_russell
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${plane_dir}/s1_plane.dck ${plane_check} s1)
set_tests_properties(plane_s1_against_slab plane_s1_hird_russell PROPERTIES LABELS "regression;contact"
                     TIMEOUT ${scaled_60})
# Restart of a plastic, total Lagrangian axisymmetric run from 1.2 and 1.3: the final state
# bit for bit the uninterrupted run's (tests/restart/restart_test.sh).
add_test(NAME restart_axisym COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_test.sh ${FRIX_BIN}
         ${plane_dir}/restart_axisym.dck 1.2 1.3)
set_tests_properties(restart_axisym PROPERTIES LABELS regression TIMEOUT ${scaled_60})
# V2 Cook's membrane, 16 x 16: PLANE4 on the z = 0 layer of the HEX8 mesh against the plain
# HEX8 slab with u_z = 0 (cook_plane_hex8_16x16.dck: the same field, the same numbers).
add_test(NAME plane_cook_against_slab
         COMMAND bash ${plane_dir}/run_pair.sh ${FRIX_BIN} ${plane_dir}/cook_plane2d_plain_16x16.dck
                 ${PROJECT_SOURCE_DIR}/inputs/verification/v2_cook/cook_plane_hex8_16x16.dck 1e-9 u2_n3 u2_n31)
set_tests_properties(plane_cook_against_slab PROPERTIES LABELS regression TIMEOUT ${scaled_60})
