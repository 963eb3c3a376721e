!> The smoothed normal field of a master surface, in plain reals: averaged nodal normals of a
!> face's patch and their exact derivatives with respect to the patch's node coordinates, the
!> interpolated normal, and the projection of a point along that field. Used by the contact
!> search (values) and the contact kernel (values, and the derivatives it chains onto the
!> derivatives it takes with respect to the nodal normals).
!>
!> Nodal normal of a face's node a (Yang, Laursen & Meng, IJNME 62 (2005); Wriggers,
!> *Computational Contact Mechanics*, 2nd ed., Springer 2006, 9.5): n_a = s/|s|,
!> s = sum over the patch faces f that hold node a of u_f = c_f/|c_f|, c_f = x_,1 x x_,2 of
!> face f at a's corner (the facet's outward area vector there; HEX8 face order).
!> Derivatives: dc = -[x_,2]x dx_,1 + [x_,1]x dx_,2 with dx_,k = sum_b N_b,k dx_b;
!> du = (I - u u) dc/|c|; dn = (I - n n) ds/|s|.
!>
!> Smoothed normal at xi: n(xi) = m/|m|, m = sum_a N_a(xi) n_a. Projection of p along it:
!> r_k(xi) = d . a_k - (d . n)(n . a_k) = 0, d = p - x(xi), a_k = x_,k; Newton with the exact
!> Jacobian
!>   dr_k/dxi_l = -a_l . a_k + d . a_kl - (-a_l . n + d . n_l)(n . a_k) - (d . n)(n_l . a_k + n . a_kl),
!> n_l = (I - n n) m_,l / |m|, a_11 = a_22 = 0 and a_12 = sum_b xi_b eta_b x_b / 4 on a
!> bilinear face.
!>
!> Faces: x_face(3, 4) the face's nodes in face order, x_ring(3, n_ring) the other nodes of its
!> patch, patch_faces(4, n) the patch's faces as local node numbers (1-4: x_face's nodes,
!> 4 + j: x_ring(:, j)), outward (HEX8 face) order (frix_contact_patches).
module frix_smoothed_normals
   use frix_kinds, only: dp
   use frix_vector_algebra, only: cross_product, skew
   use frix_face_projection, only: face_node_xi, face_node_eta, face_shape_functions, project_onto_face
   implicit none
   private

   public :: patch_normals, patch_normal_derivatives, smooth_normal_at, smooth_projection, smooth_residual

   !> Newton iterations and step tolerance (parent coordinates) of the smoothed-normal projection.
   integer, parameter :: smooth_projection_iterations = 30
   real(dp), parameter :: smooth_projection_tolerance = 1.0e-13_dp
   !> a step below this that is not half the previous one has reached round-off: converged
   real(dp), parameter :: stagnation_step = 1.0e-9_dp

