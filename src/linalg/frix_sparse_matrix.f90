!> The system matrix (frix_system_matrix) in compressed sparse column (CSC) storage of the
!> FULL pattern (both triangles), with a node-blocked layout for cheap finite element scatter:
!> the serial implementation, read by the direct solvers (CHOLMOD, UMFPACK) through `csc_arrays`.
!>
!> Equation numbering is node-major with 3 DOFs per node: equation `3*(node-1) + i`,
!> i = 1, 2, 3 the direction (x, y, z). The CSC index arrays `col_ptr` and `row_index` are
!> 0-based `integer(i8)` (SuiteSparse_long) so that the 64-bit interfaces of SuiteSparse
!> (`cholmod_l_*`, `umfpack_dl_*`) read them without copies. Positions in `values` are default
!> integers: at most 2^31 - 1 entries, about 26 million equations of HEX8 (81 entries per
!> equation), far beyond what a direct factorization of such a mesh fits in memory.
!>
!> Layout. The node graph is kept in CSR form (`node_ptr`, `node_adj`, 1-based, every
!> node list sorted and containing the node itself). With deg(a) = node_ptr(a+1) - node_ptr(a),
!> the 3 columns of node a are stored one after the other, each as 3*deg(a) rows: the
!> 3x3 block of neighbour number k (node b = node_adj(node_ptr(a)+k-1)) at rows offset
!> 3*(k-1). Hence the 0-based position of entry (row (b,j), column (a,i)) is
!>
!>     p = 9*(node_ptr(a) - 1) + 3*deg(a)*(i - 1) + 3*(k - 1) + (j - 1)
!>
!> and `values(p + 1)` holds it; `col_ptr(3*(a-1) + i - 1) = 9*(node_ptr(a) - 1) +
!> 3*deg(a)*(i - 1)`. Rows inside a column are sorted because `node_adj` is.
module frix_sparse_matrix
   use frix_kinds, only: dp, i4, i8
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_finite_check, only: first_non_finite
   use frix_system_matrix, only: system_matrix_t
   implicit none
   private

   public :: sparse_matrix_t

   !> Counter handing out pattern identifiers; 0 means "no pattern".
   integer, save :: last_pattern_id = 0

   !> Square sparse matrix, CSC with full (structurally symmetric) node-block pattern.
   type, extends(system_matrix_t) :: sparse_matrix_t
      private
      integer(i8), allocatable :: col_ptr(:)    !! (0:n) 0-based offsets of the columns
      integer(i8), allocatable :: row_index(:)  !! (nnz) 0-based rows, sorted within a column
      real(dp), allocatable :: values(:)        !! (nnz) entries, same order as row_index
      integer(i4), allocatable :: node_ptr(:)   !! (n_nodes+1) 1-based CSR offsets of the node graph
      integer(i4), allocatable :: node_adj(:)   !! 1-based sorted neighbour lists (node itself included)
   contains
      procedure :: create_node_block_pattern
      procedure :: zero
      procedure :: add_element
      procedure :: multiply
      procedure :: multiply_transpose
      procedure :: apply_dirichlet
      procedure :: is_symmetric
      procedure :: entry
      procedure :: get_diagonal
      procedure :: nnz
      procedure :: memory_bytes
      procedure :: couples
      procedure :: move_equation
      procedure :: first_non_finite_column
      procedure :: neighbour_index
      procedure :: entry_position
      procedure :: csc_arrays
      procedure :: node_graph
      procedure :: mirror_positions
   end type sparse_matrix_t

