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
!>   solved locally so that h = sum_g G^T S dV_g = 0 (Newton with a line search, K_aa solved
!>   after diagonal scaling, each mode's residual against its own scale: solve_enhanced);
!>   the returned tangent is the statically
!>   condensed K_uu - K_ua K_aa^{-1} K_au, i.e. exactly d fint/du with alpha = alpha(u).
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
   use frix_dense_algebra, only: solve_in_place
   use frix_hex8_cell, only: hex8_corner, hex8_gauss_points
   use frix_solid_kinematics, only: compatible_kinematics, material_pass, nonlinear_b, cauchy_from_pk2, &
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

   !> Newton steps on alpha before giving up. Under total Lagrangian kinematics with little
   !> hardening a local solve far from equilibrium can take some 20-40 line-searched steps
   !> before it converges quadratically (a thin element of a global Newton iterate).
   integer, parameter :: max_local_iterations = 50
   !> Material passes of the line search along one Newton step (enhanced_line_search).
   integer, parameter :: max_line_search_trials = 8
   !> The line search ends where |d . h| <= line_search_ratio |d . h(alpha)| along the step d.
   real(dp), parameter :: line_search_ratio = 0.25_dp
   !> The regula falsi's trial stays this fraction of the bracket away from its ends.
   real(dp), parameter :: bracket_guard = 0.1_dp
   !> Longest step along d (in Newton steps) that the line search tries.
   real(dp), parameter :: max_step_length = 8.0_dp
   !> Converged: every |h_k| <= local_tolerance sum_g |G_gk| max|S_g| dV, each mode against the
   !> size of its own terms (a test against the largest mode's terms would leave the modes along
   !> the length of a thin element, whose G is (thickness / length)^2 smaller, unconverged).
   real(dp), parameter :: local_tolerance = 1.0e-12_dp
   !> Round-off plateau test: |h| stopped decreasing and |h_k| <= plateau_tolerance *
   !> sum_g |G_gk| stress_floor max|C| dV, i.e. below 1e-12 |C| |G| dV, the round-off of S.
   real(dp), parameter :: stress_floor = 1.0e-2_dp
   real(dp), parameter :: plateau_tolerance = 1.0e-10_dp
   !> Where K_aa is singular: the weight w of the elastic K_aa^el added to it (K_aa + w K_aa^el,
   !> positive definite; solve_enhanced_system) in the local steps and in the condensation of an
   !> unsymmetric tangent (local_regularisation), and in the condensation of a symmetric one
   !> (condensation_regularisation: the null space of K_aa lies in that of K_ua there, and a w
   !> small against 1 leaves the condensed tangent exact to about w; docs/elements.md).
   real(dp), parameter :: local_regularisation = 1.0_dp
   real(dp), parameter :: condensation_regularisation = 1.0e-8_dp

   !> Voigt rows (11 22 33 12 13 23) and derivative directions of the three nonzero entries
   !> of column i of the linear nodal strain-displacement block B_a (6 x 3).
   integer, parameter :: b_row(3, 3) = reshape([1, 4, 5, 2, 4, 6, 3, 5, 6], [3, 3])
   integer, parameter :: b_derivative(3, 3) = reshape([1, 2, 3, 2, 1, 3, 3, 1, 2], [3, 3])

   !> The fixed data of an element's local EAS problem h(alpha) = 0.
   type :: local_problem_t
      integer :: n = 0                  !! number of enhanced parameters
      logical :: finite = .false.       !! total Lagrangian: strains E, stresses S
      real(dp) :: enhanced(6, max_eas_modes, 8) = 0.0_dp   !! G at each point
      real(dp) :: volume(8) = 0.0_dp                       !! dV at each point
      real(dp) :: compatible(6, 8) = 0.0_dp                !! compatible strains
      logical :: prestressed = .false.                     !! the points start from `initial`
      real(dp) :: initial(6, 8) = 0.0_dp                   !! sigma0 (S0) at each point
      real(dp) :: elastic(6, 6) = 0.0_dp   !! the law's elastic moduli D (regularises a singular K_aa)
   end type local_problem_t

   !> The local problem evaluated at one alpha.
   type :: local_point_t
      real(dp) :: total(6, 8), pk2(6, 8), moduli(6, 6, 8)   !! strains, stresses, tangents
      real(dp) :: residual(max_eas_modes)      !! h = sum_g G^T S dV
      real(dp) :: scale(max_eas_modes)         !! sum_g |G_g| max|S_g| dV, the size of h's terms
      real(dp) :: floor_scale(max_eas_modes)   !! sum_g |G| stress_floor max|C| dV
   end type local_point_t

   !> The state of one line search along a local Newton step (enhanced_line_search).
   type :: line_search_t
      real(dp) :: slope0 = 0.0_dp, norm0 = 0.0_dp   !! phi(0) = d . h and |h| at the step's start
      logical :: energy = .true.   !! phi(0) < 0: regula falsi on phi, else halving on |h|
      real(dp) :: low = 0.0_dp, slope_low = 0.0_dp     !! bracket: phi(low) < 0 ...
      real(dp) :: high = 0.0_dp, slope_high = 0.0_dp   !! ... phi(high) > 0 (huge: failed; high <= low: none yet)
      integer :: side = 0        !! which end moved last (-1 low, 1 high), for the Illinois rule
      real(dp) :: s = 1.0_dp     !! the trial step
      real(dp) :: kept_s = 0.0_dp   !! the last admissible trial (0: none yet)
      real(dp) :: max_s = max_step_length   !! the longest step tried
   contains
      procedure :: start => line_search_start
      procedure :: accepts => line_search_accepts
   end type line_search_t

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
      type(local_point_t) :: point
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
         problem%n = n
         problem%finite = total_lagrangian
         problem%volume = volume
         problem%compatible = compatible
         if (present(initial_stress)) then
            problem%prestressed = .true.
            problem%initial = initial_stress(:, 1:8)
         end if
         call enhanced_operators(self%name, coords, volume, n, problem%enhanced, error)
         if (allocated(error)) return
         call material%elastic_tangent(problem%elastic)
         call solve_enhanced(self%name, material, problem, state_old, state_new, alpha(1:n), point, error)
         if (allocated(error)) return
         total = point%total
         pk2 = point%pk2
         moduli = point%moduli
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
            call condense(self%name, problem, dn_dx, deformation, moduli, symmetric, tangent, error)
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

   !> Local Newton on alpha: h(alpha) = sum_g G_g^T S_g dV_g = 0, starting from the alpha
   !> passed in, with K_aa = sum_g G^T C G dV and a line search along each Newton step
   !> (enhanced_line_search). Converged when every |h_k| <= local_tolerance sum_g |G_gk|
   !> max|S_g| dV_g, or when |h| stops decreasing at round-off level (see plateau_tolerance); fails after
   !> max_local_iterations steps. On return stresses, tangents and history belong to the
   !> converged alpha.
   subroutine solve_enhanced(name, material, problem, state_old, state_new, alpha, point, error)
      character(len=*), intent(in) :: name
      class(material_t), intent(in) :: material
      type(local_problem_t), intent(in) :: problem
      real(dp), intent(in) :: state_old(:, :)
      real(dp), intent(inout) :: state_new(:, :)
      real(dp), intent(inout) :: alpha(:)
      type(local_point_t), intent(out) :: point
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: direction(max_eas_modes, 1), previous_max
      integer :: iteration, n
      logical :: singular, regularised
      n = problem%n
      call evaluate_local(name, material, problem, alpha(1:n), state_old, state_new, point, error)
      if (allocated(error)) return
      previous_max = huge(1.0_dp)
      do iteration = 1, max_local_iterations
         if (local_converged(point, n, previous_max)) return
         previous_max = maxval(abs(point%residual(1:n)))
         direction(1:n, 1) = -point%residual(1:n)
         call solve_enhanced_system(problem, point%moduli, local_regularisation, direction(1:n, :), singular, &
                                    regularised)
         if (singular) then
            call fatal_error(error, name//': singular enhanced-strain stiffness K_aa')
            return
         end if
         call enhanced_line_search(name, material, problem, direction(1:n, 1), merge(1.0_dp, max_step_length, &
                                   regularised), state_old, state_new, alpha(1:n), point, error)
         if (allocated(error)) return
      end do
      if (local_converged(point, n, previous_max)) return
      call fatal_error(error, name//': local EAS iteration not converged after '// &
                       to_string(max_local_iterations)//' steps (|h| = '// &
                       to_string(maxval(abs(point%residual(1:n))))//')')
   end subroutine solve_enhanced

   !> Every |h_k| <= local_tolerance scale_k (a mode without stress, scale_k = 0, must have
   !> h_k = 0), or the round-off plateau: a stress computed with cancellation (neo-Hookean
   !> S = mu (I - C^-1) + ...) carries errors of order 1e-16 |C| however small it is, which
   !> the relative test cannot beat in a nearly unstressed element: a residual that stopped
   !> decreasing (above half the last one) at a level negligible against stress_floor |C| is
   !> accepted.
   pure logical function local_converged(point, n, previous_max) result(converged)
      type(local_point_t), intent(in) :: point
      integer, intent(in) :: n
      real(dp), intent(in) :: previous_max   !! max|h| of the last step (huge before the first)
      real(dp) :: residual_max
      converged = all(abs(point%residual(1:n)) <= local_tolerance*point%scale(1:n))
      if (converged) return
      residual_max = maxval(abs(point%residual(1:n)))
      converged = residual_max > 0.5_dp*previous_max .and. &
                  all(abs(point%residual(1:n)) <= plateau_tolerance*point%floor_scale(1:n))
   end function local_converged

   !> Strains, material response, h and its scales at alpha (all 8 points).
   subroutine evaluate_local(name, material, problem, alpha, state_old, state_new, point, error)
      character(len=*), intent(in) :: name
      class(material_t), intent(in) :: material
      type(local_problem_t), intent(in) :: problem
      real(dp), intent(in) :: alpha(:)
      real(dp), intent(in) :: state_old(:, :)
      real(dp), intent(inout) :: state_new(:, :)
      type(local_point_t), intent(out) :: point
      type(error_t), allocatable, intent(out) :: error
      integer :: g, n
      n = problem%n
      do g = 1, 8
         point%total(:, g) = problem%compatible(:, g) + matmul(problem%enhanced(:, 1:n, g), alpha(1:n))
      end do
      if (problem%prestressed) then
         call material_pass(name, material, problem%finite, point%total, state_old, state_new, point%pk2, &
                            point%moduli, error, problem%initial)
      else
         call material_pass(name, material, problem%finite, point%total, state_old, state_new, point%pk2, &
                            point%moduli, error)
      end if
      if (allocated(error)) return
      point%residual(1:n) = 0.0_dp
      point%scale(1:n) = 0.0_dp
      point%floor_scale(1:n) = 0.0_dp
      do g = 1, 8
         point%residual(1:n) = point%residual(1:n) + &
                               problem%volume(g)*matmul(enhanced_stress(problem, point, g), problem%enhanced(:, 1:n, g))
         point%scale(1:n) = point%scale(1:n) + problem%volume(g)*maxval(abs(point%pk2(:, g)))* &
                            sum(abs(problem%enhanced(:, 1:n, g)), dim=1)
         point%floor_scale(1:n) = point%floor_scale(1:n) + problem%volume(g)*stress_floor* &
                                  maxval(abs(point%moduli(:, :, g)))*sum(abs(problem%enhanced(:, 1:n, g)), dim=1)
      end do
   end subroutine evaluate_local

   !> The stress the enhanced equations h = sum_g G^T S dV = 0 weigh at point g: S, or S - S0
   !> from an initial stress S0 (module header: the initial stress is an assumed stress field of
   !> the Hu-Washizu functional, which drives no enhanced strain).
   pure function enhanced_stress(problem, point, g) result(stress)
      type(local_problem_t), intent(in) :: problem
      type(local_point_t), intent(in) :: point
      integer, intent(in) :: g
      real(dp) :: stress(6)
      if (problem%prestressed) then
         stress = point%pk2(:, g) - problem%initial(:, g)
      else
         stress = point%pk2(:, g)
      end if
   end function enhanced_stress

   !> alpha <- alpha + s d along the Newton direction d = -K_aa^{-1} h. With the slope
   !> phi(s) = d . h(alpha + s d), phi(0) = -d . K_aa d, which is negative where K_aa is
   !> positive definite: the full step s = 1 is taken when |phi(1)| <= line_search_ratio
   !> |phi(0)|, as in a converging Newton iteration; otherwise s is sought where |phi(s)| <=
   !> line_search_ratio |phi(0)| by the Illinois variant of regula falsi (next_energy_trial;
   !> s doubles up to max_step_length while phi stays negative): the line search of Crisfield,
   !> Non-linear FE analysis of solids and structures, vol. 1, 9.3, on the local equations. For
   !> an associated law h is the gradient of the element's incremental energy in alpha and the
   !> root of phi its minimum along d, so the iteration cannot cycle between two alphas as the
   !> bare Newton steps can where points switch between elastic and plastic response. Where
   !> phi(0) >= 0 (K_aa indefinite: a finite-strain law with little hardening far from
   !> equilibrium) the step is halved instead until |h(s)| <= (1 - s/2) |h(0)| (Armijo's rule
   !> on |h|, for which the Newton step is a descent direction whatever K_aa; Dennis & Schnabel,
   !> Numerical Methods for Unconstrained Optimization and Nonlinear Equations, 6.3). A trial
   !> after which the material fails (det C <= 0 under a large plastic flow, say) counts as an
   !> overshoot. After max_line_search_trials the last admissible trial is kept. A step from a
   !> regularised K_aa (solve_enhanced_system) is no Newton step and is not extended: max_s = 1.
   subroutine enhanced_line_search(name, material, problem, direction, max_s, state_old, state_new, alpha, &
                                   point, error)
      character(len=*), intent(in) :: name
      class(material_t), intent(in) :: material
      type(local_problem_t), intent(in) :: problem
      real(dp), intent(in) :: direction(:)
      real(dp), intent(in) :: max_s   !! the longest step tried
      real(dp), intent(in) :: state_old(:, :)
      real(dp), intent(inout) :: state_new(:, :)
      real(dp), intent(inout) :: alpha(:)
      type(local_point_t), intent(inout) :: point   !! at alpha on entry, at the new alpha on return
      type(error_t), allocatable, intent(out) :: error
      type(local_point_t) :: trial
      type(line_search_t) :: search
      real(dp) :: slope, norm
      integer :: k, n
      logical :: failed
      n = problem%n
      call search%start(dot_product(direction, point%residual(1:n)), norm2(point%residual(1:n)), max_s)
      do k = 1, max_line_search_trials
         call try_step(name, material, problem, alpha(1:n) + search%s*direction, state_old, state_new, &
                       trial, failed)
         slope = 0.0_dp
         norm = 0.0_dp
         if (.not. failed) then
            point = trial
            slope = dot_product(direction, trial%residual(1:n))
            norm = norm2(trial%residual(1:n))
         end if
         if (search%accepts(failed, slope, norm, k == max_line_search_trials)) exit
      end do
      if (search%kept_s /= search%s .or. failed) then
         ! state_new must belong to the kept alpha, not to the last trial
         if (.not. (search%kept_s > 0.0_dp)) search%kept_s = search%s
         call evaluate_local(name, material, problem, alpha(1:n) + search%kept_s*direction, state_old, &
                             state_new, point, error)
         if (allocated(error)) return
      end if
      alpha(1:n) = alpha(1:n) + search%kept_s*direction
   end subroutine enhanced_line_search

   !> evaluate_local at alpha that reports the material's failure as `failed`.
   subroutine try_step(name, material, problem, alpha, state_old, state_new, trial, failed)
      character(len=*), intent(in) :: name
      class(material_t), intent(in) :: material
      type(local_problem_t), intent(in) :: problem
      real(dp), intent(in) :: alpha(:)
      real(dp), intent(in) :: state_old(:, :)
      real(dp), intent(inout) :: state_new(:, :)
      type(local_point_t), intent(out) :: trial
      logical, intent(out) :: failed
      type(error_t), allocatable :: trial_error
      call evaluate_local(name, material, problem, alpha, state_old, state_new, trial, trial_error)
      failed = allocated(trial_error)
   end subroutine try_step

   !> Start a line search (see enhanced_line_search): first trial s = 1.
   pure subroutine line_search_start(self, slope0, norm0, max_s)
      class(line_search_t), intent(inout) :: self
      real(dp), intent(in) :: slope0   !! phi(0) = d . h(alpha)
      real(dp), intent(in) :: norm0    !! |h(alpha)|
      real(dp), intent(in) :: max_s    !! the longest step tried
      self%slope0 = slope0
      self%norm0 = norm0
      self%energy = slope0 < 0.0_dp
      self%low = 0.0_dp
      self%slope_low = slope0
      self%high = 0.0_dp   ! none yet
      self%slope_high = huge(1.0_dp)
      self%side = 0
      self%s = 1.0_dp
      self%kept_s = 0.0_dp
      self%max_s = max_s
   end subroutine line_search_start

   !> Judge the trial at s: true when it ends the search (then kept_s = s), else the next s.
   !> `failed`: the material failed at s; `slope` = phi(s), `norm` = |h(s)|; `last`: no trial
   !> follows (the last admissible one is kept).
   logical function line_search_accepts(self, failed, slope, norm, last) result(done)
      class(line_search_t), intent(inout) :: self
      logical, intent(in) :: failed, last
      real(dp), intent(in) :: slope, norm
      if (.not. failed) self%kept_s = self%s
      if (self%energy) then
         done = .not. failed .and. (abs(slope) <= line_search_ratio*abs(self%slope0) .or. &
                                    (slope < 0.0_dp .and. self%s >= self%max_s))
      else
         done = .not. failed .and. norm <= (1.0_dp - 0.5_dp*self%s)*self%norm0
      end if
      if (done .or. (last .and. self%kept_s > 0.0_dp)) then
         done = .true.
      else if (self%energy) then
         call next_energy_trial(self, failed, slope)
      else
         self%s = 0.5_dp*self%s
      end if
   end function line_search_accepts

   !> The next s of the regula falsi on phi: the bracket [low, high] narrowed by the trial at
   !> s (phi(s) > 0 or a failed material: s is the new high; else the new low), the Illinois
   !> rule halving the slope of an end kept twice, the new s kept bracket_guard of the width
   !> away from both ends (after a failed material the low end + bracket_guard width: where
   !> phi rises by orders of magnitude within the bracket the trials shrink it tenfold each);
   !> without a high end yet the step doubles.
   pure subroutine next_energy_trial(self, failed, slope)
      class(line_search_t), intent(inout) :: self
      logical, intent(in) :: failed
      real(dp), intent(in) :: slope
      real(dp) :: next, width
      if (failed .or. slope > 0.0_dp) then
         if (self%side == 1 .and. .not. failed) self%slope_low = 0.5_dp*self%slope_low
         self%high = self%s
         self%slope_high = merge(huge(1.0_dp), slope, failed)
         self%side = 1
      else
         if (self%side == -1 .and. self%slope_high < huge(1.0_dp)) self%slope_high = 0.5_dp*self%slope_high
         self%low = self%s
         self%slope_low = slope
         self%side = -1
      end if
      if (.not. (self%high > self%low)) then
         self%s = min(2.0_dp*self%s, self%max_s)
         return
      end if
      width = self%high - self%low
      next = self%low + bracket_guard*width
      if (self%slope_high < huge(1.0_dp)) next = self%low - self%slope_low*width/(self%slope_high - self%slope_low)
      self%s = min(max(next, self%low + bracket_guard*width), self%high - bracket_guard*width)
   end subroutine next_energy_trial


   !> K_aa = sum_g G^T C G dV.
   pure subroutine enhanced_stiffness(problem, moduli, stiffness)
      type(local_problem_t), intent(in) :: problem
      real(dp), intent(in) :: moduli(6, 6, 8)
      real(dp), intent(out) :: stiffness(:, :)
      real(dp) :: weighted(6, max_eas_modes)
      integer :: g, n
      n = problem%n
      stiffness(1:n, 1:n) = 0.0_dp
      do g = 1, 8
         weighted(:, 1:n) = problem%volume(g)*matmul(moduli(:, :, g), problem%enhanced(:, 1:n, g))
         stiffness(1:n, 1:n) = stiffness(1:n, 1:n) + matmul(transpose(problem%enhanced(:, 1:n, g)), &
                                                           weighted(:, 1:n))
      end do
   end subroutine enhanced_stiffness

   !> Solve K_aa X = B (B <- X), K_aa = sum_g G^T C G dV from the points' moduli C
   !> (solve_scaled). Where K_aa is singular (solve_scaled's pivot test) the system is solved
   !> with K_aa + weight K_aa^el, K_aa^el = sum_g G^T D G dV from the law's elastic moduli D.
   pure subroutine solve_enhanced_system(problem, moduli, weight, rhs, singular, regularised)
      type(local_problem_t), intent(in) :: problem
      real(dp), intent(in) :: moduli(6, 6, 8)
      real(dp), intent(in) :: weight
      real(dp), intent(inout) :: rhs(:, :)
      logical, intent(out) :: singular
      logical, intent(out), optional :: regularised   !! K_aa + weight K_aa^el was solved
      real(dp) :: stiffness(problem%n, problem%n), matrix(problem%n, problem%n), elastic(problem%n, problem%n)
      real(dp) :: solved(size(rhs, 1), size(rhs, 2))
      call enhanced_stiffness(problem, moduli, stiffness)
      matrix = stiffness
      solved = rhs
      call solve_scaled(matrix, solved, singular)
      if (present(regularised)) regularised = singular
      if (.not. singular) then
         rhs = solved
         return
      end if
      call enhanced_stiffness(problem, spread(problem%elastic, 3, 8), elastic)
      matrix = stiffness + weight*elastic
      call solve_scaled(matrix, rhs, singular)
   end subroutine solve_enhanced_system

   !> Solve K_aa X = B (B <- X) with K_aa scaled symmetrically by D = diag(|K_aa|)^{-1/2}:
   !> (D K_aa D) (D^{-1} X) = D B. The enhanced modes of a thin, long element differ in size by
   !> (thickness / length)^2 in G and by its square in K_aa (1e-9 at an aspect ratio of 150),
   !> which the scaling removes before the pivoting and the singularity test of solve_in_place
   !> see them (Jacobi equilibration: Golub & Van Loan, Matrix Computations, 3.5.2).
   pure subroutine solve_scaled(stiffness, rhs, singular)
      real(dp), intent(inout) :: stiffness(:, :)   !! K_aa, destroyed
      real(dp), intent(inout) :: rhs(:, :)
      logical, intent(out) :: singular
      real(dp) :: factor(size(stiffness, 1))
      integer :: i
      singular = .true.
      do i = 1, size(stiffness, 1)
         if (.not. (abs(stiffness(i, i)) > 0.0_dp)) return
         factor(i) = 1.0_dp/sqrt(abs(stiffness(i, i)))
      end do
      do i = 1, size(stiffness, 1)
         stiffness(:, i) = factor*stiffness(:, i)*factor(i)
         rhs(i, :) = factor(i)*rhs(i, :)
      end do
      call solve_in_place(stiffness, rhs, singular)
      if (singular) return
      do i = 1, size(stiffness, 1)
         rhs(i, :) = factor(i)*rhs(i, :)
      end do
   end subroutine solve_scaled

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

   !> Static condensation K <- K - K_ua K_aa^{-1} K_au with K_ua = sum_g B^T C G dV,
   !> K_au = sum_g G^T C B dV and K_aa = sum_g G^T C G dV at the converged alpha (for a
   !> symmetric C, K_au = K_ua^T).
   subroutine condense(name, problem, dn_dx, deformation, moduli, symmetric, tangent, error)
      character(len=*), intent(in) :: name
      type(local_problem_t), intent(in) :: problem
      real(dp), intent(in) :: dn_dx(3, 8, 8), deformation(3, 3, 8), moduli(6, 6, 8)
      logical, intent(in) :: symmetric
      real(dp), intent(inout) :: tangent(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: coupling(24, max_eas_modes), solved(max_eas_modes, 24)
      real(dp) :: weighted(6, max_eas_modes), b_nl(6, 3, 8)
      integer :: g, a, n
      logical :: singular
      n = problem%n
      coupling(:, 1:n) = 0.0_dp
      solved(1:n, :) = 0.0_dp   ! K_au, accumulated for an unsymmetric C
      do g = 1, 8
         call nonlinear_b(deformation(:, :, g), dn_dx(:, :, g), b_nl)
         weighted(:, 1:n) = problem%volume(g)*matmul(moduli(:, :, g), problem%enhanced(:, 1:n, g))
         do a = 1, 8
            coupling(3*a - 2:3*a, 1:n) = coupling(3*a - 2:3*a, 1:n) + &
                                         matmul(transpose(b_nl(:, :, a)), weighted(:, 1:n))
            if (.not. symmetric) solved(1:n, 3*a - 2:3*a) = solved(1:n, 3*a - 2:3*a) + &
                                 problem%volume(g)*matmul(transpose(problem%enhanced(:, 1:n, g)), &
                                                          matmul(moduli(:, :, g), b_nl(:, :, a)))
         end do
      end do
      if (symmetric) solved(1:n, :) = transpose(coupling(:, 1:n))
      call solve_enhanced_system(problem, moduli, merge(condensation_regularisation, local_regularisation, symmetric), &
                                 solved(1:n, :), singular)
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

end module frix_hex8
