!> St. Venant-Kirchhoff: S = lambda tr(E) I + 2 mu E (Holzapfel eq. 6.151), evaluated here in
!> 3 x 3 tensor form with E_ij = gamma_ij / 2, independently of the Voigt matrix of the library.
module test_saint_venant_kirchhoff
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close
   use frix_saint_venant_kirchhoff, only: saint_venant_kirchhoff_t, new_saint_venant_kirchhoff
   use test_material_checks, only: check_tangent_by_differences, material_response
   implicit none
   private

   public :: collect_saint_venant_kirchhoff

   real(dp), parameter :: young = 1000.0_dp, poisson = 0.3_dp
   real(dp), parameter :: finite_strain(6) = [0.1_dp, -0.05_dp, 0.2_dp, 0.3_dp, -0.1_dp, 0.15_dp]

contains

   subroutine collect_saint_venant_kirchhoff(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('constructor sets name and data', test_constructor), &
               new_unittest('finite strain: S = lambda tr(E) I + 2 mu E (tensor form)', test_tensor_form), &
               new_unittest('tangent vs finite differences', test_tangent_differences)]
   end subroutine collect_saint_venant_kirchhoff

   subroutine test_constructor(error)
      type(error_t), allocatable, intent(out) :: error
      type(saint_venant_kirchhoff_t) :: material
      material = new_saint_venant_kirchhoff(young, poisson, 20.0_dp)
      call check(error, material%name == 'MAT_Struct_StVenantKirchhoff', 'name')
      if (allocated(error)) return
      call check_close(error, material%density, 20.0_dp, 0.0_dp, message='density')
   end subroutine test_constructor

   subroutine test_tensor_form(error)
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: row(6) = [1, 2, 3, 1, 1, 2], column(6) = [1, 2, 3, 2, 3, 3]
      real(dp) :: strain_tensor(3, 3), stress_tensor(3, 3), identity(3, 3)
      real(dp) :: stress(6), tangent(6, 6), lambda, mu
      integer :: a
      lambda = young*poisson/((1.0_dp + poisson)*(1.0_dp - 2.0_dp*poisson))
      mu = young/(2.0_dp*(1.0_dp + poisson))
      identity = 0.0_dp
      do a = 1, 3
         identity(a, a) = 1.0_dp
         strain_tensor(a, a) = finite_strain(a)
      end do
      do a = 4, 6
         strain_tensor(row(a), column(a)) = 0.5_dp*finite_strain(a)
         strain_tensor(column(a), row(a)) = 0.5_dp*finite_strain(a)
      end do
      stress_tensor = lambda*(strain_tensor(1, 1) + strain_tensor(2, 2) + strain_tensor(3, 3))*identity &
                      + 2.0_dp*mu*strain_tensor
      call material_response(error, new_saint_venant_kirchhoff(young, poisson, 0.0_dp), finite_strain, &
                             stress, tangent)
      if (allocated(error)) return
      do a = 1, 6
         call check_close(error, stress(a), stress_tensor(row(a), column(a)), 1.0e-13_dp, &
                          1.0e-13_dp*maxval(abs(stress_tensor)), 'S component')
         if (allocated(error)) return
      end do
   end subroutine test_tensor_form

   subroutine test_tangent_differences(error)
      type(error_t), allocatable, intent(out) :: error
      call check_tangent_by_differences(error, new_saint_venant_kirchhoff(young, poisson, 0.0_dp), &
                                        finite_strain, 1.0e-6_dp, 'dS/dE')
   end subroutine test_tangent_differences
end module test_saint_venant_kirchhoff
