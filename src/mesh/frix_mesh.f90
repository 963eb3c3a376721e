!> The mesh: nodes, elements of any cell type of the cell registry (HEX8, TET4) and named sets.
!> Internal numbering is 1..n in the order read; `node_ids` and `element_ids` keep the user's
!> (deck or gmsh) ids for messages and output.
!>
!> Each element has a cell type, `element_cell(e)`, an index into `cells` (the cell registry's
!> table, frix_cell_registry): its local node order, node count and faces are that cell's.
!> The connectivity stays one rectangular array with as many rows as the largest cell of the
!> mesh has nodes, at least 8 (`connectivity_rows`: a mesh of hexahedra or linear tetrahedra
!> keeps the 8 rows of its output files); the rows past an element's own node count hold 0. Use `element_nodes`,
!> `face_nodes`, `node_count` and `face_count` rather than the rows. A mesh made without
!> `element_cell` (built by hand in a test) is all HEX8.
module frix_mesh
   use frix_kinds, only: dp
   use frix_hex8_cell, only: hex8_face_nodes
   use frix_reference_cell, only: reference_cell_t
   use frix_cell_registry, only: cell_entry_t, cell_table, find_in_table, hex8_cell_index
   implicit none
   private

   public :: mesh_t, node_set_t, element_set_t, surface_t, hex8_face_nodes, cell_index, connectivity_rows

   type :: node_set_t
      character(len=:), allocatable :: name
      integer, allocatable :: nodes(:)      !! internal node numbers, sorted, unique
   end type node_set_t

   type :: element_set_t
      character(len=:), allocatable :: name
      integer, allocatable :: elements(:)   !! internal element numbers, sorted, unique
   end type element_set_t

   !> A surface is a list of element faces.
   type :: surface_t
      character(len=:), allocatable :: name
      integer, allocatable :: elements(:)   !! internal element numbers
      integer, allocatable :: faces(:)      !! local face number of each (1..6 on a HEX8, 1..4 on a TET4)
   end type surface_t

   type :: mesh_t
      integer :: n_nodes = 0
      integer :: n_elements = 0
      real(dp), allocatable :: coords(:, :)         !! (3, n_nodes) reference coordinates
      integer, allocatable :: node_ids(:)           !! (n_nodes) user ids
      integer, allocatable :: connectivity(:, :)    !! (max nodes, n_elements) internal node numbers, 0 past an element's own
      integer, allocatable :: element_cell(:)       !! (n_elements) index of the element's cell in `cells`
      type(cell_entry_t), allocatable :: cells(:)   !! the cell registry's table
      integer, allocatable :: element_ids(:)        !! (n_elements) user ids
      integer, allocatable :: element_block(:)      !! (n_elements) element block (property) index
      type(node_set_t), allocatable :: node_sets(:)
      type(element_set_t), allocatable :: element_sets(:)
      type(surface_t), allocatable :: surfaces(:)
   contains
      procedure :: find_node_set
      procedure :: set_cells
      procedure :: widen_connectivity
      procedure :: cell_of
      procedure :: node_count
      procedure :: face_count
      procedure :: cell_dimension
      procedure :: face_cell_of
      procedure :: element_nodes
      procedure :: face_nodes
      procedure :: has_only_hex8
      procedure :: first_non_hex8_element
      procedure :: cell_name
      procedure :: cell_indices
      procedure :: find_element_set
      procedure :: find_surface
   end type mesh_t

