!> Drucker-Prager plasticity (frix_drucker_prager): the matchings to Mohr-Coulomb against the
!> Mohr-Coulomb closed forms (outer cone: the triaxial compression limit; inner cone: the
!> triaxial extension limit; plane strain: the plane-strain limit of associated flow), the
!> dilatancy of the cone's flow, a shear path at constant mean stress, returns far past yield
!> onto the cone and the apex, elastic unloading, and the consistent tangent against central
!> differences on the cone and at the apex for each matching, associated and non-associated,
!> with and without hardening, from a plastic history and under finite strain.
!> Soil: E = 20000, nu = 0.3, c = 10 (kPa), phi = 30 degrees, tension positive.
module test_drucker_prager
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_testing, only: unittest_t, new_unittest, check, check_close
   use frix_material, only: material_t
   use frix_linear_elastic, only: hooke_tangent
   use frix_drucker_prager, only: cone_parameters, match_outer, match_inner, match_plane_strain
   use frix_frictional_plasticity, only: state_eqps, state_region, state_plastic_strain, state_alpha, &
                                         region_elastic, region_surface, region_apex
   use test_material_checks, only: check_tangent_by_differences, material_response, check_matrix_close
   use test_soil_paths, only: make_soil, mixed_control, trial_strain, rotation, n_state, confining, &
                              consolidate, triaxial, young, poisson
   implicit none
   private

   public :: collect_drucker_prager

   character(len=*), parameter :: law = 'MAT_3DDruckerPrager'
   real(dp), parameter :: cohesion = 10.0_dp, phi = 30.0_dp
   real(dp), parameter :: pi = 3.14159265358979323846264338327950_dp
   real(dp), parameter :: sin_phi = 0.5_dp, cos_phi = 0.86602540378443864676372317075294_dp

