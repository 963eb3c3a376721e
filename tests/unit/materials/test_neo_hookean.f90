!> Compressible neo-Hookean law, S = mu (I - C^-1) + lambda ln J C^-1 (Simo & Hughes 1998;
!> Bonet & Wood sec. 6.4.3), checked against closed forms worked out by hand for deformations
!> whose C^-1 is known explicitly:
!>   pure dilatation  C = l^2 I:            J = l^3, S = (mu (1 - l^-2) + lambda ln J l^-2) I
!>   confined stretch C = diag(l^2, 1, 1):   J = l,   S_xx = mu (1 - l^-2) + lambda ln l l^-2,
!>                                                    S_yy = S_zz = lambda ln l
!>   simple shear     F = I + g e_x (x) e_y: C = [1 g 0; g 1+g^2 0; 0 0 1], J = 1,
!>                    C^-1 = [1+g^2 -g 0; -g 1 0; 0 0 1], S = mu (I - C^-1):
!>                    S_xx = -mu g^2, S_xy = mu g, others 0; E = (0, g^2/2, 0, g, 0, 0) in Voigt.
module test_neo_hookean
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close, check_message_contains
   use frix_neo_hookean, only: neo_hookean_t, new_neo_hookean
   use frix_linear_elastic, only: linear_elastic_t, new_linear_elastic
   use test_material_checks, only: check_matrix_close, check_tangent_by_differences, material_response
   implicit none
   private

   public :: collect_neo_hookean

   real(dp), parameter :: young = 1000.0_dp, poisson = 0.3_dp
   !> Lame parameters of (young, poisson), written out: lambda = E nu/((1+nu)(1-2nu)), mu = E/(2(1+nu)).
   real(dp), parameter :: lambda = young*poisson/((1.0_dp + poisson)*(1.0_dp - 2.0_dp*poisson))
   real(dp), parameter :: mu = young/(2.0_dp*(1.0_dp + poisson))

