!> Checks shared by the material suites: matrix comparison scaled by the largest entry, and
!> the consistent tangent against a central finite difference of the stress.
module test_material_checks
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_material, only: material_t
   use frix_testing, only: check_close
   implicit none
   private

   public :: check_matrix_close, check_tangent_by_differences, material_response

contains

   !> Every entry within rel_tol * max|expected| (the scale of the block, so that entries
   !> which vanish analytically do not fail on round-off).
   subroutine check_matrix_close(error, actual, expected, rel_tol, message)
      type(error_t), allocatable, intent(out) :: error
      real(dp), intent(in) :: actual(:, :), expected(:, :)
      real(dp), intent(in) :: rel_tol
      character(len=*), intent(in) :: message
      real(dp) :: scale
      integer :: i, j
      scale = maxval(abs(expected))
      do j = 1, size(expected, 2)
         do i = 1, size(expected, 1)
            call check_close(error, actual(i, j), expected(i, j), rel_tol, rel_tol*scale, &
                             message//' ('//to_string(i)//','//to_string(j)//')')
            if (allocated(error)) return
         end do
      end do
   end subroutine check_matrix_close

   !> Stress and tangent of a material at `strain` from the history `state_old` (default: none,
   !> or zeros of the law's size) under small (default) or finite strain, from an initial stress
   !> if given (initial_stress_response); error if the law fails.
   subroutine material_response(error, material, strain, stress, tangent, finite, state_old, state_new, initial_stress)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), intent(in) :: material
      real(dp), intent(in) :: strain(6)
      real(dp), intent(out) :: stress(6), tangent(6, 6)
      logical, intent(in), optional :: finite
      real(dp), intent(in), optional :: state_old(:)
      real(dp), intent(out), optional :: state_new(:)
      real(dp), intent(in), optional :: initial_stress(6)
      real(dp) :: old(material%n_state()), new(material%n_state())
      type(error_t), allocatable :: law_error
      old = 0.0_dp
      if (present(state_old)) old = state_old
      new = 0.0_dp
      if (present(initial_stress)) then
         call material%initial_stress_response(strain, optional_true(finite), initial_stress, old, new, stress, tangent, &
                                               law_error)
      else
         call material%response(strain, optional_true(finite), old, new, stress, tangent, law_error)
      end if
      if (allocated(law_error)) call fatal_error(error, 'response failed: '//law_error%message)
      if (present(state_new)) state_new = new
   end subroutine material_response

   pure logical function optional_true(flag)
      logical, intent(in), optional :: flag
      optional_true = .false.
      if (present(flag)) optional_true = flag
   end function optional_true

   !> Column j of the tangent vs (S(E + h e_j) - S(E - h e_j)) / (2 h), h = 1e-7 max(1, |E_j|).
   !> Truncation error O(h^2) ~ 1e-14 relative; round-off ~ 1e-16 / h ~ 1e-9 relative.
   subroutine check_tangent_by_differences(error, material, strain, rel_tol, message, finite, state_old, initial_stress)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), intent(in) :: material
      real(dp), intent(in) :: strain(6)
      real(dp), intent(in) :: rel_tol
      character(len=*), intent(in) :: message
      logical, intent(in), optional :: finite      !! default: small strain
      real(dp), intent(in), optional :: state_old(:)  !! default: zero history
      real(dp), intent(in), optional :: initial_stress(6)  !! default: none
      real(dp) :: stress(6), tangent(6, 6), differences(6, 6)
      real(dp) :: stress_plus(6), stress_minus(6), unused(6, 6), perturbed(6), step
      real(dp) :: old(material%n_state())
      integer :: j
      old = 0.0_dp
      if (present(state_old)) old = state_old
      call material_response(error, material, strain, stress, tangent, finite, old, initial_stress=initial_stress)
      if (allocated(error)) return
      do j = 1, 6
         step = 1.0e-7_dp*max(1.0_dp, abs(strain(j)))
         perturbed = strain
         perturbed(j) = strain(j) + step
         call material_response(error, material, perturbed, stress_plus, unused, finite, old, initial_stress=initial_stress)
         if (allocated(error)) return
         perturbed(j) = strain(j) - step
         call material_response(error, material, perturbed, stress_minus, unused, finite, old, initial_stress=initial_stress)
         if (allocated(error)) return
         differences(:, j) = (stress_plus - stress_minus)/(2.0_dp*step)
      end do
      call check_matrix_close(error, tangent, differences, rel_tol, message)
   end subroutine check_tangent_by_differences
end module test_material_checks
