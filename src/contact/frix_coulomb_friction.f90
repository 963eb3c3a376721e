!> Coulomb friction with a constant coefficient mu (mu = 0: frictionless).
!>
!> Return mapping (Wriggers, *Computational Contact Mechanics*, 2nd ed., 2006, eq. 10.53;
!> Simo & Laursen, Comput. Struct. 42 (1992) 97-116):
!>   phi = |t_trial| - mu p_N;  phi <= 0: stick, t = t_trial;
!>   phi > 0: slip, t = mu p_N t_trial / |t_trial|.
!> Differentiated by the caller's dual numbers, the slip branch gives
!>   dt = mu (t_trial/|t_trial|) dp_N + mu p_N/|t_trial| (I - e e) dt_trial,  e = t_trial/|t_trial|,
!> whose dp_N term makes the contact tangent unsymmetric.
module frix_coulomb_friction
   use frix_kinds, only: dp
   use frix_dual_number, only: dual_t, dual_norm, dual_constant, operator(*), operator(/)
   use frix_friction_law, only: friction_law_t
   implicit none
   private

   public :: coulomb_friction_t, new_coulomb_friction

   type, extends(friction_law_t) :: coulomb_friction_t
      real(dp) :: coefficient = 0.0_dp   !! mu (dimensionless, >= 0)
   contains
      procedure :: return_map
      procedure :: frictionless
   end type coulomb_friction_t

contains

   !> Coulomb law of coefficient mu >= 0 (not checked here: the registry validates deck input).
   pure function new_coulomb_friction(coefficient) result(law)
      real(dp), intent(in) :: coefficient
      type(coulomb_friction_t) :: law
      law%coefficient = coefficient
      if (coefficient > 0.0_dp) then
         law%name = 'COULOMB'
      else
         law%name = 'FRICTIONLESS'
      end if
   end function new_coulomb_friction

   pure subroutine return_map(self, trial_traction, pressure, traction, slipping)
      class(coulomb_friction_t), intent(in) :: self
      type(dual_t), intent(in) :: trial_traction(3)
      type(dual_t), intent(in) :: pressure
      type(dual_t), intent(out) :: traction(3)
      logical, intent(out) :: slipping
      real(dp) :: trial_magnitude
      if (self%frictionless()) then
         traction = dual_constant(0.0_dp)
         slipping = .true.
         return
      end if
      trial_magnitude = norm2(trial_traction%value)
      slipping = trial_magnitude > self%coefficient*pressure%value
      if (slipping) then
         ! trial_magnitude > mu p_N >= 0: the norm is differentiable here.
         traction = (self%coefficient*pressure)*(trial_traction/dual_norm(trial_traction))
      else
         traction = trial_traction
      end if
   end subroutine return_map

   pure logical function frictionless(self)
      class(coulomb_friction_t), intent(in) :: self
      frictionless = .not. (self%coefficient > 0.0_dp)
   end function frictionless
end module frix_coulomb_friction
