!> The 10-node tetrahedron as a reference cell: quadratic shape functions on the unit simplex,
!> the 4-point rule of degree 2 (points at barycentric coordinates (a, b, b, b) and its
!> permutations, a = (5 + 3 sqrt 5)/20, b = (5 - sqrt 5)/20, weights 1/24: Zienkiewicz &
!> Taylor, vol. 1, table 9.3; Keast 1986), VTK_QUADRATIC_TETRA (24), gmsh type 11, Abaqus C3D10;
!> no POS3D name. Faces: 6-node triangles (TRI6), corners first.
!>
!> Local node order is VTK's (= Abaqus C3D10): corners 1-4 as TET4 (frix_tet4_cell), then the
!> mid-edge nodes 5: 1-2, 6: 2-3, 7: 3-1, 8: 1-4, 9: 2-4, 10: 3-4. Sources: VTK's
!> vtkQuadraticTetra (mid-edge points 4-9 on the edges (0,1), (1,2), (2,0), (0,3), (1,3),
!> (2,3)); Abaqus Analysis User's Guide, "Three-dimensional solid element library", and the
!> CalculiX User's Manual, C3D10 (the same). gmsh's type 11 (Gmsh Reference Manual, "Node
!> ordering", Tetrahedron10, and a tetrahedron meshed by gmsh 4.8.4 checked node by node)
!> lists the last two the other way round (9: 3-4, 10: 2-4): `gmsh_nodes` swaps them.
!> With barycentric coordinates L_1 = 1 - xi - eta - zeta, L_2 = xi, L_3 = eta, L_4 = zeta:
!> N_a = L_a (2 L_a - 1) at corner a, N_m = 4 L_i L_j at the node m on edge i-j
!> (Zienkiewicz & Taylor, vol. 1, 8.8.2; frix_quadratic_simplex).
!> Local faces (TRI6: corners counter-clockwise seen from outside, then the mid-edge nodes of
!> their edges 1-2, 2-3, 3-1), in the order of Abaqus' S1-S4 as TET4's:
!>   1: (1 3 2 7 6 5)   2: (1 2 4 5 9 8)   3: (2 3 4 6 10 9)   4: (3 1 4 7 8 10)
!> Extrapolation to the nodes: the linear field through the 4 point values (point g beside
!> corner g), evaluated at the nodes: E(a, g) = (L_g(x_a) - b) / (a - b).
module frix_tet10_cell
   use frix_kinds, only: dp
   use frix_reference_cell, only: reference_cell_t
   use frix_quadratic_simplex, only: quadratic_simplex_shape
   implicit none
   private

   public :: tet10_cell_t, new_tet10_cell, tet10_gmsh_type

   !> Codes of the cell in VTK (VTK_QUADRATIC_TETRA) and gmsh (element type 11, nodes 9 and 10 swapped).
   integer, parameter :: tet10_vtk_type = 24, tet10_gmsh_type = 11

   !> The two local corners of each mid-edge node 5..10.
   integer, parameter :: edge_corners(2, 5:10) = reshape([1, 2, 2, 3, 3, 1, 1, 4, 2, 4, 3, 4], [2, 6])
   !> Local node numbers of each face, outward orientation, (6, 4).
   integer, parameter :: tet10_face_nodes(6, 4) = reshape([1, 3, 2, 7, 6, 5, 1, 2, 4, 5, 9, 8, &
                                                           2, 3, 4, 6, 10, 9, 3, 1, 4, 7, 8, 10], [6, 4])
   !> Barycentric coordinates of the rule's points: a at its own corner, b at the others.
   real(dp), parameter :: rule_a = 0.58541019662496845446_dp, rule_b = 0.13819660112501051518_dp
   !> dL_i/dxi_d of the barycentric coordinates, (3, 4).
   real(dp), parameter :: barycentric_gradient(3, 4) = reshape([-1.0_dp, -1.0_dp, -1.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, &
                                                                0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [3, 4])

   type, extends(reference_cell_t) :: tet10_cell_t
   contains
      procedure :: shape_functions => tet10_shape_functions
      procedure :: extrapolation => tet10_extrapolation
   end type tet10_cell_t

contains

   pure function new_tet10_cell() result(cell)
      type(tet10_cell_t) :: cell
      integer :: m, g
      cell%name = 'TET10'
      cell%dimension = 3
      cell%n_nodes = 10
      allocate (cell%node_coordinates(3, 10), source=0.0_dp)
      cell%node_coordinates(:, 2:4) = barycentric_gradient(:, 2:4)
      do m = 5, 10
         cell%node_coordinates(:, m) = 0.5_dp*(cell%node_coordinates(:, edge_corners(1, m)) + &
                                               cell%node_coordinates(:, edge_corners(2, m)))
      end do
      cell%face_cell = 'TRI6'
      cell%face_nodes = tet10_face_nodes
      cell%simplex = .true.
      cell%rule_degree = 2
      allocate (cell%points(3, 4), source=rule_b)
      do g = 2, 4
         cell%points(g - 1, g) = rule_a   ! point g beside corner g: L_g = a
      end do
      allocate (cell%weights(4), source=1.0_dp/24.0_dp)
      cell%vtk_type = tet10_vtk_type
      cell%gmsh_type = tet10_gmsh_type
      cell%gmsh_nodes = [1, 2, 3, 4, 5, 6, 7, 8, 10, 9]
      cell%pos3d_name = ''
   end function new_tet10_cell

   pure function barycentric(xi) result(l)
      real(dp), intent(in) :: xi(:)
      real(dp) :: l(4)
      l = [1.0_dp - xi(1) - xi(2) - xi(3), xi(1), xi(2), xi(3)]
   end function barycentric

   pure subroutine tet10_shape_functions(self, xi, values, derivatives)
      class(tet10_cell_t), intent(in) :: self
      real(dp), intent(in) :: xi(:)
      real(dp), intent(out) :: values(:)
      real(dp), intent(out) :: derivatives(:, :)
      call quadratic_simplex_shape(barycentric(xi), barycentric_gradient, edge_corners, values(1:10), &
                                   derivatives(1:3, 1:10))
   end subroutine tet10_shape_functions

   !> E(a, g) = (L_g(x_a) - b) / (a - b): the linear field through the 4 point values.
   pure function tet10_extrapolation(self) result(matrix)
      class(tet10_cell_t), intent(in) :: self
      real(dp), allocatable :: matrix(:, :)
      integer :: a
      allocate (matrix(10, 4))
      do a = 1, 10
         matrix(a, :) = (barycentric(self%node_coordinates(:, a)) - rule_b)/(rule_a - rule_b)
      end do
   end function tet10_extrapolation

end module frix_tet10_cell
