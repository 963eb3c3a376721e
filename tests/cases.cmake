# Deck-level tests. The frix binary is run on decks; each family has its own label.
math(EXPR scaled_60 "60 * ${FRIX_TIMEOUT_SCALE}")
math(EXPR scaled_300 "300 * ${FRIX_TIMEOUT_SCALE}")
math(EXPR scaled_600 "600 * ${FRIX_TIMEOUT_SCALE}")
set(FRIX_BIN $<TARGET_FILE:frix>)
# One deck run in a scratch folder, then its Python checker (the benchmark families).
set(run_deck_check ${CMAKE_CURRENT_SOURCE_DIR}/harness/run_deck_check.sh)

# Error cases: every tests/errors/*.dck must be rejected with the message given in its
# `// EXPECT:` lines, without a crash.
file(GLOB error_decks CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/errors/*.dck)
foreach(deck ${error_decks})
  get_filename_component(name ${deck} NAME_WE)
  add_test(NAME errors_${name}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/errors/check_error_case.sh ${FRIX_BIN} ${deck})
  set_tests_properties(errors_${name} PROPERTIES LABELS errors)
endforeach()

# Output checks (shell): VTK files read back with meshio; the listing comparison script.
add_test(NAME io_vtk_readback COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/vtk_readback_test.sh $<TARGET_FILE:test_io>)
add_test(NAME compare_selftest COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/compare_selftest.sh)
set_tests_properties(io_vtk_readback compare_selftest PROPERTIES LABELS unit)

# The fuzzer: mutated decks and gmsh meshes must never crash frix (tests/fuzz/README.md).
include(${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz.cmake OPTIONAL)

# Verification problems (V1 patch tests, V2 Cook's membrane, V3 large deflection, ...).
include(${CMAKE_CURRENT_SOURCE_DIR}/verification/verification.cmake OPTIONAL)

# Driver behaviour on models that cannot be solved (tests/solver/check_run.sh).
set(check_run ${CMAKE_CURRENT_SOURCE_DIR}/solver/check_run.sh)
add_test(NAME solver_unsupported_direction
         COMMAND bash ${check_run} ${FRIX_BIN} ${CMAKE_CURRENT_SOURCE_DIR}/solver/unsupported_direction.dck 1
                 "has no Dirichlet condition in directions y and z")
add_test(NAME solver_rotation_mode
         COMMAND bash ${check_run} ${FRIX_BIN} ${CMAKE_CURRENT_SOURCE_DIR}/solver/rotation_mode.dck 1
                 "the stiffness matrix is singular at node")
# Limit point at t = 0.7698: cut-backs, a failure message that names where the last iterate
# is worst (top nodes 5-8 of the cube, in z), and the converged increments kept.
add_test(NAME solver_limit_point_cutback
         COMMAND bash ${check_run} ${FRIX_BIN} ${CMAKE_CURRENT_SOURCE_DIR}/solver/limit_point_cutback.dck 1
                 "at the smallest increment allowed|, direction z, largest Newton correction "
                 limit_point_cutback.pvd limit_point_cutback_0001_0009.vtu
                 limit_point_cutback_history.csv limit_point_cutback_listing.txt)
# The finite-value guard: step 1 converges and is written, step 2's load overflows (a located
# failure after the cut-backs, no NaN or Inf in any file: check_run.sh).
add_test(NAME solver_overflow_load
         COMMAND bash ${check_run} ${FRIX_BIN} ${CMAKE_CURRENT_SOURCE_DIR}/solver/overflow_load.dck 1
                 "is not finite|at node 3, direction x|the results of the 1 converged increments"
                 overflow_load_0001_0001.vtu overflow_load_history.csv overflow_load.pos overflow_load.h5)
# MAXITER up to the largest integer: the iteration log grows as the iterations go.
add_test(NAME solver_huge_maxiter
         COMMAND bash ${check_run} ${FRIX_BIN} ${CMAKE_CURRENT_SOURCE_DIR}/solver/huge_maxiter.dck 0
                 "3 converged increments" huge_maxiter_0002_0002.vtu)
# Numbers beyond the fixed-width formats: an automatic EPSN of 1.3462E-297 in the progress and
# the listing header (no asterisks: check_run.sh).
add_test(NAME solver_tiny_penalty_factor
         COMMAND bash ${check_run} ${FRIX_BIN} ${CMAKE_CURRENT_SOURCE_DIR}/solver/tiny_penalty_factor.dck 1
                 "EPSN 1.3462E-297 (automatic: 1.0000E-300 x 1.3462E+03" tiny_penalty_factor_listing.txt)
# A TIE between two faces of one body is legitimate (a periodic or seam tie) when the body is
# supported; unsupported it is a deck error (tests/errors/tie_same_body_unsupported.dck).
add_test(NAME solver_tie_same_body
         COMMAND bash ${check_run} ${FRIX_BIN} ${CMAKE_CURRENT_SOURCE_DIR}/solver/tie_same_body.dck 0
                 "1 converged increments")
# Derived output values beyond the range of reals: the von Mises stress of 1e198 stresses, with
# and without POS3D (whose material block writes E = 1e200 finite; check_run.sh: no Inf in any
# file).
add_test(NAME solver_huge_modulus
         COMMAND bash ${check_run} ${FRIX_BIN} ${CMAKE_CURRENT_SOURCE_DIR}/solver/huge_modulus.dck 1
                 "is not written: the von Mises stress (element mean) at element 1 is not finite")
add_test(NAME solver_huge_modulus_pos3d
         COMMAND bash ${check_run} ${FRIX_BIN} ${CMAKE_CURRENT_SOURCE_DIR}/solver/huge_modulus_pos3d.dck 1
                 "is not written: the von Mises stress (element mean) at element 1 is not finite")
set_tests_properties(solver_unsupported_direction solver_rotation_mode solver_limit_point_cutback
                     solver_overflow_load solver_huge_maxiter solver_tiny_penalty_factor solver_tie_same_body
                     solver_huge_modulus solver_huge_modulus_pos3d
                     PROPERTIES LABELS regression)
# SIGINT / SIGTERM stop a run at a safe point (exit 3, files complete, no temporary file);
# SIGKILL during the first increment leaves the contact CSV's header.
foreach(signal INT TERM KILL)
  add_test(NAME solver_stop_sig${signal}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/solver/stop_signal_test.sh ${FRIX_BIN}
                   ${CMAKE_CURRENT_SOURCE_DIR}/solver/stop_signal.dck ${signal})
  set_tests_properties(solver_stop_sig${signal} PROPERTIES LABELS regression TIMEOUT ${scaled_300})
endforeach()
add_test(NAME solver_limit_point_values
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/solver/limit_point_check.sh ${FRIX_BIN}
                 ${CMAKE_CURRENT_SOURCE_DIR}/solver/limit_point_cutback.dck)
set_tests_properties(solver_limit_point_values PROPERTIES LABELS regression)
# Path following (CONTROL Path, docs/solver.md): the same cube passes its limit point with the
# top node's displacement driven; and lands on t = 1 when the full load comes first.
add_test(NAME solver_path_following_limit_point
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/solver/path_following_check.sh ${FRIX_BIN}
                 ${CMAKE_CURRENT_SOURCE_DIR}/solver/limit_point_path.dck 250 passes)
add_test(NAME solver_path_following_landing
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/solver/path_following_check.sh ${FRIX_BIN}
                 ${CMAKE_CURRENT_SOURCE_DIR}/solver/limit_point_path_landing.dck 150 lands)
# A target within the displacement tolerance of the start: the step ends after NUMSTEP
# increments (it repeated increments that did not move before the review of 2026-11-23).
add_test(NAME solver_path_following_target_near_start
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/solver/path_following_check.sh ${FRIX_BIN}
                 ${CMAKE_CURRENT_SOURCE_DIR}/solver/path_target_near_start.dck 250 near)
set_tests_properties(solver_path_following_limit_point solver_path_following_landing
                     solver_path_following_target_near_start PROPERTIES LABELS regression TIMEOUT ${scaled_60})

# POS3D neutral file: writer checks on synthetic data, and a run read back independently.
add_executable(pos3d_writer_check ${PROJECT_SOURCE_DIR}/tests/pos3d/pos3d_writer_check.f90)
set_target_properties(pos3d_writer_check PROPERTIES Fortran_MODULE_DIRECTORY ${PROJECT_BINARY_DIR}/modules/pos3d_check)
target_link_libraries(pos3d_writer_check PRIVATE frix_io)
add_test(NAME pos3d_writer COMMAND bash ${PROJECT_SOURCE_DIR}/tests/pos3d/pos3d_writer_test.sh $<TARGET_FILE:pos3d_writer_check>)
add_test(NAME pos3d_roundtrip COMMAND bash ${PROJECT_SOURCE_DIR}/tests/pos3d/pos3d_roundtrip_test.sh ${FRIX_BIN})
set_tests_properties(pos3d_writer PROPERTIES LABELS unit)
set_tests_properties(pos3d_roundtrip PROPERTIES LABELS regression SKIP_RETURN_CODE 77)

# HDF5 results: write/read round trip (Fortran) and the documented layout (h5py).
add_executable(hdf5_roundtrip_check hdf5/hdf5_roundtrip_suite.f90 hdf5/hdf5_roundtrip_check.f90)
set_target_properties(hdf5_roundtrip_check PROPERTIES Fortran_MODULE_DIRECTORY ${PROJECT_BINARY_DIR}/modules/hdf5_roundtrip_check)
target_link_libraries(hdf5_roundtrip_check PRIVATE frix_io frix_testing)
add_test(NAME hdf5_roundtrip COMMAND hdf5_roundtrip_check)
set_tests_properties(hdf5_roundtrip PROPERTIES LABELS unit ENVIRONMENT FRIX_TEST_OUTPUT_DIR=${CMAKE_CURRENT_BINARY_DIR})
add_test(NAME hdf5_h5py_layout COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/hdf5/h5py_layout_test.sh $<TARGET_FILE:hdf5_roundtrip_check>)
set_tests_properties(hdf5_h5py_layout PROPERTIES LABELS unit)

# Restart from the HDF5 file of an earlier run reaches the same final state.
add_test(NAME restart_beam COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_test.sh ${FRIX_BIN}
         ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_beam.dck)
set_tests_properties(restart_beam PROPERTIES LABELS regression)
# In the plastic range: restarted at the first yield (1.3) and in plastic loading (2.2).
add_test(NAME restart_plastic COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_test.sh ${FRIX_BIN}
         ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_plastic.dck 1.3 2.2)
set_tests_properties(restart_plastic PROPERTIES LABELS "regression;plasticity")
# With a tied interface (S5, TIE): the ties are set up again from the mesh, not read back.
add_test(NAME restart_tied COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_test.sh ${FRIX_BIN}
         ${PROJECT_SOURCE_DIR}/inputs/s5_buried_pipe/s5_tied.dck 1.1 1.3)
set_tests_properties(restart_tied PROPERTIES LABELS "regression;contact")
# After cut-backs, with EXTRAPOLATION Linear: the increment size in force and the last
# increment's displacement rate come back from the HDF5 file (restarts inside steps 1, 2, 3).
add_test(NAME restart_cutback COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_test.sh ${FRIX_BIN}
         ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_cutback.dck 1.2 2.3 3.2)
set_tests_properties(restart_cutback PROPERTIES LABELS regression)
# Inside a CONTROL Path step (before and after the limit point): the driven displacement per
# increment comes back from the HDF5 file.
add_test(NAME restart_path COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_test.sh ${FRIX_BIN}
         ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_path.dck 1.5 1.12)
set_tests_properties(restart_path PROPERTIES LABELS regression)
# Damaged restart files (NaN time or values, a time outside its step, integer displacements,
# an increment not marked complete) are refused with exit 1 and a message naming the damage.
add_test(NAME restart_validation COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_validation_test.sh
         ${FRIX_BIN} ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_s1_augmented.dck)
set_tests_properties(restart_validation PROPERTIES LABELS "regression;contact")

# Post-processing scripts run on real frix output (tests/postproc/test_*.sh).
foreach(script plot_history plot_line render_mesh mohr_coulomb compare_runs cells)
  add_test(NAME postproc_${script}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/postproc/test_${script}.sh ${FRIX_BIN})
  set_tests_properties(postproc_${script} PROPERTIES LABELS postproc)
endforeach()

# Contact benchmarks (labels regression;contact, heavier ones also slow).
foreach(case contact_s1/s1 contact_s4/s4 contact_s4/s4_tl contact_v5v6/v5v6 contact_s3/s3
             contact_s5/s5 contact_autopenalty/autopenalty contact_s6/s6 contact_s2/s2
             contact_free_edge/free_edge
             contact_robustness/robustness contact_mortar/mortar contact_ironing/ironing)
  include(${CMAKE_CURRENT_SOURCE_DIR}/${case}.cmake OPTIONAL)
endforeach()

# Loads against closed forms: body force (self-weight column), follower pressure (neo-Hookean
# cube under hydrostatic follower pressure, total Lagrangian).
add_test(NAME loads_closed_form COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/loads/check_loads.sh ${FRIX_BIN}
         ${CMAKE_CURRENT_SOURCE_DIR}/loads)
set_tests_properties(loads_closed_form PROPERTIES LABELS regression)

# STEP ... RESET_DISPLACEMENT: reported displacements against closed forms in every output,
# and restarts across the resets bit-identical to the uninterrupted run (tests/steps).
add_test(NAME steps_reset_displacement COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/steps/check_reset_displacement.sh
         ${FRIX_BIN} ${CMAKE_CURRENT_SOURCE_DIR}/steps/reset_displacement_column.dck)
add_test(NAME restart_reset_displacement COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/steps/check_reset_restart.sh
         ${FRIX_BIN} ${CMAKE_CURRENT_SOURCE_DIR}/steps/reset_displacement_column.dck)
set_tests_properties(steps_reset_displacement restart_reset_displacement PROPERTIES LABELS regression)

# Regression for the first-increment friction defect found by benchmark P2: stick tractions
# must not depend on the number of increments (bench/p2/check_first_increment_friction.sh).
include(${PROJECT_SOURCE_DIR}/bench/p2/p2_tests.cmake)
add_test(NAME restart_contact COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_contact_test.sh ${FRIX_BIN}
         ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_s1.dck)
set_tests_properties(restart_contact PROPERTIES LABELS "regression;contact")
add_test(NAME restart_contact_augmented COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_contact_test.sh
         ${FRIX_BIN} ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_s1_augmented.dck)
set_tests_properties(restart_contact_augmented PROPERTIES LABELS "regression;contact")

# Write failures (docs/output.md, "When a write fails"): tests/io/fail_writes.c, preloaded,
# makes the writes into one result file fail with ENOSPC as on a full disk; the run must end
# with exit status 1 and a message naming the file, the increments before it readable.
add_library(frix_fail_writes SHARED ${CMAKE_CURRENT_SOURCE_DIR}/io/fail_writes.c)
target_link_libraries(frix_fail_writes PRIVATE ${CMAKE_DL_LIBS})
set(FRIX_FAIL_WRITES $<TARGET_FILE:frix_fail_writes>)
foreach(case hdf5 hdf5_device listing listing_hdf5 history contact vtu pvd pos)
  add_test(NAME io_write_failure_${case}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/io/write_failure_test.sh ${FRIX_BIN} ${FRIX_FAIL_WRITES}
                   ${CMAKE_CURRENT_SOURCE_DIR}/io/write_failure.dck ${case})
  set_tests_properties(io_write_failure_${case} PROPERTIES LABELS regression TIMEOUT ${scaled_60})
endforeach()
# A run killed while it writes the HDF5 file's mesh leaves a file that h5py opens.
add_test(NAME hdf5_kill_during_header
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/hdf5/kill_test.sh ${FRIX_BIN} ${FRIX_FAIL_WRITES}
                 ${CMAKE_CURRENT_SOURCE_DIR}/io/write_failure.dck)
set_tests_properties(hdf5_kill_during_header PROPERTIES LABELS regression TIMEOUT ${scaled_60})
# A real full disk (a small tmpfs; root only, else skipped) under a run with HDF5 on.
add_test(NAME hdf5_disk_full
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/hdf5/disk_full_test.sh ${FRIX_BIN}
                 ${CMAKE_CURRENT_SOURCE_DIR}/io/write_failure.dck)
set_tests_properties(hdf5_disk_full PROPERTIES LABELS regression SKIP_RETURN_CODE 77 TIMEOUT ${scaled_60})

# frix --check on a valid deck lists what it found (docs/deck-format.md, "Checking a deck"):
# the S5 deck's 16 pipe elements (one layer through the wall) give 16 faces on each pipe
# surface; its pair and its element blocks as the deck defines them.
add_test(NAME check_summary_s5 COMMAND ${FRIX_BIN} --check ${PROJECT_SOURCE_DIR}/inputs/s5_buried_pipe/s5_mu0.dck)
set_tests_properties(check_summary_s5 PROPERTIES LABELS regression PASS_REGULAR_EXPRESSION
  "mesh: 846 nodes, 360 elements, 2538 equations.*block 1: 16 elements HEX8-EAS9 .*surfaces \\(faces\\):.* cavity \\(16\\) pipe_outer \\(16\\).*contact pair 1: slave pipe_outer, master cavity, node-to-segment, 1 pass.*steps: 1, 4 nominal increments")
# ... and the couplings: the 20 x 2 x 2 cantilever's end face has 3 x 3 coupled nodes.
add_test(NAME check_summary_coupling COMMAND ${FRIX_BIN} --check ${CMAKE_CURRENT_SOURCE_DIR}/coupling/cantilever_axial.dck)
set_tests_properties(check_summary_coupling PROPERTIES LABELS regression PASS_REGULAR_EXPRESSION
  "coupling 1: 9 nodes to reference node 1001, rotation node 1002")
# A run and its restart joined into one series by postproc/join_restart.py.
add_test(NAME restart_join_series COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/restart/join_restart_test.sh ${FRIX_BIN}
         ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_s1.dck ${PROJECT_SOURCE_DIR}/postproc)
set_tests_properties(restart_join_series PROPERTIES LABELS "regression;contact")
# ParaView opens, warps, colours and renders a frix .pvd (pvpython under xvfb-run); skipped
# (exit 77) where ParaView is not installed.
add_test(NAME paraview_render COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/postproc/paraview_test.sh ${FRIX_BIN})
set_tests_properties(paraview_render PROPERTIES LABELS "paraview;postproc" SKIP_RETURN_CODE 77 TIMEOUT ${scaled_60})
# History totals (RESULTS HISTORY ... SUM / MEAN, HISTORY CONTACT) in the CSV history, the
# listing's TOTALS blocks and the HDF5 file, against closed forms (tests/io/check_totals.py;
# the references are derived in each deck's title).
set(totals ${CMAKE_CURRENT_SOURCE_DIR}/io)
add_test(NAME io_totals_bar
         COMMAND bash ${totals}/run_totals.sh ${FRIX_BIN} ${totals}/totals_bar.dck
                 "r3_sum_bar_zmax=5*t" "r3_sum_bar_zmin=-5*t" "u3_mean_bar_zmax=0.01*t" "u1_mean_bar_xmax=-1.5e-3*t")
# contact resultants: the residual tolerance is 1e-10 of the loads, hence 1e-9; cn_pair1 differs
# from the normal load by the tilt of the deformable master (9e-6 measured, 1e-4 allowed)
foreach(variant contact contact_mortar)
  add_test(NAME io_totals_${variant}
           COMMAND bash ${totals}/run_totals.sh ${FRIX_BIN} ${totals}/totals_${variant}.dck
                   "c1_pair1=-0.9*max(t-1,0)@1e-9" "c2_pair1=0@1e-9" "c3_pair1=10*min(t,1)@1e-9"
                   "cn_pair1=10*min(t,1)@1e-4" "r1_sum_block_zmin=-0.9*max(t-1,0)@1e-9"
                   "r3_sum_block_zmin=10*min(t,1)@1e-9")
endforeach()
add_test(NAME io_totals_contact_plane
         COMMAND bash ${totals}/run_totals.sh ${FRIX_BIN} ${totals}/totals_contact_plane.dck
                 "c1_pair1=-0.9*max(t-1,0)@1e-9" "c2_pair1=0@1e-9" "c3_pair1=10*min(t,1)@1e-9"
                 "cn_pair1=10*min(t,1)@1e-9")
set_tests_properties(io_totals_bar io_totals_contact io_totals_contact_mortar io_totals_contact_plane
                     PROPERTIES LABELS regression TIMEOUT ${scaled_60})
# A reader holding the HDF5 file open while frix runs: frix waits for it, or gives up with a
# clear error after FRIX_HDF5_LOCK_WAIT seconds; the file stays whole (docs/output.md).
add_test(NAME hdf5_reader_during_run
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/hdf5/reader_during_run_test.py ${FRIX_BIN}
                 ${CMAKE_CURRENT_SOURCE_DIR}/hdf5/reader_during_run.dck)
set_tests_properties(hdf5_reader_during_run PROPERTIES LABELS regression TIMEOUT ${scaled_60})
# The Abaqus/CalculiX .inp mesh reader.
include(${CMAKE_CURRENT_SOURCE_DIR}/inp/inp.cmake)
include(${CMAKE_CURRENT_SOURCE_DIR}/tet4/tet4.cmake)
# The pipe-in-soil tutorial's deck (docs/tutorial-pipe-in-soil.md) on its committed gmsh mesh:
# it converges, and the pull on the pipe's ends balances the soil's supports.
set(pipe_in_soil ${PROJECT_SOURCE_DIR}/inputs/examples/pipe_in_soil)
add_test(NAME tutorial_pipe_in_soil
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/inp/run_inp_case.sh ${FRIX_BIN}
                 ${pipe_in_soil}/check_pipe_in_soil.py ${pipe_in_soil}/pipe_in_soil.dck)
set_tests_properties(tutorial_pipe_in_soil PROPERTIES LABELS "regression;contact" TIMEOUT ${scaled_60})
# Kinematic couplings (tests/coupling).
include(${CMAKE_CURRENT_SOURCE_DIR}/coupling/coupling.cmake)
# Thin, long EAS elements (tests/eas_thin)
include(${CMAKE_CURRENT_SOURCE_DIR}/eas_thin/eas_thin.cmake)
# Soil plasticity decks (tests/soil).
include(${CMAKE_CURRENT_SOURCE_DIR}/soil/soil.cmake)
# The initial (in-situ) stress of soil (tests/soil_insitu).
include(${CMAKE_CURRENT_SOURCE_DIR}/soil_insitu/soil_insitu.cmake)
# The strip footing against Prandtl (tests/footing).
include(${CMAKE_CURRENT_SOURCE_DIR}/footing/footing.cmake)
# A buried pipe pulled through sand and clay against ALA and DNV (tests/pipe_soil).
include(${CMAKE_CURRENT_SOURCE_DIR}/pipe_soil/pipe_soil.cmake)
# SOLVER Petsc (tests/solver/petsc.cmake).
include(${CMAKE_CURRENT_SOURCE_DIR}/solver/petsc.cmake)
# Plane strain and axisymmetric elements (tests/plane).
include(${CMAKE_CURRENT_SOURCE_DIR}/plane/plane.cmake)

# Plane meshes read from gmsh and .inp files (tests/mesh2d/README.md).
include(${CMAKE_CURRENT_SOURCE_DIR}/mesh2d/mesh2d.cmake)
