!> The 4-node quadrilateral as a reference cell: bilinear shape functions on [-1, 1]^2, the
!> 2 x 2 Gauss rule, VTK_QUAD (9), gmsh type 3, POS3D QUAD4 (Q4). It is the face of the HEX8 cell
!> (frix_hex8_cell) on which surface loads and contact faces are integrated.
!> Local node order counter-clockwise: (-1,-1), (1,-1), (1,1), (-1,1); integration point g sits
!> at quad4_corner(:, g) / sqrt(3), beside node g, weight 1. Its edges are 2-node lines.
!> N_a(xi) = (1 + xi_a xi)(1 + eta_a eta) / 4 (Zienkiewicz & Taylor, vol. 1, 8.3).
module frix_quad4_cell
   use frix_kinds, only: dp
   use frix_reference_cell, only: reference_cell_t
   use frix_hex8_cell, only: hex8_gauss_abscissa
   implicit none
   private

   public :: quad4_cell_t, new_quad4_cell
   public :: quad4_corner, quad4_gauss_points, quad4_vtk_type, quad4_gmsh_type

   !> Codes of the cell in VTK (VTK_QUAD) and gmsh (element type 3, the same node order).
   integer, parameter :: quad4_vtk_type = 9, quad4_gmsh_type = 3

   !> Natural coordinates of the nodes, counter-clockwise, (2, 4).
   integer, parameter :: quad4_corner(2, 4) = reshape([-1, -1, 1, -1, 1, 1, -1, 1], [2, 4])
   !> Natural coordinates of the 4 integration points (point g beside node g), (2, 4).
   real(dp), parameter :: quad4_gauss_points(2, 4) = quad4_corner*hex8_gauss_abscissa
   !> Local node numbers of each edge, counter-clockwise, (2, 4).
   integer, parameter :: quad4_edge_nodes(2, 4) = reshape([1, 2, 2, 3, 3, 4, 4, 1], [2, 4])

   type, extends(reference_cell_t) :: quad4_cell_t
   contains
      procedure :: shape_functions => quad4_shape_functions
      procedure :: extrapolation => quad4_extrapolation
   end type quad4_cell_t

contains

   pure function new_quad4_cell() result(cell)
      type(quad4_cell_t) :: cell
      cell%name = 'QUAD4'
      cell%dimension = 2
      cell%n_nodes = 4
      cell%node_coordinates = real(quad4_corner, dp)
      cell%face_cell = 'LINE2'
      cell%face_nodes = quad4_edge_nodes
      cell%points = quad4_gauss_points
      cell%rule_degree = 3
      allocate (cell%weights(4), source=1.0_dp)
      cell%vtk_type = quad4_vtk_type
      cell%gmsh_type = quad4_gmsh_type
      cell%pos3d_name = 'Q4'
   end function new_quad4_cell

   pure subroutine quad4_shape_functions(self, xi, values, derivatives)
      class(quad4_cell_t), intent(in) :: self
      real(dp), intent(in) :: xi(:)
      real(dp), intent(out) :: values(:)
      real(dp), intent(out) :: derivatives(:, :)
      real(dp) :: factors(2)
      integer :: a
      do a = 1, 4
         factors = 1.0_dp + quad4_corner(:, a)*xi(1:2)
         values(a) = 0.25_dp*factors(1)*factors(2)
         derivatives(1, a) = 0.25_dp*quad4_corner(1, a)*factors(2)
         derivatives(2, a) = 0.25_dp*quad4_corner(2, a)*factors(1)
      end do
   end subroutine quad4_shape_functions

   !> E(a, g) = N_g(sqrt(3) xi_a): the bilinear field through the 4 Gauss values evaluated at
   !> the nodes (as frix_hex8_cell's, in two dimensions).
   pure function quad4_extrapolation(self) result(matrix)
      class(quad4_cell_t), intent(in) :: self
      real(dp), allocatable :: matrix(:, :)
      integer :: a, g
      allocate (matrix(4, 4))
      do g = 1, 4
         do a = 1, 4
            matrix(a, g) = product(1.0_dp + sqrt(3.0_dp)*real(quad4_corner(:, g)*quad4_corner(:, a), dp))/4.0_dp
         end do
      end do
   end function quad4_extrapolation

end module frix_quad4_cell
