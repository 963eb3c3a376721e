!> The state of one .inp reading (frix_inp_reader) shared by the data-line readers
!> (frix_inp_data_lines): the nodes, hexahedra, node and element sets and surfaces read so far,
!> already in internal numbers (an id must be defined before a line names it), and what the
!> current keyword's data lines are. Set names are matched case-insensitively, as Abaqus and
!> CalculiX do; a set keeps the spelling of its first definition.
module frix_inp_context
   use frix_kinds, only: dp
   use frix_strings, only: to_upper
   use frix_id_map, only: id_map_t
   use frix_gmsh_context, only: integer_list_t, push, name_t
   implicit none
   private

   public :: inp_data_t, inp_set_t, inp_surface_t
   public :: node_kind, element_kind
   public :: mode_skip, mode_node, mode_element, mode_set, mode_set_generate, mode_surface
   public :: find_set, set_index, new_surface, add_node, add_element, add_file

   integer, parameter :: node_kind = 1, element_kind = 2

   !> What the data lines of the current keyword hold.
   integer, parameter :: mode_skip = 0, mode_node = 1, mode_element = 2, mode_set = 3, &
                         mode_set_generate = 4, mode_surface = 5

   type :: inp_set_t
      character(len=:), allocatable :: name
      integer :: kind = node_kind              !! node_kind or element_kind
      type(integer_list_t) :: members          !! internal numbers, in the order given
   end type inp_set_t

   type :: inp_surface_t
      character(len=:), allocatable :: name
      type(integer_list_t) :: elements, faces  !! internal element numbers, faces 1..6
   end type inp_surface_t

   type :: inp_data_t
      ! the files read (the main file, then each *INCLUDE), for messages
      integer :: n_files = 0
      type(name_t), allocatable :: files(:)
      ! nodes
      type(integer_list_t) :: node_ids, node_lines, node_files
      real(dp), allocatable :: coords(:, :)
      type(id_map_t) :: node_map
      ! elements: the nodes of each element, its cell's node count of them, one element after
      ! the other in `connectivity`; element_cells: its cell (index in the cell table,
      ! frix_mesh's cell_index)
      type(integer_list_t) :: element_ids, element_lines, element_files, connectivity, element_cells
      type(id_map_t) :: element_map
      ! sets and surfaces
      integer :: n_sets = 0, n_surfaces = 0
      type(inp_set_t), allocatable :: sets(:)
      type(inp_surface_t), allocatable :: surfaces(:)
      ! the current keyword: `mode` for its data lines, the set `target_set` (0: none) its
      ! nodes or elements join, the surface `target_surface`
      integer :: mode = mode_skip, target_set = 0, target_surface = 0
      ! element being read (its line may continue on the next): id and nodes so far
      logical :: pending = .false.
      integer :: pending_id = 0, pending_count = 0, pending_file = 0, pending_line = 0
      integer, allocatable :: pending_nodes(:)
      ! the cell of the current *ELEMENT keyword's elements, its node count and name (C3D8: HEX8)
      integer :: element_cell = 0, element_node_count = 8
      character(len=:), allocatable :: element_cell_name
      ! the dimension of the mesh's cells (0 before the first *ELEMENT: 3 solids, 2 plane), and
      ! the TYPE and "file:line" of the first *ELEMENT that set it (a mesh has one dimension)
      integer :: cell_dimension = 0
      character(len=:), allocatable :: dimension_type, dimension_where
   end type inp_data_t

contains

   !> Index of the set of `kind` called `name` (any case), 0 if none.
   integer function find_set(data, kind, name) result(found)
      type(inp_data_t), intent(in) :: data
      integer, intent(in) :: kind
      character(len=*), intent(in) :: name
      integer :: k
      found = 0
      do k = 1, data%n_sets
         if (data%sets(k)%kind == kind .and. to_upper(data%sets(k)%name) == to_upper(name)) then
            found = k
            return
         end if
      end do
   end function find_set

   !> Index of the set of `kind` called `name`, created empty if new (Abaqus adds the members
   !> of a set defined twice to it).
   integer function set_index(data, kind, name) result(found)
      type(inp_data_t), intent(inout) :: data
      integer, intent(in) :: kind
      character(len=*), intent(in) :: name
      type(inp_set_t), allocatable :: larger(:)
      integer :: k
      found = find_set(data, kind, name)
      if (found > 0) return
      if (.not. allocated(data%sets)) allocate (data%sets(8))
      if (data%n_sets == size(data%sets)) then
         allocate (larger(2*data%n_sets))
         do k = 1, data%n_sets
            call move_alloc(data%sets(k)%name, larger(k)%name)
            larger(k)%kind = data%sets(k)%kind
            larger(k)%members%count = data%sets(k)%members%count
            call move_alloc(data%sets(k)%members%items, larger(k)%members%items)
         end do
         call move_alloc(larger, data%sets)
      end if
      data%n_sets = data%n_sets + 1
      found = data%n_sets
      data%sets(found)%name = name
      data%sets(found)%kind = kind
   end function set_index

   !> A new surface called `name` (not defined before), empty.
   integer function new_surface(data, name) result(found)
      type(inp_data_t), intent(inout) :: data
      character(len=*), intent(in) :: name
      type(inp_surface_t), allocatable :: larger(:)
      integer :: k
      if (.not. allocated(data%surfaces)) allocate (data%surfaces(4))
      if (data%n_surfaces == size(data%surfaces)) then
         allocate (larger(2*data%n_surfaces))
         do k = 1, data%n_surfaces
            call move_alloc(data%surfaces(k)%name, larger(k)%name)
            larger(k)%elements%count = data%surfaces(k)%elements%count
            call move_alloc(data%surfaces(k)%elements%items, larger(k)%elements%items)
            larger(k)%faces%count = data%surfaces(k)%faces%count
            call move_alloc(data%surfaces(k)%faces%items, larger(k)%faces%items)
         end do
         call move_alloc(larger, data%surfaces)
      end if
      data%n_surfaces = data%n_surfaces + 1
      found = data%n_surfaces
      data%surfaces(found)%name = name
   end function new_surface

   !> Record the file `path` among those read; `file` is its number.
   subroutine add_file(data, path, file)
      type(inp_data_t), intent(inout) :: data
      character(len=*), intent(in) :: path
      integer, intent(out) :: file
      type(name_t), allocatable :: larger(:)
      integer :: k
      if (.not. allocated(data%files)) allocate (data%files(4))
      if (data%n_files == size(data%files)) then
         allocate (larger(2*data%n_files))
         do k = 1, data%n_files
            call move_alloc(data%files(k)%text, larger(k)%text)
         end do
         call move_alloc(larger, data%files)
      end if
      data%n_files = data%n_files + 1
      file = data%n_files
      data%files(file)%text = path
   end subroutine add_file

   !> A node (its id not yet defined) read on `line` of file number `file`.
   subroutine add_node(data, id, xyz, file, line)
      type(inp_data_t), intent(inout) :: data
      integer, intent(in) :: id, file, line
      real(dp), intent(in) :: xyz(3)
      real(dp), allocatable :: larger(:, :)
      integer :: n
      n = data%node_ids%count + 1
      if (.not. allocated(data%coords)) allocate (data%coords(3, 64))
      if (n > size(data%coords, 2)) then
         allocate (larger(3, 2*size(data%coords, 2)))
         larger(:, 1:n - 1) = data%coords(:, 1:n - 1)
         call move_alloc(larger, data%coords)
      end if
      data%coords(:, n) = xyz
      call push(data%node_ids, id)
      call push(data%node_lines, line)
      call push(data%node_files, file)
   end subroutine add_node

   !> An element of the current *ELEMENT's cell (its id not yet defined) with internal node
   !> numbers `nodes` (the cell's node count of them).
   subroutine add_element(data, id, nodes, file, line)
      type(inp_data_t), intent(inout) :: data
      integer, intent(in) :: id, nodes(:), file, line
      integer :: k
      do k = 1, size(nodes)
         call push(data%connectivity, nodes(k))
      end do
      call push(data%element_cells, data%element_cell)
      call push(data%element_ids, id)
      call push(data%element_lines, line)
      call push(data%element_files, file)
   end subroutine add_element
end module frix_inp_context
