!> Mohr-Coulomb plasticity with associated or non-associated flow and linear cohesion hardening
!> or softening; deck keyword MAT_3DMohrCoulomb, properties YOUNG NUE COHESION PHI PSI [HARD]
!> [DENS] (frix_frictional_plasticity: elasticity, cohesion, history; docs/materials.md).
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
!>
!> Return mapping in principal stresses (de Souza Neto, Peric & Owen, Computational Methods for
!> Plasticity, Wiley 2008, ch. 8; Clausen, Damkilde & Andersen, IJNME 66, 2006): the trial
!> stress sigma* = D eps_e* (D = lambda 1 x 1 + 2 G I in principal space) returns onto a set S of
!> active planes by the closed form of linear hardening,
!>   sigma = sigma* - D B^T dgamma,   J dgamma = f(sigma*),   J_ji = a_j . D b_i + 4 cos^2(phi) H,
!>   d alpha = 2 cos(phi) sum(dgamma),
!> trying S = {1} (the plane), then {1, 3} and {1, 2} (the edges); a return holds where
!> dgamma >= 0 and no plane is violated (f_1, f_2, f_3 <= 0: f_2 > 0 or f_3 > 0 after a plane
!> return is exactly the loss of the principal order). Else the apex sigma = p 1 with
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
module frix_mohr_coulomb
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_property_list, only: property_list_t
   use frix_material, only: material_t
   use frix_linear_elastic, only: hooke_tangent
   use frix_symmetric_tensor, only: tensor_of_strain, stress_of_tensor, rotated_unit_strain
   use frix_logarithmic_strain, only: symmetric_eigen3
   use frix_frictional_plasticity, only: frictional_plastic_t, return_outcome_t, read_frictional_properties, &
                                         region_elastic, region_surface, region_edge, region_apex
   implicit none
   private

   public :: mohr_coulomb_t, mohr_coulomb_from_properties

   !> A return is taken when its multipliers are >= -tolerance * their largest and no plane is
   !> violated by more than tolerance * the stress scale (round-off at region boundaries).
   real(dp), parameter :: region_tolerance = 1.0e-10_dp
   !> Trial excess over the surface, relative to the stress scale, below which a point is elastic.
   real(dp), parameter :: yield_tolerance = 1.0e-12_dp

   type, extends(frictional_plastic_t) :: mohr_coulomb_t
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
      real(dp) :: normals(3, 3)     !! a_i (row i), of phi
      real(dp) :: flows(3, 3)       !! b_i (row i), of psi
      real(dp) :: elastic(3, 3)     !! D in principal space
      real(dp) :: bulk, shear, cohesion, slope, scale
   end type planes_t

contains

   !> The law of deck properties YOUNG NUE DENS COHESION PHI PSI HARD.
   subroutine mohr_coulomb_from_properties(properties, material, error)
      type(property_list_t), intent(in) :: properties
      class(material_t), allocatable, intent(out) :: material
      type(error_t), allocatable, intent(out) :: error
      type(mohr_coulomb_t) :: law
      law%name = 'MAT_3DMohrCoulomb'
      call read_frictional_properties(properties, law, error, [character(len=8) ::], &
                                      'YOUNG, NUE, DENS, COHESION, PHI, PSI, HARD')
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
      if (dot_product(planes%normals(1, :), trial) - 2.0_dp*cohesion*cos(self%friction_angle) &
          <= yield_tolerance*planes%scale) then
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
      planes%normals = plane_vectors(sin(self%friction_angle))
      planes%flows = plane_vectors(sin(self%dilation_angle))
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

   !> The plane, then the edge sigma_1 = sigma_2, then the edge sigma_2 = sigma_3, then the apex.
   subroutine principal_return(self, planes, trial, principal, error)
      class(mohr_coulomb_t), intent(in) :: self
      type(planes_t), intent(in) :: planes
      real(dp), intent(in) :: trial(3)
      type(principal_return_t), intent(out) :: principal
      type(error_t), allocatable, intent(out) :: error
      logical :: valid
      call planes_return(self, planes, trial, [1], principal, valid)
      if (valid) return
      call planes_return(self, planes, trial, [1, 3], principal, valid)
      if (valid) return
      call planes_return(self, planes, trial, [1, 2], principal, valid)
      if (valid) return
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
      real(dp) :: inverse(size(active), size(active)), excess(size(active)), multipliers(size(active))
      real(dp) :: two_cos, cohesion
      logical :: invertible
      two_cos = 2.0_dp*cos(self%friction_angle)
      normals = planes%normals(active, :)
      flows = matmul(planes%elastic, transpose(planes%flows(active, :)))   ! columns D b_i
      jacobian = matmul(normals, flows) + two_cos**2*planes%slope
      call small_inverse(jacobian, inverse, invertible)
      valid = .false.
      if (.not. invertible) return
      excess = matmul(normals, trial) - two_cos*planes%cohesion
      multipliers = matmul(inverse, excess)
      principal%stress = trial - matmul(flows, multipliers)
      principal%alpha_increment = two_cos*sum(multipliers)
      cohesion = planes%cohesion + planes%slope*principal%alpha_increment
      valid = all(multipliers >= -region_tolerance*maxval(abs(multipliers))) .and. &
              all(matmul(planes%normals, principal%stress) - two_cos*cohesion <= region_tolerance*planes%scale)
      principal%derivative = planes%elastic - matmul(flows, matmul(inverse, matmul(normals, planes%elastic)))
      if (size(active) == 1) then
         principal%region = region_surface
      else
         principal%region = region_edge
         if (active(2) == 3) principal%tied(1, 2) = .true.
         if (active(2) == 2) principal%tied(2, 3) = .true.
         principal%tied = principal%tied .or. transpose(principal%tied)
      end if
   end subroutine planes_return

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

   !> Inverse of a 1 x 1 or 2 x 2 matrix; `invertible` false for a determinant <= 0 (a return
   !> with softening too steep for the plastic multipliers to be unique).
   pure subroutine small_inverse(matrix, inverse, invertible)
      real(dp), intent(in) :: matrix(:, :)
      real(dp), intent(out) :: inverse(size(matrix, 1), size(matrix, 2))
      logical, intent(out) :: invertible
      real(dp) :: determinant
      if (size(matrix, 1) == 1) then
         determinant = matrix(1, 1)
      else
         determinant = matrix(1, 1)*matrix(2, 2) - matrix(1, 2)*matrix(2, 1)
      end if
      invertible = determinant > 0.0_dp
      if (.not. invertible) then
         inverse = 0.0_dp
      else if (size(matrix, 1) == 1) then
         inverse = 1.0_dp/determinant
      else
         inverse = reshape([matrix(2, 2), -matrix(2, 1), -matrix(1, 2), matrix(1, 1)], [2, 2])/determinant
      end if
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
