!> The friction law registry and the parameter constructor: keywords, property checks, and
!> the Coulomb return mapping on a hand example (t_trial = (40, 30, 0), |t_trial| = 50,
!> p_N = 100: mu = 0.3 slips to 30 (0.8, 0.6, 0); mu = 0.6 sticks).
module test_friction_law_registry
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close, check_message_contains
   use frix_dual_number, only: dual_t, dual_constant
   use frix_friction_law, only: friction_law_t, branch_free, branch_stick, branch_slip
   use frix_coulomb_friction, only: coulomb_friction_t
   use frix_friction_law_registry, only: create_friction_law
   use frix_contact_parameters, only: contact_parameters_t, new_contact_parameters
   use frix_penalty_normal_law, only: new_penalty_normal_law
   implicit none
   private

   public :: collect_friction_law_registry

contains

   subroutine collect_friction_law_registry(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('COULOMB with MU: return mapping by hand', test_coulomb), &
               new_unittest('FRICTIONLESS: no traction', test_frictionless), &
               new_unittest('bad keywords and properties are reported', test_errors), &
               new_unittest('contact parameters validated', test_parameters)]
   end subroutine collect_friction_law_registry

   subroutine test_coulomb(error)
      type(error_t), allocatable, intent(out) :: error
      class(friction_law_t), allocatable :: law
      type(error_t), allocatable :: failure
      type(dual_t) :: traction(3)
      logical :: slipping, law_slipping
      call create_friction_law('coulomb', ['mu'], [0.3_dp], law, failure)
      call check(error, .not. allocated(failure) .and. allocated(law), 'created')
      if (allocated(error)) return
      call check(error, .not. law%frictionless() .and. law%name == 'COULOMB', 'a frictional law named COULOMB')
      if (allocated(error)) return
      call law%return_map(dual_constant([40.0_dp, 30.0_dp, 0.0_dp]), dual_constant(100.0_dp), branch_free, traction, &
                          slipping, law_slipping)
      call check(error, slipping .and. maxval(abs(traction%value - [24.0_dp, 18.0_dp, 0.0_dp])) <= 1.0e-13_dp, &
                 'slip to mu p_N along t_trial')
      if (allocated(error)) return
      call create_friction_law('COULOMB', ['MU'], [0.6_dp], law, failure)
      call law%return_map(dual_constant([40.0_dp, 30.0_dp, 0.0_dp]), dual_constant(100.0_dp), branch_free, traction, &
                          slipping, law_slipping)
      call check(error, .not. slipping .and. all(traction%value == [40.0_dp, 30.0_dp, 0.0_dp]), 'stick')
      if (allocated(error)) return
      ! imposed branches (mu = 0.6, p_N = 100, |t_trial| = 50): the law chooses stick
      call law%return_map(dual_constant([40.0_dp, 30.0_dp, 0.0_dp]), dual_constant(100.0_dp), branch_slip, traction, &
                          slipping, law_slipping)
      call check(error, slipping .and. .not. law_slipping .and. &
                 maxval(abs(traction%value - [48.0_dp, 36.0_dp, 0.0_dp])) <= 1.0e-13_dp, &
                 'imposed slip: t = mu p_N t_trial/|t_trial| = (48, 36, 0), the law says stick')
      if (allocated(error)) return
      call law%return_map(dual_constant([80.0_dp, 60.0_dp, 0.0_dp]), dual_constant(100.0_dp), branch_stick, traction, &
                          slipping, law_slipping)
      call check(error, .not. slipping .and. law_slipping .and. all(traction%value == [80.0_dp, 60.0_dp, 0.0_dp]), &
                 'imposed stick outside the cone (|t_trial| = 100 > 60): t = t_trial, the law says slip')
      if (allocated(error)) return
      select type (law)
      type is (coulomb_friction_t)
         call check_close(error, law%coefficient, 0.6_dp, 0.0_dp, message='mu stored')
      class default
         call check(error, .false., 'a coulomb_friction_t')
      end select
   end subroutine test_coulomb

   subroutine test_frictionless(error)
      type(error_t), allocatable, intent(out) :: error
      class(friction_law_t), allocatable :: law
      type(error_t), allocatable :: failure
      type(dual_t) :: traction(3)
      logical :: slipping, law_slipping
      character(len=2) :: no_names(0)
      real(dp) :: no_values(0)
      call create_friction_law('Frictionless', no_names, no_values, law, failure)
      call check(error, .not. allocated(failure) .and. law%frictionless(), 'frictionless')
      if (allocated(error)) return
      call law%return_map(dual_constant([0.0_dp, 0.0_dp, 0.0_dp]), dual_constant(100.0_dp), branch_free, traction, &
                          slipping, law_slipping)
      call check(error, all(traction%value == 0.0_dp), 'zero traction even for a zero trial')
      if (allocated(error)) return
      call create_friction_law('COULOMB', ['MU'], [0.0_dp], law, failure)
      call check(error, law%frictionless(), 'COULOMB with MU 0 is frictionless')
   end subroutine test_frictionless

   subroutine test_errors(error)
      type(error_t), allocatable, intent(out) :: error
      class(friction_law_t), allocatable :: law
      type(error_t), allocatable :: failure
      call create_friction_law('TRESCA', ['MU'], [0.3_dp], law, failure)
      call check_message_contains(error, failure, 'unknown friction law "TRESCA"')
      if (allocated(error)) return
      call create_friction_law('COULOMB', ['MUE'], [0.3_dp], law, failure)
      call check_message_contains(error, failure, 'unknown property "MUE"')
      if (allocated(error)) return
      call check_message_contains(error, failure, 'missing property MU')
      if (allocated(error)) return
      call create_friction_law('COULOMB', ['MU'], [-0.1_dp], law, failure)
      call check_message_contains(error, failure, 'MU must be >= 0')
      if (allocated(error)) return
      call check(error, .not. allocated(law), 'no law on error')
      if (allocated(error)) return
      call create_friction_law('COULOMB', ['MU', 'MU'], [0.1_dp, 0.2_dp], law, failure)
      call check_message_contains(error, failure, 'property MU given twice')
      if (allocated(error)) return
      call create_friction_law('FRICTIONLESS', ['MU'], [0.1_dp], law, failure)
      call check_message_contains(error, failure, 'takes no property')
   end subroutine test_errors

   subroutine test_parameters(error)
      type(error_t), allocatable, intent(out) :: error
      class(friction_law_t), allocatable :: law
      type(error_t), allocatable :: failure
      type(contact_parameters_t) :: parameters
      character(len=2) :: no_names(0)
      real(dp) :: no_values(0)
      call create_friction_law('COULOMB', ['MU'], [0.5_dp], law, failure)
      call new_contact_parameters(new_penalty_normal_law(1.0e8_dp), 1.0e6_dp, 1.0e-4_dp, law, parameters, failure)
      call check(error, .not. allocated(failure) .and. parameters%normal%stiffness() == 1.0e8_dp .and. &
                 allocated(parameters%friction), 'valid parameters')
      if (allocated(error)) return
      ! EPSN is the penalty law's, validated by the normal law registry (test_normal_contact_law)
      call new_contact_parameters(new_penalty_normal_law(1.0e8_dp), 0.0_dp, -1.0_dp, law, parameters, failure)
      call check_message_contains(error, failure, 'EPST must be > 0')
      if (allocated(error)) return
      call check_message_contains(error, failure, 'gap tolerance must be >= 0')
      if (allocated(error)) return
      ! without EPST (automatic: the deck reader sets eps_T = eps_N later) eps_T = 0 is accepted
      call new_contact_parameters(new_penalty_normal_law(1.0e8_dp), 0.0_dp, 0.0_dp, law, parameters, failure, &
                                  automatic_tangential=.true.)
      call check(error, .not. allocated(failure) .and. parameters%automatic_tangential_penalty, &
                 'friction without EPST: automatic eps_T')
      if (allocated(error)) return
      call create_friction_law('FRICTIONLESS', no_names, no_values, law, failure)
      call new_contact_parameters(new_penalty_normal_law(1.0e8_dp), 0.0_dp, 0.0_dp, law, parameters, failure, &
                                  automatic_tangential=.true.)
      call check(error, .not. allocated(failure) .and. .not. parameters%automatic_tangential_penalty, &
                 'frictionless needs no EPST, automatic or not')
   end subroutine test_parameters
end module test_friction_law_registry
