!> The augmented Lagrangian normal contact law (METHOD Augmented):
!>   p_N = max(0, lambda + eps_N (-g)),
!> lambda the slave node's multiplier (force/area), held fixed during the Newton iterations of
!> a solution and updated after it by Uzawa's rule lambda <- p_N, until the largest penetration
!> is below a tolerance (Simo & Laursen, Comput. Struct. 42 (1992) 97-116; Laursen,
!> *Computational Contact and Impact Mechanics*, Springer 2002, 5.3; Wriggers, *Computational
!> Contact Mechanics*, 2nd ed., Springer 2006, 6.3). At the converged multiplier the
!> penetration is the tolerance's, whatever eps_N: eps_N only sets how many augmentations it
!> takes. The point is in contact iff lambda + eps_N (-g) > 0. Properties: EPSN (as the
!> penalty law's), PENTOL (the penetration tolerance, length, > 0; default 1e-5 of the
!> master's mean face size), MAXAUG (most augmentations per increment, >= 1, default 20),
!> PENGROW, PENRATE, PENCAP (the penalty growth of the method of multipliers: Bertsekas,
!> *Constrained Optimization and Lagrange Multiplier Methods*, Academic Press 1982, 2.2;
!> frix_contact_augmentation's grow_penalties).
module frix_augmented_normal_law
   use frix_kinds, only: dp
   use frix_error, only: error_t, append_error
   use frix_strings, only: to_string
   use frix_property_list, only: property_list_t, property_spec_t, spec_names
   use frix_dual_number, only: dual_t, dual_constant, operator(+), operator(-), operator(*)
   use frix_normal_contact_law, only: normal_contact_law_t, augmentation_t
   use frix_penalty_normal_law, only: penalty_normal_law_t, penalty_from_properties, penalty_properties
   implicit none
   private

   public :: augmented_normal_law_t, augmented_from_properties, augmented_properties

   integer, parameter :: default_max_augmentations = 20
   !> Defaults of the penalty growth (Bertsekas 1982, 2.2: beta in [4, 10], gamma = 0.25):
   !> eps x PENGROW after an augmentation that did not bring the largest |gap| of a pressed
   !> node (stick slip) below PENRATE times the previous one, up to PENCAP times the given
   !> eps (1e4: four decades at most, against the round-off of an ever stiffer system;
   !> docs/contact.md, "Augmented Lagrangian")
   real(dp), parameter :: default_growth_factor = 10.0_dp
   real(dp), parameter :: default_growth_rate = 0.25_dp
   real(dp), parameter :: default_growth_limit = 1.0e4_dp

   type, extends(penalty_normal_law_t) :: augmented_normal_law_t
      real(dp) :: penetration_tolerance = -1.0_dp   !! length; < 0: the default
      integer :: max_augmentations = default_max_augmentations
      real(dp) :: growth_factor = default_growth_factor   !! PENGROW >= 1 (1: no growth)
      real(dp) :: growth_rate = default_growth_rate       !! PENRATE, 0 < . <= 1
      real(dp) :: growth_limit = default_growth_limit     !! PENCAP >= 1
   contains
      procedure :: active
      procedure :: pressure
      procedure :: augmentation
   end type augmented_normal_law_t

contains

   !> AUGMENTED's properties: EPSN (the penalty law's), PENTOL (> 0), MAXAUG (>= 1), PENGROW
   !> (>= 1), PENRATE (0 < . <= 1), PENCAP (>= 1).
   function augmented_properties() result(specs)
      type(property_spec_t), allocatable :: specs(:)
      specs = [penalty_properties(), &
               property_spec_t(name='PENTOL', what='PENTOL', bounded=.true., strict=.true., &
                               bound_message='PENTOL must be positive'), &
               at_least_one('MAXAUG', whole=.true.), at_least_one('PENGROW'), &
               property_spec_t(name='PENRATE', what='PENRATE', bounded=.true., strict=.true., &
                               bounded_above=.true., maximum=1.0_dp, &
                               bound_message='PENRATE must be > 0 and <= 1'), &
               at_least_one('PENCAP')]
   contains
      !> A property whose value must be >= 1 (`whole`: a whole number, default real).
      function at_least_one(name, whole) result(spec)
         character(len=*), intent(in) :: name
         logical, intent(in), optional :: whole
         type(property_spec_t) :: spec
         spec = property_spec_t(name=name, what=name, bounded=.true., minimum=1.0_dp, &
                                bound_message=name//' must be at least 1')
         if (present(whole)) spec%whole = whole
      end function at_least_one
   end function augmented_properties

   !> AUGMENTED from its properties: eps_N as the penalty law reads it, PENTOL, MAXAUG.
   subroutine augmented_from_properties(properties, law, error)
      type(property_list_t), intent(in) :: properties
      class(normal_contact_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      class(normal_contact_law_t), allocatable :: penalty_law
      type(augmented_normal_law_t), allocatable :: augmented
      real(dp) :: tolerance, growth, rate, cap
      integer :: limit
      logical :: found
      call properties%check_names(spec_names(augmented_properties()), error)
      if (allocated(error)) return
      call penalty_from_properties(properties%restricted_to(penalty_properties()), penalty_law, error)
      call properties%take_real('PENTOL', tolerance, found, error, default=-1.0_dp)
      if (found .and. .not. (tolerance > 0.0_dp .and. tolerance < huge(1.0_dp))) &
         call append_error(error, trim(properties%owner)//': PENTOL must be > 0, got '//to_string(tolerance))
      call properties%take_integer('MAXAUG', limit, found, error, default=default_max_augmentations)
      if (limit < 1) call append_error(error, trim(properties%owner)//': MAXAUG must be at least 1, got '// &
                                       to_string(limit))
      call properties%take_real('PENGROW', growth, found, error, default=default_growth_factor)
      if (.not. (growth >= 1.0_dp .and. growth < huge(1.0_dp))) &
         call append_error(error, trim(properties%owner)//': PENGROW must be >= 1, got '//to_string(growth))
      call properties%take_real('PENRATE', rate, found, error, default=default_growth_rate)
      if (.not. (rate > 0.0_dp .and. rate <= 1.0_dp)) &
         call append_error(error, trim(properties%owner)//': PENRATE must be > 0 and <= 1, got '//to_string(rate))
      call properties%take_real('PENCAP', cap, found, error, default=default_growth_limit)
      if (.not. (cap >= 1.0_dp .and. cap < huge(1.0_dp))) &
         call append_error(error, trim(properties%owner)//': PENCAP must be >= 1, got '//to_string(cap))
      if (allocated(error)) return
      allocate (augmented)
      select type (penalty_law)
      type is (penalty_normal_law_t)
         augmented%penalty_normal_law_t = penalty_law
      end select
      augmented%name = 'AUGMENTED'
      augmented%penetration_tolerance = tolerance
      augmented%max_augmentations = limit
      augmented%growth_factor = growth
      augmented%growth_rate = rate
      augmented%growth_limit = cap
      call move_alloc(augmented, law)
   end subroutine augmented_from_properties

   !> In contact iff lambda + eps_N (-g) > 0 (NaN: not in contact).
   pure logical function active(self, gap, multiplier)
      class(augmented_normal_law_t), intent(in) :: self
      real(dp), intent(in) :: gap, multiplier
      active = multiplier + self%eps_n*(-gap) > 0.0_dp
   end function active

   !> p_N = lambda + eps_N (-g) where positive, else 0; dp_N = -eps_N dg in contact.
   pure function pressure(self, gap, multiplier)
      class(augmented_normal_law_t), intent(in) :: self
      type(dual_t), intent(in) :: gap
      real(dp), intent(in) :: multiplier
      type(dual_t) :: pressure
      if (multiplier + self%eps_n*(-gap%value) > 0.0_dp) then
         pressure = dual_constant(multiplier) + self%eps_n*(-gap)
      else
         pressure = dual_constant(0.0_dp)
      end if
   end function pressure

   !> Augmented, with the law's tolerance, limit and penalty growth.
   pure function augmentation(self) result(settings)
      class(augmented_normal_law_t), intent(in) :: self
      type(augmentation_t) :: settings
      settings%augmented = .true.
      settings%penetration_tolerance = self%penetration_tolerance
      settings%max_augmentations = self%max_augmentations
      settings%growth_factor = self%growth_factor
      settings%growth_rate = self%growth_rate
      settings%growth_limit = self%growth_limit
   end function augmentation
end module frix_augmented_normal_law
