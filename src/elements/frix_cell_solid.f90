!> A displacement solid element over any 3D reference cell (frix_reference_cell): the cell
!> supplies its shape functions, their natural derivatives and its Gauss rule; this module
!> does the rest, written once over the shape-function derivatives. The TET4 formulation is
!> this element on the TET4 cell (constant strain tetrahedron, 1 point), TET10 on the TET10
!> cell (quadratic tetrahedron, 4 points); another cell type is a new cell, a constructor here
!> and one line in the element registry.
!>
!> At each point g of the rule: J_ij = dX_j/dxi_i = sum_a dN_a/dxi_i X_ja, dN_a/dX = J^{-1}
!> dN_a/dxi, dV0_g = detJ w_g (Zienkiewicz & Taylor, vol. 1, 9.2-9.4).
!> Linear kinematics: eps = B u, sigma = material(eps), fint = sum_g B^T sigma dV_g,
!>   K = sum_g B^T C B dV_g.
!> Total Lagrangian: F = I + Grad u, E = (F^T F - I)/2, S = material(E),
!>   fint_a = sum_g (F S) Grad N_a dV0_g, K = sum_g (B_NL^T C B_NL + (Grad N_a . S . Grad N_b) I)
!>   dV0_g (Bathe, Finite Element Procedures, 6.2; Wriggers, Nonlinear FEM, 4.2).
!> The kinematics, the material pass, B_NL and the Cauchy stress come from frix_solid_kinematics,
!> shared with frix_hex8.
!> No enhanced strains: n_enhanced = 0. The full tangent is computed (no mirroring).
module frix_cell_solid
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_property_list, only: property_list_t, property_spec_t
   use frix_material, only: material_t
   use frix_element, only: element_t, kinematics_total_lagrangian
   use frix_vector_algebra, only: determinant, invert3
   use frix_reference_cell, only: reference_cell_t
   use frix_tet4_cell, only: new_tet4_cell
   use frix_tet10_cell, only: new_tet10_cell
   use frix_solid_kinematics, only: compatible_kinematics, deformed_material_pass, nonlinear_b, point_stresses, &
                                    tensor_from_voigt
   implicit none
   private

   public :: cell_solid_t, new_cell_solid, tet4_from_options, tet10_from_options, no_options

   type, extends(element_t) :: cell_solid_t
      class(reference_cell_t), allocatable :: cell
      real(dp), allocatable :: shape_values(:, :)        !! N_a at point g, (n_nodes, n_points)
      real(dp), allocatable :: natural_derivatives(:, :, :)   !! dN_a/dxi_d at g, (cell dimension, n_nodes, n_points)
   contains
      procedure :: n_nodes => cell_solid_n_nodes
      procedure :: n_points => cell_solid_n_points
      procedure :: n_enhanced => cell_solid_n_enhanced
      procedure :: evaluate => cell_solid_evaluate
      procedure :: volume_weights => cell_solid_volume_weights
      procedure :: point_positions => cell_solid_point_positions
   end type cell_solid_t

