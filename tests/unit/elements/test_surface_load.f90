!> Pressure load kernel (frix_surface_load) on a bilinear quadrilateral face and on 3- and
!> 6-node triangles. Reference values:
!>   - total force of a pressure p on a face = -p (vector area), with the vector area of a
!>     bilinear face exactly (d1 x d2)/2 of its diagonals d1 = x3 - x1, d2 = x4 - x2;
!>   - on a unit square each node carries a quarter (symmetry);
!>   - tributary areas of a trapezoid worked out by hand (see test_trapezoid_weights);
!>   - the follower load stiffness against a central difference of the force; the force is
!>     quadratic in u, so the central difference has no truncation error, only round-off
!>     (on the warped quadrilateral and on a 6-node triangle with curved edges);
!>   - a flat triangle with straight edges: total force -p (x2 - x1) x (x3 - x1) / 2; TRI3: a
!>     third on each node; TRI6: nothing on the corners, a third on each mid-edge node
!>     (int N_corner dA = 0, int N_mid dA = A/3 for quadratic shape functions);
!>   - the face shape functions: N_a(xi_b) = delta_ab at the corners, sum_a N_a = 1, and their
!>     derivatives against central differences (N_a is linear in each of xi, eta separately, so
!>     the difference is exact up to round-off);
!>   - the vector product on the right-handed basis (e_x x e_y = e_z, cyclic) and, for two
!>     general vectors, anticommutativity and orthogonality to both operands.
module test_surface_load
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_testing, only: unittest_t, new_unittest, check, check_close
   use frix_surface_load, only: pressure_load, face_area_weights, face_shape_functions, face_node_xi, face_node_eta
   use frix_vector_algebra, only: cross_product
   use frix_reference_cell, only: reference_cell_t
   use frix_quad4_cell, only: new_quad4_cell
   use frix_tri3_cell, only: new_tri3_cell
   use frix_tri6_cell, only: new_tri6_cell
   implicit none
   private

   public :: collect_surface_load

   !> Unit square in z = 0, counter-clockwise seen from +z: outward normal +z.
   real(dp), parameter :: unit_square(3, 4) = reshape([0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, &
                                                        1.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp], [3, 4])
   !> A warped, skewed face (no two edges parallel, nodes not coplanar).
   real(dp), parameter :: warped_face(3, 4) = reshape([0.0_dp, 0.0_dp, 0.0_dp, 2.1_dp, 0.2_dp, 0.3_dp, &
                                                        1.8_dp, 1.7_dp, -0.2_dp, -0.3_dp, 1.2_dp, 0.4_dp], [3, 4])
   !> A displacement of the warped face of the order of 20 % of its size.
   real(dp), parameter :: warped_displacement(3, 4) = reshape([0.1_dp, -0.2_dp, 0.05_dp, 0.3_dp, 0.1_dp, -0.25_dp, &
                                                                -0.15_dp, 0.2_dp, 0.35_dp, 0.05_dp, -0.1_dp, 0.2_dp], &
                                                               [3, 4])

