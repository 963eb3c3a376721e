!> Consistent tangents of the contact kernel against central differences of its internal
!> force (reference: the kernel's own residual, differenced with step 1e-7 x face size; the
!> status is checked at every perturbed point so that no difference crosses a branch).
!> Geometry: the warped face of test_contact_fixtures (non-planar, non-rectangular);
!> eps_N = 1e4, eps_T = 1e3, A_s = 0.5, penetration 0.01 so p_N = 100; with mu = 0.3 the slip
!> limit is 30, reached at an elastic slip of 0.03: anchors 0.01 away stick, 0.1 away slip.
module test_contact_tangent
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check
   use frix_strings, only: to_string
   use frix_contact_kernel, only: contact_open, contact_stick, contact_slip, contact_point_result_t, &
                                  node_face_contact
   use frix_face_projection, only: face_position, face_normal, face_shape_functions
   use test_contact_fixtures, only: warped_face, make_parameters, check_face_tangent, check_plane_tangent, &
                                    asymmetry, slave_below, grid_patch, slave_below_smoothed, fold_surface
   use frix_contact_patches, only: surface_patches_t, surface_patches, ring_nodes_of, patch_faces_of
   implicit none
   private

   public :: collect_contact_tangent

   real(dp), parameter :: area = 0.5_dp, depth = 0.01_dp, mu = 0.3_dp
   !> The face sharing warped_face's edge xi1 = +1 (its nodes 2 and 3), continuing the surface
   !> with a kink; counter-clockwise seen from +z like warped_face. On it that edge is xi1 = -1.
   real(dp), parameter :: neighbour_face(3, 4) = reshape([2.1_dp, 0.2_dp, 0.3_dp, 4.0_dp, 0.1_dp, 0.2_dp, &
                                                           3.9_dp, 1.8_dp, 0.0_dp, 1.8_dp, 1.7_dp, -0.2_dp], [3, 4])
   !> A rigid plane through (0.1, -0.2, 0.3) with a tilted normal (not a coordinate axis).
   real(dp), parameter :: plane_point(3) = [0.1_dp, -0.2_dp, 0.3_dp]
   real(dp), parameter :: plane_normal(3) = [0.2_dp, -0.3_dp, 1.0_dp]

