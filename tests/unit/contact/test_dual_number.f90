!> Dual numbers against hand-differentiated functions (reference: the analytic derivatives
!> written in each test).
module test_dual_number
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close
   use frix_dual_number, only: dual_t, dual_variable, dual_constant, dual_dot, dual_cross, dual_norm, dual_sum, &
                               operator(+), operator(-), operator(*), operator(/), operator(**), &
                               operator(<), operator(>), sqrt, abs, assignment(=)
   implicit none
   private

   public :: collect_dual_number

contains

   subroutine collect_dual_number(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('arithmetic and sqrt: gradient of a rational function', test_arithmetic), &
               new_unittest('dot, cross, norm: gradients', test_vector_helpers), &
               new_unittest('constants, assignment, comparisons, abs', test_constants)]
   end subroutine collect_dual_number

   !> f(x, y) = x y / sqrt(x^2 + y^2) + x^3 - 2/y + (x - y)/3;
   !> df/dx = y^3/r^3 + 3 x^2 + 1/3, df/dy = x^3/r^3 + 2/y^2 - 1/3, r = sqrt(x^2 + y^2).
   subroutine test_arithmetic(error)
      type(error_t), allocatable, intent(out) :: error
      type(dual_t) :: q(2), f
      real(dp), parameter :: x = 0.7_dp, y = -1.3_dp
      real(dp) :: r
      q = dual_variable([x, y], 4)
      f = q(1)*q(2)/sqrt(q(1)**2 + q(2)**2) + q(1)**3 - 2.0_dp/q(2) + (q(1) - q(2))/3.0_dp
      r = sqrt(x**2 + y**2)
      call check_close(error, f%value, x*y/r + x**3 - 2.0_dp/y + (x - y)/3.0_dp, 1.0e-15_dp, message='value')
      if (allocated(error)) return
      call check_close(error, f%gradient(4), y**3/r**3 + 3.0_dp*x**2 + 1.0_dp/3.0_dp, 1.0e-14_dp, message='df/dx')
      if (allocated(error)) return
      call check_close(error, f%gradient(5), x**3/r**3 + 2.0_dp/y**2 - 1.0_dp/3.0_dp, 1.0e-14_dp, message='df/dy')
      if (allocated(error)) return
      call check(error, all(f%gradient(1:3) == 0.0_dp) .and. all(f%gradient(6:) == 0.0_dp), 'unseeded entries zero')
   end subroutine test_arithmetic

   !> With a = (q1, q2, q3), b = (1, 2, q1), by hand:
   !> a.b = q1 + 2 q2 + q3 q1 -> (1 + q3, 2, q1); (a x b)_3 = 2 q1 - q2 -> (2, -1, 0);
   !> d|a|/dq = a/|a|.
   subroutine test_vector_helpers(error)
      type(error_t), allocatable, intent(out) :: error
      type(dual_t) :: a(3), b(3), c(3), s
      real(dp), parameter :: v(3) = [0.3_dp, -0.5_dp, 1.1_dp]
      a = dual_variable(v, 1)
      b(1:2) = dual_constant([1.0_dp, 2.0_dp])
      b(3) = a(1)
      s = dual_dot(a, b)
      call check(error, maxval(abs(s%gradient(1:3) - [1.0_dp + v(3), 2.0_dp, v(1)])) <= 1.0e-15_dp, 'd(a.b)')
      if (allocated(error)) return
      c = dual_cross(a, b)
      call check(error, maxval(abs(c(3)%gradient(1:3) - [2.0_dp, -1.0_dp, 0.0_dp])) <= 1.0e-15_dp, 'd(a x b)_3')
      if (allocated(error)) return
      s = dual_norm(a)
      call check(error, maxval(abs(s%gradient(1:3) - v/norm2(v))) <= 1.0e-15_dp, 'd|a|')
      if (allocated(error)) return
      s = dual_sum(a)
      call check(error, all(s%gradient(1:3) == 1.0_dp) .and. abs(s%value - sum(v)) <= 1.0e-15_dp, 'sum')
   end subroutine test_vector_helpers

   subroutine test_constants(error)
      type(error_t), allocatable, intent(out) :: error
      type(dual_t) :: a, b, seeded(1)
      a = 2.5_dp
      call check(error, a%value == 2.5_dp .and. all(a%gradient == 0.0_dp), 'assignment from real')
      if (allocated(error)) return
      seeded = dual_variable([-1.5_dp], 15)
      b = abs(seeded(1))
      call check(error, b%value == 1.5_dp .and. b%gradient(15) == -1.0_dp, 'abs of a negative value')
      if (allocated(error)) return
      call check(error, b < a .and. a > b .and. .not. (a < 2.0_dp), 'comparisons on the value')
      if (allocated(error)) return
      b = b**0
      call check(error, b%value == 1.0_dp .and. all(b%gradient == 0.0_dp), 'power 0')
   end subroutine test_constants
end module test_dual_number
