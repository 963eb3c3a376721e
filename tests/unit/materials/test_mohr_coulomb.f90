!> Mohr-Coulomb plasticity (frix_mohr_coulomb): triaxial compression and extension and a shear
!> path at constant mean stress against the closed-form limit stresses and dilatancy ratios; a
!> strain far past yield returns onto the surface in each region (plane, both edges, apex) with
!> the principal order kept; softening stops at zero cohesion; unloading is elastic; the
!> consistent tangent against central differences in each region, associated and
!> non-associated, with and without hardening, at coinciding trial principal values and under
!> finite strain. Soil: E = 20000, nu = 0.3, c = 10 (kPa), phi = 30 degrees, tension positive.
module test_mohr_coulomb
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_testing, only: unittest_t, new_unittest, check, check_close
   use frix_material, only: material_t
   use frix_linear_elastic, only: hooke_tangent
   use frix_symmetric_tensor, only: tensor_of_stress
   use frix_frictional_plasticity, only: state_eqps, state_region, state_plastic_strain, state_alpha, &
                                         region_elastic, region_surface, region_edge, region_apex, region_tension
   use frix_material_registry, only: create_material
   use test_material_checks, only: check_tangent_by_differences, material_response, check_matrix_close
   use test_soil_paths, only: make_soil, young, poisson, mixed_control, trial_strain, mohr_coulomb_excess, rotation, n_state, &
                              principal_stresses, &
                              confining, consolidate, triaxial
   implicit none
   private

   public :: collect_mohr_coulomb

   character(len=*), parameter :: law = 'MAT_3DMohrCoulomb'
   real(dp), parameter :: cohesion = 10.0_dp, phi = 30.0_dp
   real(dp), parameter :: pi = 3.14159265358979323846264338327950_dp
   real(dp), parameter :: sin_phi = 0.5_dp, cos_phi = 0.86602540378443864676372317075294_dp

