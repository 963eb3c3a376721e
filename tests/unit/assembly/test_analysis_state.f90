!> The starting point of an increment under EXTRAPOLATION Linear (frix_analysis_state,
!> extrapolate_displacements): the last converged increment's rate carried on within its step
!> (a full and a cut-back increment), never across a step's end, nothing before the first
!> increment; the rate kept by commit_state.
module test_analysis_state
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close
   use frix_analysis_state, only: analysis_state_t, commit_state, extrapolate_displacements
   use frix_model, only: model_t
   implicit none
   private

   public :: collect_analysis_state

   !> displacements of two nodes at t = 1 and t = 1.25 (step 2 spans (1, 2])
   real(dp), parameter :: u_at_1(6) = [0.1_dp, -0.2_dp, 0.3_dp, 0.0_dp, 1.0_dp, -4.0_dp]
   real(dp), parameter :: u_at_125(6) = [0.15_dp, -0.1_dp, 0.3_dp, 2.0_dp, 1.5_dp, -4.5_dp]

   !> A model without contact pairs: commit_state reads it only for mortar contact passes.
   type(model_t) :: no_contact

contains

   subroutine collect_analysis_state(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('extrapolation within a step: full and half increment', test_within_step), &
               new_unittest('no extrapolation across the end of a step', test_across_steps), &
               new_unittest('no extrapolation before the first increment', test_first_increment)]
   end subroutine collect_analysis_state

   !> A state committed at t = 1 and then at t = 1.25 (the increment 1 -> 1.25 gives the rate).
   subroutine two_increments(state)
      type(analysis_state_t), intent(out) :: state
      allocate (state%alpha(0, 1), state%history(0, 0, 1), state%rate(6), source=0.0_dp)
      state%committed_u = [real(dp) :: 0, 0, 0, 0, 0, 0]
      state%committed_alpha = state%alpha
      state%committed_history = state%history
      state%time = 1.0_dp
      state%u = u_at_1
      call commit_state(state, no_contact)
      state%time = 1.25_dp
      state%u = u_at_125
      call commit_state(state, no_contact)
   end subroutine two_increments

   subroutine test_within_step(error)
      type(error_t), allocatable, intent(out) :: error
      type(analysis_state_t) :: state
      integer :: i
      call two_increments(state)
      call check_close(error, state%rate_start, 1.0_dp, 0.0_dp, message='the rate''s increment began at t = 1')
      if (allocated(error)) return
      call extrapolate_displacements(state, 1.5_dp)   ! the same size again: u = 2 u(1.25) - u(1)
      do i = 1, 6
         call check_close(error, state%u(i), 2*u_at_125(i) - u_at_1(i), 1.0e-14_dp, 1.0e-15_dp, &
                          'full increment, component '//achar(iachar('0') + i))
         if (allocated(error)) return
      end do
      call extrapolate_displacements(state, 1.375_dp)   ! half the size (a cut-back)
      do i = 1, 6
         call check_close(error, state%u(i), u_at_125(i) + 0.5_dp*(u_at_125(i) - u_at_1(i)), 1.0e-14_dp, &
                          1.0e-15_dp, 'half increment, component '//achar(iachar('0') + i))
         if (allocated(error)) return
      end do
   end subroutine test_within_step

   subroutine test_across_steps(error)
      type(error_t), allocatable, intent(out) :: error
      type(analysis_state_t) :: state
      call two_increments(state)
      ! step 2 ends with the increment 1.25 -> 2
      state%time = 2.0_dp
      state%u = 3*u_at_125
      call commit_state(state, no_contact)
      state%u = 0.0_dp
      call extrapolate_displacements(state, 2.25_dp)   ! step 3: the last increment was in step 2
      call check(error, all(state%u == 0.0_dp), 'the first increment of a step was extrapolated')
   end subroutine test_across_steps

   subroutine test_first_increment(error)
      type(error_t), allocatable, intent(out) :: error
      type(analysis_state_t) :: state
      allocate (state%rate(6), state%u(6), state%committed_u(6), source=0.0_dp)
      state%rate = 1.0_dp   ! whatever it holds: rate_start < 0 says there is no increment yet
      call extrapolate_displacements(state, 0.5_dp)
      call check(error, all(state%u == 0.0_dp), 'the first increment of the run was extrapolated')
   end subroutine test_first_increment
end module test_analysis_state
