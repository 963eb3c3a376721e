!> Structured block generator (in the manner of FEAP's BLOCK command), so that simple
!> benchmark decks need no mesh file. Pure geometry: the deck reader parses, this module builds.
!>
!> The block [x0, x0+lx] x [y0, y0+ly] x [z0, z0+lz] is cut into nx x ny x nz equal HEX8.
!> A plane block (nz = 0 and lz = 0) is the rectangle [x0, x0+lx] x [y0, y0+ly] in the plane
!> z = z0 cut into nx x ny equal QUAD4 (nodes counter-clockwise seen from +z, for the plane
!> strain and axisymmetric elements); it has the four sides x/y min/max, whose faces are the
!> QUAD4 edges (frix_quad4_cell: xmin 4, xmax 2, ymin 1, ymax 3).
!> Node (i, j, k), 0 <= i <= nx etc., is the internal node 1 + i + (nx+1) (j + (ny+1) k) of the
!> returned mesh (i runs fastest); element (i, j, k), 0 <= i < nx, is the internal element
!> 1 + i + nx (j + ny k), with its nodes in frix_mesh's HEX8 order (VTK's), which gives a
!> positive Jacobian for positive lengths.
!>
!> Named entities created (`name` as given, case kept):
!>   element set `name` (all elements), node set `name` (all nodes),
!>   node sets and surfaces `name_xmin`, `name_xmax`, `name_ymin`, `name_ymax`, `name_zmin`,
!>   `name_zmax`: the nodes on, and the element faces forming, each side of the block.
!>   Faces use frix_mesh's local face numbers (xmin: 6, xmax: 4, ymin: 3, ymax: 5, zmin: 1,
!>   zmax: 2), whose node order gives the outward normal.
module frix_block_generator
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_mesh, only: mesh_t, cell_index, connectivity_rows
   implicit none
   private

   public :: generate_block, block_side_names

   !> Suffixes of the six sides, in the order of the `sides` loop below.
   character(len=5), parameter :: block_side_names(6) = &
      [character(len=5) :: 'xmin', 'xmax', 'ymin', 'ymax', 'zmin', 'zmax']
   !> frix_mesh local face lying on each side (see hex8_face_nodes), and the QUAD4 edge lying
   !> on each side of a plane block (quad4_edge_nodes).
   integer, parameter :: side_face(6) = [6, 4, 3, 5, 1, 2], side_edge(4) = [4, 2, 1, 3]

