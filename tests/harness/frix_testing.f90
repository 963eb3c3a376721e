!> A small unit-test harness in the shape of fortran-lang/test-drive: a suite is a
!> `collect_<suite>` subroutine returning named tests; `run_suites` runs them, prints one
!> line per test and a closing "N passed, N failed" line, and stops with a non-zero code on
!> failure. Real comparisons pass when |actual - expected| <= max(abs_tol, rel_tol |expected|).
module frix_testing
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   implicit none
   private

   public :: unittest_t, new_unittest, test_procedure, collect_interface
   public :: check, check_close, check_message_contains, run_suites, testsuite_t, new_testsuite
   public :: output_path

   abstract interface
      !> One test: leaves `error` unallocated on success.
      subroutine test_procedure(error)
         import :: error_t
         type(error_t), allocatable, intent(out) :: error
      end subroutine test_procedure
   end interface

   !> The longest test or suite name. Names are fixed-length (blank-padded) rather than
   !> allocatable: the suites build their lists as array constructors of `new_unittest` /
   !> `new_testsuite` results, and gfortran 12 leaks the allocatable components of function
   !> results in an array constructor (LeakSanitizer, scripts/check.sh sanitize).
   integer, parameter :: name_length = 160

   type :: unittest_t
      character(len=name_length) :: name = ''
      procedure(test_procedure), pointer, nopass :: test => null()
   end type unittest_t

   abstract interface
      subroutine collect_interface(tests)
         import :: unittest_t
         type(unittest_t), allocatable, intent(out) :: tests(:)
      end subroutine collect_interface
   end interface

   type :: testsuite_t
      character(len=name_length) :: name = ''
      procedure(collect_interface), pointer, nopass :: collect => null()
   end type testsuite_t

   interface check
      module procedure check_logical
   end interface check

contains

   function new_unittest(name, test) result(unittest)
      character(len=*), intent(in) :: name
      procedure(test_procedure) :: test
      type(unittest_t) :: unittest
      call check_name_length(name)
      unittest%name = name
      unittest%test => test
   end function new_unittest

   function new_testsuite(name, collect) result(suite)
      character(len=*), intent(in) :: name
      procedure(collect_interface) :: collect
      type(testsuite_t) :: suite
      call check_name_length(name)
      suite%name = name
      suite%collect => collect
   end function new_testsuite

   subroutine check_name_length(name)
      character(len=*), intent(in) :: name
      if (len(name) > name_length) then
         write (0, '(a)') 'frix_testing: name longer than '//to_string(name_length)//' characters: '//name
         error stop 2
      end if
   end subroutine check_name_length

   subroutine check_logical(error, condition, message)
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in) :: condition
      character(len=*), intent(in) :: message
      if (.not. condition) call fatal_error(error, message)
   end subroutine check_logical

   !> Fails unless |actual - expected| <= max(abs_tol, rel_tol*|expected|); NaN always fails.
   subroutine check_close(error, actual, expected, rel_tol, abs_tol, message)
      type(error_t), allocatable, intent(out) :: error
      real(dp), intent(in) :: actual, expected
      real(dp), intent(in) :: rel_tol
      real(dp), intent(in), optional :: abs_tol
      character(len=*), intent(in) :: message
      real(dp) :: tolerance
      tolerance = rel_tol*abs(expected)
      if (present(abs_tol)) tolerance = max(tolerance, abs_tol)
      if (.not. (abs(actual - expected) <= tolerance)) then
         call fatal_error(error, message//': got '//to_string(actual)//', expected '// &
                          to_string(expected)//' (tolerance '//to_string(tolerance)//')')
      end if
   end subroutine check_close

   subroutine check_message_contains(error, actual_error, fragment)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable, intent(in) :: actual_error
      character(len=*), intent(in) :: fragment
      if (.not. allocated(actual_error)) then
         call fatal_error(error, 'expected an error containing "'//fragment//'", got none')
      else if (index(actual_error%message, fragment) == 0) then
         call fatal_error(error, 'expected an error containing "'//fragment//'", got: '// &
                          actual_error%message)
      end if
   end subroutine check_message_contains

   !> Run every test of every suite (or only the suite named by the first command
   !> argument), print the outcome, and stop with code 1 if any failed.
   subroutine run_suites(suites)
      type(testsuite_t), intent(in) :: suites(:)
      type(unittest_t), allocatable :: tests(:)
      type(error_t), allocatable :: error
      character(len=256) :: only
      integer :: i, j, passed, failed
      only = ''
      if (command_argument_count() >= 1) call get_command_argument(1, only)
      passed = 0
      failed = 0
      do i = 1, size(suites)
         if (len_trim(only) > 0 .and. trim(only) /= trim(suites(i)%name)) cycle
         call suites(i)%collect(tests)
         do j = 1, size(tests)
            call tests(j)%test(error)
            if (allocated(error)) then
               failed = failed + 1
               write (*, '(a)') '  FAIL  '//trim(suites(i)%name)//' / '//trim(tests(j)%name)
               write (*, '(a)') '        '//error%message
               deallocate (error)
            else
               passed = passed + 1
               write (*, '(a)') '  ok    '//trim(suites(i)%name)//' / '//trim(tests(j)%name)
            end if
         end do
      end do
      write (*, '(a)') to_string(passed)//' passed, '//to_string(failed)//' failed'
      if (failed > 0) error stop 1
      if (passed == 0) error stop 77
   end subroutine run_suites

   !> `name` in the folder named by the environment variable FRIX_TEST_OUTPUT_DIR, else in the
   !> working directory: where the test suites write their files.
   function output_path(name) result(path)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: path
      character(len=1024) :: folder
      integer :: length, stat
      call get_environment_variable('FRIX_TEST_OUTPUT_DIR', folder, length, stat)
      if (stat == 0 .and. length > 0) then
         path = trim(folder)//'/'//name
      else
         path = name
      end if
   end function output_path
end module frix_testing
