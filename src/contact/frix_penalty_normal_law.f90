!> The penalty normal contact law (METHOD Penalty, the default):
!>   p_N = eps_N max(0, -g),
!> eps_N > 0 a stiffness per unit area (stress per length, e.g. kPa/m), so that the nodal force
!> eps_N (-g) A_s does not depend on the mesh (Wriggers, *Computational Contact Mechanics*,
!> 2nd ed., Springer 2006, ch. 6, the penalty method). The point is in contact iff g < 0; the Lagrange multiplier
!> is not used. Property EPSN = eps_N (required, > 0 and finite).
module frix_penalty_normal_law
   use frix_kinds, only: dp
   use frix_error, only: error_t, append_error
   use frix_strings, only: to_string
   use frix_property_list, only: property_list_t, property_spec_t, spec_names
   use frix_dual_number, only: dual_t, dual_constant, operator(-), operator(*)
   use frix_normal_contact_law, only: normal_contact_law_t
   implicit none
   private

   public :: penalty_normal_law_t, new_penalty_normal_law, penalty_from_properties, penalty_properties

   type, extends(normal_contact_law_t) :: penalty_normal_law_t
      real(dp) :: penalty = 0.0_dp   !! eps_N (force/area/length), > 0
   contains
      procedure :: active
      procedure :: pressure
      procedure :: stiffness
   end type penalty_normal_law_t

contains

   !> The penalty law of stiffness eps_N (not checked here: penalty_from_properties validates
   !> deck input).
   pure function new_penalty_normal_law(penalty) result(law)
      real(dp), intent(in) :: penalty   !! eps_N (force/area/length)
      type(penalty_normal_law_t) :: law
      law%name = 'PENALTY'
      law%penalty = penalty
   end function new_penalty_normal_law

   !> PENALTY's property EPSN (> 0, no default: a contact pair must give it).
   function penalty_properties() result(specs)
      type(property_spec_t), allocatable :: specs(:)
      allocate (specs(1))
      specs(1)%name = 'EPSN'
      specs(1)%what = 'EPSN'
      specs(1)%bounded = .true.
      specs(1)%strict = .true.
      specs(1)%bound_message = 'EPSN must be positive'
   end function penalty_properties

   !> PENALTY: property EPSN (required, > 0 and finite). A missing EPSN is reported as the
   !> deck's contact pair that lacks it.
   subroutine penalty_from_properties(properties, law, error)
      type(property_list_t), intent(in) :: properties
      class(normal_contact_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: penalty
      logical :: found
      call properties%check_names(spec_names(penalty_properties()), error)
      call properties%take_real('EPSN', penalty, found, error, default=0.0_dp)
      if (.not. found) then
         call append_error(error, 'contact pair without EPSN (normal penalty)')
      else if (.not. (penalty > 0.0_dp .and. penalty < huge(1.0_dp))) then
         call append_error(error, trim(properties%owner)//': EPSN must be > 0, got '//to_string(penalty))
      end if
      if (.not. allocated(error)) allocate (law, source=new_penalty_normal_law(penalty))
   end subroutine penalty_from_properties

   !> In contact iff g < 0 (NaN: not in contact).
   pure logical function active(self, gap, multiplier)
      class(penalty_normal_law_t), intent(in) :: self
      real(dp), intent(in) :: gap, multiplier
      active = gap < 0.0_dp
   end function active

   !> p_N = eps_N (-g) for g < 0, else 0; dp_N = -eps_N dg in contact.
   pure function pressure(self, gap, multiplier)
      class(penalty_normal_law_t), intent(in) :: self
      type(dual_t), intent(in) :: gap
      real(dp), intent(in) :: multiplier
      type(dual_t) :: pressure
      if (gap%value < 0.0_dp) then
         pressure = self%penalty*(-gap)
      else
         pressure = dual_constant(0.0_dp)
      end if
   end function pressure

   !> eps_N.
   pure real(dp) function stiffness(self)
      class(penalty_normal_law_t), intent(in) :: self
      stiffness = self%penalty
   end function stiffness
end module frix_penalty_normal_law
