!> Shared check of the master-slave elimination (frix_constraint_equations) against dense
!> products: T^T K T, T^T v and T u with the transformation T written out densely by the test.
module elimination_checks
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: check, check_close
   use frix_sparse_matrix, only: sparse_matrix_t
   use frix_constraint_equations, only: constraint_equations_t
   implicit none
   private

   public :: check_elimination

contains

   !> `matrix` holds K (= `dense` on the full pattern) on entry and is condensed here; the
   !> condensed matrix must equal T^T K T to `matrix_tolerance`, condense_vector give T^T v and
   !> expand_vector T u (u zero on the dependent equations) to `vector_tolerance` (absolute).
   subroutine check_elimination(constraints, dependent, matrix, dense, t, matrix_tolerance, vector_tolerance, error)
      type(constraint_equations_t), intent(in) :: constraints
      logical, intent(in) :: dependent(:)
      type(sparse_matrix_t), intent(inout) :: matrix
      real(dp), intent(in) :: dense(:, :), t(:, :)
      real(dp), intent(in) :: matrix_tolerance, vector_tolerance
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: failure
      real(dp) :: expected(size(t, 1), size(t, 1)), v(size(t, 1)), u(size(t, 1)), got(size(t, 1))
      integer :: i, j, n
      n = size(t, 1)
      expected = matmul(transpose(t), matmul(dense, t))
      call constraints%condense_matrix(dependent, matrix, failure)
      call check(error, .not. allocated(failure), 'every pair in the pattern')
      if (allocated(error)) return
      do j = 1, n
         do i = 1, n
            call check_close(error, matrix%entry(i, j), expected(i, j), 0.0_dp, matrix_tolerance, 'T^T K T')
            if (allocated(error)) return
         end do
      end do
      v = [(cos(real(i, dp)), i=1, n)]
      got = v
      call constraints%condense_vector(dependent, got)
      do i = 1, n
         call check_close(error, got(i), dot_product(t(:, i), v), 0.0_dp, vector_tolerance, 'T^T v')
         if (allocated(error)) return
      end do
      u = v
      where (dependent) u = 0.0_dp
      got = u
      call constraints%expand_vector(dependent, got)
      do i = 1, n
         call check_close(error, got(i), dot_product(t(i, :), u), 0.0_dp, vector_tolerance, 'T u')
         if (allocated(error)) return
      end do
   end subroutine check_elimination
end module elimination_checks
