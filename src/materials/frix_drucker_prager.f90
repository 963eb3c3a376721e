!> Drucker-Prager plasticity matched to Mohr-Coulomb, associated or non-associated flow, linear
!> cohesion hardening or softening; deck keyword MAT_3DDruckerPrager, properties YOUNG NUE
!> COHESION PHI PSI [MATCH] [HARD] [DENS] (frix_frictional_plasticity: elasticity, cohesion,
!> history; docs/materials.md).
!>
!> Tension positive, p = tr(sigma)/3, s = dev(sigma), J2 = s : s / 2. Yield function and flow
!> potential (de Souza Neto, Peric & Owen, Computational Methods for Plasticity, Wiley 2008,
!> ch. 8):
!>   f = sqrt(J2) + eta p - xi c(alpha),   g = sqrt(J2) + eta_bar p,   d alpha = xi d gamma,
!> with eta, xi of phi and eta_bar of psi by the matching MATCH:
!>   1 outer cone (meets Mohr-Coulomb on the triaxial compression meridian, default):
!>     eta = 6 sin(phi) / (sqrt(3) (3 - sin(phi))),  xi = 6 cos(phi) / (sqrt(3) (3 - sin(phi)))
!>   2 inner cone (meets it on the triaxial extension meridian): 3 + sin(phi) in both
!>   3 plane strain (the same plane-strain limit load for associated flow):
!>     eta = 3 tan(phi) / sqrt(9 + 12 tan^2(phi)),  xi = 3 / sqrt(9 + 12 tan^2(phi))
!> Return to the cone with linear hardening, closed form:
!>   d gamma = f(sigma*) / (G + K eta eta_bar + xi^2 H),
!>   s = (1 - G d gamma / sqrt(J2*)) s*,   p = p* - K eta_bar d gamma,
!> valid while sqrt(J2*) >= G d gamma; else the apex sigma = p 1 with p = xi c(alpha) / eta,
!>   p = p* - K d eps_v,  d alpha = xi / eta_bar d eps_v.
!> Consistent tangent (the derivative of these; e* the trial deviatoric strain, n = e*/|e*|,
!> A = 1 / (G + K eta eta_bar + xi^2 H)), cone:
!>   C = 2G (1 - d gamma / (sqrt(2) |e*|)) I_dev + 2G (d gamma / (sqrt(2) |e*|) - G A) n x n
!>       - sqrt(2) G K A (eta n x 1 + eta_bar 1 x n) + K (1 - K eta eta_bar A) 1 x 1,
!> apex: C = K H~ / (K + H~) 1 x 1, H~ = xi^2 H / (eta eta_bar). Unsymmetric when psi /= phi.
module frix_drucker_prager
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error, append_error
   use frix_strings, only: to_string
   use frix_property_list, only: property_list_t
   use frix_material, only: material_t
   use frix_linear_elastic, only: hooke_tangent
   use frix_frictional_plasticity, only: frictional_plastic_t, return_outcome_t, read_frictional_properties, &
                                         region_surface, region_apex
   implicit none
   private

   public :: drucker_prager_t, drucker_prager_from_properties, cone_parameters
   public :: match_outer, match_inner, match_plane_strain

   integer, parameter :: match_outer = 1, match_inner = 2, match_plane_strain = 3

   !> Trial excess over the surface, relative to the stress scale, below which a point is elastic.
   real(dp), parameter :: yield_tolerance = 1.0e-12_dp
   real(dp), parameter :: root_two = 1.4142135623730950488016887242097_dp

   type, extends(frictional_plastic_t) :: drucker_prager_t
      integer :: match = match_outer
      real(dp) :: eta = 0.0_dp       !! pressure coefficient of f (of phi)
      real(dp) :: xi = 0.0_dp        !! cohesion coefficient of f (of phi)
      real(dp) :: eta_bar = 0.0_dp   !! pressure coefficient of g (of psi)
   contains
      procedure :: corrector => drucker_prager_corrector
   end type drucker_prager_t

