!> Unit tests of frix_hex8: consistency of the tangent with finite differences of fint for
!> every EAS variant and both kinematics, rigid-body modes, patch-type constant-strain states,
!> rigid rotations under total Lagrangian kinematics, volume weights, error paths and a
!> one-element bending check.
module test_hex8
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_testing, only: unittest_t, new_unittest, check, check_close, check_message_contains
   use frix_material, only: material_t
   use frix_element, only: kinematics_linear, kinematics_total_lagrangian
   use frix_hex8, only: hex8_t, new_hex8
   use frix_linear_elastic, only: new_linear_elastic, hooke_tangent
   use frix_saint_venant_kirchhoff, only: new_saint_venant_kirchhoff
   use frix_neo_hookean, only: new_neo_hookean
   use frix_material_registry, only: create_material
   use test_unsymmetric_material, only: new_unsymmetric_elastic
   use test_element_fixtures, only: distorted_coords, sample_displacement, parent_corner, &
                                    symmetric_eigenvalues, solve_dense, element_size
   implicit none
   private

   public :: collect_hex8, check_tangent

   real(dp), parameter :: young = 1000.0_dp      !! stress unit of all tests
   real(dp), parameter :: poisson = 0.3_dp
   integer, parameter :: variants(5) = [0, 3, 9, 21, 30]

   !> Finite-difference step relative to the element size, and the tolerance on
   !> max|K - K_fd| / max|K|. Central differences have truncation error ~ (h/size)^2 ~ 1e-12
   !> relative and round-off ~ eps |fint| / (h max|K|) ~ 1e-10 relative (observed: 3e-12 for
   !> linear kinematics, 1e-10 for total Lagrangian with displacements of 15 % of the size).
   !> 1e-8 keeps a factor 100 above that, and leaves room for the local EAS solve (residual
   !> converged quadratically below 1e-12 relative), while any wrong term in K (geometric
   !> part, condensation, B_NL) shows up at 1e-3 or above.
   real(dp), parameter :: fd_step = 1.0e-6_dp
   real(dp), parameter :: fd_tolerance = 1.0e-8_dp

