!> Meshes, reproducible pseudo-random element matrices and a dense reference assembly for
!> the linalg tests. The dense assembly is the independent computation every sparse result
!> is compared against.
module test_linalg_fixtures
   use frix_kinds, only: dp, i8
   implicit none
   private

   public :: cube_connectivity, fill_random, spd_block, unsymmetric_block, laplacian_block, dense_add

contains

   !> Structured HEX8 brick of n_x * n_y * n_z unit elements; node (i, j, k), 0-based grid
   !> indices, is number 1 + i + (n_x+1)*(j + (n_y+1)*k). Local order: bottom face
   !> counter-clockwise, then top face (the HEX8 order of frix_mesh).
   subroutine cube_connectivity(n_x, n_y, n_z, connectivity, n_nodes)
      integer, intent(in) :: n_x, n_y, n_z
      integer, allocatable, intent(out) :: connectivity(:, :)
      integer, intent(out) :: n_nodes
      integer :: i, j, k, e
      n_nodes = (n_x + 1)*(n_y + 1)*(n_z + 1)
      allocate (connectivity(8, n_x*n_y*n_z))
      e = 0
      do k = 0, n_z - 1
         do j = 0, n_y - 1
            do i = 0, n_x - 1
               e = e + 1
               connectivity(:, e) = [node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k), &
                                     node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1), &
                                     node(i, j + 1, k + 1)]
            end do
         end do
      end do
   contains
      pure integer function node(i, j, k)
         integer, intent(in) :: i, j, k
         node = 1 + i + (n_x + 1)*(j + (n_y + 1)*k)
      end function node
   end subroutine cube_connectivity

   !> Uniform numbers in (-1, 1) from the Park-Miller minimal standard generator
   !> (x <- 16807 x mod (2^31 - 1)); reproducible on every compiler, no overflow in i8.
   subroutine fill_random(state, values)
      integer(i8), intent(inout) :: state   !! generator state, 1 <= state < 2^31 - 1
      real(dp), intent(out) :: values(:, :)
      integer :: i, j
      do j = 1, size(values, 2)
         do i = 1, size(values, 1)
            state = mod(16807_i8*state, 2147483647_i8)
            values(i, j) = 2.0_dp*real(state, dp)/2147483647.0_dp - 1.0_dp
         end do
      end do
   end subroutine fill_random

   !> Symmetric positive definite block G^T G + I (G random): eigenvalues >= 1.
   subroutine spd_block(state, block)
      integer(i8), intent(inout) :: state
      real(dp), intent(out) :: block(:, :)
      real(dp) :: g(size(block, 1), size(block, 1))
      integer :: i
      call fill_random(state, g)
      block = matmul(transpose(g), g)
      do i = 1, size(block, 1)
         block(i, i) = block(i, i) + 1.0_dp
      end do
   end subroutine spd_block

   !> Unsymmetric block G^T G + I + (H - H^T): its symmetric part is SPD, so x^T A x > 0 and
   !> any sum of such blocks is nonsingular.
   subroutine unsymmetric_block(state, block)
      integer(i8), intent(inout) :: state
      real(dp), intent(out) :: block(:, :)
      real(dp) :: h(size(block, 1), size(block, 1))
      call spd_block(state, block)
      call fill_random(state, h)
      block = block + h - transpose(h)
   end subroutine unsymmetric_block

   !> Node-blocked graph Laplacian of the complete graph of the element's nodes, times I3:
   !> block(3(a-1)+i, 3(b-1)+j) = (m delta_ab - 1) delta_ij, m = number of nodes. Positive
   !> semidefinite; constant vectors per direction are its null space, so an assembly without
   !> Dirichlet conditions is singular.
   subroutine laplacian_block(n_element_nodes, block)
      integer, intent(in) :: n_element_nodes
      real(dp), intent(out) :: block(:, :)
      integer :: a, b, i
      block = 0.0_dp
      do a = 1, n_element_nodes
         do b = 1, n_element_nodes
            do i = 1, 3
               block(3*(a - 1) + i, 3*(b - 1) + i) = -1.0_dp
               if (a == b) block(3*(a - 1) + i, 3*(b - 1) + i) = real(n_element_nodes - 1, dp)
            end do
         end do
      end do
   end subroutine laplacian_block

   !> Dense reference assembly: dense(3(nb-1)+j, 3(na-1)+i) += block(3(b-1)+j, 3(a-1)+i).
   subroutine dense_add(dense, nodes, block)
      real(dp), intent(inout) :: dense(:, :)
      integer, intent(in) :: nodes(:)
      real(dp), intent(in) :: block(:, :)
      integer :: a, b, i, j
      do a = 1, size(nodes)
         do i = 1, 3
            do b = 1, size(nodes)
               do j = 1, 3
                  dense(3*(nodes(b) - 1) + j, 3*(nodes(a) - 1) + i) = &
                     dense(3*(nodes(b) - 1) + j, 3*(nodes(a) - 1) + i) + block(3*(b - 1) + j, 3*(a - 1) + i)
               end do
            end do
         end do
      end do
   end subroutine dense_add
end module test_linalg_fixtures
