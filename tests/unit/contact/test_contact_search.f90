!> The contact search (frix_contact_search). References: on the flat unit grid of 3 x 3 faces
!> in z = 0 (face 1 + i + 3 j spans [i, i + 1] x [j, j + 1]) the nearest face of a node above
!> the surface is the one under it, by hand; a node higher than the search band, or outside
!> every face box, gets none; on an edge shared by two faces the node keeps its face; moving
!> the master by u moves the answer with it. Beyond the surface's free edge (its boundary) the
!> nearest (clamped) face is kept within the extension zone, 0.1 of the face's length across
!> the edge (0.1 on the unit grid, 0.2 across the edges x = const of a grid stretched to 2 in
!> x, still 0.1 across y = const), farther the node gets none (also with smoothed normals,
!> and no initial anchor), except in a tie. On a wavy 10 x 10 surface the bucket grid gives
!> the same faces as a brute-force search over all faces (without free edges: the free-edge
!> rule acts after the grid's choice). With smoothed normals a node placed along the smoothed
!> normal below a face point gets that face and, as initial anchor, that point.
module test_contact_search
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close
   use frix_strings, only: to_string
   use frix_face_projection, only: closest_point_in_face, face_position, face_normal
   use frix_smoothed_normals, only: smooth_normal_at
   use frix_contact_patches, only: surface_patches, all_faces_angle, free_edges
   use frix_contact_pass, only: contact_pass_t, start_pass_state
   use frix_contact_search, only: assign_faces, initial_anchors, plane_anchors, face_nodal_normals
   use test_contact_fixtures, only: grid_faces, fold_surface
   implicit none
   private

   public :: collect_contact_search

   real(dp), parameter :: band = 0.5_dp, edge_tolerance = 1.0e-6_dp

contains

   subroutine collect_contact_search(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('flat grid: face under the node, band, outside', test_flat), &
               new_unittest('beyond a free edge: the extension zone, then open', test_free_edge), &
               new_unittest('beyond a free edge: no face with smoothed normals, no anchor, tie kept', &
                            test_free_edge_cases), &
               new_unittest('beyond the free edge of a nearer face: the face under the node', &
                            test_free_edge_nearer), &
               new_unittest('node on a shared edge keeps its current face', test_tie), &
               new_unittest('displaced master: the face moves with u', test_displaced), &
               new_unittest('wavy 10 x 10 surface: bucket grid = brute force', test_brute_force), &
               new_unittest('initial anchors: closest point; no face, no anchor', test_anchors), &
               new_unittest('smoothed normals: face and anchor of the normal projection', test_smoothed), &
               new_unittest('rigid plane: the anchors are the foot points', test_plane), &
               new_unittest('feature angle 30: faces on both sides of a 90-degree fold', test_fold)]
   end subroutine collect_contact_search

   !> A pass of slave points against the n x n faces of a grid of nodes 1 + i + (n + 1) j at
   !> (i, j, height(i, j)); the slaves are nodes (n + 1)^2 + 1, ... of coords.
   subroutine grid_pass(n, slaves, coords, pass, wavy)
      integer, intent(in) :: n
      real(dp), intent(in) :: slaves(:, :)
      real(dp), allocatable, intent(out) :: coords(:, :)
      type(contact_pass_t), intent(out) :: pass
      logical, intent(in) :: wavy   !! z = 0.15 (x - 1.5)^2 - 0.1 (y - 1.5)^2 + 0.05 x y (else 0)
      integer :: i, j, n_grid
      real(dp) :: x, y
      n_grid = (n + 1)**2
      allocate (coords(3, n_grid + size(slaves, 2)), source=0.0_dp)
      do j = 0, n
         do i = 0, n
            x = real(i, dp)
            y = real(j, dp)
            coords(:, 1 + i + (n + 1)*j) = [x, y, 0.0_dp]
            if (wavy) coords(3, 1 + i + (n + 1)*j) = 0.15_dp*(x - 1.5_dp)**2 - 0.1_dp*(y - 1.5_dp)**2 + 0.05_dp*x*y
         end do
      end do
      coords(:, n_grid + 1:) = slaves
      pass%faces = grid_faces(n)
      pass%free_edge = free_edges(size(coords, 2), pass%faces)
      pass%slave_nodes = [(n_grid + i, i=1, size(slaves, 2))]
      pass%band = band
      call start_pass_state(pass)
   end subroutine grid_pass

   subroutine test_flat(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: coords(:, :), zero(:)
      type(contact_pass_t) :: pass
      ! above face 5; slightly into face 7; above the band; far outside
      real(dp), parameter :: slaves(3, 4) = reshape([1.5_dp, 1.5_dp, 0.1_dp, 0.2_dp, 2.7_dp, -0.05_dp, &
                                                     1.5_dp, 1.5_dp, 0.7_dp, 5.0_dp, 5.0_dp, 0.0_dp], [3, 4])
      call grid_pass(3, slaves, coords, pass, .false.)
      allocate (zero(size(coords)), source=0.0_dp)
      call assign_faces(coords, zero, edge_tolerance, pass)
      call check(error, all(pass%face == [5, 7, 0, 0]), 'faces '//faces_text(pass%face))
   end subroutine test_flat

   !> The unit 3 x 3 grid, 0.1 above it, beyond its free edges: x = 3 by 0.05 (inside the zone:
   !> face 3), by 0.15 and 0.3 (open); beyond the corner (3, 3) by 0.05 in x and y (face 9), by
   !> 0.05 in x and 0.2 in y (open); y = 0 by 0.05 (face 2). Then the grid stretched to 2 in x:
   !> beyond x = 6 by 0.15 (zone 0.2: face 3), by 0.25 (open); beyond y = 0 by 0.15 (zone 0.1,
   !> the face's length across that edge, not along it: open).
   subroutine test_free_edge(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: coords(:, :), zero(:)
      type(contact_pass_t) :: pass
      real(dp), parameter :: slaves(3, 6) = reshape([3.05_dp, 0.5_dp, 0.1_dp, 3.15_dp, 0.5_dp, 0.1_dp, &
                                                     3.3_dp, 0.5_dp, 0.1_dp, 3.05_dp, 3.05_dp, 0.1_dp, &
                                                     3.05_dp, 3.2_dp, 0.1_dp, 1.5_dp, -0.05_dp, 0.1_dp], [3, 6])
      real(dp), parameter :: stretched(3, 3) = reshape([6.15_dp, 0.5_dp, 0.1_dp, 6.25_dp, 0.5_dp, 0.1_dp, &
                                                        3.0_dp, -0.15_dp, 0.1_dp], [3, 3])
      call grid_pass(3, slaves, coords, pass, .false.)
      allocate (zero(size(coords)), source=0.0_dp)
      call assign_faces(coords, zero, edge_tolerance, pass)
      call check(error, all(pass%face == [3, 0, 0, 9, 0, 2]), 'unit grid: faces '//faces_text(pass%face))
      if (allocated(error)) return
      call grid_pass(3, stretched, coords, pass, .false.)
      coords(1, :16) = 2.0_dp*coords(1, :16)
      call assign_faces(coords, zero(:size(coords)), edge_tolerance, pass)
      call check(error, all(pass%face == [3, 0, 0]), 'stretched grid: faces '//faces_text(pass%face))
   end subroutine test_free_edge

   !> The unit 3 x 3 grid and nodes 0.1 above it beyond x = 3 by 0.05 and 0.3: with smoothed
   !> normals (no normal projection inside a face: the facet rule) faces 3 and 0; the initial
   !> anchors, the clamped point (3, 0.5) and none; a tie keeps both (its coverage decides).
   subroutine test_free_edge_cases(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: coords(:, :), zero(:)
      type(contact_pass_t) :: pass
      real(dp), parameter :: slaves(3, 2) = reshape([3.05_dp, 0.5_dp, 0.1_dp, 3.3_dp, 0.5_dp, 0.1_dp], [3, 2])
      call grid_pass(3, slaves, coords, pass, .false.)
      call surface_patches(coords, pass%faces, all_faces_angle, pass%patches)
      pass%smooth = .true.
      call initial_anchors(coords, edge_tolerance, pass)
      call check(error, all(pass%face == [3, 0]), 'smoothed normals: faces '//faces_text(pass%face))
      if (allocated(error)) return
      ! face 3 spans [2, 3] x [0, 1]: (3, 0.5) is xi = (1, 0)
      call check(error, pass%has_anchor(1) .and. pass%anchor_face(1) == 3 .and. &
                 maxval(abs(pass%anchor_xi(:, 1) - [1.0_dp, 0.0_dp])) <= 1.0e-14_dp .and. &
                 .not. pass%has_anchor(2) .and. pass%anchor_face(2) == 0, 'anchors')
      if (allocated(error)) return
      call grid_pass(3, slaves, coords, pass, .false.)
      pass%tied = .true.
      allocate (zero(size(coords)), source=0.0_dp)
      call assign_faces(coords, zero, edge_tolerance, pass)
      call check(error, all(pass%face == [3, 3]), 'tie: faces '//faces_text(pass%face))
   end subroutine test_free_edge_cases

   !> The unit 3 x 3 grid and a separate narrow face 10 (a second part of the master surface)
   !> 0.04 below it, spanning x in [1.53, 1.63], y in [1, 2] (length across its edge x = 1.53:
   !> 0.1, zone 0.01). A node sunk 0.05 into face 5 at (1.5, 1.5) is nearer to face 10's free
   !> edge (0.032) than to face 5 (0.05), and 0.03 beyond that edge: face 10 is not its face, but
   !> face 5, under it, still is.
   subroutine test_free_edge_nearer(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: zero(:)
      real(dp) :: coords(3, 21)
      type(contact_pass_t) :: pass
      real(dp), parameter :: narrow(3, 4) = reshape([1.53_dp, 1.0_dp, -0.04_dp, 1.63_dp, 1.0_dp, -0.04_dp, &
                                                     1.63_dp, 2.0_dp, -0.04_dp, 1.53_dp, 2.0_dp, -0.04_dp], [3, 4])
      integer :: i, j
      ! nodes 1-16 the grid (node 1 + i + 4 j at (i, j, 0)), 17-20 the narrow face, 21 the slave
      do j = 0, 3
         do i = 0, 3
            coords(:, 1 + i + 4*j) = [real(i, dp), real(j, dp), 0.0_dp]
         end do
      end do
      coords(:, 17:20) = narrow
      coords(:, 21) = [1.5_dp, 1.5_dp, -0.05_dp]
      pass%faces = reshape([grid_faces(3), 17, 18, 19, 20], [4, 10])
      pass%free_edge = free_edges(size(coords, 2), pass%faces)
      pass%slave_nodes = [21]
      pass%band = band
      call start_pass_state(pass)
      allocate (zero(size(coords)), source=0.0_dp)
      call assign_faces(coords, zero, edge_tolerance, pass)
      call check(error, all(pass%face == [5]), 'faces '//faces_text(pass%face))
   end subroutine test_free_edge_nearer

   subroutine test_tie(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: coords(:, :), zero(:)
      type(contact_pass_t) :: pass
      integer :: current
      ! above the edge x = 1 shared by faces 4 and 5
      call grid_pass(3, reshape([1.0_dp, 1.5_dp, 0.05_dp], [3, 1]), coords, pass, .false.)
      allocate (zero(size(coords)), source=0.0_dp)
      do current = 4, 5
         pass%face = current
         call assign_faces(coords, zero, edge_tolerance, pass)
         call check(error, pass%face(1) == current, 'current face '//to_string(current)//', got '// &
                    to_string(pass%face(1)))
         if (allocated(error)) return
      end do
   end subroutine test_tie

   subroutine test_displaced(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: coords(:, :), u(:)
      type(contact_pass_t) :: pass
      integer :: node
      call grid_pass(3, reshape([1.5_dp, 1.5_dp, 0.1_dp], [3, 1]), coords, pass, .false.)
      allocate (u(size(coords)), source=0.0_dp)
      do node = 1, 16
         u(3*node - 2) = 1.0_dp   ! the master moves by +1 along x: face 4 comes under the node
      end do
      call assign_faces(coords, u, edge_tolerance, pass)
      call check(error, pass%face(1) == 4, 'face 4, got '//to_string(pass%face(1)))
   end subroutine test_displaced

   subroutine test_brute_force(error)
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: n = 10, n_slaves = 400
      real(dp), allocatable :: coords(:, :), zero(:)
      real(dp) :: slaves(3, n_slaves), x_face(3, 4), xi(2), closest(3), distance, best
      type(contact_pass_t) :: pass
      logical :: fixed(2)
      integer :: i, f, expected, node
      do i = 1, n_slaves
         ! quasi-random points (golden-ratio sequences) over and beyond the surface
         slaves(:, i) = [-0.5_dp + 11.0_dp*frac(0.6180339887_dp*i), -0.5_dp + 11.0_dp*frac(0.7548776662_dp*i), &
                         -1.0_dp + 2.0_dp*frac(0.5698402910_dp*i)]
      end do
      call grid_pass(n, slaves, coords, pass, .false.)
      pass%free_edge = .false.   ! the grid's choice alone (test_free_edge: the rule after it)
      coords(3, :(n + 1)**2) = 0.3_dp*sin(coords(1, :(n + 1)**2))*cos(0.7_dp*coords(2, :(n + 1)**2))
      allocate (zero(size(coords)), source=0.0_dp)
      call assign_faces(coords, zero, edge_tolerance, pass)
      do i = 1, n_slaves
         node = pass%slave_nodes(i)
         expected = 0
         best = huge(1.0_dp)
         do f = 1, n*n
            x_face = coords(:, pass%faces(:, f))
            if (any(coords(:, node) < minval(x_face, dim=2) - band) .or. &
                any(coords(:, node) > maxval(x_face, dim=2) + band)) cycle
            call closest_point_in_face(x_face, coords(:, node), 0.0_dp, xi, fixed)
            closest = face_position(x_face, xi)
            if (dot_product(coords(:, node) - closest, face_normal(x_face, xi)) > band) cycle
            distance = norm2(coords(:, node) - closest)
            if (distance < best) then
               best = distance
               expected = f
            end if
         end do
         call check(error, pass%face(i) == expected, 'slave '//to_string(i)//': face '//to_string(pass%face(i))// &
                    ', brute force '//to_string(expected))
         if (allocated(error)) return
      end do
      call check(error, count(pass%face > 0) > n_slaves/2 .and. count(pass%face == 0) > 0, &
                 'both nodes with and without a face: '//to_string(count(pass%face > 0)))
   contains
      pure real(dp) function frac(x)
         real(dp), intent(in) :: x
         frac = x - aint(x)
      end function frac
   end subroutine test_brute_force

   subroutine test_anchors(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: coords(:, :)
      type(contact_pass_t) :: pass
      call grid_pass(3, reshape([1.25_dp, 1.75_dp, 0.1_dp, 1.25_dp, 1.75_dp, 5.0_dp], [3, 2]), coords, pass, .false.)
      call initial_anchors(coords, edge_tolerance, pass)
      ! face 5 spans [1, 2]^2: xi = 2 (x - 1.5, y - 1.5)
      call check(error, pass%has_anchor(1) .and. pass%anchor_face(1) == 5 .and. &
                 maxval(abs(pass%anchor_xi(:, 1) - [-0.5_dp, 0.5_dp])) <= 1.0e-14_dp, 'anchor of slave 1')
      if (allocated(error)) return
      call check(error, .not. pass%has_anchor(2) .and. pass%anchor_face(2) == 0, 'slave 2 above the band: no anchor')
   end subroutine test_anchors

   subroutine test_smoothed(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: coords(:, :), zero(:)
      type(contact_pass_t) :: pass
      real(dp), parameter :: xi(2) = [0.9_dp, -0.2_dp], depth = 0.05_dp
      call grid_pass(3, reshape([0.0_dp, 0.0_dp, 0.0_dp], [3, 1]), coords, pass, .true.)
      call surface_patches(coords, pass%faces, all_faces_angle, pass%patches)
      pass%smooth = .true.
      allocate (zero(size(coords)), source=0.0_dp)
      ! below the point xi of the centre face 5, along the smoothed normal there
      coords(:, pass%slave_nodes(1)) = face_position(coords(:, pass%faces(:, 5)), xi) - &
                                       depth*smooth_normal_at(face_nodal_normals(coords, zero, pass, 5), xi)
      call initial_anchors(coords, edge_tolerance, pass)
      call check(error, pass%face(1) == 5 .and. pass%anchor_face(1) == 5, 'face 5, got '//to_string(pass%face(1)))
      if (allocated(error)) return
      call check_close(error, pass%anchor_xi(1, 1), xi(1), 0.0_dp, 1.0e-10_dp, 'anchor xi1')
      if (allocated(error)) return
      call check_close(error, pass%anchor_xi(2, 1), xi(2), 0.0_dp, 1.0e-10_dp, 'anchor xi2')
   end subroutine test_smoothed

   !> fold_surface (top z = 0 for x <= 0, side x = 0 below) with feature angle 30: the nodal
   !> normals are facet-like at the fold, so a node above the top next to the fold gets the
   !> top face 2, one beside the side gets face 3, one above the convex edge (no normal
   !> projection inside a face, the facet rule decides) one of the two, and each initial anchor
   !> is the normal projection along the smoothed normals (the facet closest point on face 2,
   !> whose kept neighbours are coplanar).
   subroutine test_fold(error)
      type(error_t), allocatable, intent(out) :: error
      type(contact_pass_t) :: pass
      real(dp) :: coords(3, 24), offset(3), normal(3)
      real(dp), allocatable :: zero(:)
      integer :: faces(4, 12)
      real(dp), parameter :: slaves(3, 3) = reshape([-0.1_dp, 0.5_dp, 0.05_dp, 0.05_dp, 0.5_dp, -0.1_dp, &
                                                     0.03_dp, 0.5_dp, 0.04_dp], [3, 3])
      call fold_surface(coords(:, :21), faces)
      coords(:, 22:) = slaves
      pass%faces = faces
      pass%free_edge = free_edges(size(coords, 2), pass%faces)
      pass%slave_nodes = [22, 23, 24]
      pass%band = band
      call start_pass_state(pass)
      call surface_patches(coords, pass%faces, 30.0_dp, pass%patches)
      pass%smooth = .true.
      call initial_anchors(coords, edge_tolerance, pass)
      call check(error, pass%face(1) == 2 .and. pass%face(2) == 3 .and. any(pass%face(3) == [2, 3]), &
                 'faces '//faces_text(pass%face))
      if (allocated(error)) return
      ! face 2 spans x in [-1, 0] (xi1 = 2 x + 1), y in [0, 1] (xi2 = 2 y - 1), flat with flat
      ! neighbours kept: the facet closest point
      call check(error, maxval(abs(pass%anchor_xi(:, 1) - [0.8_dp, 0.0_dp])) <= 1.0e-12_dp, &
                 'anchor of slave 1: '//to_string(pass%anchor_xi(1, 1))//' '//to_string(pass%anchor_xi(2, 1)))
      if (allocated(error)) return
      ! face 3 meets the curve (nodal normals +x at the fold, 5 degrees down at its other end):
      ! the offset of slave 2 from its anchor is along the smoothed normal there
      allocate (zero(size(coords)), source=0.0_dp)
      offset = slaves(:, 2) - face_position(coords(:, faces(:, 3)), pass%anchor_xi(:, 2))
      normal = smooth_normal_at(face_nodal_normals(coords, zero, pass, 3), pass%anchor_xi(:, 2))
      call check(error, norm2(offset - dot_product(offset, normal)*normal) <= 1.0e-12_dp .and. &
                 abs(pass%anchor_xi(1, 2) + 0.8_dp) < 0.01_dp, 'anchor of slave 2: '// &
                 to_string(pass%anchor_xi(1, 2))//' '//to_string(pass%anchor_xi(2, 2)))
   end subroutine test_fold

   subroutine test_plane(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: coords(:, :)
      type(contact_pass_t) :: pass
      real(dp), parameter :: point(3) = [0.0_dp, 0.0_dp, 1.0_dp], normal(3) = [0.0_dp, 0.6_dp, 0.8_dp]
      real(dp) :: offset(3)
      integer :: i
      call grid_pass(1, reshape([0.3_dp, -0.4_dp, 2.0_dp, 1.0_dp, 2.0_dp, -0.5_dp], [3, 2]), coords, pass, .false.)
      call plane_anchors(coords, point, normal, pass)
      do i = 1, 2
         ! on the plane, and the slave minus its foot along the normal
         offset = coords(:, pass%slave_nodes(i)) - pass%anchor_point(:, i)
         call check(error, pass%has_anchor(i) .and. abs(dot_product(pass%anchor_point(:, i) - point, normal)) <= 1.0e-15_dp &
                    .and. norm2(offset - dot_product(offset, normal)*normal) <= 1.0e-15_dp, 'foot point of slave '//to_string(i))
         if (allocated(error)) return
      end do
   end subroutine test_plane

   pure function faces_text(faces) result(text)
      integer, intent(in) :: faces(:)
      character(len=:), allocatable :: text
      integer :: i
      text = ''
      do i = 1, size(faces)
         text = text//' '//to_string(faces(i))
      end do
   end function faces_text
end module test_contact_search