contains

   subroutine collect_surface_load(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('unit square, p = 1: a quarter of -n area per node', test_unit_square), &
               new_unittest('warped face, dead load: total = -p (d1 x d2)/2', test_warped_dead), &
               new_unittest('warped face, follower: total on the current face', test_warped_follower), &
               new_unittest('dead load ignores u and has no stiffness', test_dead_independent_of_u), &
               new_unittest('follower stiffness vs central differences', test_follower_tangent), &
               new_unittest('flat triangles: total -p A n; TRI3 thirds, TRI6 on mid-edges', test_flat_triangles), &
               new_unittest('TRI6 follower stiffness vs central differences', test_tri6_follower_tangent), &
               new_unittest('area weights of a unit square and a rectangle', test_rectangle_weights), &
               new_unittest('area weights of a trapezoid (by hand)', test_trapezoid_weights), &
               new_unittest('plane face: nodal force = -p n weight', test_plane_force_matches_weights), &
               new_unittest('face shape functions: corners, unity, derivatives', test_face_shape_functions), &
               new_unittest('cross product: basis, anticommutative, orthogonal', test_cross_product)]
   end subroutine collect_surface_load

   subroutine test_unit_square(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: force(12), tangent(12, 12), expected(3)
      logical :: follower
      integer :: a, i, k
      expected = [0.0_dp, 0.0_dp, -0.25_dp]
      do k = 1, 2
         follower = k == 2
         call pressure_load(new_quad4_cell(), unit_square, spread([0.0_dp, 0.0_dp, 0.0_dp], 2, 4), 1.0_dp, follower, force, tangent)
         do a = 1, 4
            do i = 1, 3
               call check_close(error, force(3*(a - 1) + i), expected(i), 1.0e-14_dp, 1.0e-15_dp, &
                                'node '//to_string(a)//' direction '//to_string(i))
               if (allocated(error)) return
            end do
         end do
      end do
   end subroutine test_unit_square

   subroutine test_warped_dead(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: pressure = 2.5_dp
      real(dp) :: force(12), tangent(12, 12)
      call pressure_load(new_quad4_cell(), warped_face, warped_displacement, pressure, .false., force, tangent)
      call check_total(error, force, -pressure*half_diagonal_cross(warped_face))
   end subroutine test_warped_dead

   subroutine test_warped_follower(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: pressure = -1.7_dp  ! suction: sign must carry through
      real(dp) :: force(12), tangent(12, 12)
      call pressure_load(new_quad4_cell(), warped_face, warped_displacement, pressure, .true., force, tangent)
      call check_total(error, force, -pressure*half_diagonal_cross(warped_face + warped_displacement))
   end subroutine test_warped_follower

   subroutine test_dead_independent_of_u(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: force(12), force_zero(12), tangent(12, 12)
      integer :: i
      call pressure_load(new_quad4_cell(), warped_face, spread([0.0_dp, 0.0_dp, 0.0_dp], 2, 4), 3.0_dp, .false., force_zero)
      call pressure_load(new_quad4_cell(), warped_face, warped_displacement, 3.0_dp, .false., force, tangent)
      do i = 1, 12
         call check_close(error, force(i), force_zero(i), 0.0_dp, message='force entry '//to_string(i))
         if (allocated(error)) return
      end do
      call check(error, all(tangent == 0.0_dp), 'dead load stiffness must be zero')
   end subroutine test_dead_independent_of_u

   !> The warped quadrilateral's follower stiffness (check_follower_tangent).
   subroutine test_follower_tangent(error)
      type(error_t), allocatable, intent(out) :: error
      call check_follower_tangent(new_quad4_cell(), warped_face, warped_displacement, error)
   end subroutine test_follower_tangent

   !> A 6-node triangle with curved edges (mid-edge nodes off the middle), displaced by about
   !> 20 % of its size: its follower stiffness (check_follower_tangent).
   subroutine test_tri6_follower_tangent(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: coords(3, 6), u(3, 6)
      integer :: a
      coords(:, 1:3) = warped_face(:, 1:3)
      coords(:, 4) = 0.5_dp*(coords(:, 1) + coords(:, 2)) + [0.05_dp, -0.1_dp, 0.2_dp]
      coords(:, 5) = 0.5_dp*(coords(:, 2) + coords(:, 3)) + [-0.1_dp, 0.05_dp, 0.1_dp]
      coords(:, 6) = 0.5_dp*(coords(:, 3) + coords(:, 1)) + [0.1_dp, 0.1_dp, -0.15_dp]
      do a = 1, 6
         u(:, a) = 0.3_dp*[sin(1.1_dp*a), cos(0.7_dp*a), sin(0.4_dp*a + 1.0_dp)]
      end do
      call check_follower_tangent(new_tri6_cell(), coords, u, error)
   end subroutine test_tri6_follower_tangent

   !> Column j of d fext/du vs (f(u + h e_j) - f(u - h e_j)) / (2 h), h = 1e-6 (face size ~2);
   !> the stiffness must be unsymmetric (a curved or warped face).
   subroutine check_follower_tangent(face, coords, u, error)
      class(reference_cell_t), intent(in) :: face
      real(dp), intent(in) :: coords(:, :), u(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: pressure = 4.0_dp, step = 1.0e-6_dp
      real(dp), allocatable :: force(:), tangent(:, :), differences(:, :), plus(:), minus(:), perturbed(:, :)
      real(dp) :: scale
      integer :: i, j, a, direction, n
      n = 3*size(coords, 2)
      allocate (force(n), tangent(n, n), differences(n, n), plus(n), minus(n))
      call pressure_load(face, coords, u, pressure, .true., force, tangent)
      do j = 1, n
         a = (j - 1)/3 + 1
         direction = j - 3*(a - 1)
         perturbed = u
         perturbed(direction, a) = u(direction, a) + step
         call pressure_load(face, coords, perturbed, pressure, .true., plus)
         perturbed(direction, a) = u(direction, a) - step
         call pressure_load(face, coords, perturbed, pressure, .true., minus)
         differences(:, j) = (plus - minus)/(2.0_dp*step)
      end do
      scale = maxval(abs(differences))
      call check(error, maxval(abs(tangent - transpose(tangent))) > 1.0e-3_dp*scale, &
                 face%name//': load stiffness of a warped face should be unsymmetric')
      if (allocated(error)) return
      do j = 1, n
         do i = 1, n
            call check_close(error, tangent(i, j), differences(i, j), 1.0e-6_dp, 1.0e-6_dp*scale, &
                             face%name//': K_load('//to_string(i)//','//to_string(j)//')')
            if (allocated(error)) return
         end do
      end do
   end subroutine check_follower_tangent

   !> A flat triangle with straight edges in an oblique plane, dead and follower (u = 0) load:
   !> the total force -p (x2 - x1) x (x3 - x1) / 2; TRI3 a third of it on each node, TRI6
   !> nothing on the corners and a third on each mid-edge node.
   subroutine test_flat_triangles(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: pressure = 2.5_dp
      real(dp) :: coords(3, 6), force(18), total(3), expected(3, 6)
      integer :: k, n
      logical :: follower
      coords(:, 1) = [0.2_dp, -0.1_dp, 0.3_dp]
      coords(:, 2) = [1.9_dp, 0.4_dp, -0.2_dp]
      coords(:, 3) = [0.5_dp, 1.6_dp, 0.9_dp]
      coords(:, 4) = 0.5_dp*(coords(:, 1) + coords(:, 2))
      coords(:, 5) = 0.5_dp*(coords(:, 2) + coords(:, 3))
      coords(:, 6) = 0.5_dp*(coords(:, 3) + coords(:, 1))
      total = -pressure*0.5_dp*cross_product(coords(:, 2) - coords(:, 1), coords(:, 3) - coords(:, 1))
      do k = 1, 4
         follower = k > 2
         if (mod(k, 2) == 1) then
            n = 3
            expected(:, 1:3) = spread(total/3, 2, 3)
            call pressure_load(new_tri3_cell(), coords(:, 1:3), 0.0_dp*coords(:, 1:3), pressure, follower, force)
         else
            n = 6
            expected(:, 1:3) = 0.0_dp
            expected(:, 4:6) = spread(total/3, 2, 3)
            call pressure_load(new_tri6_cell(), coords, 0.0_dp*coords, pressure, follower, force)
         end if
         call check(error, maxval(abs(force(1:3*n) - reshape(expected(:, 1:n), [3*n]))) <= 1.0e-14_dp*norm2(total), &
                    'TRI'//to_string(n)//' nodal forces off by '// &
                    to_string(maxval(abs(force(1:3*n) - reshape(expected(:, 1:n), [3*n])))))
         if (allocated(error)) return
      end do
   end subroutine test_flat_triangles

   subroutine test_rectangle_weights(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: weights(4), rectangle(3, 4)
      integer :: a
      call face_area_weights(unit_square, weights)
      do a = 1, 4
         call check_close(error, weights(a), 0.25_dp, 1.0e-14_dp, message='unit square weight')
         if (allocated(error)) return
      end do
      rectangle = unit_square
      rectangle(1, :) = 2.0_dp*rectangle(1, :)
      rectangle(2, :) = 3.0_dp*rectangle(2, :)
      call face_area_weights(rectangle, weights)
      do a = 1, 4
         call check_close(error, weights(a), 1.5_dp, 1.0e-14_dp, message='2 x 3 rectangle weight')
         if (allocated(error)) return
      end do
   end subroutine test_rectangle_weights

   !> Trapezoid (0,0), (4,0), (3,2), (1,2) in a tilted plane: in its plane the width is 3 - eta
   !> and the height 2, so dA = (3 - eta)/2 dxi deta and
   !>   w1 = w2 = (1/8) int (1 - xi) dxi int (1 - eta)(3 - eta) deta = (1/8)(2)(20/3) = 5/3,
   !>   w3 = w4 = (1/8)(2) int (1 + eta)(3 - eta) deta = (1/8)(2)(16/3) = 4/3; sum 6 = area.
   !> The plane is rotated by 30 degrees about x (a rotation preserves areas).
   subroutine test_trapezoid_weights(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: trapezoid(3, 4), weights(4), expected(4), rotation(3, 3), angle
      integer :: a
      angle = acos(-1.0_dp)/6.0_dp
      rotation = reshape([1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, cos(angle), sin(angle), &
                          0.0_dp, -sin(angle), cos(angle)], [3, 3])
      trapezoid = reshape([0.0_dp, 0.0_dp, 0.0_dp, 4.0_dp, 0.0_dp, 0.0_dp, &
                           3.0_dp, 2.0_dp, 0.0_dp, 1.0_dp, 2.0_dp, 0.0_dp], [3, 4])
      trapezoid = matmul(rotation, trapezoid)
      expected = [5.0_dp/3.0_dp, 5.0_dp/3.0_dp, 4.0_dp/3.0_dp, 4.0_dp/3.0_dp]
      call face_area_weights(trapezoid, weights)
      do a = 1, 4
         call check_close(error, weights(a), expected(a), 1.0e-14_dp, message='weight '//to_string(a))
         if (allocated(error)) return
      end do
   end subroutine test_trapezoid_weights

   !> On a plane face n is constant, so f_a = -p n integral N_a dA = -p n w_a.
   subroutine test_plane_force_matches_weights(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: pressure = 7.0_dp
      real(dp) :: face(3, 4), weights(4), force(12), normal(3)
      integer :: a, i
      face = reshape([0.0_dp, 0.0_dp, 1.0_dp, 3.0_dp, 0.5_dp, 1.0_dp, &
                      2.5_dp, 2.0_dp, 1.0_dp, 0.4_dp, 1.5_dp, 1.0_dp], [3, 4])
      normal = [0.0_dp, 0.0_dp, 1.0_dp]  ! counter-clockwise seen from +z
      call face_area_weights(face, weights)
      call pressure_load(new_quad4_cell(), face, spread([0.0_dp, 0.0_dp, 0.0_dp], 2, 4), pressure, .false., force)
      do a = 1, 4
         do i = 1, 3
            call check_close(error, force(3*(a - 1) + i), -pressure*normal(i)*weights(a), 1.0e-14_dp, &
                             1.0e-14_dp*pressure*maxval(weights), 'node '//to_string(a))
            if (allocated(error)) return
         end do
      end do
   end subroutine test_plane_force_matches_weights

   !> Sum of the nodal forces against an expected total, relative to its size.
   subroutine check_total(error, force, expected)
      type(error_t), allocatable, intent(out) :: error
      real(dp), intent(in) :: force(12), expected(3)
      real(dp) :: total(3)
      integer :: i
      total = sum(reshape(force, [3, 4]), dim=2)
      do i = 1, 3
         call check_close(error, total(i), expected(i), 1.0e-13_dp, 1.0e-13_dp*norm2(expected), &
                          'total force direction '//to_string(i))
         if (allocated(error)) return
      end do
   end subroutine check_total

   subroutine test_face_shape_functions(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: h = 1.0e-3_dp
      real(dp), parameter :: points(2, 3) = reshape([0.3_dp, -0.7_dp, -0.45_dp, 0.2_dp, 1.3_dp, 0.9_dp], [2, 3])
      real(dp) :: shape(4), d_xi(4), d_eta(4), plus(4), minus(4), unused_xi(4), unused_eta(4)
      integer :: a, b, p
      do b = 1, 4
         call face_shape_functions([face_node_xi(b), face_node_eta(b)], shape, d_xi, d_eta)
         do a = 1, 4
            call check_close(error, shape(a), merge(1.0_dp, 0.0_dp, a == b), rel_tol=0.0_dp, &
                             abs_tol=1.0e-15_dp, &
                             message='N_'//to_string(a)//' at node '//to_string(b))
            if (allocated(error)) return
         end do
      end do
      do p = 1, size(points, 2)
         call face_shape_functions(points(:, p), shape, d_xi, d_eta)
         call check_close(error, sum(shape), 1.0_dp, rel_tol=0.0_dp, abs_tol=1.0e-15_dp, &
                          message='partition of unity')
         if (allocated(error)) return
         call face_shape_functions(points(:, p) + [h, 0.0_dp], plus, unused_xi, unused_eta)
         call face_shape_functions(points(:, p) - [h, 0.0_dp], minus, unused_xi, unused_eta)
         do a = 1, 4
            call check_close(error, d_xi(a), (plus(a) - minus(a))/(2.0_dp*h), rel_tol=0.0_dp, &
                             abs_tol=1.0e-12_dp, &
                             message='dN_'//to_string(a)//'/dxi')
            if (allocated(error)) return
         end do
         call face_shape_functions(points(:, p) + [0.0_dp, h], plus, unused_xi, unused_eta)
         call face_shape_functions(points(:, p) - [0.0_dp, h], minus, unused_xi, unused_eta)
         do a = 1, 4
            call check_close(error, d_eta(a), (plus(a) - minus(a))/(2.0_dp*h), rel_tol=0.0_dp, &
                             abs_tol=1.0e-12_dp, &
                             message='dN_'//to_string(a)//'/deta')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_face_shape_functions

   subroutine test_cross_product(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: left(3) = [1.5_dp, -2.0_dp, 0.25_dp], right(3) = [-0.5_dp, 3.0_dp, 4.0_dp]
      real(dp) :: product(3)
      integer :: k
      do k = 1, 3
         product = cross_product(unit_vector(k), unit_vector(mod(k, 3) + 1))
         call check(error, all(product == unit_vector(mod(k + 1, 3) + 1)), &
                    'e_'//to_string(k)//' x e_'//to_string(mod(k, 3) + 1)//' = e_'//to_string(mod(k + 1, 3) + 1))
         if (allocated(error)) return
      end do
      ! left x right by hand: (-2*4 - 0.25*3, 0.25*(-0.5) - 1.5*4, 1.5*3 - (-2)*(-0.5)) = (-8.75, -6.125, 3.5)
      product = cross_product(left, right)
      call check(error, all(product == [-8.75_dp, -6.125_dp, 3.5_dp]), 'left x right by hand')
      if (allocated(error)) return
      call check(error, all(cross_product(right, left) == -product), 'anticommutative')
      if (allocated(error)) return
      call check_close(error, dot_product(product, left), 0.0_dp, rel_tol=0.0_dp, abs_tol=1.0e-14_dp, &
                       message='orthogonal to left')
      if (allocated(error)) return
      call check_close(error, dot_product(product, right), 0.0_dp, rel_tol=0.0_dp, abs_tol=1.0e-14_dp, &
                       message='orthogonal to right')
   end subroutine test_cross_product

   !> Cartesian basis vector e_k.
   pure function unit_vector(k) result(vector)
      integer, intent(in) :: k
      real(dp) :: vector(3)
      vector = 0.0_dp
      vector(k) = 1.0_dp
   end function unit_vector

   !> (d1 x d2)/2 with d1 = x3 - x1, d2 = x4 - x2: the vector area of a bilinear face.
   pure function half_diagonal_cross(x) result(area)
      real(dp), intent(in) :: x(3, 4)
      real(dp) :: area(3), d1(3), d2(3)
      d1 = x(:, 3) - x(:, 1)
      d2 = x(:, 4) - x(:, 2)
      area = 0.5_dp*[d1(2)*d2(3) - d1(3)*d2(2), d1(3)*d2(1) - d1(1)*d2(3), d1(1)*d2(2) - d1(2)*d2(1)]
   end function half_diagonal_cross
end module test_surface_load
