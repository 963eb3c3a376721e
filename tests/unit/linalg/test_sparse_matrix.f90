!> Tests of sparse_matrix_t: node-block pattern, scatter, products, Dirichlet, symmetry.
!> Reference values: counts derived by hand from the meshes (stated at each test) and the
!> dense assembly of test_linalg_fixtures (same additions, in the same order).
module test_sparse_matrix
   use frix_kinds, only: dp, i4, i8
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close, check_message_contains
   use frix_sparse_matrix, only: sparse_matrix_t
   use test_linalg_fixtures, only: cube_connectivity, spd_block, unsymmetric_block, dense_add
   implicit none
   private

   public :: collect_sparse_matrix

contains

   subroutine collect_sparse_matrix(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [ &
              new_unittest('two_element_pattern_counts', test_two_element_pattern_counts), &
              new_unittest('position_formula_consistent', test_position_formula), &
              new_unittest('add_element_reads_back', test_add_element_reads_back), &
              new_unittest('extra_pairs_add_blocks', test_extra_pairs), &
              new_unittest('multiply_matches_dense', test_multiply), &
              new_unittest('apply_dirichlet', test_apply_dirichlet), &
              new_unittest('is_symmetric_detects_asymmetry', test_is_symmetric), &
              new_unittest('pattern_errors', test_pattern_errors), &
              new_unittest('add_element_outside_pattern', test_add_outside_pattern), &
              new_unittest('pattern_id_changes', test_pattern_id), &
              new_unittest('mirror_positions_transpose', test_mirror_positions), &
              new_unittest('move_equation_matches_dense', test_move_equation) &
              ]
   end subroutine collect_sparse_matrix

   !> 2 HEX8 elements sharing a face: 12 nodes; the 4 shared nodes see all 12 nodes, the 8
   !> others see the 8 nodes of their element. Sum of degrees 4*12 + 8*8 = 112, nnz = 9*112.
   subroutine test_two_element_pattern_counts(error)
      type(error_t), allocatable, intent(out) :: error
      type(sparse_matrix_t), target :: matrix
      integer(i8), pointer, contiguous :: col_ptr(:), row_index(:)
      real(dp), pointer, contiguous :: values(:)
      integer(i4), pointer, contiguous :: node_ptr(:), node_adj(:)
      integer, allocatable :: connectivity(:, :)
      integer :: n_nodes, a, degree, shared
      call cube_connectivity(2, 1, 1, connectivity, n_nodes)
      call matrix%create_node_block_pattern(n_nodes, connectivity)
      call matrix%csc_arrays(col_ptr, row_index, values)
      call matrix%node_graph(node_ptr, node_adj)
      call check(error, matrix%n == 36, 'n = 3 * 12 nodes')
      if (allocated(error)) return
      call check(error, matrix%nnz() == 1008_i8, 'nnz = 9 * (4*12 + 8*8) = 1008')
      if (allocated(error)) return
      call check(error, col_ptr(matrix%n) == 1008, 'col_ptr(n) = nnz')
      if (allocated(error)) return
      shared = 0
      do a = 1, n_nodes
         degree = node_ptr(a + 1) - node_ptr(a)
         if (degree == 12) shared = shared + 1
         call check(error, degree == 12 .or. degree == 8, 'degree is 8 or 12')
         if (allocated(error)) return
      end do
      call check(error, shared == 4, 'four nodes on the shared face have degree 12')
      if (allocated(error)) return
      ! the shared face nodes are i = 1 of the 3 x 2 x 2 grid: 2, 5, 8, 11
      call check(error, all(node_ptr([3, 6, 9, 12]) - node_ptr([2, 5, 8, 11]) == 12), &
                 'shared nodes 2, 5, 8, 11 have degree 12')
   end subroutine test_two_element_pattern_counts

   !> For every node a, neighbour k (node b), directions i, j: the documented position
   !> p = 9*(node_ptr(a)-1) + 3*deg(a)*(i-1) + 3*(k-1) + (j-1) lies in column 3(a-1)+i and holds
   !> row 3(b-1)+j-1 (0-based); rows strictly increase inside every column.
   subroutine test_position_formula(error)
      type(error_t), allocatable, intent(out) :: error
      type(sparse_matrix_t), target :: matrix
      integer(i8), pointer, contiguous :: col_ptr(:), row_index(:)
      real(dp), pointer, contiguous :: values(:)
      integer(i4), pointer, contiguous :: node_ptr(:), node_adj(:)
      integer, allocatable :: connectivity(:, :)
      integer :: n_nodes, a, b, k, i, j, degree, p, column
      call cube_connectivity(2, 2, 1, connectivity, n_nodes)
      call matrix%create_node_block_pattern(n_nodes, connectivity, extra_pairs=reshape([1, 18], [2, 1]))
      call matrix%csc_arrays(col_ptr, row_index, values)
      call matrix%node_graph(node_ptr, node_adj)
      do a = 1, n_nodes
         degree = node_ptr(a + 1) - node_ptr(a)
         do i = 1, 3
            column = 3*(a - 1) + i
            call check(error, col_ptr(column - 1) == 9*(node_ptr(a) - 1) + 3*degree*(i - 1), &
                       'col_ptr formula')
            if (allocated(error)) return
            do k = 1, degree
               b = node_adj(node_ptr(a) + k - 1)
               call check(error, matrix%neighbour_index(a, b) == k, 'neighbour_index finds k')
               if (allocated(error)) return
               do j = 1, 3
                  p = 9*(node_ptr(a) - 1) + 3*degree*(i - 1) + 3*(k - 1) + (j - 1)
                  call check(error, p >= col_ptr(column - 1) .and. p < col_ptr(column), &
                             'position inside its column')
                  if (allocated(error)) return
                  call check(error, row_index(p + 1) == 3*(b - 1) + j - 1, 'row index at position')
                  if (allocated(error)) return
                  call check(error, matrix%entry_position(a, k, i, j) == p + 1, 'entry_position = p + 1')
                  if (allocated(error)) return
               end do
            end do
         end do
      end do
      do column = 1, matrix%n
         do p = int(col_ptr(column - 1)) + 2, int(col_ptr(column))
            call check(error, row_index(p) > row_index(p - 1), 'rows sorted in every column')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_position_formula

   !> Assemble two random (unsymmetric) element matrices; entry() must return exactly the
   !> dense assembly (same additions in the same order), including 0 outside the pattern.
   subroutine test_add_element_reads_back(error)
      type(error_t), allocatable, intent(out) :: error
      type(sparse_matrix_t), target :: matrix
      integer(i8), pointer, contiguous :: col_ptr(:), row_index(:)
      real(dp), pointer, contiguous :: values(:)
      integer, allocatable :: connectivity(:, :)
      real(dp), allocatable :: dense(:, :)
      integer(i8) :: state
      integer :: n_nodes, row, column
      call cube_connectivity(2, 1, 1, connectivity, n_nodes)
      call matrix%create_node_block_pattern(n_nodes, connectivity)
      call matrix%csc_arrays(col_ptr, row_index, values)
      state = 12345
      call assemble_unsymmetric(matrix, connectivity, state, dense, error)
      if (allocated(error)) return
      do column = 1, matrix%n
         do row = 1, matrix%n
            call check(error, matrix%entry(row, column) == dense(row, column), 'entry equals dense assembly')
            if (allocated(error)) return
         end do
      end do
      ! node 1 (first element only) and node 3 (second element only) are not coupled
      call check(error, matrix%neighbour_index(1, 3) == 0, 'nodes 1 and 3 are not coupled')
      if (allocated(error)) return
      call check(error, count(dense /= 0.0_dp) == 1008, 'the random blocks fill the whole pattern')
      if (allocated(error)) return
      call matrix%zero()
      call check(error, all(values == 0.0_dp), 'zero() clears the values')
   end subroutine test_add_element_reads_back

   !> Extra pair (1, 3) couples two nodes of different elements: 2 new 3x3 blocks (18 entries).
   subroutine test_extra_pairs(error)
      type(error_t), allocatable, intent(out) :: error
      type(sparse_matrix_t) :: matrix
      integer, allocatable :: connectivity(:, :)
      integer :: n_nodes, column_value
      real(dp) :: block(6, 6)
      call cube_connectivity(2, 1, 1, connectivity, n_nodes)
      ! pair given twice and in both orders: still one coupling
      call matrix%create_node_block_pattern(n_nodes, connectivity, extra_pairs=reshape([1, 3, 3, 1], [2, 2]))
      call check(error, matrix%nnz() == 1008_i8 + 18_i8, 'nnz grows by two 3x3 blocks')
      if (allocated(error)) return
      call check(error, matrix%neighbour_index(1, 3) > 0 .and. matrix%neighbour_index(3, 1) > 0, &
                 'both blocks (1,3) and (3,1) in the pattern')
      if (allocated(error)) return
      block = reshape([(real(column_value, dp), column_value=1, 36)], [6, 6])
      call matrix%add_element([1, 3], block, error)
      if (allocated(error)) return
      ! block(3*(2-1)+2, 3*(1-1)+1) = block(5, 1) = 5 -> row (node 3, y) = 8, column (node 1, x) = 1
      call check(error, matrix%entry(8, 1) == 5.0_dp, 'contact block entry (8, 1) = block(5, 1)')
   end subroutine test_extra_pairs

   !> y = A x and y = A^T x against matmul with the dense assembly, random x.
   subroutine test_multiply(error)
      type(error_t), allocatable, intent(out) :: error
      type(sparse_matrix_t) :: matrix
      integer, allocatable :: connectivity(:, :)
      real(dp), allocatable :: dense(:, :), x(:, :), y(:), y_dense(:)
      integer(i8) :: state
      integer :: n_nodes, i
      call cube_connectivity(2, 2, 2, connectivity, n_nodes)
      call matrix%create_node_block_pattern(n_nodes, connectivity)
      state = 777
      call assemble_unsymmetric(matrix, connectivity, state, dense, error)
      if (allocated(error)) return
      allocate (x(matrix%n, 1), y(matrix%n))
      call fill_vector(state, x)
      call matrix%multiply(x(:, 1), y)
      y_dense = matmul(dense, x(:, 1))
      do i = 1, matrix%n
         ! sums of ~80 products of O(10) terms: rounding ~1e-13 relative to max |y|
         call check_close(error, y(i), y_dense(i), 0.0_dp, 1.0e-13_dp*maxval(abs(y_dense)), 'A x')
         if (allocated(error)) return
      end do
      call matrix%multiply_transpose(x(:, 1), y)
      y_dense = matmul(transpose(dense), x(:, 1))
      do i = 1, matrix%n
         call check_close(error, y(i), y_dense(i), 0.0_dp, 1.0e-13_dp*maxval(abs(y_dense)), 'A^T x')
         if (allocated(error)) return
      end do
   contains
      subroutine fill_vector(state, values)
         use test_linalg_fixtures, only: fill_random
         integer(i8), intent(inout) :: state
         real(dp), intent(out) :: values(:, :)
         call fill_random(state, values)
      end subroutine fill_vector
   end subroutine test_multiply

   !> Fixed rows/columns become 0, fixed diagonals the given value, other entries unchanged,
   !> symmetry kept.
   subroutine test_apply_dirichlet(error)
      type(error_t), allocatable, intent(out) :: error
      type(sparse_matrix_t) :: matrix
      integer, allocatable :: connectivity(:, :)
      real(dp), allocatable :: dense(:, :), diagonal(:)
      logical, allocatable :: fixed(:)
      real(dp) :: block(24, 24), expected
      integer(i8) :: state
      integer :: n_nodes, e, row, column
      call cube_connectivity(2, 1, 1, connectivity, n_nodes)
      call matrix%create_node_block_pattern(n_nodes, connectivity)
      allocate (dense(matrix%n, matrix%n), source=0.0_dp)
      state = 4242
      do e = 1, size(connectivity, 2)
         call spd_block(state, block)
         call matrix%add_element(connectivity(:, e), block)
         call dense_add(dense, connectivity(:, e), block)
      end do
      call check(error, matrix%is_symmetric(1.0e-14_dp), 'SPD assembly is symmetric')
      if (allocated(error)) return
      allocate (fixed(matrix%n), source=.false.)
      fixed([1, 2, 3, 8, 20]) = .true.   ! node 1 fully, node 3 y, node 7 y
      call matrix%apply_dirichlet(fixed, 2.5_dp)
      call check(error, matrix%is_symmetric(1.0e-14_dp), 'still symmetric after apply_dirichlet')
      if (allocated(error)) return
      do column = 1, matrix%n
         do row = 1, matrix%n
            if (fixed(row) .or. fixed(column)) then
               expected = 0.0_dp
               if (row == column) expected = 2.5_dp
            else
               expected = dense(row, column)
            end if
            call check(error, matrix%entry(row, column) == expected, 'entry after apply_dirichlet')
            if (allocated(error)) return
         end do
      end do
      allocate (diagonal(matrix%n))
      call matrix%get_diagonal(diagonal)
      do row = 1, matrix%n
         expected = dense(row, row)
         if (fixed(row)) expected = 2.5_dp
         call check(error, diagonal(row) == expected, 'get_diagonal')
         if (allocated(error)) return
      end do
   end subroutine test_apply_dirichlet

   !> One perturbed off-diagonal entry (relative 1e-6 of max |A|) makes is_symmetric false
   !> at tolerance 1e-8 and true at 1e-4.
   subroutine test_is_symmetric(error)
      type(error_t), allocatable, intent(out) :: error
      type(sparse_matrix_t) :: matrix
      integer, allocatable :: connectivity(:, :)
      real(dp) :: block(24, 24)
      integer(i8) :: state
      integer :: n_nodes
      call cube_connectivity(1, 1, 1, connectivity, n_nodes)
      call matrix%create_node_block_pattern(n_nodes, connectivity)
      state = 99
      call spd_block(state, block)
      block(5, 17) = block(5, 17) + 1.0e-6_dp*maxval(abs(block))
      call matrix%add_element(connectivity(:, 1), block)
      call check(error, .not. matrix%is_symmetric(1.0e-8_dp), 'asymmetry 1e-6 detected at 1e-8')
      if (allocated(error)) return
      call check(error, matrix%is_symmetric(1.0e-4_dp), 'asymmetry 1e-6 accepted at 1e-4')
   end subroutine test_is_symmetric

   subroutine test_pattern_errors(error)
      type(error_t), allocatable, intent(out) :: error
      type(sparse_matrix_t) :: matrix
      type(error_t), allocatable :: pattern_error
      call matrix%create_node_block_pattern(3, reshape([1, 2, 4], [3, 1]), error=pattern_error)
      call check_message_contains(error, pattern_error, 'outside 1..3')
      if (allocated(error)) return
      call check(error, matrix%n == 0 .and. matrix%pattern_id == 0, 'matrix left empty on error')
      if (allocated(error)) return
      call matrix%create_node_block_pattern(3, reshape([1, 2, 3], [3, 1]), &
                                            extra_pairs=reshape([1, 0], [2, 1]), error=pattern_error)
      call check_message_contains(error, pattern_error, 'extra_pairs')
   end subroutine test_pattern_errors

   subroutine test_add_outside_pattern(error)
      type(error_t), allocatable, intent(out) :: error
      type(sparse_matrix_t) :: matrix
      type(error_t), allocatable :: add_error
      real(dp) :: block(6, 6)
      ! two separate 2-node "elements": nodes 1 and 4 are not coupled
      call matrix%create_node_block_pattern(4, reshape([1, 2, 3, 4], [2, 2]))
      block = 1.0_dp
      call matrix%add_element([1, 4], block, add_error)
      call check_message_contains(error, add_error, 'not in the matrix pattern')
      if (allocated(error)) return
      call matrix%zero()
      call matrix%add_element([1, 4], block)
      ! blocks (1,1) and (4,4) added, (1,4) and (4,1) dropped: 2 x 9 entries
      call check(error, matrix%dropped_entries == 18_i8, 'dropped entries counted')
      if (allocated(error)) return
      call check(error, matrix%entry(1, 1) == 1.0_dp .and. matrix%entry(10, 1) == 0.0_dp, &
                 'coupled entries added, uncoupled not')
   end subroutine test_add_outside_pattern

   subroutine test_pattern_id(error)
      type(error_t), allocatable, intent(out) :: error
      type(sparse_matrix_t), target :: matrix
      integer(i8), pointer, contiguous :: col_ptr(:), row_index(:)
      real(dp), pointer, contiguous :: values(:)
      integer :: first
      call matrix%create_node_block_pattern(2, reshape([1, 2], [2, 1]))
      call matrix%csc_arrays(col_ptr, row_index, values)
      first = matrix%pattern_id
      call check(error, first > 0, 'pattern_id positive after a build')
      if (allocated(error)) return
      values = 1.0_dp
      call matrix%create_node_block_pattern(2, reshape([1, 2], [2, 1]))
      call matrix%csc_arrays(col_ptr, row_index, values)
      call check(error, matrix%pattern_id /= first, 'rebuilding the same pattern changes pattern_id')
      if (allocated(error)) return
      call check(error, all(values == 0.0_dp), 'a rebuild reusing the storage zeroes the values')
      if (allocated(error)) return
      call check(error, matrix%memory_bytes() == 8_i8*36 + 8_i8*36 + 8_i8*7 + 4_i8*3 + 4_i8*4, &
                 'memory_bytes = values + row_index + col_ptr + node_ptr + node_adj')
   end subroutine test_pattern_id

   !> On an unsymmetric assembly of 2 x 2 x 1 HEX8 (with an extra pair): the entry at the
   !> mirror position of every stored entry (row r, column c) is A(c, r) (dense reference),
   !> and the mirror of the mirror is the position itself.
   subroutine test_mirror_positions(error)
      type(error_t), allocatable, intent(out) :: error
      type(sparse_matrix_t), target :: matrix
      integer(i8), pointer, contiguous :: col_ptr(:), row_index(:)
      real(dp), pointer, contiguous :: values(:)
      integer, allocatable :: connectivity(:, :), mirror(:)
      real(dp), allocatable :: dense(:, :)
      integer(i8) :: state
      integer :: n_nodes, column, p, row
      call cube_connectivity(2, 2, 1, connectivity, n_nodes)
      call matrix%create_node_block_pattern(n_nodes, connectivity, extra_pairs=reshape([1, 18], [2, 1]))
      call matrix%csc_arrays(col_ptr, row_index, values)
      state = 4242
      call assemble_unsymmetric(matrix, connectivity, state, dense, error)
      if (allocated(error)) return
      call matrix%mirror_positions(mirror)
      call check(error, size(mirror) == size(values), 'one mirror per stored entry')
      if (allocated(error)) return
      do column = 1, matrix%n
         do p = int(col_ptr(column - 1)) + 1, int(col_ptr(column))
            row = int(row_index(p)) + 1
            call check(error, values(mirror(p)) == dense(column, row), 'values(mirror(p)) = A(c, r)')
            if (allocated(error)) return
            call check(error, mirror(mirror(p)) == p, 'the mirror of the mirror is p')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_mirror_positions

   !> move_equation against the dense elimination: row e times w added to the master rows and
   !> zeroed, then the same for the column (u_e = 0.5 u_m1 + 0.25 u_m2); a master outside the
   !> pattern is reported as the missing pair (master node, other node).
   subroutine test_move_equation(error)
      type(error_t), allocatable, intent(out) :: error
      type(sparse_matrix_t) :: matrix
      integer, allocatable :: connectivity(:, :)
      real(dp), allocatable :: dense(:, :)
      real(dp) :: weights(2)
      integer(i8) :: state
      integer :: n_nodes, row, column, masters(2), missing(2), dependent
      call cube_connectivity(2, 1, 1, connectivity, n_nodes)
      call matrix%create_node_block_pattern(n_nodes, connectivity)
      state = 777
      call assemble_unsymmetric(matrix, connectivity, state, dense, error)
      if (allocated(error)) return
      ! nodes 2, 5 and 8 lie on the shared face (coupled to every node); equation 3*(2-1)+2
      ! depends on equations 3*(5-1)+1 (node 5, x) and 3*(8-1)+3 (node 8, z)
      dependent = 5
      masters = [13, 24]
      weights = [0.5_dp, 0.25_dp]
      call matrix%move_equation(dependent, masters, weights, .true., missing)
      call check(error, all(missing == 0), 'no pair missing')
      if (allocated(error)) return
      dense(masters(1), :) = dense(masters(1), :) + weights(1)*dense(dependent, :)
      dense(masters(2), :) = dense(masters(2), :) + weights(2)*dense(dependent, :)
      dense(dependent, :) = 0.0_dp
      call matrix%move_equation(dependent, masters, weights, .false., missing)
      dense(:, masters(1)) = dense(:, masters(1)) + weights(1)*dense(:, dependent)
      dense(:, masters(2)) = dense(:, masters(2)) + weights(2)*dense(:, dependent)
      dense(:, dependent) = 0.0_dp
      do column = 1, matrix%n
         do row = 1, matrix%n
            call check_close(error, matrix%entry(row, column), dense(row, column), 1.0e-14_dp, &
                             abs_tol=1.0e-14_dp, message='entry equals the dense elimination')
            if (allocated(error)) return
         end do
      end do
      ! node 1 and node 3 share no element: moving node 1's x onto node 3's x lacks (3, n)
      call matrix%move_equation(1, [7], [1.0_dp], .true., missing)
      call check(error, missing(1) == 3 .and. missing(2) > 0, 'missing pair reported with the master node')
   end subroutine test_move_equation

   !> Pseudo-random unsymmetric element blocks (seeded by `state`, advanced) added to `matrix`
   !> and to the dense reference `dense` (allocated here) in the same order.
   subroutine assemble_unsymmetric(matrix, connectivity, state, dense, error)
      type(sparse_matrix_t), intent(inout) :: matrix
      integer, intent(in) :: connectivity(:, :)
      integer(i8), intent(inout) :: state
      real(dp), allocatable, intent(out) :: dense(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: block(3*size(connectivity, 1), 3*size(connectivity, 1))
      integer :: e
      allocate (dense(matrix%n, matrix%n), source=0.0_dp)
      do e = 1, size(connectivity, 2)
         call unsymmetric_block(state, block)
         call matrix%add_element(connectivity(:, e), block, error)
         if (allocated(error)) return
         call dense_add(dense, connectivity(:, e), block)
      end do
   end subroutine assemble_unsymmetric
end module test_sparse_matrix
