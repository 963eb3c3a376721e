!> Reductions over vectors of global equations (one entry per equation, 3 per node): the
!> norms, dot products and largest entries with which the Newton iterations, the line search
!> and the convergence checks judge residuals and corrections. In one place so that a
!> distributed vector reduces over every process the same way; here every vector is whole
!> and the reductions are Fortran's intrinsics.
module frix_global_reductions
   use frix_kinds, only: dp
   implicit none
   private

   public :: global_norm, global_dot, global_max_abs_location

contains

   !> Euclidean norm |x| (norm2: scaled against overflow).
   function global_norm(x) result(norm)
      real(dp), intent(in) :: x(:)
      real(dp) :: norm
      norm = norm2(x)
   end function global_norm

   !> x . y
   function global_dot(x, y) result(dot)
      real(dp), intent(in) :: x(:), y(:)
      real(dp) :: dot
      dot = dot_product(x, y)
   end function global_dot

   !> The global equation of the entry of largest magnitude (the first on ties; 0 for an empty
   !> vector).
   function global_max_abs_location(x) result(equation)
      real(dp), intent(in) :: x(:)
      integer :: equation
      equation = maxloc(abs(x), dim=1)
   end function global_max_abs_location
end module frix_global_reductions
