!> The smoothed normal field in plain reals (frix_smoothed_normals): the nodal normals'
!> closed-form derivatives and the projection's Jacobian against central differences of the
!> values (an independent computation), the projection's defining condition d x n = 0, and the
!> nodal normals of a flat patch (exactly the facet normal). The curved patch is face (2, 2) of
!> test_contact_fixtures' grid_patch (a doubly curved 3 x 3 grid, no two nodal normals alike).
module test_smoothed_normals
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check
   use frix_strings, only: to_string
   use frix_vector_algebra, only: cross_product
   use frix_face_projection, only: face_position
   use frix_smoothed_normals, only: patch_normals, patch_normal_derivatives, smooth_normal_at, smooth_projection, &
                                    smooth_residual
   use test_contact_fixtures, only: grid_patch
   implicit none
   private

   public :: collect_smoothed_normals

   !> Central differences with step h = 1e-6 (coordinates of size 1): truncation O(h^2) ~ 1e-12,
   !> round-off ~ 1e-16/h ~ 1e-10 of the derivative's size; 1e-7 leaves room for both. A
   !> derivative missing one face's corner normal, or the projector (I - n n), errs by 1e-2 or
   !> more.
   real(dp), parameter :: step = 1.0e-6_dp, tolerance = 1.0e-7_dp

contains

   subroutine collect_smoothed_normals(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('flat patch: every nodal normal is the facet normal', test_flat), &
               new_unittest('curved patch: nodal normal derivatives = central differences', test_derivatives), &
               new_unittest('curved patch: projection Jacobian = central differences of r(xi)', test_jacobian), &
               new_unittest('curved patch: the projection puts the point on the smoothed normal', test_projection)]
   end subroutine collect_smoothed_normals

   subroutine test_flat(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: x_face(3, 4), nodal(3, 4)
      real(dp), allocatable :: x_ring(:, :)
      integer, allocatable :: patch_faces(:, :)
      real(dp), parameter :: facet(3) = [0.0_dp, 0.0_dp, 1.0_dp]
      ! grid_patch flattened onto z = 0 (its nodes keep their in-plane irregularity)
      call grid_patch(2, 2, x_face, x_ring, patch_faces)
      x_face(3, :) = 0.0_dp
      x_ring(3, :) = 0.0_dp
      nodal = patch_normals(x_face, x_ring, patch_faces)
      call check(error, maxval(abs(nodal - spread(facet, 2, 4))) <= 1.0e-15_dp, &
                 'nodal normals of a flat patch differ from the facet normal by '// &
                 to_string(maxval(abs(nodal - spread(facet, 2, 4)))))
   end subroutine test_flat

   subroutine test_derivatives(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: x_face(3, 4), nodal(3, 4), plus(3, 4), minus(3, 4), worst
      real(dp), allocatable :: x_ring(:, :), derivative(:, :), moved_face(:, :), moved_ring(:, :)
      integer, allocatable :: patch_faces(:, :)
      integer :: b, k, column
      call grid_patch(2, 2, x_face, x_ring, patch_faces)
      allocate (derivative(12, 3*(4 + size(x_ring, 2))))
      call patch_normal_derivatives(x_face, x_ring, patch_faces, nodal, derivative)
      call check(error, maxval(abs(nodal - patch_normals(x_face, x_ring, patch_faces))) == 0.0_dp, &
                 'the values differ from patch_normals')
      if (allocated(error)) return
      worst = 0.0_dp
      do b = 1, 4 + size(x_ring, 2)
         do k = 1, 3
            column = 3*(b - 1) + k
            moved_face = x_face
            moved_ring = x_ring
            call shift(moved_face, moved_ring, b, k, step)
            plus = patch_normals(moved_face, moved_ring, patch_faces)
            call shift(moved_face, moved_ring, b, k, -2.0_dp*step)
            minus = patch_normals(moved_face, moved_ring, patch_faces)
            worst = max(worst, maxval(abs(reshape((plus - minus)/(2.0_dp*step), [12]) - derivative(:, column))))
         end do
      end do
      call check(error, worst <= tolerance*maxval(abs(derivative)), &
                 'd n_a / d x_b differs from central differences by '//to_string(worst)// &
                 ' (largest entry '//to_string(maxval(abs(derivative)))//')')
   end subroutine test_derivatives

   !> Move coordinate k of patch node b (1-4 the face's, then the ring's) by delta.
   pure subroutine shift(x_face, x_ring, b, k, delta)
      real(dp), intent(inout) :: x_face(:, :), x_ring(:, :)
      integer, intent(in) :: b, k
      real(dp), intent(in) :: delta
      if (b <= 4) then
         x_face(k, b) = x_face(k, b) + delta
      else
         x_ring(k, b - 4) = x_ring(k, b - 4) + delta
      end if
   end subroutine shift

   subroutine test_jacobian(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: x_face(3, 4), nodal(3, 4), point(3), xi(2), residual(2), jacobian(2, 2), plus(2), minus(2)
      real(dp) :: unused(2, 2), difference(2, 2)
      real(dp), allocatable :: x_ring(:, :)
      integer, allocatable :: patch_faces(:, :)
      integer :: l
      call grid_patch(2, 2, x_face, x_ring, patch_faces)
      nodal = patch_normals(x_face, x_ring, patch_faces)
      point = face_position(x_face, [0.3_dp, -0.45_dp]) + [0.07_dp, -0.04_dp, 0.2_dp]
      xi = [0.1_dp, -0.2_dp]   ! away from the solution: every term of the Jacobian counts
      call smooth_residual(x_face, nodal, point, xi, residual, jacobian)
      do l = 1, 2
         call smooth_residual(x_face, nodal, point, xi + merge(step, 0.0_dp, [1, 2] == l), plus, unused)
         call smooth_residual(x_face, nodal, point, xi - merge(step, 0.0_dp, [1, 2] == l), minus, unused)
         difference(:, l) = (plus - minus)/(2.0_dp*step)
      end do
      call check(error, maxval(abs(difference - jacobian)) <= tolerance*maxval(abs(jacobian)), &
                 'dr/dxi differs from central differences by '//to_string(maxval(abs(difference - jacobian))))
   end subroutine test_jacobian

   subroutine test_projection(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: x_face(3, 4), nodal(3, 4), point(3), xi(2), jacobian(2, 2), offset(3), normal(3)
      real(dp), allocatable :: x_ring(:, :)
      integer, allocatable :: patch_faces(:, :)
      logical :: converged
      call grid_patch(2, 2, x_face, x_ring, patch_faces)
      nodal = patch_normals(x_face, x_ring, patch_faces)
      point = face_position(x_face, [0.6_dp, 0.25_dp]) + [0.03_dp, 0.05_dp, 0.3_dp]
      call smooth_projection(x_face, nodal, point, xi, converged, jacobian)
      call check(error, converged, 'the projection did not converge')
      if (allocated(error)) return
      offset = point - face_position(x_face, xi)
      normal = smooth_normal_at(nodal, xi)
      call check(error, norm2(cross_product(offset, normal)) <= 1.0e-14_dp*norm2(offset), &
                 '|d x n(xi*)| = '//to_string(norm2(cross_product(offset, normal)))//', |d| = '// &
                 to_string(norm2(offset)))
   end subroutine test_projection
end module test_smoothed_normals