contains

   !> The index of the cell `name` in the cell registry's table (0 if none).
   integer function cell_index(name)
      character(len=*), intent(in) :: name
      cell_index = find_in_table(cell_table(), name)
   end function cell_index

   !> Rows of the connectivity of a mesh whose elements have the cells `element_cell` (indices
   !> into the cell table): the most nodes of those cells, at least HEX8's 8.
   integer function connectivity_rows(element_cell)
      integer, intent(in) :: element_cell(:)
      type(cell_entry_t), allocatable :: table(:)
      integer :: k
      table = cell_table()
      connectivity_rows = table(hex8_cell_index)%cell%n_nodes
      do k = 1, size(table)
         if (any(element_cell == k)) connectivity_rows = max(connectivity_rows, table(k)%cell%n_nodes)
      end do
   end function connectivity_rows

   !> Give the connectivity at least `rows` rows, the new ones 0.
   subroutine widen_connectivity(self, rows)
      class(mesh_t), intent(inout) :: self
      integer, intent(in) :: rows
      integer, allocatable :: wider(:, :)
      if (.not. allocated(self%connectivity)) allocate (self%connectivity(rows, 0))
      if (size(self%connectivity, 1) >= rows) return
      allocate (wider(rows, size(self%connectivity, 2)), source=0)
      wider(1:size(self%connectivity, 1), :) = self%connectivity
      call move_alloc(wider, self%connectivity)
   end subroutine widen_connectivity

   !> Give the elements their cell types (`element_cell`, indices into the cell table) and keep
   !> the table in the mesh.
   subroutine set_cells(self, element_cell)
      class(mesh_t), intent(inout) :: self
      integer, intent(in) :: element_cell(:)
      self%element_cell = element_cell
      if (.not. allocated(self%cells)) self%cells = cell_table()
   end subroutine set_cells

   !> The cell index of element e (HEX8's in a mesh without cell types).
   pure integer function cell_of(self, e)
      class(mesh_t), intent(in) :: self
      integer, intent(in) :: e
      cell_of = hex8_cell_index
      if (allocated(self%element_cell)) cell_of = self%element_cell(e)
   end function cell_of

   !> Nodes of element e.
   pure integer function node_count(self, e)
      class(mesh_t), intent(in) :: self
      integer, intent(in) :: e
      node_count = 8
      if (allocated(self%element_cell)) node_count = self%cells(self%element_cell(e))%cell%n_nodes
   end function node_count

   !> The dimension of element e's cell: 3 for the solids, 2 for the plane strain and
   !> axisymmetric elements (whose nodes move in the x-y plane only).
   pure integer function cell_dimension(self, e)
      class(mesh_t), intent(in) :: self
      integer, intent(in) :: e
      cell_dimension = 3
      if (allocated(self%element_cell)) cell_dimension = self%cells(self%element_cell(e))%cell%dimension
   end function cell_dimension

   !> The index in `cells` of the cell of element e's faces (QUAD4 for a HEX8, TRI3 for a
   !> TET4, LINE2 for a QUAD4): what a pressure or a contact surface on the face integrates
   !> over. Needs the cells (set_cells: every mesh of the readers and the deck has them).
   pure integer function face_cell_of(self, e)
      class(mesh_t), intent(in) :: self
      integer, intent(in) :: e
      face_cell_of = find_in_table(self%cells, self%cells(self%cell_of(e))%cell%face_cell)
   end function face_cell_of

   !> Faces of element e.
   pure integer function face_count(self, e)
      class(mesh_t), intent(in) :: self
      integer, intent(in) :: e
      face_count = 6
      if (allocated(self%element_cell)) face_count = self%cells(self%element_cell(e))%cell%n_faces()
   end function face_count

   !> Internal node numbers of element e, in its cell's order.
   pure function element_nodes(self, e) result(nodes)
      class(mesh_t), intent(in) :: self
      integer, intent(in) :: e
      integer, allocatable :: nodes(:)
      nodes = self%connectivity(1:self%node_count(e), e)
   end function element_nodes

   !> Internal node numbers of local face f of element e, outward order.
   pure function face_nodes(self, e, f) result(nodes)
      class(mesh_t), intent(in) :: self
      integer, intent(in) :: e, f
      integer, allocatable :: nodes(:)
      if (allocated(self%element_cell)) then
         nodes = self%connectivity(self%cells(self%element_cell(e))%cell%face_nodes(:, f), e)
      else
         nodes = self%connectivity(hex8_face_nodes(:, f), e)
      end if
   end function face_nodes

   !> True when every element is a HEX8 (the writers and contact that know only HEX8 ask).
   pure logical function has_only_hex8(self)
      class(mesh_t), intent(in) :: self
      has_only_hex8 = .true.
      if (allocated(self%element_cell)) has_only_hex8 = all(self%element_cell(1:self%n_elements) == hex8_cell_index)
   end function has_only_hex8

   !> The first element on surface `surface` (index into `surfaces`) that is not a HEX8, 0 if
   !> none: pressures and contact integrate only over QUAD4 faces so far.
   pure integer function first_non_hex8_element(self, surface) result(element)
      class(mesh_t), intent(in) :: self
      integer, intent(in) :: surface
      integer :: k
      element = 0
      do k = 1, size(self%surfaces(surface)%elements)
         if (self%cell_of(self%surfaces(surface)%elements(k)) /= hex8_cell_index) then
            element = self%surfaces(surface)%elements(k)
            return
         end if
      end do
   end function first_non_hex8_element

   !> The cell index of every element (all HEX8's in a mesh without cell types).
   pure function cell_indices(self) result(indices)
      class(mesh_t), intent(in) :: self
      integer, allocatable :: indices(:)
      integer :: e
      indices = [(self%cell_of(e), e=1, self%n_elements)]
   end function cell_indices

   !> The cell name of element e ('HEX8' in a mesh without cell types).
   pure function cell_name(self, e) result(name)
      class(mesh_t), intent(in) :: self
      integer, intent(in) :: e
      character(len=:), allocatable :: name
      name = 'HEX8'
      if (allocated(self%element_cell)) name = self%cells(self%element_cell(e))%cell%name
   end function cell_name

   !> Index of the node set called `name` (case-sensitive), 0 if none.
   pure integer function find_node_set(self, name) result(index_found)
      class(mesh_t), intent(in) :: self
      character(len=*), intent(in) :: name
      integer :: i
      index_found = 0
      if (.not. allocated(self%node_sets)) return
      do i = 1, size(self%node_sets)
         if (self%node_sets(i)%name == name) then
            index_found = i
            return
         end if
      end do
   end function find_node_set

   pure integer function find_element_set(self, name) result(index_found)
      class(mesh_t), intent(in) :: self
      character(len=*), intent(in) :: name
      integer :: i
      index_found = 0
      if (.not. allocated(self%element_sets)) return
      do i = 1, size(self%element_sets)
         if (self%element_sets(i)%name == name) then
            index_found = i
            return
         end if
      end do
   end function find_element_set

   pure integer function find_surface(self, name) result(index_found)
      class(mesh_t), intent(in) :: self
      character(len=*), intent(in) :: name
      integer :: i
      index_found = 0
      if (.not. allocated(self%surfaces)) return
      do i = 1, size(self%surfaces)
         if (self%surfaces(i)%name == name) then
            index_found = i
            return
         end if
      end do
   end function find_surface
end module frix_mesh