contains

   subroutine collect_contact_tangent(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('open: zero force and tangent', test_open), &
               new_unittest('warped face, inside, stick', test_inside_stick), &
               new_unittest('warped face, inside, slip (unsymmetric)', test_inside_slip), &
               new_unittest('warped face, inside, frictionless (symmetric)', test_inside_frictionless), &
               new_unittest('warped face, no anchor yet: stick at zero traction', test_no_anchor), &
               new_unittest('warped face, near an edge (xi = 0.95), stick', test_edge_stick), &
               new_unittest('warped face, near an edge (xi = 0.95), slip', test_edge_slip), &
               new_unittest('warped face, beyond an edge, clamped, slip', test_clamped_edge), &
               new_unittest('warped face, beyond a corner, clamped, stick', test_clamped_corner_stick), &
               new_unittest('warped face, beyond a free edge, in the fade, slip', test_free_edge_slip), &
               new_unittest('warped face, beyond a free edge, in the fade, stick', test_free_edge_stick), &
               new_unittest('warped face, beyond a corner of two free edges, in the fade, slip', &
                            test_free_corner_slip), &
               new_unittest('warped face, beyond a corner, clamped, slip', test_clamped_corner_slip), &
               new_unittest('anchor on the neighbouring face, stick', test_other_face_stick), &
               new_unittest('anchor on the neighbouring face, slip', test_other_face_slip), &
               new_unittest('anchor on the neighbouring face: stick commits its projection', &
                            test_other_face_commit), &
               new_unittest('smoothed normals, inside, stick', test_smoothed_stick), &
               new_unittest('feature angle 30: patch cut at a 90-degree fold, slip and stick', test_feature_angle), &
               new_unittest('smoothed normals, inside, slip', test_smoothed_slip), &
               new_unittest('smoothed normals, inside, frictionless', test_smoothed_frictionless), &
               new_unittest('smoothed normals, near an edge (xi = 0.95), slip', test_smoothed_edge_slip), &
               new_unittest('smoothed normals, border face, clamped beyond its free edge, slip', &
                            test_smoothed_clamped), &
               new_unittest('smoothed normals, anchor on the neighbouring face, stick', test_smoothed_other_face), &
               new_unittest('smoothed normals, projection beyond the face, facet point inside: clamped', &
                            test_smoothed_facet_inside), &
               new_unittest('rigid plane, stick (symmetric)', test_plane_stick), &
               new_unittest('rigid plane, slip (unsymmetric)', test_plane_slip), &
               new_unittest('augmented friction: tangential multiplier, stick and slip', test_tangential_multiplier), &
               new_unittest('augmented friction, rigid plane: stick and slip', test_plane_tangential_multiplier)]
   end subroutine collect_contact_tangent

   !> A tangential multiplier lambda_T (with a normal component, which the kernel drops) in the
   !> trial traction: the tangent still equals the differences of fint, stick and slip.
   subroutine test_tangential_multiplier(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(15, 15)
      real(dp), parameter :: lambda(3) = [3.0e2_dp, -2.0e2_dp, 5.0e1_dp]
      call check_face_tangent(error, make_parameters(mu), slave_below(warped_face, [0.2_dp, -0.3_dp], depth), &
                              warped_face, area, [0.205_dp, -0.305_dp], .true., .false., contact_stick, tangent, &
                              tangential_multiplier=0.01_dp*lambda)
      if (allocated(error)) return
      call check_face_tangent(error, make_parameters(mu), slave_below(warped_face, [0.2_dp, -0.3_dp], depth), &
                              warped_face, area, [0.205_dp, -0.305_dp], .true., .false., contact_slip, tangent, &
                              tangential_multiplier=lambda)
   end subroutine test_tangential_multiplier

   subroutine test_open(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(15, 15)
      call check_face_tangent(error, make_parameters(mu), slave_below(warped_face, [0.2_dp, -0.3_dp], -depth), &
                              warped_face, area, [0.21_dp, -0.3_dp], .true., .false., contact_open, tangent)
   end subroutine test_open

   subroutine test_inside_stick(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(15, 15)
      call check_face_tangent(error, make_parameters(mu), slave_below(warped_face, [0.2_dp, -0.3_dp], depth), &
                              warped_face, area, [0.205_dp, -0.305_dp], .true., .false., contact_stick, tangent)
   end subroutine test_inside_stick

   subroutine test_inside_slip(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(15, 15)
      call check_face_tangent(error, make_parameters(mu), slave_below(warped_face, [0.2_dp, -0.3_dp], depth), &
                              warped_face, area, [0.3_dp, -0.25_dp], .true., .false., contact_slip, tangent)
      if (allocated(error)) return
      call check(error, asymmetry(tangent) > 1.0e-3_dp, 'slip tangent should be unsymmetric, asymmetry '// &
                 to_string(asymmetry(tangent)))
   end subroutine test_inside_slip

   !> Frictionless: fint is the gradient of the penalty potential eps_N A g^2/2 (g the signed
   !> distance to the closest point), so the tangent is its Hessian: symmetric.
   subroutine test_inside_frictionless(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(15, 15)
      call check_face_tangent(error, make_parameters(0.0_dp), slave_below(warped_face, [0.2_dp, -0.3_dp], depth), &
                              warped_face, area, [0.3_dp, -0.25_dp], .true., .false., contact_slip, tangent)
      if (allocated(error)) return
      call check(error, asymmetry(tangent) < 1.0e-12_dp, 'frictionless tangent should be symmetric, asymmetry '// &
                 to_string(asymmetry(tangent)))
   end subroutine test_inside_frictionless

   subroutine test_no_anchor(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(15, 15)
      call check_face_tangent(error, make_parameters(mu), slave_below(warped_face, [0.2_dp, -0.3_dp], depth), &
                              warped_face, area, [9.0_dp, 9.0_dp], .false., .false., contact_stick, tangent)
   end subroutine test_no_anchor

   subroutine test_edge_stick(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(15, 15)
      call check_face_tangent(error, make_parameters(mu), slave_below(warped_face, [0.95_dp, 0.4_dp], depth), &
                              warped_face, area, [0.945_dp, 0.405_dp], .true., .false., contact_stick, tangent)
   end subroutine test_edge_stick

   subroutine test_edge_slip(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(15, 15)
      call check_face_tangent(error, make_parameters(mu), slave_below(warped_face, [0.95_dp, 0.4_dp], depth), &
                              warped_face, area, [0.85_dp, 0.45_dp], .true., .false., contact_slip, tangent)
   end subroutine test_edge_slip

   !> A slave 0.05 (in xi1) beyond the edge xi1 = +1, below the extrapolated surface: the
   !> clamped closest point lies on that edge (xi1 fixed, xi2 free).
   subroutine test_clamped_edge(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(15, 15)
      call check_face_tangent(error, make_parameters(mu), slave_below(warped_face, [1.05_dp, 0.3_dp], depth), &
                              warped_face, area, [0.9_dp, 0.35_dp], .true., .true., contact_slip, tangent)
   end subroutine test_clamped_edge

   !> A slave beyond the corner xi = (1, 1): the clamped point is the corner node 3.
   subroutine test_clamped_corner_stick(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(15, 15)
      call check_face_tangent(error, make_parameters(mu), slave_below(warped_face, [1.01_dp, 1.01_dp], depth), &
                              warped_face, area, [0.995_dp, 0.995_dp], .true., .true., contact_stick, tangent)
   end subroutine test_clamped_corner_stick

   !> A slave 0.15 (in xi1: 0.075 of the face's length) beyond the edge xi1 = +1, a free edge of
   !> the master: the force is faded (the zone 0.1, the fade from 0.05), its derivative enters
   !> the tangent.
   subroutine test_free_edge_slip(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(15, 15)
      call check_face_tangent(error, make_parameters(mu), slave_below(warped_face, [1.15_dp, 0.3_dp], depth), &
                              warped_face, area, [0.9_dp, 0.35_dp], .true., .true., contact_slip, tangent, &
                              free_edges=[.false., .true., .false., .false.])
   end subroutine test_free_edge_slip

   subroutine test_free_edge_stick(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(15, 15)
      call check_face_tangent(error, make_parameters(mu), slave_below(warped_face, [1.15_dp, 0.3_dp], depth), &
                              warped_face, area, [1.148_dp, 0.301_dp], .true., .true., contact_stick, tangent, &
                              free_edges=[.false., .true., .false., .false.])
   end subroutine test_free_edge_stick

   !> Beyond the corner xi = (1, 1) where the free edges 2 (xi1 = +1) and 3 (xi2 = +1) meet:
   !> faded across both.
   subroutine test_free_corner_slip(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(15, 15)
      call check_face_tangent(error, make_parameters(mu), slave_below(warped_face, [1.14_dp, 1.12_dp], depth), &
                              warped_face, area, [0.9_dp, 0.95_dp], .true., .true., contact_slip, tangent, &
                              free_edges=[.false., .true., .true., .false.])
   end subroutine test_free_corner_slip

   subroutine test_clamped_corner_slip(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(15, 15)
      call check_face_tangent(error, make_parameters(mu), slave_below(warped_face, [1.04_dp, 1.03_dp], depth), &
                              warped_face, area, [0.9_dp, 0.95_dp], .true., .true., contact_slip, tangent)
   end subroutine test_clamped_corner_slip

   !> A node that slid from neighbour_face onto warped_face across their common edge: its
   !> anchor is a material point of neighbour_face, whose 12 coordinates enter the tangent.
   subroutine test_other_face_stick(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(27, 27)
      call check_face_tangent(error, make_parameters(mu), slave_below(warped_face, [0.99_dp, 0.4_dp], depth), &
                              warped_face, area, [-0.995_dp, 0.4_dp], .true., .false., contact_stick, tangent, &
                              x_anchor_face=neighbour_face)
      if (allocated(error)) return
      call check(error, maxval(abs(tangent(:, 16:27))) > 1.0e-2_dp*maxval(abs(tangent)), &
                 'the anchor face nodes should enter the tangent')
   end subroutine test_other_face_stick

   subroutine test_other_face_slip(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(27, 27)
      call check_face_tangent(error, make_parameters(mu), slave_below(warped_face, [0.9_dp, 0.4_dp], depth), &
                              warped_face, area, [-0.8_dp, 0.5_dp], .true., .false., contact_slip, tangent, &
                              x_anchor_face=neighbour_face)
      if (allocated(error)) return
      call check(error, maxval(abs(tangent(:, 16:27))) > 1.0e-3_dp*maxval(abs(tangent)), &
                 'the anchor face nodes should enter the tangent')
   end subroutine test_other_face_slip

   !> In stick with the anchor on neighbour_face, the anchor to commit is the projection of
   !> x_A onto warped_face: x(new_anchor_xi) - x_A is normal to warped_face there (closest
   !> point), and no slip is counted.
   subroutine test_other_face_commit(error)
      type(error_t), allocatable, intent(out) :: error
      type(contact_point_result_t) :: result
      real(dp) :: fint(27), tangent(27, 27), x_anchor(3), offset(3), shape(4), d_xi(4), d_eta(4)
      real(dp) :: a1(3), a2(3)
      integer :: k
      call node_face_contact(make_parameters(mu), slave_below(warped_face, [0.99_dp, 0.4_dp], depth), &
                             warped_face, area, [-0.995_dp, 0.4_dp], .true., .false., result, fint, tangent, &
                             x_anchor_face=neighbour_face)
      call check(error, result%status == contact_stick, 'stick')
      if (allocated(error)) return
      x_anchor = face_position(neighbour_face, [-0.995_dp, 0.4_dp])
      offset = x_anchor - face_position(warped_face, result%new_anchor_xi)
      call face_shape_functions(result%new_anchor_xi, shape, d_xi, d_eta)
      do k = 1, 3
         a1(k) = dot_product(d_xi, warped_face(k, :))
         a2(k) = dot_product(d_eta, warped_face(k, :))
      end do
      call check(error, abs(dot_product(offset, a1)) <= 1.0e-12_dp*norm2(a1) .and. &
                 abs(dot_product(offset, a2)) <= 1.0e-12_dp*norm2(a2), &
                 'committed anchor = closest point of x_A on the contact face, tangential offset '// &
                 to_string(max(abs(dot_product(offset, a1)), abs(dot_product(offset, a2)))))
      if (allocated(error)) return
      call check(error, result%slip_increment == 0.0_dp .and. all(fint(16:27) == 0.0_dp), &
                 'no slip counted in stick, no force on the anchor face')
   end subroutine test_other_face_commit

   !> Smoothed normals on face (2, 2) of grid_patch (12 ring nodes, 51 unknowns): the slave
   !> at depth 0.01 below x(xi) along the smoothed normal, the anchor near (stick) or far
   !> (slip); the ring nodes must enter the tangent.
   subroutine check_smoothed(error, coefficient, xi, anchor_xi, expected_status, i, clamp)
      type(error_t), allocatable, intent(out) :: error
      real(dp), intent(in) :: coefficient, xi(2), anchor_xi(2)
      integer, intent(in) :: expected_status, i
      logical, intent(in) :: clamp
      real(dp) :: x_face(3, 4)
      real(dp), allocatable :: x_ring(:, :), tangent(:, :)
      integer, allocatable :: patch_faces(:, :)
      integer :: n
      call grid_patch(i, 2, x_face, x_ring, patch_faces)
      n = 15 + size(x_ring)
      allocate (tangent(n, n))
      call check_face_tangent(error, make_parameters(coefficient), &
                              slave_below_smoothed(x_face, x_ring, patch_faces, xi, depth), x_face, area, anchor_xi, &
                              .true., clamp, expected_status, tangent, x_ring=x_ring, patch_faces=patch_faces)
      if (allocated(error)) return
      call check(error, maxval(abs(tangent(:, 16:))) > 1.0e-3_dp*maxval(abs(tangent)), &
                 'the ring nodes should enter the tangent, max '//to_string(maxval(abs(tangent(:, 16:)))))
   end subroutine check_smoothed

   !> Face 3 of fold_surface (the first face past the 90-degree fold, first row): with feature
   !> angle 30 its patch leaves out the 2 faces across the fold, 4 of 6 faces kept; slave at
   !> depth 0.01 along the smoothed normal, anchor far (slip) or near (stick): the tangent
   !> must still match the central differences.
   subroutine test_feature_angle(error)
      type(error_t), allocatable, intent(out) :: error
      type(surface_patches_t) :: patches
      real(dp) :: coords(3, 21), x_face(3, 4)
      real(dp), allocatable :: x_ring(:, :), tangent(:, :)
      integer :: faces(4, 12), k
      integer, allocatable :: patch_faces(:, :)
      real(dp), parameter :: xi(2, 2) = reshape([-0.7_dp, 0.3_dp, 0.4_dp, -0.2_dp], [2, 2])
      real(dp), parameter :: anchor(2, 2) = reshape([-0.5_dp, 0.4_dp, 0.405_dp, -0.205_dp], [2, 2])
      integer, parameter :: status(2) = [contact_slip, contact_stick]
      call fold_surface(coords, faces)
      call surface_patches(coords, faces, 30.0_dp, patches)
      x_face = coords(:, faces(:, 3))
      x_ring = coords(:, ring_nodes_of(patches, 3))
      patch_faces = patch_faces_of(patches, 3)
      call check(error, size(patch_faces, 2) == 4, 'face 3: 4 patch faces, got '//to_string(size(patch_faces, 2)))
      if (allocated(error)) return
      allocate (tangent(15 + size(x_ring), 15 + size(x_ring)))
      do k = 1, 2
         call check_face_tangent(error, make_parameters(mu), &
                                 slave_below_smoothed(x_face, x_ring, patch_faces, xi(:, k), depth), x_face, area, &
                                 anchor(:, k), .true., .false., status(k), tangent, x_ring=x_ring, &
                                 patch_faces=patch_faces)
         if (allocated(error)) return
      end do
   end subroutine test_feature_angle

   subroutine test_smoothed_stick(error)
      type(error_t), allocatable, intent(out) :: error
      call check_smoothed(error, mu, [0.2_dp, -0.3_dp], [0.205_dp, -0.305_dp], contact_stick, 2, .false.)
   end subroutine test_smoothed_stick

   subroutine test_smoothed_slip(error)
      type(error_t), allocatable, intent(out) :: error
      call check_smoothed(error, mu, [0.2_dp, -0.3_dp], [0.3_dp, -0.25_dp], contact_slip, 2, .false.)
   end subroutine test_smoothed_slip

   subroutine test_smoothed_frictionless(error)
      type(error_t), allocatable, intent(out) :: error
      call check_smoothed(error, 0.0_dp, [0.2_dp, -0.3_dp], [0.3_dp, -0.25_dp], contact_slip, 2, .false.)
   end subroutine test_smoothed_frictionless

   subroutine test_smoothed_edge_slip(error)
      type(error_t), allocatable, intent(out) :: error
      call check_smoothed(error, mu, [0.95_dp, 0.4_dp], [0.85_dp, 0.45_dp], contact_slip, 2, .false.)
   end subroutine test_smoothed_edge_slip

   !> Face (1, 2) lies on the grid's border x = 0 (its edge xi1 = -1 is free, 6 ring nodes):
   !> a slave 0.05 beyond that edge is clamped onto it.
   subroutine test_smoothed_clamped(error)
      type(error_t), allocatable, intent(out) :: error
      call check_smoothed(error, mu, [-1.05_dp, 0.3_dp], [-0.9_dp, 0.35_dp], contact_slip, 1, .true.)
   end subroutine test_smoothed_clamped

   !> A node that slid from face (3, 2) onto face (2, 2): 3 (1 + 4 + 4 + 12) = 63 unknowns,
   !> the largest kernel.
   subroutine test_smoothed_other_face(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: x_face(3, 4), x_neighbour(3, 4)
      real(dp), allocatable :: x_ring(:, :), other_ring(:, :), tangent(:, :)
      integer, allocatable :: patch_faces(:, :), other_patch(:, :)
      call grid_patch(2, 2, x_face, x_ring, patch_faces)
      call grid_patch(3, 2, x_neighbour, other_ring, other_patch)
      allocate (tangent(63, 63))
      call check_face_tangent(error, make_parameters(mu), &
                              slave_below_smoothed(x_face, x_ring, patch_faces, [0.99_dp, 0.4_dp], depth), x_face, &
                              area, [-0.995_dp, 0.4_dp], .true., .false., contact_stick, tangent, &
                              x_anchor_face=x_neighbour, x_ring=x_ring, patch_faces=patch_faces)
      if (allocated(error)) return
      call check(error, maxval(abs(tangent(:, 16:27))) > 1.0e-2_dp*maxval(abs(tangent)), &
                 'the anchor face nodes should enter the tangent')
   end subroutine test_smoothed_other_face

   !> A slave 0.06 below the facet point xi = (0.99, 0.99) of face (2, 2) along the FACET
   !> normal: its projection along the smoothed normals lies beyond the face (xi2 > 1), its
   !> facet closest point inside. With clamp the kernel uses that facet point (not clamped to
   !> an edge) with the smoothed normal there, and its tangent is exact (the case found by the
   !> review of the smoothed normals, met by slaves on the symmetry planes of S3).
   subroutine test_smoothed_facet_inside(error)
      type(error_t), allocatable, intent(out) :: error
      type(contact_point_result_t) :: result
      real(dp) :: x_face(3, 4)
      real(dp), allocatable :: x_ring(:, :), tangent(:, :), fint(:)
      integer, allocatable :: patch_faces(:, :)
      real(dp) :: x_slave(3)
      integer :: k
      real(dp), parameter :: coefficients(2) = [0.0_dp, mu]
      call grid_patch(2, 2, x_face, x_ring, patch_faces)
      x_slave = slave_below(x_face, [0.99_dp, 0.99_dp], 0.06_dp)
      allocate (tangent(15 + size(x_ring), 15 + size(x_ring)), fint(15 + size(x_ring)))
      call node_face_contact(make_parameters(mu), x_slave, x_face, area, [0.4_dp, 0.3_dp], .true., .true., &
                             result, fint, tangent, x_ring=x_ring, patch_faces=patch_faces)
      call check(error, result%clamped .and. all(abs(result%xi - [0.99_dp, 0.99_dp]) < 1.0e-10_dp), &
                 'clamped at the facet closest point (0.99, 0.99), got '//to_string(result%xi(1))//' '// &
                 to_string(result%xi(2)))
      if (allocated(error)) return
      do k = 1, 2   ! frictionless, then slip
         call check_face_tangent(error, make_parameters(coefficients(k)), x_slave, x_face, area, [0.4_dp, 0.3_dp], &
                                 .true., .true., contact_slip, tangent, x_ring=x_ring, patch_faces=patch_faces)
         if (allocated(error)) return
      end do
   end subroutine test_smoothed_facet_inside

   subroutine test_plane_stick(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(3, 3), normal(3), slave(3), anchor(3)
      normal = plane_normal/norm2(plane_normal)
      slave = plane_point + [0.4_dp, 0.3_dp, 0.0_dp] - depth*normal
      anchor = slave + [0.01_dp, -0.005_dp, 0.0_dp]
      call check_plane_tangent(error, make_parameters(mu), slave, plane_point, plane_normal, area, anchor, &
                               contact_stick, tangent)
      if (allocated(error)) return
      call check(error, asymmetry(tangent) < 1.0e-14_dp, 'stick tangent on a plane should be symmetric')
   end subroutine test_plane_stick

   subroutine test_plane_tangential_multiplier(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(3, 3), normal(3), slave(3), anchor(3)
      real(dp), parameter :: lambda(3) = [3.0e2_dp, -2.0e2_dp, 5.0e1_dp]
      normal = plane_normal/norm2(plane_normal)
      slave = plane_point + [0.4_dp, 0.3_dp, 0.0_dp] - depth*normal
      anchor = slave + [0.01_dp, -0.005_dp, 0.0_dp]
      call check_plane_tangent(error, make_parameters(mu), slave, plane_point, plane_normal, area, anchor, &
                               contact_stick, tangent, tangential_multiplier=0.01_dp*lambda)
      if (allocated(error)) return
      call check_plane_tangent(error, make_parameters(mu), slave, plane_point, plane_normal, area, anchor, &
                               contact_slip, tangent, tangential_multiplier=lambda)
   end subroutine test_plane_tangential_multiplier

   subroutine test_plane_slip(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: tangent(3, 3), normal(3), slave(3), anchor(3)
      normal = plane_normal/norm2(plane_normal)
      slave = plane_point + [0.4_dp, 0.3_dp, 0.0_dp] - depth*normal
      anchor = slave + [0.1_dp, -0.05_dp, 0.0_dp]
      call check_plane_tangent(error, make_parameters(mu), slave, plane_point, plane_normal, area, anchor, &
                               contact_slip, tangent)
      if (allocated(error)) return
      call check(error, asymmetry(tangent) > 1.0e-3_dp, 'slip tangent should be unsymmetric')
   end subroutine test_plane_slip
end module test_contact_tangent