contains

   subroutine collect_drucker_prager(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('cone parameters at phi = 30: 0.693/1.200, 0.495/0.857, 0.480/0.832', test_parameters), &
               new_unittest('outer cone: the Mohr-Coulomb triaxial compression limit, dilatancy', test_compression), &
               new_unittest('inner cone: the Mohr-Coulomb triaxial extension limit, dilatancy', test_extension), &
               new_unittest('plane-strain match: the Mohr-Coulomb plane-strain limit (associated)', test_plane_strain), &
               new_unittest('shear at constant mean stress: tau = xi c - eta p, d eps_v / d gamma_p = eta_bar', test_shear), &
               new_unittest('a strain far past yield returns onto the cone and the apex', test_large_step), &
               new_unittest('unloading is elastic', test_unloading), &
               new_unittest('tangent vs differences: cone and apex, each matching, (non-)associated, hardening', &
                            test_tangents), &
               new_unittest('tangent vs differences: plastic history, finite strain', test_tangent_special)]
   end subroutine collect_drucker_prager

   !> eta and xi of each matching at phi = 30 degrees, to 3 digits: the values computed by hand
   !> from the formulas of docs/materials.md (outer 0.693/1.200, inner 0.495/0.857, plane
   !> strain 0.480/0.832).
   subroutine test_parameters(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: expected(2, 3) = reshape([0.693_dp, 1.200_dp, 0.495_dp, 0.857_dp, 0.480_dp, 0.832_dp], [2, 3])
      integer, parameter :: matches(3) = [match_outer, match_inner, match_plane_strain]
      real(dp) :: eta, xi
      integer :: k
      do k = 1, 3
         call cone_parameters(matches(k), phi*pi/180.0_dp, eta, xi)
         call check_close(error, eta, expected(1, k), 0.0_dp, 5.0e-4_dp, 'eta, match '//to_string(matches(k)))
         if (allocated(error)) return
         call check_close(error, xi, expected(2, k), 0.0_dp, 5.0e-4_dp, 'xi, match '//to_string(matches(k)))
         if (allocated(error)) return
      end do
   end subroutine test_parameters

   pure real(dp) function eta_of(match, angle)
      integer, intent(in) :: match
      real(dp), intent(in) :: angle   !! degrees
      real(dp) :: xi
      call cone_parameters(match, angle*pi/180.0_dp, eta_of, xi)
   end function eta_of

   !> Outer cone, sigma_xx = sigma_yy = -100 >= sigma_zz: the Mohr-Coulomb limit sigma_zz = (sigma_1
   !> (1 + sin phi) - 2 c cos phi) / (1 - sin phi); flow n / sqrt(2) + eta_bar / 3 1 with
   !> n = (1, 1, -2) / sqrt(6): d eps_v^p / d eps_zz^p = eta_bar / (eta_bar / 3 - 1 / sqrt(3)).
   subroutine test_compression(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp) :: stress(6), state(n_state), plastic(6), psi, eta_bar
      integer :: k
      do k = 1, 2
         psi = merge(phi, 10.0_dp, k == 1)
         eta_bar = eta_of(match_outer, psi)
         call make_soil(material, law, cohesion, phi, psi, 0.0_dp, match_outer)
         call triaxial(error, material, -1.0e-3_dp, 30, stress, state, plastic)
         if (allocated(error)) return
         call check_close(error, stress(3), (confining*(1.0_dp + sin_phi) - 2.0_dp*cohesion*cos_phi)/(1.0_dp - sin_phi), &
                          1.0e-10_dp, message='sigma_zz at failure, psi = '//to_string(psi))
         if (allocated(error)) return
         call check(error, nint(state(state_region)) == region_surface, 'region: cone')
         if (allocated(error)) return
         call check_close(error, sum(plastic(1:3))/plastic(3), eta_bar/(eta_bar/3.0_dp - 1.0_dp/sqrt(3.0_dp)), 1.0e-9_dp, &
                          message='dilatancy ratio, psi = '//to_string(psi))
         if (allocated(error)) return
      end do
   end subroutine test_compression

   !> Inner cone, sigma_zz >= sigma_xx = sigma_yy = -100: sigma_zz = (2 c cos phi + sigma_3
   !> (1 - sin phi)) / (1 + sin phi); n = (-1, -1, 2) / sqrt(6): ratio eta_bar / (eta_bar / 3 + 1 /
   !> sqrt(3)).
   subroutine test_extension(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp) :: stress(6), state(n_state), plastic(6), psi, eta_bar
      integer :: k
      do k = 1, 2
         psi = merge(phi, 10.0_dp, k == 1)
         eta_bar = eta_of(match_inner, psi)
         call make_soil(material, law, cohesion, phi, psi, 0.0_dp, match_inner)
         call triaxial(error, material, 5.0e-4_dp, 30, stress, state, plastic)
         if (allocated(error)) return
         call check_close(error, stress(3), (2.0_dp*cohesion*cos_phi + confining*(1.0_dp - sin_phi))/(1.0_dp + sin_phi), &
                          1.0e-10_dp, message='sigma_zz at failure, psi = '//to_string(psi))
         if (allocated(error)) return
         call check_close(error, sum(plastic(1:3))/plastic(3), eta_bar/(eta_bar/3.0_dp + 1.0_dp/sqrt(3.0_dp)), 1.0e-9_dp, &
                          message='dilatancy ratio, psi = '//to_string(psi))
         if (allocated(error)) return
      end do
   end subroutine test_extension

   !> Plane strain (eps_zz = 0), sigma_xx held at -100, eps_yy decreased, associated flow: in the
   !> limit state (stress stationary, so d eps_zz^p = 0) the plane-strain cone gives the
   !> Mohr-Coulomb limit sigma_yy = (sigma_xx (1 + sin phi) - 2 c cos phi) / (1 - sin phi), with
   !> sigma_zz between. The approach to the limit is gradual; after eps_yy = -0.2 the stress has
   !> settled to 1e-9.
   subroutine test_plane_strain(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp) :: strain(6), state(n_state), stress(6)
      integer :: k
      call make_soil(material, law, cohesion, phi, phi, 0.0_dp, match_plane_strain)
      strain = 0.0_dp
      state = 0.0_dp
      call mixed_control(error, material, strain, [1, 2], [confining, confining], state, stress)
      if (allocated(error)) return
      do k = 1, 200
         strain(2) = strain(2) - 1.0e-3_dp
         call mixed_control(error, material, strain, [1], [confining], state, stress)
         if (allocated(error)) return
      end do
      call check_close(error, stress(2), (confining*(1.0_dp + sin_phi) - 2.0_dp*cohesion*cos_phi)/(1.0_dp - sin_phi), &
                       1.0e-9_dp, message='sigma_yy at the plane-strain limit')
      if (allocated(error)) return
      call check(error, stress(3) < confining .and. stress(3) > stress(2), 'sigma_zz intermediate')
   end subroutine test_plane_strain

   !> Normal stresses held at p = -100, gamma_xy increased: sqrt(J2) = tau, so tau = xi c - eta p;
   !> the flow has gamma_xy^p = d gamma and eps_v^p = eta_bar d gamma.
   subroutine test_shear(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp) :: strain(6), state(n_state), stress(6), before(6), plastic(6), psi, eta, xi
      integer :: k, step
      call cone_parameters(match_outer, phi*pi/180.0_dp, eta, xi)
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
         call check_close(error, stress(4), xi*cohesion - eta*confining, 1.0e-10_dp, message='tau, psi = '//to_string(psi))
         if (allocated(error)) return
         call check_close(error, sum(plastic(1:3))/plastic(4), eta_of(match_outer, psi), 1.0e-9_dp, &
                          message='d eps_v^p / d gamma_xy^p = eta_bar, psi = '//to_string(psi))
         if (allocated(error)) return
      end do
   end subroutine test_shear

   !> sqrt(J2) + eta p - xi c of a Voigt stress.
   real(dp) function cone_excess(stress, eta, xi, cohesion_now)
      real(dp), intent(in) :: stress(6), eta, xi, cohesion_now
      real(dp) :: p, deviator(3)
      p = sum(stress(1:3))/3.0_dp
      deviator = stress(1:3) - p
      cone_excess = sqrt(0.5_dp*sum(deviator**2) + sum(stress(4:6)**2)) + eta*p - xi*cohesion_now
   end function cone_excess

   !> Trial principal stresses onto the cone (1) and beyond the apex (2).
   pure function region_trial(r) result(principal)
      integer, intent(in) :: r
      real(dp) :: principal(3)
      if (r == 1) then
         principal = [-50.0_dp, -100.0_dp, -300.0_dp]
      else
         principal = [40.0_dp, 35.0_dp, 30.0_dp]
      end if
   end function region_trial

   !> 100 x the trial stresses of the tangent states, for each matching, with hardening: the
   !> stress satisfies f = 0 with c(alpha) to round-off, REGION names the cone or the apex.
   subroutine test_large_step(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp) :: axes(3, 3), stress(6), tangent(6, 6), state(n_state), new(n_state), eta, xi, current
      integer :: r, m
      integer, parameter :: regions(2) = [region_surface, region_apex]
      axes = rotation([1.0_dp, 2.0_dp, -0.5_dp], 0.7_dp)
      state = 0.0_dp
      do m = 1, 3
         call make_soil(material, law, cohesion, phi, 10.0_dp, 500.0_dp, m)
         call cone_parameters(m, phi*pi/180.0_dp, eta, xi)
         do r = 1, 2
            call material_response(error, material, trial_strain(100.0_dp*region_trial(r), axes), stress, tangent, &
                                   .false., state, new)
            if (allocated(error)) return
            call check(error, nint(new(state_region)) == regions(r), 'region, match '//to_string(m))
            if (allocated(error)) return
            current = cohesion + 500.0_dp*new(state_alpha)
            call check_close(error, cone_excess(stress, eta, xi, current), 0.0_dp, 0.0_dp, &
                             1.0e-11_dp*maxval(abs(stress)) + 1.0e-11_dp*current, 'f = 0, match '//to_string(m))
            if (allocated(error)) return
         end do
      end do
   end subroutine test_large_step

   subroutine test_unloading(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp) :: strain(6), state(n_state), new(n_state), loaded(6), unloaded(6), tangent(6, 6), step(6)
      call make_soil(material, law, cohesion, phi, 10.0_dp, 500.0_dp)
      state = 0.0_dp
      strain = trial_strain(region_trial(1), rotation([1.0_dp, 0.0_dp, 1.0_dp], 0.3_dp))
      call material_response(error, material, strain, loaded, tangent, .false., state, new)
      if (allocated(error)) return
      call check(error, nint(new(state_region)) == region_surface, 'loaded onto the cone')
      if (allocated(error)) return
      state = new
      step = -0.3_dp*(strain - state(state_plastic_strain:state_plastic_strain + 5))
      call material_response(error, material, strain + step, unloaded, tangent, .false., state, new)
      if (allocated(error)) return
      call check_matrix_close(error, tangent, hooke_tangent(young, poisson), 1.0e-14_dp, 'unloading tangent')
      if (allocated(error)) return
      call check(error, nint(new(state_region)) == region_elastic .and. new(state_eqps) == state(state_eqps), &
                 'no plastic flow')
      if (allocated(error)) return
      call check_matrix_close(error, reshape(unloaded - loaded, [6, 1]), &
                              reshape(matmul(hooke_tangent(young, poisson), step), [6, 1]), 1.0e-12_dp, &
                              'stress change = D d eps')
   end subroutine test_unloading

   subroutine test_tangents(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp) :: axes(3, 3), stress(6), tangent(6, 6), state(n_state), new(n_state), psi, hard
      integer :: r, k, h, m
      integer, parameter :: regions(2) = [region_surface, region_apex]
      axes = rotation([0.4_dp, -1.0_dp, 0.7_dp], 1.1_dp)
      state = 0.0_dp
      do m = 1, 3
         do h = 1, 2
            hard = merge(0.0_dp, 500.0_dp, h == 1)
            do k = 1, 2
               psi = merge(phi, 10.0_dp, k == 1)
               call make_soil(material, law, cohesion, phi, psi, hard, m)
               do r = 1, 2
                  call material_response(error, material, trial_strain(region_trial(r), axes), stress, tangent, &
                                         .false., state, new)
                  if (allocated(error)) return
                  call check(error, nint(new(state_region)) == regions(r), 'region '//to_string(regions(r)))
                  if (allocated(error)) return
                  call check_tangent_by_differences(error, material, trial_strain(region_trial(r), axes), 1.0e-6_dp, &
                                                    'match '//to_string(m)//', region '//to_string(regions(r))// &
                                                    ', psi '//to_string(psi)//', H '//to_string(hard), .false., state)
                  if (allocated(error)) return
               end do
            end do
         end do
      end do
   end subroutine test_tangents

   subroutine test_tangent_special(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp) :: stress(6), tangent(6, 6), state(n_state), new(n_state), axes(3, 3), green(6)
      call make_soil(material, law, cohesion, phi, 10.0_dp, 500.0_dp)
      state = 0.0_dp
      axes = rotation([1.0_dp, 1.0_dp, 1.0_dp], 0.5_dp)
      call material_response(error, material, trial_strain(region_trial(1), axes), stress, tangent, .false., state, new)
      if (allocated(error)) return
      axes = rotation([0.0_dp, 1.0_dp, 0.3_dp], -0.8_dp)
      call check_tangent_by_differences(error, material, trial_strain(2.0_dp*region_trial(1), axes), 1.0e-6_dp, &
                                        'plastic history', .false., new)
      if (allocated(error)) return
      green = trial_strain(region_trial(1), axes) + [-0.05_dp, 0.02_dp, 0.01_dp, 0.04_dp, 0.0_dp, -0.02_dp]
      call material_response(error, material, green, stress, tangent, .true., state, new)
      if (allocated(error)) return
      call check(error, nint(new(state_region)) /= region_elastic, 'finite strain: plastic')
      if (allocated(error)) return
      call check_tangent_by_differences(error, material, green, 1.0e-6_dp, 'finite strain', .true., state)
   end subroutine test_tangent_special
end module test_drucker_prager
