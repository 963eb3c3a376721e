!> Unit tests of the assembly library (frix_assembly).
program test_assembly
   use frix_testing, only: run_suites, new_testsuite
   use test_tie_constraints, only: collect_tie_constraints
   use test_surface_stiffness, only: collect_surface_stiffness
   use test_analysis_state, only: collect_analysis_state
   use test_kinematic_coupling, only: collect_kinematic_coupling
   use test_initial_stress_points, only: collect_initial_stress_points
   implicit none
   call run_suites([new_testsuite('tie_constraints', collect_tie_constraints), &
                    new_testsuite('surface_stiffness', collect_surface_stiffness), &
                    new_testsuite('analysis_state', collect_analysis_state), &
                    new_testsuite('kinematic_coupling', collect_kinematic_coupling), &
                    new_testsuite('initial_stress_points', collect_initial_stress_points)])
end program test_assembly
