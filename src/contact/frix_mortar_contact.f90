!> Mortar (segment-to-segment) frictionless contact with dual mortar weights (deck
!> `DISCRETIZATION Mortar`; docs/contact.md, "Mortar contact"). Per slave node j, in the
!> current configuration at every evaluation (integrals of frix_mortar_segments):
!>
!>     D_j  = int phi_j dA                                  (area; = int N_j dA where covered)
!>     g_j  = int phi_j (x_s - x_m) . n_j dA
!>          = n_j . (sum_k D_jk x_k - sum_l M_jl x_l)        (length x area)
!>     p_j  = p_N(g_j / D_j)                                 (force/area, the pair's normal law)
!>
!> (Puso & Laursen, CMAME 193 (2004) 601-629; Popp, Gee & Wall, IJNME 79 (2009) 1354-1391),
!> with n_j the slave node's averaged normal turned round: the unit normal out of the master
!> body towards the slave, as in node-to-segment contact, so that g_j / D_j < 0 is
!> penetration. Forces: p_j D_jk n_j on slave node k and -p_j M_jl n_j on master node l
!> (where the master covers the slave faces, p_j D_j n_j on node j itself). Row j's
!> coefficients c_jk (+D_jk on slave nodes, -M_jl on master nodes) give g_j = n_j . sum c_jk x_k.
!>
!> Tangent: d fint / d x with D, M and n_j held fixed (the derivatives of the mortar integrals
!> and of the nodal normal are left out), K = -(dp_N/dg) / D_j (c n_j)(c n_j)^T: symmetric.
module frix_mortar_contact
   use frix_kinds, only: dp
   use frix_face_projection, only: face_normal, face_node_xi, face_node_eta
   use frix_dual_number, only: dual_t, dual_variable
   use frix_normal_contact_law, only: normal_contact_law_t
   use frix_contact_kernel, only: contact_point_result_t, contact_slip
   use frix_mortar_segments, only: triplets_t, append_triplet, mortar_triplets, compress_rows
   implicit none
   private

   public :: mortar_rows_t, mortar_rows, mortar_node_contact, mortar_row_stiffness, least_mortar_coverage

   !> A slave node takes part in the contact when the master covers this fraction of its
   !> tributary area A_j (D_j >= least_mortar_coverage A_j), as a tied node (frix_tie_pass).
   real(dp), parameter :: least_mortar_coverage = 0.5_dp

   !> The mortar rows of a pass's slave nodes: row j's nodes nodes(start(j) + 1 : start(j + 1))
   !> (mesh numbers, slave and master) with coefficients c_jk (area), D_j (area), the normal
   !> n_j (unit, out of the master body) and a master face overlapping node j's faces (0: none).
   type :: mortar_rows_t
      integer, allocatable :: start(:), nodes(:)
      real(dp), allocatable :: weight(:)
      real(dp), allocatable :: dual_area(:)
      real(dp), allocatable :: normal(:, :)
      integer, allocatable :: master_face(:)
   end type mortar_rows_t

contains

   !> The mortar rows of `slave_nodes` over slave_faces(4, :) against master_faces(4, :) at the
   !> coordinates `coords` (3, n_nodes), a master face taking part within `distance` (length;
   !> frix_mortar_segments' pairing).
   subroutine mortar_rows(coords, slave_nodes, slave_faces, master_faces, distance, rows)
      real(dp), intent(in) :: coords(:, :)
      integer, intent(in) :: slave_nodes(:), slave_faces(:, :), master_faces(:, :)
      real(dp), intent(in) :: distance
      type(mortar_rows_t), intent(out) :: rows
      type(triplets_t) :: m, d
      integer :: k, n_slave
      n_slave = size(slave_nodes)
      allocate (rows%master_face(n_slave))
      call mortar_triplets(coords, slave_nodes, slave_faces, master_faces, distance, m, d, rows%master_face)
      allocate (rows%dual_area(n_slave), source=0.0_dp)
      do k = 1, d%n
         rows%dual_area(d%row(k)) = rows%dual_area(d%row(k)) + d%value(k)
         call append_triplet(m, d%row(k), d%node(k), -d%value(k))
      end do
      ! m now holds M_jl and -D_jk; c_jk = D_jk - M_jk
      call compress_rows(m, n_slave, rows%start, rows%nodes, rows%weight)
      rows%weight = -rows%weight
      rows%normal = slave_nodal_normals(coords, slave_nodes, slave_faces)
   end subroutine mortar_rows

   !> n_j: minus the normalised sum of the unit outward normals of the slave faces at node j
   !> (at the node's corner of each face), i.e. out of the master body.
   function slave_nodal_normals(coords, slave_nodes, slave_faces) result(normal)
      real(dp), intent(in) :: coords(:, :)
      integer, intent(in) :: slave_nodes(:), slave_faces(:, :)
      real(dp) :: normal(3, size(slave_nodes))
      integer, allocatable :: position_of(:)
      integer :: f, a, j
      real(dp) :: length
      allocate (position_of(size(coords, 2)), source=0)
      do j = 1, size(slave_nodes)
         position_of(slave_nodes(j)) = j
      end do
      normal = 0.0_dp
      do f = 1, size(slave_faces, 2)
         do a = 1, 4
            j = position_of(slave_faces(a, f))
            normal(:, j) = normal(:, j) - face_normal(coords(:, slave_faces(:, f)), [face_node_xi(a), face_node_eta(a)])
         end do
      end do
      do j = 1, size(slave_nodes)
         length = norm2(normal(:, j))
         if (length > 0.0_dp) normal(:, j) = normal(:, j)/length
      end do
   end function slave_nodal_normals

   !> Slave node j (tributary area `area`) of `rows` at the current positions x(3, :) of its
   !> row's nodes: the result (gap g_j / D_j; pressure p_j D_j / A_j, the node's normal force
   !> over its reference tributary area, as node-to-segment contact writes it, where p_j is per
   !> current area; normal, status), the internal force
   !> fint = -(forces on the nodes) (3 per row node, node-major) and its tangent with D, M and
   !> n_j fixed (force/length). A node with D_j < least_mortar_coverage A_j is open with gap
   !> huge; a node the law does not make active is open with its gap.
   subroutine mortar_node_contact(law, rows, j, x, area, result, fint, tangent)
      class(normal_contact_law_t), intent(in) :: law
      type(mortar_rows_t), intent(in) :: rows
      integer, intent(in) :: j
      real(dp), intent(in) :: x(:, :)          !! (3, row length) current positions
      real(dp), intent(in) :: area             !! A_j (reference)
      type(contact_point_result_t), intent(out) :: result
      real(dp), intent(out) :: fint(:)         !! 3 x row length
      real(dp), intent(out) :: tangent(:, :)   !! (3 x row length) squared
      type(dual_t) :: gap(1), pressure
      integer :: k
      fint = 0.0_dp
      tangent = 0.0_dp
      result%normal = rows%normal(:, j)
      result%gap = huge(1.0_dp)
      if (.not. rows%dual_area(j) >= least_mortar_coverage*area) return
      associate (c => rows%weight(rows%start(j) + 1:rows%start(j + 1)), n => rows%normal(:, j), &
                 dual_area => rows%dual_area(j))
         result%gap = dot_product(n, matmul(x, c))/dual_area
         if (.not. law%active(result%gap, 0.0_dp)) return
         gap = dual_variable([result%gap], 1)
         pressure = law%pressure(gap(1), 0.0_dp)
         ! written per reference tributary area, as node-to-segment's p_N A_j / A_j
         result%pressure = pressure%value*dual_area/area
         result%status = contact_slip   ! frictionless, as node-to-segment's
         result%law_status = contact_slip
         do k = 1, size(c)
            fint(3*k - 2:3*k) = -pressure%value*c(k)*n
         end do
         tangent = mortar_row_stiffness(rows, j, -pressure%gradient(1)/dual_area)
      end associate
   end subroutine mortar_node_contact

   !> factor (c n_j)(c n_j)^T over row j's nodes (3 x row length squared): the stiffness of a
   !> normal spring factor D_j (force/area/length) on the weighted gap g_j / D_j.
   pure function mortar_row_stiffness(rows, j, factor) result(stiffness)
      type(mortar_rows_t), intent(in) :: rows
      integer, intent(in) :: j
      real(dp), intent(in) :: factor   !! (force/area/length) / area
      real(dp), allocatable :: stiffness(:, :)
      real(dp), allocatable :: v(:)
      integer :: k, n_row
      n_row = rows%start(j + 1) - rows%start(j)
      allocate (v(3*n_row))
      do k = 1, n_row
         v(3*k - 2:3*k) = rows%weight(rows%start(j) + k)*rows%normal(:, j)
      end do
      stiffness = factor*spread(v, 2, 3*n_row)*spread(v, 1, 3*n_row)
   end function mortar_row_stiffness
end module frix_mortar_contact
