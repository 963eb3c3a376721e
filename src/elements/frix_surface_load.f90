!> Pressure loads on a 4-node bilinear quadrilateral face (a HEX8 face), 2 x 2 Gauss points.
!>
!> Face node order: counter-clockwise seen from outside the body, so that the area vector
!> a = x_,xi x x_,eta (right-hand rule) points out of the body. Parent coordinates of the
!> nodes: (-1,-1), (1,-1), (1,1), (-1,1); N_a = (1 + xi xi_a)(1 + eta eta_a) / 4.
!>
!> Sign convention: a pressure p > 0 is compressive, it pushes INTO the body: the traction is
!> t = -p n with n the outward unit normal, and the equivalent nodal forces are
!>   f_a = -p integral N_a (x_,xi x x_,eta) dxi deta   (dA n = x_,xi x x_,eta dxi deta).
!> Force vectors are node-major: entry 3*(a-1)+i is direction i of face node a.
!> x_,xi x x_,eta is linear in (xi, eta) on a bilinear face, so the 2 x 2 rule integrates
!> f_a exactly; the total force is -p (vector area) = -p (d1 x d2)/2 with the diagonals
!> d1 = x3 - x1, d2 = x4 - x2 (exact also for a warped face).
module frix_surface_load
   use frix_kinds, only: dp
   use frix_vector_algebra, only: cross_product, skew
   use frix_quad4_cell, only: quad4_corner, quad4_gauss_points
   implicit none
   private

   public :: pressure_load, face_area_weights
   public :: face_node_xi, face_node_eta, face_shape_functions

   !> Natural coordinates of the face nodes and of the 2 x 2 Gauss points (weights 1): the
   !> QUAD4 reference cell's (frix_quad4_cell).
   real(dp), parameter :: face_node_xi(4) = real(quad4_corner(1, :), dp)
   real(dp), parameter :: face_node_eta(4) = real(quad4_corner(2, :), dp)
   real(dp), parameter :: point_xi(4) = quad4_gauss_points(1, :)
   real(dp), parameter :: point_eta(4) = quad4_gauss_points(2, :)

contains

   !> Equivalent nodal forces of a uniform pressure on one face, and for a follower load the
   !> load stiffness.
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
   pure subroutine pressure_load(coords, u, pressure, follower, force, tangent)
      real(dp), intent(in) :: coords(3, 4)    !! reference coordinates of the face nodes
      real(dp), intent(in) :: u(3, 4)         !! total displacements of the face nodes
      real(dp), intent(in) :: pressure        !! p (stress unit), > 0 pushes into the body
      logical, intent(in) :: follower         !! .true.: current normal and area
      real(dp), intent(out) :: force(12)      !! fext (force unit), node-major
      real(dp), intent(out), optional :: tangent(12, 12)  !! d fext / d u (0 for a dead load)
      real(dp) :: x(3, 4), shape(4), d_xi(4), d_eta(4), g_xi(3), g_eta(3), area_vector(3)
      real(dp) :: block(3, 3)
      integer :: point, a, b

      force = 0.0_dp
      if (present(tangent)) tangent = 0.0_dp
      if (follower) then
         x = coords + u
      else
         x = coords
      end if

      do point = 1, 4
         call face_shape_functions([point_xi(point), point_eta(point)], shape, d_xi, d_eta)
         g_xi = matmul(x, d_xi)
         g_eta = matmul(x, d_eta)
         area_vector = cross_product(g_xi, g_eta)
         do a = 1, 4
            force(3*a - 2:3*a) = force(3*a - 2:3*a) - pressure*shape(a)*area_vector
         end do
         if (follower .and. present(tangent)) then
            do b = 1, 4
               block = d_eta(b)*skew(g_xi) - d_xi(b)*skew(g_eta)
               do a = 1, 4
                  tangent(3*a - 2:3*a, 3*b - 2:3*b) = tangent(3*a - 2:3*a, 3*b - 2:3*b) &
                                                      - pressure*shape(a)*block
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
         call face_shape_functions([point_xi(point), point_eta(point)], shape, d_xi, d_eta)
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
