!> What the frictional (pressure-dependent) plasticity laws of soil share - Mohr-Coulomb
!> (frix_mohr_coulomb) and Drucker-Prager (frix_drucker_prager): isotropic Hooke elasticity with
!> an additive split eps = eps_e + eps_p, a cohesion c(alpha) that hardens or softens linearly
!> in the hardening variable alpha, their deck properties, and their history.
!>
!> Sign convention: tension positive (sigma_1 >= sigma_2 >= sigma_3, p = tr(sigma)/3 > 0 in
!> tension), as everywhere in frix; a soil under its weight has negative stresses.
!>
!> Cohesion (de Souza Neto, Peric & Owen, Computational Methods for Plasticity, Wiley 2008,
!> ch. 8): c(alpha) = max(c0 + H alpha, 0), H = HARD (dc/dalpha, stress unit; < 0 softens to
!> zero cohesion and stays there). alpha grows with the plastic multipliers: on Mohr-Coulomb
!> planes d alpha = 2 cos(phi) sum(d gamma_i), on the Drucker-Prager cone d alpha = xi d gamma;
!> at either apex alpha grows with the volumetric plastic strain in the same proportion.
!>
!> An initial stress sigma0 (frix_plastic_law) enters as the elastic strain D^-1 sigma0 at zero
!> strain; the history's plastic strain is then eps - D^-1 (sigma - sigma0).
!>
!> History per integration point (n_state = 10):
!>   EQPS     sum of sqrt(2/3 d eps_p : d eps_p) over the increments (as for von Mises)
!>   YIELDED  1 when the point yielded in the increment, else 0
!>   REGION   where the return went: 0 elastic, 1 the smooth surface (a Mohr-Coulomb plane, the
!>            Drucker-Prager cone), 2 an edge (two Mohr-Coulomb planes), 3 the apex, 4 a
!>            return involving the tension cut-off of Mohr-Coulomb
!>   EPSP_XX .. EPSP_YZ  the plastic strain (engineering shears)
!>   alpha    the hardening variable (internal: restart data, not shown)
module frix_frictional_plasticity
   use frix_kinds, only: dp
   use frix_error, only: error_t, append_error
   use frix_strings, only: to_string
   use frix_property_list, only: property_list_t
   use frix_material, only: history_name_length
   use frix_plastic_law, only: plastic_law_t
   use frix_linear_elastic, only: elastic_constants, hooke_tangent, lame_parameters, hooke_strain
   implicit none
   private

   public :: frictional_plastic_t, return_outcome_t, read_frictional_properties
   public :: state_eqps, state_yielded, state_region, state_plastic_strain, state_alpha
   public :: region_elastic, region_surface, region_edge, region_apex, region_tension

   integer, parameter :: state_eqps = 1
   integer, parameter :: state_yielded = 2
   integer, parameter :: state_region = 3
   integer, parameter :: state_plastic_strain = 4  !! first of 6 entries of eps_p
   integer, parameter :: state_alpha = 10
   integer, parameter :: n_history = 10

   integer, parameter :: region_elastic = 0, region_surface = 1, region_edge = 2, region_apex = 3
   integer, parameter :: region_tension = 4   !! a return involving the tension cut-off

   real(dp), parameter :: degree = 0.017453292519943295769236907684886_dp  !! pi / 180

   !> What a law's corrector returns for one trial state.
   type :: return_outcome_t
      real(dp) :: stress(6) = 0.0_dp          !! sigma, Voigt, tensor shears
      real(dp) :: tangent(6, 6) = 0.0_dp      !! d sigma / d eps, consistent
      real(dp) :: alpha_increment = 0.0_dp    !! d alpha of the return (0 if elastic)
      integer :: region = region_elastic
   end type return_outcome_t

   type, abstract, extends(plastic_law_t) :: frictional_plastic_t
      real(dp) :: cohesion = 0.0_dp           !! c0 (stress unit)
      real(dp) :: friction_angle = 0.0_dp     !! phi (radians)
      real(dp) :: dilation_angle = 0.0_dp     !! psi (radians), 0 <= psi <= phi
      real(dp) :: hardening_modulus = 0.0_dp  !! H = dc/dalpha
   contains
      !> The return of a trial elastic strain with the cohesion c + slope d alpha.
      procedure(corrector_interface), deferred :: corrector
      procedure :: return_map => frictional_return_map
      procedure :: n_state => frictional_n_state
      procedure :: history_names => frictional_history_names
      procedure :: elastic_tangent => frictional_elastic_tangent
      procedure :: symmetric_tangent => frictional_symmetric_tangent
      procedure :: moduli
   end type frictional_plastic_t

   abstract interface
      !> The stress and consistent tangent of the trial elastic strain: the elastic stress and
      !> Hooke's matrix (region 0) where the trial stress lies inside the surface of cohesion
      !> `cohesion`, else the return onto the surface whose cohesion is cohesion + slope
      !> d alpha. An error when no return exists (a point beyond the apex without dilation).
      subroutine corrector_interface(self, elastic_strain, cohesion, slope, outcome, error)
         import :: frictional_plastic_t, dp, return_outcome_t, error_t
         class(frictional_plastic_t), intent(in) :: self
         real(dp), intent(in) :: elastic_strain(6)  !! eps - eps_p,n, engineering shears
         real(dp), intent(in) :: cohesion           !! c at the start of the increment
         real(dp), intent(in) :: slope              !! dc/dalpha during the increment
         type(return_outcome_t), intent(out) :: outcome
         type(error_t), allocatable, intent(out) :: error
      end subroutine corrector_interface
   end interface

