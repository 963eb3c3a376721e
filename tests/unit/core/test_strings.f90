!> Unit tests of frix_strings' fixed-width helpers: padded, scientific and fixed_point give the
!> text of the edit descriptors they replace where a value fits and never asterisks.
module test_strings
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, ieee_quiet_nan
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check
   use frix_strings, only: padded, scientific, fixed_point
   implicit none
   private

   public :: collect_strings

contains

   subroutine collect_strings(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [ &
              new_unittest('padded right-justifies, never truncates', test_padded), &
              new_unittest('scientific: two exponent digits, three when needed', test_scientific), &
              new_unittest('fixed_point: F format, scientific beyond 1e15', test_fixed_point) &
              ]
   end subroutine collect_strings

   subroutine test_padded(error)
      type(error_t), allocatable, intent(out) :: error
      call check(error, padded('12', 4) == '  12', 'padded 12 in 4: "'//padded('12', 4)//'"')
      if (allocated(error)) return
      call check(error, padded('123456', 4) == '123456', 'padded 123456 in 4: "'//padded('123456', 4)//'"')
   end subroutine test_padded

   subroutine test_scientific(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: infinity
      call check(error, scientific(5384.6_dp, 4) == '5.3846E+03', 'E+03: '//scientific(5384.6_dp, 4))
      if (allocated(error)) return
      call check(error, scientific(1.0e-300_dp, 4) == '1.0000E-300', 'E-300: '//scientific(1.0e-300_dp, 4))
      if (allocated(error)) return
      call check(error, scientific(-1.3462e-297_dp, 4) == '-1.3462E-297', 'negative: '//scientific(-1.3462e-297_dp, 4))
      if (allocated(error)) return
      call check(error, scientific(0.0_dp, 4) == '0.0000E+00', 'zero: '//scientific(0.0_dp, 4))
      if (allocated(error)) return
      infinity = ieee_value(1.0_dp, ieee_positive_inf)
      call check(error, scientific(infinity, 4) == 'Infinity', 'infinity: '//scientific(infinity, 4))
      if (allocated(error)) return
      call check(error, scientific(ieee_value(1.0_dp, ieee_quiet_nan), 4) == 'NaN', 'NaN')
   end subroutine test_scientific

   subroutine test_fixed_point(error)
      type(error_t), allocatable, intent(out) :: error
      call check(error, fixed_point(0.5_dp, 2) == '0.50', 'f .2: '//fixed_point(0.5_dp, 2))
      if (allocated(error)) return
      call check(error, fixed_point(-12.25_dp, 1) == '-12.2' .or. fixed_point(-12.25_dp, 1) == '-12.3', &
                 'negative: '//fixed_point(-12.25_dp, 1))
      if (allocated(error)) return
      call check(error, fixed_point(3.0e20_dp, 1) == '3.0E+20', 'beyond 1e15: '//fixed_point(3.0e20_dp, 1))
      if (allocated(error)) return
      call check(error, index(fixed_point(-huge(1.0_dp), 1), '*') == 0, 'no asterisks: '//fixed_point(-huge(1.0_dp), 1))
   end subroutine test_fixed_point
end module test_strings
