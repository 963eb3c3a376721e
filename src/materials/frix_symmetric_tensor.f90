!> Symmetric 3 x 3 tensors in the Voigt convention of frix_material (xx yy zz xy xz yz;
!> strains with engineering shears, stresses with tensor shears), and the inverse of a
!> symmetric 3 x 3 matrix, shared by the laws that work with C = I + 2 E.
module frix_symmetric_tensor
   use frix_kinds, only: dp
   implicit none
   private

   public :: voigt_i, voigt_j, tensor_of_strain, tensor_of_stress, strain_of_tensor, symmetric_inverse

   !> Voigt index pairs (i, j) of the components xx yy zz xy xz yz.
   integer, parameter :: voigt_i(6) = [1, 2, 3, 1, 1, 2]
   integer, parameter :: voigt_j(6) = [1, 2, 3, 2, 3, 3]

contains

   !> Symmetric tensor of a Voigt strain (engineering shears halved).
   pure function tensor_of_strain(voigt) result(tensor)
      real(dp), intent(in) :: voigt(6)
      real(dp) :: tensor(3, 3)
      integer :: a
      do a = 1, 6
         tensor(voigt_i(a), voigt_j(a)) = merge(voigt(a), 0.5_dp*voigt(a), a <= 3)
         tensor(voigt_j(a), voigt_i(a)) = tensor(voigt_i(a), voigt_j(a))
      end do
   end function tensor_of_strain

   !> Symmetric tensor of a Voigt stress (tensor shears).
   pure function tensor_of_stress(voigt) result(tensor)
      real(dp), intent(in) :: voigt(6)
      real(dp) :: tensor(3, 3)
      integer :: a
      do a = 1, 6
         tensor(voigt_i(a), voigt_j(a)) = voigt(a)
         tensor(voigt_j(a), voigt_i(a)) = voigt(a)
      end do
   end function tensor_of_stress

   !> Voigt strain (engineering shears) of a symmetric tensor.
   pure function strain_of_tensor(tensor) result(voigt)
      real(dp), intent(in) :: tensor(3, 3)
      real(dp) :: voigt(6)
      integer :: a
      do a = 1, 6
         voigt(a) = merge(tensor(voigt_i(a), voigt_j(a)), &
                          tensor(voigt_i(a), voigt_j(a)) + tensor(voigt_j(a), voigt_i(a)), a <= 3)
      end do
   end function strain_of_tensor

   !> Inverse of a symmetric 3 x 3 matrix by cofactors, and its determinant. When the
   !> determinant is zero the inverse is left as the (unscaled) adjugate.
   pure subroutine symmetric_inverse(matrix, inverse, determinant)
      real(dp), intent(in) :: matrix(3, 3)
      real(dp), intent(out) :: inverse(3, 3)
      real(dp), intent(out) :: determinant
      inverse(1, 1) = matrix(2, 2)*matrix(3, 3) - matrix(2, 3)*matrix(3, 2)
      inverse(1, 2) = matrix(1, 3)*matrix(3, 2) - matrix(1, 2)*matrix(3, 3)
      inverse(1, 3) = matrix(1, 2)*matrix(2, 3) - matrix(1, 3)*matrix(2, 2)
      inverse(2, 2) = matrix(1, 1)*matrix(3, 3) - matrix(1, 3)*matrix(3, 1)
      inverse(2, 3) = matrix(1, 3)*matrix(2, 1) - matrix(1, 1)*matrix(2, 3)
      inverse(3, 3) = matrix(1, 1)*matrix(2, 2) - matrix(1, 2)*matrix(2, 1)
      inverse(2, 1) = inverse(1, 2)
      inverse(3, 1) = inverse(1, 3)
      inverse(3, 2) = inverse(2, 3)
      determinant = matrix(1, 1)*inverse(1, 1) + matrix(1, 2)*inverse(2, 1) &
                    + matrix(1, 3)*inverse(3, 1)
      if (determinant /= 0.0_dp) inverse = inverse/determinant
   end subroutine symmetric_inverse
end module frix_symmetric_tensor
