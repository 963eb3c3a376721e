!> The 3-node triangle as a reference cell: linear shape functions on the unit triangle
!> {xi, eta >= 0, xi + eta <= 1}, the 3-point interior rule (points (1/6, 1/6), (2/3, 1/6),
!> (1/6, 2/3), weights 1/6; exact for polynomials of degree 2: Strang & Fix 1973, table 4.1;
!> Zienkiewicz & Taylor, vol. 1, table 9.2), VTK_TRIANGLE (5), gmsh type 2, POS3D T3. It is
!> the face of the TET4 cell (frix_tet4_cell). Node order counter-clockwise: (0,0), (1,0),
!> (0,1); point g sits beside node g. Its edges are 2-node lines.
!> N_1 = 1 - xi - eta, N_2 = xi, N_3 = eta.
module frix_tri3_cell
   use frix_kinds, only: dp
   use frix_reference_cell, only: reference_cell_t
   implicit none
   private

   public :: tri3_cell_t, new_tri3_cell, tri3_vtk_type, tri3_gmsh_type, tri3_points

   !> Codes of the cell in VTK (VTK_TRIANGLE) and gmsh (element type 2, the same node order).
   integer, parameter :: tri3_vtk_type = 5, tri3_gmsh_type = 2

   !> Natural coordinates of the nodes, counter-clockwise, (2, 3).
   integer, parameter :: tri3_corner(2, 3) = reshape([0, 0, 1, 0, 0, 1], [2, 3])
   !> Local node numbers of each edge, counter-clockwise, (2, 3).
   integer, parameter :: tri3_edge_nodes(2, 3) = reshape([1, 2, 2, 3, 3, 1], [2, 3])
   !> The 3-point rule's points, point g beside node g, (2, 3).
   real(dp), parameter :: tri3_points(2, 3) = reshape([1.0_dp/6, 1.0_dp/6, 2.0_dp/3, 1.0_dp/6, &
                                                       1.0_dp/6, 2.0_dp/3], [2, 3])

   type, extends(reference_cell_t) :: tri3_cell_t
   contains
      procedure :: shape_functions => tri3_shape_functions
      procedure :: extrapolation => tri3_extrapolation
   end type tri3_cell_t

contains

   pure function new_tri3_cell() result(cell)
      type(tri3_cell_t) :: cell
      cell%name = 'TRI3'
      cell%dimension = 2
      cell%n_nodes = 3
      cell%node_coordinates = real(tri3_corner, dp)
      cell%face_cell = 'LINE2'
      cell%face_nodes = tri3_edge_nodes
      cell%simplex = .true.
      cell%rule_degree = 2
      cell%points = tri3_points
      allocate (cell%weights(3), source=1.0_dp/6.0_dp)
      cell%vtk_type = tri3_vtk_type
      cell%gmsh_type = tri3_gmsh_type
      cell%pos3d_name = 'T3'
   end function new_tri3_cell

   pure subroutine tri3_shape_functions(self, xi, values, derivatives)
      class(tri3_cell_t), intent(in) :: self
      real(dp), intent(in) :: xi(:)
      real(dp), intent(out) :: values(:)
      real(dp), intent(out) :: derivatives(:, :)
      values(1:3) = [1.0_dp - xi(1) - xi(2), xi(1), xi(2)]
      derivatives(1:2, 1) = -1.0_dp
      derivatives(1:2, 2:3) = real(tri3_corner(:, 2:3), dp)
   end subroutine tri3_shape_functions

   !> E = M^{-1} with M(g, a) = N_a(xi_g) = 1/6 + delta_ga/2, i.e. E(a, g) = 2 delta_ag - 1/3:
   !> the linear field through the three point values, evaluated at the nodes.
   pure function tri3_extrapolation(self) result(matrix)
      class(tri3_cell_t), intent(in) :: self
      real(dp), allocatable :: matrix(:, :)
      integer :: a
      allocate (matrix(3, 3), source=-1.0_dp/3.0_dp)
      do a = 1, 3
         matrix(a, a) = matrix(a, a) + 2.0_dp
      end do
   end function tri3_extrapolation

end module frix_tri3_cell
