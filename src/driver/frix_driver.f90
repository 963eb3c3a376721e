!> Top level of a run: read the deck, set up the analysis, march through the steps with
!> automatic cut-back, and write the results of every converged increment.
!>
!> Increment control: step s runs from t = s-1 to t = s in NUMSTEP equal increments of size
!> dt = 1/NUMSTEP. An increment that fails (no convergence within MAXITER, diverging residual,
!> an element turned inside out) is retried with half the size, down to the smallest size
!> dt / 2^MAXCUT. After a cut, the size grows back by a factor 1.5 (never beyond dt) after
!> every increment that converged in at most a third of MAXITER iterations. When an increment
!> of the smallest size fails, the run stops with a message and a non-zero exit; the results
!> of every converged increment are already on disk.
!>
!> A step with CONTROL Path advances the driving displacement instead, by (TARGET - its value
!> at the start of the step) / NUMSTEP per increment, with the load factor an unknown (the same
!> cut-back and growth of the increment size); it ends when the displacement reaches TARGET.
!> An increment whose load factor passes the step's end is repeated under load control to
!> t = s, which ends the step.
module frix_driver
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string, padded, fixed_point
   use frix_model, only: model_t
   use frix_deck_reader, only: read_deck
   use frix_analysis_state, only: analysis_state_t, create_analysis_state, commit_state, &
                                  restore_state, take_displacement_reference, extrapolate_displacements
   use frix_newton_solver, only: newton_context_t, path_constraint_t, setup_newton
   use frix_augmentation, only: solve_augmented
   use frix_newton_report, only: newton_report_t
   use frix_equation_checks, only: equation_label
   use frix_results_output, only: results_output_t
   use frix_results_collection, only: collect_results
   use frix_increment_results, only: increment_results_t
   use frix_linear_solver, only: wall_clock_seconds
   use frix_linear_solver_registry, only: finish_linear_solvers
   use frix_model_summary, only: model_summary
   use frix_state_restart, only: read_state_restart
   use frix_hdf5_file, only: hdf5_finalize
   use frix_process_group, only: agree_on_failure, n_processes, partition_summary
   use frix_stop_request, only: stop_requested, stop_signal_name
   implicit none
   private

   public :: run_options_t, run_deck

   type :: run_options_t
      character(len=:), allocatable :: deck_path
      character(len=:), allocatable :: output_directory  !! default: the deck's directory
      logical :: check_only = .false.
      logical :: quiet = .false.
      character(len=:), allocatable :: restart_path    !! HDF5 file of an earlier run
      integer :: restart_step = 0                       !! continue after this converged increment
      integer :: restart_increment = 0
   end type run_options_t

   real(dp), parameter :: growth_factor = 1.5_dp

   !> Where a restarted run resumes inside a step: the increment control stored with the
   !> increment it starts from (zero: none stored, the step's nominal values apply).
   type :: resume_t
      integer :: increment = 0             !! converged increments of the step already done
      real(dp) :: increment_size = 0.0_dp  !! the next increment's size [pseudo time]
      real(dp) :: path_increment = 0.0_dp  !! CONTROL Path: driven displacement per nominal increment
   end type resume_t

   !> The progress lines' clock: the time-left estimate extrapolates the run's mean rate (wall
   !> time per unit of pseudo time since the first increment of this run, cut-backs included),
   !> which changes slowly, rather than the last increment's, which jumps with every cut-back
   !> and every change of the increment's size.
   type :: progress_t
      logical :: quiet = .false.
      real(dp) :: start_wall = 0.0_dp   !! wall clock when the run's first increment began [s]
      real(dp) :: start_time = 0.0_dp   !! the pseudo time it began from
   end type progress_t

   !> The increment control of one step (see the module head).
   type :: step_control_t
      integer :: step = 0
      real(dp) :: step_end = 0.0_dp        !! t at the step's end
      real(dp) :: nominal = 0.0_dp         !! 1 / NUMSTEP
      real(dp) :: size_now = 0.0_dp        !! the present increment size (after cut-backs)
      real(dp) :: smallest = 0.0_dp        !! nominal / 2^MAXCUT
      integer :: increment = 0             !! converged increments of the step
      integer :: max_iterations = 0
      logical :: path_control = .false.
      logical :: landing = .false.         !! path control passed t = step_end: load control to it
      logical :: final_increment = .false. !! the attempted path increment reaches TARGET
      logical :: target_reached = .false.
      type(path_constraint_t) :: path, landing_path
      real(dp) :: path_increment = 0.0_dp  !! driven displacement per nominal increment [length]
   end type step_control_t

contains

   subroutine run_deck(options, error)
      type(run_options_t), intent(in) :: options
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      real(dp) :: start

      start = wall_clock_seconds()
      call read_deck(options%deck_path, model, error)
      if (allocated(error)) return
      if (options%check_only) then
         if (.not. options%quiet) write (*, '(a)', advance='no') 'frix: '//options%deck_path//': deck is valid'// &
                                     new_line('a')//model_summary(model)
         return
      end if
      call run_analysis(model, options, start, error)
      call hdf5_finalize()
   end subroutine run_deck

   !> The analysis of a model read from a deck: setup, the steps, the results.
   !>
   !> It computes with the floating-point traps off. Everything here computes with what the
   !> deck gives (loads of 1e308, penalties, coordinates): an overflow or an invalid operation
   !> is a property of the data, not a defect of frix, and must end in the same located failure
   !> whatever the build's trap flags (-ffpe-trap in the Debug and Sanitize builds). The
   !> finite-value guard of the Newton loop (check_finite in frix_newton_solver) stops an
   !> increment at the first non-finite force, tangent entry, correction, energy or
   !> displacement, the driver cuts back, and the output checks every field before writing
   !> (docs/solver.md, "Non-finite values"). The flags raised are cleared; the halting mode is
   !> restored on return (Fortran 2008, 14.5: by the compiler).
   subroutine run_analysis(model, options, start, error)
      use, intrinsic :: ieee_exceptions, only: ieee_set_halting_mode, ieee_set_flag, ieee_usual
      type(model_t), intent(in) :: model
      type(run_options_t), intent(in) :: options
      real(dp), intent(in) :: start   !! wall clock at the start of the run [s]
      type(error_t), allocatable, intent(out) :: error
      call ieee_set_halting_mode(ieee_usual, .false.)
      call analyse(model, options, start, error)
      call finish_linear_solvers()
      call ieee_set_flag(ieee_usual, .false.)
   end subroutine run_analysis

   !> run_analysis's work: state, Newton context, output, then every step.
   subroutine analyse(model, options, start, error)
      type(model_t), intent(in) :: model
      type(run_options_t), intent(in) :: options
      real(dp), intent(in) :: start   !! wall clock at the start of the run [s]
      type(error_t), allocatable, intent(out) :: error
      type(analysis_state_t) :: state
      type(newton_context_t) :: context
      type(results_output_t) :: output
      integer :: step, first_step
      type(resume_t) :: resume
      type(progress_t) :: progress

      call create_analysis_state(model, state, error)
      if (allocated(error)) return
      call setup_newton(model, state, context, error)
      if (allocated(error)) return
      context%quiet = options%quiet
      first_step = 1
      if (allocated(options%restart_path)) then
         call restart_state(model, options, results_base(options), state, first_step, resume, error)
         if (allocated(error)) return
      end if
      call output%open(model, results_base(options), error)
      if (allocated(error)) then
         call output%close(error)   ! the files opened before the failure
         return
      end if
      if (.not. options%quiet) call print_banner(model, context)

      progress = progress_t(options%quiet, wall_clock_seconds(), state%committed_time)
      do step = first_step, size(model%steps)
         if (step /= first_step) resume = resume_t()
         call run_step(model, step, resume, context, state, output, progress, error)
         if (allocated(error)) exit
      end do
      call output%close(error)   ! every file, also after a failure: an error keeps the first
      if (allocated(error)) return
      if (.not. options%quiet) then
         write (*, '(a)') 'frix: '//to_string(output%n_increments)// &
            ' converged increments; results in '//results_base(options)//'*'
         call print_statistics(context, state%has_contact, wall_clock_seconds() - start)
      end if
   end subroutine analyse

   !> The closing statistics block (read by bench/ scripts: keep the `frix: stat` keys).
   subroutine print_statistics(context, has_contact, total_seconds)
      type(newton_context_t), intent(in) :: context
      logical, intent(in) :: has_contact
      real(dp), intent(in) :: total_seconds
      character(len=*), parameter :: row = '(a,t40,f12.4)'
      real(dp) :: analyse, factorize, solve
      integer :: factorizations
      write (*, '(a,t40,i12)') 'frix: stat equations', context%matrix%n
      write (*, '(a,t40,i12)') 'frix: stat matrix_nonzeros', context%matrix%nnz()
      write (*, '(a,t40,i12)') 'frix: stat factor_nonzeros', context%solver%factor_entries
      write (*, '(a,t40,i12)') 'frix: stat newton_iterations', context%n_iterations
      write (*, '(a,t40,i12)') 'frix: stat assemblies', context%n_assemblies
      if (has_contact) write (*, '(a,t40,i12)') 'frix: stat line_search_trials', context%n_line_search_trials
      if (has_contact) write (*, '(a,t40,i12)') 'frix: stat stick_releases', context%n_releases
      if (has_contact) write (*, '(a,t40,i12)') 'frix: stat predicted_contact_solves', context%n_predicted_contact
      if (has_contact) write (*, '(a,t40,i12)') 'frix: stat friction_continuations', &
         context%n_continuations
      if (context%n_augmentations > 0) write (*, '(a,t40,i12)') 'frix: stat augmentations', &
         context%n_augmentations
      write (*, '(a,t40,i12)') 'frix: stat factorizations', context%solver%n_factorizations
      write (*, row) 'frix: stat assembly_seconds', context%assembly_seconds
      write (*, row) 'frix: stat element_seconds', context%element_seconds
      if (has_contact) write (*, row) 'frix: stat contact_search_seconds', context%search_seconds
      if (has_contact) write (*, row) 'frix: stat contact_seconds', context%contact_seconds
      analyse = 0.0_dp
      factorize = 0.0_dp
      solve = 0.0_dp
      factorizations = 0
      call context%solver%add_totals(analyse, factorize, solve, factorizations)
      write (*, '(a,t40,i12)') 'frix: stat factorizations_total', factorizations
      write (*, row) 'frix: stat analyse_seconds', analyse
      write (*, row) 'frix: stat factorize_seconds', factorize
      write (*, row) 'frix: stat solve_seconds', solve
      write (*, row) 'frix: stat total_seconds', total_seconds
      write (*, row) 'frix: stat peak_memory_mb', peak_resident_megabytes()
      write (*, '(a)') 'frix: linear solver '//context%solver%description()
   end subroutine print_statistics

   !> Peak resident set size of this process (VmHWM of /proc/self/status) in MiB; 0 if unknown.
   function peak_resident_megabytes() result(megabytes)
      real(dp) :: megabytes
      character(len=256) :: line
      integer :: unit, stat, kilobytes
      megabytes = 0.0_dp
      open (newunit=unit, file='/proc/self/status', action='read', status='old', iostat=stat)
      if (stat /= 0) return
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         if (line(1:6) == 'VmHWM:') then
            read (line(7:), *, iostat=stat) kilobytes
            if (stat == 0) megabytes = kilobytes/1024.0_dp
            exit
         end if
      end do
      close (unit)
   end function peak_resident_megabytes

   !> March through step `step`, cutting back failed increments.
   subroutine run_step(model, step, resume, context, state, output, progress, error)
      type(model_t), intent(in) :: model
      integer, intent(in) :: step
      type(resume_t), intent(in) :: resume   !! a restart inside this step: where it resumes
      type(newton_context_t), intent(inout) :: context
      type(analysis_state_t), intent(inout) :: state
      type(results_output_t), intent(inout) :: output
      type(progress_t), intent(in) :: progress
      type(error_t), allocatable, intent(out) :: error
      type(step_control_t) :: control
      type(newton_report_t) :: report
      integer :: iterations
      real(dp) :: increment_start, previous_time
      character(len=:), allocatable :: attempted
      logical :: repeat, quiet

      quiet = progress%quiet

      call begin_step(model, step, resume, state, control)
      if (model%steps(step)%reset_displacement .and. resume%increment == 0) then
         call reset_displacements(step, state, output, quiet, error)
         if (allocated(error)) return
      end if
      do while (state%committed_time < control%step_end - 1.0e-12_dp .and. .not. control%target_reached)
         if (agree_on_failure(stop_requested())) then   ! (on every process alike)
            call stopped_error(step, output, state, error)
            return
         end if
         increment_start = wall_clock_seconds()
         previous_time = state%committed_time
         call try_increment(model, control, context, state, quiet, report, iterations, attempted, repeat, error)
         if (allocated(error)) return
         if (report%interrupted) then
            call restore_state(state)
            call stopped_error(step, output, state, error)
            return
         end if
         if (repeat) cycle
         if (report%converged) then
            ! the next increment's size, stored with this one for a restart
            if (control%size_now < control%nominal .and. iterations <= control%max_iterations/3) &
               control%size_now = min(control%nominal, growth_factor*control%size_now)
            call accept_increment(model, control, context, state, report, output, error)
            if (allocated(error)) return
            if (.not. quiet) call print_increment_done(model, state%time, previous_time, progress, &
                                                       wall_clock_seconds() - increment_start, iterations)
         else
            call cut_back(model, control, state, report, attempted, output, quiet, error)
            if (allocated(error)) return
         end if
      end do
      if (control%target_reached .and. .not. quiet) &
         write (*, '(a)') 'frix: step '//to_string(step)//' ends at t = '//time_text(state%committed_time)// &
         ': the displacement at '//equation_label(model, control%path%equation)//' reached its target '// &
         time_text(model%steps(step)%path_target)
   end subroutine run_step

   !> RESET_DISPLACEMENT at the start of step `step`: the converged state becomes the reference
   !> of the reported displacements (a restart within the step reads it from the results file
   !> instead); one line on the terminal and in the listing says so.
   subroutine reset_displacements(step, state, output, quiet, error)
      integer, intent(in) :: step
      type(analysis_state_t), intent(inout) :: state
      type(results_output_t), intent(inout) :: output
      logical, intent(in) :: quiet
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: note
      call take_displacement_reference(state)
      note = 'step '//to_string(step)//': displacements reported from t = '//time_text(state%committed_time)// &
             ' (RESET_DISPLACEMENT)'
      if (.not. quiet) write (*, '(a)') 'frix: '//note
      call output%write_note(note, error)
   end subroutine reset_displacements

   !> The increment control of `step` at its start (see the module head), or where a restart
   !> resumes it.
   subroutine begin_step(model, step, resume, state, control)
      type(model_t), intent(in) :: model
      integer, intent(in) :: step
      type(resume_t), intent(in) :: resume
      type(analysis_state_t), intent(in) :: state
      type(step_control_t), intent(out) :: control
      control%step = step
      control%step_end = real(step, dp)
      control%nominal = 1.0_dp/model%steps(step)%n_increments
      control%max_iterations = model%steps(step)%max_iterations
      if (control%max_iterations <= 0) control%max_iterations = model%controls%max_iterations
      control%size_now = control%nominal
      if (resume%increment_size > 0.0_dp) control%size_now = resume%increment_size
      control%smallest = control%nominal*0.5_dp**model%controls%max_cutbacks
      control%increment = resume%increment
      control%path_control = model%steps(step)%control == 'PATH'
      if (.not. control%path_control) return
      control%path%equation = 3*(model%steps(step)%path_node - 1) + model%steps(step)%path_component
      control%path%step_start = control%step_end - 1.0_dp
      control%path%step_end = control%step_end
      control%path_increment = (model%steps(step)%path_target - state%committed_u(control%path%equation))/ &
                               model%steps(step)%n_increments
      if (resume%path_increment /= 0.0_dp) control%path_increment = resume%path_increment
      control%landing_path = control%path
      control%landing_path%equation = 0   ! load control at the step's end, with the step's loads
   end subroutine begin_step

   !> Attempt the next increment of the step: under path control, the driving displacement's
   !> next target (`repeat`: the load factor passed the step's end, so the increment is to be
   !> repeated under load control to it); else the next load factor. `attempted` describes it
   !> for a failure message.
   subroutine try_increment(model, control, context, state, quiet, report, iterations, attempted, repeat, error)
      type(model_t), intent(in) :: model
      type(step_control_t), intent(inout) :: control
      type(newton_context_t), intent(inout) :: context
      type(analysis_state_t), intent(inout) :: state
      logical, intent(in) :: quiet
      type(newton_report_t), intent(out) :: report
      integer, intent(out) :: iterations
      character(len=:), allocatable, intent(out) :: attempted
      logical, intent(out) :: repeat
      type(error_t), allocatable, intent(out) :: error
      character(len=64) :: label
      real(dp) :: target_time
      repeat = .false.
      label = 'step'//padded(to_string(control%step), 3)//'  incr'//padded(to_string(control%increment + 1), 4)
      if (control%path_control .and. .not. control%landing) then
         associate (path => control%path, final_target => model%steps(control%step)%path_target)
            path%target = state%committed_u(path%equation) + control%path_increment*control%size_now/control%nominal
            ! the increment that reaches (or would pass) TARGET ends on it and ends the step
            control%final_increment = (path%target - final_target)*control%path_increment >= 0.0_dp
            if (control%final_increment) path%target = final_target
            attempted = 'the increment from t = '//time_text(state%committed_time)//' moving '// &
                        'the displacement at '//equation_label(model, path%equation)//' from '// &
                        time_text(state%committed_u(path%equation))//' to '//time_text(path%target)
         end associate
         call attempt_increment(model, context, state, state%committed_time, control%max_iterations, trim(label), &
                                report, iterations, error, control%path)
         if (allocated(error) .or. report%interrupted) return
         if (report%converged .and. state%time > control%step_end) then
            ! past the step's end: land on it under load control
            call restore_state(state)
            control%landing = .true.
            if (.not. quiet) write (*, '(2x,a)') 'the load factor passes t = '//time_text(control%step_end)// &
               ' in this increment: repeated under load control to t = '//time_text(control%step_end)
            control%size_now = control%step_end - state%committed_time
            repeat = .true.
         end if
         return
      end if
      target_time = min(state%committed_time + control%size_now, control%step_end)
      if (control%step_end - target_time < 1.0e-9_dp*control%nominal) target_time = control%step_end
      attempted = 'the increment from t = '//time_text(state%committed_time)//' to t = '//time_text(target_time)
      if (control%landing) then
         call attempt_increment(model, context, state, target_time, control%max_iterations, trim(label), &
                                report, iterations, error, control%landing_path)
      else
         call attempt_increment(model, context, state, target_time, control%max_iterations, trim(label), &
                                report, iterations, error)
      end if
   end subroutine try_increment

   !> Commit a converged increment and write its results.
   subroutine accept_increment(model, control, context, state, report, output, error)
      type(model_t), intent(in) :: model
      type(step_control_t), intent(inout) :: control
      type(newton_context_t), intent(in) :: context
      type(analysis_state_t), intent(inout) :: state
      type(newton_report_t), intent(in) :: report
      type(results_output_t), intent(inout) :: output
      type(error_t), allocatable, intent(out) :: error
      type(increment_results_t) :: results
      control%increment = control%increment + 1
      control%target_reached = control%path_control .and. .not. control%landing .and. control%final_increment
      call commit_state(state, model)
      call collect_results(model, control%step, control%increment, state, context, report, results, error)
      if (allocated(error)) return
      results%increment_size = control%size_now
      results%path_increment = control%path_increment
      call output%write_increment(model, results, error)
   end subroutine accept_increment

   !> After a failed increment: back to the committed state and half the increment size; at
   !> the smallest size allowed, the error that ends the run.
   subroutine cut_back(model, control, state, report, attempted, output, quiet, error)
      type(model_t), intent(in) :: model
      type(step_control_t), intent(inout) :: control
      type(analysis_state_t), intent(inout) :: state
      type(newton_report_t), intent(in) :: report
      character(len=*), intent(in) :: attempted
      type(results_output_t), intent(in) :: output
      logical, intent(in) :: quiet
      type(error_t), allocatable, intent(out) :: error
      call restore_state(state)
      if (control%size_now <= control%smallest*(1.0_dp + 1.0e-9_dp)) then
         call fatal_error(error, 'frix: step '//to_string(control%step)//': '//attempted// &
                          ' failed ('//report%failure//') at the smallest increment allowed ('// &
                          to_string(model%controls%max_cutbacks)//' cut-backs of '// &
                          time_text(control%nominal)//'); the results of the '// &
                          to_string(output%n_increments)//' converged increments up to t = '// &
                          time_text(state%committed_time)//' are written')
         return
      end if
      control%size_now = max(control%smallest, 0.5_dp*control%size_now)
      if (.not. quiet) write (*, '(2x,a)') 'cut-back: '//report%failure//'; new increment size '// &
         time_text(control%size_now)
   end subroutine cut_back

   !> Solve one increment (solve_increment's arguments, with the augmentations of augmented
   !> Lagrangian contact, frix_augmentation), with the friction continuation of
   !> MU_CONTINUATION f_1 > ... > f_m > 1 if that fails on a model with frictional contact: a
   !> homotopy in the friction coefficient within the increment. From the committed state, the
   !> increment is solved with every friction law seeing the pressure f_k p_N (Coulomb: the
   !> coefficient f_k mu), k = 1 .. m, and finally with f = 1, each stage's Newton iterations
   !> starting from the previous stage's solution; the committed contact history (anchors, slip)
   !> is the same in every stage, so the last stage solves exactly the increment that failed
   !> and only its starting point differs. More friction widens the stick zones (mu p_N /
   !> eps_T) and stiffens the sliding modes, which is where Newton failed with low mu
   !> (docs/verification/s3.md); each stage moves its solution a little. A failing stage fails
   !> the attempt (then the caller cuts back). `iterations`: Newton iterations spent in all.
   subroutine attempt_increment(model, context, state, time, max_iterations, label, report, iterations, &
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
      real(dp), allocatable :: factors(:)
      real(dp) :: stage_time
      integer :: k, stage_iterations
      character(len=16) :: factor_text

      if (model%controls%extrapolate .and. .not. present(path)) call extrapolate_displacements(state, time)
      call solve_augmented(model, context, state, time, max_iterations, label, report, iterations, error, path)
      if (allocated(error) .or. report%converged .or. report%interrupted) return
      if (.not. allocated(model%controls%friction_continuation)) return
      if (.not. (state%has_contact .and. state%contact%frictional)) return
      factors = [model%controls%friction_continuation, 1.0_dp]
      context%n_continuations = context%n_continuations + 1
      call restore_state(state)
      stage_time = time   ! path following: each stage starts from the previous stage's load factor
      do k = 1, size(factors)
         state%contact%friction_scale = factors(k)
         write (factor_text, '(f0.3)') factors(k)
         if (.not. context%quiet) write (*, '(2x,a)') 'friction continuation: mu x '//trim(factor_text)
         call solve_augmented(model, context, state, stage_time, max_iterations, label, report, stage_iterations, &
                              error, path)
         iterations = iterations + stage_iterations
         if (allocated(error) .or. report%interrupted) exit
         if (.not. report%converged) then
            if (allocated(report%failure)) report%failure = report%failure// &
               ' in the friction continuation''s stage mu x '//trim(factor_text)
            exit
         end if
         stage_time = state%time
      end do
      state%contact%friction_scale = 1.0_dp
   end subroutine attempt_increment

   !> The error that ends a run stopped by SIGINT or SIGTERM (the program's main exits with
   !> status 3); the increment under way is dropped, the converged ones are written.
   subroutine stopped_error(step, output, state, error)
      integer, intent(in) :: step
      type(results_output_t), intent(in) :: output
      type(analysis_state_t), intent(in) :: state
      type(error_t), allocatable, intent(out) :: error
      call fatal_error(error, 'frix: stopped by '//stop_signal_name()//' in step '//to_string(step)// &
                       '; the results of the '//to_string(output%n_increments)// &
                       ' converged increments up to t = '//time_text(state%committed_time)//' are written')
   end subroutine stopped_error

   !> Load the state of converged increment (restart_step, restart_increment) from the HDF5
   !> file of an earlier run of the same model, and say where the run continues: the step
   !> holding that increment (or the next step if the increment ended its step).
   subroutine restart_state(model, options, base, state, first_step, resume, error)
      type(model_t), intent(in) :: model
      type(run_options_t), intent(in) :: options
      character(len=*), intent(in) :: base
      type(analysis_state_t), intent(inout) :: state
      integer, intent(out) :: first_step
      type(resume_t), intent(out) :: resume
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: time
      if (model%results%hdf5 .and. same_file(options%restart_path, base//'.h5')) then
         call fatal_error(error, 'frix: the restart file '//options%restart_path//' would be '// &
                          'overwritten by this run''s HDF5 results: write them elsewhere with --out DIR')
         return
      end if
      if (options%restart_step < 1 .or. options%restart_step > size(model%steps)) then
         call fatal_error(error, 'frix: --from '//to_string(options%restart_step)//'.'// &
                          to_string(options%restart_increment)//': the deck has steps 1 to '// &
                          to_string(size(model%steps)))
         return
      end if
      call read_state_restart(model, options%restart_path, options%restart_step, options%restart_increment, &
                              state, time, resume%increment_size, resume%path_increment, error)
      if (allocated(error)) then
         error%message = 'frix: restart from '//options%restart_path//': '//error%message
         return
      end if
      ! step s spans the pseudo times (s - 1, s]
      if (.not. (time > real(options%restart_step - 1, dp) .and. &
                 time <= real(options%restart_step, dp) + 1.0e-12_dp)) then
         call fatal_error(error, 'frix: restart from '//options%restart_path//': increment '// &
                          to_string(options%restart_increment)//' of step '//to_string(options%restart_step)// &
                          ' has the time '//time_text(time)//', outside the step')
         return
      end if
      first_step = options%restart_step
      resume%increment = options%restart_increment
      if (abs(time - real(first_step, dp)) < 1.0e-12_dp) then
         first_step = first_step + 1
         resume = resume_t()
      end if
      if (.not. options%quiet) write (*, '(a)') 'frix: restarting from '//options%restart_path// &
         ', step '//to_string(options%restart_step)//' increment '//to_string(options%restart_increment)// &
         ' (t = '//time_text(time)//')'
   end subroutine restart_state

   !> Whether two paths name the same existing file (compared by their canonical form).
   function same_file(first, second) result(same)
      character(len=*), intent(in) :: first, second
      logical :: same
      logical :: exists_first, exists_second
      inquire (file=first, exist=exists_first)
      inquire (file=second, exist=exists_second)
      same = .false.
      if (.not. (exists_first .and. exists_second)) return
      same = canonical(first) == canonical(second)
   end function same_file

   !> The path with "./" and "//" removed; enough for the restart clash check.
   function canonical(path) result(clean)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: clean
      integer :: k
      clean = path
      do
         k = index(clean, '//')
         if (k == 0) exit
         clean = clean(:k)//clean(k + 2:)
      end do
      do
         k = index(clean, '/./')
         if (k == 0) exit
         clean = clean(:k)//clean(k + 3:)
      end do
      if (len(clean) > 2) then
         if (clean(1:2) == './') clean = clean(3:)
      end if
   end function canonical

   !> The line closing a converged increment: its wall time and an estimate of the time left,
   !> the run's mean rate (progress_t) extrapolated to the end of the last step.
   subroutine print_increment_done(model, time, previous_time, progress, seconds, iterations)
      type(model_t), intent(in) :: model
      real(dp), intent(in) :: time, previous_time, seconds
      type(progress_t), intent(in) :: progress
      integer, intent(in) :: iterations
      real(dp) :: left, end_time
      end_time = real(size(model%steps), dp)
      write (*, '(a)', advance='no') '  converged in'//padded(to_string(iterations), 4)//' iterations,'// &
         padded(fixed_point(seconds, 2), 9)//' s;  t ='//padded(fixed_point(time, 4), 9)//' of'// &
         padded(fixed_point(end_time, 1), 6)//' ('//padded(fixed_point(100.0_dp*time/end_time, 1), 5)//' %)'
      ! no estimate when the load factor decreased (path following past a limit point) or
      ! when the rate gives none (a pseudo time past the end, a step of zero length)
      if (time > previous_time .and. time > progress%start_time) then
         left = (wall_clock_seconds() - progress%start_wall)*(end_time - time)/(time - progress%start_time)
         if (left >= 0.0_dp .and. left < 1.0e9_dp) then
            write (*, '(a)', advance='no') ',  about'//padded(fixed_point(left, 1), 10)//' s left'
         else if (left >= 1.0e9_dp) then
            write (*, '(a)', advance='no') ',  more than 1e9 s left'
         end if
      end if
      write (*, '(a)') ''
      flush (6)
   end subroutine print_increment_done

   !> A pseudo time with 10 significant digits.
   pure function time_text(time) result(text)
      real(dp), intent(in) :: time
      character(len=:), allocatable :: text
      character(len=24) :: buffer
      write (buffer, '(es17.10)') time
      text = trim(adjustl(buffer))
   end function time_text

   !> Path prefix of every result file: <output directory>/<deck name without extension>.
   function results_base(options) result(base)
      type(run_options_t), intent(in) :: options
      character(len=:), allocatable :: base
      character(len=:), allocatable :: directory, name
      integer :: slash, dot
      slash = index(options%deck_path, '/', back=.true.)
      name = options%deck_path(slash + 1:)
      dot = index(name, '.', back=.true.)
      if (dot > 1) name = name(:dot - 1)
      if (allocated(options%output_directory)) then
         directory = options%output_directory
      else if (slash > 0) then
         directory = options%deck_path(:slash - 1)
      else
         directory = '.'
      end if
      base = directory//'/'//name
   end function results_base

   subroutine print_banner(model, context)
      type(model_t), intent(in) :: model
      type(newton_context_t), intent(in) :: context
      integer :: k
      write (*, '(a)') 'frix: '//model%deck_path//': '//to_string(model%mesh%n_nodes)//' nodes, '// &
         to_string(model%mesh%n_elements)//' elements, '//to_string(3*model%mesh%n_nodes)// &
         ' equations, '//to_string(size(model%steps))//' steps; linear solver '//context%solver%name()
      if (n_processes() > 1) write (*, '(a)') 'frix: '//partition_summary()   ! (docs/parallel.md)
      do k = 1, size(model%contact_pairs)
         associate (pair => model%contact_pairs(k))
            if (allocated(pair%penalty_note)) &
               write (*, '(a)') 'frix: contact pair '//to_string(pair%id)//': '//pair%penalty_note
         end associate
      end do
   end subroutine print_banner
end module frix_driver
