!> The mesh of a deck: MESH FILE (gmsh .msh, or Abaqus/CalculiX .inp), NODE COORDS, MESH BLOCK, then NODE SETS and SURFACES
!> (docs/deck-format.md). The element lines of STRUCTURE ELEMENTS are read with the element
!> properties (frix_deck_properties).
module frix_deck_mesh
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string, to_lower
   use frix_mesh, only: mesh_t, node_set_t, surface_t, connectivity_rows
   use frix_id_map, only: id_map_t
   use frix_mesh_checks, only: merge_meshes, mesh_bounding_box
   use frix_mesh_selection, only: nodes_in_box, boundary_faces_in_box, sorted_unique
   use frix_gmsh_reader, only: read_gmsh
   use frix_inp_reader, only: read_inp
   use frix_block_generator, only: generate_block
   use frix_model, only: model_t
   use frix_deck_tokens, only: deck_line_t
   use frix_deck_context, only: deck_reader_t, require, extend_origins, extend_properties, box_tolerance, &
                                resume_position, after_keyword, s_mesh_file, s_node_coords, s_mesh_block, &
                                s_node_sets, s_surfaces
   implicit none
   private

   public :: read_mesh_file, read_node_coords, read_mesh_blocks, finish_mesh_numbering
   public :: read_node_sets, read_surfaces

   !> The keywords of a MESH BLOCK line after its name.
   character(len=14), parameter :: block_keywords(5) = [character(len=14) :: 'ORIGIN', 'SIZE', 'DIVISIONS', &
      'NODE_OFFSET', 'ELEMENT_OFFSET']

