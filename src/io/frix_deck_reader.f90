!> The input deck reader: reads a CARAT-style deck (format: docs/deck-format.md) into a
!> model_t and validates it. Every mistake of the deck is collected - a bad line never stops
!> the reading of later lines, semantic checks run after reading - and returned as one
!> error_t with one `<deck>:<line>:<column>: error: <what> near "<token>"` entry per mistake
!> (see frix_deck_diagnostics).
!>
!> Sections are processed in a fixed order, whatever their order in the file, so that every
!> reference points backwards: controls, curves, materials; the mesh (MESH FILE, NODE COORDS,
!> element lines of STRUCTURE ELEMENTS, MESH BLOCK, then the SET lines of STRUCTURE ELEMENTS);
!> NODE SETS, SURFACES; conditions and loads; STEPS; RESULTS.
module frix_deck_reader
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string, to_upper
   use frix_mesh, only: mesh_t, node_set_t, surface_t, hex8_face_nodes
   use frix_id_map, only: id_map_t
   use frix_mesh_checks, only: check_hex8_jacobians, find_orphan_nodes, merge_meshes, &
                               mesh_bounding_box
   use frix_gmsh_reader, only: read_gmsh
   use frix_material, only: material_slot_t
   use frix_material_registry, only: create_material
   use frix_element, only: kinematics_linear, kinematics_total_lagrangian
   use frix_element_registry, only: create_element
   use frix_friction_law, only: friction_law_t
   use frix_friction_law_registry, only: create_friction_law
   use frix_contact_parameters, only: new_contact_parameters
   use frix_contact_kernel, only: max_ring_nodes
   use frix_contact_assembly, only: largest_patch_ring
   use frix_model, only: contact_pair_t, model_t, dirichlet_t, nodal_force_t, pressure_load_t, body_force_t, &
                         load_curve_t, step_t, history_request_t, solver_auto, solver_cholmod, &
                         solver_umfpack, curve_factor
   use frix_text_scanner, only: text_scanner_t, open_text_file
   use frix_deck_tokens, only: deck_line_t, split_line, parse_real, parse_integer, &
                               is_section_line, section_name
   use frix_deck_diagnostics, only: deck_diagnostics_t
   use frix_deck_lookup, only: sorted_order
   use frix_block_generator, only: generate_block
   implicit none
   private

   public :: read_deck, deck_section_names

   integer, parameter :: name_length = 20
   !> Known sections; their index is the processing order (see the module comment).
   character(len=name_length), parameter :: deck_section_names(17) = [character(len=name_length) :: &
      'PROBLEM TYP', 'STATIC', 'LOAD CURVES', 'MATERIALS', 'MESH FILE', 'NODE COORDS', &
      'STRUCTURE ELEMENTS', 'MESH BLOCK', 'NODE SETS', 'SURFACES', 'DIRICHLET CONDITIONS', &
      'NEUMANN CONDITIONS', 'BODY FORCE', 'STEPS', 'RESULTS', 'CONTACT CONDITIONS', 'END']
   integer, parameter :: s_problem = 1, s_static = 2, s_curves = 3, s_materials = 4, &
                         s_mesh_file = 5, s_node_coords = 6, s_elements = 7, s_mesh_block = 8, &
                         s_node_sets = 9, s_surfaces = 10, s_dirichlet = 11, s_neumann = 12, &
                         s_body_force = 13, s_steps = 14, s_results = 15, s_contact = 16, s_end = 17

   !> Relative tolerance of BOX selections, times the diagonal of the model's bounding box.
   real(dp), parameter :: box_tolerance = 1.0e-9_dp

   !> One element formulation + material combination (becomes an element block).
   type :: property_t
      character(len=:), allocatable :: shape   !! upper case, e.g. HEX8, HEXA8-E3
      integer :: n_eas = 0
      integer :: kinematics = kinematics_linear
      integer :: material = 0                  !! index into model%materials
      integer :: line = 0                      !! first deck line using it
      integer :: token = 1                     !! its shape token
   end type property_t

   type :: reader_t
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
      procedure :: take_integer
      procedure :: take_real
      procedure :: take_reals
      procedure :: take_word
      procedure :: expect_keyword
      procedure :: take_curve
      procedure :: take_kinematics
      procedure :: take_yes_no
      procedure :: take_choice
      procedure :: take_node_target
   end type reader_t

