!> Compressible neo-Hookean hyperelasticity (Simo & Hughes, Computational Inelasticity, 1998,
!> sec. 9.2; Bonet & Wood, Nonlinear Continuum Mechanics for FEA, 2nd ed., sec. 6.4.3):
!>
!>   W(C) = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2,   I1 = tr C,  J = sqrt(det C),
!>   S    = 2 dW/dC = mu (I - C^-1) + lambda ln J C^-1,
!>   C_ijkl = 4 d2W/dC_ij dC_kl = lambda C^-1_ij C^-1_kl + 2 (mu - lambda ln J) I_ijkl(C^-1),
!>   I_ijkl(C^-1) = (C^-1_ik C^-1_jl + C^-1_il C^-1_jk) / 2,
!>
!> with C = I + 2 E the right Cauchy-Green tensor. lambda and mu are the Lame parameters of
!> the small-strain E and nu, so the law reduces to Hooke's at E -> 0.
!>
!> Voigt (frix_material): the input E carries engineering shears, so C_12 = 2 E_12 = gamma_12;
!> S carries tensor shears. Since S is symmetric and C_ijkl has minor symmetries,
!> dS_ij / dgamma_kl = C_ijkl for k /= l as well, so the 6 x 6 tangent is C_ijkl with the
!> Voigt index map (11 22 33 12 13 23) and no factors of 2.
!> Under small strain kinematics the strain eps is used as if it were E (only meaningful in
!> the small-strain limit, where the law is Hooke's).
module frix_neo_hookean
   use frix_kinds, only: dp
   use frix_vector_algebra, only: invert3
   use frix_symmetric_tensor, only: voigt_i, voigt_j, right_cauchy_green
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_material, only: material_t
   use frix_property_list, only: property_list_t
   use frix_linear_elastic, only: lame_parameters, hooke_tangent, elastic_constants
   implicit none
   private

   public :: neo_hookean_t, new_neo_hookean, neo_hookean_from_properties

   !> Row i and column j of the symmetric 3 x 3 tensor behind Voigt index 1..6.

   !> Compressible neo-Hookean material; no history.
   type, extends(material_t) :: neo_hookean_t
      real(dp) :: young = 0.0_dp    !! small-strain Young's modulus E (stress unit)
      real(dp) :: poisson = 0.0_dp  !! small-strain Poisson's ratio nu
      real(dp) :: lambda = 0.0_dp   !! first Lame parameter (stress unit)
      real(dp) :: mu = 0.0_dp       !! shear modulus (stress unit)
   contains
      procedure :: n_state => neo_hookean_n_state
      procedure :: response => neo_hookean_response
      procedure :: elastic_tangent => neo_hookean_elastic_tangent
   end type neo_hookean_t

contains

   !> Neo-Hookean material named by the deck keyword MAT_Struct_NeoHooke.
   pure function new_neo_hookean(young, poisson, density) result(material)
      real(dp), intent(in) :: young    !! small-strain Young's modulus E (stress unit), > 0
      real(dp), intent(in) :: poisson  !! small-strain Poisson's ratio nu, in (-1, 0.5)
      real(dp), intent(in) :: density  !! mass per unit reference volume, >= 0
      type(neo_hookean_t) :: material
      material%name = 'MAT_Struct_NeoHooke'
      material%young = young
      material%poisson = poisson
      material%density = density
      call lame_parameters(young, poisson, material%lambda, material%mu)
   end function new_neo_hookean

   !> The material of deck properties YOUNG, NUE, DENS (frix_linear_elastic's elastic_constants).
   subroutine neo_hookean_from_properties(properties, material, error)
      type(property_list_t), intent(in) :: properties
      class(material_t), allocatable, intent(out) :: material
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: young, poisson, density
      call elastic_constants(properties, young, poisson, density, error)
      if (.not. allocated(error)) allocate (material, source=new_neo_hookean(young, poisson, density))
   end subroutine neo_hookean_from_properties

   pure function neo_hookean_n_state(self) result(n)
      class(neo_hookean_t), intent(in) :: self
      integer :: n
      n = 0
   end function neo_hookean_n_state

   !> Second Piola-Kirchhoff stress and tangent dS/dE for a Green-Lagrange strain E.
   !> Fails if det C <= 0 (inverted or degenerate deformation).
   subroutine neo_hookean_response(self, strain, finite, state_old, state_new, stress, tangent, error)
      class(neo_hookean_t), intent(in) :: self
      real(dp), intent(in) :: strain(6)        !! Green-Lagrange E, Voigt, engineering shears
      logical, intent(in) :: finite            !! unused: the same law under both kinematics
      real(dp), intent(in) :: state_old(:)     !! unused (no history)
      real(dp), intent(inout) :: state_new(:)  !! unused (no history)
      real(dp), intent(out) :: stress(6)       !! S, Voigt, tensor shears
      real(dp), intent(out) :: tangent(6, 6)   !! dS/dE, Voigt
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: c(3, 3), inverse(3, 3), det_c, log_j
      integer :: a, b, i, j, k, l

      stress = 0.0_dp
      tangent = 0.0_dp
      c = right_cauchy_green(strain)
      call invert3(c, inverse, det_c)
      if (.not. (det_c > 0.0_dp)) then
         call fatal_error(error, self%name//': det C = '//to_string(det_c)// &
                          ' <= 0 (inverted or degenerate deformation)')
         return
      end if
      log_j = 0.5_dp*log(det_c)

      do a = 1, 6
         i = voigt_i(a)
         j = voigt_j(a)
         stress(a) = self%mu*(merge(1.0_dp, 0.0_dp, i == j) - inverse(i, j)) &
                     + self%lambda*log_j*inverse(i, j)
         do b = 1, 6
            k = voigt_i(b)
            l = voigt_j(b)
            tangent(a, b) = self%lambda*inverse(i, j)*inverse(k, l) &
                            + (self%mu - self%lambda*log_j) &
                            *(inverse(i, k)*inverse(j, l) + inverse(i, l)*inverse(j, k))
         end do
      end do
   end subroutine neo_hookean_response

   !> Tangent at E = 0: Hooke's matrix of the same E and nu.
   pure subroutine neo_hookean_elastic_tangent(self, tangent)
      class(neo_hookean_t), intent(in) :: self
      real(dp), intent(out) :: tangent(6, 6)
      tangent = hooke_tangent(self%young, self%poisson)
   end subroutine neo_hookean_elastic_tangent

end module frix_neo_hookean
