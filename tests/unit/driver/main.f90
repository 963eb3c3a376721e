!> Unit tests of the driver library (frix_driver). One line per suite: add yours to the list.
program test_driver
   use frix_testing, only: run_suites, new_testsuite
   use test_results_output, only: collect_results_output
   use test_factor_reuse, only: collect_factor_reuse
   implicit none
   call run_suites([new_testsuite('results_output', collect_results_output), &
                    new_testsuite('factor_reuse', collect_factor_reuse)])
end program test_driver
