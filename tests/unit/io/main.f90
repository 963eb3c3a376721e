!> Unit tests of the io library (frix_io). One line per suite: add yours to the list.
program test_io
   use frix_testing, only: run_suites, new_testsuite
   use test_field_recovery, only: collect_field_recovery
   use test_listing_writer, only: collect_listing_writer
   use test_history_writer, only: collect_history_writer
   use test_vtk_writer, only: collect_vtk_writer
   implicit none
   call run_suites([ &
                   new_testsuite('field_recovery', collect_field_recovery), &
                   new_testsuite('listing_writer', collect_listing_writer), &
                   new_testsuite('history_writer', collect_history_writer), &
                   new_testsuite('vtk_writer', collect_vtk_writer) &
                   ])
end program test_io
