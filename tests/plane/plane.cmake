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
# bilinear field, the same tip displacement and clamp reaction to 1e-11 (round-off: measured 4.5e-15).
add_test(NAME plane_beam_against_slab
         COMMAND bash ${plane_dir}/run_pair.sh ${FRIX_BIN} ${plane_dir}/beam_plane.dck ${plane_dir}/beam_slab.dck
                 1e-11 u2_n105 u1_n105)
# V4 thick cylinder, elastic: plane strain on the in-plane nodes of the HEX8 quarter ring
# against the plain HEX8 slab (same numbers) and Lame (Timoshenko & Goodier ch. 4: within the
# 0.5 % of docs/benchmarks.md V4); axisymmetric against Lame and the axial force 60 pi.
add_test(NAME plane_ring_against_slab
         COMMAND bash ${plane_dir}/run_pair.sh ${FRIX_BIN} ${plane_dir}/ring_plane_elastic.dck
                 ${PROJECT_SOURCE_DIR}/inputs/verification/v4_thick_cylinder/cylinder_elastic_hex8.dck
                 1e-11 u1_n1 u1_n21 u2_n169 u2_n189)
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
# independent 1D solution at p = 90 (docs/verification/s6a_pipe.md) within 0.02 % (measured 0.005 %).
add_test(NAME plane_s6a_axisymmetric
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${plane_dir}/s6a_axisym.dck ${plane_check} history
                 u1_n1@1=1.661977672e-4:2e-4 u1_n5@1=1.639279950e-4:2e-4 u1_n1@2=4.674524e-3:2e-4 u1_n5@2=4.541972e-3:2e-4)
set_tests_properties(plane_s6a_axisymmetric PROPERTIES LABELS "regression;plasticity" TIMEOUT ${scaled_60})
# S1 in plane strain on a rigid line (RIGID_PLANE with a normal in the x-y plane): against the
# plain HEX8 slab with u_z = 0 on the same nodes (same numbers) and against Hird & Russell.
add_test(NAME plane_s1_against_slab
         COMMAND bash ${plane_dir}/run_pair.sh ${FRIX_BIN} ${plane_dir}/s1_plane.dck ${plane_dir}/s1_slab.dck
                 1e-11 u1_n31 u2_n31 u1_n16 r1_sum_block_xmin)
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
                 ${PROJECT_SOURCE_DIR}/inputs/verification/v2_cook/cook_plane_hex8_16x16.dck 1e-11 u2_n3 u2_n31)
set_tests_properties(plane_cook_against_slab PROPERTIES LABELS regression TIMEOUT ${scaled_60})
# V2 Cook's membrane 16 x 16 with PLANE4 EAS 4 (cook_plane2d_eas4_16x16.dck, make_cook_deck.py):
# u_y(C) against 23.96 (Simo & Rifai 1990; docs/verification.md V2), 2 % (measured 23.883, -0.32 %;
# plain PLANE4 23.43), and against the HEX8 EAS 9 slab with u_z = 0 on the same nodes
# (cook_plane_eas9_16x16.dck: one layer without variation along z, whose in-plane modes are
# EAS 4's; measured the same to 5e-14).
add_test(NAME plane_cook_eas4
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${plane_dir}/cook_plane2d_eas4_16x16.dck ${plane_check}
                 history u2_n31=23.96:0.02)
add_test(NAME plane_cook_eas4_against_slab
         COMMAND bash ${plane_dir}/run_pair.sh ${FRIX_BIN} ${plane_dir}/cook_plane2d_eas4_16x16.dck
                 ${PROJECT_SOURCE_DIR}/inputs/verification/v2_cook/cook_plane_eas9_16x16.dck 1e-11 u2_n3 u2_n31)
# V4 thick cylinder, perfectly plastic, to the limit load by load control (the HEX8 deck
# cylinder_plastic_eas9.dck's curve and steps): the last converged pressure against
# p_limit = (2/sqrt 3) sigma_y ln(b/a) = 192.0906 (Hill 1950, ch. V), 2 %; PLANE4 EAS 4 on the
# quarter ring (ring_plane_plastic_eas4.dck, make_ring_deck.py; measured 192.127, +0.02 %) and
# AXISYM4 EAS 4 on the tube slice (measured 192.127). The plain PLANE4 and AXISYM4 lock: both
# carry the whole curve to 1.05 p_limit.
add_test(NAME plane_ring_plastic_eas4
         COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/tests/verification/check_cylinder.py run ${FRIX_BIN}
                 ${plane_dir}/ring_plane_plastic_eas4.dck --curve 0,0,1,150,2,180,3,201.70 --allow-stop
                 --limit 192.0906 0.02 "limit pressure vs (2/sqrt 3) sigma_y ln(b/a)")
