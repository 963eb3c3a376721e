!> The input deck reader: reads a CARAT-style deck (format: docs/deck-format.md) into a
!> model_t and validates it. Every mistake of the deck is collected - a bad line never stops
!> the reading of later lines, semantic checks run after reading - and returned as one
!> error_t with one `<deck>:<line>:<column>: error: <what> near "<token>"` entry per mistake
!> (see frix_deck_diagnostics).
!>
!> Sections are processed in a fixed order, whatever their order in the file, so that every
!> reference points backwards: controls, curves, materials; the mesh (MESH FILE, NODE COORDS,
!> element lines of STRUCTURE ELEMENTS, MESH BLOCK, then the SET lines of STRUCTURE ELEMENTS);
!> NODE SETS, SURFACES; conditions, loads and initial stresses; CONTACT CONDITIONS; COUPLINGS; STEPS; RESULTS;
!> then, in a valid model (mesh, materials and element blocks complete), the initial stresses
!> at the integration points (frix_deck_initial_stress), the automatic contact
!> penalties, the ties' nodes and the supports against rigid-body motion (frix_deck_supports).
!> Each section has its reader in a module of its own (frix_deck_controls, _properties, _mesh,
!> _loads, _initial_stress, _contact, _couplings, _results).
module frix_deck_reader
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_mesh_checks, only: check_element_jacobians, find_orphan_nodes
   use frix_model, only: model_t
   use frix_text_scanner, only: text_scanner_t, open_text_file
   use frix_deck_tokens, only: split_line, is_section_line, section_name
   use frix_deck_context, only: deck_reader_t, deck_section_names, s_end, s_steps
   use frix_deck_controls, only: read_controls, read_curves, read_steps
   use frix_deck_properties, only: read_materials, read_element_lines, read_element_set_lines, create_blocks
   use frix_deck_mesh, only: read_mesh_file, read_node_coords, read_mesh_blocks, finish_mesh_numbering, &
                             read_node_sets, read_surfaces
   use frix_deck_loads, only: read_dirichlet, read_neumann, read_body_forces
   use frix_deck_initial_stress, only: read_initial_stresses, evaluate_initial_stresses
   use frix_deck_contact, only: read_contact_pairs, set_automatic_penalties
   use frix_deck_couplings, only: read_couplings
   use frix_deck_results, only: read_results
   use frix_deck_supports, only: check_ties_and_supports
   implicit none
   private

   public :: read_deck

contains

   !> Read the deck at `path` into `model` and validate it; all mistakes are returned in
   !> `error` (one entry per mistake), which is unallocated for a valid deck.
   subroutine read_deck(path, model, error)
      character(len=*), intent(in) :: path
      type(model_t), intent(out) :: model
      type(error_t), allocatable, intent(out) :: error
      type(deck_reader_t) :: reader
      integer :: slash

      model%deck_path = path
      reader%diagnostics%path = path
      slash = index(path, '/', back=.true.)
      reader%directory = path(1:slash)

      call load_lines(reader, path, error)
      if (allocated(error)) return
      call find_sections(reader, model)

      call read_controls(reader, model)
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
      call read_initial_stresses(reader, model)
      call read_contact_pairs(reader, model)
      call read_couplings(reader, model)
      call read_steps(reader, model)
      call read_results(reader, model)
      call validate_model(reader, model)
      if (.not. reader%diagnostics%has_errors()) call evaluate_initial_stresses(reader, model)
      if (.not. reader%diagnostics%has_errors()) call set_automatic_penalties(reader, model)
      if (.not. reader%diagnostics%has_errors()) call check_ties_and_supports(reader, model)

      call reader%diagnostics%finish(error)
   end subroutine read_deck

   ! ---- reading the file and finding the sections --------------------------------------------

   subroutine load_lines(reader, path, error)
      type(deck_reader_t), intent(inout) :: reader
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
      type(deck_reader_t), intent(inout) :: reader
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

   ! ---- checks of the whole model --------------------------------------------------------

   subroutine validate_model(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      integer, allocatable :: bad(:), overflowing(:), orphans(:), missing(:)
      integer :: k, end_line

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

      call create_blocks(reader, model, missing)
      if (.not. reader%property_failed) call report_elements(reader, model, missing, 'has no material/property')

      if (model%mesh%n_elements > 0) then
         call check_element_jacobians(model%mesh, bad, overflowing)
         call report_elements(reader, model, bad, 'has a non-positive Jacobian (inverted or degenerate)')
         call report_elements(reader, model, overflowing, 'has a Jacobian beyond the range of real '// &
                              'numbers (coordinates too large)')
         call report_elements(reader, model, other_dimension(model), 'is a plane element among solids or a '// &
                              'solid among plane elements (a model is either plane or three-dimensional)')
         call check_plane_z_conditions(reader, model)
      end if

      if (model%mesh%n_nodes > 0 .and. .not. reader%mesh_failed) then
         call find_orphan_nodes(model%mesh, orphans)
         do k = 1, size(orphans)
            associate (node => orphans(k))
               if (reference_or_rotation(model, node)) cycle   ! a coupling's own node (frix_deck_couplings)
               if (reader%node_condition_line(node) > 0) then
                  call reader%diagnostics%at_line(reader%lines(reader%node_condition_line(node)), 1, &
                                                  'node '//to_string(model%mesh%node_ids(node))// &
                                                  ' carries a condition or load but belongs to no element')
               end if
            end associate
         end do
      end if
   end subroutine validate_model

   !> A Dirichlet condition that prescribes a z displacement other than 0 on a node of plane
   !> elements (whose z is held at 0): an error at the condition's line.
   subroutine check_plane_z_conditions(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      logical, allocatable :: plane_node(:)
      integer :: i, e
      allocate (plane_node(model%mesh%n_nodes), source=.false.)
      do e = 1, model%mesh%n_elements
         if (model%mesh%cell_dimension(e) == 2) plane_node(model%mesh%element_nodes(e)) = .true.
      end do
      if (.not. any(plane_node) .or. .not. allocated(model%dirichlet)) return
      do i = 1, size(model%dirichlet)
         associate (condition => model%dirichlet(i))
            if (condition%component /= 3 .or. condition%value == 0.0_dp .or. condition%line == 0) cycle
            if (.not. any(plane_node(condition%nodes))) cycle
            call reader%diagnostics%at_line(reader%lines(condition%line), 1, 'a z displacement '// &
                                            'prescribed on the nodes of plane elements, which move in x and y only')
         end associate
      end do
   end subroutine check_plane_z_conditions

   !> The elements whose cell's dimension differs from the first element's.
   function other_dimension(model) result(elements)
      type(model_t), intent(in) :: model
      integer, allocatable :: elements(:)
      integer :: e
      elements = pack([(e, e=1, model%mesh%n_elements)], &
                      [(model%mesh%cell_dimension(e) /= model%mesh%cell_dimension(1), e=1, model%mesh%n_elements)])
   end function other_dimension

   !> Whether `node` is the reference or rotation node of a coupling (these carry conditions
   !> and loads without an element).
   logical function reference_or_rotation(model, node)
      type(model_t), intent(in) :: model
      integer, intent(in) :: node
      integer :: k
      reference_or_rotation = .false.
      do k = 1, size(model%couplings)
         if (any([model%couplings(k)%reference_node, model%couplings(k)%rotation_node] == node)) &
            reference_or_rotation = .true.
      end do
   end function reference_or_rotation

   !> One message per deck line that created offending elements, naming the first of them.
   subroutine report_elements(reader, model, elements, what)
      type(deck_reader_t), intent(inout) :: reader
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