contains

   subroutine collect_neo_hookean(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('constructor sets name and Lame parameters', test_constructor), &
               new_unittest('zero strain gives zero stress and Hooke tangent', test_zero_strain), &
               new_unittest('small-strain limit equals Hooke', test_small_strain_limit), &
               new_unittest('pure dilatation, stretch 1.3 and 0.7', test_dilatation), &
               new_unittest('confined uniaxial stretch 1.4 and 0.6', test_confined_stretch), &
               new_unittest('simple shear g = 0.5 (engineering shear input)', test_simple_shear), &
               new_unittest('tangent symmetric at finite strain', test_tangent_symmetric), &
               new_unittest('tangent vs finite differences, tension', test_tangent_tension), &
               new_unittest('tangent vs finite differences, compression', test_tangent_compression), &
               new_unittest('det C <= 0 is an error', test_inverted)]
   end subroutine collect_neo_hookean

   subroutine test_constructor(error)
      type(error_t), allocatable, intent(out) :: error
      type(neo_hookean_t) :: material
      material = new_neo_hookean(young, poisson, 3.0_dp)
      call check(error, material%name == 'MAT_Struct_NeoHooke', 'name')
      if (allocated(error)) return
      call check(error, material%n_state() == 0, 'no history')
      if (allocated(error)) return
      call check_close(error, material%density, 3.0_dp, 0.0_dp, message='density')
      if (allocated(error)) return
      call check_close(error, material%lambda, lambda, 1.0e-15_dp, message='lambda')
      if (allocated(error)) return
      call check_close(error, material%mu, mu, 1.0e-15_dp, message='mu')
   end subroutine test_constructor

   subroutine test_zero_strain(error)
      type(error_t), allocatable, intent(out) :: error
      type(neo_hookean_t) :: material
      real(dp) :: stress(6), tangent(6, 6), hooke(6, 6), elastic(6, 6)
      integer :: i
      material = new_neo_hookean(young, poisson, 0.0_dp)
      call material_response(error, material, [real(dp) :: 0, 0, 0, 0, 0, 0], stress, tangent)
      if (allocated(error)) return
      do i = 1, 6
         call check_close(error, stress(i), 0.0_dp, 0.0_dp, 1.0e-13_dp*young, 'stress at E = 0')
         if (allocated(error)) return
      end do
      hooke = hooke_matrix()
      call check_matrix_close(error, tangent, hooke, 1.0e-14_dp, 'tangent at E = 0 vs Hooke')
      if (allocated(error)) return
      call material%elastic_tangent(elastic)
      call check_matrix_close(error, elastic, hooke, 1.0e-14_dp, 'elastic_tangent vs Hooke')
   end subroutine test_zero_strain

   !> At |E| ~ 1e-7 the tangent differs from Hooke's by O(|E|) relative, and the stress from
   !> D E by O(|E|^2) absolute, i.e. O(|E|) relative.
   subroutine test_small_strain_limit(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: direction(6) = [0.3_dp, -0.5_dp, 1.0_dp, 0.7_dp, -0.2_dp, 0.4_dp]
      real(dp) :: strain(6), stress(6), tangent(6, 6), hooke(6, 6), hooke_stress(6)
      integer :: i
      strain = 1.0e-7_dp*direction
      call material_response(error, new_neo_hookean(young, poisson, 0.0_dp), strain, stress, tangent)
      if (allocated(error)) return
      hooke = hooke_matrix()
      call check_matrix_close(error, tangent, hooke, 1.0e-6_dp, 'tangent vs Hooke')
      if (allocated(error)) return
      hooke_stress = matmul(hooke, strain)
      do i = 1, 6
         call check_close(error, stress(i), hooke_stress(i), 1.0e-6_dp, 1.0e-6_dp*maxval(abs(hooke_stress)), &
                          'stress vs Hooke')
         if (allocated(error)) return
      end do
   end subroutine test_small_strain_limit

   subroutine test_dilatation(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: stretches(2), stretch, green, expected, stress(6), tangent(6, 6)
      integer :: k, i
      stretches = [1.3_dp, 0.7_dp]
      do k = 1, 2
         stretch = stretches(k)
         green = 0.5_dp*(stretch**2 - 1.0_dp)
         expected = mu*(1.0_dp - stretch**(-2)) + lambda*log(stretch**3)*stretch**(-2)
         call material_response(error, new_neo_hookean(young, poisson, 0.0_dp), &
                                [green, green, green, 0.0_dp, 0.0_dp, 0.0_dp], stress, tangent)
         if (allocated(error)) return
         do i = 1, 3
            call check_close(error, stress(i), expected, 1.0e-13_dp, message='S_ii')
            if (allocated(error)) return
            call check_close(error, stress(i + 3), 0.0_dp, 0.0_dp, 1.0e-13_dp*abs(expected), 'S_ij')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_dilatation

   subroutine test_confined_stretch(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: stretches(2), stretch, stress(6), tangent(6, 6), axial, lateral
      integer :: k, i
      stretches = [1.4_dp, 0.6_dp]
      do k = 1, 2
         stretch = stretches(k)
         axial = mu*(1.0_dp - stretch**(-2)) + lambda*log(stretch)*stretch**(-2)
         lateral = lambda*log(stretch)
         call material_response(error, new_neo_hookean(young, poisson, 0.0_dp), &
                                [0.5_dp*(stretch**2 - 1.0_dp), 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], &
                                stress, tangent)
         if (allocated(error)) return
         call check_close(error, stress(1), axial, 1.0e-13_dp, message='S_xx')
         if (allocated(error)) return
         call check_close(error, stress(2), lateral, 1.0e-13_dp, message='S_yy')
         if (allocated(error)) return
         call check_close(error, stress(3), lateral, 1.0e-13_dp, message='S_zz')
         if (allocated(error)) return
         do i = 4, 6
            call check_close(error, stress(i), 0.0_dp, 0.0_dp, 1.0e-13_dp*abs(axial), 'S_ij')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_confined_stretch

   subroutine test_simple_shear(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: g = 0.5_dp
      real(dp) :: stress(6), tangent(6, 6), expected(6)
      integer :: i
      expected = [-mu*g**2, 0.0_dp, 0.0_dp, mu*g, 0.0_dp, 0.0_dp]
      call material_response(error, new_neo_hookean(young, poisson, 0.0_dp), &
                             [0.0_dp, 0.5_dp*g**2, 0.0_dp, g, 0.0_dp, 0.0_dp], stress, tangent)
      if (allocated(error)) return
      do i = 1, 6
         call check_close(error, stress(i), expected(i), 1.0e-12_dp, 1.0e-12_dp*mu, 'S component')
         if (allocated(error)) return
      end do
   end subroutine test_simple_shear

   !> A hyperelastic tangent is the Hessian of W: major symmetry.
   subroutine test_tangent_symmetric(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: stress(6), tangent(6, 6)
      call material_response(error, new_neo_hookean(young, poisson, 0.0_dp), &
                             [0.2_dp, -0.1_dp, 0.3_dp, 0.25_dp, -0.15_dp, 0.1_dp], stress, tangent)
      if (allocated(error)) return
      call check_matrix_close(error, tangent, transpose(tangent), 1.0e-14_dp, 'symmetry')
   end subroutine test_tangent_symmetric

   subroutine test_tangent_tension(error)
      type(error_t), allocatable, intent(out) :: error
      call check_tangent_by_differences(error, new_neo_hookean(young, poisson, 0.0_dp), &
                                        [0.2_dp, -0.1_dp, 0.3_dp, 0.25_dp, -0.15_dp, 0.1_dp], 1.0e-6_dp, 'dS/dE')
   end subroutine test_tangent_tension

   subroutine test_tangent_compression(error)
      type(error_t), allocatable, intent(out) :: error
      call check_tangent_by_differences(error, new_neo_hookean(young, 0.45_dp, 0.0_dp), &
                                        [-0.3_dp, 0.1_dp, -0.2_dp, 0.2_dp, 0.1_dp, -0.1_dp], 1.0e-6_dp, 'dS/dE')
   end subroutine test_tangent_compression

   !> E_xx = -0.6 gives C_xx = -0.2, det C = -0.2.
   subroutine test_inverted(error)
      type(error_t), allocatable, intent(out) :: error
      type(neo_hookean_t) :: material
      type(error_t), allocatable :: law_error
      real(dp) :: state_old(0), state_new(0), stress(6), tangent(6, 6)
      material = new_neo_hookean(young, poisson, 0.0_dp)
      call material%response([-0.6_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], .true., state_old, state_new, stress, &
                             tangent, law_error)
      call check_message_contains(error, law_error, 'det C')
      if (allocated(error)) return
      call check_message_contains(error, law_error, 'MAT_Struct_NeoHooke')
   end subroutine test_inverted

   !> Hooke's matrix of the same E and nu (itself checked against analytic states in
   !> test_linear_elastic).
   function hooke_matrix() result(tangent)
      real(dp) :: tangent(6, 6)
      type(linear_elastic_t) :: hooke_material
      hooke_material = new_linear_elastic(young, poisson, 0.0_dp)
      call hooke_material%elastic_tangent(tangent)
   end function hooke_matrix
end module test_neo_hookean
