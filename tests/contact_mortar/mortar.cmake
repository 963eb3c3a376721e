# Mortar contact (DISCRETIZATION Mortar, docs/contact.md "Mortar contact"), included by
# tests/cases.cmake, which defines FRIX_BIN. Labels regression;contact.
set(MORTAR_DIR ${CMAKE_CURRENT_SOURCE_DIR}/contact_mortar)
set(V5V6_DIR ${CMAKE_CURRENT_SOURCE_DIR}/contact_v5v6)

# Contact patch test with ONE pass (patch_*.dck: the V5 blocks, non-matching 3 x 3 or 5 x 5 on
# 4 x 4). Exact solution (closed form): sigma_zz = -p in both blocks, all other stresses 0,
# contact pressure p at every slave node. Measured (2026-11-27): slave pressures equal to p
# within 1.4e-10 (3 x 3 upper), 2.2e-10 (lower under 3 x 3), 2.6e-10 (5 x 5 upper), 3.8e-10 (lower
# under 5 x 5); stresses within 2.3e-13 of p. The pressure is eps_N times a gap of -p/eps_N =
# -1e-6 computed from positions of about 0.5: its round-off is 1e-16 x 0.5/1e-6 = 5e-11 per
# term, summed over the row's 10-20 terms (1e-9). Bounds: 5e-9 on the pressures (the slave
# side's <slave>_err and pass1_min/max), 1e-10 on the stresses, 1e-8 on the load balance
# pass_sum.
# Node-to-segment with one pass on the same meshes fails (v5_u*_1pass in contact_v5v6: the
# master's stresses 5-18 % off, its nodal tractions 15-41 %). The checker's master-side error
# (N_a(xi)-weighted nodal tractions, node-to-segment's load path) does not apply: not checked.
set(MORTAR_PATCH_EXACT --check pass_sum=0.99999999:1.00000001 --check pass1_min=0.999999995:1.000000005
                       --check pass1_max=0.999999995:1.000000005 --check tangential=0:1e-10
                       --check upper_szz=0:1e-10 --check lower_szz=0:1e-10 --check upper_soff=0:1e-10
                       --check lower_soff=0:1e-10)
foreach(case "u3_slave_upper;3;upper" "u3_slave_lower;3;lower" "u5_slave_upper;5;upper" "u5_slave_lower;5;lower")
  list(GET case 0 deck)
  list(GET case 1 divisions)
  list(GET case 2 slave)
  add_test(NAME contact_mortar_patch_${deck}
           COMMAND bash ${V5V6_DIR}/run_v5.sh ${FRIX_BIN} ${MORTAR_DIR}/patch_${deck}.dck ${divisions}
                   ${MORTAR_PATCH_EXACT} --check ${slave}_err=0:5e-9 --max-iterations 2)
  set_tests_properties(contact_mortar_patch_${deck} PROPERTIES LABELS "regression;contact")
endforeach()

# Hertz on NON-aligned meshes (hertz_nonaligned.dck/.geo: the V6 cylinder with h = 0.008 on a
# block with 0.62 h; slave the cylinder). Closed form (Johnson 1985, eqs. 4.43-4.45):
# a = sqrt(4 P R/(pi E*)), p0 = 2 P/(pi a) (v6_hertz_check.py). Measured (2026-11-27):
# p0_ratio 0.99977, a_fit_ratio 0.99896, force_ratio 0.99912, max_err 0.85 % and max_err_all
# (every slave node; the nodes of the y = 0 and y = T rows, which plane strain makes equal,
# averaged) 1.5 % of p0, ripple 1.2 % of p0; 30 Newton iterations in 4 increments,
# 12 s on the shared 2-core machine. Node-to-segment on the same meshes: p0_ratio 0.8456,
# max_err 15.4 %, ripple 22 % (the pressure alternates from node to node). Bounds: 2 % of p0
# for p0, a and every node's error (the accuracy asked of mortar contact), 2.5 % for the ripple (twice the
# measured value, a tenth of node-to-segment's), the V6 bounds for the rest.
add_test(NAME contact_mortar_hertz_nonaligned
         COMMAND bash ${V5V6_DIR}/run_v6.sh ${FRIX_BIN} ${MORTAR_DIR}/hertz_nonaligned.dck
                 --check p0_ratio=0.98:1.02 --check a_fit_ratio=0.98:1.02 --check p0_fit_ratio=0.98:1.02
                 --check a_last_ratio=0:1 --check a_open_ratio=1:2 --check force_ratio=0.99:1.01
                 --check max_err_all=0:0.02 --check ripple=0:0.025)
set_tests_properties(contact_mortar_hertz_nonaligned PROPERTIES LABELS "regression;contact")

