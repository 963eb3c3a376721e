# Thin, long EAS elements (docs/elements.md, "Static condensation and the local alpha iteration"): a plane strain quarter
# of a steel pipe, a = 0.24 m, b = 0.25 m (wall 10 mm), 2 elements through the wall, 16 around,
# 1 along z of 0.75 m: aspect ratio 150, SI units (tests/eas_thin/thin_pipe.msh, written by
# inputs/meshes/ring_mesh.py). HEX8 and HEX8 EAS 9 alike must converge without cut-back
# (check_increments.py: the planned increments and a bound on the Newton iterations of each).
# Elastic, p = 5e6 Pa in one increment: Lame's plane strain u_r(a) = 1.296816e-4 m and
# u_r(b) = 1.273469e-4 m (tests/verification/check_cylinder.py reference --inner 0.24 --outer
# 0.25 --young 2.1e11 --poisson 0.3 --pressure 5e6), within 0.5 % (measured: EAS 9 -0.007 %,
# HEX8 -0.07 % small strain; +0.07 % and +0.01 % total Lagrangian).
set(EAS_THIN_DIR ${CMAKE_CURRENT_SOURCE_DIR}/eas_thin)
foreach(variant hex8_lin eas9_lin hex8_tl eas9_tl)
  add_test(NAME eas_thin_pipe_elastic_${variant}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/verification/run_case.sh ${FRIX_BIN}
                   ${EAS_THIN_DIR}/thin_pipe_elastic_${variant}.dck
                   --check u1_n1 1 1.296816327e-4 0.005 "u_r(a) vs Lame"
                   --check u1_n3 1 1.273469388e-4 0.005 "u_r(b) vs Lame"
                   --script ${EAS_THIN_DIR}/check_increments.py "1 2")
  set_tests_properties(eas_thin_pipe_elastic_${variant} PROPERTIES LABELS "regression;plasticity")
endforeach()
# Plastic, H = E/100, p to 1.75e7 Pa (every point yields; the perfectly plastic limit is
# 1.6734e7 Pa) in 1 + 5 increments, small strain: u_r(a) = 2.144618e-3 m and u_r(b) =
# 2.070301e-3 m from the independent 1D solution (tests/verification/tube_plane_strain_1d.py
# --inner 0.24 --outer 0.25 --young 2.1e11 --poisson 0.3 --sigy 3.55e8 --hard 2.1e9
# --pressure 17.5e6 --elements 50 --step 1e5). EAS 9 within 0.5 % (measured +0.20 %); HEX8
# within 2 % (measured -1.34 %: two plain bricks through the wall lock against the isochoric
# plastic flow of plane strain).
foreach(variant eas9 hex8)
  if(variant STREQUAL eas9)
    set(tolerance 0.005)
  else()
    set(tolerance 0.02)
  endif()
  add_test(NAME eas_thin_pipe_plastic_${variant}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/verification/run_case.sh ${FRIX_BIN}
                   ${EAS_THIN_DIR}/thin_pipe_plastic_${variant}_lin.dck
                   --check u1_n1 1 2.144618069e-3 ${tolerance} "u_r(a) vs 1D plane strain solution"
                   --check u1_n3 1 2.070300936e-3 ${tolerance} "u_r(b) vs 1D plane strain solution"
                   --script ${EAS_THIN_DIR}/check_increments.py "6 8")
  set_tests_properties(eas_thin_pipe_plastic_${variant} PROPERTIES LABELS "regression;plasticity")
endforeach()
# The bar of docs/materials.md "Known limits" (HEX8 EAS 9, H/E = 6e-4, 2 increments, MAXCUT 2):
# the run must end at t = 1 (it stopped at t = 0.31 while the local iteration cycled); its pulled
# end at the prescribed u_x = 0.02 (node 10), 4 increments with the 2 cut-backs of the global
# iteration at the first one.
add_test(NAME eas_thin_bar_near_perfect_plasticity
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/verification/run_case.sh ${FRIX_BIN}
                 ${EAS_THIN_DIR}/bar_near_perfect_eas9.dck
                 --check u1_n10 1 0.02 1e-12 "u_x at the pulled end, t = 1"
                 --script ${EAS_THIN_DIR}/check_increments.py "4 25")
set_tests_properties(eas_thin_bar_near_perfect_plasticity PROPERTIES LABELS "regression;plasticity")
