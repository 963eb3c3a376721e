!> The contact search of a deformable pass: which master face each slave node touches, and the
!> initial anchors of the reference configuration. docs/contact.md, "In the global system".
!>
!> Each slave node is given the master face whose closest point (clamped to the face: an edge
!> or corner point when the node lies beyond it) is nearest; the node's current face is kept
!> on ties, so that a node on an edge shared by two faces does not chatter between them. With
!> smoothed normals the nearest face whose normal projection along the smoothed normals lies
!> inside it comes first (docs/contact.md, "Normals"); the candidates are projected along the
!> smoothed normals in the order of their facet distance (the distance to the bounded face's
!> closest point, a lower bound of the distance to any point of the face) until none left can
!> be nearer than the nearest found, and a face's nodal normals are computed when it is first
!> projected in a search. A face is a candidate when its
!> current bounding box inflated by the search band holds the node and the node is at most the
!> band above it (gap <= band). Candidates come from a uniform bucket grid of the boxes,
!> rebuilt at every search (linear cost). A node whose closest point on its face is clamped
!> onto a free edge of the master surface (its boundary, pass%free_edge) and lies beyond that
!> edge by more than the extension zone gets no face: it is open (beyond_free_edge).
!>
!> Positions are current: x = X + u, X the mesh's reference coordinates (3, n_nodes), u the
!> displacements node-major (3 n_nodes); a master face's corners are read through
!> frix_contact_pass's pass_positions (a plane pass's corners move with their nodes).
module frix_contact_search
   use frix_kinds, only: dp
   use frix_vector_algebra, only: cross_product
   use frix_face_projection, only: face_position, face_normal, closest_point_in_face, face_contains
   use frix_smoothed_normals, only: patch_normals, smooth_projection, smooth_normal_at
   use frix_contact_patches, only: ring_nodes_of, patch_faces_of
   use frix_contact_pass, only: contact_pass_t, pass_positions
   use frix_free_edge_zone, only: extension_zone, edge_nodes, clamped_on_edge
   use frix_face_grid, only: face_grid_t, build_face_grid, grid_cell
   implicit none
   private

   public :: assign_faces, initial_anchors, plane_anchors, face_nodal_normals

   real(dp), parameter :: tie_tolerance = 1.0e-10_dp  !! relative distance difference counted as a tie
   !> Facet search (nearest_face): the node's current face is kept against a nearer face whose
   !> normal at its closest point is within coplanar_angle of the current face's, unless that
   !> face is nearer by more than face_hysteresis of the current face's distance. Two such
   !> faces are one plane to within the angle, and either gives the node nearly the same force
   !> (they differ by p A x angle); where a load dishes the master under a slab, the faces on
   !> either side of an edge tilt towards each other by 1e-5 to 1e-4 rad, each face's push along
   !> its own normal left the node nearer the other, and a node over that edge changed face at
   !> every iteration: Newton froze at a relative residual of 1e-5 and no increment converged
   !> (tests/contact_robustness, edge_wide; a margin of 1e-5 of the distance was too small).
   !> Faces meeting at a real angle (a faceted pipe or cavity: 360 / n degrees) keep the strict
   !> nearest-face rule: there the choice decides the force's direction.
   real(dp), parameter :: face_hysteresis = 1.0e-3_dp
   real(dp), parameter :: coplanar_angle = 1.0e-2_dp   !! rad

   !> A candidate face of a slave node: its facet distance (to the bounded face's closest point)
   !> and, once projected along the smoothed normals, whether that projection qualifies
   !> (inside the face, gap within the band) and its distance.
   type :: candidate_t
      integer :: face = 0
      real(dp) :: distance = 0.0_dp
      integer :: position = 0            !! in the grid's order
      logical :: qualifies = .false.
      real(dp) :: smooth_distance = 0.0_dp
   end type candidate_t

   !> The master surface of a pass at the current displacements.
   type :: master_state_t
      real(dp), allocatable :: x_faces(:, :, :)     !! (3, 4, n_faces) current face nodes
      !> (3, 4, n_faces) smoothed nodal normals of each face's nodes: per face, since with a
      !> feature angle a node on a sharp edge has one normal on each side of it; those of face f
      !> are set once has_normals(f)
      real(dp), allocatable :: face_normals(:, :, :)
      logical, allocatable :: has_normals(:)
      !> (n_faces) with smoothed normals: 2 t (1 + t) D, t the edge tolerance, D the largest
      !> distance between the face's nodes (nearest_inside_face)
      real(dp), allocatable :: reach(:)
      type(face_grid_t) :: grid
      !> room for one slave node's candidates (the most faces a grid cell holds)
      type(candidate_t), allocatable :: candidates(:)
   end type master_state_t

   !> One slave node's search: its current position, its face so far (kept on ties) and the
   !> pair's edge tolerance (parent coordinates).
   type :: slave_query_t
      real(dp) :: x_slave(3) = 0.0_dp
      integer :: current = 0
      real(dp) :: edge_tolerance = 0.0_dp
   end type slave_query_t


contains

   !> The nearest master face of every slave node of a deformable pass at displacements u
   !> (pass%face; 0 for none). pass%face holds the current faces on entry (kept on ties).
   subroutine assign_faces(coords, u, edge_tolerance, pass)
      real(dp), intent(in) :: coords(:, :)       !! reference coordinates (3, n_nodes)
      real(dp), intent(in) :: u(:)               !! displacements (3 n_nodes)
      real(dp), intent(in) :: edge_tolerance     !! the pair's, parent coordinates
      type(contact_pass_t), intent(inout) :: pass
      type(master_state_t) :: master
      type(slave_query_t) :: query
      integer :: f, i
      if (size(pass%faces, 2) == 0) then
         pass%face = 0
         return
      end if
      allocate (master%x_faces(3, 4, size(pass%faces, 2)))
      do f = 1, size(pass%faces, 2)
         master%x_faces(:, :, f) = pass_positions(pass, coords, u, pass%faces(:, f))
      end do
      call build_face_grid(master%x_faces, pass%band, master%grid)
      associate (start => master%grid%cell_start)
         allocate (master%candidates(maxval(start(2:) - start(:size(start) - 1))))
      end associate
      if (pass%smooth) then
         allocate (master%face_normals(3, 4, size(pass%faces, 2)))
         allocate (master%has_normals(size(pass%faces, 2)), source=.false.)
         allocate (master%reach(size(pass%faces, 2)))
         do f = 1, size(pass%faces, 2)
            master%reach(f) = 2.0_dp*edge_tolerance*(1.0_dp + edge_tolerance)*node_spread(master%x_faces(:, :, f))
         end do
      else
         allocate (master%face_normals(3, 4, 0))   ! facet normals: none (allocated for a defined descriptor)
      end if
      query%edge_tolerance = edge_tolerance
      do i = 1, size(pass%slave_nodes)
         associate (s => pass%slave_nodes(i))
            query%x_slave = coords(:, s) + u(3*s - 2:3*s)
         end associate
         query%current = pass%face(i)
         pass%face(i) = nearest_face(coords, u, pass, master, query)
      end do
   end subroutine assign_faces

   !> The face given to a slave node (0: none). coords and u: as for assign_faces (the nodal
   !> normals of a face projected for the first time in this search).
   integer function nearest_face(coords, u, pass, master, query) result(face)
      real(dp), intent(in) :: coords(:, :), u(:)
      type(contact_pass_t), intent(in) :: pass
      type(master_state_t), intent(inout) :: master
      type(slave_query_t), intent(in) :: query
      real(dp) :: x_face(3, 4), xi(2), closest(3), normal(3), distance, gap, best
      real(dp) :: best_normal(3), current_normal(3), current_distance
      integer :: k, f, c, best_face, n_candidates
      logical :: fixed(2)
      best = 0.5_dp*huge(1.0_dp)   ! best*(1 + tie_tolerance) must not overflow
      best_face = 0
      best_normal = 0.0_dp
      current_normal = 0.0_dp
      current_distance = -1.0_dp   ! the current face is no candidate
      face = 0
      c = grid_cell(master%grid, query%x_slave)
      if (c == 0) return
      n_candidates = 0
      do k = master%grid%cell_start(c) + 1, master%grid%cell_start(c + 1)
         f = master%grid%cell_faces(k)
         if (any(query%x_slave < master%grid%lower(:, f)) .or. any(query%x_slave > master%grid%upper(:, f))) cycle
         x_face = master%x_faces(:, :, f)
         call closest_point_in_face(x_face, query%x_slave, 0.0_dp, xi, fixed)
         closest = face_position(x_face, xi)
         distance = norm2(query%x_slave - closest)
         n_candidates = n_candidates + 1
         master%candidates(n_candidates) = candidate_t(f, distance, n_candidates)
         normal = face_normal(x_face, xi)
         gap = dot_product(query%x_slave - closest, normal)
         if (gap > pass%band) cycle
         ! beyond the master surface's boundary by more than the extension zone: not this
         ! face's (another face may still hold the node; a tie decides at its boundary by its
         ! own coverage rule, frix_tie_pass)
         if (.not. pass%tied) then
            if (beyond_free_edge(x_face, pass%free_edge(:, f), query%x_slave, xi, fixed)) cycle
         end if
         if (f == query%current) then
            current_distance = distance
            current_normal = normal
         end if
         call keep_nearer(f, distance, query%current, best, best_face)
         if (best_face == f) best_normal = normal
      end do
      face = best_face
      if (current_distance >= 0.0_dp .and. best_face /= query%current) then
         if (current_distance*(1.0_dp - face_hysteresis) <= best .and. &
             dot_product(current_normal, best_normal) >= cos(coplanar_angle)) face = query%current
      end if
      ! smoothed normals: the nearest face whose normal projection lies inside it, else
      ! (beyond a free edge of the master surface, or no projection) the nearest face
      if (pass%smooth) then
         f = nearest_inside_face(coords, u, pass, master, query, n_candidates)
         if (f > 0) face = f
      end if
   end function nearest_face

   !> The nearest of the candidate faces (master%candidates(:n_candidates)) whose normal projection along the smoothed normals
   !> lies inside it with a gap within the band (0: none), chosen as keep_nearer chooses in the
   !> grid's order. Candidates are projected in the order of their facet distances d_f, and
   !> none is projected once d_f exceeds the nearest distance found by more than the tie
   !> tolerance and the edge tolerance's reach: a projection inside the face within
   !> edge_tolerance lies at least d_f - 2 t (1 + t) D from x_slave (t the edge tolerance, D
   !> the largest distance between the face's nodes, which bounds |x_,k| on the extrapolated
   !> face), so that face can neither be nearer nor tie.
   integer function nearest_inside_face(coords, u, pass, master, query, n_candidates) result(best_face)
      real(dp), intent(in) :: coords(:, :), u(:)
      type(contact_pass_t), intent(in) :: pass
      type(master_state_t), intent(inout) :: master
      type(slave_query_t), intent(in) :: query
      integer, intent(in) :: n_candidates
      type(candidate_t) :: by_distance(n_candidates)
      real(dp) :: best, distance, gap
      integer :: k, f
      logical :: inside
      by_distance = master%candidates(:n_candidates)
      call sort_by_distance(by_distance)
      best = 0.5_dp*huge(1.0_dp)
      do k = 1, n_candidates
         f = by_distance(k)%face
         if (by_distance(k)%distance - master%reach(f) > best*(1.0_dp + tie_tolerance)) exit
         if (.not. master%has_normals(f)) then
            master%face_normals(:, :, f) = face_nodal_normals(coords, u, pass, f)
            master%has_normals(f) = .true.
         end if
         call smooth_candidate(master%x_faces(:, :, f), master%face_normals(:, :, f), query%x_slave, &
                               query%edge_tolerance, distance, gap, inside)
         if (.not. (inside .and. gap <= pass%band)) cycle
         associate (candidate => master%candidates(by_distance(k)%position))
            candidate%qualifies = .true.
            candidate%smooth_distance = distance
         end associate
         best = min(best, distance)
      end do
      best = 0.5_dp*huge(1.0_dp)
      best_face = 0
      do k = 1, n_candidates
         associate (candidate => master%candidates(k))
            if (candidate%qualifies) &
               call keep_nearer(candidate%face, candidate%smooth_distance, query%current, best, best_face)
         end associate
      end do
   end function nearest_inside_face

   !> Sort candidates by increasing facet distance, the order of the grid kept among equal
   !> distances (insertion sort: a handful of candidates).
   pure subroutine sort_by_distance(candidates)
      type(candidate_t), intent(inout) :: candidates(:)
      type(candidate_t) :: moving
      integer :: k, j
      do k = 2, size(candidates)
         moving = candidates(k)
         j = k - 1
         do while (j >= 1)
            if (candidates(j)%distance <= moving%distance) exit
            candidates(j + 1) = candidates(j)
            j = j - 1
         end do
         candidates(j + 1) = moving
      end do
   end subroutine sort_by_distance

   !> The largest distance between two nodes of a face.
   pure real(dp) function node_spread(x_face)
      real(dp), intent(in) :: x_face(3, 4)
      integer :: a, b
      node_spread = 0.0_dp
      do a = 1, 3
         do b = a + 1, 4
            node_spread = max(node_spread, norm2(x_face(:, a) - x_face(:, b)))
         end do
      end do
   end function node_spread

   !> Whether the closest point of x_slave on the bounded face x_face (parent coordinates xi,
   !> `fixed` the clamped ones: closest_point_in_face's) is clamped onto one of the face's free
   !> edges (or a corner on one) with x_slave beyond that edge by more than the extension zone
   !> (frix_free_edge_zone). Beyond: d . m, d = x_slave - x_c (x_c the clamped point), m the unit
   !> outward normal of the edge in the face's tangent plane at x_c (e x n, e the edge's
   !> direction in face order, n the face normal); on an edge d . m is the whole tangential part
   !> of d, at a corner only the part across the free edge counts. The zone: extension_zone
   !> times the face's length across the edge.
   pure logical function beyond_free_edge(x_face, free, x_slave, xi, fixed) result(beyond)
      real(dp), intent(in) :: x_face(3, 4), x_slave(3), xi(2)
      logical, intent(in) :: free(4)          !! the face's free edges (pass%free_edge)
      logical, intent(in) :: fixed(2)
      real(dp) :: offset(3), outward(3), across
      integer :: k, first, second, after, before
      beyond = .false.
      if (.not. any(free)) return
      offset = x_slave - face_position(x_face, xi)
      do k = 1, 4
         if (.not. (free(k) .and. clamped_on_edge(k, xi, fixed))) cycle
         call edge_nodes(k, first, second, after, before)
         outward = cross_product(x_face(:, second) - x_face(:, first), face_normal(x_face, xi))
         across = 0.5_dp*(norm2(x_face(:, after) - x_face(:, second)) + norm2(x_face(:, first) - x_face(:, before)))
         if (dot_product(offset, outward) > extension_zone*across*norm2(outward)) beyond = .true.
      end do
   end function beyond_free_edge

   !> Make face f the best so far if it is nearer, or as near (within tie_tolerance) and the
   !> node's current face, so that a node on a shared edge does not chatter.
   pure subroutine keep_nearer(f, distance, current, best, best_face)
      integer, intent(in) :: f, current
      real(dp), intent(in) :: distance
      real(dp), intent(inout) :: best
      integer, intent(inout) :: best_face
      if (distance < best*(1.0_dp - tie_tolerance) .or. &
          (distance <= best*(1.0_dp + tie_tolerance) .and. f == current)) then
         best = distance
         best_face = f
      end if
   end subroutine keep_nearer

   !> A face's normal projection along the smoothed normals (nodal normals `nodal`): distance,
   !> gap (along the smoothed normal there) and whether it lies inside the face.
   subroutine smooth_candidate(x_face, nodal, x_slave, edge_tolerance, distance, gap, inside)
      real(dp), intent(in) :: x_face(3, 4), nodal(3, 4), x_slave(3), edge_tolerance
      real(dp), intent(out) :: distance, gap
      logical, intent(out) :: inside
      real(dp) :: xi(2), jacobian(2, 2), offset(3)
      logical :: converged
      call smooth_projection(x_face, nodal, x_slave, xi, converged, jacobian)
      inside = converged
      if (converged) inside = face_contains(xi, edge_tolerance)
      distance = huge(1.0_dp)
      gap = huge(1.0_dp)
      if (.not. inside) return
      offset = x_slave - face_position(x_face, xi)
      distance = norm2(offset)
      gap = dot_product(offset, smooth_normal_at(nodal, xi))
   end subroutine smooth_candidate


   !> Anchors of the reference configuration of a deformable pass: every slave node starts
   !> with the closest point of its reference position on the nearest master face within the
   !> search band (with smoothed normals the point along the smoothed normal where it lies on
   !> the face), so that friction acts from the first increment and a body held sideways only
   !> by friction is supported from the first iteration. Nodes with no face (above the band, or
   !> beyond a free edge of the master surface by more than the extension zone) get no anchor.
   subroutine initial_anchors(coords, edge_tolerance, pass)
      real(dp), intent(in) :: coords(:, :)       !! reference coordinates (3, n_nodes)
      real(dp), intent(in) :: edge_tolerance     !! the pair's, parent coordinates
      type(contact_pass_t), intent(inout) :: pass
      real(dp), allocatable :: zero(:)
      real(dp) :: x_slave(3), xi(2), jacobian(2, 2)
      logical :: fixed(2), converged
      integer :: i, f
      allocate (zero(size(coords)), source=0.0_dp)
      call assign_faces(coords, zero, edge_tolerance, pass)
      do i = 1, size(pass%slave_nodes)
         f = pass%face(i)
         if (f == 0) cycle
         x_slave = coords(:, pass%slave_nodes(i))
         call closest_point_in_face(pass_positions(pass, coords, zero, pass%faces(:, f)), x_slave, 0.0_dp, &
                                    pass%anchor_xi(:, i), fixed)
         if (pass%smooth) then
            call smooth_projection(pass_positions(pass, coords, zero, pass%faces(:, f)), &
                                   face_nodal_normals(coords, zero, pass, f), &
                                   x_slave, xi, converged, jacobian)
            if (converged) then
               if (face_contains(xi, edge_tolerance)) pass%anchor_xi(:, i) = xi
            end if
         end if
         pass%anchor_face(i) = f
         pass%has_anchor(i) = .true.
      end do
   end subroutine initial_anchors

   !> Anchors of the reference configuration against a rigid plane: every slave node's foot
   !> point on the plane (so that friction acts from the first increment).
   pure subroutine plane_anchors(coords, plane_point, plane_normal, pass)
      real(dp), intent(in) :: coords(:, :)                   !! reference coordinates (3, n_nodes)
      real(dp), intent(in) :: plane_point(3), plane_normal(3)  !! unit normal
      type(contact_pass_t), intent(inout) :: pass
      real(dp) :: x_slave(3)
      integer :: i
      do i = 1, size(pass%slave_nodes)
         x_slave = coords(:, pass%slave_nodes(i))
         pass%anchor_point(:, i) = x_slave - dot_product(x_slave - plane_point, plane_normal)*plane_normal
      end do
      pass%has_anchor = .true.
   end subroutine plane_anchors

   !> The averaged nodal normals of master face f's 4 nodes at displacements u (the kernel's
   !> patch_normals over the face's patch).
   pure function face_nodal_normals(coords, u, pass, f) result(nodal)
      real(dp), intent(in) :: coords(:, :), u(:)
      type(contact_pass_t), intent(in) :: pass
      integer, intent(in) :: f
      real(dp) :: nodal(3, 4)
      nodal = patch_normals(pass_positions(pass, coords, u, pass%faces(:, f)), &
                            pass_positions(pass, coords, u, ring_nodes_of(pass%patches, f)), &
                            patch_faces_of(pass%patches, f))
   end function face_nodal_normals
end module frix_contact_search
