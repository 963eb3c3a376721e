!> A reference cell: the topology and integration of one cell type as data, so that the mesh,
!> the elements and the writers read them from one table instead of assuming a shape
!> (docs/architecture.md, "Cells"). A cell gives its natural node coordinates, its faces (local
!> nodes in outward orientation and the faces' own cell type), its Gauss rule, its codes in
!> VTK, gmsh and POS3D, its shape functions and the extrapolation of integration-point values
!> to its nodes. One concrete cell per file (frix_hex8_cell, frix_quad4_cell,
!> frix_tet4_cell, frix_tri3_cell, frix_tet10_cell, frix_tri6_cell), listed in
!> frix_cell_registry.
module frix_reference_cell
   use frix_kinds, only: dp
   implicit none
   private

   public :: reference_cell_t

   type, abstract :: reference_cell_t
      character(len=:), allocatable :: name          !! e.g. 'HEX8'
      integer :: dimension = 0                       !! of its natural coordinates
      integer :: n_nodes = 0
      real(dp), allocatable :: node_coordinates(:, :)   !! (dimension, n_nodes), natural
      character(len=:), allocatable :: face_cell     !! the faces' cell type, '' if none
      integer, allocatable :: face_nodes(:, :)       !! (nodes per face, n_faces), outward
      real(dp), allocatable :: points(:, :)          !! (dimension, n_points), Gauss rule
      real(dp), allocatable :: weights(:)            !! (n_points)
      !> The natural domain: the unit simplex (true) or [-1, 1]^dimension (false).
      logical :: simplex = .false.
      !> The rule integrates exactly the monomials of this degree: in each direction on
      !> [-1, 1]^dimension (a tensor-product rule), in total on the simplex.
      integer :: rule_degree = 0
      integer :: vtk_type = 0                        !! VTK cell type code
      integer :: gmsh_type = 0                       !! gmsh element type code
      !> Local node a is node gmsh_nodes(a) of a gmsh element of the cell's type (not allocated:
      !> the same order)
      integer, allocatable :: gmsh_nodes(:)
      character(len=:), allocatable :: pos3d_name    !! POS3D %ELEMENT.<name>, '' if none
   contains
      procedure(shape_interface), deferred :: shape_functions
      procedure(extrapolation_interface), deferred :: extrapolation
      procedure :: n_points
      procedure :: n_faces
      procedure :: values_at_points
      procedure :: derivatives_at_points
   end type reference_cell_t

   abstract interface
      !> Shape function values N_a(xi) (n_nodes) and natural derivatives dN_a/dxi_d
      !> (dimension, n_nodes) at natural point `xi` (dimension).
      pure subroutine shape_interface(self, xi, values, derivatives)
         import :: reference_cell_t, dp
         class(reference_cell_t), intent(in) :: self
         real(dp), intent(in) :: xi(:)
         real(dp), intent(out) :: values(:)
         real(dp), intent(out) :: derivatives(:, :)
      end subroutine shape_interface

      !> E(a, g): the value at node a of the field that the cell's rule recovers from the
      !> values at its integration points, f_a = sum_g E(a, g) f_g, (n_nodes, n_points).
      pure function extrapolation_interface(self) result(matrix)
         import :: reference_cell_t, dp
         class(reference_cell_t), intent(in) :: self
         real(dp), allocatable :: matrix(:, :)
      end function extrapolation_interface
   end interface

contains

   pure integer function n_points(self)
      class(reference_cell_t), intent(in) :: self
      n_points = size(self%weights)
   end function n_points

   pure integer function n_faces(self)
      class(reference_cell_t), intent(in) :: self
      n_faces = 0
      if (allocated(self%face_nodes)) n_faces = size(self%face_nodes, 2)
   end function n_faces

   !> N_a at every integration point g, (n_nodes, n_points).
   pure function values_at_points(self) result(values)
      class(reference_cell_t), intent(in) :: self
      real(dp), allocatable :: values(:, :)
      real(dp), allocatable :: derivatives(:, :)
      integer :: g
      allocate (values(self%n_nodes, self%n_points()), derivatives(self%dimension, self%n_nodes))
      do g = 1, self%n_points()
         call self%shape_functions(self%points(:, g), values(:, g), derivatives)
      end do
   end function values_at_points

   !> dN_a/dxi_d at every integration point g, (dimension, n_nodes, n_points).
   pure function derivatives_at_points(self) result(derivatives)
      class(reference_cell_t), intent(in) :: self
      real(dp), allocatable :: derivatives(:, :, :)
      real(dp), allocatable :: values(:)
      integer :: g
      allocate (derivatives(self%dimension, self%n_nodes, self%n_points()), values(self%n_nodes))
      do g = 1, self%n_points()
         call self%shape_functions(self%points(:, g), values, derivatives(:, :, g))
      end do
   end function derivatives_at_points

end module frix_reference_cell
