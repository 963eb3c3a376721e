!> Finite-value checks of computed quantities (the guard of docs/solver.md, "Non-finite
!> values"): a non-finite residual, energy, displacement, stress or contact quantity stops the
!> increment that produced it, and no result file of a run receives one.
module frix_finite_check
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use frix_kinds, only: dp
   implicit none
   private

   public :: first_non_finite

contains

   !> Index of the first entry of `values` that is NaN or infinite; 0 when all are finite.
   pure function first_non_finite(values) result(position)
      real(dp), intent(in) :: values(:)
      integer :: position
      integer :: i
      position = 0
      do i = 1, size(values)
         if (.not. ieee_is_finite(values(i))) then
            position = i
            return
         end if
      end do
   end function first_non_finite
end module frix_finite_check
