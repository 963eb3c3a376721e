!> The friction law interface: the return mapping of a trial tangential traction.
!>
!> Elastic-stick penalty regularisation (Wriggers, *Computational Contact Mechanics*, 2nd ed.,
!> Springer 2006, 5.2 and 10.3.2; Laursen, *Computational Contact and Impact Mechanics*,
!> Springer 2002, 5.3): the trial traction t_trial = -eps_T g_T (force per unit area, acting on
!> the slave, tangential to the master) is mapped onto the admissible set of the law; the law
!> sees the current normal pressure p_N >= 0 (force per unit area, compressive positive).
!> Arguments are dual numbers so that the return mapping is differentiated exactly (slip
!> branch included) by the contact kernel.
module frix_friction_law
   use frix_dual_number, only: dual_t
   implicit none
   private

   public :: friction_law_t
   public :: branch_free, branch_stick, branch_slip

   !> Which branch return_map evaluates: the law's own choice, or one imposed by the caller
   !> (the Newton iterations hold a node whose slip reverses in the stick branch, see
   !> docs/contact.md, "Slip reversal"; branch_slip completes the set and is unit-tested).
   integer, parameter :: branch_free = 0
   integer, parameter :: branch_stick = 1
   integer, parameter :: branch_slip = 2

   type, abstract :: friction_law_t
      character(len=:), allocatable :: name   !! deck keyword of the law, e.g. COULOMB
   contains
      !> Tangential traction t and whether the point slips, from t_trial and p_N.
      procedure(return_map_interface), deferred :: return_map
      !> True if the law never transmits a tangential traction (the kernel then keeps no
      !> anchor and adds no tangential stiffness, so the contact tangent stays symmetric).
      procedure(frictionless_interface), deferred :: frictionless
   end type friction_law_t

   abstract interface
      pure subroutine return_map_interface(self, trial_traction, pressure, branch, traction, slipping, &
                                           law_slipping)
         import :: friction_law_t, dual_t
         class(friction_law_t), intent(in) :: self
         type(dual_t), intent(in) :: trial_traction(3)  !! t_trial (force/area), tangential
         type(dual_t), intent(in) :: pressure           !! p_N >= 0 (force/area)
         integer, intent(in) :: branch                  !! branch_free, branch_stick or branch_slip
         type(dual_t), intent(out) :: traction(3)       !! t on the slave (force/area)
         logical, intent(out) :: slipping               !! .true.: slip branch evaluated
         logical, intent(out) :: law_slipping           !! .true.: the law's own choice is slip
      end subroutine return_map_interface

      pure logical function frictionless_interface(self)
         import :: friction_law_t
         class(friction_law_t), intent(in) :: self
      end function frictionless_interface
   end interface
end module frix_friction_law
