!> The mesh: nodes, 8-node hexahedra and named sets. Internal numbering is 1..n in the order
!> read; `node_ids` and `element_ids` keep the user's (deck or gmsh) ids for messages and output.
!>
!> HEX8 local node order is VTK's (= Abaqus C3D8, gmsh hexahedron): nodes 1-4 on the face
!> zeta = -1 counter-clockwise seen from zeta = +1, node a+4 above node a.
!> Local faces, each listed counter-clockwise seen from outside (right-hand rule gives the
!> outward normal), see `hex8_face_nodes`:
!>   1: zeta=-1 (1 4 3 2)   2: zeta=+1 (5 6 7 8)   3: eta=-1 (1 2 6 5)
!>   4: xi=+1  (2 3 7 6)    5: eta=+1 (3 4 8 7)    6: xi=-1  (1 5 8 4)
module frix_mesh
   use frix_kinds, only: dp
   implicit none
   private

   public :: mesh_t, node_set_t, element_set_t, surface_t, hex8_face_nodes

   !> Local node numbers of each HEX8 face, outward orientation, (4, 6).
   integer, parameter :: hex8_face_nodes(4, 6) = reshape([ &
                                                         1, 4, 3, 2, &
                                                         5, 6, 7, 8, &
                                                         1, 2, 6, 5, &
                                                         2, 3, 7, 6, &
                                                         3, 4, 8, 7, &
                                                         1, 5, 8, 4], [4, 6])

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