add_test(NAME plane_tube_axisymmetric_plastic_eas4
         COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/tests/verification/check_cylinder.py run ${FRIX_BIN}
                 ${plane_dir}/tube_axisym_plastic_eas4.dck --curve 0,0,1,150,2,180,3,201.70 --allow-stop
                 --limit 192.0906 0.02 "limit pressure vs (2/sqrt 3) sigma_y ln(b/a)")
set_tests_properties(plane_cook_eas4 plane_cook_eas4_against_slab plane_ring_plastic_eas4
                     plane_tube_axisymmetric_plastic_eas4
                     PROPERTIES LABELS "regression;plasticity" TIMEOUT ${scaled_60})
# The EAS option of the plane shapes: a count other than 0 or 4 on a quadrilateral, and any
# count but 0 on a triangle, are errors naming the deck line and the valid counts.
foreach(name error_plane4_eas3 error_axisym3_eas4)
  add_test(NAME plane_${name}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/errors/check_error_case.sh ${FRIX_BIN} ${plane_dir}/${name}.dck)
  set_tests_properties(plane_${name} PROPERTIES LABELS errors)
endforeach()
# 2D contact between deformable plane bodies (node-to-segment against 2-node master segments,
# frix_contact_pass's plane passes). A pad pressed and dragged on a base with Coulomb friction
# (mu 0.3, sliding), against the same model as plain HEX8 slabs with u_z = 0 and the 3D
# node-to-face contact (same numbers to round-off: measured 8.5e-14 of the largest value,
# the contact force included); one pass with facet normals, and two passes with smoothed
# normals and the automatic penalties (eps_N = eps_T = 26923 in both; measured 1.8e-15).
add_test(NAME plane_contact_drag_against_slab
         COMMAND bash ${plane_dir}/run_pair.sh ${FRIX_BIN} ${plane_dir}/drag_plane.dck ${plane_dir}/drag_slab.dck
                 1e-11 u1_n1001 u2_n1001 u1_n1006 u2_n1006 u1_n18 u2_n18 r1_sum_base_ymin r2_sum_base_ymin
                 c1_pair1 c2_pair1)
add_test(NAME plane_contact_drag_two_pass_against_slab
         COMMAND bash ${plane_dir}/run_pair.sh ${FRIX_BIN} ${plane_dir}/drag_plane_two_pass.dck
                 ${plane_dir}/drag_slab_two_pass.dck
                 1e-11 u1_n1001 u2_n1001 u1_n1006 u2_n1006 u1_n18 u2_n18 r1_sum_base_ymin r2_sum_base_ymin
                 c1_pair1 c2_pair1)
# Contact patch test in plane strain (Taylor & Papadopoulos 1991): two PLANE4 blocks with
# non-matching edges, two passes, augmented normal law (PENTOL 1e-12): the uniaxial stress and
# the interface pressure p at every node to 1e-7 of p (measured: stress 1.3e-8, pressure
# 1.5e-8; one pass fails it: 0.13 pressure error, 0.21 stress).
add_test(NAME plane_contact_patch
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${plane_dir}/contact_patch_plane.dck ${plane_check}
                 contact_patch --pressure 100 --poisson 0.3 --tolerance 1e-7)
# The same in axisymmetry (contact_patch_axisym.dck: rings r in [1, 2], AXISYM4; tributary
# areas 2 pi r times the edge lengths): hoop stress 0 (measured: stress 6.2e-9, pressure
# 7.1e-9; one pass: 0.12 pressure error).
add_test(NAME plane_contact_patch_axisymmetric
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${plane_dir}/contact_patch_axisym.dck ${plane_check}
                 contact_patch --pressure 100 --poisson 0.3 --tolerance 1e-7 --axisymmetric)
set_tests_properties(plane_contact_drag_against_slab plane_contact_drag_two_pass_against_slab plane_contact_patch
                     plane_contact_patch_axisymmetric PROPERTIES LABELS "regression;contact" TIMEOUT ${scaled_60})