contains

   subroutine collect_mohr_coulomb(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('triaxial compression: limit stress and dilatancy, edge sigma_1 = sigma_2', &
                            test_triaxial_compression), &
               new_unittest('triaxial extension: limit stress and dilatancy, edge sigma_2 = sigma_3', &
                            test_triaxial_extension), &
               new_unittest('shear at constant mean stress: tau = c cos(phi) - p sin(phi), d eps_v / d gamma_p = sin(psi)', &
                            test_shear), &
               new_unittest('a strain far past yield returns onto the surface in each region', test_large_step), &
               new_unittest('softening stops at zero cohesion', test_softening), &
               new_unittest('unloading is elastic', test_unloading), &
               new_unittest('tangent vs differences: each region, (non-)associated, hardening', test_tangents), &
               new_unittest('tangent vs differences: coinciding trial values, plastic history, finite strain', &
                            test_tangent_special), &
               new_unittest('tension cut-off: uniaxial tension stops at sigma = t, flow along sigma_1', test_tension_uniaxial), &
               new_unittest('tension cut-off: returns onto the cut-off, its edges, its corner with the plane, its apex', &
                            test_tension_regions)]
   end subroutine collect_mohr_coulomb

   !> sigma_1 = sigma_2 = -100 >= sigma_3 = sigma_zz: f = 0 gives sigma_3 = (sigma_1 (1 + sin phi)
   !> - 2 c cos phi) / (1 - sin phi); flow b_1 + b_3 = (1 + sin psi, 1 + sin psi, -2 (1 - sin psi))
   !> gives d eps_v^p / d eps_zz^p = -2 sin psi / (1 - sin psi).
   subroutine test_triaxial_compression(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp) :: stress(6), state(n_state), plastic(6), psi
      integer :: k
      do k = 1, 2
         psi = merge(phi, 10.0_dp, k == 1)
         call make_soil(material, law, cohesion, phi, psi, 0.0_dp)
         call triaxial(error, material, -1.0e-3_dp, 30, stress, state, plastic)
         if (allocated(error)) return
         call check_close(error, stress(3), (confining*(1.0_dp + sin_phi) - 2.0_dp*cohesion*cos_phi)/(1.0_dp - sin_phi), &
                          1.0e-10_dp, message='sigma_zz at failure, psi = '//to_string(psi))
         if (allocated(error)) return
         call check(error, nint(state(state_region)) == region_edge, 'region: edge')
         if (allocated(error)) return
         call check_close(error, sum(plastic(1:3))/plastic(3), -2.0_dp*sin(psi*pi/180.0_dp)/(1.0_dp - sin(psi*pi/180.0_dp)), &
                          1.0e-9_dp, message='dilatancy ratio, psi = '//to_string(psi))
         if (allocated(error)) return
      end do
   end subroutine test_triaxial_compression

   !> sigma_1 = sigma_zz >= sigma_2 = sigma_3 = -100: sigma_1 = (2 c cos phi + sigma_3 (1 - sin phi))
   !> / (1 + sin phi); flow b_1 + b_2 gives d eps_v^p / d eps_zz^p = 2 sin psi / (1 + sin psi).
   subroutine test_triaxial_extension(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp) :: stress(6), state(n_state), plastic(6), psi
      integer :: k
      do k = 1, 2
         psi = merge(phi, 10.0_dp, k == 1)
         call make_soil(material, law, cohesion, phi, psi, 0.0_dp)
         call triaxial(error, material, 5.0e-4_dp, 30, stress, state, plastic)
         if (allocated(error)) return
         call check_close(error, stress(3), (2.0_dp*cohesion*cos_phi + confining*(1.0_dp - sin_phi))/(1.0_dp + sin_phi), &
                          1.0e-10_dp, message='sigma_zz at failure, psi = '//to_string(psi))
         if (allocated(error)) return
         call check(error, nint(state(state_region)) == region_edge, 'region: edge')
         if (allocated(error)) return
         call check_close(error, sum(plastic(1:3))/plastic(3), 2.0_dp*sin(psi*pi/180.0_dp)/(1.0_dp + sin(psi*pi/180.0_dp)), &
                          1.0e-9_dp, message='dilatancy ratio, psi = '//to_string(psi))
         if (allocated(error)) return
      end do
   end subroutine test_triaxial_extension

   !> Normal stresses held at p = -100, gamma_xy increased: principal stresses p + tau, p, p - tau,
   !> so f = 2 tau + 2 p sin phi - 2 c cos phi = 0 on the plane; the plastic strain of b_1 in the
   !> principal axes at 45 degrees has gamma_xy^p = 2 d gamma, eps_v^p = 2 sin psi d gamma.
   subroutine test_shear(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp) :: strain(6), state(n_state), stress(6), before(6), plastic(6), psi
      integer :: k, step
      do k = 1, 2
         psi = merge(phi, 10.0_dp, k == 1)
         call make_soil(material, law, cohesion, phi, psi, 0.0_dp)
         call consolidate(error, material, strain, state)
         if (allocated(error)) return
         do step = 1, 20
            before = state(state_plastic_strain:state_plastic_strain + 5)
            strain(4) = strain(4) + 1.0e-3_dp
            call mixed_control(error, material, strain, [1, 2, 3], [confining, confining, confining], state, stress)
            if (allocated(error)) return
         end do
         plastic = state(state_plastic_strain:state_plastic_strain + 5) - before
         call check_close(error, stress(4), cohesion*cos_phi - confining*sin_phi, 1.0e-10_dp, &
                          message='tau at failure, psi = '//to_string(psi))
         if (allocated(error)) return
         call check(error, nint(state(state_region)) == region_surface, 'region: plane')
         if (allocated(error)) return
         call check_close(error, sum(plastic(1:3))/plastic(4), sin(psi*pi/180.0_dp), 1.0e-9_dp, &
                          message='d eps_v^p / d gamma_xy^p = sin psi, psi = '//to_string(psi))
         if (allocated(error)) return
      end do
   end subroutine test_shear

   !> Trial principal stresses 100 x those of the tangent states (far past yield), in rotated
   !> axes: the stress satisfies f = 0 with c(alpha) to round-off, its principal directions are
   !> the trial's with the values in the trial's order, and REGION names the expected region.
   subroutine test_large_step(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp) :: axes(3, 3), stress(6), tangent(6, 6), state(n_state), new(n_state), in_axes(3, 3), current
      integer :: r, a
      axes = rotation([1.0_dp, 2.0_dp, -0.5_dp], 0.7_dp)
      call make_soil(material, law, cohesion, phi, 10.0_dp, 500.0_dp)
      state = 0.0_dp
      do r = 1, 4
         call material_response(error, material, trial_strain(100.0_dp*region_trial(r), axes), stress, tangent, &
                                .false., state, new)
         if (allocated(error)) return
         call check(error, nint(new(state_region)) == expected_region(r), 'region '//to_string(expected_region(r))// &
                    ', got '//to_string(nint(new(state_region))))
         if (allocated(error)) return
         current = cohesion + 500.0_dp*new(state_alpha)
         call check_close(error, mohr_coulomb_excess(stress, current, phi), 0.0_dp, 0.0_dp, &
                          1.0e-11_dp*maxval(abs(stress)) + 1.0e-11_dp*current, 'f = 0, region '//to_string(r))
         if (allocated(error)) return
         in_axes = matmul(transpose(axes), matmul(tensor_of_stress(stress), axes))
         do a = 1, 3
            call check(error, all(abs(pack(in_axes(a, :), [1, 2, 3] /= a)) <= 1.0e-11_dp*maxval(abs(stress))), &
                       'principal axes kept, region '//to_string(r))
            if (allocated(error)) return
         end do
         call check(error, in_axes(1, 1) >= in_axes(2, 2) - 1.0e-11_dp*maxval(abs(stress)) .and. &
                    in_axes(2, 2) >= in_axes(3, 3) - 1.0e-11_dp*maxval(abs(stress)), 'principal order kept')
         if (allocated(error)) return
      end do
   end subroutine test_large_step

   !> Trial principal stresses (descending) that return onto the plane, the edge
   !> sigma_1 = sigma_2, the edge sigma_2 = sigma_3 and the apex (p = 35 > c cot phi = 17.3).
   pure function region_trial(r) result(principal)
      integer, intent(in) :: r
      real(dp) :: principal(3)
      select case (r)
      case (1)
         principal = [-50.0_dp, -100.0_dp, -250.0_dp]
      case (2)
         principal = [-95.0_dp, -100.0_dp, -400.0_dp]
      case (3)
         principal = [0.0_dp, -195.0_dp, -200.0_dp]
      case default
         principal = [40.0_dp, 35.0_dp, 30.0_dp]
      end select
   end function region_trial

   pure integer function expected_region(r)
      integer, intent(in) :: r
      integer, parameter :: regions(4) = [region_surface, region_edge, region_edge, region_apex]
      expected_region = regions(r)
   end function expected_region

   !> HARD = -200: a large step takes c0 + H alpha below zero; the stress then satisfies f = 0
   !> with c = 0, and a further step keeps c = 0.
   subroutine test_softening(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp) :: stress(6), tangent(6, 6), state(n_state), new(n_state), axes(3, 3)
      axes = rotation([0.3_dp, -1.0_dp, 0.2_dp], 0.4_dp)
      call make_soil(material, law, cohesion, phi, 10.0_dp, -200.0_dp)
      state = 0.0_dp
      call material_response(error, material, trial_strain(100.0_dp*region_trial(1), axes), stress, tangent, &
                             .false., state, new)
      if (allocated(error)) return
      call check(error, cohesion - 200.0_dp*new(state_alpha) < 0.0_dp, 'alpha past the floor')
      if (allocated(error)) return
      call check_close(error, mohr_coulomb_excess(stress, 0.0_dp, phi), 0.0_dp, 0.0_dp, 1.0e-11_dp*maxval(abs(stress)), &
                       'f = 0 with c = 0')
      if (allocated(error)) return
      state = new
      call material_response(error, material, trial_strain(110.0_dp*region_trial(1), axes), stress, tangent, &
                             .false., state, new)
      if (allocated(error)) return
      call check_close(error, mohr_coulomb_excess(stress, 0.0_dp, phi), 0.0_dp, 0.0_dp, 1.0e-11_dp*maxval(abs(stress)), &
                       'f = 0 with c = 0, next step')
   end subroutine test_softening

   !> From a plastic state on the plane, a strain step back: Hooke's tangent, no plastic flow,
   !> stress change D d eps.
   subroutine test_unloading(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp) :: strain(6), state(n_state), new(n_state), loaded(6), unloaded(6), tangent(6, 6), step(6), axes(3, 3)
      axes = rotation([1.0_dp, 0.0_dp, 1.0_dp], 0.3_dp)
      call make_soil(material, law, cohesion, phi, 10.0_dp, 500.0_dp)
      state = 0.0_dp
      strain = trial_strain(region_trial(1), axes)
      call material_response(error, material, strain, loaded, tangent, .false., state, new)
      if (allocated(error)) return
      call check(error, nint(new(state_region)) == region_surface, 'loaded onto the plane')
      if (allocated(error)) return
      state = new
      step = -0.3_dp*(strain - state(state_plastic_strain:state_plastic_strain + 5))
      call material_response(error, material, strain + step, unloaded, tangent, .false., state, new)
      if (allocated(error)) return
      call check_matrix_close(error, tangent, hooke_tangent(20000.0_dp, 0.3_dp), 1.0e-14_dp, 'unloading tangent')
      if (allocated(error)) return
      call check(error, nint(new(state_region)) == region_elastic .and. new(state_eqps) == state(state_eqps) .and. &
                 all(new(state_plastic_strain:state_plastic_strain + 5) == state(state_plastic_strain:state_plastic_strain + 5)), &
                 'no plastic flow')
      if (allocated(error)) return
      call check_matrix_close(error, reshape(unloaded - loaded, [6, 1]), &
                              reshape(matmul(hooke_tangent(20000.0_dp, 0.3_dp), step), [6, 1]), 1.0e-12_dp, &
                              'stress change = D d eps')
   end subroutine test_unloading

   !> Each region (trial stresses region_trial in rotated axes), psi = phi and psi = 10 degrees,
   !> H = 0 and H = 500 (at the apex H = 0 gives a zero tangent, compared exactly).
   subroutine test_tangents(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp) :: axes(3, 3), stress(6), tangent(6, 6), state(n_state), new(n_state), psi, hard
      integer :: r, k, h
      axes = rotation([0.4_dp, -1.0_dp, 0.7_dp], 1.1_dp)
      state = 0.0_dp
      do h = 1, 2
         hard = merge(0.0_dp, 500.0_dp, h == 1)
         do k = 1, 2
            psi = merge(phi, 10.0_dp, k == 1)
            call make_soil(material, law, cohesion, phi, psi, hard)
            do r = 1, 4
               call material_response(error, material, trial_strain(region_trial(r), axes), stress, tangent, &
                                      .false., state, new)
               if (allocated(error)) return
               call check(error, nint(new(state_region)) == expected_region(r), 'region '//to_string(r))
               if (allocated(error)) return
               call check_tangent_by_differences(error, material, trial_strain(region_trial(r), axes), 1.0e-6_dp, &
                                                 'region '//to_string(r)//', psi '//to_string(psi)//', H '// &
                                                 to_string(hard), .false., state)
               if (allocated(error)) return
            end do
         end do
      end do
   end subroutine test_tangents

   !> Trial values coinciding exactly (triaxial compression and extension trials, returned onto
   !> the edges); a plastic history (eps_p, alpha) with axes turned since; the law applied to
   !> E_log under finite strain, on the plane and at an edge.
   subroutine test_tangent_special(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp) :: stress(6), tangent(6, 6), state(n_state), new(n_state), axes(3, 3), green(6)
      call make_soil(material, law, cohesion, phi, 10.0_dp, 500.0_dp)
      state = 0.0_dp
      axes = rotation([1.0_dp, 1.0_dp, 1.0_dp], 0.5_dp)
      call check_tangent_by_differences(error, material, trial_strain([-100.0_dp, -100.0_dp, -400.0_dp], axes), &
                                        1.0e-6_dp, 'sigma_1* = sigma_2*', .false., state)
      if (allocated(error)) return
      call check_tangent_by_differences(error, material, trial_strain([0.0_dp, -200.0_dp, -200.0_dp], axes), &
                                        1.0e-6_dp, 'sigma_2* = sigma_3*', .false., state)
      if (allocated(error)) return
      call material_response(error, material, trial_strain(region_trial(1), axes), stress, tangent, .false., state, new)
      if (allocated(error)) return
      axes = rotation([0.0_dp, 1.0_dp, 0.3_dp], -0.8_dp)
      call check_tangent_by_differences(error, material, trial_strain(2.0_dp*region_trial(2), axes), 1.0e-6_dp, &
                                        'plastic history', .false., new)
      if (allocated(error)) return
      green = trial_strain(region_trial(1), axes) + [-0.05_dp, 0.02_dp, 0.01_dp, 0.04_dp, 0.0_dp, -0.02_dp]
      call material_response(error, material, green, stress, tangent, .true., state, new)
      if (allocated(error)) return
      call check(error, nint(new(state_region)) /= region_elastic, 'finite strain: plastic')
      if (allocated(error)) return
      call check_tangent_by_differences(error, material, green, 1.0e-6_dp, 'finite strain', .true., state)
   end subroutine test_tangent_special

   !> The law with a tension cut-off t = 5 < c cot(phi) = 17.3 (and the other properties as above).
   subroutine make_cut_off_soil(material, psi, hard)
      class(material_t), allocatable, intent(out) :: material
      real(dp), intent(in) :: psi, hard
      type(error_t), allocatable :: error
      call create_material(law, [character(len=8) :: 'YOUNG', 'NUE', 'COHESION', 'PHI', 'PSI', 'HARD', 'TENSION'], &
                           [young, poisson, cohesion, phi, psi, hard, 5.0_dp], material, error)
      if (allocated(error)) error stop 'test_mohr_coulomb: invalid soil with a tension cut-off'
   end subroutine make_cut_off_soil

   !> sigma_yy = sigma_zz = 0, eps_xx increased: without the cut-off the limit would be the
   !> Mohr-Coulomb tension strength 2 c cos(phi) / (1 + sin(phi)) = 11.5; with t = 5 it is
   !> sigma_xx = t, and the associated flow of the cut-off is eps_p = d lambda e_1.
   subroutine test_tension_uniaxial(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp) :: strain(6), state(n_state), stress(6)
      integer :: step
      call make_cut_off_soil(material, 10.0_dp, 0.0_dp)
      strain = 0.0_dp
      state = 0.0_dp
      do step = 1, 10
         strain(1) = strain(1) + 1.0e-4_dp
         call mixed_control(error, material, strain, [2, 3], [0.0_dp, 0.0_dp], state, stress)
         if (allocated(error)) return
      end do
      call check_close(error, stress(1), 5.0_dp, 1.0e-12_dp, message='sigma_xx = t')
      if (allocated(error)) return
      call check(error, nint(state(state_region)) == region_tension, 'region: cut-off')
      if (allocated(error)) return
      call check_close(error, state(state_plastic_strain), 1.0e-3_dp - 5.0_dp/young, 1.0e-10_dp, &
                       message='eps_p,xx = eps_xx - t / E')
      if (allocated(error)) return
      call check(error, all(abs(state(state_plastic_strain + 1:state_plastic_strain + 5)) <= 1.0e-15_dp), &
                 'eps_p only along x')
   end subroutine test_tension_uniaxial

   !> Trials onto the cut-off sigma_1 = t, its edge sigma_1 = sigma_2 = t, its apex sigma = t 1,
   !> its corner with the main plane, the corner of that edge with the main plane, and the
   !> corner of the cut-off with the edge sigma_2 = sigma_3 of the Mohr-Coulomb planes.
   !> Each: no plane violated after the return, REGION 4, and the tangent against differences
   !> (psi = phi and 10 degrees, H = 0 and 500).
   subroutine test_tension_regions(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp), parameter :: trials(3, 6) = reshape([10.0_dp, 0.0_dp, -2.0_dp, 10.0_dp, 9.0_dp, 0.0_dp, &
                                                     12.0_dp, 11.0_dp, 10.0_dp, 30.0_dp, 0.0_dp, -10.0_dp, &
                                                     30.0_dp, 29.0_dp, -10.0_dp, 80.0_dp, 10.0_dp, 9.0_dp], [3, 6])
      integer, parameter :: at_cut_off(6) = [1, 2, 3, 1, 2, 1]   !! principal stresses = t after the return
      real(dp) :: axes(3, 3), stress(6), tangent(6, 6), state(n_state), new(n_state), psi, hard, s(3)
      integer :: r, k, h
      axes = rotation([0.4_dp, -1.0_dp, 0.7_dp], 1.1_dp)
      state = 0.0_dp
      do h = 1, 2
         hard = merge(0.0_dp, 500.0_dp, h == 1)
         do k = 1, 2
            psi = merge(phi, 10.0_dp, k == 1)
            call make_cut_off_soil(material, psi, hard)
            do r = 1, 6
               call material_response(error, material, trial_strain(trials(:, r), axes), stress, tangent, &
                                      .false., state, new)
               if (allocated(error)) return
               s = principal_stresses(stress)
               call check(error, nint(new(state_region)) == region_tension .and. abs(s(1) - 5.0_dp) <= 1.0e-12_dp*20.0_dp &
                          .and. mohr_coulomb_excess(stress, cohesion + hard*new(state_alpha), phi) <= 1.0e-12_dp*30.0_dp, &
                          'cut-off return, trial '//to_string(r))
               if (allocated(error)) return
               call check(error, count(abs(s - 5.0_dp) <= 1.0e-12_dp*20.0_dp) == at_cut_off(r), &
                          'principal stresses at the cut-off, trial '//to_string(r))
               if (allocated(error)) return
               if (r >= 4) call check_close(error, mohr_coulomb_excess(stress, cohesion + hard*new(state_alpha), phi), &
                                            0.0_dp, 0.0_dp, 1.0e-12_dp*30.0_dp, 'corner: on the main plane too, trial '// &
                                            to_string(r))
               if (allocated(error)) return
               if (r == 6) call check(error, abs(s(2) - s(3)) <= 1.0e-12_dp*30.0_dp, 'corner: sigma_2 = sigma_3')
               if (allocated(error)) return
               call check_tangent_by_differences(error, material, trial_strain(trials(:, r), axes), 1.0e-6_dp, &
                                                 'cut-off trial '//to_string(r)//', psi '//to_string(psi)//', H '// &
                                                 to_string(hard), .false., state)
               if (allocated(error)) return
            end do
         end do
      end do
   end subroutine test_tension_regions
end module test_mohr_coulomb
