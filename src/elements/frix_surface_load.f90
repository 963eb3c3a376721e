!> Pressure loads on an element face of any face cell (frix_reference_cell of dimension 2:
!> QUAD4 of a HEX8, TRI3 of a TET4, TRI6 of a TET10), integrated with the face cell's rule
!> (QUAD4: 2 x 2 Gauss points; TRI3 and TRI6: 3 interior points, degree 2).
!>
!> Face node order: counter-clockwise seen from outside the body, so that the area vector
!> a = x_,xi x x_,eta (right-hand rule) points out of the body (frix_mesh's faces are listed so).
!>
!> Sign convention: a pressure p > 0 is compressive, it pushes INTO the body: the traction is
!> t = -p n with n the outward unit normal, and the equivalent nodal forces are
!>   f_a = -p integral N_a (x_,xi x x_,eta) dxi deta   (dA n = x_,xi x x_,eta dxi deta).
!> Force vectors are node-major: entry 3*(a-1)+i is direction i of face node a.
!> On a bilinear face x_,xi x x_,eta is linear in (xi, eta), so the 2 x 2 rule integrates
!> f_a exactly; the total force is -p (vector area) = -p (d1 x d2)/2 with the diagonals
!> d1 = x3 - x1, d2 = x4 - x2 (exact also for a warped face). On a flat triangle with straight
!> edges x_,xi x x_,eta is constant and N_a of degree 1 or 2, so the 3-point rule is exact and
!> the total force -p A n (sum_a N_a = 1).
module frix_surface_load
   use frix_kinds, only: dp
   use frix_vector_algebra, only: cross_product, skew
   use frix_quad4_cell, only: quad4_corner, quad4_gauss_points
   use frix_reference_cell, only: reference_cell_t
   implicit none
   private

   public :: pressure_load, face_area_weights
   public :: face_node_xi, face_node_eta, face_shape_functions

   !> Natural coordinates of the nodes of a QUAD4 face (frix_quad4_cell), for the contact
   !> modules and face_area_weights.
   real(dp), parameter :: face_node_xi(4) = real(quad4_corner(1, :), dp)
   real(dp), parameter :: face_node_eta(4) = real(quad4_corner(2, :), dp)

contains

   !> Equivalent nodal forces of a uniform pressure on one face of cell `face`, and for a
   !> follower load the load stiffness.
   !>
   !> Dead load (`follower = .false.`): p acts per unit REFERENCE area along the reference
   !> normal (the face geometry is `coords`; `u` is not used); the load does not depend on u,
   !> so `tangent` is zero.
   !> Follower load (`follower = .true.`): p acts per unit CURRENT area along the current
   !> normal of x = coords + u, and
   !>   tangent = K_load = d fext / d u,
   !>   K_load(a, b) = -p integral N_a (N_b,eta [x_,xi]x - N_b,xi [x_,eta]x) dxi deta,
   !> with [v]x w = v x w. K_load is unsymmetric in general. Since the residual is
   !> fext - fint, the caller adds -K_load to the stiffness d fint / d u.
   pure subroutine pressure_load(face, coords, u, pressure, follower, force, tangent)
      class(reference_cell_t), intent(in) :: face   !! the face's cell (dimension 2)
      real(dp), intent(in) :: coords(:, :)    !! (3, face nodes) reference coordinates of the face nodes
      real(dp), intent(in) :: u(:, :)         !! (3, face nodes) total displacements of the face nodes
      real(dp), intent(in) :: pressure        !! p (stress unit), > 0 pushes into the body
      logical, intent(in) :: follower         !! .true.: current normal and area
      real(dp), intent(out) :: force(:)       !! (3 face nodes) fext (force unit), node-major
      real(dp), intent(out), optional :: tangent(:, :)  !! (3 face nodes, same) d fext / d u (0 for a dead load)
      real(dp) :: x(3, face%n_nodes), shape(face%n_nodes), derivatives(2, face%n_nodes)
      real(dp) :: g_xi(3), g_eta(3), area_vector(3), block(3, 3), weighted
      integer :: point, a, b, n

      n = face%n_nodes
      force(1:3*n) = 0.0_dp
      if (present(tangent)) tangent(1:3*n, 1:3*n) = 0.0_dp
      if (follower) then
         x = coords(:, 1:n) + u(:, 1:n)
      else
         x = coords(:, 1:n)
      end if

      do point = 1, face%n_points()
         call face%shape_functions(face%points(:, point), shape, derivatives)
         g_xi = matmul(x, derivatives(1, :))
         g_eta = matmul(x, derivatives(2, :))
         area_vector = cross_product(g_xi, g_eta)
         weighted = pressure*face%weights(point)
         do a = 1, n
            force(3*a - 2:3*a) = force(3*a - 2:3*a) - weighted*shape(a)*area_vector
         end do
         if (follower .and. present(tangent)) then
            do b = 1, n
               block = derivatives(2, b)*skew(g_xi) - derivatives(1, b)*skew(g_eta)
               do a = 1, n
                  tangent(3*a - 2:3*a, 3*b - 2:3*b) = tangent(3*a - 2:3*a, 3*b - 2:3*b) &
                                                      - weighted*shape(a)*block
               end do
            end do
         end if
      end do
   end subroutine pressure_load

   !> Tributary areas of the face nodes: weights(a) = integral over the reference face of
   !> N_a dA0 (area unit), 2 x 2 Gauss (exact for a plane face, whose |x_,xi x x_,eta| is
   !> linear in xi and eta). Their sum is the face area.
   pure subroutine face_area_weights(coords, weights)
      real(dp), intent(in) :: coords(3, 4)  !! reference coordinates of the face nodes
      real(dp), intent(out) :: weights(4)   !! integral of N_a dA0
      real(dp) :: shape(4), d_xi(4), d_eta(4)
      integer :: point
      weights = 0.0_dp
      do point = 1, 4
         call face_shape_functions(quad4_gauss_points(:, point), shape, d_xi, d_eta)
         weights = weights + shape*norm2(cross_product(matmul(coords, d_xi), matmul(coords, d_eta)))
      end do
   end subroutine face_area_weights

   !> Bilinear shape functions N_a(xi) = (1 + xi xi_a)(1 + eta eta_a)/4 of the quadrilateral
   !> face and their parent derivatives dN_a/dxi, dN_a/deta, at xi = (xi, eta) (also outside
   !> [-1, 1]^2: the bilinear extrapolation). Used by the contact modules too.
   pure subroutine face_shape_functions(xi, shape, d_xi, d_eta)
      real(dp), intent(in) :: xi(2)          !! parent coordinates (xi, eta)
      real(dp), intent(out) :: shape(4), d_xi(4), d_eta(4)
      shape = 0.25_dp*(1.0_dp + xi(1)*face_node_xi)*(1.0_dp + xi(2)*face_node_eta)
      d_xi = 0.25_dp*face_node_xi*(1.0_dp + xi(2)*face_node_eta)
      d_eta = 0.25_dp*face_node_eta*(1.0_dp + xi(1)*face_node_xi)
   end subroutine face_shape_functions
end module frix_surface_load
