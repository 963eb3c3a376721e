!> Tests of the direct solvers behind linear_solver_t (CHOLMOD, UMFPACK) and the registry.
!> Every solve is checked by its residual ||A x - b|| / ||b|| computed with
!> sparse_matrix_t%multiply (checked against a dense product in test_sparse_matrix).
module test_direct_solvers
   use frix_kinds, only: dp, i8
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_testing, only: unittest_t, new_unittest, check, check_message_contains
   use frix_sparse_matrix, only: sparse_matrix_t
   use frix_linear_solver, only: linear_solver_t
   use frix_linear_solver_registry, only: create_linear_solver
   use frix_metis_ordering, only: metis_dof_permutation
   use frix_cholmod_solver, only: cholmod_failure
   use frix_umfpack_solver, only: umfpack_solver_t, umfpack_strategy_unsymmetric, umfpack_ordering_amd
   use frix_linear_solver, only: solver_too_large, solver_out_of_memory
   use test_linalg_fixtures, only: cube_connectivity, fill_random, spd_block, unsymmetric_block, laplacian_block
   implicit none
   private

   public :: collect_direct_solvers

   !> Double precision residual target of the brief: backward stable direct solvers reach
   !> ~ n_nonzeros_per_row * eps ~ 1e-14 on these well-conditioned systems.
   real(dp), parameter :: residual_tolerance = 1.0e-12_dp

   integer, parameter :: spd = 1, unsymmetric = 2, laplacian = 3

