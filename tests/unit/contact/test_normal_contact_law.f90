!> The normal contact law registry and the penalty law: METHOD keywords, the EPSN checks, a law
!> created without EPSN (automatic penalty, set later through set_penalty), and
!> p_N = eps_N max(0, -g) with its derivative on a hand example (eps_N = 1e4, gap seeded as
!> the first unknown: g = -0.01 gives p_N = 100 and dp_N/dg = -1e4; g = 0.01 gives zero).
module test_normal_contact_law
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close, check_message_contains
   use frix_property_list, only: property_list_t, new_property_list, spec_names
   use frix_dual_number, only: dual_t, dual_variable
   use frix_normal_contact_law, only: normal_contact_law_t
   use frix_normal_contact_law_registry, only: create_normal_contact_law, normal_property_specs, &
                                               default_normal_method
   implicit none
   private

   public :: collect_normal_contact_law

   real(dp), parameter :: penalty = 1.0e4_dp   !! eps_N (force/area/length)

contains

   subroutine collect_normal_contact_law(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('PENALTY from EPSN, the default METHOD', test_create), &
               new_unittest('without EPSN: an automatic penalty, set later', test_automatic), &
               new_unittest('negative, zero, huge EPSN, unknown METHOD', test_errors), &
               new_unittest('penalty p_N and dp_N/dg, g < 0 and g > 0', test_pressure)]
   end subroutine collect_normal_contact_law

   !> The property list EPSN = `value` (any case of the name).
   function epsn(value) result(list)
      real(dp), intent(in) :: value
      type(property_list_t) :: list
      type(error_t), allocatable :: failure
      call new_property_list('', ['epsn'], [value], list, failure)
   end function epsn

   subroutine test_create(error)
      type(error_t), allocatable, intent(out) :: error
      class(normal_contact_law_t), allocatable :: law
      type(error_t), allocatable :: failure
      call check(error, default_normal_method() == 'PENALTY', 'a pair without METHOD is PENALTY')
      if (allocated(error)) return
      call check(error, any(spec_names(normal_property_specs()) == 'EPSN'), 'the deck reads EPSN for the registry')
      if (allocated(error)) return
      call create_normal_contact_law('Penalty', epsn(penalty), law, failure)
      call check(error, .not. allocated(failure) .and. allocated(law), 'created')
      if (allocated(error)) return
      call check(error, law%name == 'PENALTY', 'named PENALTY')
      if (allocated(error)) return
      call check_close(error, law%stiffness(), penalty, 0.0_dp, message='stiffness = EPSN')
      if (allocated(error)) return
      call check_close(error, law%penalty(), penalty, 0.0_dp, message='penalty() = EPSN')
      if (allocated(error)) return
      call check(error, .not. law%automatic_penalty, 'a given EPSN is not automatic')
   end subroutine test_create

   !> Without EPSN the registry creates the law with automatic_penalty set and eps_N = 0; the
   !> deck reader's set_penalty then gives it its eps_N, which pressure and stiffness use.
   subroutine test_automatic(error)
      type(error_t), allocatable, intent(out) :: error
      class(normal_contact_law_t), allocatable :: law
      type(error_t), allocatable :: failure
      type(property_list_t) :: nothing
      type(dual_t) :: gap(1), pressure
      call create_normal_contact_law('PENALTY', nothing, law, failure)
      call check(error, .not. allocated(failure) .and. allocated(law), 'created without EPSN')
      if (allocated(error)) return
      call check(error, law%automatic_penalty, 'marked as needing an automatic penalty')
      if (allocated(error)) return
      call check(error, law%penalty() == 0.0_dp, 'eps_N = 0 until set')
      if (allocated(error)) return
      call law%set_penalty(2.5e5_dp)
      call check_close(error, law%penalty(), 2.5e5_dp, 0.0_dp, message='penalty() after set_penalty')
      if (allocated(error)) return
      call check_close(error, law%stiffness(), 2.5e5_dp, 0.0_dp, message='stiffness after set_penalty')
      if (allocated(error)) return
      call check(error, law%automatic_penalty, 'still marked automatic after set_penalty')
      if (allocated(error)) return
      gap = dual_variable([-2.0e-3_dp], 1)
      pressure = law%pressure(gap(1), 0.0_dp)
      call check_close(error, pressure%value, 500.0_dp, 1.0e-14_dp, message='p_N = eps_N (-g) = 2.5e5 x 2e-3')
   end subroutine test_automatic

   subroutine test_errors(error)
      type(error_t), allocatable, intent(out) :: error
      class(normal_contact_law_t), allocatable :: law
      type(error_t), allocatable :: failure
      call create_normal_contact_law('PENALTY', epsn(-1.0e6_dp), law, failure)
      call check_message_contains(error, failure, 'PENALTY: EPSN must be > 0')
      if (allocated(error)) return
      call create_normal_contact_law('PENALTY', epsn(0.0_dp), law, failure)
      call check_message_contains(error, failure, 'EPSN must be > 0')
      if (allocated(error)) return
      call create_normal_contact_law('PENALTY', epsn(huge(1.0_dp)), law, failure)
      call check_message_contains(error, failure, 'EPSN must be > 0')
      if (allocated(error)) return
      call create_normal_contact_law('Foo', epsn(penalty), law, failure)
      call check_message_contains(error, failure, 'unknown normal contact method "Foo"; valid methods: PENALTY')
      if (allocated(error)) return
      call check(error, .not. allocated(law), 'no law for an unknown METHOD')
   end subroutine test_errors

   subroutine test_pressure(error)
      type(error_t), allocatable, intent(out) :: error
      class(normal_contact_law_t), allocatable :: law
      type(error_t), allocatable :: failure
      type(dual_t) :: gap(1), pressure
      call create_normal_contact_law('PENALTY', epsn(penalty), law, failure)
      call check(error, allocated(law), 'created')
      if (allocated(error)) return
      ! penetration: p_N = eps_N (-g), dp_N/dg = -eps_N; the multiplier is not used
      gap = dual_variable([-0.01_dp], 1)
      pressure = law%pressure(gap(1), 50.0_dp)
      call check(error, law%active(gap(1)%value, 0.0_dp), 'g < 0 is in contact')
      if (allocated(error)) return
      call check_close(error, pressure%value, 100.0_dp, 1.0e-14_dp, message='p_N = eps_N (-g)')
      if (allocated(error)) return
      call check_close(error, pressure%gradient(1), -penalty, 1.0e-14_dp, message='dp_N/dg = -eps_N')
      if (allocated(error)) return
      call check(error, all(pressure%gradient(2:) == 0.0_dp), 'no other derivative')
      if (allocated(error)) return
      ! open: zero pressure, zero derivative
      gap = dual_variable([0.01_dp], 1)
      pressure = law%pressure(gap(1), 50.0_dp)
      call check(error, .not. law%active(gap(1)%value, 0.0_dp) .and. .not. law%active(0.0_dp, 0.0_dp), &
                 'g >= 0 is open')
      if (allocated(error)) return
      call check(error, pressure%value == 0.0_dp .and. all(pressure%gradient == 0.0_dp), 'p_N = 0, dp_N = 0 for g > 0')
   end subroutine test_pressure
end module test_normal_contact_law
