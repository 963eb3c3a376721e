!> The analysis controls of a deck: PROBLEM TYP and STATIC (keyword/value pairs), LOAD CURVES
!> and STEPS (docs/deck-format.md).
module frix_deck_controls
   use frix_kinds, only: dp
   use frix_strings, only: to_string, to_upper
   use frix_linear_solver_registry, only: is_linear_solver_keyword, linear_solver_choices, &
                                          linear_solver_unavailable
   use frix_model, only: model_t, load_curve_t, step_t, curve_factor
   use frix_deck_tokens, only: deck_line_t, parse_real
   use frix_deck_context, only: deck_reader_t, read_keyword_pairs, keyword_pair_t, require, read_node_dof, &
                                resume_position, after_keyword, s_problem, s_static, s_curves, s_steps
   implicit none
   private

   public :: read_controls, read_curves, read_steps

   !> The keywords of STATIC (read by read_static_pair).
   character(len=15), parameter :: static_keywords(9) = [character(len=15) :: 'KINTYP', 'MAXITER', 'MAXCUT', &
      'TOLRESID', 'TOLDISP', 'SOLVER', 'MU_CONTINUATION', 'EXTRAPOLATION', 'NEWTONRAPHSO']

   !> The keywords of a STEP line after its number.
   character(len=18), parameter :: step_keywords(4) = [character(len=18) :: 'NUMSTEP', 'CONTROL', 'MAXITER', &
      'RESET_DISPLACEMENT']

