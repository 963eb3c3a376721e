!> The 4-node tetrahedron as a reference cell: linear shape functions on the unit simplex
!> {xi, eta, zeta >= 0, xi + eta + zeta <= 1}, the 1-point rule at the centroid (weight 1/6,
!> the simplex's volume; exact for polynomials of degree 1), VTK_TETRA (10), gmsh type 4,
!> Abaqus/CalculiX C3D4; no POS3D name (frix writes BRICK8 only there, docs/pos3d.md).
!>
!> Local node order is VTK's (= gmsh, = Abaqus C3D4): node 1 at the origin, nodes 2, 3, 4 on the
!> xi, eta and zeta axes, so that nodes 1-2-3 turn counter-clockwise seen from node 4.
!> N_1 = 1 - xi - eta - zeta, N_2 = xi, N_3 = eta, N_4 = zeta (Zienkiewicz & Taylor, vol. 1, 8.8).
!> Local faces (TRI3), in the order of Abaqus' faces S1-S4, each counter-clockwise seen from
!> outside (the right-hand rule gives the outward normal), `tet4_face_nodes`:
!>   1: zeta=0 (1 3 2)   2: eta=0 (1 2 4)   3: xi+eta+zeta=1 (2 3 4)   4: xi=0 (3 1 4)
!> Extrapolation to the nodes: the one point's value at every node (a constant field).
module frix_tet4_cell
   use frix_kinds, only: dp
   use frix_reference_cell, only: reference_cell_t
   implicit none
   private

   public :: tet4_cell_t, new_tet4_cell, tet4_face_nodes, tet4_vtk_type, tet4_gmsh_type

   !> Codes of the cell in VTK (VTK_TETRA) and gmsh (element type 4, the same node order).
   integer, parameter :: tet4_vtk_type = 10, tet4_gmsh_type = 4

   !> Natural coordinates of the nodes, (3, 4).
   integer, parameter :: tet4_corner(3, 4) = reshape([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 4])
   !> Local node numbers of each face, outward orientation, (3, 4).
   integer, parameter :: tet4_face_nodes(3, 4) = reshape([1, 3, 2, 1, 2, 4, 2, 3, 4, 3, 1, 4], [3, 4])

   type, extends(reference_cell_t) :: tet4_cell_t
   contains
      procedure :: shape_functions => tet4_shape_functions
      procedure :: extrapolation => tet4_extrapolation
   end type tet4_cell_t

contains

   pure function new_tet4_cell() result(cell)
      type(tet4_cell_t) :: cell
      cell%name = 'TET4'
      cell%dimension = 3
      cell%n_nodes = 4
      cell%node_coordinates = real(tet4_corner, dp)
      cell%face_cell = 'TRI3'
      cell%face_nodes = tet4_face_nodes
      cell%simplex = .true.
      cell%rule_degree = 1
      allocate (cell%points(3, 1), source=0.25_dp)
      allocate (cell%weights(1), source=1.0_dp/6.0_dp)
      cell%vtk_type = tet4_vtk_type
      cell%gmsh_type = tet4_gmsh_type
      cell%pos3d_name = ''
   end function new_tet4_cell

   pure subroutine tet4_shape_functions(self, xi, values, derivatives)
      class(tet4_cell_t), intent(in) :: self
      real(dp), intent(in) :: xi(:)
      real(dp), intent(out) :: values(:)
      real(dp), intent(out) :: derivatives(:, :)
      values(1:4) = [1.0_dp - xi(1) - xi(2) - xi(3), xi(1), xi(2), xi(3)]
      derivatives(1:3, 1) = -1.0_dp
      derivatives(1:3, 2:4) = real(tet4_corner(:, 2:4), dp)
   end subroutine tet4_shape_functions

   !> E(a, 1) = 1: the constant field of the one point.
   pure function tet4_extrapolation(self) result(matrix)
      class(tet4_cell_t), intent(in) :: self
      real(dp), allocatable :: matrix(:, :)
      allocate (matrix(4, 1), source=1.0_dp)
   end function tet4_extrapolation

end module frix_tet4_cell
