!> Closest-point projection of a point onto a 4-node bilinear quadrilateral face (plain reals).
!>
!> Face geometry: x(xi) = sum_a N_a(xi) x_a, xi = (xi1, xi2) in [-1, 1]^2, parent corners
!> (-1,-1), (1,-1), (1,1), (-1,1), N_a = (1 + xi1 xi1_a)(1 + xi2 xi2_a)/4. With the HEX8 face
!> order of frix_mesh (counter-clockwise seen from outside) the unit normal
!> n = (x_,1 x x_,2)/|x_,1 x x_,2| points OUT of the body that owns the face.
!>
!> Closest point (Wriggers, *Computational Contact Mechanics*, 2nd ed., Springer 2006, 4.1):
!> xi* minimises f(xi) = |p - x(xi)|^2 / 2, i.e. solves r_i = -(p - x).x_,i = 0. Newton with
!> the exact Hessian H_ij = x_,i . x_,j - (p - x) . x_,ij (x_,11 = x_,22 = 0 on a bilinear face,
!> x_,12 = sum_a xi1_a xi2_a x_a / 4), falling back to the Gauss-Newton matrix x_,i . x_,j when
!> H is not positive definite (far from a strongly warped face), steps limited to a length 1
!> in parent coordinates. xi* may lie outside [-1, 1]^2 (the point projects beyond an edge):
!> `closest_point_in_face` gives the closest point of the bounded face instead (on an edge or
!> at a corner). This module is used by the contact kernel and by the contact search.
module frix_face_projection
   use frix_kinds, only: dp
   use frix_vector_algebra, only: cross_product
   use frix_surface_load, only: face_node_xi, face_node_eta, face_shape_functions
   implicit none
   private

   !> Re-exported from frix_surface_load (the one definition of the bilinear face).
   public :: face_node_xi, face_node_eta, face_shape_functions
   public :: face_position, face_normal
   public :: project_onto_face, closest_point_in_face, face_contains

   integer, parameter :: max_iterations = 50
   !> Newton stops when the step is below this (parent coordinates, i.e. relative to the face
   !> size) and then takes one more step, which brings xi to round-off.
   real(dp), parameter :: step_tolerance = 1.0e-12_dp

