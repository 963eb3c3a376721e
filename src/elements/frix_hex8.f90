!> The 8-node hexahedron: trilinear displacement interpolation, 2x2x2 Gauss quadrature,
!> optionally enhanced assumed strains (EAS3, EAS9, EAS21, EAS30, see frix_eas_modes) and
!> either geometrically linear or total Lagrangian kinematics. Theory, mode tables and sources:
!> docs/elements.md.
!>
!> Node order, integration points and shape functions are the reference cell's (frix_hex8_cell):
!> node a at parent corner `hex8_corner(:, a)`, integration point g at hex8_corner(:, g) /
!> sqrt(3) with weight 1; the tables below evaluate its shape functions at those points.
!>
!> Linear kinematics: eps = B u (+ enhanced eps~), sigma = material(eps),
!>   fint = sum_g B^T sigma dV_g, K = sum_g B^T C B dV_g (Zienkiewicz & Taylor, vol. 1, ch. 6).
!> Total Lagrangian: F = I + Grad u, E = (F^T F - I)/2 (+ E~), S = material(E),
!>   fint_a = sum_g (F S) Grad N_a dV0_g, K = material part B_NL^T C B_NL + geometric part
!>   (Grad N_a . S . Grad N_b) I (Bathe, Finite Element Procedures, 6.2; Wriggers, Nonlinear FEM, 4.2).
!> EAS: E~ = (detJ0/detJ(xi)) T0^{-T} M(xi) alpha = G(xi) alpha (Simo & Rifai 1990; for the
!>   Green-Lagrange enhancement Buechter, Ramm & Roehl 1994, Simo & Armero 1992). alpha is
!>   solved locally so that h = sum_g G^T S dV_g = 0 and the returned tangent is the statically
!>   condensed K_uu - K_ua K_aa^{-1} K_au, i.e. exactly d fint/du with alpha = alpha(u): the
!>   local Newton, its line search and the condensation are frix_enhanced_strain's.
!> Initial stress S0 (an in-situ stress, element_t): S = material(E) starts from S0 at E = 0
!>   (material_t%initial_stress_response), fint and the geometric stiffness take the whole S.
!>   The enhanced equations weigh S - S0: h = sum_g G^T (S - S0) dV = 0. This is the variation
!>   in alpha of the Hu-Washizu functional whose assumed stress holds the given field S0 besides
!>   the part orthogonal to the enhanced strains (Simo & Rifai 1990 take that part only):
!>   int W(E(u) + E~) - S0 : E~ dV. The initial stress is a given field, not one the element's
!>   strains must reproduce, and a geostatic S0 varying with depth, which h = sum G^T S dV
!>   would turn into enhanced strains (int zeta S_zz(zeta) dzeta /= 0), leaves alpha = 0 at
!>   u = 0 (docs/elements.md, "Initial stress").
!> A material whose tangent is symmetric (material_t%symmetric_tangent) gets the upper block
!>   triangle computed and mirrored, and K_au = K_ua^T; for an unsymmetric one (non-associated
!>   flow) every block and K_au = sum_g G^T C B dV are computed.
module frix_hex8
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_material, only: material_t
   use frix_element, only: element_t, kinematics_linear, kinematics_total_lagrangian
   use frix_eas_modes, only: max_eas_modes, is_valid_eas_count, eas_modes, strain_push_matrix
   use frix_vector_algebra, only: determinant, invert3
   use frix_enhanced_strain, only: local_problem_t, start_local_problem, set_enhanced_operator, enhanced_response, &
                                   condense, max_local_iterations, local_tolerance
   use frix_hex8_cell, only: hex8_corner, hex8_gauss_points
   use frix_solid_kinematics, only: compatible_kinematics, material_pass, nonlinear_b, cauchy_from_pk2, check_deformation, &
                                    tensor_from_voigt
   implicit none
   private

   public :: hex8_t, new_hex8
   public :: max_local_iterations, local_tolerance
   !> The kinematics and stress helpers that the solid elements over any cell share (frix_cell_solid).

   integer :: d_, a_, g_  ! implied-do indices (direction, node, point) of the two constant tables below
   !> Shape function values N_a at point g: prod_i (1 + xi_ia xi_ig)/8, (8 nodes, 8 points).
   real(dp), parameter :: shape_value(8, 8) = reshape( &
                          [((0.125_dp*(1.0_dp + hex8_corner(1, a_)*hex8_gauss_points(1, g_)) &
                             *(1.0_dp + hex8_corner(2, a_)*hex8_gauss_points(2, g_)) &
                             *(1.0_dp + hex8_corner(3, a_)*hex8_gauss_points(3, g_)), a_=1, 8), g_=1, 8)], [8, 8])
   !> Parent derivatives dN_a/dxi_d at point g: xi_da/8 prod_(i /= d) (1 + xi_ia xi_ig), written
   !> as the full product divided by the factor of direction d, (3, 8 nodes, 8 points).
   real(dp), parameter :: parent_derivative(3, 8, 8) = reshape( &
                          [(((0.125_dp*hex8_corner(d_, a_) &
                              *(1.0_dp + hex8_corner(1, a_)*hex8_gauss_points(1, g_)) &
                              *(1.0_dp + hex8_corner(2, a_)*hex8_gauss_points(2, g_)) &
                              *(1.0_dp + hex8_corner(3, a_)*hex8_gauss_points(3, g_)) &
                              /(1.0_dp + hex8_corner(d_, a_)*hex8_gauss_points(d_, g_)), &
                              d_=1, 3), a_=1, 8), g_=1, 8)], [3, 8, 8])
   !> Parent derivatives at the centre xi = 0: xi_ia / 8, (3, 8).
   real(dp), parameter :: centre_derivative(3, 8) = 0.125_dp*hex8_corner

   !> Voigt rows (11 22 33 12 13 23) and derivative directions of the three nonzero entries
   !> of column i of the linear nodal strain-displacement block B_a (6 x 3).
   integer, parameter :: b_row(3, 3) = reshape([1, 4, 5, 2, 4, 6, 3, 5, 6], [3, 3])
   integer, parameter :: b_derivative(3, 3) = reshape([1, 2, 3, 2, 1, 3, 3, 1, 2], [3, 3])

   !> The HEX8 family. Construct with `new_hex8`.
   type, extends(element_t) :: hex8_t
      integer :: n_eas = 0   !! number of enhanced strain parameters: 0, 3, 9, 21 or 30
   contains
      procedure :: n_nodes => hex8_n_nodes
      procedure :: n_points => hex8_n_points
      procedure :: n_enhanced => hex8_n_enhanced
      procedure :: evaluate => hex8_evaluate
      procedure :: volume_weights => hex8_volume_weights
      procedure :: point_positions => hex8_point_positions
   end type hex8_t

