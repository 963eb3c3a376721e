!> The solution state of an analysis, with one interface for the driver: the displacements,
!> the per-element internal variables (EAS parameters), the material history and the contact
!> state (the passes' search results and friction branches, and their committed anchors and
!> slip), both at the last converged increment ("committed") and at the current iterate.
!> `commit_state` accepts the iterate, `restore_state` returns to the committed state after a
!> failed increment (the contact system's committed part needs no restoring: the iterations
!> never change it); a restart (frix_state_restart) reads the displacements, EAS parameters
!> and history, commits them with `commit_solution`, and sets the contact history itself.
!>
!> The displacement reference of RESET_DISPLACEMENT (docs/deck-format.md, STEPS) is kept here
!> too: `take_displacement_reference` copies the committed displacements at the start of such a
!> step, and `reported_displacement` is the one place computing what every output reports,
!> u_reported = u_total - u_reference. The mechanics never see the reference.
module frix_analysis_state
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_model, only: model_t
   use frix_contact_assembly, only: contact_system_t, setup_contact, commit_contact
   use frix_contact_augmentation, only: restore_multipliers
   use frix_process_group, only: gather_owned_elements
   implicit none
   private

   public :: analysis_state_t, create_analysis_state, commit_state, commit_solution, restore_state
   public :: take_displacement_reference, reported_displacement, extrapolate_displacements

   type :: analysis_state_t
      real(dp) :: time = 0.0_dp               !! pseudo time (load factor) of `u`
      real(dp) :: committed_time = 0.0_dp
      real(dp), allocatable :: u(:)           !! (3*n_nodes) current total displacements, node-major
      real(dp), allocatable :: committed_u(:)
      !> (3*n_nodes) du/dt of the last converged increment, which began at `rate_start`
      !> [length per unit pseudo time]; zero before the first increment
      real(dp), allocatable :: rate(:)
      real(dp) :: rate_start = -1.0_dp
      !> (3*n_nodes) total displacements from which the reported ones are measured
      !> (RESET_DISPLACEMENT); unallocated: none taken, the total displacements are reported
      real(dp), allocatable :: reference_u(:)
      real(dp), allocatable :: alpha(:, :)    !! (max EAS parameters, n_elements) current iterate
      real(dp), allocatable :: committed_alpha(:, :)
      real(dp), allocatable :: history(:, :, :)           !! (max n_state, n_points, n_elements) current
      real(dp), allocatable :: committed_history(:, :, :) !! at the last converged increment
      logical :: has_contact = .false.
      !> contact search, slip history, contact assembly; its committed part (anchors, slip;
      !> room for Lagrange multipliers) changes only in commit_state
      type(contact_system_t) :: contact
   end type analysis_state_t

contains

   !> Zero state sized for `model`, with its contact passes set up (docs/contact.md).
   subroutine create_analysis_state(model, state, error)
      type(model_t), intent(in) :: model
      type(analysis_state_t), intent(out) :: state
      type(error_t), allocatable, intent(out) :: error
      integer :: b, max_enhanced, max_state, max_points, n_equations
      max_enhanced = 0
      max_state = 0
      max_points = 0
      do b = 1, size(model%blocks)
         associate (element => model%blocks(b)%element%formulation, &
                    material => model%materials(model%blocks(b)%material)%law)
            max_enhanced = max(max_enhanced, element%n_enhanced())
            max_points = max(max_points, element%n_points())
            max_state = max(max_state, material%n_state())
         end associate
      end do
      n_equations = 3*model%mesh%n_nodes
      allocate (state%u(n_equations), source=0.0_dp)
      allocate (state%alpha(max_enhanced, model%mesh%n_elements), source=0.0_dp)
      allocate (state%history(max_state, max_points, model%mesh%n_elements), source=0.0_dp)
      state%committed_u = state%u
      allocate (state%rate(n_equations), source=0.0_dp)
      state%committed_alpha = state%alpha
      state%committed_history = state%history
      if (allocated(model%contact_pairs)) state%has_contact = size(model%contact_pairs) > 0
      if (state%has_contact) call setup_contact(model, state%contact, error)
   end subroutine create_analysis_state

   !> Accept the current iterate as converged (the model: for the mortar contact rows at the
   !> converged displacements).
   subroutine commit_state(state, model)
      type(analysis_state_t), intent(inout) :: state
      type(model_t), intent(in) :: model
      real(dp) :: dt
      dt = state%time - state%committed_time
      if (dt > 0.0_dp) then
         state%rate = (state%u - state%committed_u)/dt
         state%rate_start = state%committed_time
      end if
      call commit_solution(state)
      if (state%has_contact) call commit_contact(state%contact, dt, model, state%u)
   end subroutine commit_state

   !> Accept the current time, displacements, EAS parameters and material history (not the
   !> contact state, whose committed part commit_contact takes from a converged iterate). In a
   !> parallel run each process's elements' EAS parameters and history are gathered first
   !> (the assembly updates its own only): every process then commits the whole state.
   subroutine commit_solution(state)
      type(analysis_state_t), intent(inout) :: state
      call gather_owned_elements(state%alpha)
      call gather_owned_elements(state%history)
      state%committed_time = state%time
      state%committed_u = state%u
      state%committed_alpha = state%alpha
      state%committed_history = state%history
   end subroutine commit_solution

   !> The start of the increment to pseudo time `time` by linear extrapolation (Abaqus's
   !> EXTRAPOLATION=LINEAR): u = u_committed + (time - t_committed) du/dt of the last converged
   !> increment, when that increment lies in the same step (step s spans (s - 1, s]); else the
   !> committed displacements. Prescribed components are set afterwards by the Newton solver.
   subroutine extrapolate_displacements(state, time)
      type(analysis_state_t), intent(inout) :: state
      real(dp), intent(in) :: time
      real(dp), parameter :: slack = 1.0e-12_dp
      if (state%rate_start < real(ceiling(time - slack), dp) - 1.0_dp - slack) return
      state%u = state%committed_u + (time - state%committed_time)*state%rate
   end subroutine extrapolate_displacements

   !> Go back to the last converged increment (after a failed increment). The contact
   !> system's committed part is untouched by the iterations (each search and assembly starts
   !> from it); only the multipliers that augmentations changed go back.
   subroutine restore_state(state)
      type(analysis_state_t), intent(inout) :: state
      state%time = state%committed_time
      state%u = state%committed_u
      state%alpha = state%committed_alpha
      state%history = state%committed_history
      if (state%has_contact) call restore_multipliers(state%contact)
   end subroutine restore_state

   !> RESET_DISPLACEMENT at the start of a step: the committed (converged) displacements become
   !> the reference of the reported ones, replacing any earlier reference.
   subroutine take_displacement_reference(state)
      type(analysis_state_t), intent(inout) :: state
      state%reference_u = state%committed_u
   end subroutine take_displacement_reference

   !> The committed displacements as reported by every output (3, n_nodes): the total ones
   !> less the reference of the last RESET_DISPLACEMENT step, if any.
   pure function reported_displacement(state) result(u)
      type(analysis_state_t), intent(in) :: state
      real(dp), allocatable :: u(:, :)
      if (allocated(state%reference_u)) then
         u = reshape(state%committed_u - state%reference_u, [3, size(state%committed_u)/3])
      else
         u = reshape(state%committed_u, [3, size(state%committed_u)/3])
      end if
   end function reported_displacement
end module frix_analysis_state
