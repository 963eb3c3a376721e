!> Neo-Hookean law of Abaqus and CalculiX, W = C10 (I1bar - 3) + (J - 1)^2 / D1
!> (frix_abaqus_neo_hooke), checked against formulas that do not use its code:
!>   Cauchy stress   sigma = mu0/J (bbar - 1/3 tr(bbar) I) + K0 (J - 1) I, bbar = J^(-2/3) F F^T
!>                   (Abaqus Theory Manual 4.6.1), evaluated with 3 x 3 tensors for general
!>                   (non-symmetric, rotated) F and compared with F S F^T / J;
!>   dilatation      F = l I: bbar = I, sigma = K0 (J - 1) I, S = J l^-2 sigma = K0 l (l^3 - 1) I;
!>   uniaxial stress F = diag(l, t, t), J = l t^2: sigma_11 - sigma_22 = mu0 J^(-5/3) (l^2 - t^2),
!>                   sigma_22 = -mu0 J^(-5/3) (l^2 - t^2)/3 + K0 (J - 1). Given l and J (so t), the
!>                   lateral stress vanishes for K0 = mu0 J^(-5/3) (l^2 - t^2) / (3 (J - 1)), and then
!>                   S_11 = J sigma_11 / l^2 = mu0 J^(-2/3) (l^2 - t^2) / l^2, S_22 = S_33 = 0;
!>                   as J -> 1 the nominal stress l S_11 tends to the incompressible neo-Hookean
!>                   2 C10 (l - l^-2) (Treloar);
!>   small strain    Hooke's law with mu = mu0 = 2 C10 and K = K0 = 2/D1.
!> mu0 = 2 C10 = 160, K0 = 2/D1 = 2000 unless stated.
module test_abaqus_neo_hooke
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close, check_message_contains
   use frix_abaqus_neo_hooke, only: abaqus_neo_hooke_t, new_abaqus_neo_hooke
   use frix_linear_elastic, only: hooke_tangent
   use test_material_checks, only: check_matrix_close, check_tangent_by_differences, material_response
   implicit none
   private

   public :: collect_abaqus_neo_hooke

   real(dp), parameter :: c10 = 80.0_dp, d1 = 1.0e-3_dp
   real(dp), parameter :: mu0 = 2.0_dp*c10, k0 = 2.0_dp/d1
   !> Small-strain constants of (mu0, K0), written out: E = 9 K mu/(3K + mu), nu = (3K - 2mu)/(2(3K + mu)).
   real(dp), parameter :: young = 9.0_dp*k0*mu0/(3.0_dp*k0 + mu0)
   real(dp), parameter :: poisson = (3.0_dp*k0 - 2.0_dp*mu0)/(2.0_dp*(3.0_dp*k0 + mu0))