contains

   !> YOUNG, NUE, DENS (elastic_constants), COHESION (>= 0), PHI (degrees, in [0, 90)), PSI
   !> (degrees, in [0, PHI]), HARD (default 0), and the law's `other_names`; cohesion and PHI
   !> not both zero. `law` receives them (its other properties are the caller's).
   subroutine read_frictional_properties(properties, law, error, other_names, other_listed)
      type(property_list_t), intent(in) :: properties
      class(frictional_plastic_t), intent(inout) :: law
      type(error_t), allocatable, intent(inout) :: error
      character(len=*), intent(in) :: other_names(:)   !! upper case
      character(len=*), intent(in) :: other_listed     !! every name, as messages list them
      character(len=:), allocatable :: owner
      real(dp) :: phi, psi
      logical :: has_cohesion, has_phi, has_psi, found
      owner = trim(properties%owner)
      call elastic_constants(properties, law%young, law%poisson, law%density, error, &
                             [character(len=8) :: 'COHESION', 'PHI', 'PSI', 'HARD', other_names], other_listed)
      call properties%take_real('COHESION', law%cohesion, has_cohesion, error)
      call properties%take_real('PHI', phi, has_phi, error)
      call properties%take_real('PSI', psi, has_psi, error)
      call properties%take_real('HARD', law%hardening_modulus, found, error, default=0.0_dp)
      if (has_cohesion .and. .not. (law%cohesion >= 0.0_dp .and. law%cohesion < huge(1.0_dp))) &
         call append_error(error, owner//': COHESION must be >= 0, got '//to_string(law%cohesion))
      if (has_phi .and. .not. (phi >= 0.0_dp .and. phi < 90.0_dp)) &
         call append_error(error, owner//': PHI must lie in [0, 90) degrees, got '//to_string(phi))
      if (has_phi .and. has_psi .and. .not. (psi >= 0.0_dp .and. psi <= phi)) &
         call append_error(error, owner//': PSI must lie in [0, PHI] degrees, got '//to_string(psi))
      if (has_cohesion .and. has_phi .and. law%cohesion == 0.0_dp .and. phi == 0.0_dp) &
         call append_error(error, owner//': COHESION and PHI are both zero (no strength)')
      if (.not. abs(law%hardening_modulus) < huge(1.0_dp)) &
         call append_error(error, owner//': HARD must be finite, got '//to_string(law%hardening_modulus))
      law%friction_angle = phi*degree
      law%dilation_angle = psi*degree
   end subroutine read_frictional_properties

   pure function frictional_n_state(self) result(n)
      class(frictional_plastic_t), intent(in) :: self
      integer :: n
      n = n_history
   end function frictional_n_state

   pure subroutine frictional_history_names(self, names)
      class(frictional_plastic_t), intent(in) :: self
      character(len=history_name_length), allocatable, intent(out) :: names(:)
      names = [character(len=history_name_length) :: 'EQPS', 'YIELDED', 'REGION', 'EPSP_XX', 'EPSP_YY', &
               'EPSP_ZZ', 'EPSP_XY', 'EPSP_XZ', 'EPSP_YZ']
   end subroutine frictional_history_names

   pure subroutine frictional_elastic_tangent(self, tangent)
      class(frictional_plastic_t), intent(in) :: self
      real(dp), intent(out) :: tangent(6, 6)
      tangent = hooke_tangent(self%young, self%poisson)
   end subroutine frictional_elastic_tangent

   !> Associated flow (psi = phi) has a symmetric consistent tangent; non-associated does not.
   pure logical function frictional_symmetric_tangent(self)
      class(frictional_plastic_t), intent(in) :: self
      frictional_symmetric_tangent = self%dilation_angle == self%friction_angle
   end function frictional_symmetric_tangent

   !> Bulk modulus K and shear modulus G.
   pure subroutine moduli(self, bulk, shear)
      class(frictional_plastic_t), intent(in) :: self
      real(dp), intent(out) :: bulk, shear
      real(dp) :: lambda
      call lame_parameters(self%young, self%poisson, lambda, shear)
      bulk = lambda + 2.0_dp*shear/3.0_dp
   end subroutine moduli

   !> The return at `strain` from the history: the corrector with the cohesion's linear branch
   !> at alpha_n; where softening would take c below zero, again with c = 0 (the floor).
   subroutine frictional_return_map(self, strain, state_old, state_new, stress, tangent, error)
      class(frictional_plastic_t), intent(in) :: self
      real(dp), intent(in) :: strain(6)
      real(dp), intent(in) :: state_old(:)
      real(dp), intent(inout) :: state_new(:)
      real(dp), intent(out) :: stress(6), tangent(6, 6)
      type(error_t), allocatable, intent(out) :: error
      type(return_outcome_t) :: outcome
      real(dp) :: elastic(6), alpha, cohesion, slope
      alpha = state_old(state_alpha)
      elastic = strain - state_old(state_plastic_strain:state_plastic_strain + 5)
      cohesion = max(self%cohesion + self%hardening_modulus*alpha, 0.0_dp)
      slope = merge(self%hardening_modulus, 0.0_dp, cohesion > 0.0_dp)
      call self%corrector(elastic, cohesion, slope, outcome, error)
      if (.not. allocated(error) .and. cohesion + slope*outcome%alpha_increment < 0.0_dp) &
         call self%corrector(elastic, 0.0_dp, 0.0_dp, outcome, error)
      if (allocated(error)) then
         stress = 0.0_dp
         tangent = 0.0_dp
         return
      end if
      stress = outcome%stress
      tangent = outcome%tangent
      call commit_history(self, strain, outcome, state_old, state_new)
   end subroutine frictional_return_map

   !> The history after a return: eps_p = eps - D^-1 sigma, EQPS and alpha accumulated (`strain`
   !> includes D^-1 sigma0 of an initial stress, frix_plastic_law).
   subroutine commit_history(self, strain, outcome, state_old, state_new)
      class(frictional_plastic_t), intent(in) :: self
      real(dp), intent(in) :: strain(6)
      type(return_outcome_t), intent(in) :: outcome
      real(dp), intent(in) :: state_old(:)
      real(dp), intent(inout) :: state_new(:)
      real(dp) :: plastic(6), increment(6)
      state_new(1:n_history) = state_old(1:n_history)
      state_new(state_region) = real(outcome%region, dp)
      state_new(state_yielded) = merge(1.0_dp, 0.0_dp, outcome%region /= region_elastic)
      if (outcome%region == region_elastic) return
      plastic = strain - hooke_strain(self%young, self%poisson, outcome%stress)
      increment = plastic - state_old(state_plastic_strain:state_plastic_strain + 5)
      state_new(state_plastic_strain:state_plastic_strain + 5) = plastic
      state_new(state_eqps) = state_old(state_eqps) + &
                              sqrt(2.0_dp/3.0_dp*(sum(increment(1:3)**2) + 0.5_dp*sum(increment(4:6)**2)))
      state_new(state_alpha) = state_old(state_alpha) + outcome%alpha_increment
   end subroutine commit_history
end module frix_frictional_plasticity
