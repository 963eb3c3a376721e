!> The normal contact law interface: the contact pressure of a slave node from its normal gap.
!>
!> Sign conventions (docs/contact.md): the normal gap g (length) is negative in penetration;
!> the pressure p_N (force per unit area) is compressive positive, p_N >= 0. The law may use a
!> per-node Lagrange multiplier lambda (force per unit area, an estimate of p_N held fixed
!> during the Newton iterations of an increment), which a penalty law ignores and an augmented
!> Lagrangian law uses (p_N = max(0, lambda + eps_N (-g)), lambda updated between
!> augmentations: Simo & Laursen, Comput. Struct. 42 (1992) 97-116; Wriggers, *Computational
!> Contact Mechanics*, 2nd ed., Springer 2006, ch. 6).
!> The gap is a dual number so that the kernel differentiates p_N exactly; lambda is a real
!> (it does not depend on the current coordinates).
!>
!> A law with a penalty eps_N (force/area/length) reports it through `penalty` and takes a
!> new one through `set_penalty`; a law created without its penalty (a deck pair without EPSN)
!> has `automatic_penalty` set, and the deck reader derives eps_N from the stiffness of the
!> elements under the contact surfaces (docs/contact.md, "Choosing the penalties") and sets it
!> before the analysis.
module frix_normal_contact_law
   use frix_kinds, only: dp
   use frix_dual_number, only: dual_t
   implicit none
   private

   public :: normal_contact_law_t, augmentation_t

   !> How a law's multipliers are augmented between Newton solutions (frix_augmentation):
   !> `augmented` false for a law that does not use them (the penalty law).
   type :: augmentation_t
      logical :: augmented = .false.
      !> largest penetration accepted (length); < 0: the default, a fraction of the master's
      !> face size (frix_contact_augmentation)
      real(dp) :: penetration_tolerance = -1.0_dp
      integer :: max_augmentations = 0   !! Newton solutions after the first, at most
      !> penalty growth within an increment (method of multipliers, frix_contact_augmentation):
      !> when an augmentation leaves the largest penetration (stick slip) above `growth_rate`
      !> times the previous one, the penalty of the next solutions is multiplied by
      !> `growth_factor` (1: never), up to `growth_limit` times the given one
      real(dp) :: growth_factor = 1.0_dp
      real(dp) :: growth_rate = 1.0_dp
      real(dp) :: growth_limit = 1.0_dp
   end type augmentation_t

   type, abstract :: normal_contact_law_t
      character(len=:), allocatable :: name   !! deck keyword of the law (METHOD), e.g. PENALTY
      !> .true.: created without its penalty, which the deck reader derives and sets
      !> (`set_penalty`); it stays .true. afterwards, to say where the value came from
      logical :: automatic_penalty = .false.
   contains
      !> Whether the point is in contact, i.e. carries a pressure p_N > 0, at gap g and
      !> multiplier lambda; where it is not, the kernel adds no force and no stiffness.
      procedure(active_interface), deferred :: active
      !> p_N(g, lambda) >= 0 (force/area) with its derivatives through g.
      procedure(pressure_interface), deferred :: pressure
      !> d p_N / d(-g) in contact (force/area/length): the normal stiffness per unit area that
      !> the assembly gives touching nodes (0 <= g <= GAPTOL) in the predictor.
      procedure(stiffness_interface), deferred :: stiffness
      !> Whether and how the multipliers are augmented (default: not).
      procedure :: augmentation
      !> eps_N (force/area/length); 0 for a law without a penalty (the default).
      procedure :: penalty
      !> Set eps_N (force/area/length, > 0); a law without a penalty ignores it (the default).
      procedure :: set_penalty
   end type normal_contact_law_t

   abstract interface
      pure logical function active_interface(self, gap, multiplier)
         import :: normal_contact_law_t, dp
         class(normal_contact_law_t), intent(in) :: self
         real(dp), intent(in) :: gap          !! g (length), < 0: penetration
         real(dp), intent(in) :: multiplier   !! lambda (force/area)
      end function active_interface

      pure function pressure_interface(self, gap, multiplier) result(pressure)
         import :: normal_contact_law_t, dual_t, dp
         class(normal_contact_law_t), intent(in) :: self
         type(dual_t), intent(in) :: gap      !! g (length) and its gradient
         real(dp), intent(in) :: multiplier   !! lambda (force/area)
         type(dual_t) :: pressure             !! p_N >= 0 (force/area), compressive positive
      end function pressure_interface

      pure real(dp) function stiffness_interface(self)
         import :: normal_contact_law_t, dp
         class(normal_contact_law_t), intent(in) :: self
      end function stiffness_interface
   end interface

contains

   !> A law that ignores its multipliers: no augmentation.
   pure function augmentation(self) result(settings)
      class(normal_contact_law_t), intent(in) :: self
      type(augmentation_t) :: settings
      settings = augmentation_t()
   end function augmentation

   !> The default: a law without a penalty, eps_N = 0.
   pure real(dp) function penalty(self)
      class(normal_contact_law_t), intent(in) :: self
      penalty = 0.0_dp
   end function penalty

   !> The default: a law without a penalty ignores `eps`.
   pure subroutine set_penalty(self, eps)
      class(normal_contact_law_t), intent(inout) :: self
      real(dp), intent(in) :: eps   !! eps_N (force/area/length)
   end subroutine set_penalty
end module frix_normal_contact_law
