!> Materials and element properties of a deck: MATERIALS, and STRUCTURE ELEMENTS (element
!> lines, which also define elements, and SET lines); every (formulation, material) pair in use
!> becomes an element block (docs/deck-format.md). Laws and formulations come from their
!> registries (frix_material_registry, frix_element_registry).
module frix_deck_properties
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string, to_upper
   use frix_property_list, only: property_list_t, keyword_index, spec_names
   use frix_material, only: material_slot_t
   use frix_material_registry, only: create_material
   use frix_element, only: element_t
   use frix_element_registry, only: element_shape_t, create_element, find_element_shape, &
                                    element_shape_choices, element_shape_example
   use frix_id_map, only: id_map_t
   use frix_model, only: model_t
   use frix_mesh, only: cell_index, connectivity_rows
   use frix_cell_registry, only: max_cell_nodes
   use frix_deck_tokens, only: deck_line_t
   use frix_deck_context, only: deck_reader_t, property_t, require, extend_origins, extend_properties, &
                                one_line, line_integer, after_keyword, s_materials, s_elements
   implicit none
   private

   public :: read_materials, read_element_lines, read_element_set_lines, create_blocks

contains

   ! ---- MATERIALS ------------------------------------------------------------------------

   !> `MAT <id> <law> <PROPERTY> <value> ...` -> create_material.
   subroutine read_materials(reader, model)
      type(deck_reader_t), intent(inout) :: reader
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
      i = 0
      do while (reader%next_line(s_materials, i, position, ok))
         associate (line => reader%lines(i))
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

   !> `<id> SOLID <shape> n1 .. nk MAT <m> [<option> <value> ...] [KINTYP Geo_Lin|Tot_Lagr]`, k
   !> and the options as the element registry gives them (SET lines are read later, by
   !> read_element_set_lines).
   subroutine read_element_lines(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      integer, allocatable :: connectivity(:, :), ids(:), properties(:), origin(:), cells(:)
      integer :: i, position, id, n, existing, capacity, property, first_node, rows, e
      logical :: ok
      type(id_map_t) :: element_ids
      type(element_shape_t) :: shape

      call reader%node_map%build(model%mesh%node_ids, existing)
      call element_ids%build(model%mesh%element_ids, existing)
      capacity = max(reader%last(s_elements) - reader%first(s_elements) + 1, 0)
      allocate (connectivity(max_cell_nodes(), capacity), source=0)   ! rows for any cell
      allocate (ids(capacity), properties(capacity), origin(capacity), cells(capacity))
      n = 0
      i = 0
      do while (reader%next_line(s_elements, i, position, ok))
         associate (line => reader%lines(i))
            if (line%keyword(1) == 'SET') cycle
            call reader%take_integer(line, position, 'an element id', id, ok)
            first_node = position + 2
            call read_property(reader, model, line, position, .true., property, shape, ok)
            if (ok) call read_element_nodes(reader, line, first_node, shape, connectivity(:, n + 1), ok)
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
            cells(n) = cell_index(trim(shape%cell))
         end associate
      end do
      if (n == 0) return
      associate (mesh => model%mesh)
         ! rows for the new elements' cells too (frix_mesh)
         call mesh%widen_connectivity(connectivity_rows(cells(1:n)))
         rows = size(mesh%connectivity, 1)
         mesh%connectivity = reshape([mesh%connectivity, connectivity(1:rows, 1:n)], [rows, mesh%n_elements + n])
         mesh%element_ids = [mesh%element_ids, ids(1:n)]
         call mesh%set_cells([(mesh%cell_of(e), e=1, mesh%n_elements), cells(1:n)])
         mesh%element_block = [mesh%element_block, spread(0, 1, n)]
         call extend_origins(reader%element_line, reader%element_token, mesh%n_elements, 0, 1)
         reader%element_line = [reader%element_line, origin(1:n)]
         reader%element_token = [reader%element_token, spread(1, 1, n)]
         call extend_properties(reader, mesh%n_elements)
         reader%element_property = [reader%element_property, properties(1:n)]
         mesh%n_elements = mesh%n_elements + n
      end associate
   end subroutine read_element_lines

   !> The node ids of an element line: the tokens from `first_node` to the first keyword of
   !> the line, as many as the shape has -> internal node numbers.
   subroutine read_element_nodes(reader, line, first_node, shape, nodes, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(deck_line_t), intent(in) :: line
      integer, intent(in) :: first_node
      type(element_shape_t), intent(in) :: shape
      integer, intent(out) :: nodes(:)
      logical, intent(inout) :: ok
      integer :: k, position, n_node_tokens, id
      nodes = 0
      n_node_tokens = 0
      do k = first_node, line%n_tokens()
         if (ends_node_list(line%keyword(k), shape)) exit
         n_node_tokens = n_node_tokens + 1
      end do
      if (n_node_tokens /= shape%n_nodes) then
         call reader%report(line, first_node - 1, 'wrong node count: '//trim(shape%family)//' needs '// &
                            to_string(shape%n_nodes)//' nodes, found '//to_string(n_node_tokens))
         ok = .false.
         return
      end if
      position = first_node
      do k = 1, shape%n_nodes
         call reader%take_integer(line, position, 'a node id', id, ok)
         if (.not. ok) return
         nodes(k) = reader%node_map%lookup(id)
         if (nodes(k) == 0) then
            ok = .false.
            if (.not. reader%mesh_failed) call reader%report(line, position - 1, 'undefined node '//to_string(id))
            return
         end if
      end do
   end subroutine read_element_nodes

   !> Whether `keyword` ends the node ids of an element line: MAT, KINTYP or an option of the shape.
   pure logical function ends_node_list(keyword, shape)
      character(len=*), intent(in) :: keyword
      type(element_shape_t), intent(in) :: shape
      ends_node_list = keyword == 'MAT' .or. keyword == 'KINTYP' .or. keyword_index(spec_names(shape%options), keyword) > 0
   end function ends_node_list

   !> Reads `SOLID <shape> [nodes] MAT <m> [<option> <value> ...] [KINTYP <kin>]` starting at
   !> the family token; with `has_nodes` the node tokens after the shape are skipped (read by
   !> the caller). Returns the index of the (shape, options, kinematics, material) property.
   subroutine read_property(reader, model, line, position, has_nodes, property, shape, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      logical, intent(in) :: has_nodes
      integer, intent(out) :: property
      type(element_shape_t), intent(out) :: shape
      logical, intent(inout) :: ok
      type(property_t) :: candidate
      character(len=:), allocatable :: family, word
      logical :: known
      property = 0
      call reader%take_word(line, position, 'an element family (SOLID)', family, ok)
      if (ok .and. to_upper(family) /= 'SOLID') then
         call reader%report(line, position - 1, 'unknown element family (expected SOLID)')
         ok = .false.
      end if
      candidate%token = position
      call reader%take_word(line, position, 'an element shape ('//element_shape_example()//')', word, ok)
      if (.not. ok) return
      call find_element_shape(word, shape, known)
      if (.not. known) then
         call reader%report(line, candidate%token, 'unknown element shape (expected '//element_shape_choices()//')')
         ok = .false.
         return
      end if
      if (has_nodes) then
         do while (position <= line%n_tokens())
            if (ends_node_list(line%keyword(position), shape)) exit
            position = position + 1
         end do
      end if
      candidate%shape = trim(shape%keyword)
      candidate%kinematics = model%controls%default_kinematics
      candidate%line = line%number
      call read_property_pairs(reader, model, line, position, shape, candidate, ok)
      if (.not. ok) return
      call name_formulation(candidate)
      property = find_property(reader, candidate)
      if (property > 0) return
      call append_property(reader%properties, candidate)
      reader%n_properties = reader%n_properties + 1
      property = reader%n_properties
   end subroutine read_property

   !> The `MAT <m>`, `KINTYP <kin>` and shape option pairs of an element line into `candidate`.
   !> After a mistake the line is read on from its next keyword, so that every mistake of the
   !> line is reported.
   subroutine read_property_pairs(reader, model, line, position, shape, candidate, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      type(element_shape_t), intent(in) :: shape
      type(property_t), intent(inout) :: candidate
      logical, intent(inout) :: ok
      character(len=32), allocatable :: keywords(:)
      integer :: start
      logical :: has_material, line_ok
      keywords = [character(len=32) :: 'MAT', 'KINTYP', spec_names(shape%options)]
      has_material = .false.
      line_ok = ok
      do while (position <= line%n_tokens())
         start = position
         ok = .true.
         call read_property_pair(reader, model, line, position, shape, candidate, has_material, ok)
         call after_keyword(line, start, keywords, position, ok, line_ok)
      end do
      ok = line_ok
      if (ok .and. .not. has_material) then
         call reader%report(line, line%n_tokens() + 1, 'missing MAT <id>')
         ok = .false.
      end if
   end subroutine read_property_pairs

   !> One keyword of an element line at `position` with its value into `candidate`
   !> (`has_material` set by MAT).
   subroutine read_property_pair(reader, model, line, position, shape, candidate, has_material, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      type(element_shape_t), intent(in) :: shape
      type(property_t), intent(inout) :: candidate
      logical, intent(inout) :: has_material
      logical, intent(inout) :: ok
      integer :: material_id, option
      position = position + 1
      select case (line%keyword(position - 1))
      case ('MAT')
         call reader%take_integer(line, position, 'a material id', material_id, ok)
         if (.not. ok) return
         has_material = .true.
         candidate%material = findloc(model%material_ids, material_id, dim=1)
         if (candidate%material == 0) then
            ok = .false.
            if (.not. any(reader%failed_material_ids == material_id)) &
               call reader%report(line, position - 1, 'undefined material '//to_string(material_id))
         end if
      case ('KINTYP')
         call reader%take_kinematics(line, position, candidate%kinematics, ok)
      case default
         option = keyword_index(spec_names(shape%options), line%keyword(position - 1))
         if (option == 0) then
            call reader%report(line, position - 1, 'unknown keyword on an element line')
            ok = .false.
         else
            call reader%take_property(line, position, shape%options(option), candidate%options, ok)
         end if
      end select
   end subroutine read_property_pair

   !> `candidate%formulation`: the name of the element its shape, options and kinematics make,
   !> empty when they make none (the options are then compared instead).
   subroutine name_formulation(candidate)
      type(property_t), intent(inout) :: candidate
      class(element_t), allocatable :: element
      type(error_t), allocatable :: error
      call create_element(candidate%shape, candidate%options, candidate%kinematics, element, error)
      candidate%formulation = ''
      if (.not. allocated(error)) candidate%formulation = element%name
   end subroutine name_formulation

   !> The property equal to `candidate` (same shape, kinematics, material and formulation, or
   !> the same options where the formulation is invalid), 0 if none.
   integer function find_property(reader, candidate) result(property)
      type(deck_reader_t), intent(in) :: reader
      type(property_t), intent(in) :: candidate
      do property = 1, reader%n_properties
         associate (p => reader%properties(property))
            if (p%shape /= candidate%shape .or. p%kinematics /= candidate%kinematics .or. &
                p%material /= candidate%material .or. p%formulation /= candidate%formulation) cycle
            if (len(p%formulation) > 0 .or. p%options%same_as(candidate%options)) return
         end associate
      end do
      property = 0
   end function find_property

   !> `properties` with `property` appended, through a longer copy and move_alloc rather than
   !> `properties = [properties, property]`: gfortran 12 leaks the allocatable components of
   !> a structure inside an array constructor.
   subroutine append_property(properties, property)
      type(property_t), allocatable, intent(inout) :: properties(:)
      type(property_t), intent(in) :: property
      type(property_t), allocatable :: grown(:)
      integer :: n
      n = 0
      if (allocated(properties)) n = size(properties)
      allocate (grown(n + 1))
      if (n > 0) grown(1:n) = properties
      grown(n + 1) = property
      call move_alloc(grown, properties)
   end subroutine append_property

   !> `SET <element set> SOLID <shape> MAT <m> [EAS <k>] [KINTYP <kin>]`.
   subroutine read_element_set_lines(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      character(len=:), allocatable :: name
      integer :: i, k, position, set, property, element
      logical :: ok
      type(element_shape_t) :: shape
      i = 0
      do while (reader%next_line(s_elements, i, position, ok))
         associate (line => reader%lines(i))
            if (line%keyword(1) /= 'SET') cycle
            position = 2
            call reader%take_word(line, position, 'an element set name', name, ok)
            set = 0
            if (ok) set = model%mesh%find_element_set(name)
            if (ok .and. set == 0) then
               ok = .false.
               if (.not. reader%mesh_failed) call reader%report(line, 2, 'unknown element set')
            end if
            call read_property(reader, model, line, position, .false., property, shape, ok)
            if (.not. ok) then
               reader%property_failed = .true.
               cycle
            end if
            do k = 1, size(model%mesh%element_sets(set)%elements)
               element = model%mesh%element_sets(set)%elements(k)
               if (model%mesh%cell_name(element) /= trim(shape%cell)) then
                  ! a formulation is written for one cell type (the element registry's entry)
                  call reader%report(line, 4, 'element '//to_string(model%mesh%element_ids(element))// &
                                     ' of set "'//name//'" is a '//model%mesh%cell_name(element)//', element shape '// &
                                     trim(shape%keyword)//' is for '//trim(shape%cell)//' cells')
                  reader%property_failed = .true.
                  exit
               end if
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

   !> One element block per property in use (in the order of first use), each element's block,
   !> and the elements that have no property (`missing`).
   subroutine create_blocks(reader, model, missing)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      integer, allocatable, intent(out) :: missing(:)
      integer, allocatable :: block_of_property(:)
      type(error_t), allocatable :: error
      integer :: k, e, n_blocks
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
            call create_element(p%shape, p%options, p%kinematics, block%element%formulation, error)
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
   end subroutine create_blocks
end module frix_deck_properties
