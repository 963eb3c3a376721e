!> Hooke's law against the analytic responses of elementary stress states
!> (Timoshenko & Goodier: eps_xx = sigma/E, eps_yy = eps_zz = -nu sigma/E under uniaxial
!> stress; tau = G gamma, G = E / (2 (1 + nu)); p = K tr(eps), K = E / (3 (1 - 2 nu))).
module test_linear_elastic
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close
   use frix_linear_elastic, only: linear_elastic_t, new_linear_elastic
   use test_material_checks, only: check_matrix_close, check_tangent_by_differences, material_response
   implicit none
   private

   public :: collect_linear_elastic

   real(dp), parameter :: young = 1000.0_dp, poisson = 0.3_dp

contains

   subroutine collect_linear_elastic(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('constructor sets name and data', test_constructor), &
               new_unittest('uniaxial stress: E and lateral strain -nu', test_uniaxial_stress), &
               new_unittest('shear: tau = G gamma (engineering shear)', test_shear), &
               new_unittest('volumetric: p = K tr(eps)', test_volumetric), &
               new_unittest('tangent symmetric and equal to elastic_tangent', test_tangent_symmetric), &
               new_unittest('tangent vs finite differences', test_tangent_differences)]
   end subroutine collect_linear_elastic

   subroutine test_constructor(error)
      type(error_t), allocatable, intent(out) :: error
      type(linear_elastic_t) :: material
      material = new_linear_elastic(young, poisson, 7.5_dp)
      call check(error, material%name == 'MAT_Struct_LinearElastic', 'name')
      if (allocated(error)) return
      call check(error, material%n_state() == 0, 'no history')
      if (allocated(error)) return
      call check_close(error, material%density, 7.5_dp, 0.0_dp, message='density')
      if (allocated(error)) return
      call check_close(error, material%young, young, 0.0_dp, message='young')
      if (allocated(error)) return
      call check_close(error, material%poisson, poisson, 0.0_dp, message='poisson')
   end subroutine test_constructor

   !> Strain of the analytic compliance for sigma_xx = 2 must give stress (2, 0, 0, 0, 0, 0).
   subroutine test_uniaxial_stress(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: sigma = 2.0_dp
      real(dp) :: strain(6), stress(6), tangent(6, 6)
      integer :: i
      strain = [sigma/young, -poisson*sigma/young, -poisson*sigma/young, 0.0_dp, 0.0_dp, 0.0_dp]
      call material_response(error, new_linear_elastic(young, poisson, 0.0_dp), strain, stress, tangent)
      if (allocated(error)) return
      call check_close(error, stress(1), sigma, 1.0e-13_dp, message='sigma_xx')
      if (allocated(error)) return
      do i = 2, 6
         call check_close(error, stress(i), 0.0_dp, 0.0_dp, 1.0e-13_dp*sigma, 'lateral/shear stress')
         if (allocated(error)) return
      end do
   end subroutine test_uniaxial_stress

   subroutine test_shear(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: strain(6), stress(6), tangent(6, 6), shear_modulus
      integer :: i
      shear_modulus = young/(2.0_dp*(1.0_dp + poisson))
      do i = 4, 6
         strain = 0.0_dp
         strain(i) = 1.0e-3_dp
         call material_response(error, new_linear_elastic(young, poisson, 0.0_dp), strain, stress, tangent)
         if (allocated(error)) return
         call check_close(error, stress(i), shear_modulus*1.0e-3_dp, 1.0e-13_dp, message='tau')
         if (allocated(error)) return
         call check_close(error, sum(abs(stress)) - abs(stress(i)), 0.0_dp, 0.0_dp, 1.0e-16_dp, &
                          'no other stress component')
         if (allocated(error)) return
      end do
   end subroutine test_shear

   subroutine test_volumetric(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: e = 1.0e-3_dp
      real(dp) :: strain(6), stress(6), tangent(6, 6), bulk_modulus
      integer :: i
      bulk_modulus = young/(3.0_dp*(1.0_dp - 2.0_dp*poisson))
      strain = [e, e, e, 0.0_dp, 0.0_dp, 0.0_dp]
      call material_response(error, new_linear_elastic(young, poisson, 0.0_dp), strain, stress, tangent)
      if (allocated(error)) return
      do i = 1, 3
         call check_close(error, stress(i), bulk_modulus*3.0_dp*e, 1.0e-13_dp, message='mean stress')
         if (allocated(error)) return
      end do
   end subroutine test_volumetric

   subroutine test_tangent_symmetric(error)
      type(error_t), allocatable, intent(out) :: error
      type(linear_elastic_t) :: material
      real(dp) :: stress(6), tangent(6, 6), elastic(6, 6)
      material = new_linear_elastic(young, poisson, 0.0_dp)
      call material_response(error, material, [1.0e-3_dp, 2.0e-3_dp, -1.0e-3_dp, 5.0e-4_dp, 0.0_dp, 3.0e-4_dp], &
                             stress, tangent)
      if (allocated(error)) return
      call check_matrix_close(error, tangent, transpose(tangent), 1.0e-15_dp, 'symmetry')
      if (allocated(error)) return
      call material%elastic_tangent(elastic)
      call check_matrix_close(error, tangent, elastic, 1.0e-15_dp, 'elastic_tangent')
   end subroutine test_tangent_symmetric

   subroutine test_tangent_differences(error)
      type(error_t), allocatable, intent(out) :: error
      call check_tangent_by_differences(error, new_linear_elastic(young, poisson, 0.0_dp), &
                                        [0.1_dp, -0.05_dp, 0.2_dp, 0.3_dp, -0.1_dp, 0.15_dp], 1.0e-6_dp, 'D')
   end subroutine test_tangent_differences
end module test_linear_elastic
