!> Loading paths and stress measures shared by the tests of the frictional laws (Mohr-Coulomb,
!> Drucker-Prager): mixed stress/strain control of one material point (triaxial and shear
!> tests), trial strains of given principal stresses in rotated axes, sorted principal stresses
!> and the Mohr-Coulomb yield function. Soil of the tests: E = 20000, nu = 0.3 (kPa), tension
!> positive.
module test_soil_paths
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_testing, only: check
   use frix_material, only: material_t
   use frix_property_list, only: property_list_t, new_property_list
   use frix_material_registry, only: create_material
   use frix_linear_elastic, only: hooke_tangent
   use frix_symmetric_tensor, only: tensor_of_stress, strain_of_tensor
   use frix_logarithmic_strain, only: symmetric_eigen3
   use frix_frictional_plasticity, only: state_plastic_strain
   use test_material_checks, only: material_response
   implicit none
   private

   public :: make_soil, mixed_control, trial_strain, principal_stresses, mohr_coulomb_excess, rotation
   public :: young, poisson, n_state, confining, consolidate, triaxial

   real(dp), parameter :: young = 20000.0_dp, poisson = 0.3_dp
   integer, parameter :: n_state = 10
   real(dp), parameter :: confining = -100.0_dp   !! cell pressure of the triaxial and shear paths

