!> Small dense linear algebra of the element kernels: the solution of the small systems of the
!> EAS condensation (n <= 30 unknowns); 3 x 3 determinants and inverses are in core's
!> frix_vector_algebra.
module frix_dense_algebra
   use frix_kinds, only: dp
   implicit none
   private

   public :: solve_in_place

contains

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