contains

   !> Read the deck at `path` into `model` and validate it; all mistakes are returned in
   !> `error` (one entry per mistake), which is unallocated for a valid deck.
   subroutine read_deck(path, model, error)
      character(len=*), intent(in) :: path
      type(model_t), intent(out) :: model
      type(error_t), allocatable, intent(out) :: error
      type(reader_t) :: reader
      integer :: slash

      model%deck_path = path
      reader%diagnostics%path = path
      slash = index(path, '/', back=.true.)
      reader%directory = path(1:slash)

      call load_lines(reader, path, error)
      if (allocated(error)) return
      call find_sections(reader, model)

      call read_pairs_section(reader, model, s_problem)
      call read_pairs_section(reader, model, s_static)
      call read_curves(reader, model)
      call read_materials(reader, model)
      call read_mesh_file(reader, model)
      call read_node_coords(reader, model)
      call read_element_lines(reader, model)
      call read_mesh_blocks(reader, model)
      call finish_mesh_numbering(reader, model)
      call read_element_set_lines(reader, model)
      call read_node_sets(reader, model)
      call read_surfaces(reader, model)
      call read_dirichlet(reader, model)
      call read_neumann(reader, model)
      call read_body_forces(reader, model)
      call read_contact_pairs(reader, model)
      call read_steps(reader, model)
      call read_pairs_section(reader, model, s_results)
      call validate_model(reader, model)

      call reader%diagnostics%finish(error)
   end subroutine read_deck

   ! ---- reading the file and finding the sections --------------------------------------------

   subroutine load_lines(reader, path, error)
      type(reader_t), intent(inout) :: reader
      character(len=*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      type(text_scanner_t) :: scanner
      integer :: i
      call open_text_file(path, scanner, error)
      if (allocated(error)) then
         error%message = path//': error: cannot read the deck: '//error%message
         return
      end if
      reader%n_lines = scanner%n_lines
      allocate (reader%lines(scanner%n_lines))
      do i = 1, scanner%n_lines
         if (.not. scanner%next_line()) exit
         reader%lines(i) = split_line(i, scanner%line())
      end do
   end subroutine load_lines

   !> Find the section lines; lines before the first one are the title.
   subroutine find_sections(reader, model)
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      integer :: i, k, current, first_section
      character(len=:), allocatable :: name
      current = 0
      first_section = 0
      model%title = ''
      do i = 1, reader%n_lines
         associate (line => reader%lines(i))
            if (.not. is_section_line(line%text)) then
               if (first_section == 0) then
                  if (len_trim(line%text) > 0) then
                     if (len(model%title) > 0) model%title = model%title//new_line('a')
                     model%title = model%title//trim(line%text)
                  end if
               else if (current > 0) then
                  reader%last(current) = i
               end if  ! content of an unknown or repeated section: reported at its section line
               cycle
            end if
            if (first_section == 0) first_section = i
            name = section_name(line%text)
            current = 0
            do k = 1, size(deck_section_names)
               if (name == trim(deck_section_names(k))) current = k
            end do
            if (current == 0) then
               call reader%diagnostics%at_line(line, max(index(line%text, '-', back=.true.) + 1, 1), &
                                               'unknown section "'//name//'"')
            else if (reader%header(current) /= 0) then
               call reader%diagnostics%at_line(line, index(line%text, '-', back=.true.) + 1, &
                                               'section '//name//' appears twice (first at line '// &
                                               to_string(reader%header(current))//')')
               current = 0
            else
               reader%header(current) = i
               reader%first(current) = i + 1
               reader%last(current) = i
               if (current == s_end) exit  ! the deck ends here
            end if
         end associate
      end do
      if (first_section == 0) then
         call reader%diagnostics%in_deck(max(reader%n_lines, 1), 1, &
                                         'no section line found (a section line starts with ------)')
      end if
   end subroutine find_sections

   ! ---- token helpers: each reports its own mistake; `ok` false skips the rest of a line -----

   subroutine report_token(self, line, position, what, note)
      class(reader_t), intent(inout) :: self
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
      class(reader_t), intent(inout) :: self
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      character(len=*), intent(in) :: what
      integer, intent(out) :: value
      logical, intent(inout) :: ok
      character(len=:), allocatable :: message
      value = 0
      if (.not. ok) return
      if (position > line%n_tokens()) then
         call self%report(line, position, 'missing '//what)
         ok = .false.
         return
      end if
      call parse_integer(line%token(position), value, ok, message)
      if (.not. ok) call self%report(line, position, message//' for '//what)
      position = position + 1
   end subroutine take_integer

   subroutine take_real(self, line, position, what, value, ok)
      class(reader_t), intent(inout) :: self
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      character(len=*), intent(in) :: what
      real(dp), intent(out) :: value
      logical, intent(inout) :: ok
      character(len=:), allocatable :: message
      value = 0.0_dp
      if (.not. ok) return
      if (position > line%n_tokens()) then
         call self%report(line, position, 'missing '//what)
         ok = .false.
         return
      end if
      call parse_real(line%token(position), value, ok, message)
      if (.not. ok) call self%report(line, position, message//' for '//what)
      position = position + 1
   end subroutine take_real

   subroutine take_reals(self, line, position, what, values, ok)
      class(reader_t), intent(inout) :: self
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
      class(reader_t), intent(inout) :: self
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
      class(reader_t), intent(inout) :: self
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
      class(reader_t), intent(inout) :: self
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
      class(reader_t), intent(inout) :: self
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
      class(reader_t), intent(inout) :: self
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
      class(reader_t), intent(inout) :: self
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
      class(reader_t), intent(inout) :: self
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

   !> Mark nodes as carrying a condition or load (for the orphan-node check).
   subroutine mark_nodes(reader, nodes, line)
      type(reader_t), intent(inout) :: reader
      integer, intent(in) :: nodes(:)
      integer, intent(in) :: line
      integer :: k
      do k = 1, size(nodes)
         if (reader%node_condition_line(nodes(k)) == 0) reader%node_condition_line(nodes(k)) = line
      end do
   end subroutine mark_nodes

   ! ---- PROBLEM TYP, STATIC, RESULTS: keyword/value pairs in free order ------------------

   subroutine read_pairs_section(reader, model, section)
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      integer, intent(in) :: section
      integer :: i, position, value
      logical :: ok
      real(dp) :: real_value
      character(len=:), allocatable :: word
      type(history_request_t) :: request

      if (section == s_results .and. .not. allocated(model%results%history)) &
         allocate (model%results%history(0))
      do i = reader%first(section), reader%last(section)
         associate (line => reader%lines(i))
            position = 1
            ok = .true.
            do while (ok .and. position <= line%n_tokens())
               select case (section_keyword(section, line%keyword(position)))
               case ('PROBLEMTYP')
                  position = position + 1
                  call reader%take_word(line, position, 'PROBLEMTYP value', word, ok)
                  if (ok .and. to_upper(word) /= 'STRUCTURE') then
                     call reader%report(line, position - 1, 'unknown problem type (expected Structure)')
                     ok = .false.
                  end if
               case ('KINTYP')
                  position = position + 1
                  call reader%take_kinematics(line, position, value, ok)
                  if (ok) model%controls%default_kinematics = value
               case ('MAXITER')
                  position = position + 1
                  call reader%take_integer(line, position, 'MAXITER', value, ok)
                  call require(reader, ok, value >= 1, line, position - 1, 'MAXITER must be at least 1')
                  if (ok) model%controls%max_iterations = value
               case ('MAXCUT')
                  position = position + 1
                  call reader%take_integer(line, position, 'MAXCUT', value, ok)
                  call require(reader, ok, value >= 0, line, position - 1, 'MAXCUT must not be negative')
                  if (ok) model%controls%max_cutbacks = value
               case ('TOLRESID')
                  position = position + 1
                  call reader%take_real(line, position, 'TOLRESID', real_value, ok)
                  call require(reader, ok, real_value > 0.0_dp, line, position - 1, 'TOLRESID must be positive')
                  if (ok) model%controls%tol_residual = real_value
               case ('TOLDISP')
                  position = position + 1
                  call reader%take_real(line, position, 'TOLDISP', real_value, ok)
                  call require(reader, ok, real_value > 0.0_dp, line, position - 1, 'TOLDISP must be positive')
                  if (ok) model%controls%tol_displacement = real_value
               case ('SOLVER')
                  position = position + 1
                  call reader%take_word(line, position, 'SOLVER value', word, ok)
                  if (.not. ok) exit
                  select case (to_upper(word))
                  case ('AUTO')
                     model%controls%linear_solver = solver_auto
                  case ('CHOLMOD')
                     model%controls%linear_solver = solver_cholmod
                  case ('UMFPACK')
                     model%controls%linear_solver = solver_umfpack
                  case default
                     call reader%report(line, position - 1, 'unknown solver (expected Auto, Cholmod or Umfpack)')
                     ok = .false.
                  end select
               case ('MU_CONTINUATION')
                  position = position + 1
                  call read_friction_continuation(reader, line, position, model%controls%friction_continuation, ok)
               case ('NEWTONRAPHSO')
                  position = position + 1
                  call reader%take_word(line, position, 'NEWTONRAPHSO value', word, ok)
                  if (ok .and. to_upper(word) /= 'LOAD_CONTROL' .and. to_upper(word) /= 'DISPLACEMENT_CONTROL') then
                     call reader%report(line, position - 1, &
                                        'unknown NEWTONRAPHSO (expected Load_Control or Displacement_Control)')
                     ok = .false.
                  end if
               case ('VTK')
                  position = position + 1
                  call reader%take_yes_no(line, position, 'VTK', model%results%vtk, ok)
               case ('LISTING')
                  position = position + 1
                  call reader%take_yes_no(line, position, 'LISTING', model%results%listing, ok)
               case ('POS3D')
                  position = position + 1
                  call reader%take_yes_no(line, position, 'POS3D', model%results%pos3d, ok)
               case ('HDF5')
                  position = position + 1
                  call reader%take_yes_no(line, position, 'HDF5', model%results%hdf5, ok)
               case ('EVERY')
                  position = position + 1
                  call reader%take_integer(line, position, 'EVERY', value, ok)
                  call require(reader, ok, value >= 1, line, position - 1, 'EVERY must be at least 1')
                  if (ok) model%results%every = value
               case ('HISTORY')
                  position = position + 1
                  call read_history(reader, line, position, request, ok)
                  if (ok) model%results%history = [model%results%history, request]
               case default
                  call reader%report(line, position, 'unknown keyword in section '// &
                                     trim(deck_section_names(section)))
                  ok = .false.
               end select
            end do
         end associate
      end do
   end subroutine read_pairs_section

   !> The keyword if it belongs to `section`, else ''.
   pure function section_keyword(section, keyword) result(accepted)
      integer, intent(in) :: section
      character(len=*), intent(in) :: keyword
      character(len=:), allocatable :: accepted
      accepted = ''
      select case (section)
      case (s_problem)
         if (keyword == 'PROBLEMTYP') accepted = keyword
      case (s_static)
         select case (keyword)
         case ('KINTYP', 'MAXITER', 'MAXCUT', 'TOLRESID', 'TOLDISP', 'SOLVER', 'NEWTONRAPHSO', 'MU_CONTINUATION')
            accepted = keyword
         end select
      case (s_results)
         select case (keyword)
         case ('VTK', 'LISTING', 'POS3D', 'HDF5', 'EVERY', 'HISTORY')
            accepted = keyword
         end select
      end select
   end function section_keyword

   !> `MU_CONTINUATION f_1 f_2 ... f_m` (after the keyword): the friction scale factors of the
   !> continuation stages, each greater than 1 and smaller than the one before (the final
   !> stage, factor 1, is implied); the list ends at the line's end or at the next token that
   !> is not a number.
   subroutine read_friction_continuation(reader, line, position, factors, ok)
      type(reader_t), intent(inout) :: reader
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

   !> `HISTORY NODE <id> DOF <1-3> [KIND U|R]` (after HISTORY).
   subroutine read_history(reader, line, position, request, ok)
      type(reader_t), intent(inout) :: reader
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      type(history_request_t), intent(out) :: request
      logical, intent(inout) :: ok
      character(len=:), allocatable :: word
      call read_node_dof(reader, line, position, request%node, request%component, ok)
      if (.not. ok) return
      if (position <= line%n_tokens()) then
         if (line%keyword(position) == 'KIND') then
            position = position + 1
            call reader%take_word(line, position, 'KIND value', word, ok)
            if (.not. ok) return
            select case (to_upper(word))
            case ('U', 'R')
               request%kind = to_upper(word)
            case default
               call reader%report(line, position - 1, 'unknown KIND (expected U or R)')
               ok = .false.
            end select
         end if
      end if
   end subroutine read_history

   !> `NODE <id> DOF <1-3>`: the internal node number and the component.
   subroutine read_node_dof(reader, line, position, node, component, ok)
      type(reader_t), intent(inout) :: reader
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      integer, intent(out) :: node, component
      logical, intent(inout) :: ok
      integer :: id
      node = 0
      component = 0
      call reader%expect_keyword(line, position, 'NODE', ok)
      call reader%take_integer(line, position, 'a node id', id, ok)
      if (ok) then
         node = reader%node_map%lookup(id)
         if (node == 0) then
            ok = .false.
            if (.not. reader%mesh_failed) call reader%report(line, position - 1, 'undefined node '//to_string(id))
         end if
      end if
      call reader%expect_keyword(line, position, 'DOF', ok)
      call reader%take_integer(line, position, 'a DOF index', component, ok)
      call require(reader, ok, component >= 1 .and. component <= 3, line, position - 1, &
                   'DOF index out of range 1..3')
   end subroutine read_node_dof

   !> Report `message` at token `position` unless `condition` holds (only if still `ok`).
   subroutine require(reader, ok, condition, line, position, message)
      type(reader_t), intent(inout) :: reader
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

   ! ---- LOAD CURVES ----------------------------------------------------------------------

   !> `CURVE <id> POINTS t1 f1 t2 f2 ...`: at least two points, times strictly increasing.
   subroutine read_curves(reader, model)
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(load_curve_t), allocatable :: curves(:)
      type(load_curve_t) :: curve
      integer :: i, k, position, n_curves, n_points, id_position
      logical :: ok
      n_curves = 0
      allocate (curves(max(reader%last(s_curves) - reader%first(s_curves) + 1, 0)))
      allocate (reader%curve_ids(0), reader%failed_curve_ids(0))
      do i = reader%first(s_curves), reader%last(s_curves)
         associate (line => reader%lines(i))
            if (line%n_tokens() == 0) cycle
            position = 1
            ok = .true.
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

   ! ---- MATERIALS ------------------------------------------------------------------------

   !> `MAT <id> <law> <PROPERTY> <value> ...` -> create_material.
   subroutine read_materials(reader, model)
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(material_slot_t), allocatable :: materials(:)
      integer, allocatable :: ids(:)
      character(len=16), allocatable :: names(:)
      real(dp), allocatable :: values(:)
      character(len=:), allocatable :: law, name
      type(error_t), allocatable :: error
      integer :: i, k, position, id, n_materials, n_properties, law_position
      logical :: ok
      n_materials = 0
      allocate (materials(max(reader%last(s_materials) - reader%first(s_materials) + 1, 0)))
      allocate (ids(size(materials)), reader%failed_material_ids(0))
      do i = reader%first(s_materials), reader%last(s_materials)
         associate (line => reader%lines(i))
            if (line%n_tokens() == 0) cycle
            position = 1
            ok = .true.
            id = 0
            call reader%expect_keyword(line, position, 'MAT', ok)
            call reader%take_integer(line, position, 'a material id', id, ok)
            call require(reader, ok, id >= 1, line, position - 1, 'material id must be positive')
            if (ok) then
               if (any(ids(1:n_materials) == id)) then
                  call reader%report(line, position - 1, 'duplicate material id '//to_string(id))
                  ok = .false.
               end if
            end if
            law_position = position
            call reader%take_word(line, position, 'a material law', law, ok)
            if (.not. ok) then
               if (id > 0) reader%failed_material_ids = [reader%failed_material_ids, id]
               cycle
            end if
            n_properties = (line%n_tokens() - position + 1 + 1)/2
            allocate (names(n_properties), values(n_properties))
            do k = 1, n_properties
               call reader%take_word(line, position, 'a property name', name, ok)
               names(k) = to_upper(name)
               call reader%take_real(line, position, 'property '//name, values(k), ok)
            end do
            if (ok) then
               call create_material(law, names, values, materials(n_materials + 1)%law, error)
               if (allocated(error)) then
                  call reader%report(line, law_position, 'invalid material: '//one_line(error%message))
                  deallocate (error)
                  reader%failed_material_ids = [reader%failed_material_ids, id]
               else
                  n_materials = n_materials + 1
                  ids(n_materials) = id
               end if
            else
               reader%failed_material_ids = [reader%failed_material_ids, id]
            end if
            deallocate (names, values)
         end associate
      end do
      allocate (model%materials(n_materials))
      do k = 1, n_materials
         call move_alloc(materials(k)%law, model%materials(k)%law)
      end do
      model%material_ids = ids(1:n_materials)
   end subroutine read_materials

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

   ! ---- the mesh -------------------------------------------------------------------------

   !> `FILE <path>` (relative to the deck's directory): a gmsh mesh, the base of the mesh.
   subroutine read_mesh_file(reader, model)
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      integer :: i, position, n_files
      logical :: ok
      character(len=:), allocatable :: file, full_path
      type(error_t), allocatable :: error
      n_files = 0
      do i = reader%first(s_mesh_file), reader%last(s_mesh_file)
         associate (line => reader%lines(i))
            if (line%n_tokens() == 0) cycle
            position = 1
            ok = .true.
            call reader%expect_keyword(line, position, 'FILE', ok)
            call reader%take_word(line, position, 'a mesh file name', file, ok)
            if (ok .and. position <= line%n_tokens()) then
               call reader%report(line, position, 'unexpected text after the file name')
               ok = .false.
            end if
            if (.not. ok) cycle
            n_files = n_files + 1
            if (n_files > 1) then
               call reader%report(line, 2, 'only one mesh FILE is allowed')
               cycle
            end if
            full_path = file
            if (file(1:1) /= '/') full_path = reader%directory//file
            call read_gmsh(full_path, model%mesh, error)
            if (allocated(error)) then
               call reader%report(line, 2, 'cannot read mesh file', note=error%message)
               reader%mesh_failed = .true.
               call empty_mesh(model%mesh)
               cycle
            end if
            call extend_origins(reader%node_line, reader%node_token, model%mesh%n_nodes, i, 2)
            call extend_origins(reader%element_line, reader%element_token, model%mesh%n_elements, i, 2)
         end associate
      end do
      if (n_files == 0) call empty_mesh(model%mesh)
   end subroutine read_mesh_file

   !> A mesh with no nodes and no elements, every array allocated.
   subroutine empty_mesh(mesh)
      type(mesh_t), intent(out) :: mesh
      allocate (mesh%coords(3, 0), mesh%node_ids(0), mesh%connectivity(8, 0), mesh%element_ids(0))
      allocate (mesh%element_block(0), mesh%node_sets(0), mesh%element_sets(0), mesh%surfaces(0))
   end subroutine empty_mesh

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

   !> `NODE <id> COORD x y z`.
   subroutine read_node_coords(reader, model)
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(mesh_t) :: extra
      integer :: i, position, id, n, existing, capacity
      real(dp) :: x(3)
      logical :: ok
      type(error_t), allocatable :: error
      type(id_map_t) :: ids

      call ids%build(model%mesh%node_ids, existing)
      capacity = max(reader%last(s_node_coords) - reader%first(s_node_coords) + 1, 0)
      allocate (extra%coords(3, capacity), extra%node_ids(capacity))
      allocate (extra%connectivity(8, 0), extra%element_ids(0), extra%element_block(0))
      n = 0
      do i = reader%first(s_node_coords), reader%last(s_node_coords)
         associate (line => reader%lines(i))
            if (line%n_tokens() == 0) cycle
            position = 1
            ok = .true.
            call reader%expect_keyword(line, position, 'NODE', ok)
            call reader%take_integer(line, position, 'a node id', id, ok)
            call reader%expect_keyword(line, position, 'COORD', ok)
            call reader%take_reals(line, position, 'a coordinate', x, ok)
            if (ok .and. position <= line%n_tokens()) then
               call reader%report(line, position, 'unexpected text after the coordinates')
               ok = .false.
            end if
            if (.not. ok) then
               reader%mesh_failed = .true.
               cycle
            end if
            call ids%insert(id, model%mesh%n_nodes + n + 1, existing)
            if (existing /= 0) then
               call reader%report(line, 2, 'duplicate node id '//to_string(id)//' (first defined at line '// &
                                  to_string(reader%node_line(existing))//')')
               cycle
            end if
            n = n + 1
            extra%coords(:, n) = x
            extra%node_ids(n) = id
            call extend_origins(reader%node_line, reader%node_token, model%mesh%n_nodes + n, i, 2)
         end associate
      end do
      if (n == 0) return
      extra%n_nodes = n
      extra%coords = extra%coords(:, 1:n)
      extra%node_ids = extra%node_ids(1:n)
      call merge_meshes(model%mesh, extra, error)
      if (allocated(error)) call reader%diagnostics%in_deck(reader%header(s_node_coords), 1, error%message)
   end subroutine read_node_coords

   !> `<id> SOLID HEX8 n1 .. n8 MAT <m> [EAS <k>] [KINTYP Geo_Lin|Tot_Lagr]` (SET lines are read
   !> later, by read_element_set_lines).
   subroutine read_element_lines(reader, model)
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      integer, allocatable :: connectivity(:, :), ids(:), properties(:), origin(:)
      integer :: i, k, position, id, n, existing, capacity, property, first_node, n_node_tokens
      logical :: ok
      type(id_map_t) :: element_ids

      call reader%node_map%build(model%mesh%node_ids, existing)
      call element_ids%build(model%mesh%element_ids, existing)
      capacity = max(reader%last(s_elements) - reader%first(s_elements) + 1, 0)
      allocate (connectivity(8, capacity), ids(capacity), properties(capacity), origin(capacity))
      n = 0
      do i = reader%first(s_elements), reader%last(s_elements)
         associate (line => reader%lines(i))
            if (line%n_tokens() == 0) cycle
            if (line%keyword(1) == 'SET') cycle
            position = 1
            ok = .true.
            call reader%take_integer(line, position, 'an element id', id, ok)
            first_node = position + 2
            call read_property(reader, model, line, position, .true., property, ok)
            if (.not. ok) then
               reader%mesh_failed = .true.
               cycle
            end if
            ! the node ids are the tokens between the shape and the first keyword
            n_node_tokens = 0
            do k = first_node, line%n_tokens()
               if (is_property_keyword(line%keyword(k))) exit
               n_node_tokens = n_node_tokens + 1
            end do
            if (n_node_tokens /= 8) then
               call reader%report(line, first_node - 1, 'wrong node count: HEX8 needs 8 nodes, found '// &
                                  to_string(n_node_tokens))
               reader%mesh_failed = .true.
               cycle
            end if
            position = first_node
            do k = 1, 8
               call reader%take_integer(line, position, 'a node id', id, ok)
               if (.not. ok) exit
               connectivity(k, n + 1) = reader%node_map%lookup(id)
               if (connectivity(k, n + 1) == 0) then
                  ok = .false.
                  if (.not. reader%mesh_failed) call reader%report(line, position - 1, 'undefined node '//to_string(id))
               end if
            end do
            if (.not. ok) then
               reader%mesh_failed = .true.
               cycle
            end if
            id = line_integer(line, 1)
            call element_ids%insert(id, model%mesh%n_elements + n + 1, existing)
            if (existing /= 0) then
               if (existing > model%mesh%n_elements) then
                  existing = origin(existing - model%mesh%n_elements)
               else
                  existing = reader%element_line(existing)
               end if
               call reader%report(line, 1, 'duplicate element id '//to_string(id)//' (first defined at line '// &
                                  to_string(existing)//')')
               reader%mesh_failed = .true.
               cycle
            end if
            n = n + 1
            ids(n) = id
            properties(n) = property
            origin(n) = i
         end associate
      end do
      if (n == 0) return
      associate (mesh => model%mesh)
         mesh%connectivity = reshape([mesh%connectivity, connectivity(:, 1:n)], [8, mesh%n_elements + n])
         mesh%element_ids = [mesh%element_ids, ids(1:n)]
         mesh%element_block = [mesh%element_block, spread(0, 1, n)]
         call extend_origins(reader%element_line, reader%element_token, mesh%n_elements, 0, 1)
         reader%element_line = [reader%element_line, origin(1:n)]
         reader%element_token = [reader%element_token, spread(1, 1, n)]
         call extend_properties(reader, mesh%n_elements)
         reader%element_property = [reader%element_property, properties(1:n)]
         mesh%n_elements = mesh%n_elements + n
      end associate
   end subroutine read_element_lines

   !> Value of integer token `i` known to be valid.
   integer function line_integer(line, i) result(value)
      type(deck_line_t), intent(in) :: line
      integer, intent(in) :: i
      logical :: ok
      character(len=:), allocatable :: message
      call parse_integer(line%token(i), value, ok, message)
   end function line_integer

   pure logical function is_property_keyword(keyword)
      character(len=*), intent(in) :: keyword
      select case (keyword)
      case ('MAT', 'EAS', 'KINTYP')
         is_property_keyword = .true.
      case default
         is_property_keyword = .false.
      end select
   end function is_property_keyword

   subroutine extend_properties(reader, n)
      type(reader_t), intent(inout) :: reader
      integer, intent(in) :: n
      if (.not. allocated(reader%element_property)) allocate (reader%element_property(0))
      if (size(reader%element_property) < n) &
         reader%element_property = [reader%element_property, spread(0, 1, n - size(reader%element_property))]
   end subroutine extend_properties

   !> Reads `SOLID <shape> [nodes] MAT <m> [EAS <k>] [KINTYP <kin>]` starting at the family
   !> token; with `has_nodes` the node tokens after the shape are skipped (read by the caller).
   !> Returns the index of the (shape, EAS, kinematics, material) property.
   subroutine read_property(reader, model, line, position, has_nodes, property, ok)
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      logical, intent(in) :: has_nodes
      integer, intent(out) :: property
      logical, intent(inout) :: ok
      character(len=:), allocatable :: family, shape
      integer :: shape_position, material, material_id, n_eas, kinematics, k
      logical :: has_material
      property = 0
      call reader%take_word(line, position, 'an element family (SOLID)', family, ok)
      if (ok .and. to_upper(family) /= 'SOLID') then
         call reader%report(line, position - 1, 'unknown element family (expected SOLID)')
         ok = .false.
      end if
      shape_position = position
      call reader%take_word(line, position, 'an element shape (HEX8)', shape, ok)
      if (.not. ok) return
      shape = to_upper(shape)
      if (shape /= 'HEX8' .and. shape /= 'HEXA8-E3') then
         call reader%report(line, shape_position, 'unknown element shape (expected HEX8 or HEXA8-E3)')
         ok = .false.
         return
      end if
      if (has_nodes) then
         do while (position <= line%n_tokens())
            if (is_property_keyword(line%keyword(position))) exit
            position = position + 1
         end do
      end if
      has_material = .false.
      material = 0
      n_eas = 0
      kinematics = model%controls%default_kinematics
      do while (ok .and. position <= line%n_tokens())
         select case (line%keyword(position))
         case ('MAT')
            position = position + 1
            call reader%take_integer(line, position, 'a material id', material_id, ok)
            if (.not. ok) exit
            has_material = .true.
            material = 0
            do k = 1, size(model%material_ids)
               if (model%material_ids(k) == material_id) material = k
            end do
            if (material == 0) then
               ok = .false.
               if (.not. any(reader%failed_material_ids == material_id)) &
                  call reader%report(line, position - 1, 'undefined material '//to_string(material_id))
            end if
         case ('EAS')
            position = position + 1
            call reader%take_integer(line, position, 'an EAS parameter count', n_eas, ok)
         case ('KINTYP')
            position = position + 1
            call reader%take_kinematics(line, position, kinematics, ok)
         case default
            call reader%report(line, position, 'unknown keyword on an element line')
            ok = .false.
         end select
      end do
      if (.not. ok) return
      if (.not. has_material) then
         call reader%report(line, line%n_tokens() + 1, 'missing MAT <id>')
         ok = .false.
         return
      end if
      if (shape == 'HEXA8-E3' .and. n_eas == 0) n_eas = 3
      do k = 1, reader%n_properties
         associate (p => reader%properties(k))
            if (p%shape == shape .and. p%n_eas == n_eas .and. p%kinematics == kinematics .and. &
                p%material == material) then
               property = k
               return
            end if
         end associate
      end do
      call append_property(reader%properties, shape, n_eas, kinematics, material, line%number, shape_position)
      reader%n_properties = reader%n_properties + 1
      property = reader%n_properties
   end subroutine read_property

   !> `properties` with property_t(shape, n_eas, kinematics, material, line, token) appended,
   !> through a longer copy and move_alloc rather than `properties = [properties, property_t(...)]`:
   !> gfortran 12 leaks the allocatable components of a structure constructor inside an array
   !> constructor.
   subroutine append_property(properties, shape, n_eas, kinematics, material, line, token)
      type(property_t), allocatable, intent(inout) :: properties(:)
      character(len=*), intent(in) :: shape
      integer, intent(in) :: n_eas, kinematics, material, line, token
      type(property_t), allocatable :: grown(:)
      integer :: n
      n = 0
      if (allocated(properties)) n = size(properties)
      allocate (grown(n + 1))
      if (n > 0) grown(1:n) = properties
      grown(n + 1)%shape = shape
      grown(n + 1)%n_eas = n_eas
      grown(n + 1)%kinematics = kinematics
      grown(n + 1)%material = material
      grown(n + 1)%line = line
      grown(n + 1)%token = token
      call move_alloc(grown, properties)
   end subroutine append_property

   !> `BLOCK <name> ORIGIN x y z SIZE lx ly lz DIVISIONS nx ny nz [NODE_OFFSET n]
   !> [ELEMENT_OFFSET n]`: node ids start at NODE_OFFSET + 1 (default: after the largest
   !> existing id), likewise elements.
   subroutine read_mesh_blocks(reader, model)
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(mesh_t) :: block
      type(error_t), allocatable :: error
      character(len=:), allocatable :: name
      real(dp) :: origin(3), lengths(3)
      integer :: divisions(3), node_offset, element_offset, i, position, k
      logical :: ok, has(3)
      do i = reader%first(s_mesh_block), reader%last(s_mesh_block)
         associate (line => reader%lines(i))
            if (line%n_tokens() == 0) cycle
            position = 1
            ok = .true.
            call reader%expect_keyword(line, position, 'BLOCK', ok)
            call reader%take_word(line, position, 'a block name', name, ok)
            node_offset = 0
            element_offset = 0
            if (model%mesh%n_nodes > 0) node_offset = maxval(model%mesh%node_ids)
            if (model%mesh%n_elements > 0) element_offset = maxval(model%mesh%element_ids)
            has = .false.
            do while (ok .and. position <= line%n_tokens())
               select case (line%keyword(position))
               case ('ORIGIN')
                  position = position + 1
                  call reader%take_reals(line, position, 'an ORIGIN coordinate', origin, ok)
                  has(1) = .true.
               case ('SIZE')
                  position = position + 1
                  k = position
                  call reader%take_reals(line, position, 'a SIZE length', lengths, ok)
                  call require(reader, ok, all(lengths > 0.0_dp), line, k, 'SIZE lengths must be positive')
                  has(2) = .true.
               case ('DIVISIONS')
                  position = position + 1
                  k = position
                  do while (position < k + 3 .and. ok)
                     call reader%take_integer(line, position, 'a DIVISIONS count', divisions(position - k + 1), ok)
                  end do
                  call require(reader, ok, all(divisions >= 1), line, k, 'DIVISIONS must be at least 1')
                  has(3) = .true.
               case ('NODE_OFFSET')
                  position = position + 1
                  call reader%take_integer(line, position, 'NODE_OFFSET', node_offset, ok)
                  call require(reader, ok, node_offset >= 0, line, position - 1, 'NODE_OFFSET must not be negative')
               case ('ELEMENT_OFFSET')
                  position = position + 1
                  call reader%take_integer(line, position, 'ELEMENT_OFFSET', element_offset, ok)
                  call require(reader, ok, element_offset >= 0, line, position - 1, &
                               'ELEMENT_OFFSET must not be negative')
               case default
                  call reader%report(line, position, 'unknown keyword in MESH BLOCK')
                  ok = .false.
               end select
            end do
            if (ok .and. .not. all(has)) then
               call reader%report(line, line%n_tokens() + 1, 'a BLOCK needs ORIGIN, SIZE and DIVISIONS')
               ok = .false.
            end if
            if (.not. ok) then
               reader%mesh_failed = .true.
               cycle
            end if
            call generate_block(name, origin, lengths, divisions, node_offset + 1, element_offset + 1, block, error)
            if (.not. allocated(error)) call merge_meshes(model%mesh, block, error)
            if (allocated(error)) then
               call reader%report(line, 2, 'cannot add block: '//error%message)
               reader%mesh_failed = .true.
               cycle
            end if
            call extend_origins(reader%node_line, reader%node_token, model%mesh%n_nodes, i, 2)
            call extend_origins(reader%element_line, reader%element_token, model%mesh%n_elements, i, 2)
         end associate
      end do
   end subroutine read_mesh_blocks

   !> After all nodes and elements exist: look-ups, per-node and per-element bookkeeping.
   subroutine finish_mesh_numbering(reader, model)
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      integer :: duplicate
      real(dp) :: lower(3), upper(3)
      call reader%node_map%build(model%mesh%node_ids, duplicate)
      call reader%element_map%build(model%mesh%element_ids, duplicate)
      call extend_properties(reader, model%mesh%n_elements)
      call extend_origins(reader%node_line, reader%node_token, model%mesh%n_nodes, 0, 1)
      call extend_origins(reader%element_line, reader%element_token, model%mesh%n_elements, 0, 1)
      allocate (reader%node_condition_line(model%mesh%n_nodes), source=0)
      if (.not. allocated(model%mesh%node_sets)) allocate (model%mesh%node_sets(0))
      if (.not. allocated(model%mesh%element_sets)) allocate (model%mesh%element_sets(0))
      if (.not. allocated(model%mesh%surfaces)) allocate (model%mesh%surfaces(0))
      if (model%mesh%n_nodes > 0) then
         call mesh_bounding_box(model%mesh, lower, upper)
         reader%model_size = max(norm2(upper - lower), tiny(1.0_dp))
      end if
   end subroutine finish_mesh_numbering

   !> `SET <element set> SOLID <shape> MAT <m> [EAS <k>] [KINTYP <kin>]`.
   subroutine read_element_set_lines(reader, model)
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      character(len=:), allocatable :: name
      integer :: i, k, position, set, property, element
      logical :: ok
      do i = reader%first(s_elements), reader%last(s_elements)
         associate (line => reader%lines(i))
            if (line%n_tokens() == 0) cycle
            if (line%keyword(1) /= 'SET') cycle
            position = 2
            ok = .true.
            call reader%take_word(line, position, 'an element set name', name, ok)
            set = 0
            if (ok) set = model%mesh%find_element_set(name)
            if (ok .and. set == 0) then
               ok = .false.
               if (.not. reader%mesh_failed) call reader%report(line, 2, 'unknown element set')
            end if
            call read_property(reader, model, line, position, .false., property, ok)
            if (.not. ok) then
               reader%property_failed = .true.
               cycle
            end if
            do k = 1, size(model%mesh%element_sets(set)%elements)
               element = model%mesh%element_sets(set)%elements(k)
               if (reader%element_property(element) /= 0 .and. reader%element_property(element) /= property) then
                  call reader%report(line, 2, 'element '//to_string(model%mesh%element_ids(element))// &
                                     ' already has a different property (line '// &
                                     to_string(reader%properties(reader%element_property(element))%line)//')')
                  exit
               end if
               reader%element_property(element) = property
            end do
         end associate
      end do
   end subroutine read_element_set_lines

   ! ---- NODE SETS and SURFACES -----------------------------------------------------------

   !> `SET <name> NODES id ...` or `SET <name> BOX xmin ymin zmin xmax ymax zmax`.
   subroutine read_node_sets(reader, model)
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(node_set_t) :: set
      integer, allocatable :: nodes(:)
      character(len=:), allocatable :: name
      real(dp) :: box(6)
      integer :: i, k, n, position, id
      logical :: ok
      do i = reader%first(s_node_sets), reader%last(s_node_sets)
         associate (line => reader%lines(i))
            if (line%n_tokens() == 0) cycle
            position = 1
            ok = .true.
            call reader%expect_keyword(line, position, 'SET', ok)
            call reader%take_word(line, position, 'a node set name', name, ok)
            if (ok .and. model%mesh%find_node_set(name) /= 0) then
               call reader%report(line, 2, 'node set already defined')
               ok = .false.
            end if
            if (.not. ok) cycle
            if (position > line%n_tokens()) then
               call reader%report(line, position, 'missing NODES or BOX')
               cycle
            end if
            select case (line%keyword(position))
            case ('NODES')
               position = position + 1
               allocate (nodes(line%n_tokens() - position + 1))
               n = 0
               do k = 1, size(nodes)
                  call reader%take_integer(line, position, 'a node id', id, ok)
                  if (.not. ok) exit
                  n = n + 1
                  nodes(n) = reader%node_map%lookup(id)
                  if (nodes(n) == 0) then
                     ok = .false.
                     if (.not. reader%mesh_failed) call reader%report(line, position - 1, 'undefined node '//to_string(id))
                  end if
               end do
               if (ok .and. n == 0) then
                  call reader%report(line, position, 'empty node set: no node ids given')
                  ok = .false.
               end if
            case ('BOX')
               position = position + 1
               call read_box(reader, line, position, box, ok)
               if (ok) then
                  nodes = nodes_in_box(model%mesh, box, box_tolerance*reader%model_size)
                  if (size(nodes) == 0) then
                     ok = .false.
                     if (.not. reader%mesh_failed) call reader%report(line, 3, 'empty node set: the BOX selects no node')
                  end if
               end if
            case default
               call reader%report(line, position, 'expected NODES or BOX')
               ok = .false.
            end select
            if (ok .and. position <= line%n_tokens()) then
               call reader%report(line, position, 'unexpected text')
               ok = .false.
            end if
            if (ok) then
               set%name = name
               set%nodes = sorted_unique(nodes)
               model%mesh%node_sets = [model%mesh%node_sets, set]
            end if
            if (allocated(nodes)) deallocate (nodes)
         end associate
      end do
   end subroutine read_node_sets

   !> Six reals xmin ymin zmin xmax ymax zmax with min <= max.
   subroutine read_box(reader, line, position, box, ok)
      type(reader_t), intent(inout) :: reader
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      real(dp), intent(out) :: box(6)
      logical, intent(inout) :: ok
      integer :: start
      start = position
      call reader%take_reals(line, position, 'a BOX coordinate', box, ok)
      call require(reader, ok, all(box(1:3) <= box(4:6)), line, start, &
                   'BOX minimum exceeds its maximum (expected xmin ymin zmin xmax ymax zmax)')
   end subroutine read_box

   !> Internal numbers of the nodes inside `box` widened by `tolerance`.
   pure function nodes_in_box(mesh, box, tolerance) result(nodes)
      type(mesh_t), intent(in) :: mesh
      real(dp), intent(in) :: box(6), tolerance
      integer, allocatable :: nodes(:)
      logical, allocatable :: inside(:)
      integer :: n
      allocate (inside(mesh%n_nodes))
      do n = 1, mesh%n_nodes
         inside(n) = in_box(mesh%coords(:, n), box, tolerance)
      end do
      nodes = pack([(n, n=1, mesh%n_nodes)], inside)
   end function nodes_in_box

   pure logical function in_box(x, box, tolerance)
      real(dp), intent(in) :: x(3), box(6), tolerance
      in_box = all(x >= box(1:3) - tolerance) .and. all(x <= box(4:6) + tolerance)
   end function in_box

   pure function sorted_unique(values) result(unique)
      integer, intent(in) :: values(:)
      integer, allocatable :: unique(:)
      integer, allocatable :: order(:)
      integer :: k, n
      allocate (order(size(values)), unique(size(values)))
      order(:) = sorted_order(reshape(values, [1, size(values)]))
      n = 0
      do k = 1, size(order)
         if (n > 0) then
            if (unique(n) == values(order(k))) cycle
         end if
         n = n + 1
         unique(n) = values(order(k))
      end do
      unique = unique(1:n)
   end function sorted_unique

   !> `SURF <name> BOX xmin ymin zmin xmax ymax zmax` or `SURF <name> FACES e f e f ...`.
   subroutine read_surfaces(reader, model)
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(surface_t) :: surface
      character(len=:), allocatable :: name
      real(dp) :: box(6)
      integer :: i, k, n, position, id, face
      logical :: ok
      do i = reader%first(s_surfaces), reader%last(s_surfaces)
         associate (line => reader%lines(i))
            if (line%n_tokens() == 0) cycle
            position = 1
            ok = .true.
            call reader%expect_keyword(line, position, 'SURF', ok)
            call reader%take_word(line, position, 'a surface name', name, ok)
            if (ok .and. model%mesh%find_surface(name) /= 0) then
               call reader%report(line, 2, 'surface already defined')
               ok = .false.
            end if
            if (.not. ok) cycle
            if (position > line%n_tokens()) then
               call reader%report(line, position, 'missing BOX or FACES')
               cycle
            end if
            select case (line%keyword(position))
            case ('BOX')
               position = position + 1
               call read_box(reader, line, position, box, ok)
               if (ok) then
                  call boundary_faces_in_box(model%mesh, box, box_tolerance*reader%model_size, surface)
                  if (size(surface%elements) == 0) then
                     ok = .false.
                     if (.not. reader%mesh_failed) &
                        call reader%report(line, 3, 'empty surface: the BOX holds no boundary face')
                  end if
               end if
            case ('FACES')
               position = position + 1
               n = (line%n_tokens() - position + 1)/2
               if (mod(line%n_tokens() - position + 1, 2) /= 0 .or. n == 0) then
                  call reader%report(line, line%n_tokens() + 1, 'FACES needs (element, face) pairs')
                  cycle
               end if
               if (allocated(surface%elements)) deallocate (surface%elements, surface%faces)
               allocate (surface%elements(n), surface%faces(n))
               do k = 1, n
                  call reader%take_integer(line, position, 'an element id', id, ok)
                  if (.not. ok) exit
                  surface%elements(k) = reader%element_map%lookup(id)
                  if (surface%elements(k) == 0) then
                     ok = .false.
                     if (.not. reader%mesh_failed) call reader%report(line, position - 1, 'undefined element '//to_string(id))
                     exit
                  end if
                  call reader%take_integer(line, position, 'a face number', face, ok)
                  call require(reader, ok, face >= 1 .and. face <= 6, line, position - 1, 'face number out of range 1..6')
                  surface%faces(k) = face
               end do
            case default
               call reader%report(line, position, 'expected BOX or FACES')
               ok = .false.
            end select
            if (ok .and. position <= line%n_tokens()) then
               call reader%report(line, position, 'unexpected text')
               ok = .false.
            end if
            if (.not. ok) cycle
            surface%name = name
            model%mesh%surfaces = [model%mesh%surfaces, surface]
         end associate
      end do
   end subroutine read_surfaces

   !> Faces that belong to exactly one element and whose 4 nodes lie in the box. Candidate
   !> faces (nodes in the box) are sorted by their sorted node numbers; a face shared by two
   !> elements has both copies among the candidates, so it appears twice and is dropped.
   subroutine boundary_faces_in_box(mesh, box, tolerance, surface)
      type(mesh_t), intent(in) :: mesh
      real(dp), intent(in) :: box(6), tolerance
      type(surface_t), intent(out) :: surface
      logical, allocatable :: inside(:)
      integer, allocatable :: keys(:, :), elements(:), faces(:), order(:)
      integer :: e, f, n, k, count
      allocate (inside(mesh%n_nodes))
      do k = 1, mesh%n_nodes
         inside(k) = in_box(mesh%coords(:, k), box, tolerance)
      end do
      n = 0
      do e = 1, mesh%n_elements
         do f = 1, 6
            if (all(inside(mesh%connectivity(hex8_face_nodes(:, f), e)))) n = n + 1
         end do
      end do
      allocate (keys(4, n), elements(n), faces(n))
      n = 0
      do e = 1, mesh%n_elements
         do f = 1, 6
            if (all(inside(mesh%connectivity(hex8_face_nodes(:, f), e)))) then
               n = n + 1
               keys(:, n) = sort4(mesh%connectivity(hex8_face_nodes(:, f), e))
               elements(n) = e
               faces(n) = f
            end if
         end do
      end do
      order = sorted_order(keys)
      allocate (surface%elements(n), surface%faces(n))
      count = 0
      k = 1
      do while (k <= n)
         if (k < n) then
            if (all(keys(:, order(k)) == keys(:, order(k + 1)))) then
               k = k + 2  ! an interior face (shared by two elements)
               cycle
            end if
         end if
         count = count + 1
         surface%elements(count) = elements(order(k))
         surface%faces(count) = faces(order(k))
         k = k + 1
      end do
      surface%elements = surface%elements(1:count)
      surface%faces = surface%faces(1:count)
   end subroutine boundary_faces_in_box

   pure function sort4(values) result(sorted)
      integer, intent(in) :: values(4)
      integer :: sorted(4)
      integer :: i, j, swap
      sorted = values
      do i = 2, 4
         j = i
         do while (j > 1)
            if (sorted(j - 1) <= sorted(j)) exit
            swap = sorted(j)
            sorted(j) = sorted(j - 1)
            sorted(j - 1) = swap
            j = j - 1
         end do
      end do
   end function sort4

   ! ---- conditions and loads -------------------------------------------------------------

   !> `SET <name>|NODE <id> DOF f1 f2 f3 VAL v1 v2 v3 [CURVE c1 c2 c3]`.
   subroutine read_dirichlet(reader, model)
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(dirichlet_t) :: record
      integer, allocatable :: nodes(:)
      integer :: i, k, position, flags(3), curves(3), flag_position
      real(dp) :: values(3)
      logical :: ok
      allocate (model%dirichlet(0))
      do i = reader%first(s_dirichlet), reader%last(s_dirichlet)
         associate (line => reader%lines(i))
            if (line%n_tokens() == 0) cycle
            position = 1
            ok = .true.
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
            call reader%take_reals(line, position, 'a prescribed value', values, ok)
            curves = 0
            if (ok .and. position <= line%n_tokens()) then
               call reader%expect_keyword(line, position, 'CURVE', ok)
               do k = 1, 3
                  call reader%take_curve(line, position, curves(k), ok)
               end do
            end if
            if (ok .and. position <= line%n_tokens()) then
               call reader%report(line, position, 'unexpected text')
               ok = .false.
            end if
            if (.not. ok) cycle
            do k = 1, 3
               if (flags(k) == 0) cycle
               record%nodes = nodes
               record%component = k
               record%value = values(k)
               record%curve = curves(k)
               record%line = line%number
               model%dirichlet = [model%dirichlet, record]
            end do
            call mark_nodes(reader, nodes, i)
         end associate
      end do
   end subroutine read_dirichlet

   !> `SET <name>|NODE <id> FORCE fx fy fz [CURVE c]` or `SURF <name> PRESSURE p [CURVE c]
   !> [FOLLOWER]`.
   subroutine read_neumann(reader, model)
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(nodal_force_t) :: force
      type(pressure_load_t) :: pressure
      integer, allocatable :: nodes(:)
      character(len=:), allocatable :: name
      integer :: i, k, e, position, curve
      real(dp) :: values(3)
      logical :: ok
      allocate (model%nodal_forces(0), model%pressures(0))
      do i = reader%first(s_neumann), reader%last(s_neumann)
         associate (line => reader%lines(i))
            if (line%n_tokens() == 0) cycle
            position = 1
            ok = .true.
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
               do while (ok .and. position <= line%n_tokens())
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
               end do
               if (.not. ok) cycle
               model%pressures = [model%pressures, pressure]
               associate (surface => model%mesh%surfaces(pressure%surface))
                  do k = 1, size(surface%elements)
                     e = surface%elements(k)
                     call mark_nodes(reader, model%mesh%connectivity(hex8_face_nodes(:, surface%faces(k)), e), i)
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
            if (ok .and. position <= line%n_tokens()) then
               call reader%report(line, position, 'unexpected text')
               ok = .false.
            end if
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
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(body_force_t) :: body_force
      character(len=:), allocatable :: name
      integer :: i, k, position, set
      logical :: ok
      allocate (model%body_forces(0))
      do i = reader%first(s_body_force), reader%last(s_body_force)
         associate (line => reader%lines(i))
            if (line%n_tokens() == 0) cycle
            position = 1
            ok = .true.
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
            if (ok .and. position <= line%n_tokens()) then
               call reader%report(line, position, 'unexpected text')
               ok = .false.
            end if
            if (ok) model%body_forces = [model%body_forces, body_force]
         end associate
      end do
   end subroutine read_body_forces

   ! ---- STEPS ----------------------------------------------------------------------------

   !> CONTACT CONDITIONS: one pair per line,
   !> `PAIR <id> SLAVE <surface> MASTER <surface>|RIGID_PLANE [POINT x y z NORMAL nx ny nz]
   !>  EPSN <eps_N> [EPST <eps_T>] [MU <mu>] [LAW Coulomb|Frictionless] [GAPTOL <g>] [PASSES 1|2]
   !>  [NORMALS Facet|Smoothed]`.
   !> MU gives Coulomb friction (MU 0 or LAW Frictionless: frictionless, EPST not needed).
   subroutine read_contact_pairs(reader, model)
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(contact_pair_t) :: pair
      class(friction_law_t), allocatable :: law
      type(error_t), allocatable :: law_error
      character(len=:), allocatable :: name, word, law_keyword
      character(len=8), allocatable :: law_names(:)
      real(dp), allocatable :: law_values(:)
      real(dp) :: eps_n, eps_t, gap_tolerance, mu, length
      integer :: i, position, k, law_token, passes, normals_token, normals_choice, n_ring, face_nodes(4)
      logical :: ok, has_eps_n, has_eps_t, has_mu, has_point, has_normal, smoothed
      allocate (model%contact_pairs(0))
      do i = reader%first(s_contact), reader%last(s_contact)
         associate (line => reader%lines(i))
            if (line%n_tokens() == 0) cycle
            ok = .true.
            position = 1
            call reader%expect_keyword(line, position, 'PAIR', ok)
            call reader%take_integer(line, position, 'a pair id', pair%id, ok)
            if (.not. ok) cycle
            do k = 1, size(model%contact_pairs)
               if (model%contact_pairs(k)%id == pair%id) then
                  call reader%report(line, 2, 'duplicate contact pair id')
                  ok = .false.
               end if
            end do
            call reader%expect_keyword(line, position, 'SLAVE', ok)
            call reader%take_word(line, position, 'a slave surface name', name, ok)
            if (ok) then
               pair%slave_surface = model%mesh%find_surface(name)
               if (pair%slave_surface == 0) then
                  if (.not. reader%mesh_failed) call reader%report(line, position - 1, 'unknown surface')
                  ok = .false.
               end if
            end if
            call reader%expect_keyword(line, position, 'MASTER', ok)
            call reader%take_word(line, position, 'a master surface name or RIGID_PLANE', name, ok)
            pair%master_surface = 0
            if (ok .and. to_upper(name) /= 'RIGID_PLANE') then
               pair%master_surface = model%mesh%find_surface(name)
               if (pair%master_surface == 0) then
                  if (.not. reader%mesh_failed) call reader%report(line, position - 1, 'unknown surface')
                  ok = .false.
               else if (pair%master_surface == pair%slave_surface) then
                  call reader%report(line, position - 1, 'a surface cannot be in contact with itself')
                  ok = .false.
               end if
            end if
            has_eps_n = .false.; has_eps_t = .false.; has_mu = .false.
            has_point = .false.; has_normal = .false.
            eps_n = 0.0_dp; eps_t = 0.0_dp; mu = 0.0_dp; gap_tolerance = 0.0_dp
            passes = 1
            smoothed = .false.
            law_keyword = ''
            law_token = 0
            pair%plane_point = 0.0_dp
            pair%plane_normal = 0.0_dp
            do while (ok .and. position <= line%n_tokens())
               word = line%keyword(position)
               position = position + 1
               select case (word)
               case ('POINT')
                  call reader%take_reals(line, position, 'a coordinate', pair%plane_point, ok)
                  has_point = ok
               case ('NORMAL')
                  call reader%take_reals(line, position, 'a normal component', pair%plane_normal, ok)
                  has_normal = ok
               case ('EPSN')
                  call reader%take_real(line, position, 'EPSN', eps_n, ok)
                  call require(reader, ok, eps_n > 0.0_dp, line, position - 1, 'EPSN must be positive')
                  has_eps_n = ok
               case ('EPST')
                  call reader%take_real(line, position, 'EPST', eps_t, ok)
                  call require(reader, ok, eps_t > 0.0_dp, line, position - 1, 'EPST must be positive')
                  has_eps_t = ok
               case ('MU')
                  call reader%take_real(line, position, 'MU', mu, ok)
                  call require(reader, ok, mu >= 0.0_dp, line, position - 1, 'MU must not be negative')
                  has_mu = ok
               case ('GAPTOL')
                  call reader%take_real(line, position, 'GAPTOL', gap_tolerance, ok)
                  call require(reader, ok, gap_tolerance >= 0.0_dp, line, position - 1, &
                               'GAPTOL must not be negative')
               case ('PASSES')
                  call reader%take_integer(line, position, 'PASSES', passes, ok)
                  call require(reader, ok, passes == 1 .or. passes == 2, line, position - 1, &
                               'PASSES must be 1 or 2')
               case ('LAW')
                  law_token = position
                  call reader%take_word(line, position, 'a friction law', law_keyword, ok)
               case ('NORMALS')
                  normals_token = position
                  call reader%take_choice(line, position, 'Facet or Smoothed', &
                                          [character(len=8) :: 'FACET', 'SMOOTHED'], &
                                          'NORMALS must be Facet or Smoothed', normals_choice, ok)
                  smoothed = normals_choice == 2
                  if (ok .and. smoothed .and. pair%master_surface == 0) then
                     call reader%report(line, position - 1, 'NORMALS Smoothed needs a deformable master surface')
                     ok = .false.
                  end if
               case default
                  call reader%report(line, position - 1, 'unknown keyword (expected POINT, NORMAL, '// &
                                     'EPSN, EPST, MU, LAW, GAPTOL, PASSES or NORMALS)')
                  ok = .false.
               end select
            end do
            if (.not. ok) cycle
            if (.not. has_eps_n) then
               call reader%report(line, 1, 'contact pair without EPSN (normal penalty)')
               cycle
            end if
            if (pair%master_surface == 0) then
               if (.not. (has_point .and. has_normal)) then
                  call reader%report(line, 1, 'a RIGID_PLANE master needs POINT x y z and NORMAL nx ny nz')
                  cycle
               end if
               length = norm2(pair%plane_normal)
               if (length == 0.0_dp) then
                  call reader%report(line, 1, 'the rigid plane''s NORMAL is zero')
                  cycle
               end if
               pair%plane_normal = pair%plane_normal/length
               if (passes == 2) then
                  call reader%report(line, 1, 'PASSES 2 needs a deformable master surface')
                  cycle
               end if
            else if (has_point .or. has_normal) then
               call reader%report(line, 1, 'POINT and NORMAL belong to a RIGID_PLANE master')
               cycle
            end if
            if (len(law_keyword) == 0) law_keyword = merge('COULOMB     ', 'FRICTIONLESS', has_mu .and. mu > 0.0_dp)
            if (to_upper(law_keyword) == 'COULOMB') then
               law_names = [character(len=8) :: 'MU']
               law_values = [mu]
            else
               allocate (law_names(0), law_values(0))
            end if
            call create_friction_law(trim(law_keyword), law_names, law_values, law, law_error)
            deallocate (law_names, law_values)
            if (allocated(law_error)) then
               call reader%report(line, max(1, law_token), law_error%message)
               deallocate (law_error)
               cycle
            end if
            if (.not. law%frictionless() .and. .not. has_eps_t) then
               call reader%report(line, 1, 'a contact pair with friction needs EPST (tangential penalty)')
               cycle
            end if
            call new_contact_parameters(eps_n, eps_t, gap_tolerance, law, pair%parameters, law_error)
            if (allocated(law_error)) then
               call reader%report(line, 1, law_error%message)
               deallocate (law_error)
               cycle
            end if
            if (smoothed) then
               ! the kernel's unknowns bound the nodes around a master face (docs/contact.md)
               call largest_patch_ring(model%mesh, model%mesh%surfaces(pair%master_surface), n_ring, face_nodes)
               if (n_ring > max_ring_nodes) then
                  call reader%report(line, normals_token, 'NORMALS Smoothed: the master face of nodes '// &
                                     to_string(model%mesh%node_ids(face_nodes(1)))//' '// &
                                     to_string(model%mesh%node_ids(face_nodes(2)))//' '// &
                                     to_string(model%mesh%node_ids(face_nodes(3)))//' '// &
                                     to_string(model%mesh%node_ids(face_nodes(4)))//' has '// &
                                     to_string(n_ring)//' nodes around it, at most '// &
                                     to_string(max_ring_nodes)//' are supported (4 faces at each of its nodes)')
                  cycle
               end if
            end if
            pair%parameters%smoothed_normals = smoothed
            pair%passes = passes
            pair%line = i
            model%contact_pairs = [model%contact_pairs, pair]
         end associate
      end do
   end subroutine read_contact_pairs


   !> `STEP <n> NUMSTEP <k> [CONTROL Load|Displacement] [MAXITER m]`, numbered 1, 2, ...
   subroutine read_steps(reader, model)
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(step_t) :: step
      character(len=:), allocatable :: word
      integer :: i, position, number, expected, last_step_line
      logical :: ok
      allocate (model%steps(0))
      reader%step_lines = 0
      last_step_line = 0
      do i = reader%first(s_steps), reader%last(s_steps)
         if (reader%lines(i)%n_tokens() > 0) last_step_line = i
      end do
      expected = 1
      do i = reader%first(s_steps), reader%last(s_steps)
         associate (line => reader%lines(i))
            if (line%n_tokens() == 0) cycle
            reader%step_lines = reader%step_lines + 1
            position = 1
            ok = .true.
            call reader%expect_keyword(line, position, 'STEP', ok)
            call reader%take_integer(line, position, 'a step number', number, ok)
            call require(reader, ok, number == expected, line, position - 1, &
                         'steps must be numbered 1, 2, ... in order: expected step '//to_string(expected))
            expected = expected + 1
            step = step_t(n_increments=0, control='LOAD')   ! n_increments 0: NUMSTEP missing
            do while (ok .and. position <= line%n_tokens())
               select case (line%keyword(position))
               case ('NUMSTEP')
                  position = position + 1
                  call reader%take_integer(line, position, 'NUMSTEP', step%n_increments, ok)
                  call require(reader, ok, step%n_increments >= 1, line, position - 1, 'NUMSTEP must be positive')
               case ('CONTROL')
                  position = position + 1
                  call reader%take_word(line, position, 'CONTROL value', word, ok)
                  if (.not. ok) exit
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
               case default
                  call reader%report(line, position, 'unknown keyword in STEPS')
                  ok = .false.
               end select
            end do
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

   !> `CONTROL Path NODE <id> DOF <1-3> TARGET <value>` (after the word Path) of step `number`:
   !> the driving displacement, which must be free (no Dirichlet condition on it), and loads
   !> that change over the step while the prescribed displacements do not (the load factor is
   !> the unknown that scales the former; the latter are held at their values).
   subroutine read_path_control(reader, model, line, position, number, step, ok)
      type(reader_t), intent(inout) :: reader
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
      call read_node_dof(reader, line, position, step%path_node, step%path_component, ok)
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

   ! ---- checks of the whole model --------------------------------------------------------

   subroutine validate_model(reader, model)
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      integer, allocatable :: bad(:), overflowing(:), orphans(:), block_of_property(:), missing(:)
      type(error_t), allocatable :: error
      integer :: k, e, n_blocks, end_line

      end_line = max(reader%n_lines, 1)
      if (all(reader%header == 0)) return  ! not a deck at all: "no section line found" says it
      if (reader%header(s_end) == 0) call reader%diagnostics%in_deck(end_line, 1, 'missing END section')
      if (reader%header(s_steps) == 0) then
         call reader%diagnostics%in_deck(end_line, 1, 'no STEPS section')
      else if (reader%step_lines == 0) then
         call reader%diagnostics%at_line(reader%lines(reader%header(s_steps)), 1, 'the STEPS section defines no step')
      end if
      if (model%mesh%n_elements == 0 .and. .not. reader%mesh_failed) &
         call reader%diagnostics%in_deck(end_line, 1, 'the model has no elements')

      ! element blocks: one per property actually used
      allocate (block_of_property(reader%n_properties), source=0)
      n_blocks = 0
      do e = 1, model%mesh%n_elements
         k = reader%element_property(e)
         if (k == 0) cycle
         if (block_of_property(k) == 0) then
            n_blocks = n_blocks + 1
            block_of_property(k) = n_blocks
         end if
      end do
      allocate (model%blocks(n_blocks))
      do k = 1, reader%n_properties
         if (block_of_property(k) == 0) cycle
         associate (p => reader%properties(k), block => model%blocks(block_of_property(k)))
            block%material = p%material
            call create_element(p%shape, p%n_eas, p%kinematics, block%element%formulation, error)
            if (allocated(error)) then
               call reader%report(reader%lines(p%line), p%token, 'invalid element: '//one_line(error%message))
               deallocate (error)
            end if
         end associate
      end do
      model%mesh%element_block = [(0, e=1, model%mesh%n_elements)]
      allocate (missing(0))
      do e = 1, model%mesh%n_elements
         k = reader%element_property(e)
         if (k == 0) then
            missing = [missing, e]
         else
            model%mesh%element_block(e) = block_of_property(k)
         end if
      end do
      if (.not. reader%property_failed) call report_elements(reader, model, missing, 'has no material/property')

      if (model%mesh%n_elements > 0) then
         call check_hex8_jacobians(model%mesh, bad, overflowing)
         call report_elements(reader, model, bad, 'has a non-positive Jacobian (inverted or degenerate)')
         call report_elements(reader, model, overflowing, 'has a Jacobian beyond the range of real '// &
                              'numbers (coordinates too large)')
      end if

      if (model%mesh%n_nodes > 0 .and. .not. reader%mesh_failed) then
         call find_orphan_nodes(model%mesh, orphans)
         do k = 1, size(orphans)
            associate (node => orphans(k))
               if (reader%node_condition_line(node) > 0) then
                  call reader%diagnostics%at_line(reader%lines(reader%node_condition_line(node)), 1, &
                                                  'node '//to_string(model%mesh%node_ids(node))// &
                                                  ' carries a condition or load but belongs to no element')
               end if
            end associate
         end do
      end if
   end subroutine validate_model

   !> One message per deck line that created offending elements, naming the first of them.
   subroutine report_elements(reader, model, elements, what)
      type(reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      integer, intent(in) :: elements(:)
      character(len=*), intent(in) :: what
      logical, allocatable :: done(:)
      integer :: k, j, count, origin
      character(len=:), allocatable :: more
      allocate (done(size(elements)), source=.false.)
      do k = 1, size(elements)
         if (done(k)) cycle
         origin = reader%element_line(elements(k))
         count = 0
         do j = k, size(elements)
            if (reader%element_line(elements(j)) == origin) then
               done(j) = .true.
               count = count + 1
            end if
         end do
         more = ''
         if (count > 1) more = ' (and '//to_string(count - 1)//' more elements from this line)'
         if (origin > 0) then
            call reader%report(reader%lines(origin), reader%element_token(elements(k)), &
                               'element '//to_string(model%mesh%element_ids(elements(k)))//' '//what//more)
         else
            call reader%diagnostics%in_deck(0, 1, 'element '//to_string(model%mesh%element_ids(elements(k)))// &
                                            ' '//what//more)
         end if
      end do
   end subroutine report_elements
end module frix_deck_reader
