!> Supports and loads of a deck: DIRICHLET CONDITIONS, NEUMANN CONDITIONS, BODY FORCE
!> (docs/deck-format.md).
module frix_deck_loads
   use frix_kinds, only: dp
   use frix_model, only: model_t, dirichlet_t, nodal_force_t, pressure_load_t, body_force_t
   use frix_deck_context, only: deck_reader_t, require, mark_nodes, resume_position, after_keyword, &
                                s_dirichlet, s_neumann, s_body_force
   use frix_strings, only: to_string
   implicit none
   private

   public :: read_dirichlet, read_neumann, read_body_forces

   !> Where a DIRICHLET record was read: the reader's line index and the token of its value.
   type :: dirichlet_origin_t
      integer :: line = 0
      integer :: value_token = 0
   end type dirichlet_origin_t

   !> The keywords of a pressure line after its value.
   character(len=8), parameter :: pressure_keywords(2) = [character(len=8) :: 'CURVE', 'FOLLOWER']

contains

   !> `SET <name>|NODE <id> DOF f1 f2 f3 VAL v1 v2 v3 [CURVE c1 c2 c3]`.
   subroutine read_dirichlet(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(dirichlet_t) :: record
      type(dirichlet_origin_t), allocatable :: origins(:)
      integer, allocatable :: nodes(:)
      integer :: i, k, position, flags(3), curves(3), flag_position, value_position
      real(dp) :: values(3)
      logical :: ok
      allocate (model%dirichlet(0), origins(0))
      i = 0
      do while (reader%next_line(s_dirichlet, i, position, ok))
         associate (line => reader%lines(i))
            call reader%take_node_target(model, line, position, nodes, ok)
            call reader%expect_keyword(line, position, 'DOF', ok)
            flag_position = position
            do k = 1, 3
               call reader%take_integer(line, position, 'a DOF flag', flags(k), ok)
               call require(reader, ok, flags(k) == 0 .or. flags(k) == 1, line, position - 1, &
                            'DOF flag must be 0 or 1')
            end do
            call require(reader, ok, any(flags == 1), line, flag_position, 'no DOF flagged (all flags 0)')
            call reader%expect_keyword(line, position, 'VAL', ok)
            value_position = position
            call reader%take_reals(line, position, 'a prescribed value', values, ok)
            curves = 0
            if (ok .and. position <= line%n_tokens()) then
               call reader%expect_keyword(line, position, 'CURVE', ok)
               do k = 1, 3
                  call reader%take_curve(line, position, curves(k), ok)
               end do
            end if
            call reader%expect_end(line, position, ok)
            if (.not. ok) cycle
            do k = 1, 3
               if (flags(k) == 0) cycle
               record%nodes = nodes
               record%component = k
               record%value = values(k)
               record%curve = curves(k)
               record%line = line%number
               model%dirichlet = [model%dirichlet, record]
               origins = [origins, dirichlet_origin_t(i, value_position + k - 1)]
            end do
            call mark_nodes(reader, nodes, i)
         end associate
      end do
      call check_dirichlet_conflicts(reader, model, origins)
   end subroutine read_dirichlet

   !> A DOF prescribed by two lines (directly or through node sets, MESH BLOCK or gmsh sets)
   !> must get the same value and curve from both; a value 0 holds the DOF fixed whatever the
   !> curve. Otherwise the later line is reported, naming the node, the DOF and the earlier
   !> line (once per line and DOF).
   subroutine check_dirichlet_conflicts(reader, model, origins)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(dirichlet_origin_t), intent(in) :: origins(:)   !! of each model%dirichlet record
      integer, allocatable :: owner(:, :)   !! (3, n_nodes) the first record prescribing a DOF
      integer :: r, q, j, node
      allocate (owner(3, model%mesh%n_nodes), source=0)
      do r = 1, size(model%dirichlet)
         associate (record => model%dirichlet(r))
            do j = 1, size(record%nodes)
               node = record%nodes(j)
               q = owner(record%component, node)
               if (q == 0) then
                  owner(record%component, node) = r
               else if (.not. same_prescription(model%dirichlet(q), record)) then
                  call report_conflict(reader, model, origins(q), origins(r), q, r, node)
                  exit
               end if
            end do
         end associate
      end do
   end subroutine check_dirichlet_conflicts

   pure logical function same_prescription(a, b)
      type(dirichlet_t), intent(in) :: a, b
      same_prescription = (a%value == b%value .and. a%curve == b%curve) .or. (a%value == 0.0_dp .and. b%value == 0.0_dp)
   end function same_prescription

   !> `conflicting prescribed values for DOF <k> of node <id>` at the later line's value, with
   !> the earlier line's location and value (and whether its load curve differs).
   subroutine report_conflict(reader, model, first, later, q, r, node)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(dirichlet_origin_t), intent(in) :: first, later
      integer, intent(in) :: q, r      !! the earlier and the later record
      integer, intent(in) :: node
      character(len=:), allocatable :: curves
      curves = ''
      if (model%dirichlet(q)%curve /= model%dirichlet(r)%curve) curves = ' and another load curve'
      associate (first_line => reader%lines(first%line), later_line => reader%lines(later%line))
         call reader%report(later_line, later%value_token, 'conflicting prescribed values for DOF '// &
                            to_string(model%dirichlet(r)%component)//' of node '// &
                            to_string(model%mesh%node_ids(node))//': '//reader%diagnostics%path//':'// &
                            to_string(first_line%number)//' prescribes it with value '// &
                            first_line%token(first%value_token)//curves, &
                            note='    (a DOF takes one value and load curve: lines may repeat it, not change it)')
      end associate
   end subroutine report_conflict

   !> `SET <name>|NODE <id> FORCE fx fy fz [CURVE c]` or `SURF <name> PRESSURE p [CURVE c]
   !> [FOLLOWER]`.
   subroutine read_neumann(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(nodal_force_t) :: force
      type(pressure_load_t) :: pressure
      integer, allocatable :: nodes(:)
      character(len=:), allocatable :: name
      integer :: i, k, e, position, curve
      real(dp) :: values(3)
      integer :: start
      logical :: ok, line_ok
      allocate (model%nodal_forces(0), model%pressures(0))
      i = 0
      do while (reader%next_line(s_neumann, i, position, ok))
         associate (line => reader%lines(i))
            if (line%keyword(1) == 'SURF') then
               position = 2
               call reader%take_word(line, position, 'a surface name', name, ok)
               if (ok) then
                  pressure%surface = model%mesh%find_surface(name)
                  if (pressure%surface == 0) then
                     ok = .false.
                     if (.not. reader%mesh_failed) call reader%report(line, 2, 'unknown surface')
                  end if
               end if
               call reader%expect_keyword(line, position, 'PRESSURE', ok)
               call reader%take_real(line, position, 'a pressure', pressure%value, ok)
               pressure%curve = 0
               pressure%follower = .false.
               line_ok = ok
               if (.not. ok) position = resume_position(line, position, pressure_keywords)
               do while (position <= line%n_tokens())
                  start = position
                  ok = .true.
                  select case (line%keyword(position))
                  case ('CURVE')
                     position = position + 1
                     call reader%take_curve(line, position, pressure%curve, ok)
                  case ('FOLLOWER')
                     position = position + 1
                     pressure%follower = .true.
                  case default
                     call reader%report(line, position, 'unknown keyword (expected CURVE or FOLLOWER)')
                     ok = .false.
                  end select
                  call after_keyword(line, start, pressure_keywords, position, ok, line_ok)
               end do
               ok = line_ok
               if (.not. ok) cycle
               model%pressures = [model%pressures, pressure]
               associate (surface => model%mesh%surfaces(pressure%surface))
                  do k = 1, size(surface%elements)
                     e = surface%elements(k)
                     call mark_nodes(reader, model%mesh%face_nodes(e, surface%faces(k)), i)
                  end do
               end associate
               cycle
            end if
            call reader%take_node_target(model, line, position, nodes, ok)
            call reader%expect_keyword(line, position, 'FORCE', ok)
            call reader%take_reals(line, position, 'a force component', values, ok)
            curve = 0
            if (ok .and. position <= line%n_tokens()) then
               call reader%expect_keyword(line, position, 'CURVE', ok)
               call reader%take_curve(line, position, curve, ok)
            end if
            call reader%expect_end(line, position, ok)
            if (.not. ok) cycle
            do k = 1, 3
               if (values(k) == 0.0_dp) cycle
               force%nodes = nodes
               force%component = k
               force%value = values(k)
               force%curve = curve
               model%nodal_forces = [model%nodal_forces, force]
            end do
            call mark_nodes(reader, nodes, i)
         end associate
      end do
   end subroutine read_neumann

   !> `SET <element set>|ALL GRAVITY gx gy gz [CURVE c]`.
   subroutine read_body_forces(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(body_force_t) :: body_force
      character(len=:), allocatable :: name
      integer :: i, k, position, set
      logical :: ok
      allocate (model%body_forces(0))
      i = 0
      do while (reader%next_line(s_body_force, i, position, ok))
         associate (line => reader%lines(i))
            select case (line%keyword(1))
            case ('ALL')
               position = 2
               body_force%elements = [(k, k=1, model%mesh%n_elements)]
            case ('SET')
               position = 2
               call reader%take_word(line, position, 'an element set name', name, ok)
               if (ok) then
                  set = model%mesh%find_element_set(name)
                  if (set == 0) then
                     ok = .false.
                     if (.not. reader%mesh_failed) call reader%report(line, 2, 'unknown element set')
                  else
                     body_force%elements = model%mesh%element_sets(set)%elements
                  end if
               end if
            case default
               call reader%report(line, 1, 'expected SET <element set> or ALL')
               ok = .false.
            end select
            call reader%expect_keyword(line, position, 'GRAVITY', ok)
            call reader%take_reals(line, position, 'a gravity component', body_force%gravity, ok)
            body_force%curve = 0
            if (ok .and. position <= line%n_tokens()) then
               call reader%expect_keyword(line, position, 'CURVE', ok)
               call reader%take_curve(line, position, body_force%curve, ok)
            end if
            call reader%expect_end(line, position, ok)
            if (ok) model%body_forces = [model%body_forces, body_force]
         end associate
      end do
   end subroutine read_body_forces
end module frix_deck_loads
