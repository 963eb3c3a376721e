!> Symmetric 3 x 3 tensors in the Voigt convention of frix_material (xx yy zz xy xz yz;
!> strains with engineering shears, stresses with tensor shears), and C = I + 2 E, shared by
!> the laws that work with the right Cauchy-Green tensor.
module frix_symmetric_tensor
   use frix_kinds, only: dp
   implicit none
   private

   public :: voigt_i, voigt_j, tensor_of_strain, tensor_of_stress, strain_of_tensor, stress_of_tensor
   public :: right_cauchy_green, rotated_unit_strain, principal_dyads

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

   !> Voigt stress (tensor shears) of a symmetric tensor.
   pure function stress_of_tensor(tensor) result(voigt)
      real(dp), intent(in) :: tensor(3, 3)
      real(dp) :: voigt(6)
      integer :: a
      do a = 1, 6
         voigt(a) = 0.5_dp*(tensor(voigt_i(a), voigt_j(a)) + tensor(voigt_j(a), voigt_i(a)))
      end do
   end function stress_of_tensor

   !> Q^T H_a Q, H_a the strain tensor of a unit engineering Voigt component a = (i, j):
   !> (Q^T H_a Q)_pq = (Q_ip Q_jq + Q_jp Q_iq) / 2 for a shear, Q_ip Q_iq for a normal component.
   !> With Q the principal directions (columns), the strain increment H_a in the principal basis.
   pure function rotated_unit_strain(q, a) result(tensor)
      real(dp), intent(in) :: q(3, 3)
      integer, intent(in) :: a
      real(dp) :: tensor(3, 3)
      integer :: r, c
      do c = 1, 3
         do r = 1, 3
            tensor(r, c) = 0.5_dp*(q(voigt_i(a), r)*q(voigt_j(a), c) + q(voigt_j(a), r)*q(voigt_i(a), c))
         end do
      end do
   end function rotated_unit_strain

   !> The symmetric dyads of the columns n_1, n_2, n_3 of q in Voigt form (tensor shears): column
   !> m, (a, b) = (voigt_i(m), voigt_j(m)), is (n_a x n_b + n_b x n_a) / 2. Entry (k, m) is also
   !> entry (a, b) of Q^T H_k Q (rotated_unit_strain): with Q the principal directions, a
   !> symmetric tensor is sum_m T^_m column m (T^_m its principal-basis component (a, b), both
   !> orders for a /= b summed), and the principal component (a, b) of a unit engineering
   !> strain k is entry (k, m).
   pure function principal_dyads(q) result(dyads)
      real(dp), intent(in) :: q(3, 3)
      real(dp) :: dyads(6, 6)
      integer :: k, m
      do m = 1, 6
         do k = 1, 6
            dyads(k, m) = 0.5_dp*(q(voigt_i(k), voigt_i(m))*q(voigt_j(k), voigt_j(m)) &
                                  + q(voigt_j(k), voigt_i(m))*q(voigt_i(k), voigt_j(m)))
         end do
      end do
   end function principal_dyads

   !> C = I + 2 E of a Green-Lagrange strain in Voigt form (engineering shears: C_ij = gamma_ij).
   pure function right_cauchy_green(green) result(c)
      real(dp), intent(in) :: green(6)
      real(dp) :: c(3, 3)
      integer :: i
      c = 2.0_dp*tensor_of_strain(green)
      do i = 1, 3
         c(i, i) = c(i, i) + 1.0_dp
      end do
   end function right_cauchy_green
end module frix_symmetric_tensor
