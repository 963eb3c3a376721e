!> Mohr-Coulomb plasticity with associated or non-associated flow, linear cohesion hardening
!> or softening and an optional tension cut-off; deck keyword MAT_3DMohrCoulomb, properties
!> YOUNG NUE COHESION PHI PSI [TENSION] [HARD] [DENS] (frix_frictional_plasticity: elasticity,
!> cohesion, history; docs/materials.md).
!>
!> Tension positive, principal stresses sorted sigma_1 >= sigma_2 >= sigma_3. Yield function of
!> the main plane and flow potential (psi in place of phi):
!>   f_1 = (sigma_1 - sigma_3) + (sigma_1 + sigma_3) sin(phi) - 2 c(alpha) cos(phi)
!> and the two planes that meet it at the edges (the same function of another pair):
!>   f_2 = (sigma_1 - sigma_2) + (sigma_1 + sigma_2) sin(phi) - 2 c cos(phi)   (edge sigma_2 = sigma_3,
!>         triaxial extension)
!>   f_3 = (sigma_2 - sigma_3) + (sigma_2 + sigma_3) sin(phi) - 2 c cos(phi)   (edge sigma_1 = sigma_2,
!>         triaxial compression)
!> f_i = a_i . sigma - 2 c cos(phi), flow vector b_i = d g_i / d sigma (constant in principal space).
!> Tension cut-off (Rankine, associated, perfectly plastic; TENSION = t < c cot(phi)): the planes
!>   f_4 = sigma_1 - t,  f_5 = sigma_2 - t,  f_6 = sigma_3 - t   (a = b = the unit vector e_a).
!>
!> Return mapping in principal stresses (de Souza Neto, Peric & Owen, Computational Methods for
!> Plasticity, Wiley 2008, ch. 8; Clausen, Damkilde & Andersen, IJNME 66, 2006): the trial
!> stress sigma* = D eps_e* (D = lambda 1 x 1 + 2 G I in principal space) returns onto a set S of
!> active planes by the closed form of linear hardening,
!>   sigma = sigma* - D B^T dgamma,   J dgamma = f(sigma*),   J_ji = a_j . D b_i + 4 cos^2(phi) H,
!>   d alpha = 2 cos(phi) sum(dgamma),
!> (the sum over the Mohr-Coulomb planes of S only), trying S = {1} (the plane), then {1, 3} and
!> {1, 2} (the edges); with a tension cut-off {1}, {4}, {1, 3}, {1, 2}, {1, 4}, {4, 5},
!> {1, 2, 4}, {1, 3, 4}, {1, 3, 5}, {1, 4, 5}, {3, 4, 5}, {4, 5, 6} (at the point sigma_1 =
!> sigma_2 = t of the main plane, planes 1, 3, 4 and 5 meet, and which three of them have
!> multipliers >= 0 depends on the trial and on psi). A return holds where
!> dgamma >= 0 and no plane is violated (f_2 > 0 or f_3 > 0 after a plane return is exactly the
!> loss of the principal order). Else
!> the apex sigma = p 1 with
!>   p = p* - K d eps_v,   p = c(alpha) cot(phi),   d alpha = cos(phi)/sin(psi) d eps_v
!> (the same d alpha per volumetric plastic strain as on the planes, tr b_i = 2 sin(psi)).
!>
!> Consistent tangent of the isotropic function sigma(eps_e*) (de Souza Neto et al. 2008,
!> appendix A): in the principal basis of eps_e*, the diagonal part d sigma_a = sum_b C_ab d eps_b
!> with C = D - D B^T J^-1 A D (plane and edges), C = K H~/(K + H~) 1 x 1, H~ = H cos^2(phi) /
!> (sin(phi) sin(psi)) (apex), and the rotation of the principal axes
!> d sigma_ab = (sigma_a - sigma_b) / (eps_a - eps_b) d eps_ab (a /= b), zero for a pair the
!> return holds equal (an edge's pair, the apex), the confluent limit C_aa - C_ab where two trial
!> values coincide otherwise. Unsymmetric when psi /= phi.
!> REGION (history): 1 the main plane, 2 an edge, 3 the apex, 4 a return involving the cut-off.
module frix_mohr_coulomb
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error, append_error
   use frix_strings, only: to_string
   use frix_property_list, only: property_list_t
   use frix_material, only: material_t
   use frix_linear_elastic, only: hooke_tangent
   use frix_symmetric_tensor, only: voigt_i, voigt_j, tensor_of_strain, principal_dyads
   use frix_logarithmic_strain, only: symmetric_eigen3
   use frix_frictional_plasticity, only: frictional_plastic_t, return_outcome_t, read_frictional_properties, &
                                         region_elastic, region_surface, region_edge, region_apex, region_tension
   implicit none
   private

   public :: mohr_coulomb_t, mohr_coulomb_from_properties

   !> A return is taken when its multipliers are >= -tolerance * their largest and no plane is
   !> violated by more than tolerance * the stress scale (round-off at region boundaries).
   real(dp), parameter :: region_tolerance = 1.0e-10_dp
   !> Trial excess over the surface, relative to the stress scale, below which a point is elastic.
   real(dp), parameter :: yield_tolerance = 1.0e-12_dp

   !> The sets of active planes tried in turn (module header), without and with the cut-off.
   integer, parameter :: max_active = 3
   integer, parameter :: plain_sets(max_active, 3) = reshape([1, 0, 0, 1, 3, 0, 1, 2, 0], [max_active, 3])
   integer, parameter :: cut_off_sets(max_active, 12) = reshape([1, 0, 0, 4, 0, 0, 1, 3, 0, 1, 2, 0, 1, 4, 0, &
                                                                 4, 5, 0, 1, 2, 4, 1, 3, 4, 1, 3, 5, 1, 4, 5, &
                                                                 3, 4, 5, 4, 5, 6], [max_active, 12])

   !> The planes' normals and the constants the returns need (new_planes, built with the law).
   type :: planes_t
      real(dp) :: normals(6, 3)     !! a_i (row i): of phi (1-3), the cut-off (4-6)
      real(dp) :: flows(6, 3)       !! b_i (row i): of psi (1-3), the cut-off (4-6)
      real(dp) :: elastic(3, 3)     !! D in principal space
      real(dp) :: bulk, shear
      real(dp) :: tension           !! t, or huge without a cut-off
      real(dp) :: two_cos           !! 2 cos(phi)
   end type planes_t

   !> The cohesion of one return and what its tests compare with.
   type :: bound_t
      real(dp) :: cohesion          !! c at the start of the increment
      real(dp) :: slope             !! dc/dalpha during the increment
      real(dp) :: scale             !! of the stresses: 2 c cos(phi) + max |sigma*_a| (+ t)
   end type bound_t

   type, extends(frictional_plastic_t) :: mohr_coulomb_t
      logical :: has_tension = .false.   !! TENSION given
      real(dp) :: tension = 0.0_dp       !! t, the cut-off of the principal stresses
      type(planes_t) :: planes           !! of the law's constants (new_planes)
   contains
      procedure :: corrector => mohr_coulomb_corrector
   end type mohr_coulomb_t

   !> A return in principal space.
   type :: principal_return_t
      real(dp) :: stress(3) = 0.0_dp
      real(dp) :: derivative(3, 3) = 0.0_dp  !! d sigma_a / d eps*_b
      real(dp) :: alpha_increment = 0.0_dp
      integer :: region = region_elastic
      logical :: tied(3, 3) = .false.        !! pairs the return holds equal
   end type principal_return_t


contains

   !> The law of deck properties YOUNG NUE DENS COHESION PHI PSI HARD TENSION.
   subroutine mohr_coulomb_from_properties(properties, material, error)
      type(property_list_t), intent(in) :: properties
      class(material_t), allocatable, intent(out) :: material
      type(error_t), allocatable, intent(out) :: error
      type(mohr_coulomb_t) :: law
      character(len=:), allocatable :: bound
      law%name = 'MAT_3DMohrCoulomb'
      call read_frictional_properties(properties, law, error, [character(len=8) :: 'TENSION'], &
                                      'YOUNG, NUE, DENS, COHESION, PHI, PSI, HARD, TENSION')
      call properties%take_real('TENSION', law%tension, law%has_tension, error, default=0.0_dp)
      if (law%has_tension .and. .not. allocated(error)) then
         if (.not. (law%tension >= 0.0_dp .and. law%tension*tan(law%friction_angle) < law%cohesion)) then
            bound = 'infinity'
            if (tan(law%friction_angle) > 0.0_dp) bound = to_string(law%cohesion/tan(law%friction_angle))
            call append_error(error, trim(properties%owner)//': TENSION must lie in [0, COHESION cot(PHI)) = [0, '// &
                              bound//'), got '//to_string(law%tension))
         end if
      end if
      if (allocated(error)) return
      law%planes = new_planes(law)
      allocate (material, source=law)
   end subroutine mohr_coulomb_from_properties

   subroutine mohr_coulomb_corrector(self, elastic_strain, cohesion, slope, outcome, error)
      class(mohr_coulomb_t), intent(in) :: self
      real(dp), intent(in) :: elastic_strain(6)
      real(dp), intent(in) :: cohesion, slope
      type(return_outcome_t), intent(out) :: outcome
      type(error_t), allocatable, intent(out) :: error
      type(bound_t) :: bound
      type(principal_return_t) :: principal
      real(dp) :: strains(3), directions(3, 3), trial(3), dyads(6, 6)
      call principal_strains(elastic_strain, strains, directions)
      trial = matmul(self%planes%elastic, strains)
      bound = bound_t(cohesion, slope, self%planes%two_cos*cohesion + maxval(abs(trial)))
      if (self%has_tension) bound%scale = bound%scale + self%tension
      if (maxval(excess(self%planes, trial, cohesion)) <= yield_tolerance*bound%scale) then
         outcome%tangent = hooke_tangent(self%young, self%poisson)
         outcome%stress = matmul(outcome%tangent, elastic_strain)
         return
      end if
      call principal_return(self, bound, trial, principal, error)
      if (allocated(error)) return
      outcome%region = principal%region
      outcome%alpha_increment = principal%alpha_increment
      dyads = principal_dyads(directions)
      outcome%stress = spectral_stress(principal%stress, dyads)
      outcome%tangent = spectral_tangent(principal, strains, dyads)
   end subroutine mohr_coulomb_corrector

   !> Principal values of the strain (descending) and their directions (columns).
   subroutine principal_strains(strain, values, directions)
      real(dp), intent(in) :: strain(6)
      real(dp), intent(out) :: values(3), directions(3, 3)
      real(dp) :: unsorted(3), remaining(3), vectors(3, 3)
      integer :: order(3), a
      call symmetric_eigen3(tensor_of_strain(strain), unsorted, vectors)
      remaining = unsorted
      do a = 1, 3
         order(a) = maxloc(remaining, dim=1)
         remaining(order(a)) = -huge(1.0_dp)
      end do
      values = unsorted(order)
      directions = vectors(:, order)
   end subroutine principal_strains

   !> The planes of the law's constants.
   pure function new_planes(self) result(planes)
      class(mohr_coulomb_t), intent(in) :: self
      type(planes_t) :: planes
      real(dp) :: lambda
      integer :: a
      planes%normals = 0.0_dp
      planes%normals(1:3, :) = plane_vectors(sin(self%friction_angle))
      planes%flows = 0.0_dp
      planes%flows(1:3, :) = plane_vectors(sin(self%dilation_angle))
      do a = 1, 3
         planes%normals(3 + a, a) = 1.0_dp
         planes%flows(3 + a, a) = 1.0_dp
      end do
      planes%tension = merge(self%tension, huge(1.0_dp), self%has_tension)
      planes%two_cos = 2.0_dp*cos(self%friction_angle)
      call self%moduli(planes%bulk, planes%shear)
      lambda = planes%bulk - 2.0_dp*planes%shear/3.0_dp
      planes%elastic = lambda
      do a = 1, 3
         planes%elastic(a, a) = lambda + 2.0_dp*planes%shear
      end do
   end function new_planes

   !> Rows a_1, a_2, a_3 of f_1, f_2, f_3 (module header) for s = sin(phi) (or sin(psi): b_i).
   pure function plane_vectors(s) result(rows)
      real(dp), intent(in) :: s
      real(dp) :: rows(3, 3)
      rows(1, :) = [1.0_dp + s, 0.0_dp, -(1.0_dp - s)]
      rows(2, :) = [1.0_dp + s, -(1.0_dp - s), 0.0_dp]
      rows(3, :) = [0.0_dp, 1.0_dp + s, -(1.0_dp - s)]
   end function plane_vectors

   !> The sets of active planes in turn (module header), then the apex.
   subroutine principal_return(self, bound, trial, principal, error)
      class(mohr_coulomb_t), intent(in) :: self
      type(bound_t), intent(in) :: bound
      real(dp), intent(in) :: trial(3)
      type(principal_return_t), intent(out) :: principal
      type(error_t), allocatable, intent(out) :: error
      logical :: valid
      integer :: k
      if (self%has_tension) then
         do k = 1, size(cut_off_sets, 2)
            call planes_return(self%planes, bound, trial, cut_off_sets(:, k), principal, valid)
            if (valid) return
         end do
      else
         do k = 1, size(plain_sets, 2)
            call planes_return(self%planes, bound, trial, plain_sets(:, k), principal, valid)
            if (valid) return
         end do
      end if
      call apex_return(self, bound, trial, principal, error)
   end subroutine principal_return

   !> The closed-form return onto the planes of `active` (module header); `valid` as there.
   !> Fixed sizes: the unused rows and columns of the set's arrays are zero (an identity block
   !> of the Jacobian), which leaves the active planes' sums as they are.
   pure subroutine planes_return(planes, bound, trial, active, principal, valid)
      type(planes_t), intent(in) :: planes
      type(bound_t), intent(in) :: bound
      real(dp), intent(in) :: trial(3)
      integer, intent(in) :: active(max_active)   !! the active planes, then zeros
      type(principal_return_t), intent(out) :: principal
      logical, intent(out) :: valid
      real(dp) :: normals(max_active, 3), flows(3, max_active), jacobian(max_active, max_active)
      real(dp) :: inverse(max_active, max_active), multipliers(max_active), hardening(max_active)
      real(dp) :: trial_excess(6), active_excess(max_active)
      logical :: invertible
      integer :: n, i, k
      n = count(active > 0)
      trial_excess = excess(planes, trial, bound%cohesion)
      normals = 0.0_dp
      flows = 0.0_dp
      hardening = 0.0_dp   ! d(2 c cos(phi)) / d(c) of each plane's bound
      active_excess = 0.0_dp
      do i = 1, n
         normals(i, :) = planes%normals(active(i), :)
         flows(:, i) = matmul(planes%elastic, planes%flows(active(i), :))   ! D b_i
         if (active(i) <= 3) hardening(i) = planes%two_cos
         active_excess(i) = trial_excess(active(i))
      end do
      jacobian = matmul(normals, flows)
      do i = 1, max_active
         jacobian(:, i) = jacobian(:, i) + bound%slope*hardening*hardening(i)
         if (i > n) jacobian(i, i) = 1.0_dp
      end do
      call small_inverse(jacobian, n, inverse, invertible)
      valid = .false.
      if (.not. invertible) return
      multipliers = matmul(inverse, active_excess)
      principal%stress = trial - matmul(flows, multipliers)
      principal%alpha_increment = dot_product(hardening, multipliers)
      valid = all(multipliers >= -region_tolerance*maxval(abs(multipliers))) .and. &
              all(excess(planes, principal%stress, bound%cohesion + bound%slope*principal%alpha_increment) &
                  <= region_tolerance*bound%scale)
      principal%derivative = planes%elastic - matmul(flows, matmul(inverse, matmul(normals, planes%elastic)))
      do k = 4, 6   ! on an active cut-off sigma_a = t exactly (free of the round-off above)
         if (.not. any(active == k)) cycle
         principal%stress(k - 3) = planes%tension
         principal%derivative(k - 3, :) = 0.0_dp
      end do
      principal%region = region_of(active, n)
      principal%tied(1, 2) = any(active == 3) .or. (any(active == 4) .and. any(active == 5))
      principal%tied(2, 3) = any(active == 2) .or. (any(active == 5) .and. any(active == 6))
      principal%tied(1, 3) = principal%tied(1, 2) .and. principal%tied(2, 3)
      principal%tied = principal%tied .or. transpose(principal%tied)
   end subroutine planes_return

   !> f_1 .. f_6 (module header) at the principal stresses `stress` with the cohesion `cohesion`.
   pure function excess(planes, stress, cohesion) result(values)
      type(planes_t), intent(in) :: planes
      real(dp), intent(in) :: stress(3), cohesion
      real(dp) :: values(6)
      values = matmul(planes%normals, stress)
      values(1:3) = values(1:3) - planes%two_cos*cohesion
      values(4:6) = values(4:6) - planes%tension
   end function excess

   !> REGION of a set of n active planes.
   pure integer function region_of(active, n)
      integer, intent(in) :: active(max_active), n
      if (any(active > 3)) then
         region_of = region_tension
      else if (n == 1) then
         region_of = region_surface
      else
         region_of = region_edge
      end if
   end function region_of

   !> sigma = p 1 with p = c(alpha) cot(phi) (module header); needs phi > 0 and psi > 0.
   subroutine apex_return(self, bound, trial, principal, error)
      class(mohr_coulomb_t), intent(in) :: self
      type(bound_t), intent(in) :: bound
      real(dp), intent(in) :: trial(3)
      type(principal_return_t), intent(out) :: principal
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: modulus, volumetric, pressure
      character(len=:), allocatable :: trial_text
      trial_text = ' (trial principal stresses '//to_string(trial(1))//', '//to_string(trial(2))//', '// &
                   to_string(trial(3))//')'
      if (.not. (sin(self%friction_angle) > 0.0_dp .and. sin(self%dilation_angle) > 0.0_dp)) then
         call fatal_error(error, self%name//': a stress beyond the apex of the cone needs PSI > 0'//trial_text)
         return
      end if
      modulus = bound%slope*cos(self%friction_angle)**2/(sin(self%friction_angle)*sin(self%dilation_angle))
      pressure = sum(trial)/3.0_dp
      volumetric = (pressure - bound%cohesion/tan(self%friction_angle))/(self%planes%bulk + modulus)
      if (.not. (volumetric >= 0.0_dp .and. self%planes%bulk + modulus > 0.0_dp)) then
         call fatal_error(error, self%name//': no return onto the yield surface'//trial_text)
         return
      end if
      principal%alpha_increment = volumetric*cos(self%friction_angle)/sin(self%dilation_angle)
      ! p* - K d eps_v, written as c(alpha) cot(phi): exactly constant for perfect plasticity
      principal%stress = (bound%cohesion + bound%slope*principal%alpha_increment)/tan(self%friction_angle)
      principal%derivative = self%planes%bulk*modulus/(self%planes%bulk + modulus)
      principal%region = region_apex
      principal%tied = .true.
   end subroutine apex_return

   !> Inverse of the leading n x n block (n = 1, 2, 3) of a 3 x 3 matrix whose other rows and
   !> columns are those of the identity, by the adjugate; `invertible` false where the
   !> determinant is not above 1e-12 of the product of the rows' norms (a dependent set of
   !> planes) or, for a single plane, not positive (softening too steep for a return).
   pure subroutine small_inverse(a, n, inverse, invertible)
      real(dp), intent(in) :: a(3, 3)
      integer, intent(in) :: n
      real(dp), intent(out) :: inverse(3, 3)
      logical, intent(out) :: invertible
      real(dp) :: determinant, adjugate(3, 3)
      integer :: i, j
      do j = 1, 3
         do i = 1, 3
            adjugate(j, i) = a(mod(i, 3) + 1, mod(j, 3) + 1)*a(mod(i + 1, 3) + 1, mod(j + 1, 3) + 1) &
                             - a(mod(i, 3) + 1, mod(j + 1, 3) + 1)*a(mod(i + 1, 3) + 1, mod(j, 3) + 1)
         end do
      end do
      determinant = sum(a(1, :)*adjugate(:, 1))
      invertible = abs(determinant) > 1.0e-12_dp*product(sqrt(sum(a**2, dim=2))) .and. (n > 1 .or. determinant > 0.0_dp)
      inverse = 0.0_dp
      if (invertible) inverse = adjugate/determinant
   end subroutine small_inverse

   !> d sigma / d eps (Voigt, engineering strains) of the isotropic function (module header),
   !> with the dyads D_m of the principal directions (principal_dyads):
   !>   sum_ab C_ab D_a D_b^T + sum_(a<b) (R_ab + R_ba) D_ab D_ab^T,
   !> C = principal%derivative, R_ab the rotation term of the pair (a, b) (R_ba: C_bb - C_ba in
   !> the confluent limit); D_ab^T d eps is d eps_ab in the principal basis.
   pure function spectral_tangent(principal, strains, dyads) result(tangent)
      type(principal_return_t), intent(in) :: principal
      real(dp), intent(in) :: strains(3), dyads(6, 6)
      real(dp) :: tangent(6, 6)
      real(dp) :: normal(6), shear
      integer :: a, b, m, l
      tangent = 0.0_dp
      do b = 1, 3
         normal = matmul(dyads(:, 1:3), principal%derivative(:, b))
         do l = 1, 6
            tangent(:, l) = tangent(:, l) + normal*dyads(l, b)
         end do
      end do
      do m = 4, 6
         a = voigt_i(m)
         b = voigt_j(m)
         if (principal%tied(a, b)) cycle
         shear = rotation(a, b) + rotation(b, a)
         do l = 1, 6
            tangent(:, l) = tangent(:, l) + shear*dyads(l, m)*dyads(:, m)
         end do
      end do
   contains
      !> (sigma_a - sigma_b) / (eps_a - eps_b), or C_aa - C_ab where the trial values coincide.
      pure real(dp) function rotation(a, b)
         integer, intent(in) :: a, b
         if (strains(a) /= strains(b)) then
            rotation = (principal%stress(a) - principal%stress(b))/(strains(a) - strains(b))
         else
            rotation = principal%derivative(a, a) - principal%derivative(a, b)
         end if
      end function rotation
   end function spectral_tangent

   !> sum_a sigma_a n_a x n_a written as sigma_2 1 + (sigma_1 - sigma_2) n_1 x n_1 + (sigma_3 -
   !> sigma_2) n_3 x n_3: exactly isotropic at the apex, one direction only on an edge.
   pure function spectral_stress(values, dyads) result(stress)
      real(dp), intent(in) :: values(3), dyads(6, 6)
      real(dp) :: stress(6)
      stress = (values(1) - values(2))*dyads(:, 1) + (values(3) - values(2))*dyads(:, 3)
      stress(1:3) = stress(1:3) + values(2)
   end function spectral_stress
end module frix_mohr_coulomb
