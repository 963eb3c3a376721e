!> Unit tests of src/linalg. Set FRIX_LINALG_BENCHMARK=1 to add the (untimed, printing)
!> pattern + assembly benchmark on the 50^3 HEX8 cube.
program test_linalg
   use frix_testing, only: run_suites, new_testsuite, testsuite_t
   use test_sparse_matrix, only: collect_sparse_matrix
   use test_direct_solvers, only: collect_direct_solvers
   use test_auto_solver, only: collect_auto_solver
   use test_linalg_benchmark, only: collect_linalg_benchmark
   implicit none
   integer :: length
   call get_environment_variable('FRIX_LINALG_BENCHMARK', length=length)
   if (length > 0) then
      call run_suites([new_testsuite('benchmark', collect_linalg_benchmark)])
   else
      call run_suites([new_testsuite('sparse_matrix', collect_sparse_matrix), &
                       new_testsuite('direct_solvers', collect_direct_solvers), &
                       new_testsuite('auto_solver', collect_auto_solver)])
   end if
end program test_linalg