contains

   !> The law of deck properties YOUNG NUE DENS COHESION PHI PSI HARD MATCH (1, 2 or 3).
   subroutine drucker_prager_from_properties(properties, material, error)
      type(property_list_t), intent(in) :: properties
      class(material_t), allocatable, intent(out) :: material
      type(error_t), allocatable, intent(out) :: error
      type(drucker_prager_t) :: law
      real(dp) :: unused
      logical :: found
      law%name = 'MAT_3DDruckerPrager'
      call read_frictional_properties(properties, law, error, [character(len=8) :: 'MATCH'], &
                                      'YOUNG, NUE, DENS, COHESION, PHI, PSI, HARD, MATCH')
      call properties%take_integer('MATCH', law%match, found, error, default=match_outer)
      if (found .and. .not. any(law%match == [match_outer, match_inner, match_plane_strain])) &
         call append_error(error, trim(properties%owner)//': MATCH must be 1 (outer cone), 2 (inner cone) or '// &
                           '3 (plane strain), got '//to_string(law%match))
      if (allocated(error)) return
      call cone_parameters(law%match, law%friction_angle, law%eta, law%xi)
      call cone_parameters(law%match, law%dilation_angle, law%eta_bar, unused)
      allocate (material, source=law)
   end subroutine drucker_prager_from_properties

   !> eta and xi of the matching `match` for the angle `angle` (radians; module header).
   pure subroutine cone_parameters(match, angle, eta, xi)
      integer, intent(in) :: match
      real(dp), intent(in) :: angle
      real(dp), intent(out) :: eta, xi
      real(dp) :: denominator
      select case (match)
      case (match_inner)
         denominator = sqrt(3.0_dp)*(3.0_dp + sin(angle))
         eta = 6.0_dp*sin(angle)/denominator
         xi = 6.0_dp*cos(angle)/denominator
      case (match_plane_strain)
         denominator = sqrt(9.0_dp + 12.0_dp*tan(angle)**2)
         eta = 3.0_dp*tan(angle)/denominator
         xi = 3.0_dp/denominator
      case default
         denominator = sqrt(3.0_dp)*(3.0_dp - sin(angle))
         eta = 6.0_dp*sin(angle)/denominator
         xi = 6.0_dp*cos(angle)/denominator
      end select
   end subroutine cone_parameters

   subroutine drucker_prager_corrector(self, elastic_strain, cohesion, slope, outcome, error)
      class(drucker_prager_t), intent(in) :: self
      real(dp), intent(in) :: elastic_strain(6)
      real(dp), intent(in) :: cohesion, slope
      type(return_outcome_t), intent(out) :: outcome
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: bulk, shear, deviator(6), norm, root_j2, pressure, excess, multiplier
      call self%moduli(bulk, shear)
      pressure = bulk*sum(elastic_strain(1:3))
      deviator(1:3) = elastic_strain(1:3) - sum(elastic_strain(1:3))/3.0_dp
      deviator(4:6) = 0.5_dp*elastic_strain(4:6)
      norm = sqrt(sum(deviator(1:3)**2) + 2.0_dp*sum(deviator(4:6)**2))
      root_j2 = root_two*shear*norm
      excess = root_j2 + self%eta*pressure - self%xi*cohesion
      if (excess <= yield_tolerance*(self%xi*cohesion + root_j2 + abs(pressure))) then
         outcome%tangent = hooke_tangent(self%young, self%poisson)
         outcome%stress = matmul(outcome%tangent, elastic_strain)
         return
      end if
      multiplier = excess/(shear + bulk*self%eta*self%eta_bar + self%xi**2*slope)
      if (multiplier > 0.0_dp .and. root_j2 - shear*multiplier >= 0.0_dp) then
         call cone_return(self, bulk, shear, deviator/norm, [norm, pressure, multiplier, slope], outcome)
      else
         call apex_return(self, bulk, pressure, cohesion, slope, outcome, error)
      end if
   end subroutine drucker_prager_corrector

   !> The return to the cone and its tangent (module header); `values` = |e*|, p*, d gamma, H.
   pure subroutine cone_return(self, bulk, shear, normal, values, outcome)
      class(drucker_prager_t), intent(in) :: self
      real(dp), intent(in) :: bulk, shear
      real(dp), intent(in) :: normal(6)   !! n = e*/|e*|, tensor shears
      real(dp), intent(in) :: values(4)
      type(return_outcome_t), intent(out) :: outcome
      real(dp) :: ratio, a, unit(6)
      integer :: i
      associate (norm => values(1), pressure => values(2), multiplier => values(3), slope => values(4))
         a = 1.0_dp/(shear + bulk*self%eta*self%eta_bar + self%xi**2*slope)
         ratio = multiplier/(root_two*norm)
         unit = [1.0_dp, 1.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]
         outcome%stress = 2.0_dp*shear*norm*(1.0_dp - ratio)*normal + (pressure - bulk*self%eta_bar*multiplier)*unit
         outcome%tangent = 0.0_dp
         outcome%tangent(1:3, 1:3) = -2.0_dp*shear*(1.0_dp - ratio)/3.0_dp
         do i = 1, 3
            outcome%tangent(i, i) = outcome%tangent(i, i) + 2.0_dp*shear*(1.0_dp - ratio)
            outcome%tangent(i + 3, i + 3) = shear*(1.0_dp - ratio)
         end do
         do i = 1, 6
            outcome%tangent(:, i) = outcome%tangent(:, i) + 2.0_dp*shear*(ratio - shear*a)*normal*normal(i) &
                                    - root_two*shear*bulk*a*(self%eta*normal*unit(i) + self%eta_bar*unit*normal(i)) &
                                    + bulk*(1.0_dp - bulk*self%eta*self%eta_bar*a)*unit*unit(i)
         end do
         outcome%alpha_increment = self%xi*multiplier
         outcome%region = region_surface
      end associate
   end subroutine cone_return

   !> sigma = p 1 with p = xi c(alpha) / eta (module header); needs phi > 0 and psi > 0.
   subroutine apex_return(self, bulk, pressure, cohesion, slope, outcome, error)
      class(drucker_prager_t), intent(in) :: self
      real(dp), intent(in) :: bulk, pressure, cohesion, slope
      type(return_outcome_t), intent(out) :: outcome
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: modulus, volumetric
      if (.not. (self%eta > 0.0_dp .and. self%eta_bar > 0.0_dp)) then
         call fatal_error(error, self%name//': a stress beyond the apex of the cone needs PSI > 0 (trial p = '// &
                          to_string(pressure)//')')
         return
      end if
      modulus = self%xi**2*slope/(self%eta*self%eta_bar)
      volumetric = (pressure - self%xi*cohesion/self%eta)/(bulk + modulus)
      if (.not. (volumetric >= 0.0_dp .and. bulk + modulus > 0.0_dp)) then
         call fatal_error(error, self%name//': no return onto the yield surface (trial p = '//to_string(pressure)//')')
         return
      end if
      outcome%stress = [1.0_dp, 1.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]*(pressure - bulk*volumetric)
      outcome%tangent = 0.0_dp
      outcome%tangent(1:3, 1:3) = bulk*modulus/(bulk + modulus)
      outcome%alpha_increment = self%xi*volumetric/self%eta_bar
      outcome%region = region_apex
   end subroutine apex_return
end module frix_drucker_prager