contains

   subroutine collect_abaqus_neo_hooke(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('constructor: name, mu0 = 2 C10, K0 = 2/D1, equivalent E and nu', test_constructor), &
               new_unittest('E = 0: zero stress, Hooke tangent of mu0, K0 (both kinematics)', test_zero_strain), &
               new_unittest('small-strain limit equals Hooke', test_small_strain_limit), &
               new_unittest('Cauchy stress of the Abaqus manual, general rotated F', test_cauchy_general), &
               new_unittest('pure dilatation, stretch 1.2 and 0.8', test_dilatation), &
               new_unittest('uniaxial stress: closed form, tension and compression', test_uniaxial), &
               new_unittest('nearly incompressible uniaxial: nominal stress 2 C10 (l - l^-2)', &
                            test_incompressible_uniaxial), &
               new_unittest('tangent symmetric at finite strain', test_tangent_symmetric), &
               new_unittest('tangent vs finite differences, finite strain', test_tangent_differences), &
               new_unittest('det C <= 0 is an error', test_inverted)]
   end subroutine collect_abaqus_neo_hooke

   subroutine test_constructor(error)
      type(error_t), allocatable, intent(out) :: error
      type(abaqus_neo_hooke_t) :: material
      material = new_abaqus_neo_hooke(c10, d1, 1.5_dp)
      call check(error, material%name == 'MAT_Struct_NeoHookeAbaqus', 'name')
      if (allocated(error)) return
      call check(error, material%n_state() == 0, 'no history')
      if (allocated(error)) return
      call check_close(error, material%density, 1.5_dp, 0.0_dp, message='density')
      if (allocated(error)) return
      call check_close(error, material%shear_modulus, mu0, 1.0e-15_dp, message='mu0')
      if (allocated(error)) return
      call check_close(error, material%bulk_modulus, k0, 1.0e-15_dp, message='K0')
      if (allocated(error)) return
      call check_close(error, material%young, young, 1.0e-14_dp, message='young')
      if (allocated(error)) return
      call check_close(error, material%poisson, poisson, 1.0e-14_dp, message='poisson')
   end subroutine test_constructor

   subroutine test_zero_strain(error)
      type(error_t), allocatable, intent(out) :: error
      type(abaqus_neo_hooke_t) :: material
      real(dp) :: stress(6), tangent(6, 6), elastic(6, 6)
      integer :: k
      logical :: finite
      material = new_abaqus_neo_hooke(c10, d1, 0.0_dp)
      do k = 1, 2
         finite = k == 2
         call material_response(error, material, [real(dp) :: 0, 0, 0, 0, 0, 0], stress, tangent, finite)
         if (allocated(error)) return
         call check(error, all(abs(stress) <= 1.0e-13_dp*mu0), 'stress at E = 0')
         if (allocated(error)) return
         call check_matrix_close(error, tangent, hooke_tangent(young, poisson), 1.0e-13_dp, 'tangent at E = 0 vs Hooke')
         if (allocated(error)) return
      end do
      call material%elastic_tangent(elastic)
      call check_matrix_close(error, elastic, hooke_tangent(young, poisson), 1.0e-13_dp, 'elastic_tangent vs Hooke')
      if (allocated(error)) return
      ! shear row: tau_xy = mu0 gamma_xy
      call check_close(error, elastic(4, 4), mu0, 1.0e-14_dp, message='shear modulus mu0')
      if (allocated(error)) return
      call check_close(error, elastic(1, 2) + 2.0_dp/3.0_dp*mu0, k0, 1.0e-14_dp, message='lambda + 2/3 mu0 = K0')
   end subroutine test_zero_strain

   !> Under Geo_Lin (finite = .false.) at |eps| ~ 1e-7: tangent and stress Hooke's to O(|eps|).
   subroutine test_small_strain_limit(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: direction(6) = [0.3_dp, -0.5_dp, 1.0_dp, 0.7_dp, -0.2_dp, 0.4_dp]
      real(dp) :: strain(6), stress(6), tangent(6, 6), hooke_stress(6)
      integer :: i
      strain = 1.0e-7_dp*direction
      call material_response(error, new_abaqus_neo_hooke(c10, d1, 0.0_dp), strain, stress, tangent, .false.)
      if (allocated(error)) return
      call check_matrix_close(error, tangent, hooke_tangent(young, poisson), 1.0e-6_dp, 'tangent vs Hooke')
      if (allocated(error)) return
      hooke_stress = matmul(hooke_tangent(young, poisson), strain)
      do i = 1, 6
         call check_close(error, stress(i), hooke_stress(i), 1.0e-6_dp, 1.0e-6_dp*maxval(abs(hooke_stress)), &
                          'stress vs Hooke')
         if (allocated(error)) return
      end do
   end subroutine test_small_strain_limit

   !> sigma = F S F^T / J of the law vs the manual's Cauchy stress, for F = R A with A
   !> non-symmetric and R a rotation by 40 degrees about (1, 2, 3); J > 1 and J < 1.
   subroutine test_cauchy_general(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: stretches(3, 3, 2), gradient(3, 3), rotation(3, 3)
      real(dp) :: pk2(3, 3), pushed(3, 3), expected(3, 3), stress(6), tangent(6, 6), jacobian
      integer :: k
      stretches(:, :, 1) = reshape([1.25_dp, 0.15_dp, 0.0_dp, 0.1_dp, 0.9_dp, -0.1_dp, -0.05_dp, 0.2_dp, 1.1_dp], [3, 3])
      stretches(:, :, 2) = reshape([0.8_dp, -0.1_dp, 0.05_dp, 0.2_dp, 0.85_dp, 0.1_dp, 0.0_dp, -0.15_dp, 0.95_dp], [3, 3])
      rotation = rotation_matrix([1.0_dp, 2.0_dp, 3.0_dp], 40.0_dp)
      do k = 1, 2
         gradient = matmul(rotation, stretches(:, :, k))
         jacobian = determinant(gradient)
         call material_response(error, new_abaqus_neo_hooke(c10, d1, 0.0_dp), green_lagrange(gradient), stress, &
                                tangent, .true.)
         if (allocated(error)) return
         pk2 = tensor_of_stress(stress)
         pushed = matmul(gradient, matmul(pk2, transpose(gradient)))/jacobian
         expected = cauchy_stress(gradient)
         call check(error, (k == 1 .eqv. jacobian > 1.0_dp), 'J > 1 then J < 1')
         if (allocated(error)) return
         call check_matrix_close(error, pushed, expected, 1.0e-12_dp, 'F S F^T / J vs manual')
         if (allocated(error)) return
      end do
   end subroutine test_cauchy_general

   subroutine test_dilatation(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: stretches(2), stretch, green, expected, stress(6), tangent(6, 6)
      integer :: k, i
      stretches = [1.2_dp, 0.8_dp]
      do k = 1, 2
         stretch = stretches(k)
         green = 0.5_dp*(stretch**2 - 1.0_dp)
         expected = k0*stretch*(stretch**3 - 1.0_dp)
         call material_response(error, new_abaqus_neo_hooke(c10, d1, 0.0_dp), &
                                [green, green, green, 0.0_dp, 0.0_dp, 0.0_dp], stress, tangent, .true.)
         if (allocated(error)) return
         do i = 1, 3
            call check_close(error, stress(i), expected, 1.0e-13_dp, message='S_ii')
            if (allocated(error)) return
            call check_close(error, stress(i + 3), 0.0_dp, 0.0_dp, 1.0e-13_dp*abs(expected), 'S_ij')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_dilatation

   !> Stretch 1.5 with J = 1.1, and 0.7 with J = 0.95 (module header).
   subroutine test_uniaxial(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: axial(2) = [1.5_dp, 0.7_dp], volume(2) = [1.1_dp, 0.95_dp]
      real(dp) :: stress(6), lateral, bulk, expected
      integer :: k
      do k = 1, 2
         call uniaxial_state(axial(k), volume(k), stress, lateral, bulk, error)
         if (allocated(error)) return
         call check(error, bulk > 0.0_dp, 'K0 > 0')
         if (allocated(error)) return
         expected = mu0*volume(k)**(-2.0_dp/3.0_dp)*(axial(k)**2 - lateral**2)/axial(k)**2
         call check_close(error, stress(1), expected, 1.0e-12_dp, message='S_11')
         if (allocated(error)) return
         call check(error, all(abs(stress(2:6)) <= 1.0e-12_dp*abs(expected)), 'S_22 = S_33 = 0, no shear')
         if (allocated(error)) return
      end do
   end subroutine test_uniaxial

   !> J - 1 = +-1e-7 (K0 / mu0 ~ 1e6): the nominal stress l S_11 within 1e-6 of 2 C10 (l - l^-2).
   subroutine test_incompressible_uniaxial(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: axial(2) = [1.5_dp, 0.6_dp], volume(2) = [1.0_dp + 1.0e-7_dp, 1.0_dp - 1.0e-7_dp]
      real(dp) :: stress(6), lateral, bulk
      integer :: k
      do k = 1, 2
         call uniaxial_state(axial(k), volume(k), stress, lateral, bulk, error)
         if (allocated(error)) return
         call check(error, bulk > 1.0e5_dp*mu0, 'nearly incompressible')
         if (allocated(error)) return
         call check_close(error, axial(k)*stress(1), 2.0_dp*c10*(axial(k) - axial(k)**(-2)), 1.0e-6_dp, &
                          message='nominal stress')
         if (allocated(error)) return
         call check(error, all(abs(stress(2:6)) <= 1.0e-8_dp*abs(stress(1))), 'S_22 = S_33 = 0')
         if (allocated(error)) return
      end do
   end subroutine test_incompressible_uniaxial

   !> The law's S at F = diag(l, t, t), t = sqrt(J / l), with the K0 (D1 = 2 / K0) that makes the
   !> lateral Cauchy stress vanish (module header).
   subroutine uniaxial_state(axial, volume, stress, lateral, bulk, error)
      real(dp), intent(in) :: axial, volume
      real(dp), intent(out) :: stress(6), lateral, bulk
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(6, 6), lateral_green
      lateral = sqrt(volume/axial)
      bulk = mu0*volume**(-5.0_dp/3.0_dp)*(axial**2 - lateral**2)/(3.0_dp*(volume - 1.0_dp))
      lateral_green = 0.5_dp*(lateral**2 - 1.0_dp)
      call material_response(error, new_abaqus_neo_hooke(c10, 2.0_dp/bulk, 0.0_dp), &
                             [0.5_dp*(axial**2 - 1.0_dp), lateral_green, lateral_green, 0.0_dp, 0.0_dp, 0.0_dp], &
                             stress, tangent, .true.)
   end subroutine uniaxial_state

   !> A hyperelastic tangent is the Hessian of W: major symmetry.
   subroutine test_tangent_symmetric(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: stress(6), tangent(6, 6)
      call material_response(error, new_abaqus_neo_hooke(c10, d1, 0.0_dp), &
                             [0.2_dp, -0.1_dp, 0.3_dp, 0.25_dp, -0.15_dp, 0.1_dp], stress, tangent, .true.)
      if (allocated(error)) return
      call check_matrix_close(error, tangent, transpose(tangent), 1.0e-14_dp, 'symmetry')
   end subroutine test_tangent_symmetric

   !> Tension, compression, the E of the rotated F of test_cauchy_general, and a nearly
   !> incompressible material (K0 / mu0 = 1e4).
   subroutine test_tangent_differences(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: gradient(3, 3)
      call check_tangent_by_differences(error, new_abaqus_neo_hooke(c10, d1, 0.0_dp), &
                                        [0.2_dp, -0.1_dp, 0.3_dp, 0.25_dp, -0.15_dp, 0.1_dp], 1.0e-6_dp, &
                                        'dS/dE tension', .true.)
      if (allocated(error)) return
      call check_tangent_by_differences(error, new_abaqus_neo_hooke(c10, d1, 0.0_dp), &
                                        [-0.3_dp, 0.1_dp, -0.2_dp, 0.2_dp, 0.1_dp, -0.1_dp], 1.0e-6_dp, &
                                        'dS/dE compression', .true.)
      if (allocated(error)) return
      gradient = matmul(rotation_matrix([1.0_dp, 2.0_dp, 3.0_dp], 40.0_dp), &
                        reshape([1.25_dp, 0.15_dp, 0.0_dp, 0.1_dp, 0.9_dp, -0.1_dp, -0.05_dp, 0.2_dp, 1.1_dp], [3, 3]))
      call check_tangent_by_differences(error, new_abaqus_neo_hooke(c10, d1, 0.0_dp), green_lagrange(gradient), &
                                        1.0e-6_dp, 'dS/dE rotated F', .true.)
      if (allocated(error)) return
      call check_tangent_by_differences(error, new_abaqus_neo_hooke(c10, 2.0_dp/(1.0e4_dp*mu0), 0.0_dp), &
                                        [0.15_dp, -0.07_dp, -0.07_dp, 0.1_dp, 0.0_dp, 0.05_dp], 1.0e-6_dp, &
                                        'dS/dE nearly incompressible', .true.)
   end subroutine test_tangent_differences

   !> E_xx = -0.6 gives C_xx = -0.2, det C = -0.2.
   subroutine test_inverted(error)
      type(error_t), allocatable, intent(out) :: error
      type(abaqus_neo_hooke_t) :: material
      type(error_t), allocatable :: law_error
      real(dp) :: state_old(0), state_new(0), stress(6), tangent(6, 6)
      material = new_abaqus_neo_hooke(c10, d1, 0.0_dp)
      call material%response([-0.6_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], .true., state_old, state_new, stress, &
                             tangent, law_error)
      call check_message_contains(error, law_error, 'det C')
      if (allocated(error)) return
      call check_message_contains(error, law_error, 'MAT_Struct_NeoHookeAbaqus')
   end subroutine test_inverted

   ! ---- 3 x 3 tensor helpers, independent of the law's code ----------------------------------

   !> sigma = mu0/J (bbar - 1/3 tr(bbar) I) + K0 (J - 1) I, bbar = J^(-2/3) F F^T.
   function cauchy_stress(gradient) result(sigma)
      real(dp), intent(in) :: gradient(3, 3)
      real(dp) :: sigma(3, 3)
      real(dp) :: jacobian, left(3, 3), trace
      integer :: i
      jacobian = determinant(gradient)
      left = jacobian**(-2.0_dp/3.0_dp)*matmul(gradient, transpose(gradient))
      trace = left(1, 1) + left(2, 2) + left(3, 3)
      sigma = mu0/jacobian*left
      do i = 1, 3
         sigma(i, i) = sigma(i, i) - mu0/jacobian*trace/3.0_dp + k0*(jacobian - 1.0_dp)
      end do
   end function cauchy_stress

   !> E = (F^T F - I) / 2 in Voigt form with engineering shears (gamma_ij = C_ij, i /= j).
   function green_lagrange(gradient) result(strain)
      real(dp), intent(in) :: gradient(3, 3)
      real(dp) :: strain(6)
      real(dp) :: c(3, 3)
      c = matmul(transpose(gradient), gradient)
      strain = [0.5_dp*(c(1, 1) - 1.0_dp), 0.5_dp*(c(2, 2) - 1.0_dp), 0.5_dp*(c(3, 3) - 1.0_dp), &
                c(1, 2), c(1, 3), c(2, 3)]
   end function green_lagrange

   function tensor_of_stress(voigt) result(tensor)
      real(dp), intent(in) :: voigt(6)
      real(dp) :: tensor(3, 3)
      tensor = reshape([voigt(1), voigt(4), voigt(5), voigt(4), voigt(2), voigt(6), voigt(5), voigt(6), voigt(3)], &
                       [3, 3])
   end function tensor_of_stress

   real(dp) function determinant(a)
      real(dp), intent(in) :: a(3, 3)
      determinant = a(1, 1)*(a(2, 2)*a(3, 3) - a(2, 3)*a(3, 2)) - a(1, 2)*(a(2, 1)*a(3, 3) - a(2, 3)*a(3, 1)) &
                    + a(1, 3)*(a(2, 1)*a(3, 2) - a(2, 2)*a(3, 1))
   end function determinant

   !> Rotation by `degrees` about `axis` (Rodrigues: R = I + sin(t) K + (1 - cos(t)) K^2).
   function rotation_matrix(axis, degrees) result(rotation)
      real(dp), intent(in) :: axis(3), degrees
      real(dp) :: rotation(3, 3)
      real(dp) :: n(3), skew(3, 3), angle
      integer :: i
      n = axis/norm2(axis)
      angle = degrees*acos(-1.0_dp)/180.0_dp
      skew = reshape([0.0_dp, n(3), -n(2), -n(3), 0.0_dp, n(1), n(2), -n(1), 0.0_dp], [3, 3])
      rotation = sin(angle)*skew + (1.0_dp - cos(angle))*matmul(skew, skew)
      do i = 1, 3
         rotation(i, i) = rotation(i, i) + 1.0_dp
      end do
   end function rotation_matrix
end module test_abaqus_neo_hooke
