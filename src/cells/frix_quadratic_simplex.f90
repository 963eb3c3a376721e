!> The quadratic shape functions of a simplex (6-node triangle, 10-node tetrahedron), written
!> once over its barycentric coordinates: N_a = L_a (2 L_a - 1) at corner a and N_m = 4 L_i L_j
!> at the node m in the middle of edge i-j (Zienkiewicz & Taylor, vol. 1, 8.8), with their
!> derivatives by the chain rule through the constant dL_i/dxi.
module frix_quadratic_simplex
   use frix_kinds, only: dp
   implicit none
   private

   public :: quadratic_simplex_shape

contains

   !> Values (corners, then one node per edge) and natural derivatives (dimension, nodes) at
   !> the barycentric coordinates `l` (corners) with gradients `gradient` (dimension, corners);
   !> `edge_corners(:, k)` are the two corners of the k-th mid-edge node.
   pure subroutine quadratic_simplex_shape(l, gradient, edge_corners, values, derivatives)
      real(dp), intent(in) :: l(:), gradient(:, :)
      integer, intent(in) :: edge_corners(:, :)
      real(dp), intent(out) :: values(:), derivatives(:, :)
      integer :: a, k, i, j, n_corners
      n_corners = size(l)
      do a = 1, n_corners
         values(a) = l(a)*(2.0_dp*l(a) - 1.0_dp)
         derivatives(:, a) = (4.0_dp*l(a) - 1.0_dp)*gradient(:, a)
      end do
      do k = 1, size(edge_corners, 2)
         i = edge_corners(1, k)
         j = edge_corners(2, k)
         values(n_corners + k) = 4.0_dp*l(i)*l(j)
         derivatives(:, n_corners + k) = 4.0_dp*(l(j)*gradient(:, i) + l(i)*gradient(:, j))
      end do
   end subroutine quadratic_simplex_shape

end module frix_quadratic_simplex
