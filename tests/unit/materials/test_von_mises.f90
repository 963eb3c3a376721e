!> Von Mises plasticity (frix_von_mises_plastic): closed forms of uniaxial stress and pure shear,
!> return onto the yield surface, elastic unloading, Bauschinger effect of kinematic hardening,
!> and the consistent tangent against central differences, under small and finite strain.
!> Steel of the pipe of benchmark S6: E = 210000, nu = 0.3, sigma_y = 420, H = 75000 (MPa).
module test_von_mises
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close
   use frix_material, only: material_t
   use frix_property_list, only: property_list_t, new_property_list
   use frix_hardening, only: hardening_t, read_hardening
   use frix_von_mises_plastic, only: von_mises_plastic_t, init_von_mises_plastic, state_eqps, state_yielded, state_back_stress
   use frix_linear_elastic, only: hooke_tangent
   use test_material_checks, only: check_tangent_by_differences, material_response, check_matrix_close
   implicit none
   private

   public :: collect_von_mises

   real(dp), parameter :: young = 210000.0_dp, poisson = 0.3_dp, yield = 420.0_dp, hard = 75000.0_dp
   real(dp), parameter :: mu = young/(2.0_dp*(1.0_dp + poisson))
   real(dp), parameter :: root_two_thirds = 0.81649658092772603273242802490196_dp
   integer, parameter :: n_state = 14

