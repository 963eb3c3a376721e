!> Kinematics and material calls shared by the solid elements (frix_hex8, frix_cell_solid):
!> deformation gradient and compatible strain from shape-function gradients, the nodal blocks
!> of dE/du, the material at every integration point, and the Cauchy stress from S. Voigt order
!> 11 22 33 12 13 23; strains with engineering shears, stresses with tensor shears.
module frix_solid_kinematics
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_material, only: material_t
   use frix_vector_algebra, only: determinant
   implicit none
   private

   public :: compatible_kinematics, material_pass, nonlinear_b, cauchy_from_pk2, tensor_from_voigt
   public :: deformed_material_pass, point_stresses, check_deformation

contains

   !> F = I + Grad u (total Lagrangian) or F = I (linear); strain E = (F^T F - I)/2 or
   !> eps = sym(Grad u), Voigt with engineering shears.
   pure subroutine compatible_kinematics(dn_dx, u, total_lagrangian, deformation, strain)
      real(dp), intent(in) :: dn_dx(:, :)   !! (3, n_nodes)
      real(dp), intent(in) :: u(:, :)
      logical, intent(in) :: total_lagrangian
      real(dp), intent(out) :: deformation(3, 3)
      real(dp), intent(out) :: strain(6)
      real(dp) :: gradient(3, 3), right_cauchy(3, 3)
      integer :: a, i, j
      gradient = 0.0_dp
      do a = 1, size(dn_dx, 2)
         do j = 1, 3
            do i = 1, 3
               gradient(i, j) = gradient(i, j) + u(i, a)*dn_dx(j, a)
            end do
         end do
      end do
      deformation = gradient
      do i = 1, 3
         deformation(i, i) = deformation(i, i) + 1.0_dp
      end do
      if (total_lagrangian) then
         right_cauchy = matmul(transpose(deformation), deformation)
         strain = [0.5_dp*(right_cauchy(1, 1) - 1.0_dp), 0.5_dp*(right_cauchy(2, 2) - 1.0_dp), &
                   0.5_dp*(right_cauchy(3, 3) - 1.0_dp), right_cauchy(1, 2), right_cauchy(1, 3), &
                   right_cauchy(2, 3)]
      else
         deformation = 0.0_dp
         do i = 1, 3
            deformation(i, i) = 1.0_dp
         end do
         strain = [gradient(1, 1), gradient(2, 2), gradient(3, 3), gradient(1, 2) + gradient(2, 1), &
                   gradient(1, 3) + gradient(3, 1), gradient(2, 3) + gradient(3, 2)]
      end if
   end subroutine compatible_kinematics

   !> Stress and tangent at all points for the given total strains; with `initial_stress`
   !> (6, n_points) each point starts from its sigma0 (material_t%initial_stress_response).
   subroutine material_pass(name, material, finite, total, state_old, state_new, pk2, moduli, error, initial_stress)
      character(len=*), intent(in) :: name
      class(material_t), intent(in) :: material
      logical, intent(in) :: finite   !! total Lagrangian: total = E, pk2 = S
      real(dp), intent(in) :: total(:, :)         !! (6, n_points)
      real(dp), intent(in) :: state_old(:, :)
      real(dp), intent(inout) :: state_new(:, :)
      real(dp), intent(out) :: pk2(:, :), moduli(:, :, :)   !! (6, n_points), (6, 6, n_points)
      type(error_t), allocatable, intent(out) :: error
      real(dp), intent(in), optional :: initial_stress(:, :)
      type(error_t), allocatable :: material_error
      integer :: g
      do g = 1, size(total, 2)
         if (present(initial_stress)) then
            call material%initial_stress_response(total(:, g), finite, initial_stress(:, g), state_old(:, g), &
                                                  state_new(:, g), pk2(:, g), moduli(:, :, g), material_error)
         else
            call material%response(total(:, g), finite, state_old(:, g), state_new(:, g), pk2(:, g), &
                                   moduli(:, :, g), material_error)
         end if
         if (allocated(material_error)) then
            call fatal_error(error, name//', integration point '//to_string(g)//': '// &
                             material_error%message)
            return
         end if
      end do
   end subroutine material_pass

   !> material_pass after checking det F > 0 at every point (total Lagrangian, check_deformation).
   !> Used by the elements without enhanced strains
   !> (frix_cell_solid, frix_plane_solid).
   subroutine deformed_material_pass(name, material, finite, deformation, total, state_old, state_new, pk2, moduli, &
                                     error, initial_stress)
      character(len=*), intent(in) :: name
      class(material_t), intent(in) :: material
      logical, intent(in) :: finite   !! total Lagrangian: total = E, pk2 = S
      real(dp), intent(in) :: deformation(:, :, :)   !! (3, 3, n_points) F
      real(dp), intent(in) :: total(:, :)            !! (6, n_points)
      real(dp), intent(in) :: state_old(:, :)
      real(dp), intent(inout) :: state_new(:, :)
      real(dp), intent(out) :: pk2(:, :), moduli(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      real(dp), intent(in), optional :: initial_stress(:, :)
      integer :: n_points
      n_points = size(total, 2)
      if (finite) then
         call check_deformation(name, deformation(:, :, 1:n_points), error)
         if (allocated(error)) return
      end if
      if (present(initial_stress)) then
         call material_pass(name, material, finite, total, state_old, state_new, pk2, moduli, error, &
                            initial_stress(:, 1:n_points))
      else
         call material_pass(name, material, finite, total, state_old, state_new, pk2, moduli, error)
      end if
   end subroutine deformed_material_pass

   !> An error naming the first point whose det F is not > 0 (total Lagrangian: an inverted or
   !> degenerate point, or one that is not a number), checked before the material passes of
   !> every solid element (deformed_material_pass; frix_hex8 and frix_plane_solid with EAS).
   subroutine check_deformation(name, deformation, error)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: deformation(:, :, :)   !! (3, 3, n_points) F
      type(error_t), allocatable, intent(out) :: error
      integer :: g
      do g = 1, size(deformation, 3)
         if (.not. (determinant(deformation(:, :, g)) > 0.0_dp)) then
            call fatal_error(error, name//': non-positive deformation gradient determinant '// &
                             to_string(determinant(deformation(:, :, g)))//' at integration point '//to_string(g))
            return
         end if
      end do
   end subroutine check_deformation

   !> The Cauchy stress at every point: S under linear kinematics, F S F^T / det F otherwise.
   pure subroutine point_stresses(finite, deformation, pk2, stress)
      logical, intent(in) :: finite
      real(dp), intent(in) :: deformation(:, :, :), pk2(:, :)   !! (3, 3, n_points), (6, n_points)
      real(dp), intent(out) :: stress(:, :)                     !! (6, n_points)
      integer :: g
      do g = 1, size(pk2, 2)
         stress(:, g) = pk2(:, g)
         if (finite) stress(:, g) = cauchy_from_pk2(deformation(:, :, g), pk2(:, g))
      end do
   end subroutine point_stresses

   !> Nodal blocks of dE/du (Voigt, engineering shears): column i of node a holds
   !> dE_jk/du_ai = (F_ij N_a,k + F_ik N_a,j)/2, doubled in the shear rows. F = I gives the
   !> linear B.
   pure subroutine nonlinear_b(deformation, dn_dx, b_nl)
      real(dp), intent(in) :: deformation(3, 3), dn_dx(:, :)   !! F, (3, n_nodes)
      real(dp), intent(out) :: b_nl(:, :, :)                   !! (6, 3, n_nodes)
      integer :: a, i
      do a = 1, size(dn_dx, 2)
         do i = 1, 3
            b_nl(1, i, a) = deformation(i, 1)*dn_dx(1, a)
            b_nl(2, i, a) = deformation(i, 2)*dn_dx(2, a)
            b_nl(3, i, a) = deformation(i, 3)*dn_dx(3, a)
            b_nl(4, i, a) = deformation(i, 1)*dn_dx(2, a) + deformation(i, 2)*dn_dx(1, a)
            b_nl(5, i, a) = deformation(i, 1)*dn_dx(3, a) + deformation(i, 3)*dn_dx(1, a)
            b_nl(6, i, a) = deformation(i, 2)*dn_dx(3, a) + deformation(i, 3)*dn_dx(2, a)
         end do
      end do
   end subroutine nonlinear_b

   !> sigma = F S F^T / det F (Voigt, tensor shears).
   pure function cauchy_from_pk2(deformation, pk2) result(cauchy)
      real(dp), intent(in) :: deformation(3, 3), pk2(6)
      real(dp) :: cauchy(6)
      real(dp) :: sigma(3, 3), deformed_pk2(3, 3)
      deformed_pk2 = matmul(deformation, tensor_from_voigt(pk2))
      sigma = matmul(deformed_pk2, transpose(deformation))/determinant(deformation)
      cauchy = [sigma(1, 1), sigma(2, 2), sigma(3, 3), sigma(1, 2), sigma(1, 3), sigma(2, 3)]
   end function cauchy_from_pk2

   !> Symmetric 3x3 tensor from a stress-like Voigt vector (tensor shears).
   pure function tensor_from_voigt(voigt) result(tensor)
      real(dp), intent(in) :: voigt(6)
      real(dp) :: tensor(3, 3)
      tensor = reshape([voigt(1), voigt(4), voigt(5), voigt(4), voigt(2), voigt(6), &
                        voigt(5), voigt(6), voigt(3)], [3, 3])
   end function tensor_from_voigt

end module frix_solid_kinematics
