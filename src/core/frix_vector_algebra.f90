!> Small vector algebra on Cartesian 3-vectors (plain reals), shared by the surface load, the
!> face projection and the contact kernel.
module frix_vector_algebra
   use frix_kinds, only: dp
   implicit none
   private

   public :: cross_product

contains

   !> Vector product left x right of two Cartesian 3-vectors (right-hand rule), in the
   !> product of the operands' units.
   pure function cross_product(left, right) result(product)
      real(dp), intent(in) :: left(3), right(3)
      real(dp) :: product(3)
      product = [left(2)*right(3) - left(3)*right(2), &
                 left(3)*right(1) - left(1)*right(3), &
                 left(1)*right(2) - left(2)*right(1)]
   end function cross_product
end module frix_vector_algebra
