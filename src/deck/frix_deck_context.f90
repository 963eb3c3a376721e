!> The state of one deck reading shared by the section readers (frix_deck_*): the deck's lines
!> and sections, the diagnostics, where each node and element came from, and the token helpers.
!> Each token helper reports its own mistake; `ok` false skips the rest of a line, except on
!> keyword/value lines, whose readers go on at the next keyword (`resume_position`) so that
!> every mistake of such a line is reported.
module frix_deck_context
   use frix_kinds, only: dp
   use frix_strings, only: to_string, to_upper
   use frix_property_list, only: property_list_t, property_spec_t
   use frix_id_map, only: id_map_t
   use frix_element, only: kinematics_linear, kinematics_total_lagrangian
   use frix_model, only: model_t
   use frix_mesh, only: mesh_t
   use frix_deck_tokens, only: deck_line_t, parse_real, parse_integer
   use frix_deck_diagnostics, only: deck_diagnostics_t
   implicit none
   private

   public :: deck_reader_t, property_t, deck_section_names, box_tolerance, read_keyword_pairs, keyword_pair_t
   public :: require, resume_position, after_keyword, read_node_dof, read_dof, mark_nodes, extend_origins, extend_properties, &
             one_line, line_integer
   public :: s_problem, s_static, s_curves, s_materials, s_mesh_file, s_node_coords, s_elements, &
             s_mesh_block, s_node_sets, s_surfaces, s_dirichlet, s_neumann, s_body_force, s_steps, &
             s_results, s_contact, s_couplings, s_end, s_initial_stress

   integer, parameter :: name_length = 20
   !> Known sections (the order of reading is read_deck's, frix_deck_reader).
   character(len=name_length), parameter :: deck_section_names(19) = [character(len=name_length) :: &
      'PROBLEM TYP', 'STATIC', 'LOAD CURVES', 'MATERIALS', 'MESH FILE', 'NODE COORDS', &
      'STRUCTURE ELEMENTS', 'MESH BLOCK', 'NODE SETS', 'SURFACES', 'DIRICHLET CONDITIONS', &
      'NEUMANN CONDITIONS', 'BODY FORCE', 'STEPS', 'RESULTS', 'CONTACT CONDITIONS', 'COUPLINGS', 'END', &
      'INITIAL STRESS']
   integer, parameter :: s_problem = 1, s_static = 2, s_curves = 3, s_materials = 4, &
                         s_mesh_file = 5, s_node_coords = 6, s_elements = 7, s_mesh_block = 8, &
                         s_node_sets = 9, s_surfaces = 10, s_dirichlet = 11, s_neumann = 12, &
                         s_body_force = 13, s_steps = 14, s_results = 15, s_contact = 16, s_couplings = 17, &
                         s_end = 18, s_initial_stress = 19

   !> Relative tolerance of BOX selections, times the diagonal of the model's bounding box.
   real(dp), parameter :: box_tolerance = 1.0e-9_dp

   !> One element formulation + material combination (becomes an element block).
   type :: property_t
      character(len=:), allocatable :: shape        !! registry shape keyword, upper case
      type(property_list_t) :: options              !! the shape's options as given
      character(len=:), allocatable :: formulation  !! the formulation's name, '' if invalid
      integer :: kinematics = kinematics_linear
      integer :: material = 0                  !! index into model%materials
      integer :: line = 0                      !! first deck line using it
      integer :: token = 1                     !! its shape token
   end type property_t

   type :: deck_reader_t
      type(deck_line_t), allocatable :: lines(:)
      integer :: n_lines = 0
      type(deck_diagnostics_t) :: diagnostics
      character(len=:), allocatable :: directory  !! deck's directory, '' or ending in '/'
      integer :: header(size(deck_section_names)) = 0  !! section line of each known section
      integer :: first(size(deck_section_names)) = 1   !! its first content line
      integer :: last(size(deck_section_names)) = 0    !! its last content line
      logical :: mesh_failed = .false.       !! a node/element/block/mesh file was rejected: no cascades
      integer, allocatable :: node_line(:)   !! deck line that defined each node
      integer, allocatable :: node_token(:)
      integer, allocatable :: element_line(:)
      integer, allocatable :: element_token(:)
      integer, allocatable :: element_property(:)   !! index into properties, 0: none yet
      integer, allocatable :: node_condition_line(:)  !! first condition/load on a node, 0: none
      type(property_t), allocatable :: properties(:)
      integer :: n_properties = 0
      integer, allocatable :: curve_ids(:)
      !> Ids of curves and materials whose definition was rejected: references to them are
      !> not reported again (no cascades of one mistake).
      integer, allocatable :: failed_curve_ids(:), failed_material_ids(:)
      logical :: property_failed = .false.   !! a SET line of STRUCTURE ELEMENTS was rejected
      integer :: step_lines = 0              !! non-blank lines of the STEPS section
      type(id_map_t) :: node_map
      type(id_map_t) :: element_map
      real(dp) :: model_size = 1.0_dp
   contains
      procedure :: report => report_token
      procedure :: next_line
      procedure :: expect_end
      procedure :: take_integer
      procedure :: take_real
      procedure :: take_number
      procedure :: take_property
      procedure :: take_reals
      procedure :: take_word
      procedure :: expect_keyword
      procedure :: take_curve
      procedure :: take_kinematics
      procedure :: take_yes_no
      procedure :: take_choice
      procedure :: take_node_target
      procedure :: take_element_target
      procedure :: require_hex8_faces
   end type deck_reader_t

   !> One pair of a keyword/value section as its pair reader gets it: the deck line, the pair's
   !> keyword (upper case, one of the section's keywords) and the token after it. The pair
   !> reader reads the value(s) from `position` on and sets `ok` false after a report.
   type :: keyword_pair_t
      type(deck_line_t) :: line
      character(len=:), allocatable :: keyword
      integer :: position = 1
      logical :: ok = .true.
   end type keyword_pair_t

   abstract interface
      !> Read the value(s) of one keyword/value pair.
      subroutine pair_reader_interface(reader, model, pair)
         import :: deck_reader_t, model_t, keyword_pair_t
         type(deck_reader_t), intent(inout) :: reader
         type(model_t), intent(inout) :: model
         type(keyword_pair_t), intent(inout) :: pair
      end subroutine pair_reader_interface
   end interface

contains

   !> A section of keyword/value pairs in free order (PROBLEM TYP, STATIC, RESULTS), each pair
   !> read by `read_pair`; `keywords` (upper case) are the section's. After a mistake the line
   !> is read on from its next keyword, so that every mistake of the line is reported.
   subroutine read_keyword_pairs(reader, model, section, keywords, read_pair)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      integer, intent(in) :: section
      character(len=*), intent(in) :: keywords(:)
      procedure(pair_reader_interface) :: read_pair
      type(keyword_pair_t) :: pair
      integer :: i, start
      i = 0
      do while (reader%next_line(section, i, pair%position, pair%ok))
         pair%line = reader%lines(i)
         do while (pair%position <= pair%line%n_tokens())
            start = pair%position
            pair%keyword = pair%line%keyword(start)
            pair%position = start + 1
            pair%ok = .true.
            if (any(keywords == pair%keyword)) then
               call read_pair(reader, model, pair)
            else
               call reader%report(pair%line, start, 'unknown keyword in section '// &
                                  trim(deck_section_names(section)))
               pair%ok = .false.
            end if
            if (.not. pair%ok) pair%position = resume_position(pair%line, max(pair%position, start + 1), keywords)
         end do
      end do
   end subroutine read_keyword_pairs

   !> The next line of `section` after line `i` that has a token (i = 0: the section's first),
   !> to be read from its first token: `position` 1 and `ok`; .false. when the section has no
   !> more. The loop over a section's lines:
   !>    i = 0
   !>    do while (reader%next_line(section, i, position, ok))
   logical function next_line(self, section, i, position, ok) result(found)
      class(deck_reader_t), intent(in) :: self
      integer, intent(in) :: section
      integer, intent(inout) :: i   !! index into self%lines
      integer, intent(out) :: position
      logical, intent(out) :: ok
      position = 1
      ok = .true.
      found = .false.
      i = max(i, self%first(section) - 1)
      do while (.not. found .and. i < self%last(section))
         i = i + 1
         found = self%lines(i)%n_tokens() > 0
      end do
   end function next_line

   !> Report `message` (default: unexpected text) at token `position` if the line goes on
   !> there (only if still `ok`).
   subroutine expect_end(self, line, position, ok, message)
      class(deck_reader_t), intent(inout) :: self
      type(deck_line_t), intent(in) :: line
      integer, intent(in) :: position
      logical, intent(inout) :: ok
      character(len=*), intent(in), optional :: message
      if (.not. ok .or. position > line%n_tokens()) return
      ok = .false.
      if (present(message)) then
         call self%report(line, position, message)
      else
         call self%report(line, position, 'unexpected text')
      end if
   end subroutine expect_end

   subroutine report_token(self, line, position, what, note)
      class(deck_reader_t), intent(inout) :: self
      type(deck_line_t), intent(in) :: line
      integer, intent(in) :: position
      character(len=*), intent(in) :: what
      character(len=*), intent(in), optional :: note
      if (position > line%n_tokens()) then
         call self%diagnostics%at_end_of_line(line, what)
      else
         call self%diagnostics%at_token(line, position, what, note)
      end if
   end subroutine report_token

   !> Integer at token `position` (then advanced) for `what`.
   subroutine take_integer(self, line, position, what, value, ok)
      class(deck_reader_t), intent(inout) :: self
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      character(len=*), intent(in) :: what
      integer, intent(out) :: value
      logical, intent(inout) :: ok
      real(dp) :: number
      call self%take_number(line, position, what, .true., number, ok)
      value = nint(number)
   end subroutine take_integer

   subroutine take_real(self, line, position, what, value, ok)
      class(deck_reader_t), intent(inout) :: self
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      character(len=*), intent(in) :: what
      real(dp), intent(out) :: value
      logical, intent(inout) :: ok
      call self%take_number(line, position, what, .false., value, ok)
   end subroutine take_real

   !> A number at token `position` (then advanced) for `what`: an integer if `whole` (exact
   !> in a real: |n| <= 2147483647), else a real; 0 when not read.
   subroutine take_number(self, line, position, what, whole, value, ok)
      class(deck_reader_t), intent(inout) :: self
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      character(len=*), intent(in) :: what
      logical, intent(in) :: whole
      real(dp), intent(out) :: value
      logical, intent(inout) :: ok
      character(len=:), allocatable :: word, message
      integer :: integer_value
      value = 0.0_dp
      call self%take_word(line, position, what, word, ok)
      if (.not. ok) return
      if (whole) then
         call parse_integer(word, integer_value, ok, message)
         if (ok) value = real(integer_value, dp)
      else
         call parse_real(word, value, ok, message)
      end if
      if (.not. ok) then
         value = 0.0_dp
         call self%report(line, position - 1, message//' for '//what)
      end if
   end subroutine take_number

   !> The value of the registered property `spec` at token `position`, checked against the
   !> spec's bound and added to `list`; a property given twice on the line is reported.
   subroutine take_property(self, line, position, spec, list, ok)
      class(deck_reader_t), intent(inout) :: self
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      type(property_spec_t), intent(in) :: spec
      type(property_list_t), intent(inout) :: list
      logical, intent(inout) :: ok
      real(dp) :: value
      if (ok .and. list%count() > 0) then
         if (any(list%names == spec%name)) then
            call self%report(line, position - 1, trim(spec%name)//' given twice on this line')
            ok = .false.
         end if
      end if
      call self%take_number(line, position, trim(spec%what), spec%whole, value, ok)
      call require(self, ok, spec%admits(value), line, position - 1, trim(spec%bound_message))
      if (ok) call list%set(spec%name, value)
   end subroutine take_property

   subroutine take_reals(self, line, position, what, values, ok)
      class(deck_reader_t), intent(inout) :: self
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      character(len=*), intent(in) :: what
      real(dp), intent(out) :: values(:)
      logical, intent(inout) :: ok
      integer :: i
      do i = 1, size(values)
         call self%take_real(line, position, what, values(i), ok)
      end do
   end subroutine take_reals

   !> A name or keyword value (any text).
   subroutine take_word(self, line, position, what, word, ok)
      class(deck_reader_t), intent(inout) :: self
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      character(len=*), intent(in) :: what
      character(len=:), allocatable, intent(out) :: word
      logical, intent(inout) :: ok
      word = ''
      if (.not. ok) return
      if (position > line%n_tokens()) then
         call self%report(line, position, 'missing '//what)
         ok = .false.
         return
      end if
      word = line%token(position)
      position = position + 1
   end subroutine take_word

   subroutine expect_keyword(self, line, position, keyword, ok)
      class(deck_reader_t), intent(inout) :: self
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      character(len=*), intent(in) :: keyword
      logical, intent(inout) :: ok
      if (.not. ok) return
      if (position > line%n_tokens()) then
         call self%report(line, position, 'missing keyword '//keyword)
         ok = .false.
      else if (line%keyword(position) /= keyword) then
         call self%report(line, position, 'expected keyword '//keyword)
         ok = .false.
      end if
      position = position + 1
   end subroutine expect_keyword

   !> A curve id (0: default ramp) -> index into model%curves.
   subroutine take_curve(self, line, position, curve, ok)
      class(deck_reader_t), intent(inout) :: self
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      integer, intent(out) :: curve
      logical, intent(inout) :: ok
      integer :: id, k
      curve = 0
      call self%take_integer(line, position, 'a curve id', id, ok)
      if (.not. ok .or. id == 0) return
      if (allocated(self%curve_ids)) then
         do k = 1, size(self%curve_ids)
            if (self%curve_ids(k) == id) curve = k
         end do
      end if
      if (curve == 0) then
         ok = .false.
         if (.not. any(self%failed_curve_ids == id)) &
            call self%report(line, position - 1, 'undefined load curve '//to_string(id))
      end if
   end subroutine take_curve

   subroutine take_kinematics(self, line, position, kinematics, ok)
      class(deck_reader_t), intent(inout) :: self
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      integer, intent(out) :: kinematics
      logical, intent(inout) :: ok
      character(len=:), allocatable :: word
      kinematics = kinematics_linear
      call self%take_word(line, position, 'KINTYP value', word, ok)
      if (.not. ok) return
      select case (to_upper(word))
      case ('GEO_LIN')
         kinematics = kinematics_linear
      case ('TOT_LAGR')
         kinematics = kinematics_total_lagrangian
      case default
         call self%report(line, position - 1, 'unknown kinematics (expected Geo_Lin or Tot_Lagr)')
         ok = .false.
      end select
   end subroutine take_kinematics

   subroutine take_yes_no(self, line, position, what, value, ok)
      class(deck_reader_t), intent(inout) :: self
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      character(len=*), intent(in) :: what
      logical, intent(inout) :: value
      logical, intent(inout) :: ok
      integer :: choice
      call self%take_choice(line, position, what//' value', [character(len=3) :: 'YES', 'NO'], &
                            'expected Yes or No for '//what, choice, ok)
      if (ok) value = choice == 1
   end subroutine take_yes_no

   !> One word out of `choices` (upper case; the deck's word in any case): its index, or the
   !> report `message` at the word.
   subroutine take_choice(self, line, position, what, choices, message, choice, ok)
      class(deck_reader_t), intent(inout) :: self
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      character(len=*), intent(in) :: what, choices(:), message
      integer, intent(out) :: choice
      logical, intent(inout) :: ok
      character(len=:), allocatable :: word
      choice = 0
      call self%take_word(line, position, what, word, ok)
      if (.not. ok) return
      choice = findloc(choices, to_upper(word), dim=1)
      if (choice == 0) then
         call self%report(line, position - 1, message)
         ok = .false.
      end if
   end subroutine take_choice

   !> `SET <node set>` or `NODE <id>` -> internal node numbers.
   subroutine take_node_target(self, model, line, position, nodes, ok)
      class(deck_reader_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      integer, allocatable, intent(out) :: nodes(:)
      logical, intent(inout) :: ok
      character(len=:), allocatable :: name
      integer :: id, k
      allocate (nodes(0))
      if (.not. ok) return
      if (position > line%n_tokens()) then
         call self%report(line, position, 'missing SET <name> or NODE <id>')
         ok = .false.
         return
      end if
      select case (line%keyword(position))
      case ('SET')
         position = position + 1
         call self%take_word(line, position, 'a node set name', name, ok)
         if (.not. ok) return
         k = model%mesh%find_node_set(name)
         if (k == 0) then
            ok = .false.
            if (.not. self%mesh_failed) call self%report(line, position - 1, 'unknown node set')
            return
         end if
         nodes = model%mesh%node_sets(k)%nodes
      case ('NODE')
         position = position + 1
         call self%take_integer(line, position, 'a node id', id, ok)
         if (.not. ok) return
         k = self%node_map%lookup(id)
         if (k == 0) then
            ok = .false.
            if (.not. self%mesh_failed) call self%report(line, position - 1, 'undefined node '//to_string(id))
            return
         end if
         nodes = [k]
      case default
         call self%report(line, position, 'expected SET <name> or NODE <id>')
         ok = .false.
      end select
   end subroutine take_node_target

   !> `SET <element set>` or `ALL` at the line's first token -> internal element numbers.
   subroutine take_element_target(self, model, line, position, elements, ok)
      class(deck_reader_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      integer, allocatable, intent(out) :: elements(:)
      logical, intent(inout) :: ok
      character(len=:), allocatable :: name
      integer :: k, set
      allocate (elements(0))
      select case (line%keyword(1))
      case ('ALL')
         position = 2
         elements = [(k, k=1, model%mesh%n_elements)]
      case ('SET')
         position = 2
         call self%take_word(line, position, 'an element set name', name, ok)
         if (.not. ok) return
         set = model%mesh%find_element_set(name)
         if (set == 0) then
            ok = .false.
            if (.not. self%mesh_failed) call self%report(line, 2, 'unknown element set')
         else
            elements = model%mesh%element_sets(set)%elements
         end if
      case default
         call self%report(line, 1, 'expected SET <element set> or ALL')
         ok = .false.
      end select
   end subroutine take_element_target

   !> Mark nodes as carrying a condition or load (for the orphan-node check).
   subroutine mark_nodes(reader, nodes, line)
      type(deck_reader_t), intent(inout) :: reader
      integer, intent(in) :: nodes(:)
      integer, intent(in) :: line
      integer :: k
      do k = 1, size(nodes)
         if (reader%node_condition_line(nodes(k)) == 0) reader%node_condition_line(nodes(k)) = line
      end do
   end subroutine mark_nodes

   !> `NODE <id> DOF <1-3>` or `SET <name> DOF <1-3>` (a node set of one node, as a gmsh
   !> physical point gives): the internal node number and the component.
   subroutine read_node_dof(reader, model, line, position, node, component, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      integer, intent(out) :: node, component
      logical, intent(inout) :: ok
      integer :: id, set
      character(len=:), allocatable :: name
      node = 0
      component = 0
      if (ok .and. position <= line%n_tokens()) then
         if (line%keyword(position) == 'SET') then
            position = position + 1
            call reader%take_word(line, position, 'a node set name', name, ok)
            if (ok) then
               set = model%mesh%find_node_set(name)
               if (set == 0) then
                  ok = .false.
                  if (.not. reader%mesh_failed) call reader%report(line, position - 1, 'unknown node set')
               else if (size(model%mesh%node_sets(set)%nodes) /= 1) then
                  ok = .false.
                  call reader%report(line, position - 1, 'this node set has '// &
                                     to_string(size(model%mesh%node_sets(set)%nodes))//' nodes, not one')
               else
                  node = model%mesh%node_sets(set)%nodes(1)
               end if
            end if
            call read_dof(reader, line, position, component, ok)
            return
         end if
      end if
      call reader%expect_keyword(line, position, 'NODE', ok)
      call reader%take_integer(line, position, 'a node id', id, ok)
      if (ok) then
         node = reader%node_map%lookup(id)
         if (node == 0) then
            ok = .false.
            if (.not. reader%mesh_failed) call reader%report(line, position - 1, 'undefined node '//to_string(id))
         end if
      end if
      call read_dof(reader, line, position, component, ok)
   end subroutine read_node_dof

   !> `DOF <1-3>`.
   subroutine read_dof(reader, line, position, component, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      integer, intent(out) :: component
      logical, intent(inout) :: ok
      component = 0
      call reader%expect_keyword(line, position, 'DOF', ok)
      call reader%take_integer(line, position, 'a DOF index', component, ok)
      call require(reader, ok, component >= 1 .and. component <= 3, line, position - 1, &
                   'DOF index out of range 1..3')
   end subroutine read_dof

   !> Where a keyword/value line is read on after a mistake in what one keyword began: the first
   !> token from `position` on that is one of `keywords` (upper case), past the line's end if
   !> none is. The tokens between (the rest of a bad value, an unknown keyword's value) are
   !> skipped unread, so that no mistake is reported twice.
   pure integer function resume_position(line, position, keywords) result(resume)
      type(deck_line_t), intent(in) :: line
      integer, intent(in) :: position
      character(len=*), intent(in) :: keywords(:)
      resume = position
      do while (resume <= line%n_tokens())
         if (any(keywords == line%keyword(resume))) return
         resume = resume + 1
      end do
   end function resume_position

   !> After the keyword that began at token `start` of a keyword/value line was read: on a
   !> mistake (`ok` false) the line is rejected (`line_ok` false) and `position` moves to the
   !> line's next keyword (resume_position, at least one token on).
   pure subroutine after_keyword(line, start, keywords, position, ok, line_ok)
      type(deck_line_t), intent(in) :: line
      integer, intent(in) :: start
      character(len=*), intent(in) :: keywords(:)
      integer, intent(inout) :: position
      logical, intent(in) :: ok
      logical, intent(inout) :: line_ok
      if (ok) return
      line_ok = .false.
      position = resume_position(line, max(position, start + 1), keywords)
   end subroutine after_keyword

   !> Report `message` at token `position` unless `condition` holds (only if still `ok`).
   subroutine require(reader, ok, condition, line, position, message)
      type(deck_reader_t), intent(inout) :: reader
      logical, intent(inout) :: ok
      logical, intent(in) :: condition
      type(deck_line_t), intent(in) :: line
      integer, intent(in) :: position
      character(len=*), intent(in) :: message
      if (.not. ok) return
      if (.not. condition) then
         call reader%report(line, position, message)
         ok = .false.
      end if
   end subroutine require

   !> Grow the origin arrays to `n` entries, the new ones pointing at (line, token).
   subroutine extend_origins(lines, tokens, n, line, token)
      integer, allocatable, intent(inout) :: lines(:), tokens(:)
      integer, intent(in) :: n, line, token
      integer :: n_old
      if (.not. allocated(lines)) allocate (lines(0), tokens(0))
      n_old = size(lines)
      if (n <= n_old) return
      lines = [lines, spread(line, 1, n - n_old)]
      tokens = [tokens, spread(token, 1, n - n_old)]
   end subroutine extend_origins

   !> Value of integer token `i` known to be valid.
   integer function line_integer(line, i) result(value)
      type(deck_line_t), intent(in) :: line
      integer, intent(in) :: i
      logical :: ok
      character(len=:), allocatable :: message
      call parse_integer(line%token(i), value, ok, message)
   end function line_integer

   subroutine extend_properties(reader, n)
      type(deck_reader_t), intent(inout) :: reader
      integer, intent(in) :: n
      if (.not. allocated(reader%element_property)) allocate (reader%element_property(0))
      if (size(reader%element_property) < n) &
         reader%element_property = [reader%element_property, spread(0, 1, n - size(reader%element_property))]
   end subroutine extend_properties

   !> Several message lines joined by "; ".
   pure function one_line(text) result(joined)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: joined
      integer :: i
      joined = text
      do
         i = index(joined, new_line('a'))
         if (i == 0) exit
         joined = joined(1:i - 1)//'; '//joined(i + 1:)
      end do
   end function one_line
   !> Report at (line, column), and set ok false, when surface `surface` holds a face of an
   !> element other than a HEX8: `what` (pressure, contact) integrates only over HEX8 faces so
   !> far (the edges of plane elements are taken by frix_deck_contact before). The message
   !> names the cell and the first such element.
   subroutine require_hex8_faces(self, line, column, mesh, surface, what, ok)
      class(deck_reader_t), intent(inout) :: self
      type(deck_line_t), intent(in) :: line
      integer, intent(in) :: column, surface
      type(mesh_t), intent(in) :: mesh
      character(len=*), intent(in) :: what
      logical, intent(inout) :: ok
      integer :: element
      element = mesh%first_non_hex8_element(surface)
      if (element == 0) return
      call self%report(line, column, what//' on '//mesh%cell_name(element)//' faces is not supported yet '// &
                       '(element '//to_string(mesh%element_ids(element))//' of surface "'// &
                       mesh%surfaces(surface)%name//'" is a '//mesh%cell_name(element)//')')
      ok = .false.
   end subroutine require_hex8_faces
end module frix_deck_context
