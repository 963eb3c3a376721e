!> Augmented Lagrangian contact in the increment loop (docs/contact.md, "Augmented
!> Lagrangian"): an increment is solved by Newton with the multipliers held (predicted from
!> the last increments' with PREDICT, frix_contact_augmentation), then, while an
!> augmented pass has an active slave node whose |gap| (or stick slip) exceeds its tolerance,
!> the multipliers are updated by Uzawa's rule (frix_contact_augmentation) and the increment
!> is solved again from where the last solution ended, at most MAXAUG times (the largest over
!> the pairs). The Uzawa iteration is the nested one of Simo & Laursen (Comput. Struct. 42
!> (1992) 97-116): each Newton solution is an equilibrium for its multipliers, and each update
!> brings the penetration down by about the ratio of the interface's stiffness to eps_N; where
!> that is slow the penalties grow within the increment (the method of multipliers;
!> frix_contact_augmentation's grow_penalties; the grown penalties carry over to the next
!> increments). Every solution before the check passes is converged on the residual criterion
!> alone (frix_newton_solver's residual_only: an inexact inner minimisation, Bertsekas,
!> Constrained Optimization and Lagrange Multiplier Methods, 1982, 2.5); once it passes, the
!> increment is solved to both criteria from there (`final`, one iteration mostly; none when the
!> last solution met both anyway) and checked again. The re-solutions reuse the factorization
!> of the last tangent while it serves (frix_newton_solver's reuse_factors, frix_factor_reuse:
!> the multipliers change the contact forces, not the tangent); a grown penalty discards it. When the limit is reached with
!> penetrations still beyond tolerance the increment is accepted with a warning (its
!> equilibrium is converged; only the constraint is loose), as the progress lines say.
module frix_augmentation
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_model, only: model_t
   use frix_analysis_state, only: analysis_state_t, restore_state
   use frix_newton_solver, only: newton_context_t, path_constraint_t, solve_increment
   use frix_newton_report, only: newton_report_t
   use frix_contact_augmentation, only: penetration_check_t, check_penetrations, augment_multipliers, &
                                        max_augmentations, grow_penalties, start_penalty_growth, &
                                        predict_multipliers
   implicit none
   private

   public :: solve_augmented

contains

   !> solve_increment, followed by the augmentations of augmented contact pairs (module
   !> head), from the multipliers predicted by PREDICT (frix_contact_augmentation's
   !> predict_multipliers); when that attempt does not converge, the increment is solved
   !> again from the committed multipliers before the caller cuts back (a prediction can be
   !> poor where a node's multiplier jumped in the last increment, e.g. at a punch edge).
   !> `report` is the last solution's; `iterations` counts the Newton iterations of all.
   subroutine solve_augmented(model, context, state, time, max_iterations, label, report, iterations, &
                              error, path)
      type(model_t), intent(in) :: model
      type(newton_context_t), intent(inout) :: context
      type(analysis_state_t), intent(inout) :: state
      real(dp), intent(in) :: time
      integer, intent(in) :: max_iterations
      character(len=*), intent(in) :: label
      type(newton_report_t), intent(out) :: report
      integer, intent(out) :: iterations
      type(error_t), allocatable, intent(out) :: error
      type(path_constraint_t), intent(in), optional :: path
      integer :: retry_iterations
      logical :: predicted
      call augmented_attempt(model, context, state, time, max_iterations, label, .true., predicted, report, &
                             iterations, error, path)
      if (.not. predicted .or. allocated(error) .or. report%converged .or. report%interrupted) return
      if (.not. context%quiet) write (*, '(2x,a)') 'no convergence from the predicted multipliers: the '// &
         'increment solved again from the committed ones'
      call restore_state(state)
      call augmented_attempt(model, context, state, time, max_iterations, label, .false., predicted, report, &
                             retry_iterations, error, path)
      iterations = iterations + retry_iterations
   end subroutine solve_augmented

   !> One attempt of solve_augmented, with the multipliers predicted if `predict` (`predicted`:
   !> some multiplier was).
   subroutine augmented_attempt(model, context, state, time, max_iterations, label, predict, predicted, report, &
                                iterations, error, path)
      type(model_t), intent(in) :: model
      type(newton_context_t), intent(inout) :: context
      type(analysis_state_t), intent(inout) :: state
      real(dp), intent(in) :: time
      integer, intent(in) :: max_iterations
      character(len=*), intent(in) :: label
      logical, intent(in) :: predict
      logical, intent(out) :: predicted
      type(newton_report_t), intent(out) :: report
      integer, intent(out) :: iterations
      type(error_t), allocatable, intent(out) :: error
      type(path_constraint_t), intent(in), optional :: path
      type(penetration_check_t) :: check
      real(dp) :: change
      integer :: k, limit
      logical :: grown
      predicted = .false.
      limit = 0
      if (state%has_contact) then
         limit = max_augmentations(model, state%contact)
         call start_penalty_growth(state%contact)
         if (predict) call predict_multipliers(model, state%contact, prediction_step(state, time), predicted)
      end if
      ! with augmented pairs, every solution is intermediate (residual_only) until the check passes
      call solve_increment(model, context, state, time, max_iterations, label, report, error, path, &
                           residual_only=limit > 0)
      iterations = report%iterations
      if (allocated(error) .or. .not. report%converged .or. limit == 0) return
      k = 0
      do
         check = check_penetrations(model, state%contact)
         if (check%within .or. k == limit) then
            if (report%fully_converged) exit
            ! the last solution converged on the residual alone: to both criteria now (one
            ! iteration, mostly), and checked again
            call solve_again(label//'  final', .false.)
            if (allocated(error) .or. .not. report%converged) then
               if (allocated(report%failure)) report%failure = report%failure//' in the final solution'
               return
            end if
            cycle
         end if
         k = k + 1
         call grow_penalties(model, state%contact, grown)
         if (grown) call context%factors%discard()   ! the tangent changed with the penalty
         change = augment_multipliers(model, state%contact)
         context%n_augmentations = context%n_augmentations + 1
         call print_augmentation(context, model, k, check, change, grown)
         call solve_again(label//'  aug'//to_string(k), .true.)
         if (allocated(error) .or. .not. report%converged) then
            if (allocated(report%failure)) report%failure = report%failure//' in augmentation '//to_string(k)
            return
         end if
      end do
      if (.not. check%within .and. .not. context%quiet) &
         write (*, '(2x,a)') 'augmentation limit ('//to_string(limit)//') reached: '// &
            violation_text(model, check)//'; the increment is accepted'
   contains
      !> The increment solved again from where the last solution ended (path following: the
      !> load factor found is the start), with the factors of the last tangent while they
      !> serve (frix_newton_solver's reuse_factors); its iterations counted, those with
      !> reused factors not.
      subroutine solve_again(solve_label, residual_only)
         character(len=*), intent(in) :: solve_label
         logical, intent(in) :: residual_only
         real(dp) :: solve_time
         integer :: reused
         solve_time = state%time
         reused = context%n_reused_corrections
         call solve_increment(model, context, state, solve_time, max_iterations, solve_label, report, error, &
                              path, residual_only, reuse_factors=.true.)
         iterations = iterations + report%iterations - (context%n_reused_corrections - reused)
      end subroutine solve_again
   end subroutine augmented_attempt

   !> The pseudo time over which an increment to `time` predicts the multipliers: time -
   !> t_n, or 0 when the last converged increment ended at or before the start of time's step
   !> (step s spans (s - 1, s]; a step's first increment has nothing to extrapolate from).
   pure real(dp) function prediction_step(state, time)
      type(analysis_state_t), intent(in) :: state
      real(dp), intent(in) :: time
      prediction_step = 0.0_dp
      if (state%committed_time > real(ceiling(time), dp) - 1.0_dp) prediction_step = time - state%committed_time
   end function prediction_step

   !> The progress line of augmentation k.
   subroutine print_augmentation(context, model, k, check, change, grown)
      type(newton_context_t), intent(in) :: context
      type(model_t), intent(in) :: model
      integer, intent(in) :: k
      type(penetration_check_t), intent(in) :: check
      real(dp), intent(in) :: change
      logical, intent(in) :: grown   !! a penalty grew for the next solution
      if (context%quiet) return
      write (*, '(2x,a)') 'augmentation '//to_string(k)//': '//violation_text(model, check)// &
         '; largest multiplier change '//to_string(change)//trim(merge('; penalty grown', '               ', grown))
   end subroutine print_augmentation

   !> "<n> nodes beyond the tolerance, largest |gap| (or stick slip) <v> (tolerance <t>) at
   !> node <id>", for the progress lines.
   function violation_text(model, check) result(text)
      type(model_t), intent(in) :: model
      type(penetration_check_t), intent(in) :: check
      character(len=:), allocatable :: text
      text = to_string(check%n_over)//' nodes beyond the tolerance, largest '// &
             trim(merge('stick slip', '|gap|     ', check%slip))//' '//to_string(check%penetration)// &
             ' (tolerance '//to_string(check%tolerance)//') at node '//to_string(model%mesh%node_ids(check%node))
   end function violation_text
end module frix_augmentation