contains

   !> Build the block as a mesh of its own. User ids are first_node_id, first_node_id + 1, ...
   !> in internal order (likewise for elements). `element_block` is left 0.
   !> Errors: a division count < 1, a length <= 0 or not finite, ids that would overflow.
   subroutine generate_block(name, origin, lengths, divisions, first_node_id, first_element_id, &
                             block, error)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: origin(3)          !! corner with the smallest coordinates
      real(dp), intent(in) :: lengths(3)         !! edge lengths lx, ly, lz (> 0), deck units
      integer, intent(in) :: divisions(3)        !! nx, ny, nz (>= 1)
      integer, intent(in) :: first_node_id       !! user id of internal node 1
      integer, intent(in) :: first_element_id    !! user id of internal element 1
      type(mesh_t), intent(out) :: block
      type(error_t), allocatable, intent(out) :: error
      integer :: nx, ny, nz, i, j, k, n, e, side, count, n_sides
      integer :: corner(8)
      logical :: plane
      integer, allocatable :: side_nodes(:), side_elements(:)

      plane = divisions(3) == 0 .and. lengths(3) == 0.0_dp
      n_sides = merge(4, 6, plane)
      if (any(divisions(1:n_sides/2) < 1)) then
         call fatal_error(error, 'block "'//name//'": DIVISIONS must be at least 1 (a plane block: nx ny 0 with SIZE lx ly 0)')
         return
      end if
      if (any(.not. (lengths(1:n_sides/2) > 0.0_dp)) .or. any(lengths > huge(1.0_dp))) then
         call fatal_error(error, 'block "'//name//'": SIZE must be positive (a plane block: lx ly 0 with DIVISIONS nx ny 0)')
         return
      end if
      nx = divisions(1)
      ny = divisions(2)
      nz = divisions(3)
      if (real(nx + 1, dp)*real(ny + 1, dp)*real(nz + 1, dp) > real(huge(1), dp)/2 .or. &
          first_node_id < 1 .or. first_element_id < 1 .or. &
          real(first_node_id, dp) + real(nx + 1, dp)*real(ny + 1, dp)*real(nz + 1, dp) > real(huge(1), dp) .or. &
          real(first_element_id, dp) + real(nx, dp)*real(ny, dp)*real(nz, dp) > real(huge(1), dp)) then
         call fatal_error(error, 'block "'//name//'": too many nodes or ids out of range')
         return
      end if

      block%n_nodes = (nx + 1)*(ny + 1)*(nz + 1)
      block%n_elements = nx*ny*max(nz, 1)
      allocate (block%coords(3, block%n_nodes), block%node_ids(block%n_nodes))
      call block%set_cells(spread(cell_index(trim(merge('QUAD4', 'HEX8 ', plane))), 1, block%n_elements))
      allocate (block%connectivity(connectivity_rows(block%element_cell), block%n_elements), source=0)
      allocate (block%element_ids(block%n_elements), block%element_block(block%n_elements), source=0)

      do k = 0, nz
         do j = 0, ny
            do i = 0, nx
               n = node_number(i, j, k)
               block%coords(:, n) = origin + lengths*[real(i, dp)/nx, real(j, dp)/ny, real(k, dp)/max(nz, 1)]
               block%node_ids(n) = first_node_id + n - 1
            end do
         end do
      end do
      do k = 0, max(nz, 1) - 1
         do j = 0, ny - 1
            do i = 0, nx - 1
               e = 1 + i + nx*(j + ny*k)
               corner(1:4) = [node_number(i, j, k), node_number(i + 1, j, k), &
                              node_number(i + 1, j + 1, k), node_number(i, j + 1, k)]
               corner(5:8) = corner(1:4) + (nx + 1)*(ny + 1)
               if (plane) then
                  block%connectivity(1:4, e) = corner(1:4)
               else
                  block%connectivity(1:8, e) = corner
               end if
               block%element_ids(e) = first_element_id + e - 1
            end do
         end do
      end do

      allocate (block%element_sets(1), block%node_sets(n_sides + 1), block%surfaces(n_sides))
      block%element_sets(1)%name = name
      block%element_sets(1)%elements = [(e, e=1, block%n_elements)]
      block%node_sets(1)%name = name
      block%node_sets(1)%nodes = [(n, n=1, block%n_nodes)]

      do side = 1, n_sides
         allocate (side_nodes(block%n_nodes), side_elements(block%n_elements))
         count = 0
         do k = 0, nz
            do j = 0, ny
               do i = 0, nx
                  if (on_side(side, i, j, k, nx, ny, nz)) then
                     count = count + 1
                     side_nodes(count) = node_number(i, j, k)
                  end if
               end do
            end do
         end do
         block%node_sets(side + 1)%name = name//'_'//trim(block_side_names(side))
         block%node_sets(side + 1)%nodes = side_nodes(1:count)  ! increasing by construction
         count = 0
         do k = 0, max(nz, 1) - 1
            do j = 0, ny - 1
               do i = 0, nx - 1
                  ! element (i, j, k) has a face on a side where it is first or last of its row:
                  ! the side of the grid of element indices 0..nx-1, 0..ny-1, 0..nz-1
                  if (on_side(side, i, j, k, nx - 1, ny - 1, max(nz, 1) - 1)) then
                     count = count + 1
                     side_elements(count) = 1 + i + nx*(j + ny*k)
                  end if
               end do
            end do
         end do
         block%surfaces(side)%name = name//'_'//trim(block_side_names(side))
         block%surfaces(side)%elements = side_elements(1:count)
         if (plane) then
            allocate (block%surfaces(side)%faces(count), source=side_edge(side))
         else
            allocate (block%surfaces(side)%faces(count), source=side_face(side))
         end if
         deallocate (side_nodes, side_elements)
      end do

   contains

      pure integer function node_number(i, j, k)
         integer, intent(in) :: i, j, k
         node_number = 1 + i + (nx + 1)*(j + (ny + 1)*k)
      end function node_number
   end subroutine generate_block

   !> Whether grid node (i, j, k) lies on side `side` (order of block_side_names).
   pure logical function on_side(side, i, j, k, nx, ny, nz)
      integer, intent(in) :: side, i, j, k, nx, ny, nz
      select case (side)
      case (1)
         on_side = i == 0
      case (2)
         on_side = i == nx
      case (3)
         on_side = j == 0
      case (4)
         on_side = j == ny
      case (5)
         on_side = k == 0
      case default
         on_side = k == nz
      end select
   end function on_side
end module frix_block_generator
