!> The mesh: nodes, 8-node hexahedra and named sets. Internal numbering is 1..n in the order
!> read; `node_ids` and `element_ids` keep the user's (deck or gmsh) ids for messages and output.
!>
!> HEX8 local node order and faces: the reference cell's (frix_hex8_cell, VTK's order;
!> `hex8_face_nodes` is its face table, passed on for the mesh's users).
module frix_mesh
   use frix_kinds, only: dp
   use frix_hex8_cell, only: hex8_face_nodes
   implicit none
   private

   public :: mesh_t, node_set_t, element_set_t, surface_t, hex8_face_nodes

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
      integer, allocatable :: faces(:)      !! local face number 1..6 of each
   end type surface_t

   type :: mesh_t
      integer :: n_nodes = 0
      integer :: n_elements = 0
      real(dp), allocatable :: coords(:, :)         !! (3, n_nodes) reference coordinates
      integer, allocatable :: node_ids(:)           !! (n_nodes) user ids
      integer, allocatable :: connectivity(:, :)    !! (8, n_elements) internal node numbers
      integer, allocatable :: element_ids(:)        !! (n_elements) user ids
      integer, allocatable :: element_block(:)      !! (n_elements) element block (property) index
      type(node_set_t), allocatable :: node_sets(:)
      type(element_set_t), allocatable :: element_sets(:)
      type(surface_t), allocatable :: surfaces(:)
   contains
      procedure :: find_node_set
      procedure :: find_element_set
      procedure :: find_surface
   end type mesh_t

contains

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