# Coulomb friction (drag.dck, run_drag.sh, check_drag.py): a 3 x 3 block pressed (p = 100) onto
# a larger 8 x 4 block, then dragged 0.002 along x in 20 increments; MU 0.3, EPST 1e6, nu = 0.
# Coulomb: stick while |F_t| < mu F_n, then every node slips and F_t = mu F_n (the sums of the
# slave nodes' written tractions times their tributary areas). Measured (2026-11-27): pressing
# gives |F_t| = 7.6e-14 F_n (nu = 0: no lateral expansion); step 2 sticks in 2 increments (F_t
# up to 0.91 mu F_n), partly slips in 3, slips at every node in 15 with |F_t| = mu F_n to
# 7.2e-8 (the traction is tangential to the slave's nodal normal, tilted by the shear: its x
# part is cos(tilt) of it) and |t_i| = mu p_i at every slipping node to 1.3e-16; |F_y| 1.2e-11
# F_n; 99 Newton iterations (3 to 6 per increment; node-to-segment 76 on the deck), 2 s. Bounds: Coulomb's
# relations to 1e-6 (F_t = mu F_n; a tilt of 1e-3 would give 5e-7) and 1e-12 (per node), at
# least one sticking and ten slipping increments, pressing and lateral forces below 1e-8 F_n, and
# the friction force against the drag in every increment of step 2 (F_t / (mu F_n) <= 0;
# measured at most -0.203, the first drag increment).
add_test(NAME contact_mortar_drag_coulomb
         COMMAND bash ${MORTAR_DIR}/run_drag.sh ${FRIX_BIN} ${MORTAR_DIR}/drag.dck 0.3
                 --check press_ratio=0:1e-8 --check stick_increments=1:20 --check stick_max_ratio=0:1
                 --check slip_increments=10:20 --check slip_ratio_err=0:1e-6 --check node_slip_err=0:1e-12
                 --check lateral=0:1e-8 --check along_drag=-1:0)
set_tests_properties(contact_mortar_drag_coulomb PROPERTIES LABELS "regression;contact")

# First touch with friction (first_touch.dck, run_drag.sh, check_drag.py): drag.dck's blocks,
# the upper one 0.001 above the lower one, moved 0.0005 along x while open (step 1), then
# 0.0005 more while lowered by 0.0011 (step 2: it touches part of the way), then dragged 0.001
# more in 4 increments. Expected (Coulomb): no slip before the nodes touch, so no tangential
# traction at the end of step 2 (every node open at the last commit starts from its current
# row: F_t = 0 exactly, touch_ratio); then slip with F_t = mu F_n against the drag. Measured
# (2026-11-27): step 2 in 1 increment, every node sticking with F_t = 0 (F_n = 15.10); step 3
# slipping at every node, |F_t| / (mu F_n) - 1 = 1.2e-9, |t_i| = mu p_i to 1.0e-16, |F_y|
# 7.9e-14 F_n; 22 Newton iterations. Taking the committed row of the open nodes (and its stick
# tangent for the nodes that started from their current row), the run stopped in step 2 at
# t = 1.908 (no convergence after 6 cut-backs). Bounds: touch_ratio exactly 0; the slip
# relations as for drag.dck.
add_test(NAME contact_mortar_first_touch
         COMMAND bash ${MORTAR_DIR}/run_drag.sh ${FRIX_BIN} ${MORTAR_DIR}/first_touch.dck 0.3
                 --check touch_ratio=0:0 --check slip_increments=4:4 --check slip_ratio_err=0:1e-6
                 --check node_slip_err=0:1e-12 --check lateral=0:1e-8 --check along_drag=-1:0)
set_tests_properties(contact_mortar_first_touch PROPERTIES LABELS "regression;contact")

# Restart (drag_restart.dck: drag.dck with HDF5 and TOLRESID/TOLDISP 1e-11): run through, then
# restarted from increment 2.3 (4 nodes slipping, 12 sticking); the committed tractions come
# back from contact/pass1_history (rows 4-6), the committed rows are computed again from the
# displacements (as at every commit). Measured: displacements equal to 1.4e-13, slip 6.1e-12,
# pressures and tractions 2.1e-10 of their largest. The restarted run's sparse pattern lacks
# the node pairs gathered before 2.3, so its factorization rounds differently, and eps_N = 1e8
# turns that into the pressures (one ulp of a position, 5.5e-17, is 3.4e-11 of the largest
# pressure); node-to-segment contact on the same deck differs by 1.0e-10 too. Bound 1e-9.
add_test(NAME restart_contact_mortar
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_contact_test.sh ${FRIX_BIN}
                 ${MORTAR_DIR}/drag_restart.dck 1e-9)
set_tests_properties(restart_contact_mortar PROPERTIES LABELS "regression;contact")

# The patch test at finite strain (patch_finite_strain.dck: the 3 x 3 on 4 x 4 blocks, total
# Lagrangian neo-Hookean, dead pressure p = 1e4 in 5 increments, about 10 % strain, EPSN 1e10).
# Exact: one homogeneous uniaxial state in both blocks, so the other stress components are 0
# and the contact force per reference area is p at every slave node. Measured (2026-11-27):
# slave pressures p to 2.9e-10, other stresses 4.5e-13 of p, 20 Newton iterations (4 per
# increment; TOLRESID 1e-9 above the round-off floor: with 1e-12 the count depended on when the
# floor rule stopped, 22-32).
# One-pass node-to-segment on the same deck: pressures 0.745-1.123 p, other stresses 7.6 % of
# p, 36 iterations. (The checker's szz compares sigma_zz with -p, which holds at small strain
# only: not checked.) Bounds as for the small-strain patch test, 30 iterations.
add_test(NAME contact_mortar_patch_finite_strain
         COMMAND bash ${V5V6_DIR}/run_v5.sh ${FRIX_BIN} ${MORTAR_DIR}/patch_finite_strain.dck 3
                 --check pass_sum=0.99999999:1.00000001 --check pass1_min=0.999999995:1.000000005
                 --check pass1_max=0.999999995:1.000000005 --check tangential=0:1e-10
                 --check upper_soff=0:1e-10 --check lower_soff=0:1e-10 --check upper_err=0:5e-9
                 --max-iterations 30 --pressure 1e4)
set_tests_properties(contact_mortar_patch_finite_strain PROPERTIES LABELS "regression;contact")
