!> Unit tests of the assembly library (frix_assembly).
program test_assembly
   use frix_testing, only: run_suites, new_testsuite
   use test_tie_constraints, only: collect_tie_constraints
   use test_surface_stiffness, only: collect_surface_stiffness
   use test_analysis_state, only: collect_analysis_state
   implicit none
   call run_suites([new_testsuite('tie_constraints', collect_tie_constraints), &
                    new_testsuite('surface_stiffness', collect_surface_stiffness), &
                    new_testsuite('analysis_state', collect_analysis_state)])
end program test_assembly
