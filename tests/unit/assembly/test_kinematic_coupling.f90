!> Kinematic couplings (frix_kinematic_coupling) and their elimination
!> (frix_constraint_equations): the weights give theta x r, and with rows whose masters lie in
!> other directions (the rotations) the in-place T^T K T, T^T v and T u match dense products.
module test_kinematic_coupling
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close
   use frix_sparse_matrix, only: sparse_matrix_t
   use frix_mesh, only: mesh_t
   use frix_model, only: model_t, kinematic_coupling_t
   use frix_constraint_equations, only: constraint_equations_t
   use frix_kinematic_coupling, only: add_coupling_equations, rigid_motion_weights
   use elimination_checks, only: check_elimination
   implicit none
   private

   public :: collect_kinematic_coupling

contains

   subroutine collect_kinematic_coupling(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('rigid motion weights: W theta = theta x r', test_weights), &
               new_unittest('coupling elimination: T^T K T, T^T v, T u against dense products', test_elimination)]
   end subroutine collect_kinematic_coupling

   subroutine test_weights(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: r(3) = [0.3_dp, -1.7_dp, 2.2_dp], theta(3) = [-0.4_dp, 0.9_dp, 0.25_dp]
      real(dp) :: expected(3), got(3)
      integer :: c
      expected = [theta(2)*r(3) - theta(3)*r(2), theta(3)*r(1) - theta(1)*r(3), theta(1)*r(2) - theta(2)*r(1)]
      got = matmul(rigid_motion_weights(r), theta)
      do c = 1, 3
         call check_close(error, got(c), expected(c), 1.0e-15_dp, message='theta x r')
         if (allocated(error)) return
      end do
   end subroutine test_weights

   !> Nodes 1-2 of one "element" with nodes 3 and 4 (coupled); node 5 the reference node at
   !> (1, 2, 3), node 6 the rotation node, both in no element. Node 4 fixed in y (not dependent
   !> there). K symmetric pseudo-random on the element's nodes; T built densely from
   !> u_i = u_R + W(X_i - X_R) theta.
   subroutine test_elimination(error)
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: n = 18
      type(model_t) :: model
      type(constraint_equations_t) :: constraints
      type(sparse_matrix_t) :: matrix
      integer, allocatable :: pairs(:, :)
      real(dp) :: dense(n, n), t(n, n), w(3, 3)
      logical :: dependent(n)
      integer :: i, j, node, connectivity(4, 1)
      model%mesh%n_nodes = 6
      model%mesh%coords = reshape([0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, 0.5_dp, &
                                   0.0_dp, 1.0_dp, 2.0_dp, 1.0_dp, 2.0_dp, 3.0_dp, 9.0_dp, 9.0_dp, 9.0_dp], [3, 6])
      connectivity(:, 1) = [1, 2, 3, 4]
      ! component by component: gfortran 12 leaks the temporary of an array constructor of a
      ! structure constructor with an allocatable component (LeakSanitizer)
      allocate (model%couplings(1))
      model%couplings(1)%id = 1
      model%couplings(1)%reference_node = 5
      model%couplings(1)%rotation_node = 6
      model%couplings(1)%nodes = [3, 4]
      call add_coupling_equations(model, constraints)
      call check(error, constraints%n_rows == 6, 'three rows per coupled node')
      if (allocated(error)) return
      call constraints%pattern_pairs(6, connectivity, pairs)
      call matrix%create_node_block_pattern(6, connectivity, pairs)
      dense = 0.0_dp
      do j = 1, 12
         do i = 1, j
            dense(i, j) = sin(real(7*i + 13*j, dp)) + merge(10.0_dp, 0.0_dp, i == j)
            dense(j, i) = dense(i, j)
         end do
      end do
      call matrix%add_element([1, 2, 3, 4], dense(:12, :12))
      dependent = .false.
      dependent(7:12) = .true.
      dependent(11) = .false.   ! node 4, y: fixed
      t = 0.0_dp
      do i = 1, n
         if (.not. dependent(i)) t(i, i) = 1.0_dp
      end do
      do node = 3, 4
         w = rigid_motion_weights(model%mesh%coords(:, node) - model%mesh%coords(:, 5))
         do i = 1, 3
            if (.not. dependent(3*node - 3 + i)) cycle
            t(3*node - 3 + i, 12 + i) = 1.0_dp
            t(3*node - 3 + i, 16:18) = w(i, :)
         end do
      end do
      call check_elimination(constraints, dependent, matrix, dense, t, 1.0e-12_dp, 1.0e-13_dp, error)
   end subroutine test_elimination
end module test_kinematic_coupling
