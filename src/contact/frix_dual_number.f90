!> Forward-mode automatic differentiation with dual numbers of a fixed gradient length.
!>
!> A dual number carries a value v and its gradient dv/dq with respect to up to `dual_size`
!> seeded unknowns q (for the contact kernel: the current coordinates of a slave node, its
!> 4-node master face, the 4-node face that carries its slip anchor and, with smoothed
!> normals, the face's 4 nodal normals: 3 x 13 = 39). Every operation applies the chain rule to the gradient, so a
!> computation written with `dual_t` yields the exact derivative of the discrete algorithm it
!> performs (Griewank & Walther, *Evaluating Derivatives*, 2nd ed., SIAM 2008, ch. 3; this is
!> how AceGen-generated contact elements obtain consistent tangents, Korelc & Wriggers,
!> *Automation of Finite Element Methods*, Springer 2016).
!>
!> Comparisons (< <= > >=) look at the value only: a branch taken by the algorithm is
!> differentiated as taken, which is the derivative of that branch.
!> All operations are elemental, so arrays of duals combine like arrays of reals;
!> `matmul`, `dot_product` and `sum` do not exist for derived types: use `dual_dot`,
!> `dual_cross`, `dual_norm` and `dual_sum`.
module frix_dual_number
   use frix_kinds, only: dp
   implicit none
   private

   public :: dual_t, dual_size, dual_length, set_dual_length
   public :: dual_constant, dual_variable, dual_values
   public :: dual_dot, dual_cross, dual_norm, dual_sum
   public :: operator(+), operator(-), operator(*), operator(/), operator(**)
   public :: operator(<), operator(<=), operator(>), operator(>=)
   public :: sqrt, abs, assignment(=)

   integer, parameter :: dual_size = 39  !! maximum number of seeded unknowns
   !> The gradient entries the operations compute, 1..dual_length (<= dual_size): a caller that
   !> seeds fewer unknowns sets it (set_dual_length) and reads no entry beyond it; the others
   !> are left undefined. dual_size unless set.
   integer, protected :: dual_length = dual_size

   !> A value and its gradient with respect to the seeded unknowns (entries beyond dual_length
   !> undefined: no default initialization, which would cost every temporary dual_size stores).
   type :: dual_t
      real(dp) :: value = 0.0_dp                   !! v
      real(dp) :: gradient(dual_size)              !! dv/dq_k, k = 1..dual_length
   end type dual_t

   interface operator(+)
      module procedure add_dd, add_dr, add_rd, plus_d
   end interface operator(+)
   interface operator(-)
      module procedure subtract_dd, subtract_dr, subtract_rd, minus_d
   end interface operator(-)
   interface operator(*)
      module procedure multiply_dd, multiply_dr, multiply_rd
   end interface operator(*)
   interface operator(/)
      module procedure divide_dd, divide_dr, divide_rd
   end interface operator(/)
   interface operator(**)
      module procedure power_di
   end interface operator(**)
   interface operator(<)
      module procedure less_dd, less_dr
   end interface operator(<)
   interface operator(<=)
      module procedure less_equal_dd, less_equal_dr
   end interface operator(<=)
   interface operator(>)
      module procedure greater_dd, greater_dr
   end interface operator(>)
   interface operator(>=)
      module procedure greater_equal_dd, greater_equal_dr
   end interface operator(>=)
   interface sqrt
      module procedure sqrt_d
   end interface sqrt
   interface abs
      module procedure abs_d
   end interface abs
   interface assignment(=)
      module procedure assign_real
   end interface assignment(=)

contains

   !> Set the number of gradient entries the operations compute (1..dual_size) and return the
   !> previous one, to be set again when the caller is done.
   subroutine set_dual_length(length, previous)
      integer, intent(in) :: length
      integer, intent(out), optional :: previous
      if (present(previous)) previous = dual_length
      dual_length = max(1, min(dual_size, length))
   end subroutine set_dual_length

   !> A constant: value `value`, zero gradient.
   elemental function dual_constant(value) result(d)
      real(dp), intent(in) :: value
      type(dual_t) :: d
      d%value = value
      d%gradient(:dual_length) = 0.0_dp
   end function dual_constant

   !> Seeded unknowns: values(k) becomes unknown number first_index + k - 1
   !> (gradient = unit vector of that index).
   pure function dual_variable(values, first_index) result(d)
      real(dp), intent(in) :: values(:)
      integer, intent(in) :: first_index   !! 1 .. dual_size - size(values) + 1
      type(dual_t) :: d(size(values))
      integer :: k
      do k = 1, size(values)
         d(k)%value = values(k)
         d(k)%gradient(:dual_length) = 0.0_dp
         d(k)%gradient(first_index + k - 1) = 1.0_dp
      end do
   end function dual_variable

   !> The values of duals, as reals.
   elemental function dual_values(d) result(value)
      type(dual_t), intent(in) :: d
      real(dp) :: value
      value = d%value
   end function dual_values

   elemental subroutine assign_real(d, value)
      type(dual_t), intent(out) :: d
      real(dp), intent(in) :: value
      d%value = value
      d%gradient(:dual_length) = 0.0_dp
   end subroutine assign_real

   !> Sum of the elements of a dual vector.
   pure function dual_sum(a) result(s)
      type(dual_t), intent(in) :: a(:)
      type(dual_t) :: s
      integer :: k
      s%value = 0.0_dp
      s%gradient(:dual_length) = 0.0_dp
      do k = 1, size(a)
         s%value = s%value + a(k)%value
         s%gradient(:dual_length) = s%gradient(:dual_length) + a(k)%gradient(:dual_length)
      end do
   end function dual_sum

   !> a . b of two dual 3-vectors (or any equal length).
   pure function dual_dot(a, b) result(s)
      type(dual_t), intent(in) :: a(:), b(:)
      type(dual_t) :: s
      integer :: k
      s%value = 0.0_dp
      s%gradient(:dual_length) = 0.0_dp
      do k = 1, size(a)
         s%value = s%value + a(k)%value*b(k)%value
         s%gradient(:dual_length) = s%gradient(:dual_length) + b(k)%value*a(k)%gradient(:dual_length) &
                                    + a(k)%value*b(k)%gradient(:dual_length)
      end do
   end function dual_dot

   !> a x b of two dual 3-vectors.
   pure function dual_cross(a, b) result(c)
      type(dual_t), intent(in) :: a(3), b(3)
      type(dual_t) :: c(3)
      c(1) = a(2)*b(3) - a(3)*b(2)
      c(2) = a(3)*b(1) - a(1)*b(3)
      c(3) = a(1)*b(2) - a(2)*b(1)
   end function dual_cross

   !> Euclidean norm |a|; its gradient (a . da)/|a| is undefined at a = 0 (the caller must
   !> not differentiate the norm of a zero vector).
   pure function dual_norm(a) result(s)
      type(dual_t), intent(in) :: a(:)
      type(dual_t) :: s
      s = sqrt(dual_dot(a, a))
   end function dual_norm

   elemental function add_dd(a, b) result(c)
      type(dual_t), intent(in) :: a, b
      type(dual_t) :: c
      c%value = a%value + b%value
      c%gradient(:dual_length) = a%gradient(:dual_length) + b%gradient(:dual_length)
   end function add_dd

   elemental function add_dr(a, b) result(c)
      type(dual_t), intent(in) :: a
      real(dp), intent(in) :: b
      type(dual_t) :: c
      c%value = a%value + b
      c%gradient(:dual_length) = a%gradient(:dual_length)
   end function add_dr

   elemental function add_rd(a, b) result(c)
      real(dp), intent(in) :: a
      type(dual_t), intent(in) :: b
      type(dual_t) :: c
      c%value = a + b%value
      c%gradient(:dual_length) = b%gradient(:dual_length)
   end function add_rd

   elemental function plus_d(a) result(c)
      type(dual_t), intent(in) :: a
      type(dual_t) :: c
      c = a
   end function plus_d

   elemental function subtract_dd(a, b) result(c)
      type(dual_t), intent(in) :: a, b
      type(dual_t) :: c
      c%value = a%value - b%value
      c%gradient(:dual_length) = a%gradient(:dual_length) - b%gradient(:dual_length)
   end function subtract_dd

   elemental function subtract_dr(a, b) result(c)
      type(dual_t), intent(in) :: a
      real(dp), intent(in) :: b
      type(dual_t) :: c
      c%value = a%value - b
      c%gradient(:dual_length) = a%gradient(:dual_length)
   end function subtract_dr

   elemental function subtract_rd(a, b) result(c)
      real(dp), intent(in) :: a
      type(dual_t), intent(in) :: b
      type(dual_t) :: c
      c%value = a - b%value
      c%gradient(:dual_length) = -b%gradient(:dual_length)
   end function subtract_rd

   elemental function minus_d(a) result(c)
      type(dual_t), intent(in) :: a
      type(dual_t) :: c
      c%value = -a%value
      c%gradient(:dual_length) = -a%gradient(:dual_length)
   end function minus_d

   !> d(ab) = b da + a db
   elemental function multiply_dd(a, b) result(c)
      type(dual_t), intent(in) :: a, b
      type(dual_t) :: c
      c%value = a%value*b%value
      c%gradient(:dual_length) = b%value*a%gradient(:dual_length) + a%value*b%gradient(:dual_length)
   end function multiply_dd

   elemental function multiply_dr(a, b) result(c)
      type(dual_t), intent(in) :: a
      real(dp), intent(in) :: b
      type(dual_t) :: c
      c%value = a%value*b
      c%gradient(:dual_length) = b*a%gradient(:dual_length)
   end function multiply_dr

   elemental function multiply_rd(a, b) result(c)
      real(dp), intent(in) :: a
      type(dual_t), intent(in) :: b
      type(dual_t) :: c
      c%value = a*b%value
      c%gradient(:dual_length) = a*b%gradient(:dual_length)
   end function multiply_rd

   !> d(a/b) = (da - (a/b) db)/b
   elemental function divide_dd(a, b) result(c)
      type(dual_t), intent(in) :: a, b
      type(dual_t) :: c
      c%value = a%value/b%value
      c%gradient(:dual_length) = (a%gradient(:dual_length) - c%value*b%gradient(:dual_length))/b%value
   end function divide_dd

   elemental function divide_dr(a, b) result(c)
      type(dual_t), intent(in) :: a
      real(dp), intent(in) :: b
      type(dual_t) :: c
      c%value = a%value/b
      c%gradient(:dual_length) = a%gradient(:dual_length)/b
   end function divide_dr

   !> d(a/b) = -(a/b^2) db
   elemental function divide_rd(a, b) result(c)
      real(dp), intent(in) :: a
      type(dual_t), intent(in) :: b
      type(dual_t) :: c
      c%value = a/b%value
      c%gradient(:dual_length) = (-c%value/b%value)*b%gradient(:dual_length)
   end function divide_rd

   !> d(a^n) = n a^(n-1) da (n = 0 gives the constant 1).
   elemental function power_di(a, n) result(c)
      type(dual_t), intent(in) :: a
      integer, intent(in) :: n
      type(dual_t) :: c
      if (n == 0) then
         c%value = 1.0_dp
         c%gradient(:dual_length) = 0.0_dp
      else
         c%value = a%value**n
         c%gradient(:dual_length) = (real(n, dp)*a%value**(n - 1))*a%gradient(:dual_length)
      end if
   end function power_di

   !> d sqrt(a) = da / (2 sqrt(a)); infinite at a = 0.
   elemental function sqrt_d(a) result(c)
      type(dual_t), intent(in) :: a
      type(dual_t) :: c
      c%value = sqrt(a%value)
      c%gradient(:dual_length) = a%gradient(:dual_length)/(2.0_dp*c%value)
   end function sqrt_d

   !> d|a| = sign(a) da (the derivative at a = 0 is taken as that of +a).
   elemental function abs_d(a) result(c)
      type(dual_t), intent(in) :: a
      type(dual_t) :: c
      if (a%value < 0.0_dp) then
         c = -a
      else
         c = a
      end if
   end function abs_d

   elemental logical function less_dd(a, b)
      type(dual_t), intent(in) :: a, b
      less_dd = a%value < b%value
   end function less_dd

   elemental logical function less_dr(a, b)
      type(dual_t), intent(in) :: a
      real(dp), intent(in) :: b
      less_dr = a%value < b
   end function less_dr

   elemental logical function less_equal_dd(a, b)
      type(dual_t), intent(in) :: a, b
      less_equal_dd = a%value <= b%value
   end function less_equal_dd

   elemental logical function less_equal_dr(a, b)
      type(dual_t), intent(in) :: a
      real(dp), intent(in) :: b
      less_equal_dr = a%value <= b
   end function less_equal_dr

   elemental logical function greater_dd(a, b)
      type(dual_t), intent(in) :: a, b
      greater_dd = a%value > b%value
   end function greater_dd

   elemental logical function greater_dr(a, b)
      type(dual_t), intent(in) :: a
      real(dp), intent(in) :: b
      greater_dr = a%value > b
   end function greater_dr

   elemental logical function greater_equal_dd(a, b)
      type(dual_t), intent(in) :: a, b
      greater_equal_dd = a%value >= b%value
   end function greater_equal_dd

   elemental logical function greater_equal_dr(a, b)
      type(dual_t), intent(in) :: a
      real(dp), intent(in) :: b
      greater_equal_dr = a%value >= b
   end function greater_equal_dr
end module frix_dual_number
