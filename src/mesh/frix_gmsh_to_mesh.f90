!> The content of a gmsh .msh file (`raw_mesh_t`, read by frix_gmsh_reader) made a `mesh_t`.
!> The mesh's dimension is the highest of its cells and physical groups: 3 with volume
!> elements, 2 without (a plane mesh, in the x-y plane: every node's z must be 0).
!> The elements are the cells of that dimension, in file order (an element that format 2.2
!> writes once per physical group kept once): 8-node hexahedra, HEX8, 4-node tetrahedra,
!> TET4, and 10-node tetrahedra, TET10 (their nodes put in the cell's order), in 3D;
!> 4-node quadrilaterals, QUAD4, and 3-node triangles, TRI3, in 2D.
!> One node set per physical group; one element set per physical group of the mesh's
!> dimension (volume, or surface of a plane mesh), and one surface per physical group one
!> dimension lower (a surface: each quadrilateral or 3- or 6-node triangle matched to the
!> boundary face of a volume element with the same nodes; a curve of a plane mesh: each 2-node
!> line matched to the boundary edge of a plane element). Sets are in ascending (dim, tag)
!> order and named from `$PhysicalNames`, else "<dim>:<tag>". Errors name the file and the
!> line of the element or node concerned.
module frix_gmsh_to_mesh
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_id_map, only: id_map_t
   use frix_mesh, only: mesh_t, connectivity_rows
   use frix_cell_registry, only: cell_entry_t, cell_table, max_cell_nodes
   use frix_mesh_checks, only: node_to_elements
   use frix_mesh_selection, only: sort_nodes
   use frix_gmsh_context, only: is_element_cell, is_boundary_cell, first_off_plane, off_plane_message, &
                                raw_mesh_t
   implicit none
   private

   public :: build_mesh

contains

   !> Turn the raw content into `mesh`: node numbering, elements, sets and surfaces.
   subroutine build_mesh(file_name, raw, mesh, error)
      character(len=*), intent(in) :: file_name
      type(raw_mesh_t), intent(in) :: raw
      type(mesh_t), intent(out) :: mesh
      type(error_t), allocatable, intent(out) :: error
      type(id_map_t) :: node_map
      integer, allocatable :: record_element(:), group_offsets(:), group_records(:)
      integer :: element_dim

      element_dim = mesh_dimension(raw)
      call number_nodes(file_name, raw, node_map, mesh, error)
      if (allocated(error)) return
      if (element_dim == 2) call check_plane_nodes(file_name, raw, error)
      if (allocated(error)) return
      call collect_elements(file_name, raw, element_dim, node_map, mesh, record_element, error)
      if (allocated(error)) return
      call merge_copies(mesh, record_element)
      allocate (mesh%element_block(mesh%n_elements), source=0)
      call index_group_records(raw, group_offsets, group_records)
      call check_group_types(file_name, raw, element_dim, error)
      if (allocated(error)) return
      ! groups in ascending (dim, tag) order
      call build_sets(file_name, raw, element_dim, sorted_group_order(raw), group_offsets, group_records, &
                      record_element, node_map, mesh, error)
   end subroutine build_mesh

   !> The dimension of the mesh: 3 if the file has a volume cell or a physical volume, else 2
   !> if it has a plane cell (quadrilateral, triangle) or a physical surface; 3 for a file
   !> with neither (no elements: node sets only).
   integer function mesh_dimension(raw) result(dim)
      type(raw_mesh_t), intent(in) :: raw
      integer :: r
      dim = 0
      if (raw%group_dims%count > 0) dim = maxval(raw%group_dims%items(1:raw%group_dims%count))
      do r = 1, raw%record_ids%count
         if (is_element_cell(raw%record_types%items(r), 3)) dim = 3
         if (is_element_cell(raw%record_types%items(r), 2)) dim = max(dim, 2)
      end do
      if (dim < 2) dim = 3
   end function mesh_dimension

   !> The nodes of a plane mesh lie in the x-y plane (first_off_plane): error naming the
   !> coordinate line of the first that does not.
   subroutine check_plane_nodes(file_name, raw, error)
      character(len=*), intent(in) :: file_name
      type(raw_mesh_t), intent(in) :: raw
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      i = first_off_plane(raw%coords(:, 1:raw%n_nodes))
      if (i /= 0) call fatal_error(error, file_name//':'//to_string(raw%coordinate_lines(i))//': '// &
                                   off_plane_message(raw%node_ids(i), raw%coords(3, i)))
   end subroutine check_plane_nodes

   !> The nodes of the mesh, in file order; their ids must be unique.
   subroutine number_nodes(file_name, raw, node_map, mesh, error)
      character(len=*), intent(in) :: file_name
      type(raw_mesh_t), intent(in) :: raw
      type(id_map_t), intent(inout) :: node_map
      type(mesh_t), intent(inout) :: mesh
      type(error_t), allocatable, intent(out) :: error
      integer :: duplicate
      call node_map%build(raw%node_ids(1:raw%n_nodes), duplicate)
      if (duplicate /= 0) then
         call fatal_error(error, file_name//':'//to_string(raw%node_lines(duplicate))//': duplicate node id '// &
                          to_string(raw%node_ids(duplicate))//' (first defined on line '// &
                          to_string(raw%node_lines(node_map%lookup(raw%node_ids(duplicate))))//')')
         return
      end if
      mesh%n_nodes = raw%n_nodes
      mesh%node_ids = raw%node_ids(1:raw%n_nodes)
      mesh%coords = raw%coords(:, 1:raw%n_nodes)
   end subroutine number_nodes

   !> The elements (the cells of dimension `element_dim`), in file order; records with the
   !> same id must have the same nodes. `record_element(r)` is the element of record r (0 for
   !> other records).
   subroutine collect_elements(file_name, raw, element_dim, node_map, mesh, record_element, error)
      character(len=*), intent(in) :: file_name
      type(raw_mesh_t), intent(in) :: raw
      integer, intent(in) :: element_dim
      type(id_map_t), intent(in) :: node_map
      type(mesh_t), intent(inout) :: mesh
      integer, allocatable, intent(out) :: record_element(:)
      type(error_t), allocatable, intent(out) :: error
      type(id_map_t) :: element_map
      type(cell_entry_t), allocatable :: table(:)
      integer, allocatable :: nodes(:), cells(:), row(:), cell_of_type(:)
      integer :: n_records, n_cells, r, element, existing, cell
      table = cell_table()
      cell_of_type = cells_of_gmsh_types()
      n_records = raw%record_ids%count
      n_cells = count([(is_element_cell(raw%record_types%items(r), element_dim), r=1, n_records)])
      ! rows for any cell, cut to the mesh's cells' at the end
      allocate (mesh%connectivity(max_cell_nodes(), n_cells), mesh%element_ids(n_cells), record_element(n_records))
      allocate (cells(n_cells), row(max_cell_nodes()))
      record_element = 0
      call element_map%clear(n_cells)
      element = 0
      do r = 1, n_records
         if (.not. is_element_cell(raw%record_types%items(r), element_dim)) cycle
         call record_nodes(file_name, raw, r, node_map, nodes, error)
         if (allocated(error)) return
         cell = cell_of_type(raw%record_types%items(r))
         ! gmsh's node order made the cell's (frix_tet10_cell: TET10's nodes 9 and 10)
         if (allocated(table(cell)%cell%gmsh_nodes)) nodes = nodes(table(cell)%cell%gmsh_nodes)
         row = 0
         row(1:size(nodes)) = nodes
         call element_map%insert(raw%record_ids%items(r), element + 1, existing)
         if (existing /= 0) then
            if (any(mesh%connectivity(:, existing) /= row)) then
               call fail_at_record(file_name, raw, r, error, 'duplicate element id '// &
                                   to_string(raw%record_ids%items(r))//' with different nodes')
               return
            end if
            record_element(r) = existing
         else
            element = element + 1
            mesh%connectivity(:, element) = row
            mesh%element_ids(element) = raw%record_ids%items(r)
            cells(element) = cell
            record_element(r) = element
         end if
      end do
      mesh%n_elements = element
      mesh%connectivity = mesh%connectivity(1:connectivity_rows(cells(1:element)), 1:element)
      mesh%element_ids = mesh%element_ids(1:element)
      call mesh%set_cells(cells(1:element))
   end subroutine collect_elements

   !> The index in the cell table of the cell of each gmsh element type code, 0 for a type
   !> without a cell, (largest code of a cell).
   function cells_of_gmsh_types() result(cells)
      integer, allocatable :: cells(:)
      type(cell_entry_t), allocatable :: table(:)
      integer :: k
      table = cell_table()
      allocate (cells(maxval([(table(k)%cell%gmsh_type, k=1, size(table))])), source=0)
      do k = 1, size(table)
         if (table(k)%cell%gmsh_type > 0) cells(table(k)%cell%gmsh_type) = k
      end do
   end function cells_of_gmsh_types

   !> Format 2.2 writes an element once per physical group holding it, each copy with an id
   !> of its own (gmsh 4.8): keep the first of elements with identical node lists, and point
   !> the records of the others to it. Found through the elements around each first node.
   subroutine merge_copies(mesh, record_element)
      type(mesh_t), intent(inout) :: mesh
      integer, intent(inout) :: record_element(:)
      integer, allocatable :: offsets(:), adjacency(:), new_number(:)
      integer :: element, k, other, n_kept
      call node_to_elements(mesh, offsets, adjacency)
      allocate (new_number(mesh%n_elements))
      n_kept = 0
      do element = 1, mesh%n_elements
         new_number(element) = 0
         do k = offsets(mesh%connectivity(1, element)), offsets(mesh%connectivity(1, element) + 1) - 1
            other = adjacency(k)
            if (other >= element) exit
            if (all(mesh%connectivity(:, other) == mesh%connectivity(:, element))) then
               new_number(element) = new_number(other)
               exit
            end if
         end do
         if (new_number(element) == 0) then
            n_kept = n_kept + 1
            new_number(element) = n_kept
         end if
      end do
      if (n_kept == mesh%n_elements) return
      ! compact (new_number(e) <= e, and kept elements keep their order)
      n_kept = 0
      do element = 1, mesh%n_elements
         if (new_number(element) /= n_kept + 1) cycle   ! a copy of an earlier element
         n_kept = n_kept + 1
         mesh%connectivity(:, n_kept) = mesh%connectivity(:, element)
         mesh%element_ids(n_kept) = mesh%element_ids(element)
         mesh%element_cell(n_kept) = mesh%element_cell(element)
      end do
      where (record_element > 0) record_element = new_number(max(record_element, 1))
      mesh%n_elements = n_kept
      mesh%connectivity = mesh%connectivity(:, 1:n_kept)
      mesh%element_ids = mesh%element_ids(1:n_kept)
      mesh%element_cell = mesh%element_cell(1:n_kept)
   end subroutine merge_copies

   !> Records of each group, compressed: group g holds
   !> group_records(group_offsets(g):group_offsets(g+1)-1).
   subroutine index_group_records(raw, group_offsets, group_records)
      type(raw_mesh_t), intent(in) :: raw
      integer, allocatable, intent(out) :: group_offsets(:), group_records(:)
      integer, allocatable :: next(:)
      integer :: n_groups, a, g, r, k
      n_groups = raw%group_dims%count
      allocate (group_offsets(n_groups + 1))
      group_offsets = 0
      do a = 1, raw%record_groups%count
         g = raw%record_groups%items(a)
         group_offsets(g + 1) = group_offsets(g + 1) + 1
      end do
      group_offsets(1) = 1
      do a = 1, n_groups
         group_offsets(a + 1) = group_offsets(a + 1) + group_offsets(a)
      end do
      allocate (group_records(group_offsets(n_groups + 1) - 1))
      next = group_offsets(1:n_groups)
      do r = 1, raw%record_ids%count
         do k = raw%record_group_first%items(r), raw%record_group_first%items(r + 1) - 1
            g = raw%record_groups%items(k)
            group_records(next(g)) = r
            next(g) = next(g) + 1
         end do
      end do
   end subroutine index_group_records

   !> Element types of the groups of the mesh's dimension `element_dim` (elements) and one
   !> lower (boundary cells): the elements first, since a wrong element type (2nd order) is
   !> the cause of a wrong boundary type.
   subroutine check_group_types(file_name, raw, element_dim, error)
      character(len=*), intent(in) :: file_name
      type(raw_mesh_t), intent(in) :: raw
      integer, intent(in) :: element_dim
      type(error_t), allocatable, intent(out) :: error
      integer :: dim, r, k
      logical :: accepted
      do dim = element_dim, element_dim - 1, -1
         do r = 1, raw%record_ids%count
            do k = raw%record_group_first%items(r), raw%record_group_first%items(r + 1) - 1
               if (raw%group_dims%items(raw%record_groups%items(k)) /= dim) cycle
               associate (element_type => raw%record_types%items(r), id => raw%record_ids%items(r))
                  if (dim == element_dim) then
                     accepted = is_element_cell(element_type, element_dim)
                  else
                     accepted = is_boundary_cell(element_type, element_dim)
                  end if
                  if (.not. accepted) then
                     call fail_at_record(file_name, raw, r, error, supported_types(element_dim, dim)// &
                                         ': element '//to_string(id)//' has type '//to_string(element_type))
                     return
                  end if
               end associate
            end do
         end do
      end do
   end subroutine check_group_types

   !> The gmsh element types a physical group of dimension `dim` may hold in a mesh of
   !> dimension `element_dim` (is_element_cell, is_boundary_cell), for messages.
   function supported_types(element_dim, dim) result(text)
      integer, intent(in) :: element_dim, dim
      character(len=:), allocatable :: text
      if (element_dim == 3 .and. dim == 3) then
         text = 'only 8-node hexahedra (type 5), 4-node tetrahedra (type 4) and 10-node tetrahedra (type 11) '// &
                'are supported'
      else if (element_dim == 3) then
         text = 'only 4-node quadrilaterals (type 3), 3-node triangles (type 2) and 6-node triangles (type 9) '// &
                'are supported on surfaces'
      else if (dim == 2) then
         text = 'only 4-node quadrilaterals (type 3) and 3-node triangles (type 2) are supported in a plane '// &
                'mesh (no volume elements)'
      else
         text = 'only 2-node lines (type 1) are supported on the curves of a plane mesh (no volume elements)'
      end if
   end function supported_types

   !> Node sets, element sets and surfaces of the physical groups, in the given order (element
   !> types already checked: elements in the groups of dimension `element_dim`, boundary cells
   !> in those one lower).
   subroutine build_sets(file_name, raw, element_dim, order, group_offsets, group_records, record_element, &
                         node_map, mesh, error)
      character(len=*), intent(in) :: file_name
      type(raw_mesh_t), intent(in) :: raw
      integer, intent(in) :: element_dim
      integer, intent(in) :: order(:), group_offsets(:), group_records(:), record_element(:)
      type(id_map_t), intent(in) :: node_map
      type(mesh_t), intent(inout) :: mesh
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: node_stamp(:), element_stamp(:), face_stamp(:), nodes(:)
      integer, allocatable :: adjacency_offsets(:), adjacency(:)
      integer :: n_volumes, n_surfaces, i, g, k, r, dim, n_sets_volume, n_sets_surface
      character(len=:), allocatable :: name

      if (size(order) == 0) then
         allocate (mesh%node_sets(0), mesh%element_sets(0), mesh%surfaces(0))
         return
      end if
      n_volumes = count(raw%group_dims%items(order) == element_dim)
      n_surfaces = count(raw%group_dims%items(order) == element_dim - 1)
      allocate (mesh%node_sets(size(order)), mesh%element_sets(n_volumes), mesh%surfaces(n_surfaces))
      allocate (node_stamp(mesh%n_nodes), element_stamp(mesh%n_elements), face_stamp(6*mesh%n_elements))
      node_stamp = 0
      element_stamp = 0
      face_stamp = 0
      if (n_surfaces > 0) call node_to_elements(mesh, adjacency_offsets, adjacency)
      n_sets_volume = 0
      n_sets_surface = 0
      do i = 1, size(order)
         g = order(i)
         dim = raw%group_dims%items(g)
         name = group_name(raw, g)
         call check_new_name(file_name, raw, order, i, name, mesh, error)
         if (allocated(error)) return
         do k = group_offsets(g), group_offsets(g + 1) - 1
            r = group_records(k)
            call record_nodes(file_name, raw, r, node_map, nodes, error)
            if (allocated(error)) return
            node_stamp(nodes) = i
            if (dim == element_dim) element_stamp(record_element(r)) = i
            if (dim == element_dim - 1) then
               call stamp_face(file_name, raw, r, element_dim, mesh, adjacency_offsets, adjacency, nodes, i, &
                               face_stamp, error)
               if (allocated(error)) return
            end if
         end do
         call store_sets(mesh, i, dim, element_dim, name, node_stamp, element_stamp, face_stamp, &
                         n_sets_volume, n_sets_surface)
      end do
   end subroutine build_sets

   !> The sets of the i-th group, of dimension `dim`, from what its records stamped with i: its
   !> node set, and the next element set (dim = element_dim, the mesh's) or surface (one lower).
   subroutine store_sets(mesh, i, dim, element_dim, name, node_stamp, element_stamp, face_stamp, n_sets_volume, &
                         n_sets_surface)
      type(mesh_t), intent(inout) :: mesh
      integer, intent(in) :: i, dim, element_dim
      character(len=*), intent(in) :: name
      integer, intent(in) :: node_stamp(:), element_stamp(:), face_stamp(:)
      integer, intent(inout) :: n_sets_volume, n_sets_surface   !! element sets and surfaces stored so far
      integer, allocatable :: faces(:)
      integer :: k
      mesh%node_sets(i)%name = name
      mesh%node_sets(i)%nodes = pack([(k, k=1, mesh%n_nodes)], node_stamp == i)
      if (dim == element_dim) then
         n_sets_volume = n_sets_volume + 1
         mesh%element_sets(n_sets_volume)%name = name
         mesh%element_sets(n_sets_volume)%elements = pack([(k, k=1, mesh%n_elements)], element_stamp == i)
      else if (dim == element_dim - 1) then
         n_sets_surface = n_sets_surface + 1
         mesh%surfaces(n_sets_surface)%name = name
         faces = pack([(k, k=1, 6*mesh%n_elements)], face_stamp == i)
         mesh%surfaces(n_sets_surface)%elements = (faces - 1)/6 + 1
         mesh%surfaces(n_sets_surface)%faces = modulo(faces - 1, 6) + 1
      end if
   end subroutine store_sets

   !> Error if the i-th group of `order` has the `name` of one before it (each gives a node set).
   subroutine check_new_name(file_name, raw, order, i, name, mesh, error)
      character(len=*), intent(in) :: file_name
      type(raw_mesh_t), intent(in) :: raw
      integer, intent(in) :: order(:), i
      character(len=*), intent(in) :: name
      type(mesh_t), intent(in) :: mesh
      type(error_t), allocatable, intent(out) :: error
      integer :: j
      do j = 1, i - 1
         if (mesh%node_sets(j)%name == name) then
            call fatal_error(error, file_name//': physical groups '//to_string(raw%group_dims%items(order(j)))// &
                             ':'//to_string(raw%group_tags%items(order(j)))//' and '// &
                             to_string(raw%group_dims%items(order(i)))//':'// &
                             to_string(raw%group_tags%items(order(i)))//' have the same name "'//name//'"')
            return
         end if
      end do
   end subroutine check_new_name

   !> Stamp with `stamp` the element face of boundary record r (its `nodes`); it must match
   !> exactly one face (an edge of a plane element, `element_dim` 2).
   subroutine stamp_face(file_name, raw, r, element_dim, mesh, offsets, adjacency, nodes, stamp, face_stamp, error)
      character(len=*), intent(in) :: file_name
      type(raw_mesh_t), intent(in) :: raw
      integer, intent(in) :: r, element_dim
      type(mesh_t), intent(in) :: mesh
      integer, intent(in) :: offsets(:), adjacency(:), nodes(:), stamp
      integer, intent(inout) :: face_stamp(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: element, face, n_matches
      character(len=:), allocatable :: boundary, face_of, shared
      if (element_dim == 3) then
         boundary = 'surface element '
         face_of = 'face of a volume element'
         shared = 'a face shared by two volume elements (an interior face)'
      else
         boundary = 'line element '
         face_of = 'edge of a plane element'
         shared = 'an edge shared by two plane elements (an interior edge)'
      end if
      call match_face(mesh, offsets, adjacency, nodes, element, face, n_matches)
      if (n_matches == 0) then
         call fail_at_record(file_name, raw, r, error, boundary//to_string(raw%record_ids%items(r))// &
                             ' matches no '//face_of)
      else if (n_matches > 1) then
         call fail_at_record(file_name, raw, r, error, boundary//to_string(raw%record_ids%items(r))// &
                             ' lies on '//shared)
      else
         face_stamp(6*(element - 1) + face) = stamp
      end if
   end subroutine stamp_face

   !> The element faces with the nodes of `face_record` (any order): `n_matches` of them, the
   !> last one found is (element, face).
   subroutine match_face(mesh, offsets, adjacency, face_record, element, face, n_matches)
      type(mesh_t), intent(in) :: mesh
      integer, intent(in) :: offsets(:), adjacency(:), face_record(:)
      integer, intent(out) :: element, face, n_matches
      integer, allocatable :: key(:), candidate(:)
      integer :: k, f, e
      key = sort_nodes(face_record)
      element = 0
      face = 0
      n_matches = 0
      do k = offsets(face_record(1)), offsets(face_record(1) + 1) - 1
         e = adjacency(k)
         do f = 1, mesh%face_count(e)
            candidate = mesh%face_nodes(e, f)
            if (size(candidate) /= size(key)) cycle
            candidate = sort_nodes(candidate)
            if (all(candidate == key)) then
               n_matches = n_matches + 1
               element = e
               face = f
            end if
         end do
      end do
   end subroutine match_face

   !> Internal node numbers of record r; error naming the record's line if one is undefined.
   subroutine record_nodes(file_name, raw, r, node_map, nodes, error)
      character(len=*), intent(in) :: file_name
      type(raw_mesh_t), intent(in) :: raw
      integer, intent(in) :: r
      type(id_map_t), intent(in) :: node_map
      integer, allocatable, intent(inout) :: nodes(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: first, last, k
      first = raw%record_node_first%items(r)
      last = raw%record_node_first%items(r + 1) - 1
      if (allocated(nodes)) then
         if (size(nodes) /= last - first + 1) deallocate (nodes)
      end if
      if (.not. allocated(nodes)) allocate (nodes(last - first + 1))
      do k = first, last
         nodes(k - first + 1) = node_map%lookup(raw%record_nodes%items(k))
         if (nodes(k - first + 1) == 0) then
            call fail_at_record(file_name, raw, r, error, 'element '//to_string(raw%record_ids%items(r))// &
                                ' references node '//to_string(raw%record_nodes%items(k))//', which is not defined')
            return
         end if
      end do
   end subroutine record_nodes

   subroutine fail_at_record(file_name, raw, r, error, message)
      character(len=*), intent(in) :: file_name
      type(raw_mesh_t), intent(in) :: raw
      integer, intent(in) :: r
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: message
      call fatal_error(error, file_name//':'//to_string(raw%record_lines%items(r))//': '//message)
   end subroutine fail_at_record

   !> Group indices sorted by (dim, tag) (insertion sort: a mesh has few physical groups).
   function sorted_group_order(raw) result(order)
      type(raw_mesh_t), intent(in) :: raw
      integer, allocatable :: order(:)
      integer :: n, i, j, current
      n = raw%group_dims%count
      order = [(i, i=1, n)]
      do i = 2, n
         current = order(i)
         j = i - 1
         do while (j >= 1)
            if (.not. comes_after(order(j), current)) exit
            order(j + 1) = order(j)
            j = j - 1
         end do
         order(j + 1) = current
      end do
   contains
      logical function comes_after(first, second)
         integer, intent(in) :: first, second
         associate (dims => raw%group_dims%items, tags => raw%group_tags%items)
            comes_after = dims(first) > dims(second) .or. (dims(first) == dims(second) .and. tags(first) > tags(second))
         end associate
      end function comes_after
   end function sorted_group_order

   !> Name of group g: from $PhysicalNames, else "<dim>:<tag>".
   function group_name(raw, g) result(name)
      type(raw_mesh_t), intent(in) :: raw
      integer, intent(in) :: g
      character(len=:), allocatable :: name
      integer :: k
      do k = 1, raw%name_dims%count
         if (raw%name_dims%items(k) == raw%group_dims%items(g) .and. raw%name_tags%items(k) == raw%group_tags%items(g)) then
            name = raw%names(k)%text
            return
         end if
      end do
      name = to_string(raw%group_dims%items(g))//':'//to_string(raw%group_tags%items(g))
   end function group_name
end module frix_gmsh_to_mesh
