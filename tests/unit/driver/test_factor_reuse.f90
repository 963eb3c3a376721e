!> frix_factor_reuse: the factors of a tangent serve a further correction only while the
!> contact state they were assembled with holds (docs/contact.md, "Augmented Lagrangian"):
!> every slave node with its status and master face, the sparse pattern, and not discarded
!> (a new increment, a grown penalty).
module test_factor_reuse
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check
   use frix_analysis_state, only: analysis_state_t
   use frix_contact_kernel, only: contact_open, contact_stick, contact_slip
   use frix_factor_reuse, only: factor_reuse_t
   implicit none
   private

   public :: collect_factor_reuse

   integer, parameter :: pattern = 7   !! the sparse pattern of the recorded factorization

contains

   subroutine collect_factor_reuse(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('unchanged_state_reuses', test_unchanged), &
               new_unittest('status_change_refactorizes', test_status_change), &
               new_unittest('face_change_refactorizes', test_face_change), &
               new_unittest('pattern_or_discard_refactorizes', test_pattern_and_discard), &
               new_unittest('without_contact_reuses', test_without_contact)]
   end subroutine collect_factor_reuse

   !> Two passes: three slave nodes (stick on face 4, slip on face 5, open) and two (stick on
   !> face 1, open).
   subroutine two_pass_state(state)
      type(analysis_state_t), intent(out) :: state
      state%has_contact = .true.
      allocate (state%contact%passes(2))
      allocate (state%contact%passes(1)%result(3), state%contact%passes(2)%result(2))
      state%contact%passes(1)%result%status = [contact_stick, contact_slip, contact_open]
      state%contact%passes(1)%face = [4, 5, 0]
      state%contact%passes(2)%result%status = [contact_stick, contact_open]
      state%contact%passes(2)%face = [1, 0]
   end subroutine two_pass_state

   subroutine test_unchanged(error)
      type(error_t), allocatable, intent(out) :: error
      type(analysis_state_t) :: state
      type(factor_reuse_t) :: reuse
      call two_pass_state(state)
      call check(error, .not. reuse%matches(state, pattern), 'nothing recorded: no reuse')
      if (allocated(error)) return
      call reuse%record(state, pattern)
      call check(error, reuse%matches(state, pattern), 'the recorded state: reuse')
   end subroutine test_unchanged

   subroutine test_status_change(error)
      type(error_t), allocatable, intent(out) :: error
      type(analysis_state_t) :: state
      type(factor_reuse_t) :: reuse
      call two_pass_state(state)
      call reuse%record(state, pattern)
      state%contact%passes(2)%result(2)%status = contact_stick   ! a node of the second pass closes
      call check(error, .not. reuse%matches(state, pattern), 'a node closed: no reuse')
      if (allocated(error)) return
      state%contact%passes(2)%result(2)%status = contact_open
      state%contact%passes(1)%result(1)%status = contact_slip    ! stick to slip
      call check(error, .not. reuse%matches(state, pattern), 'a node slips: no reuse')
   end subroutine test_status_change

   subroutine test_face_change(error)
      type(error_t), allocatable, intent(out) :: error
      type(analysis_state_t) :: state
      type(factor_reuse_t) :: reuse
      call two_pass_state(state)
      call reuse%record(state, pattern)
      state%contact%passes(1)%face(2) = 6   ! the slipping node slid onto the next face
      call check(error, .not. reuse%matches(state, pattern), 'a node on another face: no reuse')
   end subroutine test_face_change

   subroutine test_pattern_and_discard(error)
      type(error_t), allocatable, intent(out) :: error
      type(analysis_state_t) :: state
      type(factor_reuse_t) :: reuse
      call two_pass_state(state)
      call reuse%record(state, pattern)
      call check(error, .not. reuse%matches(state, pattern + 1), 'a rebuilt pattern: no reuse')
      if (allocated(error)) return
      call reuse%discard()
      call check(error, .not. reuse%matches(state, pattern), 'discarded: no reuse')
   end subroutine test_pattern_and_discard

   subroutine test_without_contact(error)
      type(error_t), allocatable, intent(out) :: error
      type(analysis_state_t) :: state
      type(factor_reuse_t) :: reuse
      call reuse%record(state, pattern)
      call check(error, reuse%matches(state, pattern), 'no contact, same pattern: reuse')
   end subroutine test_without_contact
end module test_factor_reuse
