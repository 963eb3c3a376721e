!> Unit tests of the cells library (frix_cells). One line per suite: add yours to the list.
program test_cells
   use frix_testing, only: run_suites, new_testsuite
   use test_reference_cells, only: collect_reference_cells
   implicit none
   call run_suites([ &
                   new_testsuite('reference_cells', collect_reference_cells) &
                   ])
end program test_cells
