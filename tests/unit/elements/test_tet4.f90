!> Unit tests of the TET4 element (frix_cell_solid on the TET4 cell): the tangent against
!> central differences of fint under linear and total Lagrangian kinematics (elastic,
!> hyperelastic and von Mises plastic), six rigid-body modes and no spurious one, zero force
!> under a rigid motion (an infinitesimal one at small strain, a finite rotation under total
!> Lagrangian kinematics), the constant strain state exact, and the volume weights V/4.
module test_tet4
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_testing, only: unittest_t, new_unittest, check
   use frix_material, only: material_t
   use frix_element, only: element_t, kinematics_linear, kinematics_total_lagrangian
   use frix_cell_solid, only: cell_solid_t, new_cell_solid
   use frix_tet4_cell, only: new_tet4_cell
   use frix_linear_elastic, only: new_linear_elastic, hooke_tangent
   use frix_saint_venant_kirchhoff, only: new_saint_venant_kirchhoff
   use frix_neo_hookean, only: new_neo_hookean
   use frix_material_registry, only: create_material
   use test_element_fixtures, only: symmetric_eigenvalues
   implicit none
   private

   public :: collect_tet4, check_tangent, rodrigues

   real(dp), parameter :: young = 1000.0_dp, poisson = 0.3_dp
   !> A general tetrahedron, edges about 1 (positive volume: node 4 above the face 1-2-3).
   real(dp), parameter :: tet_coords(3, 4) = reshape([0.0_dp, 0.0_dp, 0.0_dp, 1.1_dp, 0.1_dp, -0.05_dp, &
                                                      0.2_dp, 0.9_dp, 0.1_dp, -0.1_dp, 0.15_dp, 1.2_dp], [3, 4])
   !> An irregular displacement pattern, scaled by the tests' amplitude.
   real(dp), parameter :: pattern(3, 4) = reshape([0.3_dp, -0.2_dp, 0.1_dp, -0.4_dp, 0.5_dp, 0.2_dp, &
                                                   0.1_dp, 0.3_dp, -0.6_dp, 0.5_dp, -0.1_dp, 0.4_dp], [3, 4])
   !> Central differences with step 1e-6 (element size 1): truncation ~1e-12 and round-off
   !> ~1e-10 relative to max|K| (as for HEX8, tests/unit/elements/test_hex8.f90); a wrong term
   !> in K shows at 1e-3 or above.
   real(dp), parameter :: fd_step = 1.0e-6_dp, fd_tolerance = 1.0e-8_dp

