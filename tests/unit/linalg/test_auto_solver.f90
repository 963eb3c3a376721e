!> Tests of frix_auto_solver: CHOLMOD guarded by UMFPACK. A matrix that is not positive
!> definite makes it factorize with UMFPACK for the rest of the increment; begin_increment
!> returns to CHOLMOD; the statistics of both add up.
module test_auto_solver
   use frix_kinds, only: dp, i8
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_testing, only: unittest_t, new_unittest, check
   use frix_sparse_matrix, only: sparse_matrix_t
   use frix_auto_solver, only: auto_solver_t
   use test_linalg_fixtures, only: cube_connectivity, fill_random, spd_block
   implicit none
   private

   public :: collect_auto_solver

contains

   subroutine collect_auto_solver(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('auto_fallback_for_the_increment', test_fallback)]
   end subroutine collect_auto_solver

   !> The SPD cube matrix of test_direct_solvers (random element blocks), or with `indefinite`
   !> equation 40 replaced by a negative diagonal (-1), as a support applied with a wrong sign.
   subroutine cube_matrix(indefinite, state, connectivity, matrix)
      logical, intent(in) :: indefinite
      integer(i8), intent(inout) :: state
      integer, intent(in) :: connectivity(:, :)
      type(sparse_matrix_t), intent(inout) :: matrix
      real(dp) :: block(3*size(connectivity, 1), 3*size(connectivity, 1))
      logical, allocatable :: fixed(:)
      integer :: e
      call matrix%zero()
      do e = 1, size(connectivity, 2)
         call spd_block(state, block)
         call matrix%add_element(connectivity(:, e), block)
      end do
      allocate (fixed(matrix%n), source=.false.)
      fixed(40) = indefinite
      if (indefinite) call matrix%apply_dirichlet(fixed, -1.0_dp)
   end subroutine cube_matrix

   !> Factorize and solve A x = b for a random b; the relative residual must be ~ eps.
   subroutine factorize_and_solve(solver, matrix, state, error)
      type(auto_solver_t), intent(inout) :: solver
      type(sparse_matrix_t), intent(in) :: matrix
      integer(i8), intent(inout) :: state
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: b(:, :), x(:), r(:)
      call solver%factorize(matrix, error)
      if (allocated(error)) return
      allocate (b(matrix%n, 1), x(matrix%n), r(matrix%n))
      call fill_random(state, b)
      call solver%solve(matrix, b(:, 1), x, error)
      if (allocated(error)) return
      call matrix%multiply(x, r)
      call check(error, norm2(r - b(:, 1)) < 1.0e-12_dp*norm2(b(:, 1)), 'residual of '//solver%description())
   end subroutine factorize_and_solve

   subroutine test_fallback(error)
      type(error_t), allocatable, intent(out) :: error
      type(auto_solver_t) :: solver
      type(sparse_matrix_t) :: matrix
      integer, allocatable :: connectivity(:, :)
      integer :: n_nodes, factorizations
      integer(i8) :: state
      real(dp) :: analyse, factorize, solve
      call cube_connectivity(3, 3, 3, connectivity, n_nodes)
      call matrix%create_node_block_pattern(n_nodes, connectivity)
      state = 404
      ! increment 1: CHOLMOD meets the indefinite matrix, UMFPACK takes over
      call cube_matrix(.true., state, connectivity, matrix)
      call factorize_and_solve(solver, matrix, state, error)
      if (allocated(error)) return
      call check(error, solver%use_fallback .and. solver%primary%n_factorizations == 1 .and. &
                 solver%fallback%n_factorizations == 1, 'fallback after the indefinite matrix')
      if (allocated(error)) return
      ! still increment 1: an SPD matrix stays with UMFPACK
      call cube_matrix(.false., state, connectivity, matrix)
      call factorize_and_solve(solver, matrix, state, error)
      if (allocated(error)) return
      call check(error, solver%primary%n_factorizations == 1 .and. solver%fallback%n_factorizations == 2, &
                 'UMFPACK for the rest of the increment')
      if (allocated(error)) return
      ! increment 2: CHOLMOD again, with its symbolic analysis kept
      call solver%begin_increment()
      call cube_matrix(.false., state, connectivity, matrix)
      call factorize_and_solve(solver, matrix, state, error)
      if (allocated(error)) return
      call check(error, .not. solver%use_fallback .and. solver%primary%n_factorizations == 2 .and. &
                 solver%n_factorizations == 2 .and. solver%primary%n_analyses == 1 .and. &
                 solver%failed_equation == 0, 'CHOLMOD after begin_increment')
      if (allocated(error)) return
      analyse = 0.0_dp; factorize = 0.0_dp; solve = 0.0_dp; factorizations = 0
      call solver%add_totals(analyse, factorize, solve, factorizations)
      call check(error, factorizations == 4, 'totals: 2 CHOLMOD + 2 UMFPACK factorizations, got '// &
                 to_string(factorizations))
      if (allocated(error)) return
      call check(error, solver%name() == 'CHOLMOD' .and. &
                 index(solver%description(), 'UMFPACK in 2 factorizations') > 0, solver%description())
      call solver%release()
   end subroutine test_fallback
end module test_auto_solver
