!> Unit tests of the core library (frix_core). One line per suite: add yours to the list.
program test_core
   use frix_testing, only: run_suites, new_testsuite
   use test_property_list, only: collect_property_list
   implicit none
   call run_suites([ &
                   new_testsuite('property_list', collect_property_list) &
                   ])
end program test_core