contains

   !> x(xi) = sum_a N_a(xi) x_a (also for xi outside [-1, 1]^2: the bilinear extrapolation).
   pure function face_position(x_face, xi) result(x)
      real(dp), intent(in) :: x_face(3, 4)   !! node coordinates, face order
      real(dp), intent(in) :: xi(2)
      real(dp) :: x(3)
      real(dp) :: shape(4), d_xi(4), d_eta(4)
      call face_shape_functions(xi, shape, d_xi, d_eta)
      x = matmul(x_face, shape)
   end function face_position

   !> Unit normal (x_,1 x x_,2)/|x_,1 x x_,2| at xi (outward for the HEX8 face order); the zero
   !> vector where x_,1 x x_,2 = 0 (a collapsed face, or a corner where two nodes coincide), so
   !> that no NaN (0/0) is passed on: callers treat a zero normal as no contribution.
   pure function face_normal(x_face, xi) result(normal)
      real(dp), intent(in) :: x_face(3, 4)
      real(dp), intent(in) :: xi(2)
      real(dp) :: normal(3)
      real(dp) :: shape(4), d_xi(4), d_eta(4), length
      call face_shape_functions(xi, shape, d_xi, d_eta)
      normal = cross_product(matmul(x_face, d_xi), matmul(x_face, d_eta))
      length = norm2(normal)
      if (length > 0.0_dp) then
         normal = normal/length
      else
         normal = 0.0_dp
      end if
   end function face_normal

   !> True if xi lies in [-1 - tolerance, 1 + tolerance]^2.
   pure logical function face_contains(xi, tolerance)
      real(dp), intent(in) :: xi(2)
      real(dp), intent(in) :: tolerance   !! in parent coordinates (1 = half the face)
      face_contains = all(abs(xi) <= 1.0_dp + tolerance)
   end function face_contains

   !> Unconstrained closest point xi* of `point` on the (extrapolated) bilinear surface.
   !> `converged` is false if Newton did not settle in 50 iterations (degenerate face or a
   !> point very far from a strongly warped face); xi is then the last iterate.
   pure subroutine project_onto_face(x_face, point, xi, converged, initial_xi)
      real(dp), intent(in) :: x_face(3, 4)     !! node coordinates, face order
      real(dp), intent(in) :: point(3)         !! the point p to project
      real(dp), intent(out) :: xi(2)           !! xi*
      logical, intent(out) :: converged
      real(dp), intent(in), optional :: initial_xi(2)  !! start of Newton (default: centre)
      real(dp) :: shape(4), d_xi(4), d_eta(4), x(3), a1(3), a2(3), a12(3), distance(3)
      real(dp) :: residual(2), hessian(2, 2), step(2), determinant, length
      integer :: iteration
      logical :: settled

      xi = 0.0_dp
      if (present(initial_xi)) xi = initial_xi
      a12 = 0.25_dp*matmul(x_face, face_node_xi*face_node_eta)
      converged = .false.
      settled = .false.
      do iteration = 1, max_iterations
         call face_shape_functions(xi, shape, d_xi, d_eta)
         x = matmul(x_face, shape)
         a1 = matmul(x_face, d_xi)
         a2 = matmul(x_face, d_eta)
         distance = point - x
         residual = -[dot_product(distance, a1), dot_product(distance, a2)]
         hessian(1, 1) = dot_product(a1, a1)
         hessian(2, 2) = dot_product(a2, a2)
         hessian(1, 2) = dot_product(a1, a2) - dot_product(distance, a12)
         hessian(2, 1) = hessian(1, 2)
         determinant = hessian(1, 1)*hessian(2, 2) - hessian(1, 2)**2
         if (.not. (determinant > 1.0e-14_dp*hessian(1, 1)*hessian(2, 2))) then
            hessian(1, 2) = dot_product(a1, a2)   ! Gauss-Newton: always positive definite
            hessian(2, 1) = hessian(1, 2)
            determinant = hessian(1, 1)*hessian(2, 2) - hessian(1, 2)**2
            if (.not. (determinant > 0.0_dp)) return   ! degenerate face
         end if
         step = -[hessian(2, 2)*residual(1) - hessian(1, 2)*residual(2), &
                  hessian(1, 1)*residual(2) - hessian(2, 1)*residual(1)]/determinant
         length = norm2(step)
         if (length > 1.0_dp) step = step/length
         xi = xi + step
         if (settled) then
            converged = .true.
            return
         end if
         settled = maxval(abs(step)) < step_tolerance
      end do
   end subroutine project_onto_face

   !> Closest point of `point` on the bounded face xi in [-1, 1]^2. If the unconstrained
   !> closest point lies inside the face (within `tolerance`) it is returned with no
   !> coordinate fixed; otherwise the closest point on the four straight edges (the edges of
   !> a bilinear face are straight segments: closest point on a segment, clamped to its ends)
   !> is returned, with fixed(k) = .true. for each coordinate held at -1 or +1 (both at a
   !> corner). This is continuous in `point` across the edge, hence free of chattering.
   pure subroutine closest_point_in_face(x_face, point, tolerance, xi, fixed)
      real(dp), intent(in) :: x_face(3, 4)
      real(dp), intent(in) :: point(3)
      real(dp), intent(in) :: tolerance     !! accept xi* within [-1 - tolerance, 1 + tolerance]^2
      real(dp), intent(out) :: xi(2)
      logical, intent(out) :: fixed(2)      !! coordinate held on the boundary
      real(dp) :: candidate(2), best, distance, t, start(3), finish(3), middle(3), edge(3)
      integer :: side, coordinate
      logical :: converged, clamped
      real(dp), parameter :: side_value(4) = [-1.0_dp, 1.0_dp, -1.0_dp, 1.0_dp]
      integer, parameter :: side_coordinate(4) = [1, 1, 2, 2]

      call project_onto_face(x_face, point, xi, converged)
      fixed = .false.
      if (converged .and. face_contains(xi, tolerance)) return

      best = huge(1.0_dp)
      do side = 1, 4
         coordinate = side_coordinate(side)
         candidate(coordinate) = side_value(side)
         candidate(3 - coordinate) = -1.0_dp
         start = face_position(x_face, candidate)
         candidate(3 - coordinate) = 1.0_dp
         finish = face_position(x_face, candidate)
         middle = 0.5_dp*(start + finish)
         edge = 0.5_dp*(finish - start)
         t = dot_product(point - middle, edge)/dot_product(edge, edge)
         clamped = abs(t) >= 1.0_dp
         t = max(-1.0_dp, min(1.0_dp, t))
         distance = norm2(point - middle - t*edge)
         if (distance < best) then
            best = distance
            xi(coordinate) = side_value(side)
            xi(3 - coordinate) = t
            fixed(coordinate) = .true.
            fixed(3 - coordinate) = clamped
         end if
      end do
   end subroutine closest_point_in_face
end module frix_face_projection