contains

   subroutine collect_direct_solvers(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [ &
              new_unittest('cholmod_spd_refactorize_reanalyse', test_cholmod_spd), &
              new_unittest('umfpack_unsymmetric_refactorize_reanalyse', test_umfpack_unsymmetric), &
              new_unittest('umfpack_controls_reach_umfpack', test_umfpack_controls), &
              new_unittest('laplacian_with_dirichlet_both_solvers', test_laplacian_dirichlet), &
              new_unittest('metis_permutation_node_blocked', test_metis_permutation), &
              new_unittest('cholmod_metis_ordering_reduces_fill', test_cholmod_fill), &
              new_unittest('cholmod_zero_block_singular', test_cholmod_zero_block), &
              new_unittest('umfpack_zero_block_singular', test_umfpack_zero_block), &
              new_unittest('cholmod_indefinite_then_recovers', test_cholmod_indefinite), &
              new_unittest('floating_point_singular_neumann', test_neumann_singular), &
              new_unittest('near_singular_pivot_ratio', test_pivot_ratio), &
              new_unittest('solve_without_factorize', test_solve_without_factorize), &
              new_unittest('cholmod_size_failures', test_cholmod_size_failures), &
              new_unittest('registry', test_registry) &
              ]
   end subroutine collect_direct_solvers

   !> Assemble blocks of the given kind over every element (fresh zero values first).
   subroutine assemble(matrix, connectivity, kind, state)
      type(sparse_matrix_t), intent(inout) :: matrix
      integer, intent(in) :: connectivity(:, :)
      integer, intent(in) :: kind
      integer(i8), intent(inout) :: state
      real(dp) :: block(3*size(connectivity, 1), 3*size(connectivity, 1))
      integer :: e
      call matrix%zero()
      if (kind == laplacian) call laplacian_block(size(connectivity, 1), block)
      do e = 1, size(connectivity, 2)
         if (kind == spd) call spd_block(state, block)
         if (kind == unsymmetric) call unsymmetric_block(state, block)
         call matrix%add_element(connectivity(:, e), block)
      end do
   end subroutine assemble

   !> Solve A x = b for a random b and check ||A x - b|| / ||b|| < residual_tolerance.
   subroutine solve_and_check(solver, matrix, state, error)
      class(linear_solver_t), intent(inout) :: solver
      type(sparse_matrix_t), intent(in) :: matrix
      integer(i8), intent(inout) :: state
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: b(:, :), x(:), r(:)
      real(dp) :: residual
      allocate (b(matrix%n, 1), x(matrix%n), r(matrix%n))
      call fill_random(state, b)
      call solver%solve(matrix, b(:, 1), x, error)
      if (allocated(error)) return
      call matrix%multiply(x, r)
      residual = norm2(r - b(:, 1))/norm2(b(:, 1))
      call check(error, residual < residual_tolerance, solver%name()//' relative residual '// &
                 to_string(residual)//' >= '//to_string(residual_tolerance))
   end subroutine solve_and_check

   !> The node-block matrix of a 4 x 3 x 3 brick (values of `kind` from the random `state`)
   !> factorized by `solver` and a random system solved and checked (solve_and_check).
   subroutine solve_small_cube(solver, kind, matrix, connectivity, n_nodes, state, error)
      class(linear_solver_t), intent(inout) :: solver
      integer, intent(in) :: kind
      type(sparse_matrix_t), intent(out) :: matrix
      integer, allocatable, intent(out) :: connectivity(:, :)
      integer, intent(out) :: n_nodes
      integer(i8), intent(inout) :: state
      type(error_t), allocatable, intent(out) :: error
      call cube_connectivity(4, 3, 3, connectivity, n_nodes)
      call matrix%create_node_block_pattern(n_nodes, connectivity)
      call assemble(matrix, connectivity, kind, state)
      call solver%factorize(matrix, error)
      if (allocated(error)) return
      call solve_and_check(solver, matrix, state, error)
   end subroutine solve_small_cube

   !> Factorize, solve; new values with the same pattern must not re-analyse; a rebuilt
   !> pattern (new pattern_id) must.
   subroutine check_refactorize_reanalyse(keyword, kind, error)
      character(len=*), intent(in) :: keyword
      integer, intent(in) :: kind
      type(error_t), allocatable, intent(out) :: error
      class(linear_solver_t), allocatable :: solver
      type(sparse_matrix_t) :: matrix
      integer, allocatable :: connectivity(:, :)
      integer :: n_nodes
      integer(i8) :: state
      call create_linear_solver(keyword, solver, error)
      if (allocated(error)) return
      state = 31337
      call solve_small_cube(solver, kind, matrix, connectivity, n_nodes, state, error)
      if (allocated(error)) return
      call assemble(matrix, connectivity, kind, state)
      call solver%factorize(matrix, error)
      if (allocated(error)) return
      call check(error, solver%n_analyses == 1 .and. solver%n_factorizations == 2, &
                 keyword//': new values, same pattern: 1 analysis, 2 factorizations; got '// &
                 to_string(solver%n_analyses)//', '//to_string(solver%n_factorizations))
      if (allocated(error)) return
      call solve_and_check(solver, matrix, state, error)
      if (allocated(error)) return
      call matrix%create_node_block_pattern(n_nodes, connectivity)
      call assemble(matrix, connectivity, kind, state)
      call solver%factorize(matrix, error)
      if (allocated(error)) return
      call check(error, solver%n_analyses == 2, keyword//': rebuilt pattern analysed again')
      if (allocated(error)) return
      call solve_and_check(solver, matrix, state, error)
      if (allocated(error)) return
      call check(error, solver%factor_entries > 0 .and. solver%peak_memory_bytes > 0, &
                 keyword//': factor size and peak memory reported')
      if (allocated(error)) return
      call check(error, solver%factorize_seconds >= solver%last_factorize_seconds .and. &
                 solver%last_factorize_seconds >= 0.0_dp .and. solver%n_solves == 3, keyword//': timings and counters')
      call solver%release()
   end subroutine check_refactorize_reanalyse

   subroutine test_cholmod_spd(error)
      type(error_t), allocatable, intent(out) :: error
      call check_refactorize_reanalyse('CHOLMOD', spd, error)
   end subroutine test_cholmod_spd

   subroutine test_umfpack_unsymmetric(error)
      type(error_t), allocatable, intent(out) :: error
      type(sparse_matrix_t) :: matrix
      integer, allocatable :: connectivity(:, :)
      integer :: n_nodes
      integer(i8) :: state
      ! the fixture is really unsymmetric (otherwise this test would not test LU)
      call cube_connectivity(1, 1, 1, connectivity, n_nodes)
      call matrix%create_node_block_pattern(n_nodes, connectivity)
      state = 5
      call assemble(matrix, connectivity, unsymmetric, state)
      call check(error, .not. matrix%is_symmetric(1.0e-3_dp), 'unsymmetric fixture')
      if (allocated(error)) return
      call check_refactorize_reanalyse('UMFPACK', unsymmetric, error)
   end subroutine test_umfpack_unsymmetric

   !> The strategy, ordering and refinement steps of umfpack_solver_t are the ones UMFPACK
   !> uses (Info: UMFPACK_STRATEGY_USED = 18, UMFPACK_ORDERING_USED = 19, UMFPACK_IR_TAKEN =
   !> 80; C index + 1 here). Defaults: the automatic strategy, which chooses the symmetric one
   !> (3) for the structurally symmetric node-block pattern, METIS (3), no refinement (with
   !> UMFPACK's default IRSTEP 2 this system takes 1 refinement step, measured: the check fails
   !> if the setting does not reach UMFPACK).
   subroutine test_umfpack_controls(error)
      type(error_t), allocatable, intent(out) :: error
      type(umfpack_solver_t) :: solver
      type(sparse_matrix_t) :: matrix
      integer, allocatable :: connectivity(:, :)
      integer :: n_nodes
      integer(i8) :: state
      state = 77
      call solve_small_cube(solver, unsymmetric, matrix, connectivity, n_nodes, state, error)
      if (allocated(error)) return
      call check(error, nint(solver%info(19)) == 3 .and. nint(solver%info(20)) == 3 .and. &
                 nint(solver%info(81)) == 0, 'defaults: symmetric strategy, METIS, no refinement; Info '// &
                 to_string(solver%info(19))//' '//to_string(solver%info(20))//' '//to_string(solver%info(81)))
      if (allocated(error)) return
      call solver%release()
      solver%strategy = umfpack_strategy_unsymmetric
      solver%ordering = umfpack_ordering_amd
      call solver%factorize(matrix, error)
      if (allocated(error)) return
      call solve_and_check(solver, matrix, state, error)
      if (allocated(error)) return
      call check(error, nint(solver%info(19)) == 1 .and. nint(solver%info(20)) == 1, &
                 'unsymmetric strategy and AMD (COLAMD) as set; Info '//to_string(solver%info(19))//' '// &
                 to_string(solver%info(20)))
   end subroutine test_umfpack_controls

   !> Node-blocked Laplacian of a 6 x 6 x 6 brick, bottom face (z = 0) fixed through
   !> apply_dirichlet with the mean absolute diagonal: SPD, solved by both solvers.
   subroutine test_laplacian_dirichlet(error)
      type(error_t), allocatable, intent(out) :: error
      type(sparse_matrix_t) :: matrix
      class(linear_solver_t), allocatable :: solver
      integer, allocatable :: connectivity(:, :)
      logical, allocatable :: fixed(:)
      real(dp), allocatable :: diagonal(:)
      integer :: n_nodes, s
      integer(i8) :: state
      character(len=7), parameter :: keywords(2) = ['CHOLMOD', 'UMFPACK']
      call cube_connectivity(6, 6, 6, connectivity, n_nodes)
      call matrix%create_node_block_pattern(n_nodes, connectivity)
      state = 2024
      call assemble(matrix, connectivity, laplacian, state)
      allocate (fixed(matrix%n), diagonal(matrix%n))
      fixed = .false.
      fixed(1:3*49) = .true.     ! nodes 1..49 form the z = 0 face of the 7 x 7 x 7 grid
      call matrix%get_diagonal(diagonal)
      call matrix%apply_dirichlet(fixed, sum(abs(diagonal))/matrix%n)
      do s = 1, 2
         call create_linear_solver(keywords(s), solver, error)
         if (allocated(error)) return
         call solver%factorize(matrix, error)
         if (allocated(error)) return
         call solve_and_check(solver, matrix, state, error)
         if (allocated(error)) return
      end do
   end subroutine test_laplacian_dirichlet

   !> The DOF permutation is a permutation of 0..n-1 and keeps node blocks together
   !> (positions 3m, 3m+1, 3m+2 hold equations 3c, 3c+1, 3c+2 of one node c).
   subroutine test_metis_permutation(error)
      type(error_t), allocatable, intent(out) :: error
      type(sparse_matrix_t) :: matrix
      integer, allocatable :: connectivity(:, :)
      integer(i8), allocatable :: permutation(:)
      logical, allocatable :: seen(:)
      integer :: n_nodes, m
      call cube_connectivity(5, 4, 3, connectivity, n_nodes)
      call matrix%create_node_block_pattern(n_nodes, connectivity)
      call metis_dof_permutation(matrix, permutation, error)
      if (allocated(error)) return
      call check(error, size(permutation) == matrix%n, 'size n')
      if (allocated(error)) return
      allocate (seen(0:matrix%n - 1), source=.false.)
      call check(error, all(permutation >= 0 .and. permutation < matrix%n), 'entries in 0..n-1')
      if (allocated(error)) return
      seen(permutation) = .true.
      call check(error, all(seen), 'every equation appears once')
      if (allocated(error)) return
      do m = 0, n_nodes - 1
         call check(error, mod(permutation(3*m + 1), 3_i8) == 0 .and. permutation(3*m + 2) == permutation(3*m + 1) + 1 &
                    .and. permutation(3*m + 3) == permutation(3*m + 1) + 2, 'node blocks kept together')
         if (allocated(error)) return
      end do
   end subroutine test_metis_permutation

   !> Nested dissection must beat the natural (banded) order on a 10 x 10 x 10 brick: with
   !> natural numbering the Cholesky factor fills the envelope, about n * 3*(11*11 + 11 + 1)
   !> = 3993 * 399 = 1.59e6 entries. Measured nnz(L) (CHOLMOD Common->lnz, this machine):
   !> METIS perm 0.90e6, natural order 1.46e6, METIS iperm (the wrong convention) 3.24e6.
   !> The bound 0.75 * envelope separates the right convention from both others.
   subroutine test_cholmod_fill(error)
      type(error_t), allocatable, intent(out) :: error
      type(sparse_matrix_t) :: matrix
      class(linear_solver_t), allocatable :: solver
      integer, allocatable :: connectivity(:, :)
      integer :: n_nodes
      integer(i8) :: state
      real(dp) :: envelope
      call cube_connectivity(10, 10, 10, connectivity, n_nodes)
      call matrix%create_node_block_pattern(n_nodes, connectivity)
      state = 7
      call assemble(matrix, connectivity, spd, state)
      call create_linear_solver('cholmod', solver, error)
      if (allocated(error)) return
      call solver%factorize(matrix, error)
      if (allocated(error)) return
      envelope = real(matrix%n, dp)*3.0_dp*(11*11 + 11 + 1)
      call check(error, real(solver%factor_entries, dp) < 0.75_dp*envelope, 'nnz(L) = '// &
                 to_string(solver%factor_entries)//' not below 0.75 times the banded envelope '//to_string(envelope))
   end subroutine test_cholmod_fill

   !> Mesh plus one node no element touches: its 3x3 diagonal block stays zero.
   subroutine check_zero_block(keyword, error)
      character(len=*), intent(in) :: keyword
      type(error_t), allocatable, intent(out) :: error
      class(linear_solver_t), allocatable :: solver
      type(sparse_matrix_t) :: matrix
      type(error_t), allocatable :: solver_error
      integer, allocatable :: connectivity(:, :)
      integer :: n_nodes
      integer(i8) :: state
      call cube_connectivity(2, 2, 2, connectivity, n_nodes)
      call matrix%create_node_block_pattern(n_nodes + 1, connectivity)
      state = 11
      call assemble(matrix, connectivity, spd, state)
      call create_linear_solver(keyword, solver, error)
      if (allocated(error)) return
      call solver%factorize(matrix, solver_error)
      call check_message_contains(error, solver_error, 'node '//to_string(n_nodes + 1))
      if (allocated(error)) return
      call check(error, solver%failed_equation > 3*n_nodes .and. solver%failed_equation <= 3*(n_nodes + 1), &
                 keyword//': failed_equation '//to_string(solver%failed_equation)//' is a DOF of node '// &
                 to_string(n_nodes + 1))
   end subroutine check_zero_block

   subroutine test_cholmod_zero_block(error)
      type(error_t), allocatable, intent(out) :: error
      call check_zero_block('CHOLMOD', error)
   end subroutine test_cholmod_zero_block

   subroutine test_umfpack_zero_block(error)
      type(error_t), allocatable, intent(out) :: error
      call check_zero_block('UMFPACK', error)
   end subroutine test_umfpack_zero_block

   !> SPD assembly with equation 40 decoupled and given diagonal -1: exactly one negative
   !> eigenvalue, so CHOLMOD must fail at equation 40 (node 14, direction 1) while UMFPACK
   !> solves it. New SPD values with the same pattern then factorize without re-analysis.
   subroutine test_cholmod_indefinite(error)
      type(error_t), allocatable, intent(out) :: error
      class(linear_solver_t), allocatable :: cholmod, umfpack
      type(sparse_matrix_t) :: matrix
      type(error_t), allocatable :: solver_error
      integer, allocatable :: connectivity(:, :)
      logical, allocatable :: fixed(:)
      integer :: n_nodes
      integer(i8) :: state
      call cube_connectivity(3, 3, 3, connectivity, n_nodes)
      call matrix%create_node_block_pattern(n_nodes, connectivity)
      state = 404
      call assemble(matrix, connectivity, spd, state)
      allocate (fixed(matrix%n), source=.false.)
      fixed(40) = .true.
      call matrix%apply_dirichlet(fixed, -1.0_dp)
      call create_linear_solver('CHOLMOD', cholmod, error)
      if (allocated(error)) return
      call cholmod%factorize(matrix, solver_error)
      call check_message_contains(error, solver_error, 'not positive definite at equation 40 (node 14, direction 1)')
      if (allocated(error)) return
      call check(error, cholmod%failed_equation == 40, 'failed_equation = 40, got '//to_string(cholmod%failed_equation))
      if (allocated(error)) return
      call create_linear_solver('UMFPACK', umfpack, error)
      if (allocated(error)) return
      call umfpack%factorize(matrix, error)
      if (allocated(error)) return
      call solve_and_check(umfpack, matrix, state, error)
      if (allocated(error)) return
      call assemble(matrix, connectivity, spd, state)
      call cholmod%factorize(matrix, error)
      if (allocated(error)) return
      call check(error, cholmod%n_analyses == 1 .and. cholmod%failed_equation == 0, 'recovery without re-analysis')
      if (allocated(error)) return
      call solve_and_check(cholmod, matrix, state, error)
   end subroutine test_cholmod_indefinite

   !> Pure Neumann Laplacian (no Dirichlet): singular in exact arithmetic (constant null
   !> vectors); in floating point the last pivots are zero, negative or ~eps relative.
   !> Both solvers must report an error with an equation, never return NaNs.
   subroutine test_neumann_singular(error)
      type(error_t), allocatable, intent(out) :: error
      class(linear_solver_t), allocatable :: solver
      type(sparse_matrix_t) :: matrix
      type(error_t), allocatable :: solver_error
      integer, allocatable :: connectivity(:, :)
      integer :: n_nodes, s
      integer(i8) :: state
      character(len=7), parameter :: keywords(2) = ['CHOLMOD', 'UMFPACK']
      call cube_connectivity(3, 3, 3, connectivity, n_nodes)
      call matrix%create_node_block_pattern(n_nodes, connectivity)
      state = 1
      call assemble(matrix, connectivity, laplacian, state)
      do s = 1, 2
         call create_linear_solver(keywords(s), solver, error)
         if (allocated(error)) return
         call solver%factorize(matrix, solver_error)
         call check_message_contains(error, solver_error, 'singular')
         if (allocated(error)) return
         call check(error, solver%failed_equation >= 1 .and. solver%failed_equation <= matrix%n, &
                    keywords(s)//': failed_equation set')
         if (allocated(error)) return
      end do
   end subroutine test_neumann_singular

   !> Pure Neumann Laplacian plus 1e-13 I: positive definite, smallest eigenvalue 1e-13
   !> while the diagonal reaches 56 (7 per element, 8 elements at an interior node), so the
   !> smallest pivot over the largest is about 1e-13/56 ~ 2e-15 < 1e-12 (default
   !> singular_pivot_ratio): both solvers must refuse it; with singular_pivot_ratio = 1e-17
   !> they accept it.
   subroutine test_pivot_ratio(error)
      type(error_t), allocatable, intent(out) :: error
      class(linear_solver_t), allocatable :: solver
      type(sparse_matrix_t) :: matrix
      type(error_t), allocatable :: solver_error
      integer, allocatable :: connectivity(:, :)
      integer :: n_nodes, s, a, i
      integer(i8) :: state
      real(dp) :: shift(3, 3)
      character(len=7), parameter :: keywords(2) = ['CHOLMOD', 'UMFPACK']
      call cube_connectivity(3, 3, 3, connectivity, n_nodes)
      call matrix%create_node_block_pattern(n_nodes, connectivity)
      state = 1
      call assemble(matrix, connectivity, laplacian, state)
      shift = 0.0_dp
      do i = 1, 3
         shift(i, i) = 1.0e-13_dp
      end do
      do a = 1, n_nodes
         call matrix%add_element([a], shift)
      end do
      do s = 1, 2
         call create_linear_solver(keywords(s), solver, error)
         if (allocated(error)) return
         call solver%factorize(matrix, solver_error)
         call check_message_contains(error, solver_error, 'pivot ratio')
         if (allocated(error)) return
         call check(error, solver%failed_equation >= 1 .and. solver%failed_equation <= matrix%n, &
                    keywords(s)//': failed_equation set')
         if (allocated(error)) return
         solver%singular_pivot_ratio = 1.0e-17_dp
         call solver%factorize(matrix, error)
         if (allocated(error)) return
      end do
   end subroutine test_pivot_ratio

   subroutine test_solve_without_factorize(error)
      type(error_t), allocatable, intent(out) :: error
      class(linear_solver_t), allocatable :: solver
      type(sparse_matrix_t) :: matrix
      type(error_t), allocatable :: solver_error
      real(dp) :: b(24), x(24)
      integer :: s
      character(len=7), parameter :: keywords(2) = ['CHOLMOD', 'UMFPACK']
      call matrix%create_node_block_pattern(8, reshape([1, 2, 3, 4, 5, 6, 7, 8], [8, 1]))
      b = 1.0_dp
      do s = 1, 2
         call create_linear_solver(keywords(s), solver, error)
         if (allocated(error)) return
         call solver%solve(matrix, b, x, solver_error)
         call check_message_contains(error, solver_error, 'without a successful factorize')
         if (allocated(error)) return
      end do
   end subroutine test_solve_without_factorize

   !> CHOLMOD_TOO_LARGE (-3) and CHOLMOD_OUT_OF_MEMORY (-2) of the 64-bit interface: the
   !> failure kinds, the system's and the factor's sizes, and the 64-bit limit in the message.
   subroutine test_cholmod_size_failures(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: failure_error
      integer :: failure
      call cholmod_failure(failure_error, -3, 'symbolic analysis', 902289, 1.913e9_dp, failure)
      call check(error, failure == solver_too_large, 'status -3: too large')
      if (allocated(error)) return
      call check_message_contains(error, failure_error, &
                                  'CHOLMOD: the problem is too large for the solver in its symbolic analysis '// &
                                  '(902289 equations, a factor of about 1.913E+09 nonzeros; the size of the '// &
                                  'factor overflows CHOLMOD''s 64-bit integers)')
      if (allocated(error)) return
      call cholmod_failure(failure_error, -2, 'numeric factorization', 1000, 0.0_dp, failure)
      call check(error, failure == solver_out_of_memory, 'status -2: out of memory')
      if (allocated(error)) return
      call check_message_contains(error, failure_error, &
                                  'CHOLMOD: out of memory in the numeric factorization (1000 equations)')
   end subroutine test_cholmod_size_failures

   subroutine test_registry(error)
      type(error_t), allocatable, intent(out) :: error
      class(linear_solver_t), allocatable :: solver
      type(error_t), allocatable :: registry_error
      call create_linear_solver('cholmod', solver, error)
      if (allocated(error)) return
      call check(error, solver%name() == 'CHOLMOD', 'cholmod -> CHOLMOD')
      if (allocated(error)) return
      call create_linear_solver(' Umfpack ', solver, error)
      if (allocated(error)) return
      call check(error, solver%name() == 'UMFPACK', 'Umfpack -> UMFPACK')
      if (allocated(error)) return
      call create_linear_solver('MUMPS', solver, registry_error)
      call check_message_contains(error, registry_error, 'valid: AUTO, CHOLMOD, UMFPACK')
   end subroutine test_registry
end module test_direct_solvers