# Hertz in plane strain (hertz_plane.dck: the V6 data as a plane model, make_hertz_mesh.py):
# PASSES 2, the curved cylinder with smoothed normals as master of pass 2. On the coarse mesh
# (a/6), with Coulomb friction mu = 0.2, against the HEX8 slab with u_z = 0 and the 3D
# contact: the same numbers (measured 5e-14 and 3.5e-13 of the largest in two runs, the
# contact force; the displacements 7e-19).
add_test(NAME plane_hertz_coarse_against_slab
         COMMAND bash ${plane_dir}/run_pair.sh ${FRIX_BIN} ${plane_dir}/hertz_coarse_plane.dck
                 ${plane_dir}/hertz_coarse_slab.dck 1e-11 u2_n813 u1_n819 u2_n819 u2_n842 u1_n848 u2_n848
                 u2_n1203 r2_sum_block_bottom c1_pair1 c2_pair1)
set_tests_properties(plane_hertz_coarse_against_slab PROPERTIES LABELS "regression;contact" TIMEOUT ${scaled_60})
# Against Hertz (Johnson 1985, 4.3; tests/contact_v5v6/v6_hertz_check.py, the reference x of
# the slave nodes from the listing): the half width a and p0 of the fit p^2 = p0^2 (1 - x^2/a^2)
# within the issue's 1 %, the transmitted force within 1 %, the nodal pressure at x = 0 and the
# largest nodal error within V6's bounds. Element size a/12 (measured: a 0.9959, p0 0.9948,
# p(0) 0.957 of Hertz, max error 4.3 % of p0 at the symmetry node) and, label long, a/24
# (a 1.0003, p0 0.9976, p(0) 0.975, max error 2.5 %).
add_test(NAME plane_hertz
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/contact_v5v6/run_v6.sh ${FRIX_BIN} ${plane_dir}/hertz_plane.dck
                 --listing-reference --check a_fit_ratio=0.99:1.01 --check p0_fit_ratio=0.99:1.01
                 --check force_ratio=0.99:1.01 --check p0_ratio=0.95:1.05 --check a_last_ratio=0:1
                 --check a_open_ratio=1:2 --check max_err=0:0.05)
add_test(NAME plane_hertz_fine
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/contact_v5v6/run_v6.sh ${FRIX_BIN} ${plane_dir}/hertz_plane_fine.dck
                 --listing-reference --check a_fit_ratio=0.995:1.005 --check p0_fit_ratio=0.995:1.005
                 --check force_ratio=0.99:1.01 --check p0_ratio=0.95:1.05 --check a_last_ratio=0:1
                 --check a_open_ratio=1:2 --check max_err=0:0.03)
set_tests_properties(plane_hertz PROPERTIES LABELS "regression;contact" TIMEOUT ${scaled_60})
set_tests_properties(plane_hertz_fine PROPERTIES LABELS "regression;contact;long" TIMEOUT ${scaled_300})
# S5 in plane strain (s5_plane.dck on make_s5_plane.py's plane mesh of s5_coarse.msh; Coulomb
# mu = 0.5, one pass, facet normals, the pipe PLANE4 EAS 4) against the 3D slab s5_slab.dck
# (s5_mu0.5.dck with TOLRESID = TOLDISP = 1e-12, no POS3D): the same displacements of the
# monitored nodes and contact force (measured 1.7e-13 of the largest displacement, 7e-14 of the
# contact force).
add_test(NAME plane_s5_against_slab
         COMMAND bash ${plane_dir}/run_pair.sh ${FRIX_BIN} ${plane_dir}/s5_plane.dck ${plane_dir}/s5_slab.dck
                 1e-11 u2_n6=u3_n6 u2_n10=u3_n10 u1_n8 u2_n8=u3_n8 u2_n1=u3_n1 c1_pair1 c2_pair1=c3_pair1)
set_tests_properties(plane_s5_against_slab PROPERTIES LABELS "regression;contact" TIMEOUT ${scaled_60})
# Restart of 2D contact between plane bodies (the two-pass drag, restarted from increment 2.3):
# the slip history of both passes comes back from the HDF5 file; the final displacements,
# pressures, tractions and slip equal the uninterrupted run's to 1e-10 (measured 1.1e-15).
add_test(NAME restart_contact_plane COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_contact_test.sh
         ${FRIX_BIN} ${plane_dir}/drag_plane_two_pass.dck)
set_tests_properties(restart_contact_plane PROPERTIES LABELS "regression;contact" TIMEOUT ${scaled_60})
