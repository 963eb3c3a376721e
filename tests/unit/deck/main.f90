!> Unit tests of the deck library (frix_deck). One line per suite: add yours to the list.
program test_deck
   use frix_testing, only: run_suites, new_testsuite
   use test_deck_reader, only: collect_deck_reader
   implicit none
   call run_suites([new_testsuite('deck_reader', collect_deck_reader)])
end program test_deck
