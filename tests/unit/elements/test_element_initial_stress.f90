!> The initial (in-situ) stress through the element interface (element_t%evaluate's
!> initial_stress, element_t%point_positions): the points' reference positions; at u = 0 the
!> stress of every point is its sigma0, HEX8-EAS keeps alpha = 0 and gives plain HEX8's internal
!> force (the enhanced equations weigh S - S0, frix_hex8); TET4 likewise; the tangent from a
!> geostatic Mohr-Coulomb state against central differences of fint, HEX8-EAS9 under both
!> kinematics, with points on the yield surface.
module test_element_initial_stress
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_testing, only: unittest_t, new_unittest, check
   use frix_material, only: material_t
   use frix_element, only: element_t, kinematics_linear, kinematics_total_lagrangian
   use frix_hex8, only: hex8_t, new_hex8
   use frix_cell_solid, only: cell_solid_t, new_cell_solid
   use frix_tet4_cell, only: new_tet4_cell
   use frix_hex8_cell, only: hex8_corner
   use frix_material_registry, only: create_material
   use test_element_fixtures, only: distorted_coords, sample_displacement, element_size
   implicit none
   private

   public :: collect_element_initial_stress

   integer, parameter :: variants(5) = [0, 3, 9, 21, 30]
   !> the geostatic state: datum z0, unit weight gamma, K0 (sigma_v = -gamma (z0 - z))
   real(dp), parameter :: datum = 10.0_dp, unit_weight = 18.0_dp, k0 = 0.5_dp