contains

   !> `FILE <path>` (relative to the deck's directory): the base of the mesh, an Abaqus/CalculiX
   !> .inp file if the name ends in `.inp` (any case), else a gmsh mesh.
   subroutine read_mesh_file(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      integer :: i, position, n_files
      logical :: ok
      character(len=:), allocatable :: file, full_path
      type(error_t), allocatable :: error
      n_files = 0
      i = 0
      do while (reader%next_line(s_mesh_file, i, position, ok))
         associate (line => reader%lines(i))
            call reader%expect_keyword(line, position, 'FILE', ok)
            call reader%take_word(line, position, 'a mesh file name', file, ok)
            call reader%expect_end(line, position, ok, 'unexpected text after the file name')
            if (.not. ok) cycle
            n_files = n_files + 1
            if (n_files > 1) then
               call reader%report(line, 2, 'only one mesh FILE is allowed')
               cycle
            end if
            full_path = file
            if (file(1:1) /= '/') full_path = reader%directory//file
            if (is_inp_file(file)) then
               call read_inp(full_path, model%mesh, error)
            else
               call read_gmsh(full_path, model%mesh, error)
            end if
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

   !> True if `file` names an Abaqus/CalculiX input file (extension .inp, any case).
   pure logical function is_inp_file(file)
      character(len=*), intent(in) :: file
      is_inp_file = .false.
      if (len(file) > 4) is_inp_file = to_lower(file(len(file) - 3:)) == '.inp'
   end function is_inp_file

   !> A mesh with no nodes and no elements, every array allocated.
   subroutine empty_mesh(mesh)
      type(mesh_t), intent(out) :: mesh
      allocate (mesh%coords(3, 0), mesh%node_ids(0), mesh%connectivity(connectivity_rows([integer ::]), 0))
      allocate (mesh%element_ids(0), mesh%element_block(0), mesh%node_sets(0), mesh%element_sets(0), mesh%surfaces(0))
      call mesh%set_cells([integer ::])
   end subroutine empty_mesh

   !> `NODE <id> COORD x y z`.
   subroutine read_node_coords(reader, model)
      type(deck_reader_t), intent(inout) :: reader
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
      allocate (extra%connectivity(connectivity_rows([integer ::]), 0), extra%element_ids(0), extra%element_block(0))
      n = 0
      i = 0
      do while (reader%next_line(s_node_coords, i, position, ok))
         associate (line => reader%lines(i))
            call reader%expect_keyword(line, position, 'NODE', ok)
            call reader%take_integer(line, position, 'a node id', id, ok)
            call reader%expect_keyword(line, position, 'COORD', ok)
            call reader%take_reals(line, position, 'a coordinate', x, ok)
            call reader%expect_end(line, position, ok, 'unexpected text after the coordinates')
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

   !> `BLOCK <name> ORIGIN x y z SIZE lx ly lz DIVISIONS nx ny nz [NODE_OFFSET n]
   !> [ELEMENT_OFFSET n]` (lz 0 and nz 0: a plane block of QUAD4): node ids start at NODE_OFFSET + 1 (default: after the largest
   !> existing id), likewise elements.
   subroutine read_mesh_blocks(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(mesh_t) :: block
      type(error_t), allocatable :: error
      character(len=:), allocatable :: name
      real(dp) :: origin(3), lengths(3)
      integer :: divisions(3), node_offset, element_offset, i, position, k
      integer :: start
      logical :: ok, has(3), line_ok
      i = 0
      do while (reader%next_line(s_mesh_block, i, position, ok))
         associate (line => reader%lines(i))
            call reader%expect_keyword(line, position, 'BLOCK', ok)
            call reader%take_word(line, position, 'a block name', name, ok)
            node_offset = 0
            element_offset = 0
            if (model%mesh%n_nodes > 0) node_offset = maxval(model%mesh%node_ids)
            if (model%mesh%n_elements > 0) element_offset = maxval(model%mesh%element_ids)
            has = .false.
            line_ok = ok
            if (.not. ok) position = resume_position(line, position, block_keywords)
            do while (position <= line%n_tokens())
               start = position
               ok = .true.
               select case (line%keyword(position))
               case ('ORIGIN')
                  position = position + 1
                  call reader%take_reals(line, position, 'an ORIGIN coordinate', origin, ok)
                  has(1) = .true.
               case ('SIZE')
                  position = position + 1
                  k = position
                  call reader%take_reals(line, position, 'a SIZE length', lengths, ok)
                  call require(reader, ok, all(lengths(1:2) > 0.0_dp) .and. lengths(3) >= 0.0_dp, line, k, &
                               'SIZE lengths must be positive (lz 0 for a plane block)')
                  has(2) = .true.
               case ('DIVISIONS')
                  position = position + 1
                  k = position
                  do while (position < k + 3 .and. ok)
                     call reader%take_integer(line, position, 'a DIVISIONS count', divisions(position - k + 1), ok)
                  end do
                  call require(reader, ok, all(divisions(1:2) >= 1) .and. divisions(3) >= 0, line, k, &
                               'DIVISIONS must be at least 1 (nz 0 for a plane block)')
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
               call after_keyword(line, start, block_keywords, position, ok, line_ok)
            end do
            ok = line_ok
            if (ok .and. .not. all(has)) then
               call reader%report(line, line%n_tokens() + 1, 'a BLOCK needs ORIGIN, SIZE and DIVISIONS')
               ok = .false.
            end if
            if (ok .and. ((divisions(3) == 0) .neqv. (lengths(3) == 0.0_dp))) then
               call reader%report(line, 2, 'a plane block (QUAD4) has both SIZE lz 0 and DIVISIONS nz 0')
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
      type(deck_reader_t), intent(inout) :: reader
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

   !> `SET <name> NODES id ...` or `SET <name> BOX xmin ymin zmin xmax ymax zmax`.
   subroutine read_node_sets(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(node_set_t) :: set
      integer, allocatable :: nodes(:)
      character(len=:), allocatable :: name
      real(dp) :: box(6)
      integer :: i, k, n, position, id
      logical :: ok
      i = 0
      do while (reader%next_line(s_node_sets, i, position, ok))
         associate (line => reader%lines(i))
            call read_selection_head(reader, model, line, .false., name, position, ok)
            if (.not. ok) cycle
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
            call reader%expect_end(line, position, ok)
            if (ok) then
               set%name = name
               set%nodes = sorted_unique(nodes)
               model%mesh%node_sets = [model%mesh%node_sets, set]
            end if
            if (allocated(nodes)) deallocate (nodes)
         end associate
      end do
   end subroutine read_node_sets

   !> `SET <name>` (node set) or `SURF <name>` (`surface`) from token `position` on, and the
   !> presence of the selection keyword after it (then at `position`); the name must be new.
   !> ok false after a report.
   subroutine read_selection_head(reader, model, line, surface, name, position, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      logical, intent(in) :: surface
      character(len=:), allocatable, intent(out) :: name
      integer, intent(inout) :: position
      logical, intent(inout) :: ok
      character(len=*), parameter :: keyword(2) = ['SET ', 'SURF'], kind(2) = ['node set', 'surface ']
      character(len=*), parameter :: choices(2) = ['NODES or BOX', 'BOX or FACES']
      integer :: k
      k = merge(2, 1, surface)
      call reader%expect_keyword(line, position, trim(keyword(k)), ok)
      call reader%take_word(line, position, 'a '//trim(kind(k))//' name', name, ok)
      if (ok) then
         if (surface) ok = model%mesh%find_surface(name) == 0
         if (.not. surface) ok = model%mesh%find_node_set(name) == 0
         if (.not. ok) call reader%report(line, 2, trim(kind(k))//' already defined')
      end if
      if (ok .and. position > line%n_tokens()) then
         call reader%report(line, position, 'missing '//choices(k))
         ok = .false.
      end if
   end subroutine read_selection_head

   !> Six reals xmin ymin zmin xmax ymax zmax with min <= max.
   subroutine read_box(reader, line, position, box, ok)
      type(deck_reader_t), intent(inout) :: reader
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

   !> `SURF <name> BOX xmin ymin zmin xmax ymax zmax` or `SURF <name> FACES e f e f ...`.
   subroutine read_surfaces(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(surface_t) :: surface
      character(len=:), allocatable :: name
      real(dp) :: box(6)
      integer :: i, k, n, position, id, face
      logical :: ok
      i = 0
      do while (reader%next_line(s_surfaces, i, position, ok))
         associate (line => reader%lines(i))
            call read_selection_head(reader, model, line, .true., name, position, ok)
            if (.not. ok) cycle
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
            call reader%expect_end(line, position, ok)
            if (.not. ok) cycle
            surface%name = name
            model%mesh%surfaces = [model%mesh%surfaces, surface]
         end associate
      end do
   end subroutine read_surfaces
end module frix_deck_mesh
