!> Closest-point projection onto a bilinear face. References: on the flat rectangle
!> [0, 2] x [0, 1] x {0} the closest point of (x, y, z) is xi = (x - 1, 2y - 1) exactly; on
!> the warped face the result is compared with a brute-force search over a 601 x 601 grid of
!> face coordinates (an independent computation) and must satisfy the orthogonality
!> conditions (p - x) . x_,i = 0.
module test_face_projection
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close
   use frix_strings, only: to_string
   use frix_face_projection, only: project_onto_face, closest_point_in_face, face_position, face_normal, &
                                   face_contains, face_shape_functions
   use test_contact_fixtures, only: flat_face, warped_face
   implicit none
   private

   public :: collect_face_projection

contains

   subroutine collect_face_projection(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('flat rectangle: exact closest point and normal', test_flat), &
               new_unittest('warped face: orthogonality and brute-force minimum', test_warped), &
               new_unittest('outside flag and clamped edge / corner point', test_outside), &
               new_unittest('inside point: clamped = unconstrained', test_inside_clamp)]
   end subroutine collect_face_projection

   subroutine test_flat(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: xi(2), normal(3)
      logical :: converged
      call project_onto_face(flat_face, [0.3_dp, 0.8_dp, -0.7_dp], xi, converged)
      call check(error, converged, 'converged')
      if (allocated(error)) return
      call check(error, maxval(abs(xi - [-0.7_dp, 0.6_dp])) <= 1.0e-15_dp, 'xi = (x - 1, 2y - 1), got '// &
                 to_string(xi(1))//', '//to_string(xi(2)))
      if (allocated(error)) return
      normal = face_normal(flat_face, xi)
      call check(error, maxval(abs(normal - [0.0_dp, 0.0_dp, 1.0_dp])) <= 1.0e-15_dp, 'normal +z')
      if (allocated(error)) return
      call check(error, maxval(abs(face_position(flat_face, xi) - [0.3_dp, 0.8_dp, 0.0_dp])) <= 1.0e-15_dp, &
                 'position')
   end subroutine test_flat

   subroutine test_warped(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: xi(2), point(3), x(3), shape(4), d_xi(4), d_eta(4), best, distance, best_xi(2), trial(2)
      real(dp), parameter :: points(3, 3) = reshape([0.9_dp, 0.7_dp, 0.35_dp, 1.5_dp, 0.3_dp, -0.4_dp, &
                                                     0.1_dp, 1.0_dp, 0.8_dp], [3, 3])
      integer :: i, j, p
      logical :: converged
      do p = 1, 3
         point = points(:, p)
         call project_onto_face(warped_face, point, xi, converged)
         call check(error, converged, 'converged')
         if (allocated(error)) return
         call face_shape_functions(xi, shape, d_xi, d_eta)
         x = matmul(warped_face, shape)
         call check(error, abs(dot_product(point - x, matmul(warped_face, d_xi))) <= 1.0e-14_dp .and. &
                    abs(dot_product(point - x, matmul(warped_face, d_eta))) <= 1.0e-14_dp, 'orthogonality')
         if (allocated(error)) return
         best = huge(1.0_dp)
         do i = 0, 600
            do j = 0, 600
               trial = [-1.5_dp + 3.0_dp*i/600.0_dp, -1.5_dp + 3.0_dp*j/600.0_dp]
               distance = norm2(point - face_position(warped_face, trial))
               if (distance < best) then
                  best = distance
                  best_xi = trial
               end if
            end do
         end do
         ! Newton's distance can only be smaller; grid spacing 0.005 in xi.
         call check(error, norm2(point - x) <= best + 1.0e-15_dp, 'not farther than the grid minimum')
         if (allocated(error)) return
         call check(error, maxval(abs(xi - best_xi)) <= 0.005_dp, 'near the grid argmin, point '//to_string(p))
         if (allocated(error)) return
      end do
   end subroutine test_warped

   subroutine test_outside(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: xi(2)
      logical :: converged, fixed(2)
      ! Beyond the edge x = 2 (xi1 = 1.3): outside; clamped to (1, 2*0.4 - 1) = (1, -0.2).
      call project_onto_face(flat_face, [2.3_dp, 0.4_dp, 0.1_dp], xi, converged)
      call check(error, converged .and. .not. face_contains(xi, 1.0e-6_dp), 'outside')
      if (allocated(error)) return
      call check(error, face_contains([1.0_dp + 1.0e-7_dp, 0.0_dp], 1.0e-6_dp), 'within tolerance is inside')
      if (allocated(error)) return
      call closest_point_in_face(flat_face, [2.3_dp, 0.4_dp, 0.1_dp], 1.0e-6_dp, xi, fixed)
      call check(error, fixed(1) .and. .not. fixed(2) .and. maxval(abs(xi - [1.0_dp, -0.2_dp])) <= 1.0e-15_dp, &
                 'edge point (1, -0.2)')
      if (allocated(error)) return
      ! Beyond the corner (0, 0): clamped to xi = (-1, -1), both fixed.
      call closest_point_in_face(flat_face, [-0.3_dp, -0.2_dp, 0.1_dp], 1.0e-6_dp, xi, fixed)
      call check(error, all(fixed) .and. maxval(abs(xi + 1.0_dp)) <= 1.0e-15_dp, 'corner (-1, -1)')
      if (allocated(error)) return
      ! Warped face beyond its corner 3: the corner node is the closest point.
      call closest_point_in_face(warped_face, warped_face(:, 3) + [0.3_dp, 0.3_dp, 0.0_dp], 1.0e-6_dp, xi, fixed)
      call check(error, all(fixed) .and. maxval(abs(xi - 1.0_dp)) <= 1.0e-15_dp, 'warped corner (1, 1)')
   end subroutine test_outside

   subroutine test_inside_clamp(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: xi(2), xi_free(2)
      logical :: converged, fixed(2)
      call project_onto_face(warped_face, [0.9_dp, 0.7_dp, 0.35_dp], xi_free, converged)
      call closest_point_in_face(warped_face, [0.9_dp, 0.7_dp, 0.35_dp], 1.0e-6_dp, xi, fixed)
      call check(error, .not. any(fixed) .and. all(xi == xi_free), 'same point, nothing fixed')
   end subroutine test_inside_clamp
end module test_face_projection
