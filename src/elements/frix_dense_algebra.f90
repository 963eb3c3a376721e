!> Small dense linear algebra of the element kernels: 3 x 3 determinant and inverse, and the
!> solution of the small systems of the EAS condensation (n <= 30 unknowns).
module frix_dense_algebra
   use frix_kinds, only: dp
   implicit none
   private

   public :: determinant, invert3, solve_in_place

contains

   !> det of a 3 x 3 matrix by cofactors of the first row.
   pure function determinant(matrix) result(det)
      real(dp), intent(in) :: matrix(3, 3)
      real(dp) :: det
      det = matrix(1, 1)*(matrix(2, 2)*matrix(3, 3) - matrix(2, 3)*matrix(3, 2)) &
            - matrix(1, 2)*(matrix(2, 1)*matrix(3, 3) - matrix(2, 3)*matrix(3, 1)) &
            + matrix(1, 3)*(matrix(2, 1)*matrix(3, 2) - matrix(2, 2)*matrix(3, 1))
   end function determinant

   !> Inverse by cofactors; `inverse` is left undefined when det = 0.
   pure subroutine invert3(matrix, inverse, det)
      real(dp), intent(in) :: matrix(3, 3)
      real(dp), intent(out) :: inverse(3, 3), det
      inverse(1, 1) = matrix(2, 2)*matrix(3, 3) - matrix(2, 3)*matrix(3, 2)
      inverse(1, 2) = matrix(1, 3)*matrix(3, 2) - matrix(1, 2)*matrix(3, 3)
      inverse(1, 3) = matrix(1, 2)*matrix(2, 3) - matrix(1, 3)*matrix(2, 2)
      inverse(2, 1) = matrix(2, 3)*matrix(3, 1) - matrix(2, 1)*matrix(3, 3)
      inverse(2, 2) = matrix(1, 1)*matrix(3, 3) - matrix(1, 3)*matrix(3, 1)
      inverse(2, 3) = matrix(1, 3)*matrix(2, 1) - matrix(1, 1)*matrix(2, 3)
      inverse(3, 1) = matrix(2, 1)*matrix(3, 2) - matrix(2, 2)*matrix(3, 1)
      inverse(3, 2) = matrix(1, 2)*matrix(3, 1) - matrix(1, 1)*matrix(3, 2)
      inverse(3, 3) = matrix(1, 1)*matrix(2, 2) - matrix(1, 2)*matrix(2, 1)
      det = matrix(1, 1)*inverse(1, 1) + matrix(1, 2)*inverse(2, 1) + matrix(1, 3)*inverse(3, 1)
      if (det /= 0.0_dp) inverse = inverse/det
   end subroutine invert3

   !> Solve A X = B in place (B <- X) by Gaussian elimination with partial pivoting; A is
   !> destroyed. `singular` when a pivot is below 1e-14 max|A| (n <= 30, so no LAPACK needed).
   pure subroutine solve_in_place(matrix, rhs, singular)
      real(dp), intent(inout) :: matrix(:, :)
      real(dp), intent(inout) :: rhs(:, :)
      logical, intent(out) :: singular
      real(dp) :: threshold, factor, swap_row(size(matrix, 2)), swap_rhs(size(rhs, 2))
      integer :: n, k, pivot, i
      n = size(matrix, 1)
      threshold = 1.0e-14_dp*maxval(abs(matrix))
      singular = .true.
      if (.not. (threshold > 0.0_dp)) return
      do k = 1, n
         pivot = k - 1 + maxloc(abs(matrix(k:n, k)), dim=1)
         if (.not. (abs(matrix(pivot, k)) > threshold)) return
         if (pivot /= k) then
            swap_row = matrix(k, :)
            matrix(k, :) = matrix(pivot, :)
            matrix(pivot, :) = swap_row
            swap_rhs = rhs(k, :)
            rhs(k, :) = rhs(pivot, :)
            rhs(pivot, :) = swap_rhs
         end if
         do i = k + 1, n
            factor = matrix(i, k)/matrix(k, k)
            matrix(i, k + 1:n) = matrix(i, k + 1:n) - factor*matrix(k, k + 1:n)
            rhs(i, :) = rhs(i, :) - factor*rhs(k, :)
         end do
      end do
      do k = n, 1, -1
         rhs(k, :) = (rhs(k, :) - matmul(matrix(k, k + 1:n), rhs(k + 1:n, :)))/matrix(k, k)
      end do
      singular = .false.
   end subroutine solve_in_place
end module frix_dense_algebra
