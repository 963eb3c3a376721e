!> Unit tests of frix_property_list: construction, case-insensitive names, required and
!> defaulted values, whole numbers, every mistake reported, specs, restriction, comparison.
module test_property_list
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_message_contains
   use frix_property_list, only: property_list_t, property_spec_t, new_property_list, joined, &
                                 keyword_index, spec_names
   implicit none
   private

   public :: collect_property_list

contains

   subroutine collect_property_list(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [ &
              new_unittest('names match in any case, last value wins', test_take_real), &
              new_unittest('missing required property reported', test_missing), &
              new_unittest('sizes of names and values must agree', test_sizes), &
              new_unittest('every bad name reported at once', test_check_names), &
              new_unittest('whole numbers', test_take_integer), &
              new_unittest('set replaces a value', test_set), &
              new_unittest('spec bounds', test_spec_bounds), &
              new_unittest('restricted_to keeps the spec names with defaults', test_restricted), &
              new_unittest('same_as ignores order', test_same_as), &
              new_unittest('keyword_index and joined', test_keywords) &
              ]
   end subroutine collect_property_list

   subroutine test_take_real(error)
      type(error_t), allocatable, intent(out) :: error
      type(property_list_t) :: list
      real(dp) :: value
      logical :: found
      call new_property_list('LAW', ['young', 'NUE  ', 'Young'], [1.0_dp, 0.3_dp, 2.0_dp], list, error)
      if (allocated(error)) return
      call list%take_real('YOUNG', value, found, error)
      if (allocated(error)) return
      call check(error, found .and. value == 2.0_dp .and. list%count() == 3, 'YOUNG: the last value given')
      if (allocated(error)) return
      call list%take_real(' nue', value, found, error)
      if (allocated(error)) return
      call check(error, found .and. value == 0.3_dp, 'asked for in lower case: nue = NUE')
      if (allocated(error)) return
      call list%take_real('DENS', value, found, error, default=7.0_dp)
      if (allocated(error)) return
      call check(error, .not. found .and. value == 7.0_dp, 'DENS defaults to 7')
   end subroutine test_take_real

   subroutine test_missing(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: failure
      type(property_list_t) :: list
      real(dp) :: value
      logical :: found
      call new_property_list('MAT_X', [character(len=4) ::], [real(dp) ::], list, error)
      if (allocated(error)) return
      call list%take_real('YOUNG', value, found, failure)
      call check_message_contains(error, failure, 'MAT_X: missing property YOUNG')
   end subroutine test_missing

   subroutine test_sizes(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: failure
      type(property_list_t) :: list
      call new_property_list('LAW', ['A', 'B'], [1.0_dp], list, failure)
      call check_message_contains(error, failure, 'LAW: 2 property names but 1 values')
   end subroutine test_sizes

   subroutine test_check_names(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: failure
      type(property_list_t) :: list
      call new_property_list('LAW', ['MU ', 'MU ', 'FOO'], [1.0_dp, 2.0_dp, 3.0_dp], list, error)
      if (allocated(error)) return
      call list%check_names(['MU ', 'EPS'], failure)
      call check_message_contains(error, failure, 'LAW: property MU given twice')
      if (allocated(error)) return
      call check_message_contains(error, failure, 'LAW: unknown property "FOO" (valid: MU, EPS)')
      if (allocated(error)) return
      deallocate (failure)
      call list%check_names([character(len=2) ::], failure)
      call check_message_contains(error, failure, 'LAW: takes no property, got "MU"')
   end subroutine test_check_names

   subroutine test_take_integer(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: failure
      type(property_list_t) :: list
      integer :: value
      logical :: found
      call new_property_list('HEX8', ['EAS', 'GP '], [9.0_dp, 2.5_dp], list, error)
      if (allocated(error)) return
      call list%take_integer('EAS', value, found, error, default=0)
      if (allocated(error)) return
      call check(error, found .and. value == 9, 'EAS 9')
      if (allocated(error)) return
      call list%take_integer('GP', value, found, failure)
      call check_message_contains(error, failure, 'HEX8: GP must be a whole number, got 2.5')
      if (allocated(error)) return
      call list%take_integer('N', value, found, error, default=4)
      if (allocated(error)) return
      call check(error, .not. found .and. value == 4, 'N defaults to 4')
   end subroutine test_take_integer

   subroutine test_set(error)
      type(error_t), allocatable, intent(out) :: error
      type(property_list_t) :: list
      call list%set('eas', 3.0_dp)
      call list%set('EAS', 9.0_dp)
      call list%set('mu', 0.5_dp)
      call check(error, list%count() == 2 .and. list%names(1) == 'EAS' .and. list%values(1) == 9.0_dp .and. &
                 list%names(2) == 'MU', 'set replaces EAS and adds MU')
   end subroutine test_set

   subroutine test_spec_bounds(error)
      type(error_t), allocatable, intent(out) :: error
      type(property_spec_t) :: spec
      call check(error, spec%admits(-1.0_dp), 'an unbounded spec admits anything')
      if (allocated(error)) return
      spec%bounded = .true.
      call check(error, spec%admits(0.0_dp) .and. .not. spec%admits(-1.0e-300_dp), '>= 0')
      if (allocated(error)) return
      spec%strict = .true.
      call check(error, .not. spec%admits(0.0_dp) .and. spec%admits(1.0e-300_dp), '> 0')
   end subroutine test_spec_bounds

   subroutine test_restricted(error)
      type(error_t), allocatable, intent(out) :: error
      type(property_list_t) :: list, restricted
      type(property_spec_t) :: specs(3)
      specs%name = ['MU ', 'EPS', 'K  ']
      specs(2)%has_default = .true.
      specs(2)%default = 4.0_dp
      call new_property_list('PAIR', ['FOO', 'MU '], [1.0_dp, 0.2_dp], list, error)
      if (allocated(error)) return
      restricted = list%restricted_to(specs)
      call check(error, restricted%count() == 2 .and. restricted%names(1) == 'MU' .and. &
                 restricted%values(1) == 0.2_dp .and. restricted%names(2) == 'EPS' .and. &
                 restricted%values(2) == 4.0_dp .and. restricted%owner == 'PAIR', &
                 'MU as given, EPS defaulted, K and FOO left out')
      if (allocated(error)) return
      call check(error, all(spec_names(specs) == ['MU ', 'EPS', 'K  ']), 'spec_names')
   end subroutine test_restricted

   subroutine test_same_as(error)
      type(error_t), allocatable, intent(out) :: error
      type(property_list_t) :: a, b, c
      call new_property_list('A', ['X', 'Y'], [1.0_dp, 2.0_dp], a, error)
      if (allocated(error)) return
      call new_property_list('B', ['y', 'x'], [2.0_dp, 1.0_dp], b, error)
      if (allocated(error)) return
      call new_property_list('C', ['X'], [1.0_dp], c, error)
      if (allocated(error)) return
      call check(error, a%same_as(b) .and. .not. a%same_as(c) .and. .not. c%same_as(a), 'same_as')
   end subroutine test_same_as

   subroutine test_keywords(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=12), parameter :: keywords(2) = ['COULOMB     ', 'FRICTIONLESS']
      call check(error, keyword_index(keywords, ' frictionless ') == 2 .and. keyword_index(keywords, 'TRESCA') == 0, &
                 'keyword_index')
      if (allocated(error)) return
      call check(error, joined(keywords) == 'COULOMB, FRICTIONLESS', 'joined: '//joined(keywords))
   end subroutine test_keywords
end module test_property_list
