# Mortar contact (DISCRETIZATION Mortar, docs/contact.md "Mortar contact"), included by
# tests/cases.cmake, which defines FRIX_BIN. Labels regression;contact.
set(MORTAR_DIR ${CMAKE_CURRENT_SOURCE_DIR}/contact_mortar)
set(V5V6_DIR ${CMAKE_CURRENT_SOURCE_DIR}/contact_v5v6)

# Contact patch test with ONE pass (patch_*.dck: the V5 blocks, non-matching 3 x 3 or 5 x 5 on
# 4 x 4). Exact solution (closed form): sigma_zz = -p in both blocks, all other stresses 0,
# contact pressure p at every slave node. Measured (2026-11-27): slave pressures equal to p
# within 5.1e-10 (3 x 3 upper), 7.5e-10 (lower under 3 x 3), 1.3e-9 (5 x 5 upper), 6.4e-10 (lower
# under 5 x 5); stresses within 5.1e-13 of p. The pressure is eps_N times a gap of -p/eps_N =
# -1e-6 computed from positions of about 0.5: its round-off is 1e-16 x 0.5/1e-6 = 5e-11 per
# term, summed over the row's 10-20 terms. Bounds: 5e-9 on the pressures (the slave side's
# <slave>_err and pass1_min/max), 1e-10 on the stresses, 1e-8 on the load balance pass_sum.
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
# (every slave node) 1.5 % of p0, ripple 1.2 % of p0; 30 Newton iterations in 4 increments,
# 12 s on the shared 2-core machine. Node-to-segment on the same meshes: p0_ratio 0.8456,
# max_err 15.4 %, ripple 22 % (the pressure alternates from node to node). Bounds: 2 % of p0
# for p0, a and every node's error (the issue's target), 2.5 % for the ripple (twice the
# measured value, a tenth of node-to-segment's), the V6 bounds for the rest.
add_test(NAME contact_mortar_hertz_nonaligned
         COMMAND bash ${V5V6_DIR}/run_v6.sh ${FRIX_BIN} ${MORTAR_DIR}/hertz_nonaligned.dck
                 --check p0_ratio=0.98:1.02 --check a_fit_ratio=0.98:1.02 --check p0_fit_ratio=0.98:1.02
                 --check a_last_ratio=0:1 --check a_open_ratio=1:2 --check force_ratio=0.99:1.01
                 --check max_err_all=0:0.02 --check ripple=0:0.025)
set_tests_properties(contact_mortar_hertz_nonaligned PROPERTIES LABELS "regression;contact")