contains

   subroutine collect_von_mises(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('uniaxial stress, linear hardening: sigma = sy + Et (eps - ey)', test_uniaxial), &
               new_unittest('pure shear, linear hardening: closed form, one step = many steps', test_shear), &
               new_unittest('a strain 100 x the yield strain returns onto the surface', test_large_step), &
               new_unittest('unloading is elastic', test_unloading), &
               new_unittest('kinematic hardening: reverse yield at H eps_p - sy', test_bauschinger), &
               new_unittest('saturation and table hardening: uniaxial closed forms', test_nonlinear_uniaxial), &
               new_unittest('tangent vs differences: small strain, each hardening', test_tangent_small), &
               new_unittest('tangent vs differences: finite strain, each hardening', test_tangent_finite), &
               new_unittest('finite strain uniaxial: Kirchhoff stress vs Hencky closed form', test_finite_uniaxial)]
   end subroutine collect_von_mises

   !> The law with hardening properties `names` = `values` (beside YOUNG, NUE).
   subroutine make_steel(material, names, values, kinematic)
      type(von_mises_plastic_t), intent(out) :: material
      character(len=*), intent(in) :: names(:)
      real(dp), intent(in) :: values(:)
      real(dp), intent(in), optional :: kinematic
      type(property_list_t) :: properties
      type(hardening_t) :: hardening
      type(error_t), allocatable :: error
      real(dp) :: kinematic_modulus
      call new_property_list('MAT_3DMisesPlastic', names, values, properties, error)
      if (.not. allocated(error)) call read_hardening(properties, hardening, error)
      if (allocated(error)) error stop 'test_von_mises: invalid hardening'
      kinematic_modulus = 0.0_dp
      if (present(kinematic)) kinematic_modulus = kinematic
      call init_von_mises_plastic(material, young, poisson, 0.0_dp, hardening, kinematic_modulus)
   end subroutine make_steel

   !> Linear isotropic hardening, SIGY 420, HARD 75000.
   subroutine make_linear_steel(material)
      type(von_mises_plastic_t), intent(out) :: material
      call make_steel(material, [character(len=4) :: 'SIGY', 'HARD'], [yield, hard])
   end subroutine make_linear_steel

   !> Uniaxial stress at axial strain `axial`: the lateral strains e22 = e33 solved so that
   !> sigma_22 = sigma_33 = 0 by Newton with the law's tangent (strain-driven, mixed control).
   subroutine uniaxial(error, material, axial, state, stress, finite)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), intent(in) :: material
      real(dp), intent(in) :: axial
      real(dp), intent(inout) :: state(:)   !! committed history in, new history out
      real(dp), intent(out) :: stress(6)
      logical, intent(in) :: finite
      real(dp) :: strain(6), tangent(6, 6), new(size(state)), lateral
      integer :: iteration
      lateral = -poisson*axial
      do iteration = 1, 50
         strain = [axial, lateral, lateral, 0.0_dp, 0.0_dp, 0.0_dp]
         call material_response(error, material, strain, stress, tangent, finite, state, new)
         if (allocated(error)) return
         if (abs(stress(2)) <= 1.0e-10_dp*yield) exit
         lateral = lateral - stress(2)/(tangent(2, 2) + tangent(2, 3))
      end do
      call check(error, abs(stress(2)) <= 1.0e-10_dp*yield .and. abs(stress(3)) <= 1.0e-10_dp*yield, &
                 'uniaxial: lateral stresses not zero')
      state = new
   end subroutine uniaxial

   subroutine test_uniaxial(error)
      type(error_t), allocatable, intent(out) :: error
      type(von_mises_plastic_t) :: material
      real(dp) :: state(n_state), stress(6), strain, tangent_modulus, expected
      integer :: k
      call make_linear_steel(material)
      state = 0.0_dp
      tangent_modulus = young*hard/(young + hard)
      do k = 1, 20
         strain = 0.001_dp*k
         call uniaxial(error, material, strain, state, stress, .false.)
         if (allocated(error)) return
         expected = merge(young*strain, yield + tangent_modulus*(strain - yield/young), strain <= yield/young)
         call check_close(error, stress(1), expected, 1.0e-10_dp, message='sigma_11 at eps = '//real_text(strain))
         if (allocated(error)) return
         call check_close(error, state(state_eqps), max(0.0_dp, strain - stress(1)/young), 1.0e-9_dp, 1.0e-14_dp, &
                          message='eqps')
         if (allocated(error)) return
      end do
   end subroutine test_uniaxial

   !> gamma_p = (mu gamma - sy/sqrt(3)) / (mu + H/3), tau = mu (gamma - gamma_p) (derived in
   !> docs/materials.md from |s| = sqrt(2) tau = sqrt(2/3) K(alpha), alpha = gamma_p/sqrt(3)).
   subroutine test_shear(error)
      type(error_t), allocatable, intent(out) :: error
      type(von_mises_plastic_t) :: material
      real(dp) :: state(n_state), new(n_state), stress(6), tangent(6, 6), gamma, gamma_p, tau
      integer :: k
      call make_linear_steel(material)
      gamma = 0.02_dp
      gamma_p = (mu*gamma - yield/sqrt(3.0_dp))/(mu + hard/3.0_dp)
      tau = mu*(gamma - gamma_p)
      state = 0.0_dp
      call material_response(error, material, [0.0_dp, 0.0_dp, 0.0_dp, gamma, 0.0_dp, 0.0_dp], stress, tangent, &
                             .false., state, new)
      if (allocated(error)) return
      call check_close(error, stress(4), tau, 1.0e-12_dp, message='tau, one step')
      if (allocated(error)) return
      call check_close(error, new(state_eqps), gamma_p/sqrt(3.0_dp), 1.0e-12_dp, message='alpha')
      if (allocated(error)) return
      do k = 1, 10
         call material_response(error, material, [0.0_dp, 0.0_dp, 0.0_dp, 0.1_dp*k*gamma, 0.0_dp, 0.0_dp], &
                                stress, tangent, .false., state, new)
         if (allocated(error)) return
         state = new
      end do
      call check_close(error, stress(4), tau, 1.0e-12_dp, message='tau, ten steps')
      if (allocated(error)) return
      call check(error, all(abs(stress([1, 2, 3, 5, 6])) <= 1.0e-9_dp*tau), 'pure shear: other stresses zero')
   end subroutine test_shear

   subroutine test_large_step(error)
      type(error_t), allocatable, intent(out) :: error
      type(von_mises_plastic_t) :: material
      real(dp) :: state(n_state), new(n_state), stress(6), tangent(6, 6), strain(6), deviator(6), radius
      call make_steel(material, [character(len=6) :: 'SIGY', 'SIGINF', 'DELTA'], [yield, 600.0_dp, 20.0_dp])
      strain = 100.0_dp*yield/young*[1.0_dp, -0.3_dp, 0.2_dp, 0.5_dp, -0.7_dp, 0.4_dp]
      state = 0.0_dp
      call material_response(error, material, strain, stress, tangent, .false., state, new)
      if (allocated(error)) return
      deviator = stress
      deviator(1:3) = stress(1:3) - sum(stress(1:3))/3.0_dp
      radius = root_two_thirds*(yield + 180.0_dp*(1.0_dp - exp(-20.0_dp*new(state_eqps))))
      call check_close(error, sqrt(sum(deviator(1:3)**2) + 2.0_dp*sum(deviator(4:6)**2)), radius, 1.0e-11_dp, &
                       message='|s| = sqrt(2/3) K(alpha)')
      if (allocated(error)) return
      call check(error, new(state_yielded) == 1.0_dp, 'YIELDED set')
   end subroutine test_large_step

   subroutine test_unloading(error)
      type(error_t), allocatable, intent(out) :: error
      type(von_mises_plastic_t) :: material
      real(dp) :: state(n_state), new(n_state), loaded(6), unloaded(6), tangent(6, 6), strain(6), step(6)
      call make_linear_steel(material)
      strain = 5.0_dp*yield/young*[1.0_dp, -0.2_dp, 0.1_dp, 0.3_dp, 0.0_dp, -0.2_dp]
      state = 0.0_dp
      call material_response(error, material, strain, loaded, tangent, .false., state, new)
      if (allocated(error)) return
      state = new
      step = -0.3_dp*strain
      call material_response(error, material, strain + step, unloaded, tangent, .false., state, new)
      if (allocated(error)) return
      call check_matrix_close(error, tangent, hooke_tangent(young, poisson), 1.0e-14_dp, 'unloading tangent')
      if (allocated(error)) return
      call check(error, new(state_yielded) == 0.0_dp .and. new(state_eqps) == state(state_eqps), 'no plastic flow')
      if (allocated(error)) return
      call check_matrix_close(error, reshape(unloaded - loaded, [6, 1]), &
                              reshape(matmul(hooke_tangent(young, poisson), step), [6, 1]), 1.0e-12_dp, &
                              'stress change = D d eps')
   end subroutine test_unloading

   !> Linear kinematic hardening (KINH = H): loading to eps_p, the reverse yield stress is
   !> H eps_p - sy (the elastic range 2 sy travels with the back stress); with isotropic
   !> hardening of the same H it is -(sy + H eps_p).
   subroutine test_bauschinger(error)
      type(error_t), allocatable, intent(out) :: error
      type(von_mises_plastic_t) :: kinematic, isotropic
      real(dp) :: state_k(n_state), state_i(n_state), stress(6), plastic
      call make_steel(kinematic, [character(len=4) :: 'SIGY'], [yield], kinematic=hard)
      call make_linear_steel(isotropic)
      state_k = 0.0_dp
      state_i = 0.0_dp
      call uniaxial(error, kinematic, 0.01_dp, state_k, stress, .false.)
      if (allocated(error)) return
      plastic = 0.01_dp - stress(1)/young
      call check_close(error, state_k(state_back_stress), (2.0_dp/3.0_dp)*hard*plastic, 1.0e-10_dp, &
                       message='beta_11 = 2/3 H eps_p')
      if (allocated(error)) return
      call uniaxial(error, isotropic, 0.01_dp, state_i, stress, .false.)
      if (allocated(error)) return
      ! unload elastically to just before each reverse yield point
      call uniaxial(error, kinematic, 0.01_dp - (stress(1) - (hard*plastic - yield))/young*0.999_dp, &
                    state_k, stress, .false.)
      if (allocated(error)) return
      call check(error, state_k(state_yielded) == 0.0_dp, 'kinematic: elastic until H eps_p - sy')
      if (allocated(error)) return
      call uniaxial(error, kinematic, 0.003_dp, state_k, stress, .false.)
      if (allocated(error)) return
      call check(error, state_k(state_yielded) == 1.0_dp, 'kinematic: reverse yield')
      if (allocated(error)) return
      call uniaxial(error, isotropic, 0.003_dp, state_i, stress, .false.)
      if (allocated(error)) return
      call check(error, state_i(state_yielded) == 0.0_dp, 'isotropic: still elastic at eps = 0.003')
   end subroutine test_bauschinger

   !> Uniaxial stress sigma = K(eps_p) with eps = eps_p + sigma/E: saturation and a table.
   subroutine test_nonlinear_uniaxial(error)
      type(error_t), allocatable, intent(out) :: error
      type(von_mises_plastic_t) :: saturation, table
      real(dp) :: state(n_state), stress(6), plastic, expected
      integer :: k
      call make_steel(saturation, [character(len=6) :: 'SIGY', 'HARD', 'SIGINF', 'DELTA'], [yield, 1000.0_dp, 600.0_dp, 20.0_dp])
      call make_steel(table, [character(len=5) :: 'SIGY', 'EPSP1', 'SIGY1', 'EPSP2', 'SIGY2'], &
                    [yield, 0.01_dp, 500.0_dp, 0.05_dp, 540.0_dp])
      state = 0.0_dp
      do k = 1, 30
         call uniaxial(error, saturation, 0.002_dp*k, state, stress, .false.)
         if (allocated(error)) return
      end do
      plastic = state(state_eqps)
      expected = yield + 1000.0_dp*plastic + 180.0_dp*(1.0_dp - exp(-20.0_dp*plastic))
      call check_close(error, stress(1), expected, 1.0e-10_dp, message='saturation: sigma = K(eps_p)')
      if (allocated(error)) return
      call check_close(error, 0.06_dp, plastic + stress(1)/young, 1.0e-10_dp, message='saturation: eps split')
      if (allocated(error)) return
      state = 0.0_dp
      do k = 1, 40
         call uniaxial(error, table, 0.0025_dp*k, state, stress, .false.)
         if (allocated(error)) return
         plastic = state(state_eqps)
         if (plastic < 0.01_dp) then
            expected = yield + 8000.0_dp*plastic
         else if (plastic < 0.05_dp) then
            expected = 500.0_dp + 1000.0_dp*(plastic - 0.01_dp)
         else
            expected = 540.0_dp
         end if
         call check_close(error, stress(1), expected, 1.0e-10_dp, &
                          message='table: sigma = K(eps_p) at step '//real_text(real(k, dp)))
         if (allocated(error)) return
      end do
   end subroutine test_nonlinear_uniaxial

   !> States: elastic; just past first yield (1.05 eps_y); plastic from a plastic history.
   subroutine tangent_states(error, material, finite, label)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), intent(in) :: material
      logical, intent(in) :: finite
      character(len=*), intent(in) :: label
      real(dp), parameter :: direction(6) = [1.0_dp, -0.4_dp, 0.1_dp, 0.6_dp, -0.3_dp, 0.2_dp]
      real(dp) :: state(n_state), new(n_state), stress(6), tangent(6, 6), first_yield, deviator(6)
      ! c direction first yields where 2 mu c |dev direction| = sqrt(2/3) sy (tensor norm)
      deviator(1:3) = direction(1:3) - sum(direction(1:3))/3.0_dp
      deviator(4:6) = 0.5_dp*direction(4:6)
      first_yield = root_two_thirds*yield/(2.0_dp*mu*sqrt(sum(deviator(1:3)**2) + 2.0_dp*sum(deviator(4:6)**2)))
      state = 0.0_dp
      call check_tangent_by_differences(error, material, 0.5_dp*first_yield*direction, 1.0e-6_dp, &
                                        label//' elastic', finite, state)
      if (allocated(error)) return
      call material_response(error, material, 1.05_dp*first_yield*direction, stress, tangent, finite, state, new)
      if (allocated(error)) return
      call check(error, new(state_yielded) == 1.0_dp, label//': 1.05 x first yield is plastic')
      if (allocated(error)) return
      call check_tangent_by_differences(error, material, 1.05_dp*first_yield*direction, 1.0e-6_dp, &
                                        label//' first yield', finite, state)
      if (allocated(error)) return
      call material_response(error, material, 8.0_dp*first_yield*direction, stress, tangent, finite, state, new)
      if (allocated(error)) return
      call check_tangent_by_differences(error, material, &
                                        8.0_dp*first_yield*direction + 3.0_dp*first_yield*[0.2_dp, 1.0_dp, -0.5_dp, &
                                        0.1_dp, 0.4_dp, -0.6_dp], 1.0e-6_dp, label//' plastic', finite, new)
   end subroutine tangent_states

   subroutine test_tangent_small(error)
      type(error_t), allocatable, intent(out) :: error
      call each_hardening(error, .false.)
   end subroutine test_tangent_small

   !> Also large strains (stretches ~ 1.3, rotations of the principal axes between history and
   !> state) and coinciding principal stretches (two equal; all three equal), where the
   !> logarithm's divided differences take their confluent limits.
   subroutine test_tangent_finite(error)
      type(error_t), allocatable, intent(out) :: error
      type(von_mises_plastic_t) :: material
      real(dp) :: state(n_state), new(n_state), stress(6), tangent(6, 6)
      call each_hardening(error, .true.)
      if (allocated(error)) return
      call make_steel(material, [character(len=6) :: 'SIGY', 'SIGINF', 'DELTA'], [yield, 600.0_dp, 20.0_dp], kinematic=hard)
      state = 0.0_dp
      call material_response(error, material, [0.3_dp, -0.1_dp, -0.12_dp, 0.2_dp, 0.05_dp, -0.1_dp], stress, &
                             tangent, .true., state, new)
      if (allocated(error)) return
      call check_tangent_by_differences(error, material, [0.35_dp, -0.12_dp, -0.1_dp, -0.1_dp, 0.15_dp, 0.1_dp], &
                                        1.0e-6_dp, 'large strain, rotated axes', .true., new)
      if (allocated(error)) return
      call check_tangent_by_differences(error, material, [0.4_dp, -0.15_dp, -0.15_dp, 0.0_dp, 0.0_dp, 0.0_dp], &
                                        1.0e-6_dp, 'two equal stretches', .true., new)
      if (allocated(error)) return
      call check_tangent_by_differences(error, material, [0.1_dp, 0.1_dp, 0.1_dp, 0.0_dp, 0.0_dp, 0.0_dp], &
                                        1.0e-6_dp, 'three equal stretches', .true., new)
   end subroutine test_tangent_finite

   subroutine each_hardening(error, finite)
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in) :: finite
      type(von_mises_plastic_t) :: material
      call make_linear_steel(material)
      call tangent_states(error, material, finite, 'linear')
      if (allocated(error)) return
      call make_steel(material, [character(len=4) :: 'SIGY'], [yield])
      call tangent_states(error, material, finite, 'perfectly plastic')
      if (allocated(error)) return
      call make_steel(material, [character(len=6) :: 'SIGY', 'SIGINF', 'DELTA'], [yield, 600.0_dp, 20.0_dp])
      call tangent_states(error, material, finite, 'saturation')
      if (allocated(error)) return
      call make_steel(material, [character(len=5) :: 'SIGY', 'EPSP1', 'SIGY1'], [yield, 0.5_dp, 900.0_dp])
      call tangent_states(error, material, finite, 'table')
      if (allocated(error)) return
      call make_steel(material, [character(len=4) :: 'SIGY', 'HARD'], [yield, 2000.0_dp], kinematic=hard)
      call tangent_states(error, material, finite, 'kinematic')
   end subroutine each_hardening

   !> Uniaxial stress at stretch lambda: in the principal axes T = tau (Kirchhoff stress) and
   !> E_log,11 = ln lambda, so tau_11 = sy + Et (ln lambda - sy/E) past yield (Hencky law with
   !> J2 flow in log strain; Miehe, Apel & Lambrecht 2002); S_11 = tau_11 / lambda^2.
   subroutine test_finite_uniaxial(error)
      type(error_t), allocatable, intent(out) :: error
      type(von_mises_plastic_t) :: material
      real(dp) :: state(n_state), stress(6), stretch, green, log_strain, expected
      integer :: k
      call make_linear_steel(material)
      state = 0.0_dp
      do k = 1, 10
         stretch = 1.0_dp + 0.03_dp*k
         green = 0.5_dp*(stretch**2 - 1.0_dp)
         call uniaxial(error, material, green, state, stress, .true.)
         if (allocated(error)) return
      end do
      log_strain = log(stretch)
      expected = yield + young*hard/(young + hard)*(log_strain - yield/young)
      call check_close(error, stress(1)*stretch**2, expected, 1.0e-10_dp, message='tau_11 at stretch 1.3')
      if (allocated(error)) return
      call check_close(error, state(state_eqps), log_strain - expected/young, 1.0e-9_dp, message='eqps = ln lambda_p')
   end subroutine test_finite_uniaxial

   function real_text(x) result(text)
      real(dp), intent(in) :: x
      character(len=16) :: text
      write (text, '(g0.4)') x
   end function real_text
end module test_von_mises
