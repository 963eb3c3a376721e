!> Unit tests of the core library (frix_core). One line per suite: add yours to the list.
program test_core
   use frix_testing, only: run_suites, new_testsuite
   use test_property_list, only: collect_property_list
   use test_strings, only: collect_strings
   implicit none
   call run_suites([ &
                   new_testsuite('property_list', collect_property_list), &
                   new_testsuite('strings', collect_strings) &
                   ])
end program test_core
