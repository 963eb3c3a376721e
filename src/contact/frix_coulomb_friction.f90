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
   use frix_error, only: error_t, append_error
   use frix_strings, only: to_string
   use frix_property_list, only: property_list_t, property_spec_t, spec_names
   use frix_dual_number, only: dual_t, dual_norm, dual_constant, operator(*), operator(/)
   use frix_friction_law, only: friction_law_t, branch_free, branch_stick, branch_slip
   implicit none
   private

   public :: coulomb_friction_t, new_coulomb_friction, coulomb_from_properties, frictionless_from_properties
   public :: coulomb_properties, frictionless_properties, coulomb_by_default, frictionless_by_default

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

   !> COULOMB's property MU (>= 0; a contact pair without MU gets 0).
   function coulomb_properties() result(specs)
      type(property_spec_t), allocatable :: specs(:)
      allocate (specs(1))
      specs(1)%name = 'MU'
      specs(1)%what = 'MU'
      specs(1)%bounded = .true.
      specs(1)%bound_message = 'MU must not be negative'
      specs(1)%has_default = .true.
   end function coulomb_properties

   !> FRICTIONLESS takes no property.
   function frictionless_properties() result(specs)
      type(property_spec_t), allocatable :: specs(:)
      allocate (specs(0))
   end function frictionless_properties

   !> A contact pair without LAW is Coulomb when it gives MU > 0.
   logical function coulomb_by_default(given)
      type(property_list_t), intent(in) :: given   !! the pair's friction properties
      real(dp) :: coefficient
      logical :: found
      type(error_t), allocatable :: error
      call given%take_real('MU', coefficient, found, error, default=0.0_dp)
      coulomb_by_default = coefficient > 0.0_dp
   end function coulomb_by_default

   !> Otherwise it is frictionless.
   logical function frictionless_by_default(given)
      type(property_list_t), intent(in) :: given
      frictionless_by_default = .true.
   end function frictionless_by_default

   !> COULOMB: property MU (required, >= 0; MU = 0 is frictionless).
   subroutine coulomb_from_properties(properties, law, error)
      type(property_list_t), intent(in) :: properties
      class(friction_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: coefficient
      logical :: found
      call properties%check_names(spec_names(coulomb_properties()), error)
      call properties%take_real('MU', coefficient, found, error)
      if (found .and. .not. (coefficient >= 0.0_dp .and. coefficient < huge(1.0_dp))) &
         call append_error(error, trim(properties%owner)//': MU must be >= 0, got '//to_string(coefficient))
      if (.not. allocated(error)) allocate (law, source=new_coulomb_friction(coefficient))
   end subroutine coulomb_from_properties

   !> FRICTIONLESS: no tangential traction (Coulomb with mu = 0); no properties.
   subroutine frictionless_from_properties(properties, law, error)
      type(property_list_t), intent(in) :: properties
      class(friction_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      call properties%check_names(spec_names(frictionless_properties()), error)
      if (.not. allocated(error)) allocate (law, source=new_coulomb_friction(0.0_dp))
   end subroutine frictionless_from_properties

   !> Coulomb return mapping (see the module head) of the branch `branch`.
   pure subroutine return_map(self, trial_traction, pressure, branch, traction, slipping, law_slipping)
      class(coulomb_friction_t), intent(in) :: self
      type(dual_t), intent(in) :: trial_traction(3)
      type(dual_t), intent(in) :: pressure
      integer, intent(in) :: branch
      type(dual_t), intent(out) :: traction(3)
      logical, intent(out) :: slipping, law_slipping
      real(dp) :: trial_magnitude
      if (self%frictionless()) then
         traction = dual_constant(0.0_dp)
         slipping = .true.
         law_slipping = .true.
         return
      end if
      trial_magnitude = norm2(trial_traction%value)
      law_slipping = trial_magnitude > self%coefficient*pressure%value
      select case (branch)
      case (branch_stick)
         slipping = .false.
      case (branch_slip)
         slipping = trial_magnitude > 0.0_dp   ! no direction to slip in at t_trial = 0
      case default
         slipping = law_slipping
      end select
      if (slipping) then
         ! trial_magnitude > 0: the norm is differentiable here.
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