contains

   subroutine collect_element_initial_stress(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('point positions: HEX8 Gauss points, TET4 centroid', test_positions), &
               new_unittest('u = 0: stress sigma0, EAS alpha = 0 and plain fint, every variant', test_at_rest), &
               new_unittest('tangent vs FD from a geostatic Mohr-Coulomb state, EAS9, both kinematics', &
                            test_plastic_tangent)]
   end subroutine collect_element_initial_stress

   !> sigma0 at the points of `coords`: (K0 sigma_v, K0 sigma_v, sigma_v, 0, 0, 0).
   function geostatic(element, coords) result(stress)
      class(element_t), intent(in) :: element
      real(dp), intent(in) :: coords(:, :)
      real(dp) :: stress(6, element%n_points()), positions(3, element%n_points())
      integer :: g
      call element%point_positions(coords, positions)
      do g = 1, element%n_points()
         stress(:, g) = -unit_weight*(datum - positions(3, g))*[k0, k0, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]
      end do
   end function geostatic

   !> The box [0, 2] x [0, 4] x [0, 6]: point g at centre + half-size hex8_corner(:, g)/sqrt(3);
   !> a TET4's one point at the mean of its corners.
   subroutine test_positions(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: size(3) = [2.0_dp, 4.0_dp, 6.0_dp]
      real(dp) :: coords(3, 8), positions(3, 8), expected(3, 8), tet(3, 4), centroid(3, 1)
      integer :: a
      type(hex8_t) :: element
      type(cell_solid_t) :: tet4
      element = new_hex8(0, kinematics_linear)
      do a = 1, 8
         coords(:, a) = 0.5_dp*size*(1.0_dp + hex8_corner(:, a))
         expected(:, a) = 0.5_dp*size*(1.0_dp + hex8_corner(:, a)/sqrt(3.0_dp))
      end do
      call element%point_positions(coords, positions)
      call check(error, maxval(abs(positions - expected)) <= 1.0e-14_dp, 'HEX8 point positions')
      if (allocated(error)) return
      tet = reshape([0.0_dp, 0.0_dp, 0.0_dp, 1.1_dp, 0.1_dp, -0.05_dp, 0.2_dp, 0.9_dp, 0.1_dp, &
                     0.1_dp, 0.2_dp, 1.3_dp], [3, 4])
      tet4 = new_cell_solid(new_tet4_cell(), kinematics_linear)
      call tet4%point_positions(tet, centroid)
      call check(error, maxval(abs(centroid(:, 1) - sum(tet, dim=2)/4.0_dp)) <= 1.0e-15_dp, 'TET4 point position')
   end subroutine test_positions

   !> Elastic law, u = 0, from the geostatic sigma0 at the points of the distorted element:
   !> the stress at every point is sigma0 to round-off, every EAS variant leaves alpha at 0 and
   !> gives the internal force of plain HEX8, int B^T sigma0 dV (without the S - S0 of the
   !> enhanced equations the depth gradient of sigma0 drives the modes zeta E_zz, ...); TET4
   !> returns its sigma0.
   subroutine test_at_rest(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      type(error_t), allocatable :: law_error
      type(hex8_t) :: element
      real(dp) :: coords(3, 8), initial(6, 8), stress(6, 8), fint(24), plain(24), state(0, 8), alpha(30)
      real(dp) :: tet(3, 4), tet_stress(6, 1), tet_force(12), tet_initial(6, 1)
      type(cell_solid_t) :: tet4
      integer :: v, k
      call create_material('MAT_Struct_LinearElastic', [character(len=5) :: 'YOUNG', 'NUE'], [20000.0_dp, 0.3_dp], &
                           material, law_error)
      if (allocated(law_error)) error stop 'test_element_initial_stress: invalid law'
      coords = distorted_coords()
      do k = 1, 2
         do v = 1, size(variants)
            element = new_hex8(variants(v), merge(kinematics_linear, kinematics_total_lagrangian, k == 1))
            initial = geostatic(element, coords)
            alpha = 0.0_dp
            call element%evaluate(material, coords, spread([0.0_dp, 0.0_dp, 0.0_dp], 2, 8), alpha, state, state, &
                                  fint, stress=stress, error=error, initial_stress=initial)
            if (allocated(error)) return
            if (v == 1) plain = fint
            call check(error, maxval(abs(stress - initial)) <= 1.0e-13_dp*maxval(abs(initial)) .and. &
                       all(alpha == 0.0_dp) .and. maxval(abs(fint - plain)) <= 1.0e-13_dp*maxval(abs(plain)), &
                       element%name//': stress - sigma0 '//to_string(maxval(abs(stress - initial)))//', max|alpha| '// &
                       to_string(maxval(abs(alpha)))//', fint - fint(HEX8) '//to_string(maxval(abs(fint - plain))))
            if (allocated(error)) return
         end do
      end do
      tet = coords(:, [1, 2, 4, 5])
      tet4 = new_cell_solid(new_tet4_cell(), kinematics_linear)
      tet_initial = geostatic(tet4, tet)
      call tet4%evaluate(material, tet, spread([0.0_dp, 0.0_dp, 0.0_dp], 2, 4), alpha, state(:, 1:1), &
                         state(:, 1:1), tet_force, stress=tet_stress, error=error, initial_stress=tet_initial)
      if (allocated(error)) return
      call check(error, maxval(abs(tet_stress - tet_initial)) <= 1.0e-13_dp*maxval(abs(tet_initial)), &
                 'TET4: stress = sigma0 at u = 0')
   end subroutine test_at_rest

   !> Mohr-Coulomb (c = 5, phi = 30, psi = 10: unsymmetric) from the geostatic state, at a
   !> displacement that takes points onto the yield surface: K = d fint / du by central
   !> differences (step 1e-7 of the element size), max|K - K_fd| <= 1e-6 max|K|.
   subroutine test_plastic_tangent(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      type(error_t), allocatable :: law_error
      type(hex8_t) :: element
      real(dp) :: coords(3, 8), initial(6, 8), u(3, 8), perturbed(3, 8), fint(24), plus(24), minus(24)
      real(dp) :: tangent(24, 24), difference(24, 24), state_old(10, 8), state_new(10, 8), alpha(9), trial(9), step
      integer :: k, a, i
      call create_material('MAT_3DMohrCoulomb', [character(len=8) :: 'YOUNG', 'NUE', 'COHESION', 'PHI', 'PSI'], &
                           [20000.0_dp, 0.3_dp, 5.0_dp, 30.0_dp, 10.0_dp], material, law_error)
      if (allocated(law_error)) error stop 'test_element_initial_stress: invalid soil'
      coords = distorted_coords()
      u = sample_displacement(0.004_dp*element_size)
      step = 1.0e-7_dp*element_size
      state_old = 0.0_dp
      do k = 1, 2
         element = new_hex8(9, merge(kinematics_linear, kinematics_total_lagrangian, k == 1))
         initial = geostatic(element, coords)
         alpha = 0.0_dp
         call element%evaluate(material, coords, u, alpha, state_old, state_new, fint, tangent=tangent, error=error, &
                               initial_stress=initial)
         if (allocated(error)) return
         call check(error, count(state_new(3, :) > 0.0_dp) >= 4, element%name//': '// &
                    to_string(count(state_new(3, :) > 0.0_dp))//' of 8 points plastic (4 at least wanted)')
         if (allocated(error)) return
         do a = 1, 8
            do i = 1, 3
               perturbed = u
               perturbed(i, a) = u(i, a) + step
               trial = alpha
               call element%evaluate(material, coords, perturbed, trial, state_old, state_new, plus, error=error, &
                                     initial_stress=initial)
               if (allocated(error)) return
               perturbed(i, a) = u(i, a) - step
               trial = alpha
               call element%evaluate(material, coords, perturbed, trial, state_old, state_new, minus, error=error, &
                                     initial_stress=initial)
               if (allocated(error)) return
               difference(:, 3*(a - 1) + i) = tangent(:, 3*(a - 1) + i) - (plus - minus)/(2.0_dp*step)
            end do
         end do
         call check(error, maxval(abs(difference)) <= 1.0e-6_dp*maxval(abs(tangent)), element%name//': max|K - K_fd| '// &
                    to_string(maxval(abs(difference)))//', max|K| '//to_string(maxval(abs(tangent))))
         if (allocated(error)) return
      end do
   end subroutine test_plastic_tangent
end module test_element_initial_stress
