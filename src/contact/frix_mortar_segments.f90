!> Segment-wise mortar integrals of a slave surface against a master surface, shared by the
!> ties' dual mortar weights (frix_tie_mortar) and mortar contact (frix_mortar_contact);
!> docs/contact.md, "Tied contact" and "Mortar contact".
!>
!> For slave node j and a node k of either surface:
!>
!>     M_jk = int_{Gamma_s} phi_j N_k^m dA   (k a master node),
!>     D_jk = int_{Gamma_s} phi_j N_k^s dA   (k a slave node),
!>
!> over the part of the slave surface the master covers, with N^s, N^m the bilinear shape
!> functions of the two surfaces and phi_j the dual (biorthogonal) basis of the slave surface,
!> int phi_j N_k^s dA = delta_jk int N_k^s dA on each whole slave face (Wohlmuth, SIAM J.
!> Numer. Anal. 38 (2000) 989-1012). Where the master covers a slave face, D is diagonal on it.
!>
!> Integration (Puso & Laursen, CMAME 193 (2004) 601-629): for each slave face and each master
!> face near it, both are projected onto the slave face's plane (at its centre), the two
!> quadrilaterals are clipped (Sutherland-Hodgman), the overlap polygon is cut into triangles
!> from its first vertex and integrated with a 7-point degree-5 rule; each point is projected
!> back onto the slave face and onto the master face for xi_s, xi_m. On flat interfaces of
!> parallelogram faces the integrands are polynomials of degree 4 on each triangle and the
!> integrals are exact; on curved ones the projection onto the plane is the approximation.
!> Whatever the coordinates passed in (reference for ties, current for contact).
module frix_mortar_segments
   use frix_kinds, only: dp
   use frix_vector_algebra, only: cross_product
   use frix_face_projection, only: face_position, face_normal, face_shape_functions, project_onto_face
   use frix_dense_algebra, only: solve_in_place
   use frix_face_grid, only: face_grid_t, build_face_grid, faces_meeting_box
   implicit none
   private

   public :: triplets_t, append_triplet, mortar_triplets, segment_integrals, compress_rows

   !> Contributions M(row, node) += value, in the order computed (repeats summed by merge_row).
   type :: triplets_t
      integer :: n = 0
      integer, allocatable :: row(:), node(:)
      real(dp), allocatable :: value(:)
   end type triplets_t

   !> Most vertices of the overlap of two quadrilaterals (each clip adds at most one).
   integer, parameter :: max_vertices = 8
   !> 7-point, degree-5 rule on the triangle (Dunavant, IJNME 21 (1985) 1129-1148):
   !> area coordinates (a, b, 1 - a - b) and weights summing to 1.
   real(dp), parameter :: rule_a(7) = [1.0_dp/3.0_dp, 0.059715871789770_dp, 0.470142064105115_dp, &
                                      0.470142064105115_dp, 0.797426985353087_dp, 0.101286507323456_dp, &
                                      0.101286507323456_dp]
   real(dp), parameter :: rule_b(7) = [1.0_dp/3.0_dp, 0.470142064105115_dp, 0.059715871789770_dp, &
                                      0.470142064105115_dp, 0.101286507323456_dp, 0.797426985353087_dp, &
                                      0.101286507323456_dp]
   real(dp), parameter :: rule_w(7) = [0.225_dp, 0.132394152788506_dp, 0.132394152788506_dp, &
                                      0.132394152788506_dp, 0.125939180544827_dp, 0.125939180544827_dp, &
                                      0.125939180544827_dp]
   !> 3 x 3 Gauss-Legendre rule on [-1, 1] for the slave faces' mass matrices.
   real(dp), parameter :: gauss_x(3) = [-0.774596669241483377_dp, 0.0_dp, 0.774596669241483377_dp]
   real(dp), parameter :: gauss_w(3) = [5.0_dp/9.0_dp, 8.0_dp/9.0_dp, 5.0_dp/9.0_dp]