contains

   subroutine collect_tet4(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('counts and name', test_counts), &
               new_unittest('tangent, linear kinematics', test_tangent_linear), &
               new_unittest('tangent, total Lagrangian', test_tangent_total), &
               new_unittest('tangent, von Mises plasticity', test_tangent_plastic), &
               new_unittest('rigid-body modes', test_rigid_body_modes), &
               new_unittest('rigid motion gives no force', test_rigid_motion), &
               new_unittest('constant strain exact', test_constant_strain), &
               new_unittest('volume weights V/4', test_volume_weights)]
   end subroutine collect_tet4

   function tet4(kinematics) result(element)
      integer, intent(in) :: kinematics
      type(cell_solid_t) :: element
      element = new_cell_solid(new_tet4_cell(), kinematics)
   end function tet4

   subroutine test_counts(error)
      type(error_t), allocatable, intent(out) :: error
      type(cell_solid_t) :: element
      element = tet4(kinematics_linear)
      call check(error, element%name == 'TET4' .and. element%n_nodes() == 4 .and. element%n_points() == 1 &
                 .and. element%n_enhanced() == 0, 'TET4: 4 nodes, 1 point, no EAS')
   end subroutine test_counts

   subroutine test_tangent_linear(error)
      type(error_t), allocatable, intent(out) :: error
      call check_tangent(tet4(kinematics_linear), new_linear_elastic(young, poisson, 0.0_dp), tet_coords, &
                         0.01_dp*pattern, error)
   end subroutine test_tangent_linear

   !> St. Venant-Kirchhoff and neo-Hookean at displacements of 15 % of the size.
   subroutine test_tangent_total(error)
      type(error_t), allocatable, intent(out) :: error
      call check_tangent(tet4(kinematics_total_lagrangian), new_saint_venant_kirchhoff(young, poisson, 0.0_dp), &
                         tet_coords, 0.15_dp*pattern, error)
      if (allocated(error)) return
      call check_tangent(tet4(kinematics_total_lagrangian), new_neo_hookean(young, poisson, 0.0_dp), tet_coords, &
                         0.15_dp*pattern, error)
   end subroutine test_tangent_total

   !> Von Mises with saturation and kinematic hardening (sigma_y = 2): the point yields at both
   !> amplitudes (checked), and K is still d fint / du.
   subroutine test_tangent_plastic(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      type(error_t), allocatable :: law_error
      call create_material('MAT_3DMisesPlastic', [character(len=6) :: 'YOUNG', 'NUE', 'SIGY', 'SIGINF', 'DELTA', &
                           'KINH'], [young, poisson, 2.0_dp, 3.0_dp, 50.0_dp, 20.0_dp], material, law_error)
      call check(error, .not. allocated(law_error), 'plastic law')
      if (allocated(error)) return
      call check_tangent(tet4(kinematics_linear), material, tet_coords, 0.01_dp*pattern, error, plastic=.true.)
      if (allocated(error)) return
      call check_tangent(tet4(kinematics_total_lagrangian), material, tet_coords, 0.15_dp*pattern, error, plastic=.true.)
   end subroutine test_tangent_plastic

   !> K of the element at displacements `u` (3, n_nodes) against central differences of fint
   !> over its 3 n_nodes dofs; K symmetric (the laws here have symmetric tangents). With
   !> `plastic`, some point must yield (history entry 2, YIELDED, of MAT_3DMisesPlastic). An
   !> element with enhanced strains solves its alpha from 0 and each perturbed evaluation from
   !> that alpha (re-solved: fint(u) with alpha = alpha(u), whose derivative the condensed K is).
   subroutine check_tangent(element, material, coords, u, error, plastic)
      class(element_t), intent(in) :: element
      class(material_t), intent(in) :: material
      real(dp), intent(in) :: coords(:, :), u(:, :)
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: plastic
      real(dp), allocatable :: perturbed(:, :), fint(:), plus(:), minus(:), tangent(:, :), difference(:, :)
      real(dp), allocatable :: state_old(:, :), state_new(:, :), alpha(:), trial(:)
      real(dp) :: scale
      integer :: a, i, n
      n = element%n_nodes()
      allocate (alpha(element%n_enhanced()), source=0.0_dp)
      allocate (fint(3*n), plus(3*n), minus(3*n), tangent(3*n, 3*n), difference(3*n, 3*n))
      allocate (state_old(material%n_state(), element%n_points()), source=0.0_dp)
      allocate (state_new(material%n_state(), element%n_points()))
      call element%evaluate(material, coords, u, alpha, state_old, state_new, fint, tangent=tangent, error=error)
      if (allocated(error)) return
      if (present(plastic)) then
         call check(error, any(state_new(2, :) == 1.0_dp), element%name//': no point yields')
         if (allocated(error)) return
      end if
      do a = 1, n
         do i = 1, 3
            perturbed = u
            perturbed(i, a) = u(i, a) + fd_step
            trial = alpha
            call element%evaluate(material, coords, perturbed, trial, state_old, state_new, plus, error=error)
            if (allocated(error)) return
            perturbed(i, a) = u(i, a) - fd_step
            trial = alpha
            call element%evaluate(material, coords, perturbed, trial, state_old, state_new, minus, error=error)
            if (allocated(error)) return
            difference(:, 3*(a - 1) + i) = tangent(:, 3*(a - 1) + i) - (plus - minus)/(2.0_dp*fd_step)
         end do
      end do
      scale = maxval(abs(tangent))
      call check(error, maxval(abs(difference)) <= fd_tolerance*scale, element%name//': max|K - K_fd| = '// &
                 to_string(maxval(abs(difference)))//', max|K| = '//to_string(scale))
      if (allocated(error)) return
      call check(error, maxval(abs(tangent - transpose(tangent))) <= 1.0e-12_dp*scale, element%name//': K not symmetric')
   end subroutine check_tangent

   !> Undeformed, Hooke: exactly 6 eigenvalues of K below 1e-10 max (translations, rotations),
   !> the 7th a deformation mode (above 1e-4 max).
   subroutine test_rigid_body_modes(error)
      type(error_t), allocatable, intent(out) :: error
      type(cell_solid_t) :: element
      real(dp) :: tangent(12, 12), fint(12), values(12), state_old(0, 1), state_new(0, 1), alpha(0)
      integer :: n_zero
      element = tet4(kinematics_linear)
      call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), tet_coords, spread([0.0_dp, 0.0_dp, 0.0_dp], &
                            2, 4), alpha, state_old, state_new, fint, tangent=tangent, error=error)
      if (allocated(error)) return
      values = symmetric_eigenvalues(tangent)
      n_zero = count(abs(values) <= 1.0e-10_dp*values(12))
      call check(error, n_zero == 6, 'TET4: '//to_string(n_zero)//' zero eigenvalues')
      if (allocated(error)) return
      call check(error, values(7) > 1.0e-4_dp*values(12), 'TET4: 7th eigenvalue '//to_string(values(7)))
   end subroutine test_rigid_body_modes

   !> fint = 0 (to round-off of E |X|) for u = c + w x X at small strain (w small) and for
   !> u = (R - I) X + c with a finite rotation R (40 degrees about an oblique axis) under total
   !> Lagrangian kinematics, where the Cauchy stress vanishes too.
   subroutine test_rigid_motion(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: u(3, 4), fint(12), stress(6, 1), state_old(0, 1), state_new(0, 1), alpha(0)
      real(dp) :: rotation(3, 3), axis(3), w(3), angle
      integer :: a
      type(cell_solid_t) :: element
      w = [1.0e-3_dp, -2.0e-3_dp, 0.5e-3_dp]
      do a = 1, 4
         u(:, a) = [0.1_dp, -0.2_dp, 0.3_dp] + cross(w, tet_coords(:, a))
      end do
      element = tet4(kinematics_linear)
      call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), tet_coords, u, alpha, state_old, state_new, &
                            fint, error=error)
      if (allocated(error)) return
      call check(error, maxval(abs(fint)) <= 1.0e-12_dp*young, 'TET4 linear: fint '//to_string(maxval(abs(fint))))
      if (allocated(error)) return
      axis = [1.0_dp, 2.0_dp, -1.0_dp]/sqrt(6.0_dp)
      angle = 40.0_dp*acos(-1.0_dp)/180.0_dp
      rotation = rodrigues(axis, angle)
      do a = 1, 4
         u(:, a) = matmul(rotation, tet_coords(:, a)) - tet_coords(:, a) + [0.5_dp, 0.0_dp, -0.3_dp]
      end do
      element = tet4(kinematics_total_lagrangian)
      call element%evaluate(new_saint_venant_kirchhoff(young, poisson, 0.0_dp), tet_coords, u, alpha, state_old, &
                            state_new, fint, stress=stress, error=error)
      if (allocated(error)) return
      call check(error, maxval(abs(fint)) <= 1.0e-12_dp*young .and. maxval(abs(stress)) <= 1.0e-12_dp*young, &
                 'TET4 total Lagrangian: fint '//to_string(maxval(abs(fint)))//', stress '// &
                 to_string(maxval(abs(stress))))
   end subroutine test_rigid_motion

   !> u = A X + c at small strain: stress C sym(A), strain sym(A) (engineering shears), and
   !> fint = B^T sigma V, i.e. the nodal forces of the constant stress: fint_a = sigma (V grad N_a).
   subroutine test_constant_strain(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: gradient(3, 3) = 1.0e-3_dp*reshape([1.0_dp, 0.2_dp, -0.7_dp, 0.4_dp, -0.5_dp, 0.1_dp, &
                                                                 -0.3_dp, 0.6_dp, 0.8_dp], [3, 3])
      real(dp) :: u(3, 4), fint(12), stress(6, 1), strain(6, 1), state_old(0, 1), state_new(0, 1), alpha(0)
      real(dp) :: expected_strain(6), expected_stress(6), hooke(6, 6)
      type(cell_solid_t) :: element
      integer :: a
      do a = 1, 4
         u(:, a) = matmul(gradient, tet_coords(:, a)) + [0.01_dp, -0.02_dp, 0.03_dp]
      end do
      expected_strain = [gradient(1, 1), gradient(2, 2), gradient(3, 3), gradient(1, 2) + gradient(2, 1), &
                         gradient(1, 3) + gradient(3, 1), gradient(2, 3) + gradient(3, 2)]
      hooke = hooke_tangent(young, poisson)
      expected_stress = matmul(hooke, expected_strain)
      element = tet4(kinematics_linear)
      call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), tet_coords, u, alpha, state_old, state_new, &
                            fint, stress=stress, strain=strain, error=error)
      if (allocated(error)) return
      call check(error, maxval(abs(stress(:, 1) - expected_stress)) <= 1.0e-12_dp*maxval(abs(expected_stress)) &
                 .and. maxval(abs(strain(:, 1) - expected_strain)) <= 1.0e-12_dp*maxval(abs(expected_strain)), &
                 'TET4: stress not C sym(A) or strain not sym(A)')
      if (allocated(error)) return
      ! equilibrium of the element: the nodal forces of a constant stress sum to zero
      call check(error, maxval(abs(sum(reshape(fint, [3, 4]), dim=2))) <= 1.0e-13_dp*maxval(abs(fint)), &
                 'TET4: nodal forces of a constant stress do not sum to 0')
   end subroutine test_constant_strain

   !> int N_a dV = V/4 for each node, V = det[x2 - x1, x3 - x1, x4 - x1]/6.
   subroutine test_volume_weights(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: weights(4), edges(3, 3), volume
      type(cell_solid_t) :: element
      element = tet4(kinematics_linear)
      call element%volume_weights(tet_coords, weights)
      edges = tet_coords(:, 2:4) - spread(tet_coords(:, 1), 2, 3)
      volume = dot_product(edges(:, 1), cross(edges(:, 2), edges(:, 3)))/6.0_dp
      call check(error, maxval(abs(weights - volume/4)) <= 1.0e-15_dp, 'TET4 weights '//to_string(weights(1))// &
                 ', V/4 = '//to_string(volume/4))
   end subroutine test_volume_weights

   pure function cross(a, b) result(c)
      real(dp), intent(in) :: a(3), b(3)
      real(dp) :: c(3)
      c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
   end function cross

   !> Rotation by `angle` about the unit `axis`: R = I cos + sin [axis]x + (1 - cos) axis axis^T.
   pure function rodrigues(axis, angle) result(rotation)
      real(dp), intent(in) :: axis(3), angle
      real(dp) :: rotation(3, 3)
      real(dp) :: skew(3, 3)
      integer :: i
      skew = reshape([0.0_dp, axis(3), -axis(2), -axis(3), 0.0_dp, axis(1), axis(2), -axis(1), 0.0_dp], [3, 3])
      rotation = sin(angle)*skew + (1.0_dp - cos(angle))*spread(axis, 2, 3)*spread(axis, 1, 3)
      do i = 1, 3
         rotation(i, i) = rotation(i, i) + cos(angle)
      end do
   end function rodrigues

end module test_tet4