contains

   !> HEX8 formulation with `n_eas` enhanced parameters (validated by the element registry;
   !> an unsupported count makes `evaluate` fail) and kinematics kinematics_linear or
   !> kinematics_total_lagrangian. Name 'HEX8' or 'HEX8-EAS<n>'.
   pure function new_hex8(n_eas, kinematics) result(element)
      integer, intent(in) :: n_eas       !! 0, 3, 9, 21 or 30
      integer, intent(in) :: kinematics  !! kinematics_linear or kinematics_total_lagrangian
      type(hex8_t) :: element
      element%n_eas = n_eas
      element%kinematics = kinematics
      if (n_eas == 0) then
         element%name = 'HEX8'
      else
         element%name = 'HEX8-EAS'//to_string(n_eas)
      end if
   end function new_hex8

   pure function hex8_n_nodes(self) result(n)
      class(hex8_t), intent(in) :: self
      integer :: n
      n = 8
   end function hex8_n_nodes

   pure function hex8_n_points(self) result(n)
      class(hex8_t), intent(in) :: self
      integer :: n
      n = 8
   end function hex8_n_points

   pure function hex8_n_enhanced(self) result(n)
      class(hex8_t), intent(in) :: self
      integer :: n
      n = self%n_eas
   end function hex8_n_enhanced

   !> Nodal lumping weights int N_a dV0 = sum_g N_a(xi_g) detJ(xi_g) (2x2x2 Gauss, exact for
   !> the trilinear map). Their sum is the reference volume.
   pure subroutine hex8_volume_weights(self, coords, weights)
      class(hex8_t), intent(in) :: self
      real(dp), intent(in) :: coords(:, :)   !! (3, 8) reference coordinates
      real(dp), intent(out) :: weights(:)    !! (8)
      real(dp) :: jacobian(3, 3)
      integer :: g
      weights(1:8) = 0.0_dp
      do g = 1, 8
         jacobian = matmul(parent_derivative(:, :, g), transpose(coords(:, 1:8)))
         weights(1:8) = weights(1:8) + shape_value(:, g)*determinant(jacobian)
      end do
   end subroutine hex8_volume_weights

   !> X_g = sum_a N_a(xi_g) X_a at the 8 Gauss points.
   pure subroutine hex8_point_positions(self, coords, positions)
      class(hex8_t), intent(in) :: self
      real(dp), intent(in) :: coords(:, :)      !! (3, 8)
      real(dp), intent(out) :: positions(:, :)  !! (3, 8)
      positions(:, 1:8) = matmul(coords(:, 1:8), shape_value)
   end subroutine hex8_point_positions

   !> Internal force and tangent (see the module header for the formulas).
   subroutine hex8_evaluate(self, material, coords, u, alpha, state_old, state_new, &
                            fint, tangent, stress, strain, error, initial_stress)
      class(hex8_t), intent(in) :: self
      class(material_t), intent(in) :: material
      real(dp), intent(in) :: coords(:, :)       !! (3, 8) reference coordinates
      real(dp), intent(in) :: u(:, :)            !! (3, 8) total displacements
      real(dp), intent(inout) :: alpha(:)        !! (n_eas) EAS parameters
      real(dp), intent(in) :: state_old(:, :)    !! (n_state, 8)
      real(dp), intent(inout) :: state_new(:, :) !! (n_state, 8)
      real(dp), intent(out) :: fint(:)           !! (24)
      real(dp), intent(out), optional :: tangent(:, :)  !! (24, 24) d fint / d u
      real(dp), intent(out), optional :: stress(:, :)   !! (6, 8) Cauchy stress
      real(dp), intent(out), optional :: strain(:, :)   !! (6, 8) eps or E incl. enhanced part
      type(error_t), allocatable, intent(out) :: error
      real(dp), intent(in), optional :: initial_stress(:, :)   !! (6, 8) sigma0 (element_t)

      real(dp) :: dn_dx(3, 8, 8)           ! reference gradients dN_a/dX_j at each point
      real(dp) :: volume(8)                ! detJ * Gauss weight
      real(dp) :: deformation(3, 3, 8)     ! F (identity under linear kinematics)
      real(dp) :: compatible(6, 8), total(6, 8), pk2(6, 8), moduli(6, 6, 8)
      type(local_problem_t) :: problem
      real(dp) :: b_blocks(6, 3, 8, 8)
      integer :: n, g, bad_point
      logical :: total_lagrangian, symmetric

      n = self%n_eas
      total_lagrangian = self%kinematics == kinematics_total_lagrangian
      if (.not. is_valid_eas_count(n)) then
         call fatal_error(error, self%name//': unsupported number of EAS parameters '//to_string(n))
         return
      end if
      if (size(alpha) < n) then
         call fatal_error(error, self%name//': alpha has '//to_string(size(alpha))// &
                          ' entries, '//to_string(n)//' needed')
         return
      end if

      call reference_gradients(coords, dn_dx, volume, bad_point)
      if (bad_point > 0) then
         call fatal_error(error, self%name//': non-positive Jacobian determinant '// &
                          to_string(volume(bad_point))//' at integration point '//to_string(bad_point))
         return
      end if

      do g = 1, 8
         call compatible_kinematics(dn_dx(:, :, g), u, total_lagrangian, deformation(:, :, g), &
                                    compatible(:, g))
      end do
      if (total_lagrangian) then
         call check_deformation(self%name, deformation, error)
         if (allocated(error)) return
      end if

      if (n > 0) then
         if (present(initial_stress)) then
            call start_local_problem(problem, n, total_lagrangian, volume, compatible, initial_stress)
         else
            call start_local_problem(problem, n, total_lagrangian, volume, compatible)
         end if
         call enhanced_operators(self%name, coords, volume, problem, error)
         if (allocated(error)) return
         call enhanced_response(self%name, material, problem, state_old, state_new, alpha, total, pk2, moduli, error)
         if (allocated(error)) return
      else
         total = compatible
         if (present(initial_stress)) then
            call material_pass(self%name, material, total_lagrangian, total, state_old, state_new, pk2, &
                               moduli, error, initial_stress(:, 1:8))
         else
            call material_pass(self%name, material, total_lagrangian, total, state_old, state_new, pk2, &
                               moduli, error)
         end if
         if (allocated(error)) return
      end if

      call internal_force(dn_dx, volume, deformation, pk2, fint)
      if (present(tangent)) then
         symmetric = material%symmetric_tangent()
         if (total_lagrangian) then
            call tangent_total_lagrangian(dn_dx, volume, deformation, pk2, moduli, symmetric, tangent)
         else
            call tangent_linear(dn_dx, volume, moduli, symmetric, tangent)
         end if
         if (n > 0) then
            do g = 1, 8
               call nonlinear_b(deformation(:, :, g), dn_dx(:, :, g), b_blocks(:, :, :, g))
            end do
            call condense(self%name, problem, b_blocks, moduli, symmetric, tangent, error)
            if (allocated(error)) return
         end if
      end if

      if (present(stress)) then
         do g = 1, 8
            if (total_lagrangian) then
               stress(:, g) = cauchy_from_pk2(deformation(:, :, g), pk2(:, g))
            else
               stress(:, g) = pk2(:, g)
            end if
         end do
      end if
      if (present(strain)) strain(:, 1:8) = total
   end subroutine hex8_evaluate

   !> dN_a/dX = J^{-1} dN_a/dxi with J_ij = dX_j/dxi_i, and dV = detJ (weight 1) at every
   !> point. `bad_point` is the first point with detJ <= 0 (its detJ left in `volume`), else 0.
   pure subroutine reference_gradients(coords, dn_dx, volume, bad_point)
      real(dp), intent(in) :: coords(:, :)
      real(dp), intent(out) :: dn_dx(3, 8, 8)
      real(dp), intent(out) :: volume(8)
      integer, intent(out) :: bad_point
      real(dp) :: jacobian(3, 3), inverse(3, 3), det
      integer :: g, a
      bad_point = 0
      do g = 1, 8
         jacobian = matmul(parent_derivative(:, :, g), transpose(coords(:, 1:8)))
         call invert3(jacobian, inverse, det)
         volume(g) = det
         if (.not. (det > 0.0_dp)) then
            bad_point = g
            return
         end if
         do a = 1, 8
            dn_dx(:, a, g) = matmul(inverse, parent_derivative(:, a, g))
         end do
      end do
   end subroutine reference_gradients

   !> G_g = (detJ0 / detJ_g) T0^{-T} M(xi_g), (6, n, 8), T0^{-T} from J0 = J(xi = 0).
   subroutine enhanced_operators(name, coords, volume, problem, error)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: coords(:, :)
      real(dp), intent(in) :: volume(8)
      type(local_problem_t), intent(inout) :: problem
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: jacobian0(3, 3), inverse0(3, 3), det0, push(6, 6), modes(6, max_eas_modes)
      integer :: g, n
      n = problem%n
      jacobian0 = matmul(centre_derivative, transpose(coords(:, 1:8)))
      call invert3(jacobian0, inverse0, det0)
      if (.not. (det0 > 0.0_dp)) then
         call fatal_error(error, name//': non-positive Jacobian determinant '//to_string(det0)// &
                          ' at the element centre')
         return
      end if
      call strain_push_matrix(inverse0, push)
      do g = 1, 8
         call eas_modes(n, hex8_gauss_points(:, g), modes(:, 1:n))
         call set_enhanced_operator(problem, g, det0/volume(g), push, modes(:, 1:n))
      end do
   end subroutine enhanced_operators

   !> fint_a = sum_g (F S) Grad N_a dV (F = I under linear kinematics, S = sigma).
   pure subroutine internal_force(dn_dx, volume, deformation, pk2, fint)
      real(dp), intent(in) :: dn_dx(3, 8, 8), volume(8), deformation(3, 3, 8), pk2(6, 8)
      real(dp), intent(out) :: fint(:)
      real(dp) :: first_pk(3, 3)
      integer :: g, a
      fint(1:24) = 0.0_dp
      do g = 1, 8
         first_pk = volume(g)*matmul(deformation(:, :, g), tensor_from_voigt(pk2(:, g)))
         do a = 1, 8
            fint(3*a - 2:3*a) = fint(3*a - 2:3*a) + matmul(first_pk, dn_dx(:, a, g))
         end do
      end do
   end subroutine internal_force

   !> K = sum_g B^T C B dV with the sparse nodal blocks of the linear B (for a symmetric C
   !> only the upper block triangle a <= b is computed, then mirrored).
   pure subroutine tangent_linear(dn_dx, volume, moduli, symmetric, tangent)
      real(dp), intent(in) :: dn_dx(3, 8, 8), volume(8), moduli(6, 6, 8)
      logical, intent(in) :: symmetric
      real(dp), intent(out) :: tangent(:, :)
      real(dp) :: weighted(6, 6), c_b(6, 3, 8), block(3, 3)
      integer :: g, a, b, i, j
      tangent(1:24, 1:24) = 0.0_dp
      do g = 1, 8
         weighted = volume(g)*moduli(:, :, g)
         ! C B_b: column j of B_b has entries dN_b/dX_{b_derivative(m, j)} in rows b_row(m, j)
         do b = 1, 8
            do j = 1, 3
               c_b(:, j, b) = weighted(:, b_row(1, j))*dn_dx(b_derivative(1, j), b, g) &
                              + weighted(:, b_row(2, j))*dn_dx(b_derivative(2, j), b, g) &
                              + weighted(:, b_row(3, j))*dn_dx(b_derivative(3, j), b, g)
            end do
         end do
         do b = 1, 8
            do a = 1, merge(b, 8, symmetric)
               do j = 1, 3
                  do i = 1, 3
                     block(i, j) = dn_dx(b_derivative(1, i), a, g)*c_b(b_row(1, i), j, b) &
                                   + dn_dx(b_derivative(2, i), a, g)*c_b(b_row(2, i), j, b) &
                                   + dn_dx(b_derivative(3, i), a, g)*c_b(b_row(3, i), j, b)
                  end do
               end do
               tangent(3*a - 2:3*a, 3*b - 2:3*b) = tangent(3*a - 2:3*a, 3*b - 2:3*b) + block
            end do
         end do
      end do
      if (symmetric) call mirror_upper_blocks(tangent)
   end subroutine tangent_linear

   !> K = sum_g (B_NL^T C B_NL + (Grad N_a . S . Grad N_b) I) dV0 (for a symmetric C the
   !> upper blocks, then mirrored).
   pure subroutine tangent_total_lagrangian(dn_dx, volume, deformation, pk2, moduli, symmetric, tangent)
      real(dp), intent(in) :: dn_dx(3, 8, 8), volume(8), deformation(3, 3, 8), pk2(6, 8)
      real(dp), intent(in) :: moduli(6, 6, 8)
      logical, intent(in) :: symmetric
      real(dp), intent(out) :: tangent(:, :)
      real(dp) :: b_nl(6, 3, 8), c_b(6, 3), s_tensor(3, 3), geometric
      integer :: g, a, b, i
      tangent(1:24, 1:24) = 0.0_dp
      do g = 1, 8
         call nonlinear_b(deformation(:, :, g), dn_dx(:, :, g), b_nl)
         s_tensor = volume(g)*tensor_from_voigt(pk2(:, g))
         do b = 1, 8
            c_b = volume(g)*matmul(moduli(:, :, g), b_nl(:, :, b))
            do a = 1, merge(b, 8, symmetric)
               geometric = dot_product(dn_dx(:, a, g), matmul(s_tensor, dn_dx(:, b, g)))
               tangent(3*a - 2:3*a, 3*b - 2:3*b) = tangent(3*a - 2:3*a, 3*b - 2:3*b) &
                                                   + matmul(transpose(b_nl(:, :, a)), c_b)
               do i = 1, 3
                  tangent(3*a - 3 + i, 3*b - 3 + i) = tangent(3*a - 3 + i, 3*b - 3 + i) + geometric
               end do
            end do
         end do
      end do
      if (symmetric) call mirror_upper_blocks(tangent)
   end subroutine tangent_total_lagrangian

   !> Copy the upper 3x3 blocks (a < b) to the lower triangle as their transposes.
   pure subroutine mirror_upper_blocks(tangent)
      real(dp), intent(inout) :: tangent(:, :)
      integer :: a, b
      do b = 1, 8
         do a = b + 1, 8
            tangent(3*a - 2:3*a, 3*b - 2:3*b) = transpose(tangent(3*b - 2:3*b, 3*a - 2:3*a))
         end do
      end do
   end subroutine mirror_upper_blocks

end module frix_hex8
