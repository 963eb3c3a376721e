!> The global system matrix as the rest of frix sees it: what assembly, the constraints, the
!> Newton checks and the linear solvers do with it, not how it is stored.
!>
!> Equations are numbered node-major with 3 DOFs per node: equation 3*(node-1) + i, i = 1, 2, 3
!> the direction (x, y, z). The pattern is structurally symmetric and made of node blocks: node
!> a is coupled to node b when they share an element or a contact pair asked for it; every
!> block is 3 x 3. An implementation keeps its storage private; `sparse_matrix_t`
!> (frix_sparse_matrix, compressed sparse columns for the serial direct solvers) is the one
!> in use. A linear solver allocates the implementation it factorizes (`new_matrix` of
!> frix_linear_solver).
module frix_system_matrix
   use frix_kinds, only: dp, i8
   use frix_error, only: error_t
   implicit none
   private

   public :: system_matrix_t

   type, abstract :: system_matrix_t
      integer :: n = 0                          !! number of equations (3 * n_nodes)
      integer :: n_nodes = 0                    !! number of nodes of the node graph
      integer :: pattern_id = 0                 !! changes at every (re)build of the pattern; 0: none
      integer(i8) :: dropped_entries = 0        !! entries add_element could not place (no error argument given)
      !> add_element adds nothing: on every process but one of a parallel run, while contact
      !> and loads, evaluated on every process, add what process 0 alone contributes
      !> (frix_process_group, docs/parallel.md)
      logical :: ignore_additions = .false.
   contains
      procedure(create_pattern_interface), deferred :: create_node_block_pattern
      procedure(zero_interface), deferred :: zero
      procedure(add_element_interface), deferred :: add_element
      procedure(multiply_interface), deferred :: multiply
      procedure(multiply_interface), deferred :: multiply_transpose
      procedure(dirichlet_interface), deferred :: apply_dirichlet
      procedure(symmetric_interface), deferred :: is_symmetric
      procedure(entry_interface), deferred :: entry
      procedure(diagonal_interface), deferred :: get_diagonal
      procedure(size_interface), deferred :: nnz
      procedure(size_interface), deferred :: memory_bytes
      procedure(couples_interface), deferred :: couples
      procedure(move_equation_interface), deferred :: move_equation
      procedure(non_finite_interface), deferred :: first_non_finite_column
   end type system_matrix_t

   abstract interface
      !> Build the node graph and the pattern; values are zero. Node a is coupled to node b when
      !> both appear in one column of `connectivity` (0 entries are padding) or together in a
      !> column of `extra_pairs`. On error the matrix is left empty (n = 0).
      subroutine create_pattern_interface(matrix, n_nodes, connectivity, extra_pairs, error)
         import :: system_matrix_t, error_t
         class(system_matrix_t), intent(inout) :: matrix
         integer, intent(in) :: n_nodes                     !! number of nodes (equations = 3*n_nodes)
         integer, intent(in) :: connectivity(:, :)          !! (nodes per element, n_elements)
         integer, intent(in), optional :: extra_pairs(:, :) !! (2, m) additional coupled node pairs
         type(error_t), allocatable, intent(out), optional :: error
      end subroutine create_pattern_interface

      !> Every stored value set to zero (pattern kept).
      subroutine zero_interface(matrix)
         import :: system_matrix_t
         class(system_matrix_t), intent(inout) :: matrix
      end subroutine zero_interface

      !> Scatter-add a node-major element matrix: `block(3*(b-1)+j, 3*(a-1)+i)` is the entry of
      !> row (local node b, direction j), column (local node a, direction i). A node pair not in
      !> the pattern sets `error` if present, else counts in `dropped_entries`.
      subroutine add_element_interface(matrix, nodes, block, error)
         import :: system_matrix_t, error_t, dp
         class(system_matrix_t), intent(inout) :: matrix
         integer, intent(in) :: nodes(:)        !! global node numbers of the element's local nodes
         real(dp), intent(in) :: block(:, :)    !! (3*size(nodes), 3*size(nodes))
         type(error_t), allocatable, intent(out), optional :: error
      end subroutine add_element_interface

      !> y = A x (multiply) or y = A^T x (multiply_transpose).
      subroutine multiply_interface(matrix, x, y)
         import :: system_matrix_t, dp
         class(system_matrix_t), intent(in) :: matrix
         real(dp), intent(in) :: x(:)    !! (n)
         real(dp), intent(out) :: y(:)   !! (n)
      end subroutine multiply_interface

      !> Homogeneous Dirichlet conditions: every entry of a fixed row or column becomes 0, the
      !> diagonal of a fixed equation `diagonal_value`. Symmetry is kept.
      subroutine dirichlet_interface(matrix, fixed, diagonal_value)
         import :: system_matrix_t, dp
         class(system_matrix_t), intent(inout) :: matrix
         logical, intent(in) :: fixed(:)            !! (n) .true. for a fixed equation
         real(dp), intent(in) :: diagonal_value
      end subroutine dirichlet_interface

      !> |A(i,j) - A(j,i)| <= rel_tol * max|A| for every stored entry.
      function symmetric_interface(matrix, rel_tol) result(symmetric)
         import :: system_matrix_t, dp
         class(system_matrix_t), intent(in) :: matrix
         real(dp), intent(in) :: rel_tol
         logical :: symmetric
      end function symmetric_interface

      !> A(row, column) (1-based equations), 0 outside the pattern; for tests and diagnostics.
      function entry_interface(matrix, row, column) result(value)
         import :: system_matrix_t, dp
         class(system_matrix_t), intent(in) :: matrix
         integer, intent(in) :: row, column
         real(dp) :: value
      end function entry_interface

      subroutine diagonal_interface(matrix, diagonal)
         import :: system_matrix_t, dp
         class(system_matrix_t), intent(in) :: matrix
         real(dp), intent(out) :: diagonal(:)   !! (n) A(e, e)
      end subroutine diagonal_interface

      !> Stored entries (nnz) or bytes held (memory_bytes).
      pure function size_interface(matrix) result(count)
         import :: system_matrix_t, i8
         class(system_matrix_t), intent(in) :: matrix
         integer(i8) :: count
      end function size_interface

      !> Whether nodes a and b are coupled in the pattern (the pair's blocks are stored).
      pure function couples_interface(matrix, a, b) result(coupled)
         import :: system_matrix_t
         class(system_matrix_t), intent(in) :: matrix
         integer, intent(in) :: a, b
         logical :: coupled
      end function couples_interface

      !> Row e (`rows`) or column e of the matrix times weights(k) added to the rows (columns)
      !> masters(k), then zeroed: the elimination of a dependent equation u_e = sum w_k u_mk.
      !> A pair of nodes the move needs but the pattern lacks is returned in `missing`
      !> ((master node, other node); 0 when none) and the move stops there.
      subroutine move_equation_interface(matrix, e, masters, weights, rows, missing)
         import :: system_matrix_t, dp
         class(system_matrix_t), intent(inout) :: matrix
         integer, intent(in) :: e, masters(:)
         real(dp), intent(in) :: weights(:)
         logical, intent(in) :: rows
         integer, intent(out) :: missing(2)
      end subroutine move_equation_interface

      !> The column (equation) holding the first stored entry that is not finite, and that
      !> entry; column 0 when every entry is finite.
      subroutine non_finite_interface(matrix, column, value)
         import :: system_matrix_t, dp
         class(system_matrix_t), intent(in) :: matrix
         integer, intent(out) :: column
         real(dp), intent(out) :: value
      end subroutine non_finite_interface
   end interface
end module frix_system_matrix