contains

   subroutine collect_hex8(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [ &
              new_unittest('counts and names', test_counts_and_names), &
              new_unittest('tangent vs FD, linear, HEX8', test_tangent_linear_0), &
              new_unittest('tangent vs FD, linear, EAS3', test_tangent_linear_3), &
              new_unittest('tangent vs FD, linear, EAS9', test_tangent_linear_9), &
              new_unittest('tangent vs FD, linear, EAS21', test_tangent_linear_21), &
              new_unittest('tangent vs FD, linear, EAS30', test_tangent_linear_30), &
              new_unittest('tangent vs FD, total Lagrangian, HEX8', test_tangent_total_0), &
              new_unittest('tangent vs FD, total Lagrangian, EAS3', test_tangent_total_3), &
              new_unittest('tangent vs FD, total Lagrangian, EAS9', test_tangent_total_9), &
              new_unittest('tangent vs FD, total Lagrangian, EAS21', test_tangent_total_21), &
              new_unittest('tangent vs FD, total Lagrangian, EAS30', test_tangent_total_30), &
              new_unittest('unsymmetric material: full tangent vs FD, every variant', test_unsymmetric_tangent), &
              new_unittest('von Mises plasticity: tangent vs FD, every variant, both kinematics', &
                           test_plastic_tangent), &
              new_unittest('six rigid-body modes, every variant', test_rigid_body_modes), &
              new_unittest('linear patch: constant stress, alpha = 0', test_patch_linear), &
              new_unittest('total Lagrangian patch: homogeneous F', test_patch_total_lagrangian), &
              new_unittest('total Lagrangian rigid rotation: no stress', test_rigid_rotation), &
              new_unittest('local EAS solve independent of start', test_alpha_start), &
              new_unittest('volume weights', test_volume_weights), &
              new_unittest('non-positive Jacobian is an error', test_inverted_element), &
              new_unittest('non-positive det F is an error', test_inverted_deformation), &
              new_unittest('unsupported EAS count is an error', test_bad_count), &
              new_unittest('thin beam bending: EAS exact, HEX8 locks', test_bending) &
              ]
   end subroutine collect_hex8

   subroutine test_counts_and_names(error)
      type(error_t), allocatable, intent(out) :: error
      type(hex8_t) :: element
      element = new_hex8(9, kinematics_total_lagrangian)
      call check(error, element%n_nodes() == 8 .and. element%n_points() == 8 .and. &
                 element%n_enhanced() == 9, 'HEX8-EAS9 counts')
      if (allocated(error)) return
      call check(error, element%name == 'HEX8-EAS9', 'name of EAS9: '//element%name)
      if (allocated(error)) return
      call check(error, element%kinematics == kinematics_total_lagrangian, 'kinematics kept')
      if (allocated(error)) return
      element = new_hex8(0, kinematics_linear)
      call check(error, element%name == 'HEX8' .and. element%n_enhanced() == 0, 'plain HEX8')
   end subroutine test_counts_and_names

   subroutine test_tangent_linear_0(error)
      type(error_t), allocatable, intent(out) :: error
      call check_tangent_linear(0, error)
   end subroutine test_tangent_linear_0

   subroutine test_tangent_linear_3(error)
      type(error_t), allocatable, intent(out) :: error
      call check_tangent_linear(3, error)
   end subroutine test_tangent_linear_3

   subroutine test_tangent_linear_9(error)
      type(error_t), allocatable, intent(out) :: error
      call check_tangent_linear(9, error)
   end subroutine test_tangent_linear_9

   subroutine test_tangent_linear_21(error)
      type(error_t), allocatable, intent(out) :: error
      call check_tangent_linear(21, error)
   end subroutine test_tangent_linear_21

   subroutine test_tangent_linear_30(error)
      type(error_t), allocatable, intent(out) :: error
      call check_tangent_linear(30, error)
   end subroutine test_tangent_linear_30

   subroutine test_tangent_total_0(error)
      type(error_t), allocatable, intent(out) :: error
      call check_tangent_total(0, error)
   end subroutine test_tangent_total_0

   subroutine test_tangent_total_3(error)
      type(error_t), allocatable, intent(out) :: error
      call check_tangent_total(3, error)
   end subroutine test_tangent_total_3

   subroutine test_tangent_total_9(error)
      type(error_t), allocatable, intent(out) :: error
      call check_tangent_total(9, error)
   end subroutine test_tangent_total_9

   subroutine test_tangent_total_21(error)
      type(error_t), allocatable, intent(out) :: error
      call check_tangent_total(21, error)
   end subroutine test_tangent_total_21

   subroutine test_tangent_total_30(error)
      type(error_t), allocatable, intent(out) :: error
      call check_tangent_total(30, error)
   end subroutine test_tangent_total_30

   !> Hooke material, displacements 1 % of the element size.
   subroutine check_tangent_linear(n_eas, error)
      integer, intent(in) :: n_eas
      type(error_t), allocatable, intent(out) :: error
      call check_tangent(new_hex8(n_eas, kinematics_linear), new_linear_elastic(young, poisson, 0.0_dp), &
                         0.01_dp*element_size, error)
   end subroutine check_tangent_linear

   !> St. Venant-Kirchhoff and neo-Hookean, displacements up to 15 % of the element size.
   subroutine check_tangent_total(n_eas, error)
      integer, intent(in) :: n_eas
      type(error_t), allocatable, intent(out) :: error
      call check_tangent(new_hex8(n_eas, kinematics_total_lagrangian), &
                         new_saint_venant_kirchhoff(young, poisson, 0.0_dp), 0.15_dp*element_size, error)
      if (allocated(error)) then
         error%message = 'St. Venant-Kirchhoff: '//error%message
         return
      end if
      call check_tangent(new_hex8(n_eas, kinematics_total_lagrangian), &
                         new_neo_hookean(young, poisson, 0.0_dp), 0.15_dp*element_size, error)
      if (allocated(error)) error%message = 'neo-Hookean: '//error%message
   end subroutine check_tangent_total

   !> A material with an unsymmetric tangent (skew part 0.2 E): for every EAS variant and both
   !> kinematics the element tangent is d fint / du (every block computed, K_au of the
   !> condensation not taken as K_ua^T), and it is unsymmetric.
   subroutine test_unsymmetric_tangent(error)
      type(error_t), allocatable, intent(out) :: error
      integer :: v
      do v = 1, size(variants)
         call check_tangent(new_hex8(variants(v), kinematics_linear), &
                            new_unsymmetric_elastic(young, poisson, 0.2_dp), 0.01_dp*element_size, error, &
                            symmetric=.false.)
         if (allocated(error)) return
         call check_tangent(new_hex8(variants(v), kinematics_total_lagrangian), &
                            new_unsymmetric_elastic(young, poisson, 0.2_dp), 0.15_dp*element_size, error, &
                            symmetric=.false.)
         if (allocated(error)) return
      end do
   end subroutine test_unsymmetric_tangent

   !> Von Mises with saturation and kinematic hardening, yield strain 2e-3 (sigma_y = 2 with
   !> E = 1000): displacements of 1 % (small strain) and 15 % (total Lagrangian) of the size
   !> make every integration point plastic (checked), and the condensed element tangent must
   !> still be d fint / du (the consistent tangent of the return mapping, and under total
   !> Lagrangian that of the logarithmic strain, carried through the EAS condensation).
   subroutine test_plastic_tangent(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      type(error_t), allocatable :: law_error
      integer :: v
      call create_material('MAT_3DMisesPlastic', [character(len=6) :: 'YOUNG', 'NUE', 'SIGY', 'SIGINF', 'DELTA', &
                           'KINH'], [young, poisson, 2.0_dp, 3.0_dp, 50.0_dp, 20.0_dp], material, law_error)
      if (allocated(law_error)) then
         call check(error, .false., 'plastic law: '//law_error%message)
         return
      end if
      do v = 1, size(variants)
         call check_all_plastic(new_hex8(variants(v), kinematics_linear), material, 0.01_dp*element_size, error)
         if (allocated(error)) return
         call check_tangent(new_hex8(variants(v), kinematics_linear), material, 0.01_dp*element_size, error)
         if (allocated(error)) return
         call check_all_plastic(new_hex8(variants(v), kinematics_total_lagrangian), material, &
                                0.15_dp*element_size, error)
         if (allocated(error)) return
         call check_tangent(new_hex8(variants(v), kinematics_total_lagrangian), material, 0.15_dp*element_size, error)
         if (allocated(error)) return
      end do
   end subroutine test_plastic_tangent

   !> Every integration point yields at the sample displacement of `amplitude` (history entry 2,
   !> YIELDED, of MAT_3DMisesPlastic).
   subroutine check_all_plastic(element, material, amplitude, error)
      type(hex8_t), intent(in) :: element
      class(material_t), intent(in) :: material
      real(dp), intent(in) :: amplitude
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: fint(24), state_old(material%n_state(), 8), state_new(material%n_state(), 8)
      real(dp) :: alpha(element%n_eas)
      state_old = 0.0_dp
      alpha = 0.0_dp
      call element%evaluate(material, distorted_coords(), sample_displacement(amplitude), alpha, state_old, &
                            state_new, fint, error=error)
      if (allocated(error)) return
      call check(error, all(state_new(2, :) == 1.0_dp), element%name//': not every point yields')
   end subroutine check_all_plastic

   !> K against central differences of fint over all 24 dofs on the distorted element (or on
   !> `geometry` with the displacements `displacement` and the difference step `step`, for
   !> elements of other sizes); each perturbed evaluation starts its local EAS solve from the
   !> alpha of the base state.
   !> Also checks that K is symmetric (hyperelastic material, symmetric condensation), or with
   !> `symmetric` false that it is not (by more than 1e-3 max|K|).
   subroutine check_tangent(element, material, amplitude, error, symmetric, geometry, displacement, step_size)
      type(hex8_t), intent(in) :: element
      class(material_t), intent(in) :: material
      real(dp), intent(in) :: amplitude   !! of sample_displacement (unused with `displacement`)
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: symmetric
      real(dp), intent(in), optional :: geometry(3, 8), displacement(3, 8), step_size
      real(dp) :: coords(3, 8), u(3, 8), perturbed(3, 8), fint(24), plus(24), minus(24)
      real(dp) :: tangent(24, 24), difference(24, 24)
      real(dp) :: state_old(material%n_state(), 8), state_new(material%n_state(), 8)
      real(dp) :: alpha(element%n_eas), trial(element%n_eas), step, scale
      integer :: a, i, column
      state_old = 0.0_dp
      coords = distorted_coords()
      if (present(geometry)) coords = geometry
      u = sample_displacement(amplitude)
      if (present(displacement)) u = displacement
      alpha = 0.0_dp
      call element%evaluate(material, coords, u, alpha, state_old, state_new, fint, tangent=tangent, &
                            error=error)
      if (allocated(error)) return
      step = fd_step*element_size
      if (present(step_size)) step = step_size
      do a = 1, 8
         do i = 1, 3
            column = 3*(a - 1) + i
            perturbed = u
            perturbed(i, a) = u(i, a) + step
            trial = alpha
            call element%evaluate(material, coords, perturbed, trial, state_old, state_new, plus, error=error)
            if (allocated(error)) return
            perturbed(i, a) = u(i, a) - step
            trial = alpha
            call element%evaluate(material, coords, perturbed, trial, state_old, state_new, minus, error=error)
            if (allocated(error)) return
            difference(:, column) = tangent(:, column) - (plus - minus)/(2.0_dp*step)
         end do
      end do
      scale = maxval(abs(tangent))
      call check(error, maxval(abs(difference)) <= fd_tolerance*scale, element%name//': max|K - K_fd| = '// &
                 to_string(maxval(abs(difference)))//', max|K| = '//to_string(scale))
      if (allocated(error)) return
      if (present(symmetric)) then
         if (.not. symmetric) then
            call check(error, maxval(abs(tangent - transpose(tangent))) > 1.0e-3_dp*scale, &
                       element%name//': K symmetric for an unsymmetric material')
            return
         end if
      end if
      call check(error, maxval(abs(tangent - transpose(tangent))) <= 1.0e-12_dp*scale, &
                 element%name//': K not symmetric')
   end subroutine check_tangent

   !> Undeformed distorted element, Hooke material: the linear K has exactly 6 eigenvalues
   !> below 1e-10 max(eigenvalue) (rigid translations and rotations), and the 7th is a
   !> genuine deformation mode (above 1e-4 max, i.e. no spurious zero-energy mode).
   subroutine test_rigid_body_modes(error)
      type(error_t), allocatable, intent(out) :: error
      type(hex8_t) :: element
      real(dp) :: tangent(24, 24), fint(24), values(24), state_old(0, 8), state_new(0, 8)
      real(dp), allocatable :: alpha(:)
      integer :: v, n_zero
      do v = 1, size(variants)
         element = new_hex8(variants(v), kinematics_linear)
         allocate (alpha(variants(v)))
         alpha = 0.0_dp
         call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), distorted_coords(), &
                               spread([0.0_dp, 0.0_dp, 0.0_dp], 2, 8), alpha, state_old, state_new, &
                               fint, tangent=tangent, error=error)
         deallocate (alpha)
         if (allocated(error)) return
         values = symmetric_eigenvalues(tangent)
         n_zero = count(abs(values) <= 1.0e-10_dp*values(24))
         call check(error, n_zero == 6, element%name//': '//to_string(n_zero)//' zero eigenvalues')
         if (allocated(error)) return
         call check(error, values(7) > 1.0e-4_dp*values(24), element%name//': 7th eigenvalue '// &
                    to_string(values(7))//' vs largest '//to_string(values(24)))
         if (allocated(error)) return
      end do
   end subroutine test_rigid_body_modes

   !> u = A X + c on the distorted element (linear kinematics): at every point the stress is
   !> C sym(A) (Hooke's matrix, engineering shears), the strain sym(A); the local solve drives
   !> alpha from a nonzero start to 0; fint equals the plain HEX8's (same constant stress).
   subroutine test_patch_linear(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: gradient(3, 3) = 1.0e-3_dp*reshape([1.0_dp, 0.2_dp, -0.7_dp, &
                                                                 0.4_dp, -0.5_dp, 0.1_dp, &
                                                                 -0.3_dp, 0.6_dp, 0.8_dp], [3, 3])
      type(hex8_t) :: element
      real(dp) :: coords(3, 8), u(3, 8), fint(24), fint_plain(24), stress(6, 8), strain(6, 8)
      real(dp) :: expected_strain(6), expected_stress(6), state_old(0, 8), state_new(0, 8)
      real(dp), allocatable :: alpha(:)
      integer :: v, a
      coords = distorted_coords()
      do a = 1, 8
         u(:, a) = matmul(gradient, coords(:, a)) + [0.01_dp, -0.02_dp, 0.03_dp]
      end do
      expected_strain = [gradient(1, 1), gradient(2, 2), gradient(3, 3), gradient(1, 2) + gradient(2, 1), &
                         gradient(1, 3) + gradient(3, 1), gradient(2, 3) + gradient(3, 2)]
      expected_stress = matmul(hooke_tangent(young, poisson), expected_strain)
      do v = 1, size(variants)
         element = new_hex8(variants(v), kinematics_linear)
         allocate (alpha(variants(v)))
         alpha = 1.0e-3_dp
         call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), coords, u, alpha, state_old, &
                               state_new, fint, stress=stress, strain=strain, error=error)
         if (allocated(error)) return
         if (v == 1) fint_plain = fint
         call check(error, maxval(abs(stress - spread(expected_stress, 2, 8))) <= &
                    1.0e-10_dp*maxval(abs(expected_stress)), element%name//': stress not C sym(A)')
         if (allocated(error)) return
         call check(error, maxval(abs(strain - spread(expected_strain, 2, 8))) <= &
                    1.0e-10_dp*maxval(abs(expected_strain)), element%name//': strain not sym(A)')
         if (allocated(error)) return
         if (size(alpha) > 0) then
            call check(error, maxval(abs(alpha)) <= 1.0e-10_dp*maxval(abs(expected_strain)), &
                       element%name//': alpha = '//to_string(maxval(abs(alpha)))//' not 0')
            if (allocated(error)) return
         end if
         call check(error, maxval(abs(fint - fint_plain)) <= 1.0e-10_dp*maxval(abs(fint_plain)), &
                    element%name//': fint differs from plain HEX8 under constant stress')
         if (allocated(error)) return
         deallocate (alpha)
      end do
   end subroutine test_patch_linear

   !> u = A X with a large A (F = I + A, det F > 0) under total Lagrangian kinematics and
   !> St. Venant-Kirchhoff: every point has E = (F^T F - I)/2, S = C E and Cauchy stress
   !> F S F^T / det F, computed here independently of the element; alpha goes to 0.
   subroutine test_patch_total_lagrangian(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: gradient(3, 3) = reshape([0.10_dp, 0.05_dp, -0.12_dp, &
                                                       0.20_dp, -0.08_dp, 0.04_dp, &
                                                       -0.06_dp, 0.15_dp, 0.12_dp], [3, 3])
      type(hex8_t) :: element
      real(dp) :: coords(3, 8), u(3, 8), fint(24), stress(6, 8), strain(6, 8), f(3, 3), c(3, 3)
      real(dp) :: green(6), pk2(6), s(3, 3), sigma(3, 3), expected_stress(6), det_f
      real(dp) :: state_old(0, 8), state_new(0, 8)
      real(dp), allocatable :: alpha(:)
      integer :: v, a, i
      coords = distorted_coords()
      do a = 1, 8
         u(:, a) = matmul(gradient, coords(:, a))
      end do
      f = gradient
      do i = 1, 3
         f(i, i) = f(i, i) + 1.0_dp
      end do
      c = matmul(transpose(f), f)
      green = [0.5_dp*(c(1, 1) - 1.0_dp), 0.5_dp*(c(2, 2) - 1.0_dp), 0.5_dp*(c(3, 3) - 1.0_dp), &
               c(1, 2), c(1, 3), c(2, 3)]
      pk2 = matmul(hooke_tangent(young, poisson), green)
      s = reshape([pk2(1), pk2(4), pk2(5), pk2(4), pk2(2), pk2(6), pk2(5), pk2(6), pk2(3)], [3, 3])
      det_f = f(1, 1)*(f(2, 2)*f(3, 3) - f(2, 3)*f(3, 2)) - f(1, 2)*(f(2, 1)*f(3, 3) - f(2, 3)*f(3, 1)) &
              + f(1, 3)*(f(2, 1)*f(3, 2) - f(2, 2)*f(3, 1))
      sigma = matmul(f, matmul(s, transpose(f)))/det_f
      expected_stress = [sigma(1, 1), sigma(2, 2), sigma(3, 3), sigma(1, 2), sigma(1, 3), sigma(2, 3)]
      do v = 1, size(variants)
         element = new_hex8(variants(v), kinematics_total_lagrangian)
         allocate (alpha(variants(v)))
         alpha = 1.0e-2_dp
         call element%evaluate(new_saint_venant_kirchhoff(young, poisson, 0.0_dp), coords, u, alpha, &
                               state_old, state_new, fint, stress=stress, strain=strain, error=error)
         if (allocated(error)) return
         call check(error, maxval(abs(stress - spread(expected_stress, 2, 8))) <= &
                    1.0e-10_dp*maxval(abs(expected_stress)), element%name//': Cauchy stress not F S F^T / J')
         if (allocated(error)) return
         call check(error, maxval(abs(strain - spread(green, 2, 8))) <= 1.0e-10_dp*maxval(abs(green)), &
                    element%name//': Green-Lagrange strain wrong')
         if (allocated(error)) return
         if (size(alpha) > 0) then
            call check(error, maxval(abs(alpha)) <= 1.0e-10_dp*maxval(abs(green)), &
                       element%name//': alpha = '//to_string(maxval(abs(alpha)))//' not 0')
            if (allocated(error)) return
         end if
         deallocate (alpha)
      end do
   end subroutine test_patch_total_lagrangian

   !> u = R X - X + c for R = 90 degrees about z and R = 120 degrees about (1, 1, 1) (which
   !> permutes the axes): E = 0 exactly, so stress and fint vanish up to round-off
   !> (tolerance 1e-12 E, forces 1e-12 E size^2).
   subroutine test_rigid_rotation(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: about_z(3, 3) = reshape([0, 1, 0, -1, 0, 0, 0, 0, 1], [3, 3])
      real(dp), parameter :: about_diagonal(3, 3) = reshape([0, 1, 0, 0, 0, 1, 1, 0, 0], [3, 3])
      type(hex8_t) :: element
      real(dp) :: coords(3, 8), u(3, 8), rotation(3, 3), fint(24), stress(6, 8)
      real(dp) :: state_old(0, 8), state_new(0, 8)
      real(dp), allocatable :: alpha(:)
      integer :: v, r, a
      coords = distorted_coords()
      do r = 1, 2
         rotation = about_z
         if (r == 2) rotation = about_diagonal
         do a = 1, 8
            u(:, a) = matmul(rotation, coords(:, a)) - coords(:, a) + [0.3_dp, -0.2_dp, 0.1_dp]
         end do
         do v = 1, size(variants)
            element = new_hex8(variants(v), kinematics_total_lagrangian)
            allocate (alpha(variants(v)))
            alpha = 0.0_dp
            call element%evaluate(new_saint_venant_kirchhoff(young, poisson, 0.0_dp), coords, u, alpha, &
                                  state_old, state_new, fint, stress=stress, error=error)
            deallocate (alpha)
            if (allocated(error)) return
            call check(error, maxval(abs(stress)) <= 1.0e-12_dp*young, element%name//': stress '// &
                       to_string(maxval(abs(stress)))//' under rigid rotation '//to_string(r))
            if (allocated(error)) return
            call check(error, maxval(abs(fint)) <= 1.0e-12_dp*young*element_size**2, &
                       element%name//': fint under rigid rotation '//to_string(r))
            if (allocated(error)) return
         end do
      end do
   end subroutine test_rigid_rotation

   !> Total Lagrangian EAS21 with neo-Hookean: starting the local solve from 0, from the
   !> converged alpha and from an arbitrary alpha gives the same alpha and fint (1e-10 relative).
   subroutine test_alpha_start(error)
      type(error_t), allocatable, intent(out) :: error
      type(hex8_t) :: element
      real(dp) :: coords(3, 8), u(3, 8), fint(24), fint_again(24), alpha(21), alpha_again(21)
      real(dp) :: state_old(0, 8), state_new(0, 8)
      integer :: start
      element = new_hex8(21, kinematics_total_lagrangian)
      coords = distorted_coords()
      u = sample_displacement(0.15_dp*element_size)
      alpha = 0.0_dp
      call element%evaluate(new_neo_hookean(young, poisson, 0.0_dp), coords, u, alpha, state_old, &
                            state_new, fint, error=error)
      if (allocated(error)) return
      call check(error, maxval(abs(alpha)) > 1.0e-3_dp, 'expected a nontrivial alpha for this state')
      if (allocated(error)) return
      do start = 1, 2
         alpha_again = alpha
         if (start == 2) alpha_again = 0.05_dp
         call element%evaluate(new_neo_hookean(young, poisson, 0.0_dp), coords, u, alpha_again, &
                               state_old, state_new, fint_again, error=error)
         if (allocated(error)) return
         call check(error, maxval(abs(alpha_again - alpha)) <= 1.0e-10_dp*maxval(abs(alpha)) .and. &
                    maxval(abs(fint_again - fint)) <= 1.0e-10_dp*maxval(abs(fint)), &
                    'result depends on the starting alpha (start '//to_string(start)//')')
         if (allocated(error)) return
      end do
   end subroutine test_alpha_start

   !> Frustum of a square pyramid (bottom 2 x 2 at z = 0, top 1 x 1 at z = 1): volume
   !> h/3 (A1 + A2 + sqrt(A1 A2)) = 7/3; by hand, int (1 - z)(2 - z)^2 dz = 17/12 over the
   !> four bottom nodes (17/48 each) and 11/12 over the top ones (11/48 each).
   !> Parallelepiped X = B xi + c: volume 8 det B.
   subroutine test_volume_weights(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: shear_map(3, 3) = reshape([1.0_dp, 0.2_dp, 0.1_dp, 0.3_dp, 0.8_dp, -0.2_dp, &
                                                        -0.1_dp, 0.25_dp, 1.5_dp], [3, 3])
      type(hex8_t) :: element
      real(dp) :: coords(3, 8), weights(8), det
      integer :: a
      element = new_hex8(0, kinematics_linear)
      do a = 1, 8
         if (parent_corner(3, a) < 0.0_dp) then
            coords(:, a) = [parent_corner(1, a), parent_corner(2, a), 0.0_dp]
         else
            coords(:, a) = [0.5_dp*parent_corner(1, a), 0.5_dp*parent_corner(2, a), 1.0_dp]
         end if
      end do
      call element%volume_weights(coords, weights)
      call check_close(error, sum(weights), 7.0_dp/3.0_dp, 1.0e-14_dp, message='frustum volume')
      if (allocated(error)) return
      call check(error, maxval(abs(weights(1:4) - 17.0_dp/48.0_dp)) <= 1.0e-14_dp .and. &
                 maxval(abs(weights(5:8) - 11.0_dp/48.0_dp)) <= 1.0e-14_dp, 'frustum nodal weights')
      if (allocated(error)) return
      do a = 1, 8
         coords(:, a) = matmul(shear_map, parent_corner(:, a)) + [5.0_dp, -1.0_dp, 2.0_dp]
      end do
      det = shear_map(1, 1)*(shear_map(2, 2)*shear_map(3, 3) - shear_map(2, 3)*shear_map(3, 2)) &
            - shear_map(1, 2)*(shear_map(2, 1)*shear_map(3, 3) - shear_map(2, 3)*shear_map(3, 1)) &
            + shear_map(1, 3)*(shear_map(2, 1)*shear_map(3, 2) - shear_map(2, 2)*shear_map(3, 1))
      call element%volume_weights(coords, weights)
      call check_close(error, sum(weights), 8.0_dp*det, 1.0e-14_dp, message='parallelepiped volume')
      if (allocated(error)) return
      call check(error, maxval(abs(weights - det)) <= 1.0e-14_dp*det, 'parallelepiped: equal weights det B')
   end subroutine test_volume_weights

   !> Mirrored node order (top and bottom faces swapped) gives detJ < 0 at every point.
   subroutine test_inverted_element(error)
      type(error_t), allocatable, intent(out) :: error
      type(hex8_t) :: element
      type(error_t), allocatable :: evaluate_error
      real(dp) :: coords(3, 8), fint(24), alpha(9), state_old(0, 8), state_new(0, 8)
      coords = distorted_coords()
      coords = coords(:, [5, 6, 7, 8, 1, 2, 3, 4])
      element = new_hex8(9, kinematics_linear)
      alpha = 0.0_dp
      call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), coords, &
                            spread([0.0_dp, 0.0_dp, 0.0_dp], 2, 8), alpha, state_old, state_new, fint, &
                            error=evaluate_error)
      call check_message_contains(error, evaluate_error, 'non-positive Jacobian')
      if (allocated(error)) return
      call check_message_contains(error, evaluate_error, 'integration point 1')
   end subroutine test_inverted_element

   !> u_x = -2 X gives F_11 = -1, det F < 0.
   subroutine test_inverted_deformation(error)
      type(error_t), allocatable, intent(out) :: error
      type(hex8_t) :: element
      type(error_t), allocatable :: evaluate_error
      real(dp) :: coords(3, 8), u(3, 8), fint(24), alpha(0), state_old(0, 8), state_new(0, 8)
      coords = distorted_coords()
      u = 0.0_dp
      u(1, :) = -2.0_dp*coords(1, :)
      element = new_hex8(0, kinematics_total_lagrangian)
      call element%evaluate(new_saint_venant_kirchhoff(young, poisson, 0.0_dp), coords, u, alpha, &
                            state_old, state_new, fint, error=evaluate_error)
      call check_message_contains(error, evaluate_error, 'non-positive deformation gradient')
   end subroutine test_inverted_deformation

   subroutine test_bad_count(error)
      type(error_t), allocatable, intent(out) :: error
      type(hex8_t) :: element
      type(error_t), allocatable :: evaluate_error
      real(dp) :: fint(24), alpha(5), state_old(0, 8), state_new(0, 8)
      element = new_hex8(5, kinematics_linear)
      alpha = 0.0_dp
      call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), distorted_coords(), &
                            spread([0.0_dp, 0.0_dp, 0.0_dp], 2, 8), alpha, state_old, state_new, fint, &
                            error=evaluate_error)
      call check_message_contains(error, evaluate_error, 'unsupported number of EAS parameters')
   end subroutine test_bad_count

   !> One element, beam L = 10 along x, h = b = 1, nu = 0, clamped at x = 0 (all dofs), end
   !> moment M = 2 F h applied as the consistent nodal forces of sigma_xx linear in y
   !> (+F on the two top, -F on the two bottom nodes at x = L). Euler-Bernoulli (exact 3D
   !> elasticity for nu = 0): u_y(L) = -M L^2 / (2 E I), I = b h^3 / 12. The EAS9, EAS21 and
   !> EAS30 elements reproduce it (1e-8 relative; their enhanced shear mode xi removes the
   !> parasitic shear of the rectangle), HEX8 and EAS3 lock (below a tenth of it).
   subroutine test_bending(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: length = 10.0_dp, height = 1.0_dp, width = 1.0_dp, force = 1.0_dp
      integer, parameter :: free_nodes(4) = [2, 3, 6, 7]
      type(hex8_t) :: element
      real(dp) :: coords(3, 8), tangent(24, 24), fint(24), load(12), reduced(12, 12), solution(12)
      real(dp) :: state_old(0, 8), state_new(0, 8), exact, deflection
      real(dp), allocatable :: alpha(:)
      integer :: dofs(12), v, a, i
      do a = 1, 8
         coords(:, a) = [0.5_dp*length*(1.0_dp + parent_corner(1, a)), 0.5_dp*height*parent_corner(2, a), &
                         0.5_dp*width*(1.0_dp + parent_corner(3, a))]
      end do
      do i = 1, 4
         dofs(3*i - 2:3*i) = 3*(free_nodes(i) - 1) + [1, 2, 3]
      end do
      load = 0.0_dp
      do i = 1, 4
         load(3*i - 2) = sign(force, coords(2, free_nodes(i)))
      end do
      exact = -(2.0_dp*force*height)*length**2/(2.0_dp*young*width*height**3/12.0_dp)
      do v = 1, size(variants)
         element = new_hex8(variants(v), kinematics_linear)
         allocate (alpha(variants(v)))
         alpha = 0.0_dp
         call element%evaluate(new_linear_elastic(young, 0.0_dp, 0.0_dp), coords, &
                               spread([0.0_dp, 0.0_dp, 0.0_dp], 2, 8), alpha, state_old, state_new, fint, &
                               tangent=tangent, error=error)
         deallocate (alpha)
         if (allocated(error)) return
         reduced = tangent(dofs, dofs)
         solution = solve_dense(reduced, load)
         deflection = sum(solution(2::3))/4.0_dp
         if (variants(v) >= 9) then
            call check_close(error, deflection, exact, 1.0e-8_dp, message=element%name//' tip deflection')
         else
            call check(error, abs(deflection) < 0.1_dp*abs(exact), element%name//' should lock: '// &
                       to_string(deflection)//' vs beam '//to_string(exact))
         end if
         if (allocated(error)) return
      end do
   end subroutine test_bending
end module test_hex8
