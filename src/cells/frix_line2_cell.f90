!> The 2-node line as a reference cell: linear shape functions on [-1, 1], the 2-point Gauss
!> rule (points -+1/sqrt(3), weight 1; exact for degree 3), VTK_LINE (3), gmsh type 1, POS3D
!> none. It is the edge (face) of the QUAD4 and TRI3 cells (frix_quad4_cell, frix_tri3_cell),
!> on which the edge pressures of the plane elements are integrated (frix_plane_solid).
!> Node order: xi = -1, +1; point g sits beside node g.
!> N_1 = (1 - xi)/2, N_2 = (1 + xi)/2.
module frix_line2_cell
   use frix_kinds, only: dp
   use frix_reference_cell, only: reference_cell_t
   use frix_hex8_cell, only: hex8_gauss_abscissa
   implicit none
   private

   public :: line2_cell_t, new_line2_cell, line2_vtk_type, line2_gmsh_type

   !> Codes of the cell in VTK (VTK_LINE) and gmsh (element type 1, the same node order).
   integer, parameter :: line2_vtk_type = 3, line2_gmsh_type = 1
   !> Natural coordinates of the nodes, (1, 2).
   integer, parameter :: line2_end(1, 2) = reshape([-1, 1], [1, 2])

   type, extends(reference_cell_t) :: line2_cell_t
   contains
      procedure :: shape_functions => line2_shape_functions
      procedure :: extrapolation => line2_extrapolation
   end type line2_cell_t

contains

   pure function new_line2_cell() result(cell)
      type(line2_cell_t) :: cell
      cell%name = 'LINE2'
      cell%dimension = 1
      cell%n_nodes = 2
      cell%node_coordinates = real(line2_end, dp)
      cell%face_cell = ''
      cell%points = line2_end*hex8_gauss_abscissa
      cell%rule_degree = 3
      allocate (cell%weights(2), source=1.0_dp)
      cell%vtk_type = line2_vtk_type
      cell%gmsh_type = line2_gmsh_type
      cell%pos3d_name = ''
   end function new_line2_cell

   pure subroutine line2_shape_functions(self, xi, values, derivatives)
      class(line2_cell_t), intent(in) :: self
      real(dp), intent(in) :: xi(:)
      real(dp), intent(out) :: values(:)
      real(dp), intent(out) :: derivatives(:, :)
      values(1:2) = 0.5_dp*(1.0_dp + real(line2_end(1, :), dp)*xi(1))
      derivatives(1, 1:2) = 0.5_dp*real(line2_end(1, :), dp)
   end subroutine line2_shape_functions

   !> E(a, g) = N_g(sqrt(3) xi_a): the linear field through the 2 Gauss values at the nodes.
   pure function line2_extrapolation(self) result(matrix)
      class(line2_cell_t), intent(in) :: self
      real(dp), allocatable :: matrix(:, :)
      integer :: a, g
      allocate (matrix(2, 2))
      do g = 1, 2
         do a = 1, 2
            matrix(a, g) = 0.5_dp*(1.0_dp + sqrt(3.0_dp)*real(line2_end(1, g)*line2_end(1, a), dp))
         end do
      end do
   end function line2_extrapolation

end module frix_line2_cell