contains

   !> Build the node graph and the node-block CSC pattern; values are set to zero.
   !> Node a is coupled to node b when both appear in one column of `connectivity` or
   !> together in a column of `extra_pairs` (contact). Entries 0 of `connectivity` are
   !> padding and skipped. Cost O(sum over nodes of (incident elements * nodes per element)).
   !> On error (node number out of range, more than huge(i4) entries) the matrix is left
   !> empty (n = 0) and `error` is set if present.
   subroutine create_node_block_pattern(matrix, n_nodes, connectivity, extra_pairs, error)
      class(sparse_matrix_t), intent(inout) :: matrix
      integer, intent(in) :: n_nodes                     !! number of nodes (equations = 3*n_nodes)
      integer, intent(in) :: connectivity(:, :)          !! (nodes per element, n_elements) node numbers
      integer, intent(in), optional :: extra_pairs(:, :) !! (2, m) additional coupled node pairs
      type(error_t), allocatable, intent(out), optional :: error
      integer, allocatable :: element_ptr(:), element_list(:), pair_ptr(:), pair_list(:)
      integer, allocatable :: marker(:)
      integer :: n_per_element, n_elements, n_pairs, e, l, a, b, m, pass, count, q, r
      integer :: degree, first, kk
      integer(i8) :: total, node_entries
      integer(i4) :: tmp
      integer(i8) :: base

      ! keep values/row_index: reused when the new pattern has the same entry count (a
      ! rebuild after a contact change often does), which saves touching fresh pages
      call clear(matrix, keep_storage=.true.)
      n_per_element = size(connectivity, 1)
      n_elements = size(connectivity, 2)
      n_pairs = 0
      if (present(extra_pairs)) then
         if (size(extra_pairs, 1) /= 2) then
            call report('create_node_block_pattern: extra_pairs must have shape (2, m)')
            return
         end if
         n_pairs = size(extra_pairs, 2)
      end if
      if (n_nodes < 0) then
         call report('create_node_block_pattern: negative node count')
         return
      end if
      if (any(connectivity < 0 .or. connectivity > n_nodes)) then
         call report('create_node_block_pattern: connectivity holds a node number outside 1..'// &
                     to_string(n_nodes))
         return
      end if
      if (n_pairs > 0) then
         if (any(extra_pairs < 1 .or. extra_pairs > n_nodes)) then
            call report('create_node_block_pattern: extra_pairs holds a node number outside 1..'// &
                        to_string(n_nodes))
            return
         end if
      end if

      ! node -> elements incidence (CSR)
      allocate (element_ptr(n_nodes + 1), source=0)
      do e = 1, n_elements
         do l = 1, n_per_element
            a = connectivity(l, e)
            if (a > 0) element_ptr(a + 1) = element_ptr(a + 1) + 1
         end do
      end do
      element_ptr(1) = 1
      do a = 1, n_nodes
         element_ptr(a + 1) = element_ptr(a + 1) + element_ptr(a)
      end do
      allocate (element_list(element_ptr(n_nodes + 1) - 1))
      allocate (marker(n_nodes + 1))
      marker(1:n_nodes) = element_ptr(1:n_nodes)
      do e = 1, n_elements
         do l = 1, n_per_element
            a = connectivity(l, e)
            if (a > 0) then
               element_list(marker(a)) = e
               marker(a) = marker(a) + 1
            end if
         end do
      end do

      ! node -> partner nodes of extra pairs (both directions)
      allocate (pair_ptr(n_nodes + 1), source=0)
      do m = 1, n_pairs
         pair_ptr(extra_pairs(1, m) + 1) = pair_ptr(extra_pairs(1, m) + 1) + 1
         pair_ptr(extra_pairs(2, m) + 1) = pair_ptr(extra_pairs(2, m) + 1) + 1
      end do
      pair_ptr(1) = 1
      do a = 1, n_nodes
         pair_ptr(a + 1) = pair_ptr(a + 1) + pair_ptr(a)
      end do
      allocate (pair_list(pair_ptr(n_nodes + 1) - 1))
      marker(1:n_nodes) = pair_ptr(1:n_nodes)
      do m = 1, n_pairs
         a = extra_pairs(1, m)
         b = extra_pairs(2, m)
         pair_list(marker(a)) = b
         marker(a) = marker(a) + 1
         pair_list(marker(b)) = a
         marker(b) = marker(b) + 1
      end do

      ! two passes over the nodes: count the distinct neighbours, then fill and sort them
      allocate (matrix%node_ptr(n_nodes + 1))
      marker = 0
      total = 0
      do pass = 1, 2
         do a = 1, n_nodes
            count = 0
            if (pass == 2) first = matrix%node_ptr(a)
            call visit(a)
            do q = element_ptr(a), element_ptr(a + 1) - 1
               e = element_list(q)
               do l = 1, n_per_element
                  b = connectivity(l, e)
                  if (b > 0) call visit(b)
               end do
            end do
            do q = pair_ptr(a), pair_ptr(a + 1) - 1
               call visit(pair_list(q))
            end do
            if (pass == 1) then
               matrix%node_ptr(a) = int(count, i4)
               total = total + count
            else
               ! insertion sort of the short list
               do q = first + 1, first + count - 1
                  tmp = matrix%node_adj(q)
                  r = q - 1
                  do while (r >= first)
                     if (matrix%node_adj(r) <= tmp) exit
                     matrix%node_adj(r + 1) = matrix%node_adj(r)
                     r = r - 1
                  end do
                  matrix%node_adj(r + 1) = tmp
               end do
            end if
         end do
         if (pass == 1) then
            if (9_i8*total > int(huge(0_i4), i8)) then
               call report('create_node_block_pattern: '//to_string(9_i8*total)// &
                           ' matrix entries exceed 2^31 - 1, the range of the positions of its values')
               return
            end if
            ! degrees -> offsets
            node_entries = 1
            do a = 1, n_nodes
               degree = matrix%node_ptr(a)
               matrix%node_ptr(a) = int(node_entries, i4)
               node_entries = node_entries + degree
            end do
            matrix%node_ptr(n_nodes + 1) = int(node_entries, i4)
            allocate (matrix%node_adj(total))
            marker = 0
         end if
      end do

      ! CSC arrays from the node graph (layout formula in the module header)
      matrix%n_nodes = n_nodes
      matrix%n = 3*n_nodes
      allocate (matrix%col_ptr(0:matrix%n))
      if (allocated(matrix%values)) then
         if (size(matrix%values, kind=i8) /= 9*total) deallocate (matrix%values, matrix%row_index)
      end if
      if (allocated(matrix%values)) then
         matrix%values = 0.0_dp
      else
         allocate (matrix%row_index(9*total))
         allocate (matrix%values(9*total), source=0.0_dp)
      end if
      matrix%col_ptr(0) = 0
      do a = 1, n_nodes
         degree = matrix%node_ptr(a + 1) - matrix%node_ptr(a)
         base = 9_i8*(matrix%node_ptr(a) - 1_i8)
         do l = 1, 3
            matrix%col_ptr(3*(a - 1) + l) = base + 3_i8*degree*l
            do kk = 1, degree
               b = matrix%node_adj(matrix%node_ptr(a) + kk - 1)
               q = int(base) + 3*degree*(l - 1) + 3*(kk - 1)
               matrix%row_index(q + 1) = 3_i8*(b - 1)
               matrix%row_index(q + 2) = 3_i8*(b - 1) + 1
               matrix%row_index(q + 3) = 3_i8*(b - 1) + 2
            end do
         end do
      end do
      last_pattern_id = last_pattern_id + 1
      matrix%pattern_id = last_pattern_id

   contains

      !> Count (pass 1) or store (pass 2) node c once for the current node a.
      subroutine visit(c)
         integer, intent(in) :: c
         if (marker(c) == a) return
         marker(c) = a
         if (pass == 2) matrix%node_adj(first + count) = int(c, i4)
         count = count + 1
      end subroutine visit

      subroutine report(message)
         character(len=*), intent(in) :: message
         call clear(matrix)
         if (present(error)) call fatal_error(error, message)
      end subroutine report
   end subroutine create_node_block_pattern

   !> Free every array (but values and row_index with keep_storage) and reset the matrix to
   !> the empty state.
   subroutine clear(matrix, keep_storage)
      class(sparse_matrix_t), intent(inout) :: matrix
      logical, intent(in), optional :: keep_storage
      logical :: keep
      keep = .false.
      if (present(keep_storage)) keep = keep_storage
      if (allocated(matrix%col_ptr)) deallocate (matrix%col_ptr)
      if (.not. keep .and. allocated(matrix%row_index)) deallocate (matrix%row_index)
      if (.not. keep .and. allocated(matrix%values)) deallocate (matrix%values)
      if (allocated(matrix%node_ptr)) deallocate (matrix%node_ptr)
      if (allocated(matrix%node_adj)) deallocate (matrix%node_adj)
      matrix%n = 0
      matrix%n_nodes = 0
      matrix%pattern_id = 0
      matrix%dropped_entries = 0
   end subroutine clear

   !> Set every stored value to zero (pattern kept).
   subroutine zero(matrix)
      class(sparse_matrix_t), intent(inout) :: matrix
      matrix%values = 0.0_dp
      matrix%dropped_entries = 0
   end subroutine zero

   !> Position k (1-based) of node b in the sorted neighbour list of node a, 0 if absent.
   !> Binary search; node lists have about 27 entries for HEX8 meshes.
   pure function neighbour_index(matrix, a, b) result(k)
      class(sparse_matrix_t), intent(in) :: matrix
      integer, intent(in) :: a   !! column node
      integer, intent(in) :: b   !! row node
      integer :: k
      integer :: low, high, middle, first
      first = matrix%node_ptr(a)
      low = first
      high = matrix%node_ptr(a + 1) - 1
      k = 0
      do while (low <= high)
         middle = (low + high)/2
         if (matrix%node_adj(middle) < b) then
            low = middle + 1
         else if (matrix%node_adj(middle) > b) then
            high = middle - 1
         else
            k = middle - first + 1
            return
         end if
      end do
   end function neighbour_index

   !> 1-based index into `values` of entry (row (b,j), column (a,i)), b being neighbour number
   !> k of node a: 9*(node_ptr(a)-1) + 3*deg(a)*(i-1) + 3*(k-1) + (j-1) + 1 (module header).
   pure function entry_position(matrix, a, k, i, j) result(position)
      class(sparse_matrix_t), intent(in) :: matrix
      integer, intent(in) :: a   !! column node
      integer, intent(in) :: k   !! neighbour number of the row node in node a's list (neighbour_index)
      integer, intent(in) :: i   !! column direction 1..3
      integer, intent(in) :: j   !! row direction 1..3
      integer :: position
      position = 9*(matrix%node_ptr(a) - 1) + 3*(matrix%node_ptr(a + 1) - matrix%node_ptr(a))*(i - 1) + &
                 3*(k - 1) + j
   end function entry_position

   !> Scatter-add a node-major element matrix: `block(3*(b-1)+j, 3*(a-1)+i)` is the entry of
   !> row (local node b, direction j), column (local node a, direction i). Entries whose node
   !> pair is not in the pattern are not added: `error` is set if present, otherwise they are
   !> counted in `dropped_entries`.
   subroutine add_element(matrix, nodes, block, error)
      class(sparse_matrix_t), intent(inout) :: matrix
      integer, intent(in) :: nodes(:)        !! global node numbers of the element's local nodes
      real(dp), intent(in) :: block(:, :)    !! (3*size(nodes), 3*size(nodes)) element matrix
      type(error_t), allocatable, intent(out), optional :: error
      integer :: la, lb, na, nb, k, degree, base, p, column, row

      if (matrix%ignore_additions) return
      do la = 1, size(nodes)
         na = nodes(la)
         degree = matrix%node_ptr(na + 1) - matrix%node_ptr(na)
         base = 9*(matrix%node_ptr(na) - 1)
         column = 3*(la - 1)
         do lb = 1, size(nodes)
            nb = nodes(lb)
            k = neighbour_index(matrix, na, nb)
            row = 3*(lb - 1)
            if (k == 0) then
               if (present(error)) then
                  call fatal_error(error, 'add_element: node pair ('//to_string(nb)//', '// &
                                   to_string(na)//') is not in the matrix pattern')
                  return
               end if
               matrix%dropped_entries = matrix%dropped_entries + 9
               cycle
            end if
            p = base + 3*(k - 1)
            matrix%values(p + 1) = matrix%values(p + 1) + block(row + 1, column + 1)
            matrix%values(p + 2) = matrix%values(p + 2) + block(row + 2, column + 1)
            matrix%values(p + 3) = matrix%values(p + 3) + block(row + 3, column + 1)
            p = p + 3*degree
            matrix%values(p + 1) = matrix%values(p + 1) + block(row + 1, column + 2)
            matrix%values(p + 2) = matrix%values(p + 2) + block(row + 2, column + 2)
            matrix%values(p + 3) = matrix%values(p + 3) + block(row + 3, column + 2)
            p = p + 3*degree
            matrix%values(p + 1) = matrix%values(p + 1) + block(row + 1, column + 3)
            matrix%values(p + 2) = matrix%values(p + 2) + block(row + 2, column + 3)
            matrix%values(p + 3) = matrix%values(p + 3) + block(row + 3, column + 3)
         end do
      end do
   end subroutine add_element

   !> y = A x.
   subroutine multiply(matrix, x, y)
      class(sparse_matrix_t), intent(in) :: matrix
      real(dp), intent(in) :: x(:)    !! (n)
      real(dp), intent(out) :: y(:)   !! (n)
      integer :: column, p
      real(dp) :: x_column
      y = 0.0_dp
      do column = 1, matrix%n
         x_column = x(column)
         do p = int(matrix%col_ptr(column - 1)) + 1, int(matrix%col_ptr(column))
            y(matrix%row_index(p) + 1) = y(matrix%row_index(p) + 1) + matrix%values(p)*x_column
         end do
      end do
   end subroutine multiply

   !> y = A^T x.
   subroutine multiply_transpose(matrix, x, y)
      class(sparse_matrix_t), intent(in) :: matrix
      real(dp), intent(in) :: x(:)    !! (n)
      real(dp), intent(out) :: y(:)   !! (n)
      integer :: column, p
      real(dp) :: total
      do column = 1, matrix%n
         total = 0.0_dp
         do p = int(matrix%col_ptr(column - 1)) + 1, int(matrix%col_ptr(column))
            total = total + matrix%values(p)*x(matrix%row_index(p) + 1)
         end do
         y(column) = total
      end do
   end subroutine multiply_transpose

   !> Impose homogeneous Dirichlet conditions on the matrix: every entry of a fixed row or a
   !> fixed column becomes 0 and the diagonal of a fixed equation becomes `diagonal_value`
   !> (the caller passes e.g. the mean absolute diagonal, so the pivots keep their scale).
   !> Symmetry is kept. The right-hand side is the caller's business.
   subroutine apply_dirichlet(matrix, fixed, diagonal_value)
      class(sparse_matrix_t), intent(inout) :: matrix
      logical, intent(in) :: fixed(:)            !! (n) .true. for a fixed equation
      real(dp), intent(in) :: diagonal_value     !! value put on the diagonal of fixed equations
      integer :: column, p, row
      do column = 1, matrix%n
         if (fixed(column)) then
            do p = int(matrix%col_ptr(column - 1)) + 1, int(matrix%col_ptr(column))
               if (matrix%row_index(p) + 1 == column) then
                  matrix%values(p) = diagonal_value
               else
                  matrix%values(p) = 0.0_dp
               end if
            end do
         else
            do p = int(matrix%col_ptr(column - 1)) + 1, int(matrix%col_ptr(column))
               row = int(matrix%row_index(p)) + 1
               if (fixed(row)) matrix%values(p) = 0.0_dp
            end do
         end if
      end do
   end subroutine apply_dirichlet

   !> True when |A(i,j) - A(j,i)| <= rel_tol * max|A| for every stored entry (the node-block
   !> pattern is structurally symmetric, so A(j,i) is always stored). An all-zero matrix is
   !> symmetric.
   function is_symmetric(matrix, rel_tol) result(symmetric)
      class(sparse_matrix_t), intent(in) :: matrix
      real(dp), intent(in) :: rel_tol
      logical :: symmetric
      real(dp) :: tolerance
      integer :: a, b, k, k_back, i, j, degree_a, p, p_back
      symmetric = .true.
      if (matrix%n == 0) return
      tolerance = rel_tol*maxval(abs(matrix%values))
      do a = 1, matrix%n_nodes
         degree_a = matrix%node_ptr(a + 1) - matrix%node_ptr(a)
         do k = 1, degree_a
            b = matrix%node_adj(matrix%node_ptr(a) + k - 1)
            if (b < a) cycle
            k_back = neighbour_index(matrix, b, a)
            do i = 1, 3
               do j = 1, 3
                  ! (row (b,j), column (a,i)) against (row (a,i), column (b,j))
                  p = entry_position(matrix, a, k, i, j)
                  p_back = entry_position(matrix, b, k_back, j, i)
                  if (abs(matrix%values(p) - matrix%values(p_back)) > tolerance) then
                     symmetric = .false.
                     return
                  end if
               end do
            end do
         end do
      end do
   end function is_symmetric

   !> Value of A(row, column) (1-based equations), 0 when outside the pattern. For tests and
   !> diagnostics: binary search, not for inner loops.
   function entry(matrix, row, column) result(value)
      class(sparse_matrix_t), intent(in) :: matrix
      integer, intent(in) :: row, column
      real(dp) :: value
      integer :: a, b, i, j, k
      value = 0.0_dp
      if (row < 1 .or. row > matrix%n .or. column < 1 .or. column > matrix%n) return
      a = (column - 1)/3 + 1
      i = column - 3*(a - 1)
      b = (row - 1)/3 + 1
      j = row - 3*(b - 1)
      k = neighbour_index(matrix, a, b)
      if (k == 0) return
      value = matrix%values(entry_position(matrix, a, k, i, j))
   end function entry

   !> The diagonal A(e, e), e = 1..n (the self block is always in the pattern at k such that
   !> node_adj = a).
   subroutine get_diagonal(matrix, diagonal)
      class(sparse_matrix_t), intent(in) :: matrix
      real(dp), intent(out) :: diagonal(:)   !! (n)
      integer :: a, i, k
      do a = 1, matrix%n_nodes
         k = neighbour_index(matrix, a, a)
         do i = 1, 3
            diagonal(3*(a - 1) + i) = matrix%values(entry_position(matrix, a, k, i, i))
         end do
      end do
   end subroutine get_diagonal

   !> Number of stored entries (9 * number of coupled node pairs, both orders).
   pure function nnz(matrix) result(count)
      class(sparse_matrix_t), intent(in) :: matrix
      integer(i8) :: count
      count = 0
      if (allocated(matrix%values)) count = size(matrix%values, kind=i8)
   end function nnz

   !> Bytes held by the arrays of the matrix.
   pure function memory_bytes(matrix) result(bytes)
      class(sparse_matrix_t), intent(in) :: matrix
      integer(i8) :: bytes
      bytes = 0
      if (allocated(matrix%values)) bytes = bytes + 8_i8*size(matrix%values, kind=i8)
      if (allocated(matrix%row_index)) bytes = bytes + 8_i8*size(matrix%row_index, kind=i8)
      if (allocated(matrix%col_ptr)) bytes = bytes + 8_i8*size(matrix%col_ptr, kind=i8)
      if (allocated(matrix%node_ptr)) bytes = bytes + 4_i8*size(matrix%node_ptr, kind=i8)
      if (allocated(matrix%node_adj)) bytes = bytes + 4_i8*size(matrix%node_adj, kind=i8)
   end function memory_bytes
   !> Whether nodes a and b are coupled in the pattern.
   pure function couples(matrix, a, b) result(coupled)
      class(sparse_matrix_t), intent(in) :: matrix
      integer, intent(in) :: a, b
      logical :: coupled
      coupled = neighbour_index(matrix, a, b) /= 0
   end function couples

   !> Row e (`rows`) or column e times weights(k) added to the rows (columns) masters(k), then
   !> zeroed (frix_system_matrix). The entries of row e are in the columns of the neighbours n
   !> of e's node s (the pattern is structurally symmetric); those of column e are node s's.
   subroutine move_equation(matrix, e, masters, weights, rows, missing)
      class(sparse_matrix_t), intent(inout) :: matrix
      integer, intent(in) :: e, masters(:)
      real(dp), intent(in) :: weights(:)
      logical, intent(in) :: rows
      integer, intent(out) :: missing(2)
      integer :: k, n, i, a, s, c, source, target, k_master, master_node, master_direction
      real(dp) :: value
      missing = 0
      s = (e + 2)/3
      c = e - 3*(s - 1)
      do k = 1, matrix%node_ptr(s + 1) - matrix%node_ptr(s)
         n = matrix%node_adj(matrix%node_ptr(s) + k - 1)
         do i = 1, 3
            if (rows) then
               source = entry_position(matrix, n, neighbour_index(matrix, n, s), i, c)
            else
               source = entry_position(matrix, s, k, c, i)
            end if
            value = matrix%values(source)
            if (value == 0.0_dp) cycle
            do a = 1, size(masters)
               master_node = (masters(a) + 2)/3
               master_direction = masters(a) - 3*(master_node - 1)
               if (rows) then
                  k_master = neighbour_index(matrix, n, master_node)
               else
                  k_master = neighbour_index(matrix, master_node, n)
               end if
               if (k_master == 0) then
                  missing = [master_node, n]
                  return
               end if
               if (rows) then
                  target = entry_position(matrix, n, k_master, i, master_direction)
               else
                  target = entry_position(matrix, master_node, k_master, master_direction, i)
               end if
               matrix%values(target) = matrix%values(target) + weights(a)*value
            end do
            matrix%values(source) = 0.0_dp
         end do
      end do
   end subroutine move_equation

   !> The column of the first stored entry that is not finite (in storage order), 0 if none.
   subroutine first_non_finite_column(matrix, column, value)
      class(sparse_matrix_t), intent(in) :: matrix
      integer, intent(out) :: column
      real(dp), intent(out) :: value
      integer :: position
      column = 0
      value = 0.0_dp
      if (.not. allocated(matrix%values)) return
      position = first_non_finite(matrix%values)
      if (position == 0) return
      column = 1
      do while (matrix%col_ptr(column) < position)   ! column j holds entries col_ptr(j-1)+1 .. col_ptr(j)
         column = column + 1
      end do
      value = matrix%values(position)
   end subroutine first_non_finite_column

   !> The CSC arrays, for a direct solver's library call: col_ptr(0:n) and row_index (0-based,
   !> SuiteSparse_long) and values. The matrix must be a TARGET where the pointers are used;
   !> they stay valid until the pattern is rebuilt.
   subroutine csc_arrays(matrix, col_ptr, row_index, values)
      class(sparse_matrix_t), intent(in), target :: matrix
      integer(i8), pointer, contiguous, intent(out) :: col_ptr(:), row_index(:)
      real(dp), pointer, contiguous, intent(out) :: values(:)
      col_ptr => matrix%col_ptr
      row_index => matrix%row_index
      values => matrix%values
   end subroutine csc_arrays

   !> The node graph in CSR form (1-based, every list sorted and holding the node itself), for
   !> a fill-reducing ordering of the nodes.
   subroutine node_graph(matrix, node_ptr, node_adj)
      class(sparse_matrix_t), intent(in), target :: matrix
      integer(i4), pointer, contiguous, intent(out) :: node_ptr(:), node_adj(:)
      node_ptr => matrix%node_ptr
      node_adj => matrix%node_adj
   end subroutine node_graph

   !> For every stored entry (1-based position p, row r, column c) the position of the entry
   !> (row c, column r), which the structurally symmetric pattern always stores. The same index
   !> arrays read as compressed sparse ROWS then describe A^T: values(mirror(p)) is A in
   !> compressed rows (for libraries that take rows, such as PETSc's AIJ).
   subroutine mirror_positions(matrix, mirror)
      class(sparse_matrix_t), intent(in) :: matrix
      integer, allocatable, intent(out) :: mirror(:)
      integer :: a, b, k, k_back, i, j
      allocate (mirror(size(matrix%values)))
      do a = 1, matrix%n_nodes
         do k = 1, matrix%node_ptr(a + 1) - matrix%node_ptr(a)
            b = matrix%node_adj(matrix%node_ptr(a) + k - 1)
            k_back = neighbour_index(matrix, b, a)
            do i = 1, 3
               do j = 1, 3
                  mirror(entry_position(matrix, a, k, i, j)) = entry_position(matrix, b, k_back, j, i)
               end do
            end do
         end do
      end do
   end subroutine mirror_positions
end module frix_sparse_matrix