contains

   !> The averaged nodal normals n_a of the face's 4 nodes (column a).
   pure function patch_normals(x_face, x_ring, patch_faces) result(nodal)
      real(dp), intent(in) :: x_face(3, 4), x_ring(:, :)
      integer, intent(in) :: patch_faces(:, :)
      real(dp) :: nodal(3, 4)
      call nodal_normals(x_face, x_ring, patch_faces, nodal)
   end function patch_normals

   !> The nodal normals (as patch_normals) and their derivatives:
   !> derivative(3 (a - 1) + i, 3 (b - 1) + k) = d n_a,i / d x_b,k, b the patch's local node
   !> number (1-4 the face's nodes, 4 + j ring node j), dimensionless per length.
   pure subroutine patch_normal_derivatives(x_face, x_ring, patch_faces, nodal, derivative)
      real(dp), intent(in) :: x_face(3, 4), x_ring(:, :)
      integer, intent(in) :: patch_faces(:, :)
      real(dp), intent(out) :: nodal(3, 4)
      real(dp), intent(out) :: derivative(12, 3*(4 + size(x_ring, 2)))
      call nodal_normals(x_face, x_ring, patch_faces, nodal, derivative)
   end subroutine patch_normal_derivatives

   !> n_a = s/|s|, s the sum of the corner unit normals u of the patch faces at node a, and
   !> (if present) dn_a/dx_b = (I - n n)/|s| sum du/dx_b, du/dx_b = (I - u u)/|c| dc/dx_b,
   !> dc/dx_b = N_b,2 [x_,1]x - N_b,1 [x_,2]x (the module's header).
   pure subroutine nodal_normals(x_face, x_ring, patch_faces, nodal, derivative)
      real(dp), intent(in) :: x_face(3, 4), x_ring(:, :)
      integer, intent(in) :: patch_faces(:, :)
      real(dp), intent(out) :: nodal(3, 4)
      real(dp), intent(out), optional :: derivative(:, :)
      real(dp) :: corner_unit(3), corner_area, projector(3, 3), a1(3), a2(3), d_xi(4), d_eta(4), length
      real(dp) :: sum_derivative(3, 3*(4 + size(x_ring, 2)))   ! d s / d x_b of node a
      integer :: a, f, j, b, node, i
      if (present(derivative)) derivative = 0.0_dp
      do a = 1, 4
         nodal(:, a) = 0.0_dp
         if (present(derivative)) sum_derivative = 0.0_dp
         do f = 1, size(patch_faces, 2)
            j = findloc(patch_faces(:, f), a, dim=1)
            if (j == 0) cycle
            call corner_normal(corner_nodes(x_face, x_ring, patch_faces(:, f)), j, corner_unit, corner_area, &
                               a1, a2, d_xi, d_eta)
            nodal(:, a) = nodal(:, a) + corner_unit
            if (.not. present(derivative)) cycle
            projector = unit_projector(corner_unit)/corner_area
            do b = 1, 4
               if (d_xi(b) == 0.0_dp .and. d_eta(b) == 0.0_dp) cycle
               node = patch_faces(b, f)
               sum_derivative(:, 3*node - 2:3*node) = sum_derivative(:, 3*node - 2:3*node) + &
                                                      matmul(projector, d_eta(b)*skew(a1) - d_xi(b)*skew(a2))
            end do
         end do
         length = sqrt(dot_product(nodal(:, a), nodal(:, a)))
         nodal(:, a) = nodal(:, a)/length
         if (.not. present(derivative)) cycle
         projector = unit_projector(nodal(:, a))/length
         do i = 1, 3
            derivative(3*(a - 1) + i, :) = matmul(projector(i, :), sum_derivative)
         end do
      end do
   end subroutine nodal_normals

   !> The smoothed normal m/|m|, m = sum_a N_a(xi) n_a, from the nodal normals.
   pure function smooth_normal_at(nodal, xi) result(normal)
      real(dp), intent(in) :: nodal(3, 4), xi(2)
      real(dp) :: normal(3), shape(4), d_xi(4), d_eta(4)
      call face_shape_functions(xi, shape, d_xi, d_eta)
      normal = matmul(nodal, shape)
      normal = normal/sqrt(dot_product(normal, normal))
   end function smooth_normal_at

   !> The residual r(xi) of the projection of `point` along the smoothed normals and its
   !> Jacobian dr/dxi (see the module's header).
   pure subroutine smooth_residual(x_face, nodal, point, xi, residual, jacobian)
      real(dp), intent(in) :: x_face(3, 4), nodal(3, 4), point(3), xi(2)
      real(dp), intent(out) :: residual(2), jacobian(2, 2)
      real(dp) :: shape(4), d_xi(4), d_eta(4), a(3, 2), a12(3), m(3), m_d(3, 2), normal(3), normal_d(3, 2)
      real(dp) :: distance(3), length, normal_distance, normal_tangent(2)
      integer :: k, l
      call face_shape_functions(xi, shape, d_xi, d_eta)
      a(:, 1) = matmul(x_face, d_xi)
      a(:, 2) = matmul(x_face, d_eta)
      a12 = 0.25_dp*matmul(x_face, face_node_xi*face_node_eta)
      m = matmul(nodal, shape)
      m_d(:, 1) = matmul(nodal, d_xi)
      m_d(:, 2) = matmul(nodal, d_eta)
      length = sqrt(dot_product(m, m))
      normal = m/length
      do l = 1, 2
         normal_d(:, l) = (m_d(:, l) - dot_product(normal, m_d(:, l))*normal)/length
      end do
      distance = point - matmul(x_face, shape)
      normal_distance = dot_product(distance, normal)
      do k = 1, 2
         normal_tangent(k) = dot_product(normal, a(:, k))
         residual(k) = dot_product(distance, a(:, k)) - normal_distance*normal_tangent(k)
      end do
      do k = 1, 2
         do l = 1, 2
            ! d . a_kl and n . a_kl: a_kl = a12 for k /= l, zero for k = l
            jacobian(k, l) = -dot_product(a(:, l), a(:, k)) &
                             - (dot_product(-a(:, l), normal) + dot_product(distance, normal_d(:, l)))*normal_tangent(k) &
                             - normal_distance*dot_product(normal_d(:, l), a(:, k))
            if (k /= l) jacobian(k, l) = jacobian(k, l) + dot_product(distance, a12) &
                                         - normal_distance*dot_product(normal, a12)
         end do
      end do
   end subroutine smooth_residual

   !> Projection of `point` onto the face along the smoothed normal field of the nodal normals:
   !> Newton on r(xi) = 0 from the facet closest point, steps of at most half a face, with the
   !> Jacobian returned at the solution. Not converged: no solution within the iteration limit,
   !> an iterate beyond |xi_k| = 10, or a singular Jacobian.
   pure subroutine smooth_projection(x_face, nodal, point, xi, converged, jacobian)
      real(dp), intent(in) :: x_face(3, 4), nodal(3, 4), point(3)
      real(dp), intent(out) :: xi(2)
      logical, intent(out) :: converged
      real(dp), intent(out) :: jacobian(2, 2)
      real(dp) :: step(2), residual(2), determinant, previous_step
      logical :: facet_converged
      integer :: iteration
      previous_step = huge(1.0_dp)
      call project_onto_face(x_face, point, xi, facet_converged)
      if (.not. facet_converged .or. any(abs(xi) > 2.0_dp)) xi = 0.0_dp
      converged = .false.
      do iteration = 1, smooth_projection_iterations + 1
         call smooth_residual(x_face, nodal, point, xi, residual, jacobian)
         determinant = jacobian(1, 1)*jacobian(2, 2) - jacobian(1, 2)*jacobian(2, 1)
         if (.not. (abs(determinant) > 0.0_dp)) then
            converged = .false.
            return
         end if
         if (converged .or. iteration > smooth_projection_iterations) return
         step = [jacobian(2, 2)*residual(1) - jacobian(1, 2)*residual(2), &
                 jacobian(1, 1)*residual(2) - jacobian(2, 1)*residual(1)]/determinant
         if (maxval(abs(step)) > 1.0_dp) step = step/maxval(abs(step))
         xi = xi - step
         if (any(abs(xi) > 10.0_dp)) return
         ! converged: a step below the tolerance, or steps that stopped shrinking at round-off
         ! level (far from the origin the residual's round-off exceeds the tolerance)
         converged = maxval(abs(step)) < smooth_projection_tolerance .or. &
                     (maxval(abs(step)) < stagnation_step .and. maxval(abs(step)) >= 0.5_dp*previous_step)
         previous_step = maxval(abs(step))
      end do
   end subroutine smooth_projection

   !> The nodes of one patch face (local numbers `local`) as coordinates (3, 4).
   pure function corner_nodes(x_face, x_ring, local) result(corners)
      real(dp), intent(in) :: x_face(3, 4), x_ring(:, :)
      integer, intent(in) :: local(4)
      real(dp) :: corners(3, 4)
      integer :: b
      do b = 1, 4
         if (local(b) <= 4) then
            corners(:, b) = x_face(:, local(b))
         else
            corners(:, b) = x_ring(:, local(b) - 4)
         end if
      end do
   end function corner_nodes

   !> The unit normal u = c/|c| of a face at its corner j, c = x_,1 x x_,2 there, with |c|,
   !> the tangents x_,1, x_,2 and the shape functions' derivatives N_b,1, N_b,2 at the corner.
   pure subroutine corner_normal(corners, j, corner_unit, corner_area, a1, a2, d_xi, d_eta)
      real(dp), intent(in) :: corners(3, 4)
      integer, intent(in) :: j
      real(dp), intent(out) :: corner_unit(3), corner_area, a1(3), a2(3), d_xi(4), d_eta(4)
      real(dp) :: shape(4)
      call face_shape_functions([face_node_xi(j), face_node_eta(j)], shape, d_xi, d_eta)
      a1 = matmul(corners, d_xi)
      a2 = matmul(corners, d_eta)
      corner_unit = cross_product(a1, a2)
      corner_area = sqrt(dot_product(corner_unit, corner_unit))
      corner_unit = corner_unit/corner_area
   end subroutine corner_normal

   !> I - u u for a unit vector u.
   pure function unit_projector(unit) result(projector)
      real(dp), intent(in) :: unit(3)
      real(dp) :: projector(3, 3)
      integer :: i
      projector = -spread(unit, 2, 3)*spread(unit, 1, 3)
      do i = 1, 3
         projector(i, i) = projector(i, i) + 1.0_dp
      end do
   end function unit_projector
end module frix_smoothed_normals
