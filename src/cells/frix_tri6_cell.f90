!> The 6-node triangle as a reference cell: quadratic shape functions on the unit triangle
!> {xi, eta >= 0, xi + eta <= 1}, the 3-point interior rule of frix_tri3_cell (degree 2),
!> VTK_QUADRATIC_TRIANGLE (22), gmsh type 9, POS3D T6. It is the face of the TET10 cell
!> (frix_tet10_cell), on which surface loads are integrated: the rule integrates N_a dA
!> exactly on a flat face with straight edges (N_a of degree 2, a constant Jacobian).
!> Node order (VTK's = gmsh's = Abaqus'): corners (0,0), (1,0), (0,1) counter-clockwise, then
!> the mid-edge nodes 4: 1-2, 5: 2-3, 6: 3-1. Its edges are 3-node lines (corners, then middle).
!> With L_1 = 1 - xi - eta, L_2 = xi, L_3 = eta: N_a = L_a (2 L_a - 1) at corner a,
!> N_m = 4 L_i L_j at the node m on edge i-j (Zienkiewicz & Taylor, vol. 1, 8.8.1;
!> frix_quadratic_simplex).
!> Extrapolation to the nodes: the linear field through the 3 point values (point g beside
!> corner g, L_g = 2/3 there, 1/6 at the others): E(a, g) = 2 L_g(x_a) - 1/3.
module frix_tri6_cell
   use frix_kinds, only: dp
   use frix_reference_cell, only: reference_cell_t
   use frix_tri3_cell, only: tri3_points
   use frix_quadratic_simplex, only: quadratic_simplex_shape
   implicit none
   private

   public :: tri6_cell_t, new_tri6_cell, tri6_gmsh_type

   !> Codes of the cell in VTK (VTK_QUADRATIC_TRIANGLE) and gmsh (element type 9, the same order).
   integer, parameter :: tri6_vtk_type = 22, tri6_gmsh_type = 9

   !> The two corners of each mid-edge node 4..6.
   integer, parameter :: edge_corners(2, 4:6) = reshape([1, 2, 2, 3, 3, 1], [2, 3])
   !> Local node numbers of each edge (corners, then middle), counter-clockwise, (3, 3).
   integer, parameter :: tri6_edge_nodes(3, 3) = reshape([1, 2, 4, 2, 3, 5, 3, 1, 6], [3, 3])
   !> dL_i/dxi_d of the barycentric coordinates, (2, 3).
   real(dp), parameter :: barycentric_gradient(2, 3) = reshape([-1.0_dp, -1.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], &
                                                               [2, 3])

   type, extends(reference_cell_t) :: tri6_cell_t
   contains
      procedure :: shape_functions => tri6_shape_functions
      procedure :: extrapolation => tri6_extrapolation
   end type tri6_cell_t

contains

   pure function new_tri6_cell() result(cell)
      type(tri6_cell_t) :: cell
      integer :: m
      cell%name = 'TRI6'
      cell%dimension = 2
      cell%n_nodes = 6
      allocate (cell%node_coordinates(2, 6), source=0.0_dp)
      cell%node_coordinates(:, 2:3) = barycentric_gradient(:, 2:3)
      do m = 4, 6
         cell%node_coordinates(:, m) = 0.5_dp*(cell%node_coordinates(:, edge_corners(1, m)) + &
                                               cell%node_coordinates(:, edge_corners(2, m)))
      end do
      cell%face_cell = 'LINE3'
      cell%face_nodes = tri6_edge_nodes
      cell%simplex = .true.
      cell%rule_degree = 2
      cell%points = tri3_points
      allocate (cell%weights(3), source=1.0_dp/6.0_dp)
      cell%vtk_type = tri6_vtk_type
      cell%gmsh_type = tri6_gmsh_type
      cell%pos3d_name = 'T6'
   end function new_tri6_cell

   pure function barycentric(xi) result(l)
      real(dp), intent(in) :: xi(:)
      real(dp) :: l(3)
      l = [1.0_dp - xi(1) - xi(2), xi(1), xi(2)]
   end function barycentric

   pure subroutine tri6_shape_functions(self, xi, values, derivatives)
      class(tri6_cell_t), intent(in) :: self
      real(dp), intent(in) :: xi(:)
      real(dp), intent(out) :: values(:)
      real(dp), intent(out) :: derivatives(:, :)
      call quadratic_simplex_shape(barycentric(xi), barycentric_gradient, edge_corners, values(1:6), &
                                   derivatives(1:2, 1:6))
   end subroutine tri6_shape_functions

   !> E(a, g) = 2 L_g(x_a) - 1/3: the linear field through the 3 point values.
   pure function tri6_extrapolation(self) result(matrix)
      class(tri6_cell_t), intent(in) :: self
      real(dp), allocatable :: matrix(:, :)
      integer :: a
      allocate (matrix(6, 3))
      do a = 1, 6
         matrix(a, :) = 2.0_dp*barycentric(self%node_coordinates(:, a)) - 1.0_dp/3.0_dp
      end do
   end function tri6_extrapolation

end module frix_tri6_cell
