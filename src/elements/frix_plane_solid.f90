!> A displacement solid element over any 2D reference cell (QUAD4, TRI3): plane strain with a
!> thickness t, or axisymmetric (x = radius R >= 0, y = axial coordinate, z = the hoop
!> direction theta). Element vectors keep the 3 slots per node of every element_t; the z
!> slots of fint and every z row and column of the tangent are zero, and z of the coordinates
!> and displacements is not read (the nodes lie in the plane z = 0).
!>
!> Geometry at point g of the cell's rule: J_ij = dX_j/dxi_i (2 x 2), dN_a/dX = J^{-1} dN_a/dxi,
!> R = sum_a N_a X_a (Zienkiewicz & Taylor, vol. 1, 9.2-9.4), and the reference measure
!>   plane strain:  dV0 = t detJ w_g,
!>   axisymmetric:  dV0 = 2 pi R detJ w_g (Zienkiewicz & Taylor, vol. 1, ch. 6: the full ring).
!> Axisymmetric forces, reactions and tangents are therefore totals over the whole
!> circumference (as in Abaqus's axisymmetric elements), not per radian.
!>
!> Kinematics, in the 3D Voigt layout of the material laws (11 22 33 12 13 23, 3 = out of plane
!> or hoop), so that every law serves the 2D element unchanged:
!>   F = [[1 + u_x,X, u_x,Y, 0], [u_y,X, 1 + u_y,Y, 0], [0, 0, F_33]],
!>   F_33 = 1 (plane strain), F_33 = 1 + u_r/R (axisymmetric, u_r = sum_a N_a u_xa);
!>   linear: eps = (u_x,X, u_y,Y, eps_33, u_x,Y + u_y,X, 0, 0), eps_33 = 0 or u_r/R;
!>   total Lagrangian: E = (F^T F - I)/2, E_33 = (F_33^2 - 1)/2.
!> The nodal blocks of dE/du, B_NL (frix_solid_kinematics%nonlinear_b over the in-plane
!> gradients), get the hoop row dE_33/du_ax = F_33 N_a/R (F_33 = 1: the linear hoop row
!> N_a/R) (Bathe, Finite Element Procedures, 5.3.3 and 6.3.4).
!>   fint_a = sum_g B_NL,a^T S dV0 (= P : dF/du_a dV0, P = F S),
!>   K_ab = sum_g (B_NL,a^T C B_NL,b + [total Lagrangian] G_ab) dV0, with the geometric part
!>   G_ab = (Grad N_a . S_2x2 . Grad N_b) I_2 + [axisymmetric] S_33 N_a N_b / R^2 on (x, x)
!>   (d^2 E_33 / du_ax du_bx = N_a N_b / R^2; Bathe 6.3.4).
!> The Cauchy stress is F S F^T / det F (frix_solid_kinematics). The element extends
!> frix_cell_solid's (cell, shape tables, node and point counts).
!>
!> Enhanced assumed strains (QUAD4 only, n_eas = 4): the strain passed to the material is
!> E(u) + G_g alpha (eps + eps~ under linear kinematics, the Green-Lagrange strain E + E~ under
!> total Lagrangian kinematics, as frix_hex8), G_g = (dV_c / dV_g) T0^{-T} M(xi_g) with the
!> modes M of Simo & Rifai (1990, IJNME 29: E11 ~ xi, E22 ~ eta, E12 ~ xi, eta;
!> frix_eas_modes%plane_eas_modes), T0^{-T} the push of natural strains by P = J0^{-1}, J0 the
!> Jacobian at the centre xi = 0 (Simo & Rifai's constant-Jacobian transformation, P_33 = 1),
!> and dV_c / dV_g = detJ0 m(R0) / (detJ_g m(R_g)), m = t or 2 pi R, R0 the centre's radius.
!> In plane strain this is Simo & Rifai's detJ0 / detJ; in axisymmetry the measure ratio keeps
!> int G dV = detJ0 m(R0) T0^{-T} sum_g M(xi_g) w_g = 0 (Simo & Rifai's condition for the patch
!> test, here on the ring's volume element). The out-of-plane / hoop strain E_33 and the
!> shears 13, 23 are not enhanced. alpha is solved locally and the tangent condensed by
!> frix_enhanced_strain.
!>
!> Edge pressure (face_pressure): on an edge (LINE2 cell, its own 2-point Gauss rule) listed
!> counter-clockwise around the element, the outward normal times the length element is
!> n ds = (y_,s, -x_,s) ds; the traction -p n (p > 0 pushes into the body) over the measure
!> t ds (plane strain) or 2 pi r ds (axisymmetric) gives f_a = -p int N_a m (y_,xi, -x_,xi) dxi,
!> m = t or 2 pi r, r = sum_b N_b x_b. Follower load: current geometry x = X + u and the load
!> stiffness d f / d u (unsymmetric); dead load: reference geometry, zero tangent.
module frix_plane_solid
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_material, only: material_t
   use frix_element, only: kinematics_total_lagrangian
   use frix_vector_algebra, only: invert3
   use frix_eas_modes, only: plane_eas_modes, strain_push_matrix
   use frix_enhanced_strain, only: local_problem_t, start_local_problem, set_enhanced_operator, enhanced_response, &
                                   condense
   use frix_cell_solid, only: cell_solid_t, new_cell_solid
   use frix_reference_cell, only: reference_cell_t
   use frix_solid_kinematics, only: compatible_kinematics, deformed_material_pass, nonlinear_b, point_stresses, &
                                    check_deformation, &
                                    tensor_from_voigt
   implicit none
   private

   public :: plane_solid_t, new_plane_solid

   real(dp), parameter :: two_pi = 8.0_dp*atan(1.0_dp)

   !> The cell, its shape tables and the counts are frix_cell_solid's (natural_derivatives:
   !> (2, n_nodes, n_points) on a 2D cell).
   type, extends(cell_solid_t) :: plane_solid_t
      logical :: axisymmetric = .false.
      real(dp) :: thickness = 1.0_dp                     !! t (length unit), plane strain only
      integer :: n_eas = 0                               !! enhanced strain parameters: 0 or 4 (QUAD4)
   contains
      procedure :: n_enhanced => plane_solid_n_enhanced
      procedure :: evaluate => plane_solid_evaluate
      procedure :: volume_weights => plane_solid_volume_weights
      procedure :: point_positions => plane_solid_point_positions
      procedure :: face_pressure => plane_solid_face_pressure
      procedure :: resists_translation => plane_solid_resists_translation
      procedure :: face_weights => plane_solid_face_weights
   end type plane_solid_t

   !> The reference geometry of the element at its points.
   type :: point_geometry_t
      real(dp), allocatable :: dn_dx(:, :, :)   !! (3, n_nodes, n_points): dN_a/dX, dN_a/dY, 0
      real(dp), allocatable :: radius(:)        !! R at each point (axisymmetric)
      real(dp), allocatable :: volume(:)        !! dV0 at each point
   end type point_geometry_t

contains

   !> The plane element called `name` on the 2D `cell`: axisymmetric, or plane strain of
   !> `thickness` (length unit, > 0; default 1), with `n_eas` enhanced strain parameters (0 or 4
   !> on QUAD4, checked by the caller; default 0; the name gets '-EAS<n>').
   function new_plane_solid(name, cell, kinematics, axisymmetric, thickness, n_eas) result(element)
      character(len=*), intent(in) :: name
      class(reference_cell_t), intent(in) :: cell
      integer, intent(in) :: kinematics
      logical, intent(in) :: axisymmetric
      real(dp), intent(in), optional :: thickness
      integer, intent(in), optional :: n_eas
      type(plane_solid_t) :: element
      element%cell_solid_t = new_cell_solid(cell, kinematics)
      element%name = name
      element%axisymmetric = axisymmetric
      if (present(thickness)) element%thickness = thickness
      if (present(n_eas)) element%n_eas = n_eas
      if (element%n_eas > 0) element%name = name//'-EAS'//to_string(element%n_eas)
   end function new_plane_solid

   pure function plane_solid_n_enhanced(self) result(n)
      class(plane_solid_t), intent(in) :: self
      integer :: n
      n = self%n_eas
   end function plane_solid_n_enhanced

   !> J^{-1} dN/dxi (2, n_nodes), detJ and R at point g.
   pure subroutine point_jacobian(self, coords, g, dn_dx, det, radius)
      class(plane_solid_t), intent(in) :: self
      real(dp), intent(in) :: coords(:, :)
      integer, intent(in) :: g
      real(dp), intent(out) :: dn_dx(:, :), det, radius
      real(dp) :: jacobian(2, 2), inverse(2, 2)
      integer :: n
      n = self%cell%n_nodes
      jacobian = matmul(self%natural_derivatives(:, :, g), transpose(coords(1:2, 1:n)))
      det = jacobian(1, 1)*jacobian(2, 2) - jacobian(1, 2)*jacobian(2, 1)
      inverse = reshape([jacobian(2, 2), -jacobian(2, 1), -jacobian(1, 2), jacobian(1, 1)], [2, 2])/det
      dn_dx(1:2, 1:n) = matmul(inverse, self%natural_derivatives(:, :, g))
      radius = dot_product(self%shape_values(:, g), coords(1, 1:n))
   end subroutine point_jacobian

   !> The measure per unit area of the section: t, or 2 pi R.
   pure real(dp) function section_measure(self, radius) result(measure)
      class(plane_solid_t), intent(in) :: self
      real(dp), intent(in) :: radius
      if (self%axisymmetric) then
         measure = two_pi*radius
      else
         measure = self%thickness
      end if
   end function section_measure

   !> int N_a dV0 = sum_g N_a(xi_g) m(R_g) detJ_g w_g (exact for an affine map: the 2 x 2 and
   !> 3-point rules integrate N_a R of degree 2).
   pure subroutine plane_solid_volume_weights(self, coords, weights)
      class(plane_solid_t), intent(in) :: self
      real(dp), intent(in) :: coords(:, :)   !! (3, n_nodes)
      real(dp), intent(out) :: weights(:)    !! (n_nodes)
      real(dp) :: dn_dx(2, self%cell%n_nodes), det, radius
      integer :: g, n
      n = self%cell%n_nodes
      weights(1:n) = 0.0_dp
      do g = 1, self%cell%n_points()
         call point_jacobian(self, coords, g, dn_dx, det, radius)
         weights(1:n) = weights(1:n) + self%shape_values(:, g)*self%cell%weights(g)*det*section_measure(self, radius)
      end do
   end subroutine plane_solid_volume_weights

   !> X_g = sum_a N_a(xi_g) X_a at the rule's points, z = 0.
   pure subroutine plane_solid_point_positions(self, coords, positions)
      class(plane_solid_t), intent(in) :: self
      real(dp), intent(in) :: coords(:, :)      !! (3, n_nodes)
      real(dp), intent(out) :: positions(:, :)  !! (3, n_points)
      integer :: n_points
      n_points = self%cell%n_points()
      positions(1:2, 1:n_points) = matmul(coords(1:2, 1:self%cell%n_nodes), self%shape_values)
      positions(3, 1:n_points) = 0.0_dp
   end subroutine plane_solid_point_positions

   !> dN_a/dX, R and dV0 at every point; an error names the first point with detJ <= 0 or,
   !> axisymmetric, R <= 0.
   subroutine reference_geometry(self, coords, geometry, error)
      class(plane_solid_t), intent(in) :: self
      real(dp), intent(in) :: coords(:, :)
      type(point_geometry_t), intent(out) :: geometry
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: det
      integer :: g, n
      n = self%cell%n_nodes
      allocate (geometry%dn_dx(3, n, self%cell%n_points()), source=0.0_dp)
      allocate (geometry%radius(self%cell%n_points()), geometry%volume(self%cell%n_points()))
      do g = 1, self%cell%n_points()
         call point_jacobian(self, coords, g, geometry%dn_dx(1:2, :, g), det, geometry%radius(g))
         if (.not. (det > 0.0_dp)) then
            call fatal_error(error, self%name//': non-positive Jacobian determinant '//to_string(det)// &
                             ' at integration point '//to_string(g))
            return
         end if
         if (self%axisymmetric .and. .not. (geometry%radius(g) > 0.0_dp)) then
            call fatal_error(error, self%name//': non-positive radius (x) '//to_string(geometry%radius(g))// &
                             ' at integration point '//to_string(g)//' of an axisymmetric element')
            return
         end if
         geometry%volume(g) = det*self%cell%weights(g)*section_measure(self, geometry%radius(g))
      end do
   end subroutine reference_geometry

   !> F and the strain at point g (formulas in the module header); `planar` is u with z = 0.
   pure subroutine point_kinematics(self, geometry, g, planar, total_lagrangian, deformation, strain)
      class(plane_solid_t), intent(in) :: self
      type(point_geometry_t), intent(in) :: geometry
      integer, intent(in) :: g
      real(dp), intent(in) :: planar(:, :)
      logical, intent(in) :: total_lagrangian
      real(dp), intent(out) :: deformation(3, 3), strain(6)
      real(dp) :: hoop
      call compatible_kinematics(geometry%dn_dx(:, :, g), planar, total_lagrangian, deformation, strain)
      hoop = 0.0_dp
      if (self%axisymmetric) hoop = dot_product(self%shape_values(:, g), planar(1, :))/geometry%radius(g)
      if (total_lagrangian) then
         deformation(3, 3) = 1.0_dp + hoop
         strain(3) = hoop + 0.5_dp*hoop**2
      else
         strain(3) = hoop
      end if
   end subroutine point_kinematics

   !> Nodal blocks of dE/du at point g, (6, 3, n_nodes): nonlinear_b over the in-plane gradients,
   !> the hoop row F_33 N_a/R, zero z columns.
   pure subroutine plane_b(self, geometry, g, deformation, b_nl)
      class(plane_solid_t), intent(in) :: self
      type(point_geometry_t), intent(in) :: geometry
      integer, intent(in) :: g
      real(dp), intent(in) :: deformation(3, 3)
      real(dp), intent(out) :: b_nl(:, :, :)
      call nonlinear_b(deformation, geometry%dn_dx(:, :, g), b_nl)
      b_nl(:, 3, :) = 0.0_dp
      if (self%axisymmetric) b_nl(3, 1, :) = deformation(3, 3)*self%shape_values(:, g)/geometry%radius(g)
   end subroutine plane_b

   !> Internal force and tangent (formulas in the module header).
   subroutine plane_solid_evaluate(self, material, coords, u, alpha, state_old, state_new, &
                                   fint, tangent, stress, strain, error, initial_stress)
      class(plane_solid_t), intent(in) :: self
      class(material_t), intent(in) :: material
      real(dp), intent(in) :: coords(:, :)       !! (3, n_nodes) reference coordinates (z not read)
      real(dp), intent(in) :: u(:, :)            !! (3, n_nodes) total displacements (z not read)
      real(dp), intent(inout) :: alpha(:)        !! (n_eas) enhanced strain parameters
      real(dp), intent(in) :: state_old(:, :)    !! (n_state, n_points)
      real(dp), intent(inout) :: state_new(:, :) !! (n_state, n_points)
      real(dp), intent(out) :: fint(:)           !! (3 n_nodes), z entries 0
      real(dp), intent(out), optional :: tangent(:, :)
      real(dp), intent(out), optional :: stress(:, :)
      real(dp), intent(out), optional :: strain(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(dp), intent(in), optional :: initial_stress(:, :)   !! (6, n_points) sigma0 (element_t)
      type(point_geometry_t) :: geometry
      type(local_problem_t) :: problem
      real(dp), allocatable :: planar(:, :), deformation(:, :, :), total(:, :), pk2(:, :), moduli(:, :, :)
      integer :: g, n, n_points
      logical :: total_lagrangian

      n = self%cell%n_nodes
      n_points = self%cell%n_points()
      total_lagrangian = self%kinematics == kinematics_total_lagrangian
      allocate (deformation(3, 3, n_points), total(6, n_points), pk2(6, n_points), moduli(6, 6, n_points))
      call reference_geometry(self, coords, geometry, error)
      if (allocated(error)) return
      planar = u(:, 1:n)
      planar(3, :) = 0.0_dp
      do g = 1, n_points
         call point_kinematics(self, geometry, g, planar, total_lagrangian, deformation(:, :, g), total(:, g))
      end do
      if (self%n_eas > 0) then
         if (present(initial_stress)) then
            call start_local_problem(problem, self%n_eas, total_lagrangian, geometry%volume, total, initial_stress)
         else
            call start_local_problem(problem, self%n_eas, total_lagrangian, geometry%volume, total)
         end if
         call enhanced_pass(self, material, coords, geometry, deformation, problem, state_old, state_new, alpha, &
                            total, pk2, moduli, error)
      else if (present(initial_stress)) then
         call deformed_material_pass(self%name, material, total_lagrangian, deformation, total, state_old, state_new, &
                                     pk2, moduli, error, initial_stress)
      else
         call deformed_material_pass(self%name, material, total_lagrangian, deformation, total, state_old, state_new, &
                                     pk2, moduli, error)
      end if
      if (allocated(error)) return
      call force_and_tangent(self, geometry, deformation, pk2, moduli, total_lagrangian, fint, tangent)
      if (self%n_eas > 0 .and. present(tangent)) then
         call condensed_tangent(self, material, geometry, deformation, problem, moduli, tangent, error)
         if (allocated(error)) return
      end if
      if (present(stress)) call point_stresses(total_lagrangian, deformation, pk2, stress)
      if (present(strain)) strain(:, 1:n_points) = total
   end subroutine plane_solid_evaluate

   !> The enhanced response (module header): det F checked (total Lagrangian), G set, alpha
   !> solved from the alpha passed in; total, pk2, moduli at the converged alpha.
   subroutine enhanced_pass(self, material, coords, geometry, deformation, problem, state_old, state_new, alpha, &
                            total, pk2, moduli, error)
      class(plane_solid_t), intent(in) :: self
      class(material_t), intent(in) :: material
      real(dp), intent(in) :: coords(:, :)
      type(point_geometry_t), intent(in) :: geometry
      real(dp), intent(in) :: deformation(:, :, :)
      type(local_problem_t), intent(inout) :: problem
      real(dp), intent(in) :: state_old(:, :)
      real(dp), intent(inout) :: state_new(:, :)
      real(dp), intent(inout) :: alpha(:)
      real(dp), intent(out) :: total(:, :), pk2(:, :), moduli(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      if (size(alpha) < self%n_eas) then
         call fatal_error(error, self%name//': alpha has '//to_string(size(alpha))//' entries, '// &
                          to_string(self%n_eas)//' needed')
         return
      end if
      if (problem%finite) then
         call check_deformation(self%name, deformation, error)
         if (allocated(error)) return
      end if
      call enhanced_operators(self, coords, geometry, problem, error)
      if (allocated(error)) return
      call enhanced_response(self%name, material, problem, state_old, state_new, alpha, total, pk2, moduli, error)
   end subroutine enhanced_pass

   !> G_g = (dV_c / dV_g) T0^{-T} M(xi_g) at every point (module header), T0^{-T} from
   !> P = J0^{-1} in the plane and P_33 = 1 (frix_eas_modes%strain_push_matrix).
   subroutine enhanced_operators(self, coords, geometry, problem, error)
      class(plane_solid_t), intent(in) :: self
      real(dp), intent(in) :: coords(:, :)
      type(point_geometry_t), intent(in) :: geometry
      type(local_problem_t), intent(inout) :: problem
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: shape(self%cell%n_nodes), derivatives(2, self%cell%n_nodes), jacobian0(3, 3), inverse0(3, 3)
      real(dp) :: det0, centre_measure, push(6, 6), modes(6, self%n_eas)
      integer :: g, n
      n = self%cell%n_nodes
      call self%cell%shape_functions([0.0_dp, 0.0_dp], shape, derivatives)
      jacobian0 = 0.0_dp
      jacobian0(1:2, 1:2) = matmul(derivatives, transpose(coords(1:2, 1:n)))
      jacobian0(3, 3) = 1.0_dp
      call invert3(jacobian0, inverse0, det0)
      if (.not. (det0 > 0.0_dp)) then
         call fatal_error(error, self%name//': non-positive Jacobian determinant '//to_string(det0)// &
                          ' at the element centre')
         return
      end if
      call strain_push_matrix(inverse0, push)
      centre_measure = det0*section_measure(self, dot_product(shape, coords(1, 1:n)))
      do g = 1, size(geometry%volume)
         call plane_eas_modes(self%n_eas, self%cell%points(:, g), modes)
         call set_enhanced_operator(problem, g, centre_measure*self%cell%weights(g)/geometry%volume(g), push, modes)
      end do
   end subroutine enhanced_operators

   !> The tangent condensed over alpha (frix_enhanced_strain%condense) with the blocks plane_b.
   subroutine condensed_tangent(self, material, geometry, deformation, problem, moduli, tangent, error)
      class(plane_solid_t), intent(in) :: self
      class(material_t), intent(in) :: material
      type(point_geometry_t), intent(in) :: geometry
      real(dp), intent(in) :: deformation(:, :, :), moduli(:, :, :)
      type(local_problem_t), intent(in) :: problem
      real(dp), intent(inout) :: tangent(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: b_blocks(6, 3, self%cell%n_nodes, size(geometry%volume))
      integer :: g
      do g = 1, size(geometry%volume)
         call plane_b(self, geometry, g, deformation(:, :, g), b_blocks(:, :, :, g))
      end do
      call condense(self%name, problem, b_blocks, moduli, material%symmetric_tangent(), tangent, error)
   end subroutine condensed_tangent

   !> fint_a = sum_g B_NL,a^T S dV0 and, if present, K = sum_g (B_NL^T C B_NL + [total
   !> Lagrangian] G) dV0 (module header).
   pure subroutine force_and_tangent(self, geometry, deformation, pk2, moduli, total_lagrangian, fint, tangent)
      class(plane_solid_t), intent(in) :: self
      type(point_geometry_t), intent(in) :: geometry
      real(dp), intent(in) :: deformation(:, :, :), pk2(:, :), moduli(:, :, :)
      logical, intent(in) :: total_lagrangian
      real(dp), intent(out) :: fint(:)
      real(dp), intent(out), optional :: tangent(:, :)
      real(dp) :: b_nl(6, 3, self%cell%n_nodes), c_b(6, 3), s_tensor(3, 3), geometric
      integer :: g, a, b, i, n
      n = self%cell%n_nodes
      fint(1:3*n) = 0.0_dp
      if (present(tangent)) tangent(1:3*n, 1:3*n) = 0.0_dp
      do g = 1, size(geometry%volume)
         call plane_b(self, geometry, g, deformation(:, :, g), b_nl)
         do a = 1, n
            fint(3*a - 2:3*a) = fint(3*a - 2:3*a) + geometry%volume(g)*matmul(pk2(:, g), b_nl(:, :, a))
         end do
         if (.not. present(tangent)) cycle
         s_tensor = geometry%volume(g)*tensor_from_voigt(pk2(:, g))
         do b = 1, n
            c_b = geometry%volume(g)*matmul(moduli(:, :, g), b_nl(:, :, b))
            do a = 1, n
               tangent(3*a - 2:3*a, 3*b - 2:3*b) = tangent(3*a - 2:3*a, 3*b - 2:3*b) + &
                                                   matmul(transpose(b_nl(:, :, a)), c_b)
               if (.not. total_lagrangian) cycle
               geometric = dot_product(geometry%dn_dx(1:2, a, g), matmul(s_tensor(1:2, 1:2), geometry%dn_dx(1:2, b, g)))
               do i = 1, 2
                  tangent(3*a - 3 + i, 3*b - 3 + i) = tangent(3*a - 3 + i, 3*b - 3 + i) + geometric
               end do
               if (self%axisymmetric) tangent(3*a - 2, 3*b - 2) = tangent(3*a - 2, 3*b - 2) + s_tensor(3, 3)* &
                  self%shape_values(a, g)*self%shape_values(b, g)/geometry%radius(g)**2
            end do
         end do
      end do
   end subroutine force_and_tangent

   !> A uniform pressure on the edge `face` (a LINE2 cell; module header): f_a = -p int N_a m
   !> (y_,xi, -x_,xi) dxi with m = t or 2 pi r; follower tangent
   !> d f_a / d u_b = -p int N_a (m dN_b/dxi [[0, 1], [-1, 0]] + (y_,xi, -x_,xi) dm/du_b) dxi,
   !> dm/du_b = (2 pi N_b, 0) axisymmetric, 0 plane strain.
   pure subroutine plane_solid_face_pressure(self, face, coords, u, pressure, follower, force, tangent)
      class(plane_solid_t), intent(in) :: self
      class(reference_cell_t), intent(in) :: face   !! the edge's cell (LINE2)
      real(dp), intent(in) :: coords(:, :)    !! (3, edge nodes) reference coordinates
      real(dp), intent(in) :: u(:, :)         !! (3, edge nodes) total displacements
      real(dp), intent(in) :: pressure        !! p (stress unit), > 0 pushes into the body
      logical, intent(in) :: follower         !! .true.: current geometry
      real(dp), intent(out) :: force(:)       !! (3 edge nodes) fext, node-major, z entries 0
      real(dp), intent(out), optional :: tangent(:, :)  !! (3 edge nodes, same) d fext / d u
      real(dp) :: x(2, face%n_nodes), shape(face%n_nodes), derivatives(1, face%n_nodes)
      real(dp) :: normal(2), measure, weighted, block(2, 2)
      integer :: point, a, b, n
      n = face%n_nodes
      force(1:3*n) = 0.0_dp
      if (present(tangent)) tangent(1:3*n, 1:3*n) = 0.0_dp
      x = coords(1:2, 1:n)
      if (follower) x = x + u(1:2, 1:n)
      do point = 1, face%n_points()
         call face%shape_functions(face%points(:, point), shape, derivatives)
         normal = [dot_product(x(2, :), derivatives(1, :)), -dot_product(x(1, :), derivatives(1, :))]
         measure = section_measure(self, dot_product(shape, x(1, :)))
         weighted = pressure*face%weights(point)
         do a = 1, n
            force(3*a - 2:3*a - 1) = force(3*a - 2:3*a - 1) - weighted*shape(a)*measure*normal
         end do
         if (.not. (follower .and. present(tangent))) cycle
         do b = 1, n
            block = measure*derivatives(1, b)*reshape([0.0_dp, -1.0_dp, 1.0_dp, 0.0_dp], [2, 2])
            if (self%axisymmetric) block(:, 1) = block(:, 1) + normal*two_pi*shape(b)
            do a = 1, n
               tangent(3*a - 2:3*a - 1, 3*b - 2:3*b - 1) = tangent(3*a - 2:3*a - 1, 3*b - 2:3*b - 1) &
                                                           - weighted*shape(a)*block
            end do
         end do
      end do
   end subroutine plane_solid_face_pressure

   !> An axisymmetric element resists a uniform radial displacement (direction 1, x = r): it
   !> strains the ring by u_r / r. No element resists a translation along the axis (y).
   pure logical function plane_solid_resists_translation(self, direction)
      class(plane_solid_t), intent(in) :: self
      integer, intent(in) :: direction
      plane_solid_resists_translation = self%axisymmetric .and. direction == 1
   end function plane_solid_resists_translation

   !> Tributary measures of an edge's nodes: integral of N_a m ds over the reference edge with
   !> the section measure m = t (plane strain) or 2 pi r (axisymmetric), on the edge cell's rule
   !> (exact for a straight edge: degree 1 in plane strain, 2 in axisymmetry).
   pure subroutine plane_solid_face_weights(self, face, coords, weights)
      class(plane_solid_t), intent(in) :: self
      class(reference_cell_t), intent(in) :: face   !! the edge's cell (LINE2)
      real(dp), intent(in) :: coords(:, :)    !! (3, edge nodes) reference coordinates
      real(dp), intent(out) :: weights(:)     !! (edge nodes) integral of N_a m ds
      real(dp) :: shape(face%n_nodes), derivatives(1, face%n_nodes), tangent(2)
      integer :: point
      weights(1:face%n_nodes) = 0.0_dp
      do point = 1, face%n_points()
         call face%shape_functions(face%points(:, point), shape, derivatives)
         tangent = matmul(coords(1:2, 1:face%n_nodes), derivatives(1, :))
         weights(1:face%n_nodes) = weights(1:face%n_nodes) + face%weights(point)*shape*norm2(tangent)* &
                                   section_measure(self, dot_product(shape, coords(1, 1:face%n_nodes)))
      end do
   end subroutine plane_solid_face_weights

end module frix_plane_solid