contains

   !> PROBLEM TYP and STATIC.
   subroutine read_controls(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      call read_keyword_pairs(reader, model, s_problem, [character(len=10) :: 'PROBLEMTYP'], read_problem_pair)
      call read_keyword_pairs(reader, model, s_static, static_keywords, read_static_pair)
   end subroutine read_controls

   !> `PROBLEMTYP Structure`.
   subroutine read_problem_pair(reader, model, pair)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(keyword_pair_t), intent(inout) :: pair
      character(len=:), allocatable :: word
      call reader%take_word(pair%line, pair%position, 'PROBLEMTYP value', word, pair%ok)
      if (pair%ok .and. to_upper(word) /= 'STRUCTURE') then
         call reader%report(pair%line, pair%position - 1, 'unknown problem type (expected Structure)')
         pair%ok = .false.
      end if
   end subroutine read_problem_pair

   !> The Newton controls of STATIC: KINTYP, MAXITER, MAXCUT, TOLRESID, TOLDISP, SOLVER,
   !> MU_CONTINUATION, EXTRAPOLATION, NEWTONRAPHSO.
   subroutine read_static_pair(reader, model, pair)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(keyword_pair_t), intent(inout) :: pair
      integer :: value
      real(dp) :: real_value
      character(len=:), allocatable :: word
      associate (line => pair%line, position => pair%position, ok => pair%ok)
         select case (pair%keyword)
         case ('KINTYP')
            call reader%take_kinematics(line, position, value, ok)
            if (ok) model%controls%default_kinematics = value
         case ('MAXITER')
            call reader%take_integer(line, position, 'MAXITER', value, ok)
            call require(reader, ok, value >= 1, line, position - 1, 'MAXITER must be at least 1')
            if (ok) model%controls%max_iterations = value
         case ('MAXCUT')
            call reader%take_integer(line, position, 'MAXCUT', value, ok)
            call require(reader, ok, value >= 0, line, position - 1, 'MAXCUT must not be negative')
            if (ok) model%controls%max_cutbacks = value
         case ('TOLRESID')
            call reader%take_real(line, position, 'TOLRESID', real_value, ok)
            call require(reader, ok, real_value > 0.0_dp, line, position - 1, 'TOLRESID must be positive')
            if (ok) model%controls%tol_residual = real_value
         case ('TOLDISP')
            call reader%take_real(line, position, 'TOLDISP', real_value, ok)
            call require(reader, ok, real_value > 0.0_dp, line, position - 1, 'TOLDISP must be positive')
            if (ok) model%controls%tol_displacement = real_value
         case ('SOLVER')
            call reader%take_word(line, position, 'SOLVER value', word, ok)
            if (ok .and. .not. is_linear_solver_keyword(word)) then
               call reader%report(line, position - 1, 'unknown solver (expected '//linear_solver_choices//')')
               ok = .false.
            else if (ok .and. linear_solver_unavailable(word) /= '') then
               call reader%report(line, position - 1, 'SOLVER '//trim(word)//': '//linear_solver_unavailable(word))
               ok = .false.
            end if
            if (ok) model%controls%linear_solver = to_upper(word)
         case ('MU_CONTINUATION')
            call read_friction_continuation(reader, line, position, model%controls%friction_continuation, ok)
         case ('EXTRAPOLATION')
            call reader%take_word(line, position, 'EXTRAPOLATION value', word, ok)
            if (ok .and. to_upper(word) /= 'LINEAR' .and. to_upper(word) /= 'NONE') then
               call reader%report(line, position - 1, 'unknown EXTRAPOLATION (expected Linear or None)')
               ok = .false.
            end if
            if (ok) model%controls%extrapolate = to_upper(word) == 'LINEAR'
         case ('NEWTONRAPHSO')
            call reader%take_word(line, position, 'NEWTONRAPHSO value', word, ok)
            if (ok .and. to_upper(word) /= 'LOAD_CONTROL' .and. to_upper(word) /= 'DISPLACEMENT_CONTROL') then
               call reader%report(line, position - 1, &
                                  'unknown NEWTONRAPHSO (expected Load_Control or Displacement_Control)')
               ok = .false.
            end if
         end select
      end associate
   end subroutine read_static_pair

   !> `MU_CONTINUATION f_1 f_2 ... f_m` (after the keyword): the friction scale factors of the
   !> continuation stages, each greater than 1 and smaller than the one before (the final
   !> stage, factor 1, is implied); the list ends at the line's end or at the next token that
   !> is not a number.
   subroutine read_friction_continuation(reader, line, position, factors, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      real(dp), allocatable, intent(inout) :: factors(:)
      logical, intent(inout) :: ok
      real(dp) :: value
      logical :: numeric
      character(len=:), allocatable :: message
      factors = [real(dp) ::]
      do while (ok .and. position <= line%n_tokens())
         call parse_real(line%token(position), value, numeric, message)
         if (.not. numeric) exit
         call reader%take_real(line, position, 'MU_CONTINUATION factor', value, ok)
         call require(reader, ok, value > 1.0_dp, line, position - 1, &
                      'MU_CONTINUATION factors must be greater than 1 (the final stage, 1, is implied)')
         if (ok .and. size(factors) > 0) call require(reader, ok, value < factors(size(factors)), line, &
                                                     position - 1, 'MU_CONTINUATION factors must decrease')
         if (ok) factors = [factors, value]
      end do
      if (ok .and. size(factors) == 0) then
         call reader%report(line, position, 'missing MU_CONTINUATION factor (a number greater than 1)')
         ok = .false.
      end if
   end subroutine read_friction_continuation

   ! ---- LOAD CURVES ----------------------------------------------------------------------

   !> `CURVE <id> POINTS t1 f1 t2 f2 ...`: at least two points, times strictly increasing.
   subroutine read_curves(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(load_curve_t), allocatable :: curves(:)
      type(load_curve_t) :: curve
      integer :: i, k, position, n_curves, n_points, id_position
      logical :: ok
      n_curves = 0
      allocate (curves(max(reader%last(s_curves) - reader%first(s_curves) + 1, 0)))
      allocate (reader%curve_ids(0), reader%failed_curve_ids(0))
      i = 0
      do while (reader%next_line(s_curves, i, position, ok))
         associate (line => reader%lines(i))
            curve%id = 0
            call reader%expect_keyword(line, position, 'CURVE', ok)
            id_position = position
            call reader%take_integer(line, position, 'a curve id', curve%id, ok)
            call require(reader, ok, curve%id >= 1, line, id_position, 'curve id must be positive')
            if (ok) then
               if (any(reader%curve_ids == curve%id)) then
                  call reader%report(line, id_position, 'duplicate curve id '//to_string(curve%id))
                  ok = .false.
               end if
            end if
            call reader%expect_keyword(line, position, 'POINTS', ok)
            n_points = (line%n_tokens() - position + 1)/2
            if (ok .and. mod(line%n_tokens() - position + 1, 2) /= 0) then
               call reader%report(line, line%n_tokens() + 1, 'curve points must come in (time, factor) pairs')
               ok = .false.
            end if
            if (ok .and. n_points < 2) then
               call reader%report(line, position, 'a curve needs at least 2 points')
               ok = .false.
            end if
            if (.not. ok) then
               if (curve%id > 0) reader%failed_curve_ids = [reader%failed_curve_ids, curve%id]
               cycle
            end if
            if (allocated(curve%times)) deallocate (curve%times, curve%factors)
            allocate (curve%times(n_points), curve%factors(n_points))
            do k = 1, n_points
               call reader%take_real(line, position, 'a curve time', curve%times(k), ok)
               if (ok .and. k > 1) then
                  if (.not. (curve%times(k) > curve%times(k - 1))) then
                     call reader%report(line, position - 1, 'curve times not increasing')
                     ok = .false.
                  end if
               end if
               call reader%take_real(line, position, 'a curve factor', curve%factors(k), ok)
            end do
            if (.not. ok) then
               reader%failed_curve_ids = [reader%failed_curve_ids, curve%id]
               cycle
            end if
            n_curves = n_curves + 1
            curves(n_curves) = curve
            reader%curve_ids = [reader%curve_ids, curve%id]
         end associate
      end do
      model%curves = curves(1:n_curves)
   end subroutine read_curves

   !> `STEP <n> NUMSTEP <k> [CONTROL Load|Displacement|Path ...] [MAXITER m] [RESET_DISPLACEMENT]`,
   !> numbered 1, 2, ...
   subroutine read_steps(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(step_t) :: step
      integer :: i, position, number, expected, last_step_line, start
      logical :: ok, line_ok
      allocate (model%steps(0))
      reader%step_lines = 0
      last_step_line = 0
      i = 0
      do while (reader%next_line(s_steps, i, position, ok))
         last_step_line = i
      end do
      expected = 1
      i = 0
      do while (reader%next_line(s_steps, i, position, ok))
         associate (line => reader%lines(i))
            reader%step_lines = reader%step_lines + 1
            call reader%expect_keyword(line, position, 'STEP', ok)
            call reader%take_integer(line, position, 'a step number', number, ok)
            call require(reader, ok, number == expected, line, position - 1, &
                         'steps must be numbered 1, 2, ... in order: expected step '//to_string(expected))
            expected = expected + 1
            step = step_t(n_increments=0, control='LOAD')   ! n_increments 0: NUMSTEP missing
            line_ok = ok
            if (.not. ok) position = resume_position(line, position, step_keywords)
            do while (position <= line%n_tokens())
               start = position
               ok = .true.
               call read_step_keyword(reader, model, line, position, number, step, ok)
               call after_keyword(line, start, step_keywords, position, ok, line_ok)
            end do
            ok = line_ok
            if (ok .and. step%n_increments == 0) then
               call reader%report(line, line%n_tokens() + 1, 'missing NUMSTEP')
               ok = .false.
            end if
            ! a Path step ends where the driving node reaches its target, at a load factor not
            ! known in advance: no step can follow it
            if (ok .and. step%control == 'PATH' .and. i /= last_step_line) then
               call reader%report(line, 1, &
                                  'CONTROL Path is allowed in the last step only (it ends at an unknown load factor)')
               ok = .false.
            end if
            if (ok) model%steps = [model%steps, step]
         end associate
      end do
   end subroutine read_steps

   !> One keyword of a STEP line at `position` (NUMSTEP, CONTROL, MAXITER, RESET_DISPLACEMENT)
   !> with its value(s), into `step` (number `number`).
   subroutine read_step_keyword(reader, model, line, position, number, step, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      integer, intent(in) :: number
      type(step_t), intent(inout) :: step
      logical, intent(inout) :: ok
      character(len=:), allocatable :: word
      select case (line%keyword(position))
      case ('NUMSTEP')
         position = position + 1
         call reader%take_integer(line, position, 'NUMSTEP', step%n_increments, ok)
         call require(reader, ok, step%n_increments >= 1, line, position - 1, 'NUMSTEP must be positive')
      case ('CONTROL')
         position = position + 1
         call reader%take_word(line, position, 'CONTROL value', word, ok)
         if (.not. ok) return
         select case (to_upper(word))
         case ('LOAD', 'DISPLACEMENT')
            step%control = to_upper(word)
         case ('PATH')
            step%control = 'PATH'
            call read_path_control(reader, model, line, position, number, step, ok)
         case default
            call reader%report(line, position - 1, 'unknown CONTROL (expected Load, Displacement or Path)')
            ok = .false.
         end select
      case ('MAXITER')
         position = position + 1
         call reader%take_integer(line, position, 'MAXITER', step%max_iterations, ok)
         call require(reader, ok, step%max_iterations >= 1, line, position - 1, 'MAXITER must be at least 1')
      case ('RESET_DISPLACEMENT')
         position = position + 1
         step%reset_displacement = .true.
      case default
         call reader%report(line, position, 'unknown keyword in STEPS')
         ok = .false.
      end select
   end subroutine read_step_keyword

   !> `CONTROL Path NODE <id> DOF <1-3> TARGET <value>` (after the word Path) of step `number`:
   !> the driving displacement, which must be free (no Dirichlet condition on it), and loads
   !> that change over the step while the prescribed displacements do not (the load factor is
   !> the unknown that scales the former; the latter are held at their values).
   subroutine read_path_control(reader, model, line, position, number, step, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      integer, intent(in) :: number        !! the step's number
      type(step_t), intent(inout) :: step
      logical, intent(inout) :: ok
      integer :: node_position, control_position, k
      real(dp) :: start, finish
      control_position = position - 1
      node_position = position + 1
      call read_node_dof(reader, model, line, position, step%path_node, step%path_component, ok)
      call reader%expect_keyword(line, position, 'TARGET', ok)
      call reader%take_real(line, position, 'TARGET (the displacement where the step ends)', step%path_target, ok)
      if (.not. ok) return
      if (.not. any(model%mesh%connectivity == step%path_node)) then
         call reader%report(line, node_position, 'this node belongs to no element (it is held fixed): '// &
                            'CONTROL Path needs a free displacement')
         ok = .false.
         return
      end if
      do k = 1, size(model%dirichlet)
         if (model%dirichlet(k)%component /= step%path_component) cycle
         if (.not. any(model%dirichlet(k)%nodes == step%path_node)) cycle
         call reader%report(line, node_position, 'this displacement is prescribed (DIRICHLET CONDITIONS, line '// &
                            to_string(model%dirichlet(k)%line)//'): CONTROL Path needs a free one')
         ok = .false.
         return
      end do
      start = real(number - 1, dp)
      finish = real(number, dp)
      do k = 1, size(model%dirichlet)
         if (model%dirichlet(k)%value == 0.0_dp) cycle
         if (curve_factor(model, model%dirichlet(k)%curve, start) == &
             curve_factor(model, model%dirichlet(k)%curve, finish)) cycle
         call reader%report(line, control_position, 'the prescribed displacement of line '// &
                            to_string(model%dirichlet(k)%line)//' changes during this step: CONTROL Path '// &
                            'holds prescribed displacements at their values')
         ok = .false.
         return
      end do
      if (.not. loads_change(model, start, finish)) then
         call reader%report(line, control_position, 'no load changes during this step: CONTROL Path '// &
                            'scales the step''s load change by the unknown load factor')
         ok = .false.
      end if
   end subroutine read_path_control

   !> Whether a nodal force, pressure or body force has a different factor at `start` and
   !> `finish`.
   logical function loads_change(model, start, finish) result(changes)
      type(model_t), intent(in) :: model
      real(dp), intent(in) :: start, finish
      integer :: k
      changes = .false.
      do k = 1, size(model%nodal_forces)
         if (model%nodal_forces(k)%value /= 0.0_dp) changes = changes .or. &
            curve_factor(model, model%nodal_forces(k)%curve, start) /= &
            curve_factor(model, model%nodal_forces(k)%curve, finish)
      end do
      do k = 1, size(model%pressures)
         if (model%pressures(k)%value /= 0.0_dp) changes = changes .or. &
            curve_factor(model, model%pressures(k)%curve, start) /= &
            curve_factor(model, model%pressures(k)%curve, finish)
      end do
      do k = 1, size(model%body_forces)
         if (any(model%body_forces(k)%gravity /= 0.0_dp)) changes = changes .or. &
            curve_factor(model, model%body_forces(k)%curve, start) /= &
            curve_factor(model, model%body_forces(k)%curve, finish)
      end do
   end function loads_change
end module frix_deck_controls
