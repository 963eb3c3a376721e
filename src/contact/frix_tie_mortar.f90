!> Dual mortar weights of a tie (docs/contact.md, "Tied contact"): the constraint of slave
!> node s is
!>
!>     u_s = sum_a w_sa u_a,   w_sa = M_sa / sum_b M_sb,   M_sa = int_{Gamma_s} phi_s N_a dA,
!>
!> with N_a the master surface's bilinear shape functions and phi_s the dual (biorthogonal)
!> basis of the slave surface, int phi_j N_k dA = delta_jk int N_k dA on each slave face
!> (Wohlmuth, SIAM J. Numer. Anal. 38 (2000) 989-1012; for tying, Puso, IJNME 59 (2004)
!> 315-336). Where the master covers the slave node's faces, sum_b M_sb = int N_s dA, the
!> slave node's tributary area. Then the elimination transmits a constant stress exactly
!> (the slave force p A_s spreads over the master nodes as p int N_a dA) and a linear
!> displacement field satisfies the constraint: the tie passes the patch test on
!> non-matching meshes, which a constraint to the closest point does not.
!>
!> Integration: segment-wise (Puso & Laursen, CMAME 193 (2004) 601-629). For each slave face
!> and each master face near it, both are projected onto the slave face's plane (at its
!> centre), the two quadrilaterals are clipped (Sutherland-Hodgman), the overlap polygon is
!> cut into triangles from its first vertex and integrated with a 7-point degree-5 rule; each
!> point is projected back onto the slave face and onto the master face for xi_s, xi_m. On
!> flat interfaces of parallelogram faces the integrand is a polynomial of degree 4 on each
!> triangle and the weights are exact; on curved ones the projection is the approximation.
!> Reference configuration; computed once.
module frix_tie_mortar
   use frix_kinds, only: dp
   use frix_vector_algebra, only: cross_product
   use frix_face_projection, only: face_position, face_normal, face_shape_functions, project_onto_face
   use frix_dense_algebra, only: solve_in_place
   use frix_surface_load, only: face_area_weights
   implicit none
   private

   public :: tie_coupling_t, mortar_coupling

   !> The weights of every slave node as compressed rows: node i's master nodes
   !> nodes(start(i) + 1 : start(i + 1)) with weights weight(same); covered(i) is the
   !> fraction of node i's slave area the master covers (1 where it covers it all).
   type :: tie_coupling_t
      integer, allocatable :: start(:), nodes(:)
      real(dp), allocatable :: weight(:), covered(:)
   end type tie_coupling_t

   !> Contributions M(row, node) += value, in the order computed (repeats summed by compress).
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

   !> The dual mortar weights of `slave_nodes` (mesh numbers) over the slave faces
   !> slave_faces(4, :) against master_faces(4, :), in the reference coordinates `coords`.
   !> A master face is paired with a slave face when their bounding boxes, widened by
   !> `distance`, meet, its centre lies within `distance` of the slave face's plane and it
   !> faces the other way. Cost: every slave face is tested against every master face's box.
   subroutine mortar_coupling(coords, slave_nodes, slave_faces, master_faces, distance, coupling)
      real(dp), intent(in) :: coords(:, :)
      integer, intent(in) :: slave_nodes(:), slave_faces(:, :), master_faces(:, :)
      real(dp), intent(in) :: distance
      type(tie_coupling_t), intent(out) :: coupling
      type(triplets_t) :: m
      real(dp), allocatable :: area(:), lower(:, :), upper(:, :)
      integer, allocatable :: position_of(:)
      real(dp) :: slave_lower(3), slave_upper(3), face_weights(4)
      integer :: f, g, j
      allocate (position_of(size(coords, 2)), source=0)
      do j = 1, size(slave_nodes)
         position_of(slave_nodes(j)) = j
      end do
      allocate (area(size(slave_nodes)), source=0.0_dp)
      allocate (lower(3, size(master_faces, 2)), upper(3, size(master_faces, 2)))
      do g = 1, size(master_faces, 2)
         lower(:, g) = minval(coords(:, master_faces(:, g)), dim=2) - distance
         upper(:, g) = maxval(coords(:, master_faces(:, g)), dim=2) + distance
      end do
      allocate (m%row(256), m%node(256), m%value(256))
      do f = 1, size(slave_faces, 2)
         ! the slave nodes' tributary areas, as frix_contact_pass's set_slave_nodes takes them
         call face_area_weights(coords(:, slave_faces(:, f)), face_weights)
         area(position_of(slave_faces(:, f))) = area(position_of(slave_faces(:, f))) + face_weights
         slave_lower = minval(coords(:, slave_faces(:, f)), dim=2)
         slave_upper = maxval(coords(:, slave_faces(:, f)), dim=2)
         do g = 1, size(master_faces, 2)
            if (any(slave_upper < lower(:, g) .or. slave_lower > upper(:, g))) cycle
            call add_segment(coords(:, slave_faces(:, f)), coords(:, master_faces(:, g)), distance, &
                             position_of(slave_faces(:, f)), master_faces(:, g), m)
         end do
      end do
      call compress(m, area, coupling)
   end subroutine mortar_coupling

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

   !> M(j, a) += int over the overlap of slave face x_slave and master face x_master of
   !> phi_j N_a dA, rows(j) and columns(a) the rows and columns of the face nodes.
   subroutine add_segment(x_slave, x_master, distance, rows, masters, m)
      real(dp), intent(in) :: x_slave(3, 4), x_master(3, 4), distance
      integer, intent(in) :: rows(4), masters(4)
      type(triplets_t), intent(inout) :: m
      real(dp) :: centre(3), normal(3), e1(3), e2(3), slave_2d(2, max_vertices), master_2d(2, 4)
      real(dp) :: polygon(2, max_vertices), c(4, 4), local(4, 4)
      integer :: n_vertices, a, t, j
      centre = 0.25_dp*sum(x_slave, dim=2)
      normal = face_normal(x_slave, [0.0_dp, 0.0_dp])
      if (dot_product(face_normal(x_master, [0.0_dp, 0.0_dp]), normal) >= 0.0_dp) return
      if (abs(dot_product(0.25_dp*sum(x_master, dim=2) - centre, normal)) > distance) return
      e1 = x_slave(:, 2) - x_slave(:, 1)
      e1 = e1 - dot_product(e1, normal)*normal
      e1 = e1/norm2(e1)
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
      c = dual_coefficients(x_slave)
      local = 0.0_dp
      do t = 2, n_vertices - 1
         call add_triangle(polygon(:, [1, t, t + 1]), centre, e1, e2, x_slave, x_master, c, local)
      end do
      do j = 1, 4
         do a = 1, 4
            call append_triplet(m, rows(j), masters(a), local(j, a))
         end do
      end do
   end subroutine add_segment

   subroutine append_triplet(m, row, node, value)
      type(triplets_t), intent(inout) :: m
      integer, intent(in) :: row, node
      real(dp), intent(in) :: value
      integer, allocatable :: grown_row(:), grown_node(:)
      real(dp), allocatable :: grown_value(:)
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

   !> The 7 points of one triangle of the overlap (plane coordinates): local(j, a) +=
   !> int phi_j N_a dA.
   subroutine add_triangle(corners, centre, e1, e2, x_slave, x_master, c, local)
      real(dp), intent(in) :: corners(2, 3), centre(3), e1(3), e2(3), x_slave(3, 4), x_master(3, 4), c(4, 4)
      real(dp), intent(inout) :: local(4, 4)
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
            local(j, :) = local(j, :) + rule_w(q)*area*dual(j)*shape_m
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

   !> Rows of M as weights w_sa = M_sa / sum_b M_sb, repeats summed, entries below 1e-12 of
   !> the row's largest dropped; covered = sum_b M_sb / area.
   subroutine compress(m, area, coupling)
      type(triplets_t), intent(in) :: m
      real(dp), intent(in) :: area(:)
      type(tie_coupling_t), intent(out) :: coupling
      integer, allocatable :: row_start(:), order(:), fill(:), nodes(:)
      real(dp), allocatable :: values(:)
      integer :: k, j, n_rows, n
      n_rows = size(area)
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
      allocate (coupling%start(n_rows + 1), coupling%covered(n_rows), coupling%nodes(m%n), coupling%weight(m%n))
      coupling%start(1) = 0
      do j = 1, n_rows
         call merge_row(m%node(order(row_start(j) + 1:row_start(j + 1))), &
                        m%value(order(row_start(j) + 1:row_start(j + 1))), nodes, values)
         coupling%covered(j) = sum(values)/area(j)
         if (size(values) > 0) then
            if (sum(values) /= 0.0_dp) values = values/sum(values)
         end if
         n = coupling%start(j)
         coupling%nodes(n + 1:n + size(nodes)) = nodes
         coupling%weight(n + 1:n + size(nodes)) = values
         coupling%start(j + 1) = n + size(nodes)
      end do
      coupling%nodes = coupling%nodes(:coupling%start(n_rows + 1))
      coupling%weight = coupling%weight(:coupling%start(n_rows + 1))
   end subroutine compress

   !> One row's (node, value) contributions with repeated nodes summed and values below 1e-12
   !> of the largest dropped.
   pure subroutine merge_row(row_nodes, row_values, nodes, values)
      integer, intent(in) :: row_nodes(:)
      real(dp), intent(in) :: row_values(:)
      integer, allocatable, intent(out) :: nodes(:)
      real(dp), allocatable, intent(out) :: values(:)
      integer :: k, position
      real(dp) :: largest
      allocate (nodes(0), values(0))
      do k = 1, size(row_nodes)
         position = findloc(nodes, row_nodes(k), dim=1)
         if (position == 0) then
            nodes = [nodes, row_nodes(k)]
            values = [values, row_values(k)]
         else
            values(position) = values(position) + row_values(k)
         end if
      end do
      if (size(values) == 0) return
      largest = maxval(abs(values))
      nodes = pack(nodes, abs(values) > 1.0e-12_dp*largest)
      values = pack(values, abs(values) > 1.0e-12_dp*largest)
   end subroutine merge_row
end module frix_tie_mortar