contains

   !> The solid element on `cell` with `kinematics`; its name is the cell's.
   function new_cell_solid(cell, kinematics) result(element)
      class(reference_cell_t), intent(in) :: cell
      integer, intent(in) :: kinematics
      type(cell_solid_t) :: element
      element%name = cell%name
      element%kinematics = kinematics
      allocate (element%cell, source=cell)
      element%shape_values = cell%values_at_points()
      element%natural_derivatives = cell%derivatives_at_points()
   end function new_cell_solid

   !> TET4 (element registry): no options (the deck reader takes only the specs' keywords,
   !> none here).
   subroutine tet4_from_options(options, kinematics, element, error)
      type(property_list_t), intent(in) :: options
      integer, intent(in) :: kinematics
      class(element_t), allocatable, intent(out) :: element
      type(error_t), allocatable, intent(out) :: error
      call solid_without_options(new_tet4_cell(), options, kinematics, element, error)
   end subroutine tet4_from_options

   !> TET10 (element registry): no options.
   subroutine tet10_from_options(options, kinematics, element, error)
      type(property_list_t), intent(in) :: options
      integer, intent(in) :: kinematics
      class(element_t), allocatable, intent(out) :: element
      type(error_t), allocatable, intent(out) :: error
      call solid_without_options(new_tet10_cell(), options, kinematics, element, error)
   end subroutine tet10_from_options

   !> The solid element on `cell`; an error if `options` holds any.
   subroutine solid_without_options(cell, options, kinematics, element, error)
      class(reference_cell_t), intent(in) :: cell
      type(property_list_t), intent(in) :: options
      integer, intent(in) :: kinematics
      class(element_t), allocatable, intent(out) :: element
      type(error_t), allocatable, intent(out) :: error
      if (allocated(options%names)) then
         if (size(options%names) > 0) then
            call fatal_error(error, 'element shape '//cell%name//' takes no options')
            return
         end if
      end if
      allocate (element, source=new_cell_solid(cell, kinematics))
   end subroutine solid_without_options

   !> The option keywords of a formulation without options.
   function no_options() result(specs)
      type(property_spec_t), allocatable :: specs(:)
      allocate (specs(0))
   end function no_options

   pure function cell_solid_n_nodes(self) result(n)
      class(cell_solid_t), intent(in) :: self
      integer :: n
      n = self%cell%n_nodes
   end function cell_solid_n_nodes

   pure function cell_solid_n_points(self) result(n)
      class(cell_solid_t), intent(in) :: self
      integer :: n
      n = self%cell%n_points()
   end function cell_solid_n_points

   pure function cell_solid_n_enhanced(self) result(n)
      class(cell_solid_t), intent(in) :: self
      integer :: n
      n = 0
   end function cell_solid_n_enhanced

   !> int N_a dV0 = sum_g N_a(xi_g) detJ_g w_g (exact for an affine map and a rule of degree >= 1).
   pure subroutine cell_solid_volume_weights(self, coords, weights)
      class(cell_solid_t), intent(in) :: self
      real(dp), intent(in) :: coords(:, :)   !! (3, n_nodes)
      real(dp), intent(out) :: weights(:)    !! (n_nodes)
      integer :: g, n
      n = self%cell%n_nodes
      weights(1:n) = 0.0_dp
      do g = 1, self%cell%n_points()
         weights(1:n) = weights(1:n) + self%shape_values(:, g)*self%cell%weights(g)* &
                        determinant(matmul(self%natural_derivatives(:, :, g), transpose(coords(:, 1:n))))
      end do
   end subroutine cell_solid_volume_weights

   !> X_g = sum_a N_a(xi_g) X_a at the rule's points.
   pure subroutine cell_solid_point_positions(self, coords, positions)
      class(cell_solid_t), intent(in) :: self
      real(dp), intent(in) :: coords(:, :)      !! (3, n_nodes)
      real(dp), intent(out) :: positions(:, :)  !! (3, n_points)
      positions(:, 1:self%cell%n_points()) = matmul(coords(:, 1:self%cell%n_nodes), self%shape_values)
   end subroutine cell_solid_point_positions

   !> Internal force and tangent (formulas in the module header).
   subroutine cell_solid_evaluate(self, material, coords, u, alpha, state_old, state_new, &
                                  fint, tangent, stress, strain, error, initial_stress)
      class(cell_solid_t), intent(in) :: self
      class(material_t), intent(in) :: material
      real(dp), intent(in) :: coords(:, :)       !! (3, n_nodes) reference coordinates
      real(dp), intent(in) :: u(:, :)            !! (3, n_nodes) total displacements
      real(dp), intent(inout) :: alpha(:)        !! unused (no enhanced strains)
      real(dp), intent(in) :: state_old(:, :)    !! (n_state, n_points)
      real(dp), intent(inout) :: state_new(:, :) !! (n_state, n_points)
      real(dp), intent(out) :: fint(:)           !! (3 n_nodes)
      real(dp), intent(out), optional :: tangent(:, :)
      real(dp), intent(out), optional :: stress(:, :)
      real(dp), intent(out), optional :: strain(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(dp), intent(in), optional :: initial_stress(:, :)   !! (6, n_points) sigma0 (element_t)
      real(dp), allocatable :: dn_dx(:, :, :), volume(:), deformation(:, :, :), total(:, :), pk2(:, :), &
                               moduli(:, :, :)
      integer :: g, n_points
      logical :: total_lagrangian

      n_points = self%cell%n_points()
      total_lagrangian = self%kinematics == kinematics_total_lagrangian
      allocate (deformation(3, 3, n_points), total(6, n_points), pk2(6, n_points), moduli(6, 6, n_points))
      call reference_gradients(self, coords, dn_dx, volume, error)
      if (allocated(error)) return
      do g = 1, n_points
         call compatible_kinematics(dn_dx(:, :, g), u, total_lagrangian, deformation(:, :, g), total(:, g))
      end do
      if (present(initial_stress)) then
         call deformed_material_pass(self%name, material, total_lagrangian, deformation, total, state_old, state_new, &
                                     pk2, moduli, error, initial_stress)
      else
         call deformed_material_pass(self%name, material, total_lagrangian, deformation, total, state_old, state_new, &
                                     pk2, moduli, error)
      end if
      if (allocated(error)) return
      call internal_force(dn_dx, volume, deformation, pk2, fint)
      if (present(tangent)) call element_tangent(dn_dx, volume, deformation, pk2, moduli, total_lagrangian, tangent)
      if (present(stress)) call point_stresses(total_lagrangian, deformation, pk2, stress)
      if (present(strain)) strain(:, 1:n_points) = total
   end subroutine cell_solid_evaluate

   !> dN_a/dX at every point and dV0 = detJ w; an error names the first point with detJ <= 0.
   subroutine reference_gradients(self, coords, dn_dx, volume, error)
      class(cell_solid_t), intent(in) :: self
      real(dp), intent(in) :: coords(:, :)
      real(dp), allocatable, intent(out) :: dn_dx(:, :, :), volume(:)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: jacobian(3, 3), inverse(3, 3), det
      integer :: g, n
      n = self%cell%n_nodes
      allocate (dn_dx(3, n, self%cell%n_points()), volume(self%cell%n_points()))
      do g = 1, self%cell%n_points()
         jacobian = matmul(self%natural_derivatives(:, :, g), transpose(coords(:, 1:n)))
         call invert3(jacobian, inverse, det)
         if (.not. (det > 0.0_dp)) then
            call fatal_error(error, self%name//': non-positive Jacobian determinant '//to_string(det)// &
                             ' at integration point '//to_string(g))
            return
         end if
         volume(g) = det*self%cell%weights(g)
         dn_dx(:, :, g) = matmul(inverse, self%natural_derivatives(:, :, g))
      end do
   end subroutine reference_gradients

   !> fint_a = sum_g (F S) Grad N_a dV (F = I under linear kinematics, S = sigma).
   pure subroutine internal_force(dn_dx, volume, deformation, pk2, fint)
      real(dp), intent(in) :: dn_dx(:, :, :), volume(:), deformation(:, :, :), pk2(:, :)
      real(dp), intent(out) :: fint(:)
      real(dp) :: first_pk(3, 3)
      integer :: g, a
      fint(1:3*size(dn_dx, 2)) = 0.0_dp
      do g = 1, size(volume)
         first_pk = volume(g)*matmul(deformation(:, :, g), tensor_from_voigt(pk2(:, g)))
         do a = 1, size(dn_dx, 2)
            fint(3*a - 2:3*a) = fint(3*a - 2:3*a) + matmul(first_pk, dn_dx(:, a, g))
         end do
      end do
   end subroutine internal_force

   !> K = sum_g (B_NL^T C B_NL + [total Lagrangian] (Grad N_a . S . Grad N_b) I) dV; F = I gives
   !> the linear B.
   pure subroutine element_tangent(dn_dx, volume, deformation, pk2, moduli, total_lagrangian, tangent)
      real(dp), intent(in) :: dn_dx(:, :, :), volume(:), deformation(:, :, :), pk2(:, :), moduli(:, :, :)
      logical, intent(in) :: total_lagrangian
      real(dp), intent(out) :: tangent(:, :)
      real(dp) :: b_nl(6, 3, size(dn_dx, 2)), c_b(6, 3), s_tensor(3, 3), geometric
      integer :: g, a, b, i, n
      n = size(dn_dx, 2)
      tangent(1:3*n, 1:3*n) = 0.0_dp
      do g = 1, size(volume)
         call nonlinear_b(deformation(:, :, g), dn_dx(:, :, g), b_nl)
         s_tensor = volume(g)*tensor_from_voigt(pk2(:, g))
         do b = 1, n
            c_b = volume(g)*matmul(moduli(:, :, g), b_nl(:, :, b))
            do a = 1, n
               tangent(3*a - 2:3*a, 3*b - 2:3*b) = tangent(3*a - 2:3*a, 3*b - 2:3*b) + &
                                                   matmul(transpose(b_nl(:, :, a)), c_b)
               if (.not. total_lagrangian) cycle
               geometric = dot_product(dn_dx(:, a, g), matmul(s_tensor, dn_dx(:, b, g)))
               do i = 1, 3
                  tangent(3*a - 3 + i, 3*b - 3 + i) = tangent(3*a - 3 + i, 3*b - 3 + i) + geometric
               end do
            end do
         end do
      end do
   end subroutine element_tangent

end module frix_cell_solid
