!> The augmented Lagrangian normal law (METHOD Augmented): p_N = max(0, lambda + eps_N (-g))
!> on hand values (eps_N = 1e4: lambda = 50 and g = -0.01 give 150, dp_N/dg = -1e4; lambda = 50
!> and g = 0.004 give 10, still in contact; g = 0.006 opens), the registry's AUGMENTED with its
!> PENTOL and MAXAUG, the penalty law's augmentation settings (none), and the errors.
module test_augmented_normal_law
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close, check_message_contains
   use frix_property_list, only: property_list_t, new_property_list
   use frix_dual_number, only: dual_t, dual_variable
   use frix_normal_contact_law, only: normal_contact_law_t, augmentation_t
   use frix_normal_contact_law_registry, only: create_normal_contact_law
   implicit none
   private

   public :: collect_augmented_normal_law

   real(dp), parameter :: penalty = 1.0e4_dp   !! eps_N (force/area/length)

contains

   subroutine collect_augmented_normal_law(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('AUGMENTED from EPSN, PENTOL, MAXAUG; PENALTY not augmented', test_create), &
               new_unittest('p_N = max(0, lambda + eps_N (-g)) and dp_N/dg', test_pressure), &
               new_unittest('PENTOL <= 0, MAXAUG < 1, unknown property', test_errors)]
   end subroutine collect_augmented_normal_law

   function properties(names, values) result(list)
      character(len=*), intent(in) :: names(:)
      real(dp), intent(in) :: values(:)
      type(property_list_t) :: list
      type(error_t), allocatable :: failure
      call new_property_list('', names, values, list, failure)
   end function properties

   subroutine test_create(error)
      type(error_t), allocatable, intent(out) :: error
      class(normal_contact_law_t), allocatable :: law
      type(error_t), allocatable :: failure
      type(augmentation_t) :: settings
      call create_normal_contact_law('Augmented', properties([character(len=6) :: 'epsn', 'pentol', 'maxaug'], &
                                     [penalty, 1.0e-6_dp, 7.0_dp]), law, failure)
      call check(error, .not. allocated(failure) .and. allocated(law), 'created')
      if (allocated(error)) return
      settings = law%augmentation()
      call check(error, settings%augmented .and. settings%max_augmentations == 7, 'augmented, MAXAUG 7')
      if (allocated(error)) return
      call check_close(error, settings%penetration_tolerance, 1.0e-6_dp, 0.0_dp, message='PENTOL')
      if (allocated(error)) return
      call check_close(error, law%stiffness(), penalty, 0.0_dp, message='stiffness = EPSN')
      if (allocated(error)) return
      call create_normal_contact_law('AUGMENTED', properties(['EPSN'], [penalty]), law, failure)
      settings = law%augmentation()
      call check(error, settings%penetration_tolerance < 0.0_dp .and. settings%max_augmentations == 20, &
                 'defaults: PENTOL from the face size, MAXAUG 20')
      if (allocated(error)) return
      call create_normal_contact_law('PENALTY', properties(['EPSN'], [penalty]), law, failure)
      settings = law%augmentation()
      call check(error, .not. settings%augmented, 'the penalty law is not augmented')
   end subroutine test_create

   subroutine test_pressure(error)
      type(error_t), allocatable, intent(out) :: error
      class(normal_contact_law_t), allocatable :: law
      type(error_t), allocatable :: failure
      type(dual_t) :: gap(1), pressure
      call create_normal_contact_law('AUGMENTED', properties(['EPSN'], [penalty]), law, failure)
      gap = dual_variable([-0.01_dp], 1)
      pressure = law%pressure(gap(1), 50.0_dp)
      call check_close(error, pressure%value, 150.0_dp, 1.0e-14_dp, message='p_N at g = -0.01, lambda = 50')
      if (allocated(error)) return
      call check_close(error, pressure%gradient(1), -penalty, 1.0e-14_dp, message='dp_N/dg = -eps_N')
      if (allocated(error)) return
      gap = dual_variable([0.004_dp], 1)
      call check(error, law%active(0.004_dp, 50.0_dp), 'in contact with a gap while lambda > eps_N g')
      if (allocated(error)) return
      pressure = law%pressure(gap(1), 50.0_dp)
      call check_close(error, pressure%value, 10.0_dp, 1.0e-12_dp, message='p_N at g = 0.004, lambda = 50')
      if (allocated(error)) return
      call check(error, .not. law%active(0.006_dp, 50.0_dp), 'open once eps_N g > lambda')
      if (allocated(error)) return
      gap = dual_variable([0.006_dp], 1)
      pressure = law%pressure(gap(1), 50.0_dp)
      call check(error, pressure%value == 0.0_dp .and. all(pressure%gradient == 0.0_dp), 'no pressure when open')
   end subroutine test_pressure

   subroutine test_errors(error)
      type(error_t), allocatable, intent(out) :: error
      class(normal_contact_law_t), allocatable :: law
      type(error_t), allocatable :: failure
      call create_normal_contact_law('AUGMENTED', properties(['EPSN  ', 'PENTOL'], [penalty, -1.0_dp]), law, failure)
      call check_message_contains(error, failure, 'PENTOL must be > 0')
      if (allocated(error)) return
      call create_normal_contact_law('AUGMENTED', properties(['EPSN  ', 'MAXAUG'], [penalty, 0.0_dp]), law, failure)
      call check_message_contains(error, failure, 'MAXAUG must be at least 1')
      if (allocated(error)) return
      call create_normal_contact_law('PENALTY', properties(['EPSN  ', 'PENTOL'], [penalty, 1.0_dp]), law, failure)
      call check(error, allocated(failure), 'PENALTY takes no PENTOL')
      if (allocated(error)) return
      call check(error, .not. allocated(law), 'no law after an error')
   end subroutine test_errors
end module test_augmented_normal_law
