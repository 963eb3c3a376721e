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
   use frix_symmetric_tensor, only: tensor_of_strain, stress_of_tensor, rotated_unit_strain
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

   type, extends(frictional_plastic_t) :: mohr_coulomb_t
      logical :: has_tension = .false.   !! TENSION given
      real(dp) :: tension = 0.0_dp       !! t, the cut-off of the principal stresses
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

   !> The planes' normals and what the returns need, for one law and increment.
   type :: planes_t
      real(dp) :: normals(6, 3)     !! a_i (row i): of phi (1-3), the cut-off (4-6)
      real(dp) :: flows(6, 3)       !! b_i (row i): of psi (1-3), the cut-off (4-6)
      real(dp) :: elastic(3, 3)     !! D in principal space
      real(dp) :: bulk, shear, cohesion, slope, scale
      real(dp) :: tension           !! t, or huge without a cut-off
      real(dp) :: two_cos           !! 2 cos(phi)
   end type planes_t

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
      if (.not. allocated(error)) allocate (material, source=law)
   end subroutine mohr_coulomb_from_properties

   subroutine mohr_coulomb_corrector(self, elastic_strain, cohesion, slope, outcome, error)
      class(mohr_coulomb_t), intent(in) :: self
      real(dp), intent(in) :: elastic_strain(6)
      real(dp), intent(in) :: cohesion, slope
      type(return_outcome_t), intent(out) :: outcome
      type(error_t), allocatable, intent(out) :: error
      type(planes_t) :: planes
      type(principal_return_t) :: principal
      real(dp) :: strains(3), directions(3, 3), trial(3)
      call principal_strains(elastic_strain, strains, directions)
      planes = new_planes(self, cohesion, slope)
      trial = matmul(planes%elastic, strains)
      planes%scale = 2.0_dp*cohesion*cos(self%friction_angle) + maxval(abs(trial))
      if (self%has_tension) planes%scale = planes%scale + self%tension
      if (maxval(excess(planes, trial, planes%cohesion)) <= yield_tolerance*planes%scale) then
         outcome%tangent = hooke_tangent(self%young, self%poisson)
         outcome%stress = matmul(outcome%tangent, elastic_strain)
         return
      end if
      call principal_return(self, planes, trial, principal, error)
      if (allocated(error)) return
      outcome%region = principal%region
      outcome%alpha_increment = principal%alpha_increment
      outcome%stress = spectral_stress(principal%stress, directions)
      outcome%tangent = spectral_tangent(principal, strains, directions)
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

   pure function new_planes(self, cohesion, slope) result(planes)
      class(mohr_coulomb_t), intent(in) :: self
      real(dp), intent(in) :: cohesion, slope
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
      planes%cohesion = cohesion
      planes%slope = slope
      planes%scale = 0.0_dp
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
   subroutine principal_return(self, planes, trial, principal, error)
      class(mohr_coulomb_t), intent(in) :: self
      type(planes_t), intent(in) :: planes
      real(dp), intent(in) :: trial(3)
      type(principal_return_t), intent(out) :: principal
      type(error_t), allocatable, intent(out) :: error
      logical :: valid
      integer :: k
      if (self%has_tension) then
         do k = 1, size(cut_off_sets, 2)
            call planes_return(self, planes, trial, pack(cut_off_sets(:, k), cut_off_sets(:, k) > 0), principal, valid)
            if (valid) return
         end do
      else
         do k = 1, size(plain_sets, 2)
            call planes_return(self, planes, trial, pack(plain_sets(:, k), plain_sets(:, k) > 0), principal, valid)
            if (valid) return
         end do
      end if
      call apex_return(self, planes, trial, principal, error)
   end subroutine principal_return

   !> The closed-form return onto the planes `active` (module header); `valid` as there.
   pure subroutine planes_return(self, planes, trial, active, principal, valid)
      class(mohr_coulomb_t), intent(in) :: self
      type(planes_t), intent(in) :: planes
      real(dp), intent(in) :: trial(3)
      integer, intent(in) :: active(:)
      type(principal_return_t), intent(out) :: principal
      logical, intent(out) :: valid
      real(dp) :: normals(size(active), 3), flows(3, size(active)), jacobian(size(active), size(active))
      real(dp) :: inverse(size(active), size(active)), multipliers(size(active)), hardening(size(active))
      real(dp) :: trial_excess(6)
      logical :: invertible
      integer :: k
      normals = planes%normals(active, :)
      flows = matmul(planes%elastic, transpose(planes%flows(active, :)))   ! columns D b_i
      hardening = merge(planes%two_cos, 0.0_dp, active <= 3)   ! d(2 c cos(phi)) / d(c) of each plane's bound
      jacobian = matmul(normals, flows) + planes%slope*spread(hardening, 2, size(active))*spread(hardening, 1, size(active))
      call small_inverse(jacobian, inverse, invertible)
      valid = .false.
      if (.not. invertible) return
      trial_excess = excess(planes, trial, planes%cohesion)
      multipliers = matmul(inverse, trial_excess(active))
      principal%stress = trial - matmul(flows, multipliers)
      principal%alpha_increment = dot_product(hardening, multipliers)
      valid = all(multipliers >= -region_tolerance*maxval(abs(multipliers))) .and. &
              all(excess(planes, principal%stress, planes%cohesion + planes%slope*principal%alpha_increment) &
                  <= region_tolerance*planes%scale)
      principal%derivative = planes%elastic - matmul(flows, matmul(inverse, matmul(normals, planes%elastic)))
      do k = 4, 6   ! on an active cut-off sigma_a = t exactly (free of the round-off above)
         if (.not. any(active == k)) cycle
         principal%stress(k - 3) = planes%tension
         principal%derivative(k - 3, :) = 0.0_dp
      end do
      principal%region = region_of(active)
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

   !> REGION of a set of active planes.
   pure integer function region_of(active)
      integer, intent(in) :: active(:)
      if (any(active > 3)) then
         region_of = region_tension
      else if (size(active) == 1) then
         region_of = region_surface
      else
         region_of = region_edge
      end if
   end function region_of

   !> sigma = p 1 with p = c(alpha) cot(phi) (module header); needs phi > 0 and psi > 0.
   subroutine apex_return(self, planes, trial, principal, error)
      class(mohr_coulomb_t), intent(in) :: self
      type(planes_t), intent(in) :: planes
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
      modulus = planes%slope*cos(self%friction_angle)**2/(sin(self%friction_angle)*sin(self%dilation_angle))
      pressure = sum(trial)/3.0_dp
      volumetric = (pressure - planes%cohesion/tan(self%friction_angle))/(planes%bulk + modulus)
      if (.not. (volumetric >= 0.0_dp .and. planes%bulk + modulus > 0.0_dp)) then
         call fatal_error(error, self%name//': no return onto the yield surface'//trial_text)
         return
      end if
      principal%alpha_increment = volumetric*cos(self%friction_angle)/sin(self%dilation_angle)
      ! p* - K d eps_v, written as c(alpha) cot(phi): exactly constant for perfect plasticity
      principal%stress = (planes%cohesion + planes%slope*principal%alpha_increment)/tan(self%friction_angle)
      principal%derivative = planes%bulk*modulus/(planes%bulk + modulus)
      principal%region = region_apex
      principal%tied = .true.
   end subroutine apex_return

   !> Inverse of a 1 x 1, 2 x 2 or 3 x 3 matrix by its adjugate; `invertible` false where the
   !> determinant is not above 1e-12 of the product of the rows' norms (a dependent set of
   !> planes) or, for a single plane, not positive (softening too steep for a return).
   pure subroutine small_inverse(matrix, inverse, invertible)
      real(dp), intent(in) :: matrix(:, :)
      real(dp), intent(out) :: inverse(size(matrix, 1), size(matrix, 2))
      logical, intent(out) :: invertible
      real(dp) :: determinant, a(3, 3), adjugate(3, 3)
      integer :: n, i, j
      n = size(matrix, 1)
      a = 0.0_dp
      do i = n + 1, 3
         a(i, i) = 1.0_dp
      end do
      a(1:n, 1:n) = matrix
      do j = 1, 3
         do i = 1, 3
            adjugate(j, i) = a(mod(i, 3) + 1, mod(j, 3) + 1)*a(mod(i + 1, 3) + 1, mod(j + 1, 3) + 1) &
                             - a(mod(i, 3) + 1, mod(j + 1, 3) + 1)*a(mod(i + 1, 3) + 1, mod(j, 3) + 1)
         end do
      end do
      determinant = sum(a(1, :)*adjugate(:, 1))
      invertible = abs(determinant) > 1.0e-12_dp*product(norm2(a, dim=2)) .and. (n > 1 .or. determinant > 0.0_dp)
      inverse = 0.0_dp
      if (invertible) inverse = adjugate(1:n, 1:n)/determinant
   end subroutine small_inverse

   !> d sigma / d eps (Voigt, engineering strains) of the isotropic function (module header):
   !> column j is the stress increment of the unit strain increment j, built in the principal
   !> basis and rotated back.
   pure function spectral_tangent(principal, strains, directions) result(tangent)
      type(principal_return_t), intent(in) :: principal
      real(dp), intent(in) :: strains(3), directions(3, 3)
      real(dp) :: tangent(6, 6)
      real(dp) :: rotation(3, 3), increment(3, 3), response(3, 3)
      integer :: a, b, j
      do b = 1, 3
         do a = 1, 3
            if (a == b .or. principal%tied(a, b)) then
               rotation(a, b) = 0.0_dp
            else if (strains(a) /= strains(b)) then
               rotation(a, b) = (principal%stress(a) - principal%stress(b))/(strains(a) - strains(b))
            else
               rotation(a, b) = principal%derivative(a, a) - principal%derivative(a, b)
            end if
         end do
      end do
      do j = 1, 6
         increment = rotated_unit_strain(directions, j)
         response = rotation*increment
         do a = 1, 3
            response(a, a) = sum(principal%derivative(a, :)*[(increment(b, b), b=1, 3)])
         end do
         tangent(:, j) = stress_of_tensor(matmul(directions, matmul(response, transpose(directions))))
      end do
   end function spectral_tangent

   !> sum_a sigma_a n_a x n_a written as sigma_2 1 + (sigma_1 - sigma_2) n_1 x n_1 + (sigma_3 -
   !> sigma_2) n_3 x n_3: exactly isotropic at the apex, one direction only on an edge.
   pure function spectral_stress(values, directions) result(stress)
      real(dp), intent(in) :: values(3), directions(3, 3)
      real(dp) :: stress(6)
      real(dp) :: tensor(3, 3)
      integer :: i
      tensor = (values(1) - values(2))*spread(directions(:, 1), 2, 3)*spread(directions(:, 1), 1, 3) &
               + (values(3) - values(2))*spread(directions(:, 3), 2, 3)*spread(directions(:, 3), 1, 3)
      do i = 1, 3
         tensor(i, i) = tensor(i, i) + values(2)
      end do
      stress = stress_of_tensor(tensor)
   end function spectral_stress
end module frix_mohr_coulomb