contains

   !> The law `keyword` with E, nu above, cohesion, phi, psi (degrees), HARD and, if given, MATCH.
   subroutine make_soil(material, keyword, cohesion, phi, psi, hard, match)
      class(material_t), allocatable, intent(out) :: material
      character(len=*), intent(in) :: keyword
      real(dp), intent(in) :: cohesion, phi, psi, hard
      integer, intent(in), optional :: match
      type(error_t), allocatable :: error
      character(len=8), parameter :: names(7) = [character(len=8) :: 'YOUNG', 'NUE', 'COHESION', 'PHI', 'PSI', &
                                                 'HARD', 'MATCH']
      real(dp) :: values(7)
      values = [young, poisson, cohesion, phi, psi, hard, 1.0_dp]
      if (present(match)) then
         values(7) = real(match, dp)
         call create_material(keyword, names, values, material, error)
      else
         call create_material(keyword, names(1:6), values(1:6), material, error)
      end if
      if (allocated(error)) then
         write (*, '(a)') error%message
         error stop 'test_soil_paths: invalid soil'
      end if
   end subroutine make_soil

   !> Isotropic compression to sigma = `confining` 1 from the virgin state.
   subroutine consolidate(error, material, strain, state)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), intent(in) :: material
      real(dp), intent(out) :: strain(6), state(n_state)
      real(dp) :: stress(6)
      strain = 0.0_dp
      state = 0.0_dp
      call mixed_control(error, material, strain, [1, 2, 3], [confining, confining, confining], state, stress)
   end subroutine consolidate

   !> Axial (z) strain steps of `step` at lateral stresses `confining` until `n_steps`; the
   !> stress and history at the end, and the plastic strain increment of the last step.
   subroutine triaxial(error, material, step, n_steps, stress, state, plastic_step)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), intent(in) :: material
      real(dp), intent(in) :: step
      integer, intent(in) :: n_steps
      real(dp), intent(out) :: stress(6), state(n_state), plastic_step(6)
      real(dp) :: strain(6), before(6)
      integer :: k
      call consolidate(error, material, strain, state)
      if (allocated(error)) return
      do k = 1, n_steps
         before = state(state_plastic_strain:state_plastic_strain + 5)
         strain(3) = strain(3) + step
         call lateral_control(error, material, strain, state, stress)
         if (allocated(error)) return
      end do
      plastic_step = state(state_plastic_strain:state_plastic_strain + 5) - before
   end subroutine triaxial

   !> The lateral strains eps_xx = eps_yy (one unknown: on an edge of the surface the tangent has
   !> no stiffness against eps_xx - eps_yy) so that sigma_xx = `confining`, by Newton.
   subroutine lateral_control(error, material, strain, state, stress)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), intent(in) :: material
      real(dp), intent(inout) :: strain(6), state(n_state)
      real(dp), intent(out) :: stress(6)
      real(dp) :: tangent(6, 6), new(n_state)
      integer :: iteration
      do iteration = 1, 60
         call material_response(error, material, strain, stress, tangent, .false., state, new)
         if (allocated(error)) return
         if (abs(stress(1) - confining) <= 1.0e-11_dp*maxval(abs(stress))) exit
         strain(1:2) = strain(1:2) - (stress(1) - confining)/(tangent(1, 1) + tangent(1, 2))
      end do
      call check(error, abs(stress(1) - confining) <= 1.0e-11_dp*maxval(abs(stress)) .and. &
                 abs(stress(2) - confining) <= 1.0e-11_dp*maxval(abs(stress)), 'lateral control did not converge')
      state = new
   end subroutine lateral_control

   !> Mixed control from the committed history `state` (and the initial stress, if given): the strain components `free` are solved
   !> (Newton with the law's tangent) so that stress(free) = target, the others are as given in
   !> `strain`. On return `strain` and `state` are the converged strain and its history.
   subroutine mixed_control(error, material, strain, free, target, state, stress, initial_stress)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), intent(in) :: material
      real(dp), intent(inout) :: strain(6)
      integer, intent(in) :: free(:)
      real(dp), intent(in) :: target(:)
      real(dp), intent(inout) :: state(:)
      real(dp), intent(out) :: stress(6)
      real(dp), intent(in), optional :: initial_stress(6)   !! sigma0 of initial_stress_response
      real(dp) :: tangent(6, 6), new(size(state)), residual(size(free))
      integer :: iteration
      do iteration = 1, 60
         call material_response(error, material, strain, stress, tangent, .false., state, new, initial_stress)
         if (allocated(error)) return
         residual = stress(free) - target
         if (maxval(abs(residual)) <= 1.0e-11_dp*maxval(abs(stress))) exit
         strain(free) = strain(free) - solve(tangent(free, free), residual)
      end do
      call check(error, maxval(abs(residual)) <= 1.0e-11_dp*maxval(abs(stress)), &
                 'mixed control did not converge: residual '//to_string(maxval(abs(residual))))
      state = new
   end subroutine mixed_control

   !> x with a x = b, Gaussian elimination with partial pivoting (n <= 6).
   function solve(a, b) result(x)
      real(dp), intent(in) :: a(:, :), b(:)
      real(dp) :: x(size(b))
      real(dp) :: m(size(b), size(b) + 1), row(size(b) + 1)
      integer :: n, k, p, i
      n = size(b)
      m(:, 1:n) = a
      m(:, n + 1) = b
      do k = 1, n
         p = k - 1 + maxloc(abs(m(k:n, k)), dim=1)
         row = m(k, :)
         m(k, :) = m(p, :)
         m(p, :) = row
         do i = k + 1, n
            m(i, :) = m(i, :) - m(i, k)/m(k, k)*m(k, :)
         end do
      end do
      do k = n, 1, -1
         x(k) = (m(k, n + 1) - sum(m(k, k + 1:n)*x(k + 1:n)))/m(k, k)
      end do
   end function solve

   !> The elastic strain (Voigt, engineering shears) whose stress has the principal values
   !> `principal` along the columns of `axes`.
   pure function trial_strain(principal, axes) result(strain)
      real(dp), intent(in) :: principal(3), axes(3, 3)
      real(dp) :: strain(6)
      real(dp) :: stress(3, 3), compliance(3)
      integer :: a
      compliance = ((1.0_dp + poisson)*principal - poisson*sum(principal))/young
      stress = 0.0_dp
      do a = 1, 3
         stress(a, a) = compliance(a)
      end do
      strain = strain_of_tensor(matmul(axes, matmul(stress, transpose(axes))))
   end function trial_strain

   !> The rotation by `angle` (radians) about the axis `axis` (Rodrigues' formula).
   pure function rotation(axis, angle) result(r)
      real(dp), intent(in) :: axis(3), angle
      real(dp) :: r(3, 3)
      real(dp) :: k(3), cross(3, 3)
      integer :: i
      k = axis/norm2(axis)
      cross = reshape([0.0_dp, k(3), -k(2), -k(3), 0.0_dp, k(1), k(2), -k(1), 0.0_dp], [3, 3])
      r = sin(angle)*cross + (1.0_dp - cos(angle))*matmul(cross, cross)
      do i = 1, 3
         r(i, i) = r(i, i) + 1.0_dp
      end do
   end function rotation

   !> Principal values of a Voigt stress, descending.
   function principal_stresses(stress) result(values)
      real(dp), intent(in) :: stress(6)
      real(dp) :: values(3)
      real(dp) :: unsorted(3), vectors(3, 3)
      call symmetric_eigen3(tensor_of_stress(stress), unsorted, vectors)
      values = [maxval(unsorted), sum(unsorted) - maxval(unsorted) - minval(unsorted), minval(unsorted)]
   end function principal_stresses

   !> max over the planes of the Mohr-Coulomb function (sigma_i - sigma_j) + (sigma_i + sigma_j)
   !> sin(phi) - 2 c cos(phi), i /= j, of the principal values of `stress` (phi in degrees).
   function mohr_coulomb_excess(stress, cohesion, phi) result(excess)
      real(dp), intent(in) :: stress(6), cohesion, phi
      real(dp) :: excess
      real(dp) :: s(3), sine
      s = principal_stresses(stress)
      sine = sin(phi*acos(-1.0_dp)/180.0_dp)
      excess = (s(1) - s(3)) + (s(1) + s(3))*sine - 2.0_dp*cohesion*sqrt(1.0_dp - sine**2)
   end function mohr_coulomb_excess
end module test_soil_paths
