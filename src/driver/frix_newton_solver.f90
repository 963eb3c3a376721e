!> Newton-Raphson solution of one load increment.
!>
!> Residual r = fext - fint on the free equations; reactions R = fint - fext on the constrained
!> ones. An iterate is converged when
!>   ||r|| <= TOLRESID * max(||fext||, ||R||)              (residual criterion), and
!>   ||du|| <= TOLDISP * ||u||  for the last correction du   (displacement criterion);
!> an iterate whose residual is already below 1e-4 TOLRESID times the reference is accepted
!> without the displacement criterion (the response was linear, as in Abaqus' "zero residual"
!> rule). An intermediate solution of augmented Lagrangian contact (`residual_only`,
!> frix_augmentation) is converged on the residual criterion alone, after one correction at
!> least: its multipliers are updated next anyway, and the solution the increment ends with
!> meets both criteria.
!> Such a re-solution may also reuse the factors (`reuse_factors`, frix_factor_reuse): a
!> correction is then solved with the factorization of an earlier tangent of the increment,
!> without assembling and factorizing a new one, while the contact statuses and faces are
!> those it was assembled with and the last correction brought ||r|| below reuse_contraction
!> times the one before (modified Newton); otherwise the iteration assembles and factorizes as
!> usual. Only the corrections with a new factorization count as Newton iterations
!> (n_iterations); the others are n_reused_corrections, their progress lines marked `reused`.
!> With contact, an iterate is converged only when no slave node is held in a friction
!> branch other than the law's own (slip reversal, frix_contact_assembly). The energy norm
!> printed per iteration is |du . r| of the correction just made.
!>
!> Path following (a `path_constraint_t` given): the load factor t is an unknown of the
!> increment, found at every iteration with the correction from one displacement constraint
!> u_c = target (Batoz & Dhatt, "Incremental displacement algorithms for nonlinear problems",
!> IJNME 14 (1979) 1262-1267): K a = r, K b = q with q = d fext / dt the load rate at the current
!> geometry, then dt = (target - u_c - a_c) / b_c and du = a + dt b. The increment can then pass a
!> limit point of the load, where K is singular along the path and load control fails.
module frix_newton_solver
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_stop_request, only: stop_requested
   use frix_model, only: model_t
   use frix_analysis_state, only: analysis_state_t
   use frix_system_matrix, only: system_matrix_t
   use frix_global_reductions, only: global_norm, global_dot, global_max_abs_location
   use frix_process_group, only: n_processes, is_root_process, sum_over_processes, agree_on_error, &
                                 agree_on_failure, partition_mesh
   use frix_linear_solver, only: linear_solver_t, wall_clock_seconds
   use frix_linear_solver_registry, only: create_linear_solver
   use frix_assembler, only: assemble_internal, internal_tangent_symmetric
   use frix_constraint_equations, only: constraint_equations_t
   use frix_tie_constraints, only: add_tie_equations, record_tie_forces
   use frix_kinematic_coupling, only: add_coupling_equations
   use frix_external_loads, only: assemble_external, prescribed_displacements, has_follower_loads
   use frix_newton_report, only: newton_report_t, reserve_iteration_log, print_progress
   use frix_factor_reuse, only: factor_reuse_t
   use frix_equation_checks, only: check_finite, check_finite_tangent, describe_singularity, equation_label
   use frix_contact_assembly, only: search_contact, assemble_contact, &
                                    contact_counts, reset_friction_branches, &
                                    release_inconsistent_branches, add_pattern_pairs, contact_gaps
   implicit none
   private

   public :: newton_context_t, path_constraint_t, setup_newton, solve_increment

   !> An increment of a path-following step (see the module head): its constraint, and the
   !> step's pseudo times over which its loads are linear in t. With equation = 0 the
   !> increment is load-controlled at the given t, with the step's loads (the landing on the
   !> step's end).
   type :: path_constraint_t
      integer :: equation = 0           !! the driven global equation (node-major, 3 per node)
      real(dp) :: target = 0.0_dp       !! its displacement at the end of the increment [length]
      real(dp) :: step_start = 0.0_dp   !! the step's pseudo times: q is the load change
      real(dp) :: step_end = 1.0_dp     !! between them (exact for loads linear in the step)
   end type path_constraint_t

   !> The contact line search's acceptance level over an increment's Newton steps: the
   !> weighted mean C_k = (eta Q_k-1 C_k-1 + |r_k|) / Q_k, Q_k = eta Q_k-1 + 1, of the residual
   !> norms |r_k| at their starts (Zhang & Hager, "A nonmonotone line search technique and its
   !> application to unconstrained optimization", SIAM J. Optim. 14 (2004) 1043-1056, with
   !> eta = nonmonotone_weight). C_k >= |r_k| while the residual falls: a step may raise the
   !> residual a little above the last one, not above the mean of the earlier ones.
   type :: acceptance_level_t
      real(dp) :: level = 0.0_dp
      real(dp) :: weight = 0.0_dp   !! Q_k; 0 before the first step
      !> consecutive Newton steps the line search shortened below short_step (a stall)
      integer :: short_steps = 0
   contains
      procedure :: include => include_step
      procedure :: record_step
   end type acceptance_level_t

   !> Everything the iterations need that outlives one increment.
   type :: newton_context_t
      class(system_matrix_t), allocatable :: matrix   !! in the storage of the solver (its new_matrix)
      class(linear_solver_t), allocatable :: solver    !! from the deck's SOLVER (frix_linear_solver_registry)
      logical :: symmetric = .true.        !! tangent symmetric: materials, loads and contact all say so
      logical, allocatable :: fixed(:)     !! constrained equations
      !> the rows of the ties and kinematic couplings (frix_constraint_equations)
      type(constraint_equations_t) :: constraints
      !> equations eliminated by those rows: solved as fixed, then recovered
      logical, allocatable :: dependent(:)
      real(dp), allocatable :: prescribed(:)
      real(dp), allocatable :: fint(:), fext(:), residual(:), correction(:)
      real(dp), allocatable :: reactions(:) !! fint - fext on constrained equations, 0 elsewhere
      real(dp), allocatable :: diagonal(:)  !! diagonal of the tangent just assembled
      real(dp), allocatable :: load_rate(:)      !! path following: q = d fext / dt
      real(dp), allocatable :: load_response(:)  !! path following: b = K^-1 q
      !> in a path-following increment: its step's pseudo times (loads linear in t between
      !> them); unallocated otherwise (then an absent argument of assemble_external)
      real(dp), allocatable :: step_window(:)
      logical :: quiet = .false.
      real(dp) :: assembly_seconds = 0.0_dp    !! element loop + scatter + loads, accumulated [s]
      !> the parts of assembly_seconds: element loop with its scatter, contact search, contact
      !> kernels with their scatter [s]
      real(dp) :: element_seconds = 0.0_dp, search_seconds = 0.0_dp, contact_seconds = 0.0_dp
      integer :: n_assemblies = 0
      integer :: n_iterations = 0              !! Newton corrections of the whole run
      integer :: n_line_search_trials = 0      !! shortened steps tried by the contact line search
      integer :: n_releases = 0                !! converged iterates where held nodes were released
      integer :: n_predicted_contact = 0       !! singular tangents solved again (solve_predicted_contact)
      integer :: n_continuations = 0           !! failed increments retried by friction continuation
      integer :: n_augmentations = 0           !! multiplier updates of augmented contact (frix_augmentation)
      !> corrections solved with the factors of an earlier tangent (solve_increment's reuse_factors)
      integer :: n_reused_corrections = 0
      type(factor_reuse_t) :: factors          !! the contact state of the last factorization
   end type newton_context_t

   real(dp), parameter :: zero_residual_fraction = 1.0e-4_dp
   !> What test_convergence found.
   integer, parameter :: outcome_iterate = 0, outcome_converged = 1, outcome_failed = 2, outcome_released = 3
   !> iterations the report's log holds at first; it doubles when MAXITER allows more
   integer, parameter :: initial_log_length = 64
   !> The weight of the past in the contact line search's acceptance level (contact_line_search;
   !> 0 would be the monotone rule): Zhang & Hager's eta, their recommended 0.85
   real(dp), parameter :: nonmonotone_weight = 0.85_dp
   !> A Newton step cut by the contact line search below this fraction counts as a stall
   !> (acceptance_level_t%short_steps, contact_line_search's first-touch trial)
   real(dp), parameter :: short_step = 0.1_dp
   !> The first-touch trial goes this factor beyond the fraction where the first open node
   !> touches (contact_line_search): inside the contact, by 10 % of the way to it
   real(dp), parameter :: touch_overshoot = 1.1_dp
   real(dp), parameter :: divergence_factor = 1.0e6_dp  !! ||r|| growing beyond this x the first: diverging
   !> A correction must bring ||r|| below this fraction of the last one for the next to reuse
   !> the factors (one decade: a new tangent is cheaper than a slow tail of modified-Newton
   !> corrections; 0.5 gives the same iterations on the augmented benchmark decks, 0.01 more
   !> on S3: docs/contact.md, "Augmented Lagrangian")
   real(dp), parameter :: reuse_contraction = 0.1_dp

contains

   !> The constraint equations of the ties and couplings, the sparse pattern from the
   !> connectivity with the pairs their elimination needs (kept among the contact system's
   !> extra pairs, which every rebuild of the pattern uses), the linear solver and work arrays.
   subroutine setup_newton(model, state, context, error)
      type(model_t), intent(in) :: model
      type(analysis_state_t), intent(inout) :: state   !! with its contact passes set up
      type(newton_context_t), intent(out) :: context
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: pairs(:, :), first(:), masters(:)
      integer :: n
      n = 3*model%mesh%n_nodes
      call partition_mesh(model%mesh%connectivity, model%mesh%n_nodes)   ! (a parallel run: docs/parallel.md)
      if (tied(state)) call add_tie_equations(state%contact%passes, context%constraints)
      call add_coupling_equations(model, context%constraints)
      call context%constraints%pattern_pairs(model%mesh%n_nodes, model%mesh%connectivity, pairs)
      context%symmetric = .not. has_follower_loads(model) .and. internal_tangent_symmetric(model)
      ! the slip branch of Coulomb friction and smoothed normals make the tangent unsymmetric
      if (state%has_contact) then
         if (state%contact%unsymmetric) context%symmetric = .false.
      end if
      call create_linear_solver(model%controls%linear_solver, context%solver, error, symmetric=context%symmetric)
      if (allocated(error)) return
      if (n_processes() > 1 .and. context%solver%name() /= 'PETSC') then
         call fatal_error(error, model%deck_path//': a run on '//to_string(n_processes())//' MPI processes needs '// &
                          'SOLVER Petsc (the solver of this deck, '//context%solver%name()// &
                          ', runs on one process; docs/parallel.md)')
         return
      end if
      call context%solver%set_node_coordinates(model%mesh%coords)
      call context%solver%new_matrix(context%matrix)
      if (state%has_contact) then
         call context%constraints%master_nodes(model%mesh%n_nodes, first, masters)
         call add_pattern_pairs(state%contact, pairs, first, masters)
         call context%matrix%create_node_block_pattern(model%mesh%n_nodes, model%mesh%connectivity, &
                                                       state%contact%extra_pairs(:, :state%contact%n_extra), error)
      else
         call context%matrix%create_node_block_pattern(model%mesh%n_nodes, model%mesh%connectivity, pairs, error)
      end if
      if (allocated(error)) return
      allocate (context%fixed(n), context%prescribed(n))
      allocate (context%dependent(n), source=.false.)
      allocate (context%fint(n), context%fext(n), context%residual(n), context%correction(n), &
                context%reactions(n), context%diagonal(n), context%load_rate(n), context%load_response(n), &
                source=0.0_dp)
   end subroutine setup_newton

   !> Iterate from the committed state to equilibrium at pseudo time `time`, or, with `path`
   !> (path%equation > 0), to equilibrium on the constraint u_c = path%target with the pseudo
   !> time an unknown that starts from `time`; with `path`, the loads are linear in t over the
   !> step and the prescribed displacements are held at their value at the step's end (equal to
   !> that at its start: the deck reader checks it). On return state holds the last iterate
   !> (converged or not) and its pseudo time; the caller commits or restores. `error` is set
   !> only for failures that a smaller increment cannot cure (a singular matrix at the first
   !> iteration, a solver failure); non-convergence is reported in `report` instead.
   !> `residual_only`: converged on the residual criterion alone (module head).
   !> `reuse_factors`: the corrections may be solved with the factors of an earlier tangent of
   !> the increment (module head; not with a driven displacement).
   subroutine solve_increment(model, context, state, time, max_iterations, label, report, error, path, &
                              residual_only, reuse_factors)
      type(model_t), intent(in) :: model
      type(newton_context_t), intent(inout) :: context
      type(analysis_state_t), intent(inout) :: state
      real(dp), intent(in) :: time
      integer, intent(in) :: max_iterations
      character(len=*), intent(in) :: label   !! "step s incr k" for the progress lines
      type(newton_report_t), intent(out) :: report
      type(error_t), allocatable, intent(out) :: error
      type(path_constraint_t), intent(in), optional :: path
      logical, intent(in), optional :: residual_only, reuse_factors
      integer :: iteration, outcome
      real(dp) :: residual_norm, reference, correction_norm, energy, current_time, time_correction
      type(acceptance_level_t) :: acceptance   !! of the contact line search
      logical :: waive_displacement, may_reuse, reusing
      logical :: evaluated   !! the line search left the residual of the iterate (reusing only)

      current_time = time
      waive_displacement = .false.
      if (present(residual_only)) waive_displacement = residual_only
      may_reuse = .false.
      if (present(reuse_factors)) may_reuse = reuse_factors .and. .not. driving(path)
      call start_increment(model, context, state, time, may_reuse, path)
      reusing = may_reuse
      evaluated = .false.
      correction_norm = huge(1.0_dp)
      energy = 0.0_dp
      call reserve_iteration_log(report, min(max_iterations, initial_log_length))

      do iteration = 0, max_iterations
         if (agree_on_failure(stop_requested())) then   ! (on every process alike)
            report%interrupted = .true.
            report%failure = 'stopped by a signal'
            return
         end if
         call evaluate_iterate(model, context, state, current_time, iteration, reusing, evaluated, residual_norm, &
                               reference, report, error)
         if (allocated(error) .or. allocated(report%failure)) return
         call record_iteration(context, state, label//trim(merge('  reused', '        ', reusing)), current_time, &
                               iteration, residual_norm, reference, energy, report)
         call test_convergence(model, context, state, iteration, max_iterations, residual_norm, reference, &
                               correction_norm, waive_displacement, report, outcome, path)
         select case (outcome)
         case (outcome_converged)
            report%converged = .true.
            return
         case (outcome_failed)
            return
         case (outcome_released)
            energy = 0.0_dp
            correction_norm = huge(1.0_dp)
            cycle
         end select
         call apply_correction(model, context, state, iteration, current_time, time_correction, energy, &
                               correction_norm, reusing, report, error, path)
         if (allocated(error) .or. allocated(report%failure)) return
         if (reusing) then
            context%n_reused_corrections = context%n_reused_corrections + 1
         else
            context%n_iterations = context%n_iterations + 1
         end if
         reusing = may_reuse   ! tried again at the next iterate (evaluate_iterate)
         evaluated = .false.
         if (state%has_contact .and. iteration > 0) then
            call acceptance%include(residual_norm)
            call contact_line_search(model, context, state, current_time, time_correction, acceptance, &
                                     correction_norm, evaluated, residual_norm, reference, report%failure, error)
            if (allocated(error) .or. allocated(report%failure)) return
         end if
      end do
   end subroutine solve_increment

   !> The iterate's residual (evaluate_equilibrium) and, unless `reusing`, its tangent. With
   !> `reusing` the residual is evaluated alone (or, when `evaluated`, taken as the line search
   !> left it: residual_norm and reference in) and the factors of the last tangent are kept
   !> for the correction when they still are its tangent (frix_factor_reuse) and the last
   !> correction reduced ||r|| by reuse_contraction at least; otherwise `reusing`
   !> turns false and the iterate is evaluated again with its tangent. Without `reusing`, an
   !> unsymmetric tangent of a symmetric system is announced to the solver and the diagonal
   !> kept (roundoff_floor).
   subroutine evaluate_iterate(model, context, state, time, iteration, reusing, evaluated, residual_norm, &
                               reference, report, error)
      type(model_t), intent(in) :: model
      type(newton_context_t), intent(inout) :: context
      type(analysis_state_t), intent(inout) :: state
      real(dp), intent(in) :: time
      integer, intent(in) :: iteration
      logical, intent(inout) :: reusing
      logical, intent(in) :: evaluated
      real(dp), intent(inout) :: residual_norm, reference
      type(newton_report_t), intent(inout) :: report
      type(error_t), allocatable, intent(out) :: error
      if (reusing) then
         if (.not. evaluated) call evaluate_equilibrium(model, context, state, time, .false., residual_norm, &
                                                        reference, report%failure, error)
         if (allocated(error) .or. allocated(report%failure)) return
         reusing = context%factors%matches(state, context%matrix%pattern_id)
         if (reusing .and. iteration > 0) &
            reusing = residual_norm <= reuse_contraction*report%residual_norms(iteration - 1)
         if (reusing) return
      end if
      call evaluate_equilibrium(model, context, state, time, .true., residual_norm, reference, &
                                report%failure, error, predictor=iteration == 0)
      if (allocated(error) .or. allocated(report%failure)) return
      if (context%symmetric .and. state%has_contact) then
         if (state%contact%clamped_unsymmetric) call context%solver%expect_unsymmetric()
      end if
      call context%matrix%get_diagonal(context%diagonal)
      if (n_processes() > 1) call sum_over_processes(context%diagonal)   ! each process holds its elements' part
   end subroutine evaluate_iterate

   !> Count the Newton steps the line search cut below short_step in a row (fraction: the
   !> accepted part of the step).
   pure subroutine record_step(acceptance, fraction)
      class(acceptance_level_t), intent(inout) :: acceptance
      real(dp), intent(in) :: fraction
      if (fraction < short_step) then
         acceptance%short_steps = acceptance%short_steps + 1
      else
         acceptance%short_steps = 0
      end if
   end subroutine record_step

   !> The level after a Newton step that starts from |r| = residual_norm (acceptance_level_t).
   pure subroutine include_step(acceptance, residual_norm)
      class(acceptance_level_t), intent(inout) :: acceptance
      real(dp), intent(in) :: residual_norm
      real(dp) :: weight
      weight = nonmonotone_weight*acceptance%weight + 1.0_dp
      acceptance%level = (nonmonotone_weight*acceptance%weight*acceptance%level + residual_norm)/weight
      acceptance%weight = weight
   end subroutine include_step

   !> Start an increment at pseudo time `time`: the solver's and the contact branches' state
   !> reset, the prescribed displacements of `time` (path following: of the step's end) set.
   !> With `reuse_factors` the solver keeps the factors of the last solution (and the choice
   !> between CHOLMOD and UMFPACK that made them); without, they are forgotten.
   subroutine start_increment(model, context, state, time, reuse_factors, path)
      type(model_t), intent(in) :: model
      type(newton_context_t), intent(inout) :: context
      type(analysis_state_t), intent(inout) :: state
      real(dp), intent(in) :: time
      logical, intent(in) :: reuse_factors
      type(path_constraint_t), intent(in), optional :: path
      state%time = time
      if (allocated(context%step_window)) deallocate (context%step_window)
      if (.not. reuse_factors) then
         call context%solver%begin_increment()
         call context%factors%discard()
      end if
      if (state%has_contact) call reset_friction_branches(state%contact)
      if (present(path)) then
         context%step_window = [path%step_start, path%step_end]
         call prescribed_displacements(model, path%step_end, context%fixed, context%prescribed)
      else
         call prescribed_displacements(model, time, context%fixed, context%prescribed)
      end if
      where (context%fixed) state%u = context%prescribed
      if (constrained(context)) then
         call context%constraints%dependent_equations(context%fixed, context%dependent)
         call context%constraints%expand_vector(context%dependent, state%u)
      end if
   end subroutine start_increment

   !> Whether the model has equations eliminated by constraints (ties, couplings).
   pure logical function constrained(context)
      type(newton_context_t), intent(in) :: context
      constrained = .not. context%constraints%empty()
   end function constrained

   !> Whether the model has ties (frix_tie_constraints).
   pure logical function tied(state)
      type(analysis_state_t), intent(in) :: state
      tied = .false.
      if (state%has_contact) tied = state%contact%tied
   end function tied

   !> The iteration's norms into the report's log, and its progress line.
   subroutine record_iteration(context, state, label, time, iteration, residual_norm, reference, energy, report)
      type(newton_context_t), intent(in) :: context
      type(analysis_state_t), intent(in) :: state
      character(len=*), intent(in) :: label
      real(dp), intent(in) :: time, residual_norm, reference, energy
      integer, intent(in) :: iteration
      type(newton_report_t), intent(inout) :: report
      if (iteration > ubound(report%residual_norms, 1)) call reserve_iteration_log(report, 2*iteration)
      report%iterations = iteration
      report%residual_norms(iteration) = residual_norm
      report%relative_norms(iteration) = residual_norm/reference
      report%energy_norms(iteration) = energy
      if (state%has_contact) then
         call contact_counts(state%contact, report%active(iteration), report%slipping(iteration))
      end if
      if (.not. context%quiet) call print_progress(label, time, iteration, residual_norm, &
                                                   residual_norm/reference, energy, state%has_contact, &
                                                   report%active(iteration), report%slipping(iteration))
   end subroutine record_iteration

   !> Whether the iterate is converged (residual and, unless the residual is negligible or
   !> `waive_displacement`, the correction below their tolerances, on the path; with contact,
   !> no node held in stick that the law would let slip: else they are released and the
   !> iterations go on, `outcome_released`), has failed (the iteration limit, divergence) or
   !> goes on (`outcome_iterate`).
   subroutine test_convergence(model, context, state, iteration, max_iterations, residual_norm, reference, &
                               correction_norm, waive_displacement, report, outcome, path)
      type(model_t), intent(in) :: model
      type(newton_context_t), intent(inout) :: context
      type(analysis_state_t), intent(inout) :: state
      integer, intent(in) :: iteration, max_iterations
      real(dp), intent(in) :: residual_norm, reference, correction_norm
      logical, intent(in) :: waive_displacement
      type(newton_report_t), intent(inout) :: report
      integer, intent(out) :: outcome
      type(path_constraint_t), intent(in), optional :: path
      real(dp) :: u_norm
      integer :: n_released
      outcome = outcome_iterate
      u_norm = global_norm(state%u)
      if (residual_norm <= max(model%controls%tol_residual*reference, roundoff_floor(model, context, state%u)) &
          .and. on_path(model, state, path, iteration, u_norm)) then
         report%fully_converged = residual_norm <= zero_residual_fraction*model%controls%tol_residual*reference &
                                  .or. correction_norm <= max(model%controls%tol_displacement*u_norm, &
                                                              position_roundoff(model, state%u)) &
                                  .or. next_correction_small(model, report, iteration, residual_norm, &
                                                             correction_norm, u_norm)
         ! (residual_only after one correction at least: its caller acts on the solution)
         if (report%fully_converged .or. (waive_displacement .and. iteration > 0)) then
            outcome = outcome_converged
            if (.not. state%has_contact) return
            ! nodes held in stick after a slip reversal that the law would let slip?
            n_released = release_inconsistent_branches(state%contact)
            if (n_released == 0) return
            context%n_releases = context%n_releases + 1
            if (.not. context%quiet) write (*, '(2x,i0,a)') n_released, ' nodes held in stick released to slip'
            outcome = outcome_released
            if (iteration < max_iterations) return
         end if
      end if
      if (iteration >= max_iterations) then
         report%failure = 'no convergence in '//to_string(max_iterations)//' iterations'//worst_entries(model, context)
         outcome = outcome_failed
      ! (path following starts from an equilibrium state: no reference to diverge from)
      else if (iteration > 0 .and. residual_norm > divergence_factor*report%residual_norms(0) .and. &
               report%residual_norms(0) > 0.0_dp .and. .not. driving(path)) then
         report%failure = 'the iterations diverge'//worst_entries(model, context)
         outcome = outcome_failed
      end if
   end subroutine test_convergence

   !> Whether the correction the next iteration would make, estimated as the last one scaled by
   !> the residual's contraction over the last iteration, |du_k| ||r_k|| / ||r_k-1||, meets the
   !> displacement criterion. With Newton's quadratic convergence the next correction is
   !> K^-1 r_k and shrinks with the residual; the estimate is trusted only when the residual
   !> fell by at least `contraction_limit` in the last iteration.
   logical function next_correction_small(model, report, iteration, residual_norm, correction_norm, u_norm)
      type(model_t), intent(in) :: model
      type(newton_report_t), intent(in) :: report
      integer, intent(in) :: iteration
      real(dp), intent(in) :: residual_norm, correction_norm, u_norm
      real(dp), parameter :: contraction_limit = 1.0e-3_dp
      real(dp) :: contraction
      next_correction_small = .false.
      if (iteration < 1) return
      if (report%residual_norms(iteration - 1) <= 0.0_dp) return
      contraction = residual_norm/report%residual_norms(iteration - 1)
      if (contraction > contraction_limit) return
      next_correction_small = contraction*correction_norm <= model%controls%tol_displacement*u_norm
   end function next_correction_small

   !> One Newton correction: the constrained system solved, the load factor's correction of
   !> path following (`time_correction`), every value checked finite, the iterate and `time`
   !> updated; `energy` = |du . r| and `correction_norm` = |du|. `reusing`: solved with the
   !> factors of an earlier tangent (evaluate_iterate), else the tangent is factorized.
   subroutine apply_correction(model, context, state, iteration, time, time_correction, energy, correction_norm, &
                               reusing, report, error, path)
      type(model_t), intent(in) :: model
      type(newton_context_t), intent(inout) :: context
      type(analysis_state_t), intent(inout) :: state
      integer, intent(in) :: iteration
      real(dp), intent(inout) :: time
      real(dp), intent(out) :: time_correction, energy, correction_norm
      logical, intent(in) :: reusing
      type(newton_report_t), intent(inout) :: report
      type(error_t), allocatable, intent(out) :: error
      type(path_constraint_t), intent(in), optional :: path
      type(error_t), allocatable :: inner_error
      energy = 0.0_dp
      correction_norm = 0.0_dp
      if (reusing) then
         call solve_factorized(context, context%residual, context%correction, inner_error)
      else
         call apply_dirichlet_rows(context)
         call factorize_and_solve(model, context, inner_error)
         if (allocated(inner_error) .and. state%has_contact) then
            if (context%solver%failed_equation > 0) then
               deallocate (inner_error)
               call solve_predicted_contact(model, context, state, time, inner_error)
            end if
         end if
         if (allocated(inner_error)) then
            call context%factors%discard()
         else
            call context%factors%record(state, context%matrix%pattern_id)
         end if
      end if
      if (allocated(inner_error)) then
         if (iteration == 0) then
            call move_alloc(inner_error, error)
         else
            report%failure = inner_error%message
         end if
         return
      end if
      where (context%fixed) context%correction = 0.0_dp
      if (constrained(context)) call context%constraints%expand_vector(context%dependent, context%correction)
      time_correction = 0.0_dp
      if (driving(path)) then
         call path_correction(model, context, state, path, time_correction, report%failure, error)
         if (allocated(error) .or. allocated(report%failure)) return
      end if
      call check_finite(model, context%correction, 'Newton correction', report%failure)
      if (allocated(report%failure)) return
      energy = abs(global_dot(context%correction, context%residual))
      if (.not. ieee_is_finite(energy)) then
         report%failure = 'the energy |du . r| of the correction is not finite (beyond the range of real '// &
                          'numbers); its largest term is at '// &
                          equation_label(model, global_max_abs_location(context%correction*context%residual))
         return
      end if
      correction_norm = global_norm(context%correction)
      state%u = state%u + context%correction
      call check_finite(model, state%u, 'displacement', report%failure)
      if (allocated(report%failure)) return
      time = time + time_correction
      if (.not. ieee_is_finite(time)) then
         report%failure = 'the load factor of the path-following iteration is not finite'
         return
      end if
      state%time = time
   end subroutine apply_correction

   !> The fixed and dependent equations' rows and columns of the tangent cleared, with the mean
   !> |K_ii| of the tangent just assembled (context%diagonal) on their diagonal; in a parallel
   !> run the processes' matrices are summed and process 0 alone puts the diagonal.
   subroutine apply_dirichlet_rows(context)
      type(newton_context_t), intent(inout) :: context
      real(dp) :: diagonal_scale
      diagonal_scale = sum(abs(context%diagonal))/max(1, size(context%diagonal))
      if (diagonal_scale == 0.0_dp) diagonal_scale = 1.0_dp
      if (.not. is_root_process()) diagonal_scale = 0.0_dp
      call context%matrix%apply_dirichlet(context%fixed .or. context%dependent, diagonal_scale)
   end subroutine apply_dirichlet_rows

   !> A singular tangent with contact (typically a body that has left all its master surfaces
   !> at this iterate and floats): the correction is solved again with every open slave node
   !> that has a master face taken as in contact, its internal force linear in its gap
   !> (A k_N g, pulling it onto the master) and its stiffness the touching one: the Newton step
   !> of the penalty law on an active set that holds every node near a master, as an active-set
   !> (semi-smooth) Newton step re-enters nodes (Hintermueller, Ito & Kunisch, SIAM J. Optim.
   !> 13 (2003) 865-888). Nodes that should stay open leave the set at the next iterate, whose
   !> residual is the true law's; the residual, fint and reactions of this iterate are kept for
   !> the line search.
   subroutine solve_predicted_contact(model, context, state, time, error)
      type(model_t), intent(in) :: model
      type(newton_context_t), intent(inout) :: context
      type(analysis_state_t), intent(inout) :: state
      real(dp), intent(in) :: time
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: residual(:), fint(:), reactions(:)
      real(dp) :: residual_norm, reference
      character(len=:), allocatable :: failure
      context%n_predicted_contact = context%n_predicted_contact + 1
      allocate (residual, source=context%residual)
      allocate (fint, source=context%fint)
      allocate (reactions, source=context%reactions)
      call evaluate_equilibrium(model, context, state, time, .true., residual_norm, reference, failure, error, &
                                open_band=huge(1.0_dp))
      if (.not. allocated(error) .and. allocated(failure)) call fatal_error(error, failure)
      if (allocated(error)) return
      call context%matrix%get_diagonal(context%diagonal)
      call apply_dirichlet_rows(context)
      call factorize_and_solve(model, context, error)
      context%residual = residual
      context%fint = fint
      context%reactions = reactions
   end subroutine solve_predicted_contact

   !> Path following: the load-factor correction dt of this iteration and the correction
   !> du = a + dt b, where a = K^-1 r is in context%correction (with K still factorized) and
   !> b = K^-1 q answers the load rate q = (fext(step_end) - fext(step_start)) / (step_end -
   !> step_start) at the current geometry (follower loads included), which is d fext / dt of
   !> the loads of a path-following step (assemble_external's step_window).
   subroutine path_correction(model, context, state, path, time_correction, failure, error)
      type(model_t), intent(in) :: model
      type(newton_context_t), intent(inout) :: context
      type(analysis_state_t), intent(in) :: state
      type(path_constraint_t), intent(in) :: path
      real(dp), intent(out) :: time_correction
      character(len=:), allocatable, intent(inout) :: failure
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: response
      time_correction = 0.0_dp
      call assemble_external(model, path%step_end, state%u, context%load_rate)
      call assemble_external(model, path%step_start, state%u, context%load_response)
      context%load_rate = (context%load_rate - context%load_response)/(path%step_end - path%step_start)
      where (context%fixed) context%load_rate = 0.0_dp
      if (constrained(context)) call context%constraints%condense_vector(context%dependent, context%load_rate)
      call solve_factorized(context, context%load_rate, context%load_response, error)
      if (allocated(error)) return
      where (context%fixed) context%load_response = 0.0_dp
      if (constrained(context)) call context%constraints%expand_vector(context%dependent, context%load_response)
      response = context%load_response(path%equation)
      if (.not. abs(response) > 0.0_dp) then
         failure = 'the loads do not move the driving displacement ('// &
                   equation_label(model, path%equation)//')'
         return
      end if
      time_correction = (path%target - state%u(path%equation) - context%correction(path%equation))/response
      context%correction = context%correction + time_correction*context%load_response
   end subroutine path_correction

   !> Whether the driven displacement of a path-following increment is at its target, within
   !> the displacement tolerance (TOLDISP ||u||), after at least one correction (an increment
   !> whose target lies within that tolerance of its start must still move onto it, or the
   !> step would repeat it); always true without a driven displacement.
   logical function on_path(model, state, path, iteration, u_norm)
      type(model_t), intent(in) :: model
      type(analysis_state_t), intent(in) :: state
      type(path_constraint_t), intent(in), optional :: path
      integer, intent(in) :: iteration
      real(dp), intent(in) :: u_norm   !! ||u|| of the iterate
      on_path = .true.
      if (.not. driving(path)) return
      on_path = iteration > 0 .and. &
                abs(state%u(path%equation) - path%target) <= model%controls%tol_displacement*u_norm
   end function on_path

   !> Whether the increment drives a displacement (path following proper).
   logical function driving(path)
      type(path_constraint_t), intent(in), optional :: path
      driving = .false.
      if (present(path)) driving = path%equation > 0
   end function driving

   !> Internal, contact and external forces at state%u: the residual r = fext - fint on the
   !> free equations, the reactions on the constrained ones, ||r|| and the reference
   !> max(||fext||, ||R||); with `with_tangent` also the tangent matrix. `failure` is set when
   !> an element cannot be evaluated (a smaller increment may cure it), `error` for a failure
   !> of the contact search.
   subroutine evaluate_equilibrium(model, context, state, time, with_tangent, residual_norm, reference, &
                                   failure, error, predictor, open_band)
      type(model_t), intent(in) :: model
      type(newton_context_t), intent(inout) :: context
      type(analysis_state_t), intent(inout) :: state
      real(dp), intent(in) :: time
      logical, intent(in) :: with_tangent
      real(dp), intent(out) :: residual_norm, reference
      character(len=:), allocatable, intent(inout) :: failure
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: predictor   !! first iteration of the increment
      real(dp), intent(in), optional :: open_band  !! open nodes taken as in contact (solve_predicted_contact)
      type(error_t), allocatable :: element_error
      real(dp) :: start, lap
      start = wall_clock_seconds()
      if (state%has_contact) then
         call search_contact(model, state%contact, state%u, context%matrix, error)
         if (allocated(error)) return
      end if
      lap = wall_clock_seconds()
      context%search_seconds = context%search_seconds + (lap - start)
      if (with_tangent) then
         call assemble_internal(model, state, context%fint, element_error, matrix=context%matrix)
      else
         call assemble_internal(model, state, context%fint, element_error)
      end if
      context%element_seconds = context%element_seconds + (wall_clock_seconds() - lap)
      if (allocated(element_error)) then
         failure = element_error%message
         return
      end if
      call check_finite(model, context%fint, 'internal force', failure)
      if (allocated(failure)) return
      lap = wall_clock_seconds()
      ! contact and loads are evaluated on every process (their state stays the same on all),
      ! their tangents added by process 0 alone (frix_process_group)
      context%matrix%ignore_additions = .not. is_root_process()
      if (state%has_contact) then
         if (with_tangent) then
            call assemble_contact(model, state%contact, state%u, context%fint, context%matrix, predictor, open_band)
         else
            call assemble_contact(model, state%contact, state%u, context%fint)
         end if
      end if
      context%contact_seconds = context%contact_seconds + (wall_clock_seconds() - lap)
      if (with_tangent) then
         call assemble_external(model, time, state%u, context%fext, matrix=context%matrix, &
                                step_window=context%step_window)
      else
         call assemble_external(model, time, state%u, context%fext, step_window=context%step_window)
      end if
      context%matrix%ignore_additions = .false.
      if (state%has_contact) call check_finite(model, context%fint, 'contact force', failure)
      if (.not. allocated(failure)) call check_finite(model, context%fext, 'external force', failure)
      if (.not. allocated(failure) .and. with_tangent) call check_finite_tangent(model, context%matrix, failure)
      if (allocated(failure)) return
      context%assembly_seconds = context%assembly_seconds + (wall_clock_seconds() - start)
      context%n_assemblies = context%n_assemblies + 1
      context%residual = context%fext - context%fint
      if (constrained(context)) then
         call eliminate_constraints(model, context, state, with_tangent, error)
         if (allocated(error)) return
      end if
      where (context%fixed)
         context%reactions = -context%residual
         context%residual = 0.0_dp
      elsewhere
         context%reactions = 0.0_dp
      end where
      residual_norm = global_norm(context%residual)
      reference = max(global_norm(merge(context%fext, 0.0_dp, .not. context%fixed)), global_norm(context%reactions))
      if (reference == 0.0_dp) reference = 1.0_dp
      if (.not. (ieee_is_finite(residual_norm) .and. ieee_is_finite(reference))) &
         failure = 'the norm of the residual or of the reactions is not finite (beyond the range of real numbers)'
   end subroutine evaluate_equilibrium

   !> Ties and couplings: the ties' bond forces recorded from the residual, then the dependent
   !> equations eliminated from the residual and (with_tangent) the tangent
   !> (frix_constraint_equations).
   subroutine eliminate_constraints(model, context, state, with_tangent, error)
      type(model_t), intent(in) :: model
      type(newton_context_t), intent(inout) :: context
      type(analysis_state_t), intent(inout) :: state
      logical, intent(in) :: with_tangent
      type(error_t), allocatable, intent(out) :: error
      if (tied(state)) call record_tie_forces(model%mesh%coords, state%u, context%dependent, context%residual, &
                                              state%contact%passes)
      call context%constraints%condense_vector(context%dependent, context%residual)
      if (with_tangent) call context%constraints%condense_matrix(context%dependent, context%matrix, error)
      ! (each process's share of the matrix: a pair missing on one is a failure on all)
      if (with_tangent) call agree_on_error(error)
   end subroutine eliminate_constraints

   !> Line search after a Newton correction du with contact, when the residual at u + du is
   !> larger than before the correction (penalty contact overshoots as nodes enter or leave
   !> contact or cross a stick/slip boundary). The step u + s du is searched for a root of
   !> the directional energy g(s) = du . r(u + s du): g(0) = du . r > 0 and g(1) < 0 bracket
   !> the point where the work of the residual along du vanishes (Crisfield, *Non-linear
   !> Finite Element Analysis of Solids and Structures*, vol. 1, Wiley 1991, 9.3;
   !> Matthies & Strang, IJNME 14 (1979)); the bracket is narrowed by the Illinois variant of
   !> regula falsi, kept at least 5 % inside. This finds the kink of a node that the step
   !> pushes across its friction cone or through its contact. Without a bracket (g(1) > 0,
   !> or g(0) <= 0 with an unsymmetric tangent) the step is halved; after a step where an
   !> element cannot be evaluated, the search stays below that step. The first trial whose
   !> residual norm is not larger than `acceptance_level` is accepted: a weighted mean of |r|
   !> at the starts of this increment's Newton steps (acceptance_level_t, nonmonotone: while
   !> the active set of a soft penalty grows over several iterations, the residual may rise a
   !> little for an iteration or two on the way to the solution, and the monotone rule cut those
   !> steps short); after `max_trials` the trial with
   !> the smallest residual norm is kept. After a stall (the last Newton step cut below
   !> short_step), a bracketed search first tries the step just past the point where the first
   !> open slave node touches its master (first_touch, touch_overshoot): a stiff penalty makes
   !> g(1) so negative that regula falsi lands at the 5 % inset, before that node touches, and
   !> the active set, hence the tangent, never changes (docs/contact.md, "In the global system",
   !> Line search). The correction norm reported is that of the
   !> accepted step. With path following the pseudo time moves with the step, t_old + s dt
   !> (`time` in: after the full step; out: after the accepted one). `evaluated`: the state is
   !> the last trial evaluated (an accepted one), whose residual (context%residual, ...) and
   !> norms (`residual_norm`, `reference`) are those of the next iterate.
   subroutine contact_line_search(model, context, state, time, time_correction, acceptance, &
                                  correction_norm, evaluated, residual_norm, reference, failure, error)
      type(model_t), intent(in) :: model
      type(newton_context_t), intent(inout) :: context
      type(analysis_state_t), intent(inout) :: state
      real(dp), intent(inout) :: time
      real(dp), intent(in) :: time_correction   !! dt of the full step (0 without path following)
      type(acceptance_level_t), intent(inout) :: acceptance
      real(dp), intent(inout) :: correction_norm
      logical, intent(out) :: evaluated
      real(dp), intent(inout) :: residual_norm, reference
      character(len=:), allocatable, intent(inout) :: failure
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: max_trials = 8
      real(dp), parameter :: inset = 0.05_dp   !! minimum distance from the bracket's ends
      real(dp) :: trial_norm, trial_reference, fraction, next, best_norm, best_fraction
      real(dp) :: low, high, g_low, g_high, g, touch
      real(dp), allocatable :: gaps_before(:)
      logical :: bracketed, failed_high
      integer :: k, replaced_end
      evaluated = .false.
      low = 0.0_dp
      g_low = global_dot(context%correction, context%residual)   ! g(0): the residual before the step
      high = 1.0_dp
      g_high = 0.0_dp
      bracketed = .false.      ! g(low) > 0 >= g(high)
      failed_high = .false.    ! high is a step where an element could not be evaluated
      replaced_end = 0         ! 1: low, 2: high replaced by the last update (Illinois)
      fraction = 1.0_dp
      best_norm = huge(1.0_dp)
      best_fraction = 1.0_dp
      if (acceptance%short_steps > 0) call contact_gaps(state%contact, gaps_before)
      touch = 1.0_dp
      do k = 1, max_trials
         call evaluate_equilibrium(model, context, state, time, .false., trial_norm, trial_reference, failure, &
                                   error)
         if (allocated(error)) return
         if (k == 1 .and. allocated(gaps_before)) touch = first_touch(state, gaps_before)
         if (allocated(failure)) then
            deallocate (failure)   ! an inverted element: a shorter step
            high = fraction
            bracketed = .false.
            failed_high = .true.
         else
            if (trial_norm <= acceptance%level) then
               call acceptance%record_step(fraction)
               correction_norm = fraction*global_norm(context%correction)
               evaluated = .true.
               residual_norm = trial_norm
               reference = trial_reference
               return
            end if
            if (trial_norm < best_norm) then
               best_norm = trial_norm
               best_fraction = fraction
            end if
            g = global_dot(context%correction, context%residual)
            if (g_low > 0.0_dp .and. g <= 0.0_dp) then
               ! overshoot (or a root): the root lies in (low, fraction]
               if (bracketed) then
                  if (replaced_end == 2) g_low = 0.5_dp*g_low   ! Illinois: low kept twice in a row
                  replaced_end = 2
               else
                  replaced_end = 0
               end if
               high = fraction
               g_high = g
               bracketed = .true.
            else if (g_low > 0.0_dp .and. (bracketed .or. failed_high)) then
               ! g > 0: the root lies beyond this trial, below high
               if (bracketed) then
                  if (replaced_end == 1) g_high = 0.5_dp*g_high   ! high kept twice in a row
                  replaced_end = 1
               end if
               low = fraction
               g_low = g
            else
               high = fraction   ! no bracket (g(1) > 0, or g(0) <= 0): halve towards 0
            end if
         end if
         if (k == max_trials) exit
         if (bracketed .and. touch < 1.0_dp) then
            ! after a stalled step: just past the first touch, so that the node enters the active set
            next = min(touch_overshoot*touch, 0.5_dp*(1.0_dp + touch))
         else if (bracketed) then
            next = low + g_low*(high - low)/(g_low - g_high)
            next = min(max(next, low + inset*(high - low)), high - inset*(high - low))
         else
            next = 0.5_dp*(low + high)
         end if
         touch = 1.0_dp   ! the first trial after the full step only
         state%u = state%u + (next - fraction)*context%correction
         time = time + (next - fraction)*time_correction
         state%time = time
         fraction = next
         context%n_line_search_trials = context%n_line_search_trials + 1
      end do
      ! no trial lowered the residual: keep the best one (u_old + best_fraction du)
      state%u = state%u + (best_fraction - fraction)*context%correction
      time = time + (best_fraction - fraction)*time_correction
      state%time = time
      correction_norm = best_fraction*global_norm(context%correction)
      call acceptance%record_step(best_fraction)
   end subroutine contact_line_search

   !> The fraction s of the step at which the first slave node open before it (gap g0 > 0 in
   !> `gaps_before`) touches its master, with the gap taken linear along the step to its value
   !> g1 < 0 after the full step: s = min g0 / (g0 - g1); 1 when no open node closes.
   real(dp) function first_touch(state, gaps_before) result(touch)
      type(analysis_state_t), intent(in) :: state
      real(dp), intent(in) :: gaps_before(:)
      real(dp), allocatable :: gaps_after(:)
      integer :: i
      call contact_gaps(state%contact, gaps_after)
      touch = 1.0_dp
      do i = 1, size(gaps_before)
         if (gaps_before(i) > 0.0_dp .and. gaps_before(i) < huge(1.0_dp) .and. gaps_after(i) < 0.0_dp) &
            touch = min(touch, gaps_before(i)/(gaps_before(i) - gaps_after(i)))
      end do
   end function first_touch

   !> Factorize and solve K du = r (a CHOLMOD solver falls back to UMFPACK by itself where the
   !> matrix is not positive definite, frix_auto_solver); a failure names where it broke down.
   subroutine factorize_and_solve(model, context, error)
      type(model_t), intent(in) :: model
      type(newton_context_t), intent(inout) :: context
      type(error_t), allocatable, intent(out) :: error
      call context%solver%factorize(context%matrix, error)
      if (allocated(error)) then
         call describe_singularity(model, context%solver%failed_equation, error)
         return
      end if
      call solve_factorized(context, context%residual, context%correction, error)
   end subroutine factorize_and_solve

   !> x = K^-1 rhs with the factorization of this iteration.
   subroutine solve_factorized(context, rhs, x, error)
      type(newton_context_t), intent(inout) :: context
      real(dp), intent(in) :: rhs(:)
      real(dp), intent(out) :: x(:)
      type(error_t), allocatable, intent(out) :: error
      call context%solver%solve(context%matrix, rhs, x, error)
   end subroutine solve_factorized

   !> Where the last iterate is worst, appended to a failure message (as an Abaqus message file
   !> names the largest residual force and displacement correction): the largest residual
   !> component (force) and the largest component of the last Newton correction (length),
   !> each with its node and direction; the last correction is that of the solve, before any
   !> line-search shortening.
   function worst_entries(model, context) result(text)
      type(model_t), intent(in) :: model
      type(newton_context_t), intent(in) :: context
      character(len=:), allocatable :: text
      integer :: residual_at, correction_at
      residual_at = global_max_abs_location(context%residual)
      correction_at = global_max_abs_location(context%correction)
      text = '; largest residual '//to_string(context%residual(residual_at))//' at '// &
             equation_label(model, residual_at)//', largest Newton correction '// &
             to_string(context%correction(correction_at))//' at '//equation_label(model, correction_at)
   end function worst_entries

   !> The round-off of the current positions, roundoff_factor epsilon ||X + u||: a correction
   !> below it cannot be made smaller, so it meets the displacement criterion however small
   !> ||u|| is (an exact solution u = 0: a soil in equilibrium with its initial stress, whose
   !> augmented contact multipliers carry the in-situ pressure with no penetration).
   function position_roundoff(model, u) result(floor)
      type(model_t), intent(in) :: model
      real(dp), intent(in) :: u(:)
      real(dp) :: floor
      real(dp), parameter :: roundoff_factor = 10.0_dp
      floor = roundoff_factor*epsilon(1.0_dp)*global_norm(reshape(model%mesh%coords, [size(u)]) + u)
   end function position_roundoff

   !> The residual that round-off alone produces: forces computed from positions (penalty
   !> contact eps_N A g, strains from x - X) carry errors of about epsilon |K_ii| |x_i| per
   !> equation, which a relative test cannot beat when the load is small (the first small
   !> increments of a cut-back with stiff penalties). Returns roundoff_factor times
   !> epsilon ||K_ii |x_i| || over the free equations, with the diagonal of the tangent just
   !> assembled (context%diagonal) and x = X + u the current coordinates (for the rotation node
   !> of a kinematic coupling, whose coordinates are no position, x = u = theta).
   function roundoff_floor(model, context, u) result(floor)
      type(model_t), intent(in) :: model
      type(newton_context_t), intent(in) :: context
      real(dp), intent(in) :: u(:)
      real(dp) :: floor
      real(dp), parameter :: roundoff_factor = 10.0_dp
      logical, allocatable :: rotation(:)
      integer :: node, i, equation
      allocate (rotation(model%mesh%n_nodes), source=.false.)
      if (allocated(model%couplings)) rotation(model%couplings%rotation_node) = .true.
      floor = 0.0_dp
      do node = 1, model%mesh%n_nodes
         do i = 1, 3
            equation = 3*(node - 1) + i
            if (context%fixed(equation)) cycle
            floor = floor + (context%diagonal(equation)* &
                             (merge(0.0_dp, model%mesh%coords(i, node), rotation(node)) + u(equation)))**2
         end do
      end do
      floor = roundoff_factor*epsilon(1.0_dp)*sqrt(floor)
   end function roundoff_floor

end module frix_newton_solver
