!> The penalty normal contact law (METHOD Penalty, the default):
!>   p_N = eps_N max(0, -g),
!> eps_N > 0 a stiffness per unit area (stress per length, e.g. kPa/m), so that the nodal force
!> eps_N (-g) A_s does not depend on the mesh (Wriggers, *Computational Contact Mechanics*,
!> 2nd ed., Springer 2006, ch. 6, the penalty method). The point is in contact iff g < 0; the Lagrange multiplier
!> is not used. Property EPSN = eps_N (> 0 and finite); without it the law is created with
!> `automatic_penalty` set and eps_N = 0, and the deck reader sets eps_N from the stiffness of
!> the elements under the contact surfaces (docs/contact.md, "Choosing the penalties").
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
      !> eps_N (force/area/length), > 0 (0 until an automatic penalty is set); read it through
      !> `penalty()` (the component cannot share the type-bound procedure's name)
      real(dp) :: eps_n = 0.0_dp
   contains
      procedure :: active
      procedure :: pressure
      procedure :: stiffness
      procedure :: penalty => penalty_value
      procedure :: set_penalty => set_penalty_value
   end type penalty_normal_law_t

contains

   !> The penalty law of stiffness eps_N (not checked here: penalty_from_properties validates
   !> deck input).
   pure function new_penalty_normal_law(penalty) result(law)
      real(dp), intent(in) :: penalty   !! eps_N (force/area/length)
      type(penalty_normal_law_t) :: law
      law%name = 'PENALTY'
      law%eps_n = penalty
   end function new_penalty_normal_law

   !> PENALTY's property EPSN (> 0; a pair without it gets an automatic penalty).
   function penalty_properties() result(specs)
      type(property_spec_t), allocatable :: specs(:)
      allocate (specs(1))
      specs(1)%name = 'EPSN'
      specs(1)%what = 'EPSN'
      specs(1)%bounded = .true.
      specs(1)%strict = .true.
      specs(1)%bound_message = 'EPSN must be positive'
   end function penalty_properties

   !> PENALTY: property EPSN (> 0 and finite). Without EPSN the law has eps_N = 0 and
   !> `automatic_penalty` set: the deck reader derives eps_N once the model is complete.
   subroutine penalty_from_properties(properties, law, error)
      type(property_list_t), intent(in) :: properties
      class(normal_contact_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: penalty
      logical :: found
      call properties%check_names(spec_names(penalty_properties()), error)
      call properties%take_real('EPSN', penalty, found, error, default=0.0_dp)
      if (found .and. .not. (penalty > 0.0_dp .and. penalty < huge(1.0_dp))) then
         call append_error(error, trim(properties%owner)//': EPSN must be > 0, got '//to_string(penalty))
      end if
      if (allocated(error)) return
      allocate (law, source=new_penalty_normal_law(penalty))
      law%automatic_penalty = .not. found
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
         pressure = self%eps_n*(-gap)
      else
         pressure = dual_constant(0.0_dp)
      end if
   end function pressure

   !> eps_N.
   pure real(dp) function stiffness(self)
      class(penalty_normal_law_t), intent(in) :: self
      stiffness = self%eps_n
   end function stiffness

   !> eps_N (0 while an automatic penalty is not set yet).
   pure real(dp) function penalty_value(self)
      class(penalty_normal_law_t), intent(in) :: self
      penalty_value = self%eps_n
   end function penalty_value

   !> eps_N = eps (not checked: the caller derives or validates it).
   pure subroutine set_penalty_value(self, eps)
      class(penalty_normal_law_t), intent(inout) :: self
      real(dp), intent(in) :: eps   !! eps_N (force/area/length)
      self%eps_n = eps
   end subroutine set_penalty_value
end module frix_penalty_normal_law
