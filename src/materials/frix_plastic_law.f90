!> A plasticity law written at small strain: its return mapping takes a strain and the history
!> at the start of the increment and gives the stress and the algorithmic moduli. `response`
!> applies it under both kinematics of frix_material:
!>   small strain (Geo_Lin): at eps, giving sigma and d sigma / d eps;
!>   finite strain (Tot_Lagr): at the Lagrangian logarithmic strain E_log = 1/2 ln C, giving the
!>   stress T conjugate to E_log, mapped to S = P^T T with the tangent P^T (dT/dE_log) P +
!>   T : d2E_log/dE dE (Miehe, Apel & Lambrecht, CMAME 191, 2002; frix_logarithmic_strain).
!> For isotropic elasticity this is the Hencky law with an additive split of E_log; the plastic
!> strain in the history is then the plastic part of E_log.
!> An initial stress sigma0 (initial_stress_response) is an initial elastic strain D^-1 sigma0
!> (D the isotropic Hooke matrix of YOUNG, NUE): the return maps eps + D^-1 sigma0 (or E_log +
!> D^-1 sigma0), so that the stress at zero strain is sigma0 and the yield condition sees
!> sigma0 + D eps_e from the start.
module frix_plastic_law
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_material, only: material_t
   use frix_logarithmic_strain, only: log_strain_t, logarithmic_strain, log_strain_stress, log_strain_tangent
   use frix_linear_elastic, only: hooke_strain
   implicit none
   private

   public :: plastic_law_t

   type, abstract, extends(material_t) :: plastic_law_t
      real(dp) :: young = 0.0_dp     !! E
      real(dp) :: poisson = 0.0_dp   !! nu
   contains
      !> Stress and algorithmic moduli at a small strain (eps, or E_log) from the history.
      procedure(return_map_interface), deferred :: return_map
      procedure :: response => plastic_law_response
      procedure :: initial_stress_response => plastic_law_initial_stress_response
   end type plastic_law_t

   abstract interface
      subroutine return_map_interface(self, strain, state_old, state_new, stress, tangent, error)
         import :: plastic_law_t, dp, error_t
         class(plastic_law_t), intent(in) :: self
         real(dp), intent(in) :: strain(6)        !! eps or E_log, Voigt, engineering shears
         real(dp), intent(in) :: state_old(:)     !! history at the start of the increment
         real(dp), intent(inout) :: state_new(:)  !! history at this strain (written)
         real(dp), intent(out) :: stress(6)       !! sigma or T, Voigt, tensor shears
         real(dp), intent(out) :: tangent(6, 6)   !! d stress / d strain, consistent
         type(error_t), allocatable, intent(out) :: error
      end subroutine return_map_interface
   end interface

contains

   !> Small strain: the return mapping at eps. Finite strain: at E_log of E, mapped back to S.
   subroutine plastic_law_response(self, strain, finite, state_old, state_new, stress, tangent, error)
      class(plastic_law_t), intent(in) :: self
      real(dp), intent(in) :: strain(6)        !! eps or E, Voigt, engineering shears
      logical, intent(in) :: finite            !! strain is E, stress is S
      real(dp), intent(in) :: state_old(:)
      real(dp), intent(inout) :: state_new(:)
      real(dp), intent(out) :: stress(6)       !! sigma or S, tensor shears
      real(dp), intent(out) :: tangent(6, 6)   !! consistent d stress / d strain
      type(error_t), allocatable, intent(out) :: error
      call shifted_response(self, strain, finite, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], state_old, state_new, &
                            stress, tangent, error)
   end subroutine plastic_law_response

   !> As plastic_law_response from the initial stress sigma0 (module header).
   subroutine plastic_law_initial_stress_response(self, strain, finite, initial_stress, state_old, state_new, stress, &
                                                  tangent, error)
      class(plastic_law_t), intent(in) :: self
      real(dp), intent(in) :: strain(6)
      logical, intent(in) :: finite
      real(dp), intent(in) :: initial_stress(6)   !! sigma0, Voigt, tensor shears
      real(dp), intent(in) :: state_old(:)
      real(dp), intent(inout) :: state_new(:)
      real(dp), intent(out) :: stress(6), tangent(6, 6)
      type(error_t), allocatable, intent(out) :: error
      call shifted_response(self, strain, finite, hooke_strain(self%young, self%poisson, initial_stress), state_old, &
                            state_new, stress, tangent, error)
   end subroutine plastic_law_initial_stress_response

   !> The return mapping at eps + shift (small strain) or E_log(E) + shift (finite strain).
   subroutine shifted_response(self, strain, finite, shift, state_old, state_new, stress, tangent, error)
      class(plastic_law_t), intent(in) :: self
      real(dp), intent(in) :: strain(6), shift(6)
      logical, intent(in) :: finite
      real(dp), intent(in) :: state_old(:)
      real(dp), intent(inout) :: state_new(:)
      real(dp), intent(out) :: stress(6), tangent(6, 6)
      type(error_t), allocatable, intent(out) :: error
      type(log_strain_t) :: log_strain
      real(dp) :: log_stress(6), moduli(6, 6)
      logical :: valid
      if (.not. finite) then
         call self%return_map(strain + shift, state_old, state_new, stress, tangent, error)
         return
      end if
      call logarithmic_strain(strain, log_strain, valid)
      if (.not. valid) then
         stress = 0.0_dp
         tangent = 0.0_dp
         call fatal_error(error, self%name//': the right Cauchy-Green tensor is not positive definite')
         return
      end if
      call self%return_map(log_strain%strain + shift, state_old, state_new, log_stress, moduli, error)
      if (allocated(error)) return
      stress = log_strain_stress(log_strain, log_stress)
      tangent = log_strain_tangent(log_strain, log_stress, moduli)
   end subroutine shifted_response
end module frix_plastic_law