contains

   !> M (and, if present, D) of `slave_nodes` (mesh numbers; the triplets' rows are positions
   !> in this list, their nodes mesh numbers) over the slave faces slave_faces(4, :) against
   !> master_faces(4, :), coordinates `coords` (3, n_nodes). A master face is paired with a
   !> slave face when their bounding boxes, widened by `distance`, meet, its centre lies
   !> within `distance` of the slave face's plane and it faces the other way (segment_integrals).
   !> master_face(j), if present: a master face (column of master_faces) overlapping a slave
   !> face of node j, 0 where none does. The master faces whose box meets a slave face's come
   !> from a bucket grid of the boxes (frix_face_grid), in increasing order as a loop over all
   !> of them would visit them: cost linear in the faces for surfaces of similar face sizes.
   subroutine mortar_triplets(coords, slave_nodes, slave_faces, master_faces, distance, m, d, master_face)
      real(dp), intent(in) :: coords(:, :)
      integer, intent(in) :: slave_nodes(:), slave_faces(:, :), master_faces(:, :)
      real(dp), intent(in) :: distance   !! length
      type(triplets_t), intent(out) :: m
      type(triplets_t), intent(out), optional :: d
      integer, intent(out), optional :: master_face(:)
      type(face_grid_t) :: grid
      integer, allocatable :: position_of(:), visited(:), near(:)
      real(dp) :: master_part(4, 4), slave_part(4, 4)
      integer :: f, g, i, j, a, rows(4), n_near
      logical :: overlap
      allocate (position_of(size(coords, 2)), source=0)
      do j = 1, size(slave_nodes)
         position_of(slave_nodes(j)) = j
      end do
      allocate (m%row(256), m%node(256), m%value(256))
      if (present(d)) allocate (d%row(256), d%node(256), d%value(256))
      if (present(master_face)) master_face = 0
      if (size(master_faces, 2) == 0) return
      call build_face_grid(reshape(coords(:, reshape(master_faces, [size(master_faces)])), &
                                   [3, 4, size(master_faces, 2)]), distance, grid)
      allocate (visited(size(master_faces, 2)), source=0)
      do f = 1, size(slave_faces, 2)
         rows = position_of(slave_faces(:, f))
         call faces_meeting_box(grid, minval(coords(:, slave_faces(:, f)), dim=2), &
                                maxval(coords(:, slave_faces(:, f)), dim=2), f, visited, near, n_near)
         do i = 1, n_near
            g = near(i)
            call segment_integrals(coords(:, slave_faces(:, f)), coords(:, master_faces(:, g)), distance, &
                                   master_part, slave_part, overlap)
            if (.not. overlap) cycle
            if (present(master_face)) master_face(rows) = g
            do j = 1, 4
               do a = 1, 4
                  call append_triplet(m, rows(j), master_faces(a, g), master_part(j, a))
                  if (present(d)) call append_triplet(d, rows(j), slave_faces(a, f), slave_part(j, a))
               end do
            end do
         end do
      end do
   end subroutine mortar_triplets

   !> The integrals over the overlap of slave face x_slave and master face x_master:
   !> master_part(j, a) = int phi_j N_a^m dA, slave_part(j, k) = int phi_j N_k^s dA (area).
   !> overlap = .false. (both zero) when either face has zero area (no normal: face_normal),
   !> the master face faces the same way as the slave face,
   !> its centre lies farther than `distance` from the slave face's plane, or the projections
   !> do not overlap.
   subroutine segment_integrals(x_slave, x_master, distance, master_part, slave_part, overlap)
      real(dp), intent(in) :: x_slave(3, 4), x_master(3, 4), distance
      real(dp), intent(out) :: master_part(4, 4), slave_part(4, 4)
      logical, intent(out) :: overlap
      real(dp) :: centre(3), normal(3), e1(3), e2(3), slave_2d(2, max_vertices), master_2d(2, 4)
      real(dp) :: polygon(2, max_vertices), c(4, 4), heights(4)
      integer :: n_vertices, a, t
      master_part = 0.0_dp
      slave_part = 0.0_dp
      overlap = .false.
      centre = 0.25_dp*sum(x_slave, dim=2)
      normal = face_normal(x_slave, [0.0_dp, 0.0_dp])
      if (dot_product(face_normal(x_master, [0.0_dp, 0.0_dp]), normal) >= 0.0_dp) return
      do a = 1, 4
         heights(a) = dot_product(x_master(:, a) - centre, normal)
      end do
      if (minval(heights) > distance .or. maxval(heights) < -distance) return
      ! a zero-area slave face has a zero normal and was left above (the dot product is 0)
      if (.not. in_plane_axis(x_slave, normal, e1)) return
      e2 = cross_product(normal, e1)
      do a = 1, 4
         slave_2d(:, a) = [dot_product(x_slave(:, a) - centre, e1), dot_product(x_slave(:, a) - centre, e2)]
         ! the master face runs the other way round: reversed, it is counter-clockwise too
         master_2d(:, 5 - a) = [dot_product(x_master(:, a) - centre, e1), dot_product(x_master(:, a) - centre, e2)]
      end do
      polygon(:, :4) = slave_2d(:, :4)
      n_vertices = 4
      call clip(polygon, n_vertices, master_2d)
      if (n_vertices < 3) return
      overlap = .true.
      c = dual_coefficients(x_slave)
      do t = 2, n_vertices - 1
         call add_triangle(polygon(:, [1, t, t + 1]), centre, e1, e2, x_slave, x_master, c, master_part, slave_part)
      end do
   end subroutine segment_integrals

   !> e1: the unit in-plane direction (normal `normal`) of the first edge of x_face whose
   !> projection onto the plane is not zero (edge 1-2 unless nodes 1 and 2 coincide); .false.
   !> when every edge projects to zero (a collapsed face).
   logical function in_plane_axis(x_face, normal, e1) result(found)
      real(dp), intent(in) :: x_face(3, 4), normal(3)
      real(dp), intent(out) :: e1(3)
      real(dp) :: length
      integer :: a
      found = .false.
      do a = 1, 4
         e1 = x_face(:, mod(a, 4) + 1) - x_face(:, a)
         e1 = e1 - dot_product(e1, normal)*normal
         length = norm2(e1)
         if (length > 0.0_dp) then
            e1 = e1/length
            found = .true.
            return
         end if
      end do
   end function in_plane_axis

   !> The dual basis coefficients of a slave face: phi_j = sum_k c(j, k) N_k with
   !> c = D M^-1, M_jk = int N_j N_k dA, D = diag(int N_j dA) (3 x 3 Gauss: exact on a
   !> parallelogram).
   function dual_coefficients(x_face) result(c)
      real(dp), intent(in) :: x_face(3, 4)
      real(dp) :: c(4, 4)
      real(dp) :: mass(4, 4), shape(4), d_xi(4), d_eta(4), jacobian, lumped(4)
      logical :: singular
      integer :: p, q, k
      mass = 0.0_dp
      do q = 1, 3
         do p = 1, 3
            call face_shape_functions([gauss_x(p), gauss_x(q)], shape, d_xi, d_eta)
            jacobian = norm2(cross_product(matmul(x_face, d_xi), matmul(x_face, d_eta)))
            do k = 1, 4
               mass(:, k) = mass(:, k) + gauss_w(p)*gauss_w(q)*jacobian*shape*shape(k)
            end do
         end do
      end do
      lumped = sum(mass, dim=2)
      ! c^T = M^-1 D (M symmetric): solve M c^T = D column by column
      c = 0.0_dp
      do k = 1, 4
         c(k, k) = lumped(k)
      end do
      call solve_in_place(mass, c, singular)
      c = transpose(c)
      if (singular) c = 0.0_dp   ! a degenerate face: no contribution
   end function dual_coefficients

   subroutine append_triplet(m, row, node, value)
      type(triplets_t), intent(inout) :: m
      integer, intent(in) :: row, node
      real(dp), intent(in) :: value
      integer, allocatable :: grown_row(:), grown_node(:)
      real(dp), allocatable :: grown_value(:)
      if (.not. allocated(m%row)) allocate (m%row(256), m%node(256), m%value(256))
      if (m%n == size(m%row)) then
         allocate (grown_row(2*m%n), grown_node(2*m%n), grown_value(2*m%n))
         grown_row(:m%n) = m%row
         grown_node(:m%n) = m%node
         grown_value(:m%n) = m%value
         call move_alloc(grown_row, m%row)
         call move_alloc(grown_node, m%node)
         call move_alloc(grown_value, m%value)
      end if
      m%n = m%n + 1
      m%row(m%n) = row
      m%node(m%n) = node
      m%value(m%n) = value
   end subroutine append_triplet

   !> The 7 points of one triangle of the overlap (plane coordinates): master_part(j, a) +=
   !> int phi_j N_a^m dA, slave_part(j, k) += int phi_j N_k^s dA.
   subroutine add_triangle(corners, centre, e1, e2, x_slave, x_master, c, master_part, slave_part)
      real(dp), intent(in) :: corners(2, 3), centre(3), e1(3), e2(3), x_slave(3, 4), x_master(3, 4), c(4, 4)
      real(dp), intent(inout) :: master_part(4, 4), slave_part(4, 4)
      real(dp) :: area, point_2d(2), point(3), xi_s(2), xi_m(2), shape_s(4), shape_m(4), d_xi(4), d_eta(4)
      real(dp) :: dual(4)
      logical :: converged_s, converged_m
      integer :: q, j
      area = 0.5_dp*abs((corners(1, 2) - corners(1, 1))*(corners(2, 3) - corners(2, 1)) - &
                        (corners(2, 2) - corners(2, 1))*(corners(1, 3) - corners(1, 1)))
      if (.not. area > 0.0_dp) return
      do q = 1, 7
         point_2d = rule_a(q)*corners(:, 1) + rule_b(q)*corners(:, 2) + (1.0_dp - rule_a(q) - rule_b(q))*corners(:, 3)
         point = centre + point_2d(1)*e1 + point_2d(2)*e2
         call project_onto_face(x_slave, point, xi_s, converged_s)
         call project_onto_face(x_master, face_position(x_slave, xi_s), xi_m, converged_m)
         if (.not. (converged_s .and. converged_m)) cycle
         call face_shape_functions(xi_s, shape_s, d_xi, d_eta)
         call face_shape_functions(xi_m, shape_m, d_xi, d_eta)
         dual = matmul(c, shape_s)
         do j = 1, 4
            master_part(j, :) = master_part(j, :) + rule_w(q)*area*dual(j)*shape_m
            slave_part(j, :) = slave_part(j, :) + rule_w(q)*area*dual(j)*shape_s
         end do
      end do
   end subroutine add_triangle

   !> Sutherland-Hodgman: `polygon` (counter-clockwise) clipped by the convex
   !> counter-clockwise quadrilateral `window`.
   subroutine clip(polygon, n_vertices, window)
      real(dp), intent(inout) :: polygon(2, max_vertices)
      integer, intent(inout) :: n_vertices
      real(dp), intent(in) :: window(2, 4)
      real(dp) :: input(2, max_vertices), edge(2), start(2), previous(2), current(2)
      real(dp) :: side_previous, side_current
      integer :: e, k, n_input
      do e = 1, 4
         if (n_vertices == 0) return
         start = window(:, e)
         edge = window(:, mod(e, 4) + 1) - start
         input(:, :n_vertices) = polygon(:, :n_vertices)
         n_input = n_vertices
         n_vertices = 0
         previous = input(:, n_input)
         side_previous = edge(1)*(previous(2) - start(2)) - edge(2)*(previous(1) - start(1))
         do k = 1, n_input
            current = input(:, k)
            side_current = edge(1)*(current(2) - start(2)) - edge(2)*(current(1) - start(1))
            if ((side_current >= 0.0_dp) .neqv. (side_previous >= 0.0_dp)) &
               call append(previous + side_previous/(side_previous - side_current)*(current - previous))
            if (side_current >= 0.0_dp) call append(current)
            previous = current
            side_previous = side_current
         end do
      end do
   contains
      subroutine append(vertex)
         real(dp), intent(in) :: vertex(2)
         if (n_vertices == max_vertices) return
         n_vertices = n_vertices + 1
         polygon(:, n_vertices) = vertex
      end subroutine append
   end subroutine clip

   !> The triplets of n_rows rows as compressed rows: row j's nodes
   !> nodes(start(j) + 1 : start(j + 1)) and values(same), repeated nodes summed; values whose
   !> magnitude is below `drop` (default 1e-12) times the row's largest are dropped (merge_row;
   !> drop = 0: only zeros).
   subroutine compress_rows(m, n_rows, start, nodes, values, drop)
      type(triplets_t), intent(in) :: m
      integer, intent(in) :: n_rows
      integer, allocatable, intent(out) :: start(:), nodes(:)
      real(dp), allocatable, intent(out) :: values(:)
      real(dp), intent(in), optional :: drop
      integer, allocatable :: row_start(:), order(:), fill(:), row_nodes(:), slot(:)
      real(dp), allocatable :: row_values(:)
      integer :: k, j, n, n_merged
      real(dp) :: relative_drop
      relative_drop = 1.0e-12_dp
      if (present(drop)) relative_drop = drop
      allocate (row_start(n_rows + 1), source=0)
      do k = 1, m%n
         row_start(m%row(k) + 1) = row_start(m%row(k) + 1) + 1
      end do
      do j = 1, n_rows
         row_start(j + 1) = row_start(j + 1) + row_start(j)
      end do
      allocate (order(m%n))
      fill = row_start(:n_rows)
      do k = 1, m%n
         fill(m%row(k)) = fill(m%row(k)) + 1
         order(fill(m%row(k))) = k
      end do
      allocate (start(n_rows + 1), nodes(m%n), values(m%n), row_nodes(m%n), row_values(m%n))
      allocate (slot(max(1, maxval(m%node(:m%n)))), source=0)
      start(1) = 0
      do j = 1, n_rows
         call merge_row(m%node(order(row_start(j) + 1:row_start(j + 1))), &
                        m%value(order(row_start(j) + 1:row_start(j + 1))), relative_drop, slot, row_nodes, &
                        row_values, n_merged)
         n = start(j)
         nodes(n + 1:n + n_merged) = row_nodes(:n_merged)
         values(n + 1:n + n_merged) = row_values(:n_merged)
         start(j + 1) = n + n_merged
      end do
      nodes = nodes(:start(n_rows + 1))
      values = values(:start(n_rows + 1))
   end subroutine compress_rows

   !> One row's (node, value) contributions with repeated nodes summed (in the order of first
   !> appearance) and values not above `drop` times the largest dropped: nodes(:n), values(:n)
   !> (room for size(row_nodes)). slot(node): the node's place in this row, 0 for none (all 0 on
   !> entry and on return; size at least the largest node number).
   pure subroutine merge_row(row_nodes, row_values, drop, slot, nodes, values, n)
      integer, intent(in) :: row_nodes(:)
      real(dp), intent(in) :: row_values(:)
      real(dp), intent(in) :: drop
      integer, intent(inout) :: slot(:)
      integer, intent(inout) :: nodes(:)
      real(dp), intent(inout) :: values(:)
      integer, intent(out) :: n
      integer :: k, kept
      real(dp) :: largest
      n = 0
      do k = 1, size(row_nodes)
         if (slot(row_nodes(k)) == 0) then
            n = n + 1
            slot(row_nodes(k)) = n
            nodes(n) = row_nodes(k)
            values(n) = row_values(k)
         else
            values(slot(row_nodes(k))) = values(slot(row_nodes(k))) + row_values(k)
         end if
      end do
      slot(nodes(:n)) = 0
      if (n == 0) return
      largest = maxval(abs(values(:n)))
      kept = 0
      do k = 1, n
         if (.not. abs(values(k)) > drop*largest) cycle
         kept = kept + 1
         nodes(kept) = nodes(k)
         values(kept) = values(k)
      end do
      n = kept
   end subroutine merge_row
end module frix_mortar_segments
