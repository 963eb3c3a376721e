!> Large-problem tests that also print timings (timings are never asserted): node-block
!> pattern and scatter of one 24x24 block per element on the 50^3 HEX8 cube (132651 nodes;
!> asserted: no entry dropped), then CHOLMOD and UMFPACK on a 20^3 Laplacian brick with its
!> bottom face fixed (asserted: both solutions equal the known exact one, and each other).
module test_linalg_benchmark
   use frix_kinds, only: dp, i8
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_testing, only: unittest_t, new_unittest, check
   use frix_sparse_matrix, only: sparse_matrix_t
   use frix_linear_solver, only: linear_solver_t, wall_clock_seconds
   use frix_linear_solver_registry, only: create_linear_solver
   use test_linalg_fixtures, only: cube_connectivity, spd_block, laplacian_block, fill_random
   implicit none
   private

   public :: collect_linalg_benchmark

contains

   subroutine collect_linalg_benchmark(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('pattern_and_scatter_50_cube', benchmark_pattern), &
               new_unittest('solvers_20_cube_laplacian', benchmark_solvers)]
   end subroutine collect_linalg_benchmark

   subroutine benchmark_pattern(error)
      type(error_t), allocatable, intent(out) :: error
      type(sparse_matrix_t) :: matrix
      integer, allocatable :: connectivity(:, :)
      real(dp) :: block(24, 24), start, pattern_seconds, scatter_seconds
      integer :: n_nodes, e
      integer(i8) :: state
      call cube_connectivity(50, 50, 50, connectivity, n_nodes)
      start = wall_clock_seconds()
      call matrix%create_node_block_pattern(n_nodes, connectivity, error=error)
      if (allocated(error)) return
      pattern_seconds = wall_clock_seconds() - start
      state = 3
      call spd_block(state, block)
      start = wall_clock_seconds()
      do e = 1, size(connectivity, 2)
         call matrix%add_element(connectivity(:, e), block)
      end do
      scatter_seconds = wall_clock_seconds() - start
      write (*, '(a)') '    50^3 cube: '//to_string(n_nodes)//' nodes, nnz '//to_string(matrix%nnz())// &
         ', matrix '//to_string(real(matrix%memory_bytes(), dp)/1.0e6_dp)//' MB'
      write (*, '(a)') '    create_node_block_pattern '//to_string(pattern_seconds)//' s; scatter of '// &
         to_string(size(connectivity, 2))//' 24x24 blocks '//to_string(scatter_seconds)//' s = '// &
         to_string(1.0e6_dp*scatter_seconds/size(connectivity, 2))//' us per element'
      call check(error, matrix%dropped_entries == 0, 'no entry dropped')
   end subroutine benchmark_pattern

   !> CHOLMOD and UMFPACK on the 20^3 Laplacian brick (n = 27783) with its bottom face fixed
   !> (diagonal 7 on the fixed equations): b = A x_exact for a reproducible random x_exact in
   !> (-1, 1), so the exact solution is known. Asserted, in the max norm relative to
   !> |x_exact|: each solver's x within 1e-10 of x_exact, and the two solutions within 1e-10
   !> of each other (measured with Debian's SuiteSparse 5.12: 1e-14 for CHOLMOD, 4e-15 for
   !> UMFPACK; the tolerance leaves four orders of magnitude for other orderings and BLAS).
   !> The timings are printed, never asserted.
   subroutine benchmark_solvers(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: tolerance = 1.0e-10_dp   !! relative, max norm
      type(sparse_matrix_t) :: matrix
      class(linear_solver_t), allocatable :: solver
      integer, allocatable :: connectivity(:, :)
      logical, allocatable :: fixed(:)
      real(dp), allocatable :: b(:), x(:, :), x_exact(:, :)
      real(dp) :: block(24, 24), scale, deviation(2), agreement
      integer :: n_nodes, e, s
      integer(i8) :: state
      character(len=7), parameter :: keywords(2) = ['CHOLMOD', 'UMFPACK']
      call cube_connectivity(20, 20, 20, connectivity, n_nodes)
      call matrix%create_node_block_pattern(n_nodes, connectivity, error=error)
      if (allocated(error)) return
      call laplacian_block(8, block)
      do e = 1, size(connectivity, 2)
         call matrix%add_element(connectivity(:, e), block)
      end do
      allocate (fixed(matrix%n), source=.false.)
      fixed(1:3*21*21) = .true.   ! the 21 x 21 nodes of the face z = 0 come first
      call matrix%apply_dirichlet(fixed, 7.0_dp)
      allocate (x_exact(matrix%n, 1), b(matrix%n), x(matrix%n, 2))
      state = 11
      call fill_random(state, x_exact)
      call matrix%multiply(x_exact(:, 1), b)
      scale = maxval(abs(x_exact))
      do s = 1, 2
         call create_linear_solver(keywords(s), solver, error)
         if (allocated(error)) return
         call solver%factorize(matrix, error)
         if (allocated(error)) return
         call solver%solve(matrix, b, x(:, s), error)
         if (allocated(error)) return
         deviation(s) = maxval(abs(x(:, s) - x_exact(:, 1)))/scale
         write (*, '(a)') '    '//keywords(s)//' n = '//to_string(matrix%n)//': analyse '// &
            to_string(solver%analyse_seconds)//' s, factorize '//to_string(solver%factorize_seconds)// &
            ' s, solve '//to_string(solver%solve_seconds)//' s, factor entries '//to_string(solver%factor_entries)// &
            ', peak '//to_string(real(solver%peak_memory_bytes, dp)/1.0e6_dp)//' MB, |x - x_exact|/|x_exact| '// &
            to_string(deviation(s))
         call solver%release()
         call check(error, deviation(s) <= tolerance, keywords(s)//' solution differs from the exact one by '// &
                    to_string(deviation(s))//' (relative, max norm; tolerance '//to_string(tolerance)//')')
         if (allocated(error)) return
      end do
      agreement = maxval(abs(x(:, 1) - x(:, 2)))/scale
      call check(error, agreement <= tolerance, 'CHOLMOD and UMFPACK solutions differ by '//to_string(agreement)// &
                 ' (relative, max norm; tolerance '//to_string(tolerance)//')')
   end subroutine benchmark_solvers
end module test_linalg_benchmark
