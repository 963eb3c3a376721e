!> The 8-node hexahedron: trilinear displacement interpolation, 2x2x2 Gauss quadrature,
!> optionally enhanced assumed strains (EAS3, EAS9, EAS21, EAS30, see frix_eas_modes) and
!> either geometrically linear or total Lagrangian kinematics. Theory, mode tables and sources:
!> docs/elements.md.
!>
!> Node order is VTK's (see frix_mesh): node a sits at parent corner (xi_a, eta_a, zeta_a) =
!> `corner(:, a)`. Integration point g sits at corner(:, g) / sqrt(3) with weight 1.
!>
!> Linear kinematics: eps = B u (+ enhanced eps~), sigma = material(eps),
!>   fint = sum_g B^T sigma dV_g, K = sum_g B^T C B dV_g (Zienkiewicz & Taylor, vol. 1, ch. 6).
!> Total Lagrangian: F = I + Grad u, E = (F^T F - I)/2 (+ E~), S = material(E),
!>   fint_a = sum_g (F S) Grad N_a dV0_g, K = material part B_NL^T C B_NL + geometric part
!>   (Grad N_a . S . Grad N_b) I (Bathe, Finite Element Procedures, 6.2; Wriggers, Nonlinear FEM, 4.2).
!> EAS: E~ = (detJ0/detJ(xi)) T0^{-T} M(xi) alpha = G(xi) alpha (Simo & Rifai 1990; for the
!>   Green-Lagrange enhancement Buechter, Ramm & Roehl 1994, Simo & Armero 1992). alpha is
!>   solved locally so that h = sum_g G^T S dV_g = 0; the returned tangent is the statically
!>   condensed K_uu - K_ua K_aa^{-1} K_au, i.e. exactly d fint/du with alpha = alpha(u).
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
   use frix_dense_algebra, only: solve_in_place
   implicit none
   private

   public :: hex8_t, new_hex8
   public :: hex8_corner, hex8_gauss_points, max_local_iterations, local_tolerance

   !> Parent coordinates of the nodes, VTK / Abaqus C3D8 order, (3, 8).
   integer, parameter :: hex8_corner(3, 8) = reshape([ &
                                                     -1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, &
                                                     -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1], [3, 8])
   !> Gauss abscissa 1/sqrt(3) of the 2-point rule (weight 1).
   real(dp), parameter :: gauss_abscissa = 0.57735026918962576450914878050196_dp
   !> Parent coordinates of the 8 integration points (point g beside node g), (3, 8).
   real(dp), parameter :: hex8_gauss_points(3, 8) = hex8_corner*gauss_abscissa

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

   integer, parameter :: max_local_iterations = 20   !! Newton steps on alpha before giving up
   !> A local step after which the material fails (e.g. det C <= 0 under a large plastic
   !> flow) is halved at most this many times (each halving counts as a local iteration).
   integer, parameter :: max_step_halvings = 8
   real(dp), parameter :: local_tolerance = 1.0e-12_dp !! |h| <= tol * sum_g |G|^T |S| dV
   !> Round-off plateau test: |h| stopped decreasing and |h| <= plateau_tolerance *
   !> sum_g |G| stress_floor max|C| dV, i.e. below 1e-12 |C| |G| dV, the round-off of S.
   real(dp), parameter :: stress_floor = 1.0e-2_dp
   real(dp), parameter :: plateau_tolerance = 1.0e-10_dp

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

   !> Internal force and tangent (see the module header for the formulas).
   subroutine hex8_evaluate(self, material, coords, u, alpha, state_old, state_new, &
                            fint, tangent, stress, strain, error)
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

      real(dp) :: dn_dx(3, 8, 8)           ! reference gradients dN_a/dX_j at each point
      real(dp) :: volume(8)                ! detJ * Gauss weight
      real(dp) :: deformation(3, 3, 8)     ! F (identity under linear kinematics)
      real(dp) :: compatible(6, 8), total(6, 8), pk2(6, 8), moduli(6, 6, 8)
      real(dp) :: enhanced(6, max_eas_modes, 8)
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
         if (total_lagrangian) then
            if (determinant(deformation(:, :, g)) <= 0.0_dp) then
               call fatal_error(error, self%name//': non-positive deformation gradient determinant '// &
                                to_string(determinant(deformation(:, :, g)))// &
                                ' at integration point '//to_string(g))
               return
            end if
         end if
      end do

      if (n > 0) then
         call enhanced_operators(self%name, coords, volume, n, enhanced, error)
         if (allocated(error)) return
         call solve_enhanced(self%name, material, total_lagrangian, n, enhanced, volume, compatible, &
                             state_old, state_new, alpha(1:n), total, pk2, moduli, error)
         if (allocated(error)) return
      else
         total = compatible
         call material_pass(self%name, material, total_lagrangian, total, state_old, state_new, pk2, &
                            moduli, error)
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
            call condense(self%name, n, dn_dx, volume, deformation, moduli, enhanced, symmetric, tangent, error)
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

   !> F = I + Grad u (total Lagrangian) or F = I (linear); strain E = (F^T F - I)/2 or
   !> eps = sym(Grad u), Voigt with engineering shears.
   pure subroutine compatible_kinematics(dn_dx, u, total_lagrangian, deformation, strain)
      real(dp), intent(in) :: dn_dx(3, 8)
      real(dp), intent(in) :: u(:, :)
      logical, intent(in) :: total_lagrangian
      real(dp), intent(out) :: deformation(3, 3)
      real(dp), intent(out) :: strain(6)
      real(dp) :: gradient(3, 3), right_cauchy(3, 3)
      integer :: a, i, j
      gradient = 0.0_dp
      do a = 1, 8
         do j = 1, 3
            do i = 1, 3
               gradient(i, j) = gradient(i, j) + u(i, a)*dn_dx(j, a)
            end do
         end do
      end do
      deformation = gradient
      do i = 1, 3
         deformation(i, i) = deformation(i, i) + 1.0_dp
      end do
      if (total_lagrangian) then
         right_cauchy = matmul(transpose(deformation), deformation)
         strain = [0.5_dp*(right_cauchy(1, 1) - 1.0_dp), 0.5_dp*(right_cauchy(2, 2) - 1.0_dp), &
                   0.5_dp*(right_cauchy(3, 3) - 1.0_dp), right_cauchy(1, 2), right_cauchy(1, 3), &
                   right_cauchy(2, 3)]
      else
         deformation = 0.0_dp
         do i = 1, 3
            deformation(i, i) = 1.0_dp
         end do
         strain = [gradient(1, 1), gradient(2, 2), gradient(3, 3), gradient(1, 2) + gradient(2, 1), &
                   gradient(1, 3) + gradient(3, 1), gradient(2, 3) + gradient(3, 2)]
      end if
   end subroutine compatible_kinematics

   !> G_g = (detJ0 / detJ_g) T0^{-T} M(xi_g), (6, n, 8), T0^{-T} from J0 = J(xi = 0).
   subroutine enhanced_operators(name, coords, volume, n, enhanced, error)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: coords(:, :)
      real(dp), intent(in) :: volume(8)
      integer, intent(in) :: n
      real(dp), intent(out) :: enhanced(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: jacobian0(3, 3), inverse0(3, 3), det0, push(6, 6), modes(6, max_eas_modes)
      integer :: g
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
         enhanced(:, 1:n, g) = (det0/volume(g))*matmul(push, modes(:, 1:n))
      end do
   end subroutine enhanced_operators

   !> Stress and tangent at all points for the given total strains.
   subroutine material_pass(name, material, finite, total, state_old, state_new, pk2, moduli, error)
      character(len=*), intent(in) :: name
      class(material_t), intent(in) :: material
      logical, intent(in) :: finite   !! total Lagrangian: total = E, pk2 = S
      real(dp), intent(in) :: total(6, 8)
      real(dp), intent(in) :: state_old(:, :)
      real(dp), intent(inout) :: state_new(:, :)
      real(dp), intent(out) :: pk2(6, 8), moduli(6, 6, 8)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: material_error
      integer :: g
      do g = 1, 8
         call material%response(total(:, g), finite, state_old(:, g), state_new(:, g), pk2(:, g), &
                                moduli(:, :, g), material_error)
         if (allocated(material_error)) then
            call fatal_error(error, name//', integration point '//to_string(g)//': '// &
                             material_error%message)
            return
         end if
      end do
   end subroutine material_pass

   !> Local Newton on alpha: h(alpha) = sum_g G_g^T S_g dV_g = 0, starting from the alpha
   !> passed in, with K_aa = sum_g G^T C G dV. Stops when max|h| <= local_tolerance *
   !> max_k sum_g |G_g|^T |S_g| dV_g, or when |h| stops decreasing at round-off level (see
   !> plateau_tolerance); a step after which the material fails is halved (max_step_halvings);
   !> fails after max_local_iterations steps. On return stresses, tangents and history belong to the converged alpha.
   subroutine solve_enhanced(name, material, finite, n, enhanced, volume, compatible, state_old, &
                             state_new, alpha, total, pk2, moduli, error)
      character(len=*), intent(in) :: name
      class(material_t), intent(in) :: material
      logical, intent(in) :: finite   !! total Lagrangian: total = E, pk2 = S
      integer, intent(in) :: n
      real(dp), intent(in) :: enhanced(:, :, :)
      real(dp), intent(in) :: volume(8), compatible(6, 8)
      real(dp), intent(in) :: state_old(:, :)
      real(dp), intent(inout) :: state_new(:, :)
      real(dp), intent(inout) :: alpha(:)
      real(dp), intent(out) :: total(6, 8), pk2(6, 8), moduli(6, 6, 8)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: residual(max_eas_modes), scale(max_eas_modes), step(max_eas_modes, 1)
      real(dp) :: floor_scale(max_eas_modes), residual_max, previous_max
      real(dp) :: stiffness(max_eas_modes, max_eas_modes), weighted(6, max_eas_modes)
      real(dp) :: accepted(max_eas_modes)
      integer :: iteration, g, halvings
      logical :: singular
      previous_max = huge(1.0_dp)
      halvings = 0
      do iteration = 0, max_local_iterations
         do g = 1, 8
            total(:, g) = compatible(:, g) + matmul(enhanced(:, 1:n, g), alpha(1:n))
         end do
         call material_pass(name, material, finite, total, state_old, state_new, pk2, moduli, error)
         if (allocated(error)) then
            ! a Newton step that left the law's domain (det C <= 0, say): halve it
            if (iteration == 0 .or. halvings == max_step_halvings) return
            deallocate (error)
            halvings = halvings + 1
            alpha(1:n) = 0.5_dp*(accepted(1:n) + alpha(1:n))
            cycle
         end if
         halvings = 0
         residual(1:n) = 0.0_dp
         scale(1:n) = 0.0_dp
         floor_scale(1:n) = 0.0_dp
         do g = 1, 8
            residual(1:n) = residual(1:n) + volume(g)*matmul(pk2(:, g), enhanced(:, 1:n, g))
            scale(1:n) = scale(1:n) + volume(g)*matmul(abs(pk2(:, g)), abs(enhanced(:, 1:n, g)))
            floor_scale(1:n) = floor_scale(1:n) + volume(g)*stress_floor*maxval(abs(moduli(:, :, g)))* &
                               sum(abs(enhanced(:, 1:n, g)), dim=1)
         end do
         residual_max = maxval(abs(residual(1:n)))
         if (residual_max <= local_tolerance*maxval(scale(1:n))) return
         ! Round-off plateau: a stress computed with cancellation (neo-Hookean
         ! S = mu (I - C^-1) + ...) carries errors of order 1e-16 |C| however small it is, which
         ! the relative test cannot beat in a nearly unstressed element: accept a residual that
         ! stopped decreasing at a level negligible against stress_floor |C|.
         if (iteration > 0 .and. residual_max > 0.5_dp*previous_max .and. &
             residual_max <= plateau_tolerance*maxval(floor_scale(1:n))) return
         previous_max = residual_max
         if (iteration == max_local_iterations) exit
         stiffness(1:n, 1:n) = 0.0_dp
         do g = 1, 8
            weighted(:, 1:n) = volume(g)*matmul(moduli(:, :, g), enhanced(:, 1:n, g))
            stiffness(1:n, 1:n) = stiffness(1:n, 1:n) + matmul(transpose(enhanced(:, 1:n, g)), weighted(:, 1:n))
         end do
         step(1:n, 1) = residual(1:n)
         call solve_in_place(stiffness(1:n, 1:n), step(1:n, :), singular)
         if (singular) then
            call fatal_error(error, name//': singular enhanced-strain stiffness K_aa')
            return
         end if
         accepted(1:n) = alpha(1:n)
         alpha(1:n) = alpha(1:n) - step(1:n, 1)
      end do
      call fatal_error(error, name//': local EAS iteration not converged after '// &
                       to_string(max_local_iterations)//' steps (|h| = '// &
                       to_string(maxval(abs(residual(1:n))))//')')
   end subroutine solve_enhanced

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

   !> Nodal blocks of dE/du (Voigt, engineering shears): column i of node a holds
   !> dE_jk/du_ai = (F_ij N_a,k + F_ik N_a,j)/2, doubled in the shear rows. F = I gives the
   !> linear B.
   pure subroutine nonlinear_b(deformation, dn_dx, b_nl)
      real(dp), intent(in) :: deformation(3, 3), dn_dx(3, 8)
      real(dp), intent(out) :: b_nl(6, 3, 8)
      integer :: a, i
      do a = 1, 8
         do i = 1, 3
            b_nl(1, i, a) = deformation(i, 1)*dn_dx(1, a)
            b_nl(2, i, a) = deformation(i, 2)*dn_dx(2, a)
            b_nl(3, i, a) = deformation(i, 3)*dn_dx(3, a)
            b_nl(4, i, a) = deformation(i, 1)*dn_dx(2, a) + deformation(i, 2)*dn_dx(1, a)
            b_nl(5, i, a) = deformation(i, 1)*dn_dx(3, a) + deformation(i, 3)*dn_dx(1, a)
            b_nl(6, i, a) = deformation(i, 2)*dn_dx(3, a) + deformation(i, 3)*dn_dx(2, a)
         end do
      end do
   end subroutine nonlinear_b

   !> Static condensation K <- K - K_ua K_aa^{-1} K_au with K_ua = sum_g B^T C G dV,
   !> K_au = sum_g G^T C B dV and K_aa = sum_g G^T C G dV at the converged alpha (for a
   !> symmetric C, K_au = K_ua^T).
   subroutine condense(name, n, dn_dx, volume, deformation, moduli, enhanced, symmetric, tangent, error)
      character(len=*), intent(in) :: name
      integer, intent(in) :: n
      real(dp), intent(in) :: dn_dx(3, 8, 8), volume(8), deformation(3, 3, 8), moduli(6, 6, 8)
      real(dp), intent(in) :: enhanced(:, :, :)
      logical, intent(in) :: symmetric
      real(dp), intent(inout) :: tangent(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: coupling(24, max_eas_modes), solved(max_eas_modes, 24)
      real(dp) :: stiffness(max_eas_modes, max_eas_modes), weighted(6, max_eas_modes), b_nl(6, 3, 8)
      integer :: g, a
      logical :: singular
      coupling(:, 1:n) = 0.0_dp
      solved(1:n, :) = 0.0_dp   ! K_au, accumulated for an unsymmetric C
      stiffness(1:n, 1:n) = 0.0_dp
      do g = 1, 8
         call nonlinear_b(deformation(:, :, g), dn_dx(:, :, g), b_nl)
         weighted(:, 1:n) = volume(g)*matmul(moduli(:, :, g), enhanced(:, 1:n, g))
         stiffness(1:n, 1:n) = stiffness(1:n, 1:n) + matmul(transpose(enhanced(:, 1:n, g)), weighted(:, 1:n))
         do a = 1, 8
            coupling(3*a - 2:3*a, 1:n) = coupling(3*a - 2:3*a, 1:n) + &
                                         matmul(transpose(b_nl(:, :, a)), weighted(:, 1:n))
            if (.not. symmetric) solved(1:n, 3*a - 2:3*a) = solved(1:n, 3*a - 2:3*a) + &
                                 volume(g)*matmul(transpose(enhanced(:, 1:n, g)), &
                                                  matmul(moduli(:, :, g), b_nl(:, :, a)))
         end do
      end do
      if (symmetric) solved(1:n, :) = transpose(coupling(:, 1:n))
      call solve_in_place(stiffness(1:n, 1:n), solved(1:n, :), singular)
      if (singular) then
         call fatal_error(error, name//': singular enhanced-strain stiffness K_aa')
         return
      end if
      tangent(1:24, 1:24) = tangent(1:24, 1:24) - matmul(coupling(:, 1:n), solved(1:n, :))
   end subroutine condense

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

   !> sigma = F S F^T / det F (Voigt, tensor shears).
   pure function cauchy_from_pk2(deformation, pk2) result(cauchy)
      real(dp), intent(in) :: deformation(3, 3), pk2(6)
      real(dp) :: cauchy(6)
      real(dp) :: sigma(3, 3), deformed_pk2(3, 3)
      deformed_pk2 = matmul(deformation, tensor_from_voigt(pk2))
      sigma = matmul(deformed_pk2, transpose(deformation))/determinant(deformation)
      cauchy = [sigma(1, 1), sigma(2, 2), sigma(3, 3), sigma(1, 2), sigma(1, 3), sigma(2, 3)]
   end function cauchy_from_pk2

   !> Symmetric 3x3 tensor from a stress-like Voigt vector (tensor shears).
   pure function tensor_from_voigt(voigt) result(tensor)
      real(dp), intent(in) :: voigt(6)
      real(dp) :: tensor(3, 3)
      tensor = reshape([voigt(1), voigt(4), voigt(5), voigt(4), voigt(2), voigt(6), &
                        voigt(5), voigt(6), voigt(3)], [3, 3])
   end function tensor_from_voigt

end module frix_hex8
