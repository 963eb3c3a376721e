!> Unit tests of the assembly library (frix_assembly).
program test_assembly
   use frix_testing, only: run_suites, new_testsuite
   use test_tie_constraints, only: collect_tie_constraints
   implicit none
   call run_suites([new_testsuite('tie_constraints', collect_tie_constraints)])
end program test_assembly
