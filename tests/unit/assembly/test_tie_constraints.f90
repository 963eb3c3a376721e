!> Ties: the dual mortar weights of frix_tie_mortar on flat grids (rows sum to 1, a linear
!> field is reproduced, the slave areas spread over the master nodes as the master's own
!> areas: the conditions of the patch test; matching grids give the identity) and the
!> elimination of the ties' rows (frix_tie_constraints, frix_constraint_equations) against the dense T^T K T, T^T v and T u.
module test_tie_constraints
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close
   use frix_sparse_matrix, only: sparse_matrix_t
   use frix_tie_mortar, only: tie_coupling_t, mortar_coupling
   use frix_contact_pass, only: contact_pass_t
   use frix_constraint_equations, only: constraint_equations_t
   use frix_tie_constraints, only: add_tie_equations
   use elimination_checks, only: check_elimination
   implicit none
   private

   public :: collect_tie_constraints

contains

   subroutine collect_tie_constraints(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('mortar weights, 3 x 3 slave on 4 x 4 master: patch-test conditions', test_non_matching), &
               new_unittest('mortar weights, 4 x 4 slave on 3 x 3 master', test_non_matching_reversed), &
               new_unittest('mortar weights, matching grids: the identity', test_matching), &
               new_unittest('elimination: T^T K T, T^T v, T u against dense products', test_elimination)]
   end subroutine collect_tie_constraints

   !> An n x n grid of faces on the unit square at height z (nodes numbered from `first`, x
   !> fastest), its faces counter-clockwise seen from +z (up = .true.) or from -z.
   subroutine square_grid(n, z, first, up, coords, faces)
      integer, intent(in) :: n, first
      real(dp), intent(in) :: z
      logical, intent(in) :: up
      real(dp), intent(inout) :: coords(:, :)
      integer, allocatable, intent(out) :: faces(:, :)
      integer :: i, j, k
      do j = 0, n
         do i = 0, n
            coords(:, first + i + (n + 1)*j) = [real(i, dp)/n, real(j, dp)/n, z]
         end do
      end do
      allocate (faces(4, n*n))
      k = 0
      do j = 0, n - 1
         do i = 0, n - 1
            k = k + 1
            faces(:, k) = first + [i + (n + 1)*j, i + 1 + (n + 1)*j, i + 1 + (n + 1)*(j + 1), i + (n + 1)*(j + 1)]
            if (.not. up) faces(:, k) = faces([1, 4, 3, 2], k)
         end do
      end do
   end subroutine square_grid

   !> Tributary area of grid node (i, j) of an n x n grid on the unit square.
   pure real(dp) function grid_area(n, i, j)
      integer, intent(in) :: n, i, j
      grid_area = merge(0.5_dp, 1.0_dp, i == 0 .or. i == n)*merge(0.5_dp, 1.0_dp, j == 0 .or. j == n)/real(n*n, dp)
   end function grid_area

   !> Slave grid n_s x n_s (facing down, z = 0.5) on master grid n_m x n_m (facing up): each
   !> row sums to 1, sum_a w_sa X_a = X_s, sum_s w_sa A_s = A_a.
   subroutine check_weights(n_s, n_m, error)
      integer, intent(in) :: n_s, n_m
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: coords(:, :), spread_area(:)
      integer, allocatable :: slave_faces(:, :), master_faces(:, :), slave_nodes(:)
      type(tie_coupling_t) :: coupling
      real(dp) :: position(3), largest_position, largest_area, largest_sum
      integer :: n_master, s, k, i, j, node
      n_master = (n_m + 1)**2
      allocate (coords(3, n_master + (n_s + 1)**2))
      call square_grid(n_m, 0.5_dp, 1, .true., coords, master_faces)
      call square_grid(n_s, 0.5_dp, n_master + 1, .false., coords, slave_faces)
      slave_nodes = [(n_master + s, s=1, (n_s + 1)**2)]
      call mortar_coupling(coords, slave_nodes, slave_faces, master_faces, 0.01_dp, coupling)
      allocate (spread_area(n_master), source=0.0_dp)
      largest_position = 0.0_dp
      largest_sum = 0.0_dp
      do s = 1, size(slave_nodes)
         associate (nodes => coupling%nodes(coupling%start(s) + 1:coupling%start(s + 1)), &
                    weights => coupling%weight(coupling%start(s) + 1:coupling%start(s + 1)))
            largest_sum = max(largest_sum, abs(sum(weights) - 1.0_dp), abs(coupling%covered(s) - 1.0_dp))
            position = matmul(coords(:, nodes), weights)
            largest_position = max(largest_position, maxval(abs(position - coords(:, slave_nodes(s)))))
            i = mod(s - 1, n_s + 1)
            j = (s - 1)/(n_s + 1)
            spread_area(nodes) = spread_area(nodes) + weights*grid_area(n_s, i, j)
         end associate
      end do
      largest_area = 0.0_dp
      do node = 1, n_master
         i = mod(node - 1, n_m + 1)
         j = (node - 1)/(n_m + 1)
         largest_area = max(largest_area, abs(spread_area(node) - grid_area(n_m, i, j))/grid_area(n_m, i, j))
      end do
      call check(error, largest_sum < 1.0e-12_dp, 'rows sum to 1 and the master covers the slave')
      if (allocated(error)) return
      call check(error, largest_position < 1.0e-13_dp, 'a linear field is reproduced')
      if (allocated(error)) return
      call check(error, largest_area < 1.0e-12_dp, 'the slave areas spread as the master areas')
      if (allocated(error)) return
      k = coupling%start(2) - coupling%start(1)
      call check(error, k > 0, 'the corner node is tied')
   end subroutine check_weights

   subroutine test_non_matching(error)
      type(error_t), allocatable, intent(out) :: error
      call check_weights(3, 4, error)
   end subroutine test_non_matching

   subroutine test_non_matching_reversed(error)
      type(error_t), allocatable, intent(out) :: error
      call check_weights(4, 3, error)
   end subroutine test_non_matching_reversed

   !> Matching 2 x 2 grids: each slave node has one master node, weight 1, at its place.
   subroutine test_matching(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: coords(3, 18)
      integer, allocatable :: slave_faces(:, :), master_faces(:, :)
      type(tie_coupling_t) :: coupling
      integer :: s
      call square_grid(2, 0.0_dp, 1, .true., coords, master_faces)
      call square_grid(2, 0.0_dp, 10, .false., coords, slave_faces)
      call mortar_coupling(coords, [(9 + s, s=1, 9)], slave_faces, master_faces, 0.01_dp, coupling)
      do s = 1, 9
         call check(error, coupling%start(s + 1) - coupling%start(s) == 1, 'one master node')
         if (allocated(error)) return
         call check(error, coupling%nodes(coupling%start(s) + 1) == s, 'the coincident node')
         if (allocated(error)) return
         call check_close(error, coupling%weight(coupling%start(s) + 1), 1.0_dp, 1.0e-13_dp, message='weight 1')
         if (allocated(error)) return
      end do
   end subroutine test_matching

   !> Six nodes, all coupled; slave nodes 5 and 6 tied to nodes 1-4 with given weights, node 6
   !> fixed in z (not dependent there). K symmetric pseudo-random; compare with dense T.
   subroutine test_elimination(error)
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: n = 18
      type(sparse_matrix_t) :: matrix
      type(contact_pass_t) :: pass(1)
      type(constraint_equations_t) :: constraints
      real(dp) :: dense(n, n), t(n, n)
      logical :: dependent(n)
      integer :: i, j, connectivity(6, 1)
      connectivity(:, 1) = [1, 2, 3, 4, 5, 6]
      call matrix%create_node_block_pattern(6, connectivity)
      do j = 1, n
         do i = 1, j
            dense(i, j) = sin(real(7*i + 13*j, dp)) + merge(10.0_dp, 0.0_dp, i == j)
            dense(j, i) = dense(i, j)
         end do
      end do
      call matrix%add_element([1, 2, 3, 4, 5, 6], dense)
      pass(1)%tied = .true.
      pass(1)%slave_nodes = [5, 6]
      pass(1)%face = [1, 1]
      pass(1)%tie%start = [0, 4, 7]
      pass(1)%tie%nodes = [1, 2, 3, 4, 2, 3, 4]
      pass(1)%tie%weight = [0.1_dp, 0.2_dp, 0.3_dp, 0.4_dp, 0.5_dp, -0.25_dp, 0.75_dp]
      call add_tie_equations(pass, constraints)
      dependent = .false.
      dependent(13:17) = .true.   ! node 5 x y z, node 6 x y
      ! T: identity but for the dependent rows, which hold the weights
      t = 0.0_dp
      do i = 1, n
         if (.not. dependent(i)) t(i, i) = 1.0_dp
      end do
      do i = 1, 3
         t(12 + i, [1, 2, 3, 4]*3 - 3 + i) = [0.1_dp, 0.2_dp, 0.3_dp, 0.4_dp]
         if (i < 3) t(15 + i, [2, 3, 4]*3 - 3 + i) = [0.5_dp, -0.25_dp, 0.75_dp]
      end do
      call check_elimination(constraints, dependent, matrix, dense, t, 1.0e-13_dp, 1.0e-14_dp, error)
   end subroutine test_elimination
end module test_tie_constraints
