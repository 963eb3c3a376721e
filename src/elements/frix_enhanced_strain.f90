!> The element-level machinery of enhanced assumed strains (EAS), shared by the solid elements
!> with enhanced strains (frix_hex8: HEX8 EAS 3/9/21/30; frix_plane_solid: PLANE4/AXISYM4
!> EAS 4), for any number of integration points, nodes and enhanced parameters. The element
!> supplies its enhanced operators G_g at its points (set_enhanced_operator), its compatible
!> strains, dV and the nodal blocks B_g of dE/du; this module solves for alpha and condenses.
!>
!> Enhanced strain at point g: E~ = G_g alpha, G_g = (dV_centre / dV_g) T0^{-T} M(xi_g)
!>   (Simo & Rifai 1990, IJNME 29; for the Green-Lagrange enhancement Buechter, Ramm & Roehl
!>   1994, Simo & Armero 1992); the strain passed to the material is E(u) + E~.
!> alpha is solved locally so that h = sum_g G^T S dV_g = 0 (Newton with a line search, K_aa
!>   solved after diagonal scaling, each mode's residual against its own scale: solve_enhanced);
!>   the element's tangent is the statically condensed K_uu - K_ua K_aa^{-1} K_au (condense),
!>   i.e. exactly d fint/du with alpha = alpha(u).
!> Initial stress S0 (an in-situ stress, element_t): the enhanced equations weigh S - S0:
!>   h = sum_g G^T (S - S0) dV = 0, the variation in alpha of the Hu-Washizu functional
!>   int W(E(u) + E~) - S0 : E~ dV whose assumed stress holds the given field S0 besides the
!>   part orthogonal to the enhanced strains (docs/elements.md, "Initial stress").
!> Where K_aa is singular the system is solved with K_aa + w K_aa^el (solve_enhanced_system;
!>   docs/elements.md, "Singular K_aa").
module frix_enhanced_strain
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_material, only: material_t
   use frix_dense_algebra, only: solve_in_place
   use frix_solid_kinematics, only: material_pass
   implicit none
   private

   public :: local_problem_t, start_local_problem, set_enhanced_operator, enhanced_response, condense
   public :: max_local_iterations, local_tolerance

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

   !> The fixed data of an element's local EAS problem h(alpha) = 0 (n parameters, p points).
   type :: local_problem_t
      integer :: n = 0                  !! number of enhanced parameters
      logical :: finite = .false.       !! total Lagrangian: strains E, stresses S
      real(dp), allocatable :: enhanced(:, :, :)   !! G at each point, (6, n, p)
      real(dp), allocatable :: volume(:)           !! dV at each point, (p)
      real(dp), allocatable :: compatible(:, :)    !! compatible strains, (6, p)
      logical :: prestressed = .false.             !! the points start from `initial`
      real(dp), allocatable :: initial(:, :)       !! sigma0 (S0) at each point, (6, p)
      real(dp) :: elastic(6, 6) = 0.0_dp   !! the law's elastic moduli D (regularises a singular K_aa)
   end type local_problem_t

   !> The local problem evaluated at one alpha.
   type :: local_point_t
      real(dp), allocatable :: total(:, :), pk2(:, :), moduli(:, :, :)   !! strains, stresses, tangents
      real(dp), allocatable :: residual(:)      !! h = sum_g G^T S dV, (n)
      real(dp), allocatable :: scale(:)         !! sum_g |G_g| max|S_g| dV, the size of h's terms
      real(dp), allocatable :: floor_scale(:)   !! sum_g |G| stress_floor max|C| dV
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

contains

   !> The problem of n parameters over the points of `volume` (dV) and `compatible` (E(u));
   !> G is set per point by set_enhanced_operator; `initial` (6, p): the points' S0, if any.
   subroutine start_local_problem(problem, n, finite, volume, compatible, initial)
      type(local_problem_t), intent(out) :: problem
      integer, intent(in) :: n
      logical, intent(in) :: finite
      real(dp), intent(in) :: volume(:), compatible(:, :)
      real(dp), intent(in), optional :: initial(:, :)
      problem%n = n
      problem%finite = finite
      problem%volume = volume
      problem%compatible = compatible
      allocate (problem%enhanced(6, n, size(volume)))
      if (present(initial)) then
         problem%prestressed = .true.
         problem%initial = initial(:, 1:size(volume))
      end if
   end subroutine start_local_problem

   !> G_g = ratio T0^{-T} M(xi_g) at point g, ratio = dV_centre / dV_g (module header).
   pure subroutine set_enhanced_operator(problem, g, ratio, push, modes)
      type(local_problem_t), intent(inout) :: problem
      integer, intent(in) :: g
      real(dp), intent(in) :: ratio
      real(dp), intent(in) :: push(6, 6)    !! T0^{-T} (frix_eas_modes%strain_push_matrix)
      real(dp), intent(in) :: modes(:, :)   !! M(xi_g), (6, n)
      problem%enhanced(:, 1:problem%n, g) = ratio*matmul(push, modes(:, 1:problem%n))
   end subroutine set_enhanced_operator

   !> Solve the local problem from the alpha passed in (solve_enhanced) and return the
   !> converged total strains, stresses and tangents at the points (history in state_new).
   subroutine enhanced_response(name, material, problem, state_old, state_new, alpha, total, pk2, moduli, error)
      character(len=*), intent(in) :: name
      class(material_t), intent(in) :: material
      type(local_problem_t), intent(inout) :: problem
      real(dp), intent(in) :: state_old(:, :)
      real(dp), intent(inout) :: state_new(:, :)
      real(dp), intent(inout) :: alpha(:)
      real(dp), intent(out) :: total(:, :), pk2(:, :), moduli(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      type(local_point_t) :: point
      call material%elastic_tangent(problem%elastic)
      call solve_enhanced(name, material, problem, state_old, state_new, alpha(1:problem%n), point, error)
      if (allocated(error)) return
      total = point%total
      pk2 = point%pk2
      moduli = point%moduli
   end subroutine enhanced_response

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
      real(dp) :: direction(problem%n, 1), previous_max
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

   !> Strains, material response, h and its scales at alpha (all points). The enhanced
   !> equations weigh S, or S - S0 from an initial stress S0 (module header: the initial stress
   !> is an assumed stress field of the Hu-Washizu functional, which drives no enhanced strain).
   subroutine evaluate_local(name, material, problem, alpha, state_old, state_new, point, error)
      character(len=*), intent(in) :: name
      class(material_t), intent(in) :: material
      type(local_problem_t), intent(in) :: problem
      real(dp), intent(in) :: alpha(:)
      real(dp), intent(in) :: state_old(:, :)
      real(dp), intent(inout) :: state_new(:, :)
      type(local_point_t), intent(inout) :: point   !! its arrays allocated here on first use
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: weighed(6, size(problem%volume))
      integer :: n, p
      n = problem%n
      p = size(problem%volume)
      if (.not. allocated(point%total)) then
         allocate (point%total(6, p), point%pk2(6, p), point%moduli(6, 6, p))
         allocate (point%residual(n), point%scale(n), point%floor_scale(n))
      end if
      call enhanced_strains(n, p, problem%enhanced, problem%compatible, alpha, point%total)
      if (problem%prestressed) then
         call material_pass(name, material, problem%finite, point%total, state_old, state_new, point%pk2, &
                            point%moduli, error, problem%initial)
      else
         call material_pass(name, material, problem%finite, point%total, state_old, state_new, point%pk2, &
                            point%moduli, error)
      end if
      if (allocated(error)) return
      weighed = point%pk2
      if (problem%prestressed) weighed = point%pk2 - problem%initial
      call residual_sums(n, p, problem%enhanced, problem%volume, weighed, point%pk2, point%moduli, point%residual, &
                         point%scale, point%floor_scale)
   end subroutine evaluate_local

   !> E_g = E(u)_g + G_g alpha at every point.
   pure subroutine enhanced_strains(n, p, enhanced, compatible, alpha, total)
      integer, intent(in) :: n, p
      real(dp), intent(in) :: enhanced(6, n, p), compatible(6, p), alpha(n)
      real(dp), intent(out) :: total(6, p)
      integer :: g
      do g = 1, p
         total(:, g) = compatible(:, g) + matmul(enhanced(:, 1:n, g), alpha(1:n))
      end do
   end subroutine enhanced_strains

   !> h = sum_g G^T weighed_g dV, its scales sum_g |G_g| max|S_g| dV and sum_g |G_g|
   !> stress_floor max|C_g| dV (local_converged).
   pure subroutine residual_sums(n, p, enhanced, volume, weighed, pk2, moduli, residual, scale, floor_scale)
      integer, intent(in) :: n, p
      real(dp), intent(in) :: enhanced(6, n, p), volume(p), weighed(6, p), pk2(6, p), moduli(6, 6, p)
      real(dp), intent(out) :: residual(n), scale(n), floor_scale(n)
      integer :: g
      residual(1:n) = 0.0_dp
      scale(1:n) = 0.0_dp
      floor_scale(1:n) = 0.0_dp
      do g = 1, p
         residual(1:n) = residual(1:n) + volume(g)*matmul(weighed(:, g), enhanced(:, 1:n, g))
         scale(1:n) = scale(1:n) + volume(g)*maxval(abs(pk2(:, g)))*sum(abs(enhanced(:, 1:n, g)), dim=1)
         floor_scale(1:n) = floor_scale(1:n) + volume(g)*stress_floor*maxval(abs(moduli(:, :, g)))* &
                            sum(abs(enhanced(:, 1:n, g)), dim=1)
      end do
   end subroutine residual_sums

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
      type(local_point_t), intent(inout) :: trial
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
      real(dp), intent(in) :: moduli(:, :, :)   !! (6, 6, p)
      real(dp), intent(out) :: stiffness(:, :)
      call stiffness_sum(problem%n, size(problem%volume), problem%enhanced, problem%volume, moduli, stiffness)
   end subroutine enhanced_stiffness

   !> enhanced_stiffness over explicit-shape arrays (the compiler sees their leading extents).
   pure subroutine stiffness_sum(n, p, enhanced, volume, moduli, stiffness)
      integer, intent(in) :: n, p
      real(dp), intent(in) :: enhanced(6, n, p), volume(p), moduli(6, 6, p)
      real(dp), intent(inout) :: stiffness(:, :)
      real(dp) :: weighted(6, n)
      integer :: g
      stiffness(1:n, 1:n) = 0.0_dp
      do g = 1, p
         weighted(:, 1:n) = volume(g)*matmul(moduli(:, :, g), enhanced(:, 1:n, g))
         stiffness(1:n, 1:n) = stiffness(1:n, 1:n) + matmul(transpose(enhanced(:, 1:n, g)), weighted(:, 1:n))
      end do
   end subroutine stiffness_sum

   !> Solve K_aa X = B (B <- X), K_aa = sum_g G^T C G dV from the points' moduli C
   !> (solve_scaled). Where K_aa is singular (solve_scaled's pivot test) the system is solved
   !> with K_aa + weight K_aa^el, K_aa^el = sum_g G^T D G dV from the law's elastic moduli D.
   pure subroutine solve_enhanced_system(problem, moduli, weight, rhs, singular, regularised)
      type(local_problem_t), intent(in) :: problem
      real(dp), intent(in) :: moduli(:, :, :)
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
      call enhanced_stiffness(problem, spread(problem%elastic, 3, size(problem%volume)), elastic)
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

   !> Static condensation K <- K - K_ua K_aa^{-1} K_au with K_ua = sum_g B^T C G dV,
   !> K_au = sum_g G^T C B dV and K_aa = sum_g G^T C G dV at the converged alpha (for a
   !> symmetric C, K_au = K_ua^T). B_g: the nodal blocks of dE/du at point g, (6, 3, nodes, p).
   subroutine condense(name, problem, b_blocks, moduli, symmetric, tangent, error)
      character(len=*), intent(in) :: name
      type(local_problem_t), intent(in) :: problem
      real(dp), intent(in) :: b_blocks(:, :, :, :), moduli(:, :, :)
      logical, intent(in) :: symmetric
      real(dp), intent(inout) :: tangent(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: coupling(3*size(b_blocks, 3), problem%n), solved(problem%n, 3*size(b_blocks, 3))
      integer :: n, m
      logical :: singular
      n = problem%n
      m = 3*size(b_blocks, 3)
      call coupling_sums(n, size(b_blocks, 3), size(problem%volume), problem%enhanced, problem%volume, b_blocks, &
                         moduli, symmetric, coupling, solved)
      call solve_enhanced_system(problem, moduli, merge(condensation_regularisation, local_regularisation, symmetric), &
                                 solved(1:n, :), singular)
      if (singular) then
         call fatal_error(error, name//': singular enhanced-strain stiffness K_aa')
         return
      end if
      tangent(1:m, 1:m) = tangent(1:m, 1:m) - matmul(coupling(:, 1:n), solved(1:n, :))
   end subroutine condense

   !> K_ua = sum_g B^T C G dV and K_au (sum_g G^T C B dV, or K_ua^T for a symmetric C) over
   !> explicit-shape arrays.
   pure subroutine coupling_sums(n, nodes, p, enhanced, volume, b_blocks, moduli, symmetric, coupling, transposed)
      integer, intent(in) :: n, nodes, p
      real(dp), intent(in) :: enhanced(6, n, p), volume(p), b_blocks(6, 3, nodes, p), moduli(6, 6, p)
      logical, intent(in) :: symmetric
      real(dp), intent(out) :: coupling(3*nodes, n), transposed(n, 3*nodes)
      real(dp) :: weighted(6, n)
      integer :: g, a
      coupling(:, 1:n) = 0.0_dp
      transposed(1:n, :) = 0.0_dp   ! K_au, accumulated for an unsymmetric C
      do g = 1, p
         weighted(:, 1:n) = volume(g)*matmul(moduli(:, :, g), enhanced(:, 1:n, g))
         do a = 1, nodes
            coupling(3*a - 2:3*a, 1:n) = coupling(3*a - 2:3*a, 1:n) + matmul(transpose(b_blocks(:, :, a, g)), weighted(:, 1:n))
            if (.not. symmetric) transposed(1:n, 3*a - 2:3*a) = transposed(1:n, 3*a - 2:3*a) + &
                                 volume(g)*matmul(transpose(enhanced(:, 1:n, g)), matmul(moduli(:, :, g), b_blocks(:, :, a, g)))
         end do
      end do
      if (symmetric) transposed(1:n, :) = transpose(coupling(:, 1:n))
   end subroutine coupling_sums

end module frix_enhanced_strain
