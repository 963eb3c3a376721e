!> Von Mises (J2) plasticity with isotropic hardening (frix_hardening: linear, saturation or
!> tabulated) and linear kinematic hardening (Prager), associated flow; deck keyword
!> MAT_3DMisesPlastic (CARAT's), properties YOUNG NUE SIGY [HARD | ETAN] [SIGINF DELTA]
!> [EPSPk SIGYk] [KINH] [DENS] (docs/materials.md).
!>
!> Small strain (the element's Geo_Lin): additive split eps = eps_e + eps_p, sigma = kappa tr(eps_e)
!> 1 + 2 mu dev(eps_e), yield function f = |dev(sigma) - beta| - sqrt(2/3) K(alpha); radial return
!> and the algorithmic (consistent) tangent of Simo & Hughes, Computational Inelasticity,
!> Springer 1998, Box 3.2 (return) and eq. 3.3.14 ff. (tangent):
!>   xi_tr = 2 mu dev(eps - eps_p,n) - beta_n,  f_tr = |xi_tr| - sqrt(2/3) K(alpha_n)
!>   g(dgamma) = |xi_tr| - (2 mu + 2/3 KINH) dgamma - sqrt(2/3) K(alpha_n + sqrt(2/3) dgamma) = 0
!>   n = xi_tr / |xi_tr|,  eps_p += dgamma n,  alpha += sqrt(2/3) dgamma,  beta += 2/3 KINH dgamma n
!>   C = kappa 1 x 1 + 2 mu theta I_dev - 2 mu theta_bar n x n,
!>   theta = 1 - 2 mu dgamma / |xi_tr|,  theta_bar = 1/(1 + (K' + KINH)/(3 mu)) - (1 - theta).
!> Finite strain (Tot_Lagr): the same return in the Lagrangian logarithmic strain space of Miehe,
!> Apel & Lambrecht (CMAME 191, 2002): eps := E_log = 1/2 ln C, eps_p the plastic part of E_log,
!> the stress T conjugate to E_log mapped to S = P^T T with the tangent P^T C P + T : d2E_log
!> (frix_plastic_law, frix_logarithmic_strain). For isotropic elasticity this is the Hencky law with the
!> exponential-map plasticity of Simo (CMAME 99, 1992) / Eterovic & Bathe (IJNME 30, 1990)
!> whenever the plastic flow is coaxial; volume-preserving (tr eps_p = 0, det F_p = 1).
!>
!> History per integration point (n_state = 14): EQPS (alpha), YIELDED (1 when the point
!> yielded in the increment, else 0), eps_p (6, engineering shears), beta (6, tensor shears).
module frix_von_mises_plastic
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error, append_error
   use frix_strings, only: to_string
   use frix_property_list, only: property_list_t
   use frix_material, only: material_t, history_name_length
   use frix_plastic_law, only: plastic_law_t
   use frix_linear_elastic, only: elastic_constants, lame_parameters, hooke_tangent
   use frix_hardening, only: hardening_t, read_hardening, hardening_names, max_table_points
   implicit none
   private

   public :: von_mises_plastic_t, von_mises_from_properties, init_von_mises_plastic
   public :: state_eqps, state_yielded, state_plastic_strain, state_back_stress

   integer, parameter :: state_eqps = 1                 !! alpha
   integer, parameter :: state_yielded = 2              !! 1 or 0
   integer, parameter :: state_plastic_strain = 3       !! first of 6 entries of eps_p
   integer, parameter :: state_back_stress = 9          !! first of 6 entries of beta
   integer, parameter :: n_history = 14

   real(dp), parameter :: root_two_thirds = 0.81649658092772603273242802490196_dp
   integer, parameter :: max_return_iterations = 60
   !> The consistency residual's tolerance relative to |xi_tr| (its round-off is ~ 1e-16 |xi_tr|),
   !> and the trial excess, relative to sqrt(2/3) K, below which a point stays elastic (the
   !> round-off of a point that is already on the surface and does not load further).
   real(dp), parameter :: return_tolerance = 1.0e-12_dp

   type, extends(plastic_law_t) :: von_mises_plastic_t
      real(dp) :: kinematic_modulus = 0.0_dp  !! KINH: Prager modulus, d beta = 2/3 KINH d eps_p
      type(hardening_t) :: hardening
   contains
      procedure :: n_state => von_mises_n_state
      procedure :: return_map => von_mises_return_map
      procedure :: elastic_tangent => von_mises_elastic_tangent
      procedure :: history_names => von_mises_history_names
   end type von_mises_plastic_t

contains

   !> Set `material` (filled in place: gfortran 12 leaks the hardening table of a function
   !> result copied into a polymorphic allocation).
   pure subroutine init_von_mises_plastic(material, young, poisson, density, hardening, kinematic_modulus)
      type(von_mises_plastic_t), intent(out) :: material
      real(dp), intent(in) :: young, poisson, density
      type(hardening_t), intent(in) :: hardening
      real(dp), intent(in) :: kinematic_modulus
      material%name = 'MAT_3DMisesPlastic'
      material%young = young
      material%poisson = poisson
      material%density = density
      material%hardening = hardening
      material%kinematic_modulus = kinematic_modulus
   end subroutine init_von_mises_plastic

   !> The law of deck properties YOUNG NUE DENS (elastic_constants), the hardening's
   !> (read_hardening) and KINH (>= 0, default 0).
   subroutine von_mises_from_properties(properties, material, error)
      type(property_list_t), intent(in) :: properties
      class(material_t), allocatable, intent(out) :: material
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: young, poisson, density, kinematic, tangent_modulus
      type(hardening_t) :: hardening
      logical :: found
      call elastic_constants(properties, young, poisson, density, error, &
                             [character(len=8) :: hardening_names(), 'KINH', 'ETAN'], &
                             'YOUNG, NUE, DENS, SIGY, HARD, ETAN, SIGINF, DELTA, EPSPk and SIGYk (k = 1..'// &
                             to_string(max_table_points)//'), KINH')
      call read_hardening(properties, hardening, error)
      ! ETAN: the tangent modulus E_t of the uniaxial curve after yield (CCARAT's `Hard`),
      ! H = E E_t / (E - E_t) (uniaxial stress: 1/E_t = 1/E + 1/H)
      call properties%take_real('ETAN', tangent_modulus, found, error, default=0.0_dp)
      if (found) then
         if (any(properties%names == 'HARD') .or. size(hardening%strains) > 1) then
            call append_error(error, trim(properties%owner)//': ETAN excludes HARD and a hardening table')
         else if (.not. (tangent_modulus >= 0.0_dp .and. tangent_modulus < young)) then
            call append_error(error, trim(properties%owner)//': ETAN must lie in [0, YOUNG), got '// &
                              to_string(tangent_modulus))
         else
            hardening%modulus = young*tangent_modulus/(young - tangent_modulus)
         end if
      end if
      call properties%take_real('KINH', kinematic, found, error, default=0.0_dp)
      if (.not. (kinematic >= 0.0_dp .and. kinematic < huge(1.0_dp))) &
         call append_error(error, trim(properties%owner)//': KINH must be >= 0, got '//to_string(kinematic))
      if (allocated(error)) return
      allocate (von_mises_plastic_t :: material)
      select type (material)
      type is (von_mises_plastic_t)
         call init_von_mises_plastic(material, young, poisson, density, hardening, kinematic)
      end select
   end subroutine von_mises_from_properties

   pure function von_mises_n_state(self) result(n)
      class(von_mises_plastic_t), intent(in) :: self
      integer :: n
      n = n_history
   end function von_mises_n_state

   pure subroutine von_mises_history_names(self, names)
      class(von_mises_plastic_t), intent(in) :: self
      character(len=history_name_length), allocatable, intent(out) :: names(:)
      names = [character(len=history_name_length) :: 'EQPS', 'YIELDED']
   end subroutine von_mises_history_names

   pure subroutine von_mises_elastic_tangent(self, tangent)
      class(von_mises_plastic_t), intent(in) :: self
      real(dp), intent(out) :: tangent(6, 6)
      tangent = hooke_tangent(self%young, self%poisson)
   end subroutine von_mises_elastic_tangent

   !> Radial return at the total strain `strain` (eps, or E_log: frix_plastic_law) from the
   !> history state_old.
   subroutine von_mises_return_map(self, strain, state_old, state_new, stress, tangent, error)
      class(von_mises_plastic_t), intent(in) :: self
      real(dp), intent(in) :: strain(6)
      real(dp), intent(in) :: state_old(:)
      real(dp), intent(inout) :: state_new(:)
      real(dp), intent(out) :: stress(6), tangent(6, 6)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: lambda, mu, kappa, elastic(6), volumetric, trial(6), relative(6), norm, normal(6)
      real(dp) :: alpha, excess, dgamma, theta, theta_bar, slope
      integer :: i
      call lame_parameters(self%young, self%poisson, lambda, mu)
      kappa = lambda + 2.0_dp*mu/3.0_dp
      alpha = state_old(state_eqps)
      elastic = strain - state_old(state_plastic_strain:state_plastic_strain + 5)
      volumetric = sum(elastic(1:3))
      trial(1:3) = 2.0_dp*mu*(elastic(1:3) - volumetric/3.0_dp)
      trial(4:6) = mu*elastic(4:6)
      relative = trial - state_old(state_back_stress:state_back_stress + 5)
      norm = tensor_norm(relative)
      excess = norm - root_two_thirds*self%hardening%yield_stress(alpha)
      state_new(1:n_history) = state_old(1:n_history)
      state_new(state_yielded) = 0.0_dp
      if (excess <= return_tolerance*root_two_thirds*self%hardening%yield_stress(alpha)) then
         tangent = hooke_tangent(self%young, self%poisson)
         stress = trial
         stress(1:3) = stress(1:3) + kappa*volumetric
         return
      end if
      call solve_consistency(self, mu, norm, alpha, dgamma, error)
      if (allocated(error)) then
         stress = 0.0_dp
         tangent = 0.0_dp
         return
      end if
      normal = relative/norm
      slope = self%hardening%slope(alpha + root_two_thirds*dgamma)
      state_new(state_eqps) = alpha + root_two_thirds*dgamma
      state_new(state_yielded) = 1.0_dp
      associate (plastic => state_new(state_plastic_strain:state_plastic_strain + 5), &
                 back => state_new(state_back_stress:state_back_stress + 5))
         plastic(1:3) = plastic(1:3) + dgamma*normal(1:3)
         plastic(4:6) = plastic(4:6) + 2.0_dp*dgamma*normal(4:6)
         back = back + (2.0_dp/3.0_dp)*self%kinematic_modulus*dgamma*normal
      end associate
      stress = trial - 2.0_dp*mu*dgamma*normal
      stress(1:3) = stress(1:3) + kappa*volumetric
      theta = 1.0_dp - 2.0_dp*mu*dgamma/norm
      theta_bar = 1.0_dp/(1.0_dp + (slope + self%kinematic_modulus)/(3.0_dp*mu)) - (1.0_dp - theta)
      tangent = 0.0_dp
      tangent(1:3, 1:3) = kappa - 2.0_dp*mu*theta/3.0_dp
      do i = 1, 3
         tangent(i, i) = tangent(i, i) + 2.0_dp*mu*theta
         tangent(i + 3, i + 3) = mu*theta
      end do
      do i = 1, 6
         tangent(:, i) = tangent(:, i) - 2.0_dp*mu*theta_bar*normal*normal(i)
      end do
   end subroutine von_mises_return_map

   !> dgamma > 0 with g(dgamma) = 0 (see the module header): Newton's method kept inside the
   !> bracket [0, |xi_tr| / (2 mu)] (g(0) > 0 >= g at the upper end since K > 0), bisecting when
   !> a step leaves it; converges in one step for linear hardening.
   subroutine solve_consistency(self, mu, norm, alpha, dgamma, error)
      class(von_mises_plastic_t), intent(in) :: self
      real(dp), intent(in) :: mu, norm, alpha
      real(dp), intent(out) :: dgamma
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: low, high, residual, derivative, modulus, scale
      integer :: iteration
      modulus = 2.0_dp*mu + (2.0_dp/3.0_dp)*self%kinematic_modulus
      low = 0.0_dp
      high = norm/(2.0_dp*mu)
      scale = root_two_thirds*self%hardening%yield_stress(alpha)
      dgamma = (norm - scale)/(modulus + (2.0_dp/3.0_dp)*self%hardening%slope(alpha))
      do iteration = 1, max_return_iterations
         if (.not. (dgamma > low .and. dgamma < high)) dgamma = 0.5_dp*(low + high)
         residual = norm - modulus*dgamma - root_two_thirds*self%hardening%yield_stress(alpha + root_two_thirds*dgamma)
         if (abs(residual) <= return_tolerance*norm) return
         if (residual > 0.0_dp) then
            low = dgamma
         else
            high = dgamma
         end if
         derivative = -modulus - (2.0_dp/3.0_dp)*self%hardening%slope(alpha + root_two_thirds*dgamma)
         dgamma = dgamma - residual/derivative
      end do
      call fatal_error(error, self%name//': the return mapping did not converge in '// &
                       to_string(max_return_iterations)//' iterations (trial |s - beta| = '//to_string(norm)//')')
   end subroutine solve_consistency

   !> |t| = sqrt(t : t) of a symmetric tensor in Voigt form with tensor shears.
   pure real(dp) function tensor_norm(t)
      real(dp), intent(in) :: t(6)
      tensor_norm = sqrt(sum(t(1:3)**2) + 2.0_dp*sum(t(4:6)**2))
   end function tensor_norm
end module frix_von_mises_plastic
