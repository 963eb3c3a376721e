!> Small vector and 3 x 3 matrix algebra (plain reals), shared by the surface load, the face
!> projection, the contact kernel, the elements and the hyperelastic laws.
module frix_vector_algebra
   use frix_kinds, only: dp
   implicit none
   private

   public :: cross_product, skew, determinant, invert3

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

   !> The matrix [v]x with [v]x w = v x w.
   pure function skew(vector) result(matrix)
      real(dp), intent(in) :: vector(3)
      real(dp) :: matrix(3, 3)
      matrix = reshape([0.0_dp, vector(3), -vector(2), &
                        -vector(3), 0.0_dp, vector(1), &
                        vector(2), -vector(1), 0.0_dp], [3, 3])
   end function skew

   !> det of a 3 x 3 matrix by cofactors of the first row.
   pure function determinant(matrix) result(det)
      real(dp), intent(in) :: matrix(3, 3)
      real(dp) :: det
      det = matrix(1, 1)*(matrix(2, 2)*matrix(3, 3) - matrix(2, 3)*matrix(3, 2)) &
            - matrix(1, 2)*(matrix(2, 1)*matrix(3, 3) - matrix(2, 3)*matrix(3, 1)) &
            + matrix(1, 3)*(matrix(2, 1)*matrix(3, 2) - matrix(2, 2)*matrix(3, 1))
   end function determinant


   !> Inverse by cofactors; `inverse` is left undefined when det = 0.
   pure subroutine invert3(matrix, inverse, det)
      real(dp), intent(in) :: matrix(3, 3)
      real(dp), intent(out) :: inverse(3, 3), det
      inverse(1, 1) = matrix(2, 2)*matrix(3, 3) - matrix(2, 3)*matrix(3, 2)
      inverse(1, 2) = matrix(1, 3)*matrix(3, 2) - matrix(1, 2)*matrix(3, 3)
      inverse(1, 3) = matrix(1, 2)*matrix(2, 3) - matrix(1, 3)*matrix(2, 2)
      inverse(2, 1) = matrix(2, 3)*matrix(3, 1) - matrix(2, 1)*matrix(3, 3)
      inverse(2, 2) = matrix(1, 1)*matrix(3, 3) - matrix(1, 3)*matrix(3, 1)
      inverse(2, 3) = matrix(1, 3)*matrix(2, 1) - matrix(1, 1)*matrix(2, 3)
      inverse(3, 1) = matrix(2, 1)*matrix(3, 2) - matrix(2, 2)*matrix(3, 1)
      inverse(3, 2) = matrix(1, 2)*matrix(3, 1) - matrix(1, 1)*matrix(3, 2)
      inverse(3, 3) = matrix(1, 1)*matrix(2, 2) - matrix(1, 2)*matrix(2, 1)
      det = matrix(1, 1)*inverse(1, 1) + matrix(1, 2)*inverse(2, 1) + matrix(1, 3)*inverse(3, 1)
      if (det /= 0.0_dp) inverse = inverse/det
   end subroutine invert3

end module frix_vector_algebra
