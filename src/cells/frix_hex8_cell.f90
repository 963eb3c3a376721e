!> The 8-node hexahedron as a reference cell: trilinear shape functions on [-1, 1]^3, the
!> 2 x 2 x 2 Gauss rule, VTK_HEXAHEDRON (12), gmsh type 5, POS3D BRICK8.
!>
!> Local node order is VTK's (= Abaqus C3D8, gmsh hexahedron): nodes 1-4 on the face
!> zeta = -1 counter-clockwise seen from zeta = +1, node a+4 above node a.
!> Local faces (QUAD4), each listed counter-clockwise seen from outside (the right-hand rule
!> gives the outward normal), `hex8_face_nodes`:
!>   1: zeta=-1 (1 4 3 2)   2: zeta=+1 (5 6 7 8)   3: eta=-1 (1 2 6 5)
!>   4: xi=+1  (2 3 7 6)    5: eta=+1 (3 4 8 7)    6: xi=-1  (1 5 8 4)
!> Integration point g sits at hex8_corner(:, g) / sqrt(3), beside node g, weight 1.
!> N_a(xi) = prod_i (1 + xi_ia xi_i) / 8 (Zienkiewicz & Taylor, vol. 1, 8.7).
module frix_hex8_cell
   use frix_kinds, only: dp
   use frix_reference_cell, only: reference_cell_t
   implicit none
   private

   public :: hex8_cell_t, new_hex8_cell
   public :: hex8_corner, hex8_face_nodes, hex8_gauss_abscissa, hex8_gauss_points
   public :: hex8_vtk_type, hex8_gmsh_type, hex8_pos3d_name

   !> Codes of the cell in VTK (VTK_HEXAHEDRON) and gmsh (element type 5, the same node order).
   integer, parameter :: hex8_vtk_type = 12, hex8_gmsh_type = 5
   !> Its element name in the POS3D neutral file (docs/pos3d.md; node order there: Tecgraf's).
   character(len=*), parameter :: hex8_pos3d_name = 'BRICK8'

   !> Natural coordinates of the nodes, VTK order, (3, 8).
   integer, parameter :: hex8_corner(3, 8) = reshape([ &
                                                     -1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, &
                                                     -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1], [3, 8])
   !> Local node numbers of each face, outward orientation, (4, 6).
   integer, parameter :: hex8_face_nodes(4, 6) = reshape([ &
                                                         1, 4, 3, 2, &
                                                         5, 6, 7, 8, &
                                                         1, 2, 6, 5, &
                                                         2, 3, 7, 6, &
                                                         3, 4, 8, 7, &
                                                         1, 5, 8, 4], [4, 6])
   !> Gauss abscissa 1/sqrt(3) of the 2-point rule (weight 1).
   real(dp), parameter :: hex8_gauss_abscissa = 0.57735026918962576450914878050196_dp
   !> Natural coordinates of the 8 integration points (point g beside node g), (3, 8).
   real(dp), parameter :: hex8_gauss_points(3, 8) = hex8_corner*hex8_gauss_abscissa

   type, extends(reference_cell_t) :: hex8_cell_t
   contains
      procedure :: shape_functions => hex8_shape_functions
      procedure :: extrapolation => hex8_extrapolation
   end type hex8_cell_t

contains

   pure function new_hex8_cell() result(cell)
      type(hex8_cell_t) :: cell
      cell%name = 'HEX8'
      cell%dimension = 3
      cell%n_nodes = 8
      cell%node_coordinates = real(hex8_corner, dp)
      cell%face_cell = 'QUAD4'
      cell%face_nodes = hex8_face_nodes
      cell%points = hex8_gauss_points
      cell%rule_degree = 3
      allocate (cell%weights(8), source=1.0_dp)
      cell%vtk_type = hex8_vtk_type
      cell%gmsh_type = hex8_gmsh_type
      cell%pos3d_name = hex8_pos3d_name
   end function new_hex8_cell

   pure subroutine hex8_shape_functions(self, xi, values, derivatives)
      class(hex8_cell_t), intent(in) :: self
      real(dp), intent(in) :: xi(:)
      real(dp), intent(out) :: values(:)
      real(dp), intent(out) :: derivatives(:, :)
      real(dp) :: factors(3)
      integer :: a
      do a = 1, 8
         factors = 1.0_dp + hex8_corner(:, a)*xi(1:3)
         values(a) = 0.125_dp*factors(1)*factors(2)*factors(3)
         derivatives(1, a) = 0.125_dp*hex8_corner(1, a)*factors(2)*factors(3)
         derivatives(2, a) = 0.125_dp*hex8_corner(2, a)*factors(1)*factors(3)
         derivatives(3, a) = 0.125_dp*hex8_corner(3, a)*factors(1)*factors(2)
      end do
   end subroutine hex8_shape_functions

   !> E(a, g) = N_g(sqrt(3) xi_a): the trilinear field through the 8 Gauss values evaluated at
   !> the nodes (Hinton & Campbell 1974: local least-squares smoothing, which for the
   !> 2 x 2 x 2 rule equals this inverse interpolation). Exact for fields trilinear in xi.
   pure function hex8_extrapolation(self) result(matrix)
      class(hex8_cell_t), intent(in) :: self
      real(dp), allocatable :: matrix(:, :)
      integer :: a, g
      allocate (matrix(8, 8))
      do g = 1, 8
         do a = 1, 8
            matrix(a, g) = product(1.0_dp + sqrt(3.0_dp)*real(hex8_corner(:, g)*hex8_corner(:, a), dp))/8.0_dp
         end do
      end do
   end function hex8_extrapolation

end module frix_hex8_cell
