!> Mortar (segment-to-segment) contact with dual mortar weights and Coulomb friction (deck
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
!> Friction (objective weighted slip increment: Puso & Laursen 2004; Gitterle, Popp, Gee &
!> Wall, IJNME 84 (2010) 543-571): with c^n the coefficients of the last converged increment,
!>
!>     u_j = sum_k (c^n_jk - c_jk) x_k = (M - M^n)_jl x_l - (D - D^n)_jk x_k   (length x area)
!>
!> the slip of the slave relative to the master over the increment times D_j (a rigid motion of
!> both bodies, which leaves D and M unchanged, gives none); elastic stick with the penalty
!> eps_T and the incremental trial traction t_trial = P t^n - eps_T P u_j / D_j (force/area,
!> on the slave; P = I - n_j n_j, t^n the traction of the last converged increment), returned
!> by the pair's friction law (frix_friction_law) with the pressure p_j. Forces
!> c_jk (p_j n_j + t_j) on every node k of the row.
!>
!> Tangent, to first order: the derivatives of the mortar integrals and of the nodal normal are
!> left out (D, M, n_j held fixed), and the slip's is taken as d (P u_j) = P sum_l c^n_jl dx_l.
!> The latter holds where the tangential part of the weighted gap vector, P sum_k c_jk x_k =
!> int phi_j P (x_s - x_m) dA, stays zero (x_s - x_m lies along the master's normal, the
!> closest-point pairing, and n_j along it too), so that P (dc) x = -P c dx; u_j is then
!> D_j (x_j - x_A) with x_A the master point that lay under the node, as node-to-segment's
!> anchor. What is left out is of relative order |g| / h, (slip increment) / h and h / R (h
!> the face size, R the surfaces' radius of curvature). The normal law's and the friction
!> law's derivatives are exact (dual numbers). Frictionless: K = -(dp_N/dg) / D_j
!> (c n_j)(c n_j)^T, symmetric. On curved surfaces frix_mortar_assembly replaces this tangent by
!> the complete one (central differences of the node's force, its row recomputed).
module frix_mortar_contact
   use frix_kinds, only: dp
   use frix_face_projection, only: face_normal, face_node_xi, face_node_eta
   use frix_surface_load, only: face_area_weights
   use frix_dual_number, only: dual_t, dual_variable
   use frix_contact_parameters, only: contact_parameters_t
   use frix_contact_kernel, only: contact_point_result_t, contact_stick, contact_slip
   use frix_mortar_segments, only: triplets_t, append_triplet, mortar_triplets, compress_rows
   implicit none
   private

   public :: mortar_rows_t, mortar_rows, mortar_node_t, mortar_node, mortar_node_contact
   public :: mortar_covered

   !> A slave node takes part in the contact when the master covers this fraction of its
   !> current tributary area a_j = int N_j dA over its current slave faces
   !> (D_j >= least_mortar_coverage a_j, both in the current configuration, so that a slave
   !> surface stretched or shrunk in its plane keeps its covered nodes), as a tied node
   !> (frix_tie_pass, where both are in the reference configuration).
   real(dp), parameter :: least_mortar_coverage = 0.5_dp

   !> The mortar rows of a pass's slave nodes: row j's nodes nodes(start(j) + 1 : start(j + 1))
   !> (mesh numbers, slave and master) with coefficients c_jk (area), D_j (area), the current
   !> tributary area a_j (area), the normal n_j (unit, out of the master body) and a master
   !> face overlapping node j's faces (0: none).
   type :: mortar_rows_t
      integer, allocatable :: start(:), nodes(:)
      real(dp), allocatable :: weight(:)
      real(dp), allocatable :: dual_area(:), tributary_area(:)
      real(dp), allocatable :: normal(:, :)
      integer, allocatable :: master_face(:)
   end type mortar_rows_t

   !> One slave node's evaluation: the nodes of its current row and, with friction, of its
   !> committed row (mesh numbers), their current positions (3, n; the caller's), the current
   !> and committed coefficients on them (0 where a node is not in that row), D_j (area), the
   !> tributary areas A_j (reference, the results' divisor) and a_j (current, the coverage's),
   !> n_j and the committed traction t^n (force/area); `fresh`: the node starts from its current
   !> row (not in contact at the last converged increment), so it has no slip increment and no
   !> friction in this increment.
   type :: mortar_node_t
      integer, allocatable :: nodes(:)
      real(dp), allocatable :: x(:, :)
      real(dp), allocatable :: weight(:), committed_weight(:)
      real(dp) :: dual_area = 0.0_dp, area = 0.0_dp, tributary_area = 0.0_dp
      real(dp) :: normal(3) = 0.0_dp, committed_traction(3) = 0.0_dp
      logical :: fresh = .true.
   end type mortar_node_t

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
      integer, allocatable :: position_of(:)
      integer :: k, n_slave
      n_slave = size(slave_nodes)
      allocate (rows%master_face(n_slave))
      call mortar_triplets(coords, slave_nodes, slave_faces, master_faces, distance, m, d, rows%master_face)
      allocate (rows%dual_area(n_slave), source=0.0_dp)
      do k = 1, d%n
         rows%dual_area(d%row(k)) = rows%dual_area(d%row(k)) + d%value(k)
         call append_triplet(m, d%row(k), d%node(k), -d%value(k))
      end do
      ! m now holds M_jl and -D_jk; c_jk = D_jk - M_jk. Nothing but zeros dropped: a dropped
      ! entry eps would move the weighted gap by eps |x|, which eps_N turns into a force that
      ! comes and goes between iterations (slivers of coincident edges hover at 1e-12)
      call compress_rows(m, n_slave, rows%start, rows%nodes, rows%weight, drop=0.0_dp)
      rows%weight = -rows%weight
      position_of = slave_positions(size(coords, 2), slave_nodes)
      rows%normal = slave_nodal_normals(coords, position_of, slave_faces)
      rows%tributary_area = tributary_areas(coords, position_of, slave_faces)
   end subroutine mortar_rows

   !> a_j = int N_j dA over the slave faces at node j at the coordinates `coords` (area;
   !> face_area_weights, as the reference A_j of frix_contact_pass).
   pure function tributary_areas(coords, position_of, slave_faces) result(area)
      real(dp), intent(in) :: coords(:, :)
      integer, intent(in) :: position_of(:)   !! slave_positions'
      integer, intent(in) :: slave_faces(:, :)
      real(dp) :: area(maxval(position_of))
      real(dp) :: weights(4)
      integer :: f
      area = 0.0_dp
      do f = 1, size(slave_faces, 2)
         call face_area_weights(coords(:, slave_faces(:, f)), weights)
         area(position_of(slave_faces(:, f))) = area(position_of(slave_faces(:, f))) + weights
      end do
   end function tributary_areas

   !> position_of(node) = the node's place in slave_nodes, 0 for a node not in it (n_nodes
   !> mesh nodes).
   pure function slave_positions(n_nodes, slave_nodes) result(position_of)
      integer, intent(in) :: n_nodes, slave_nodes(:)
      integer :: position_of(n_nodes)
      integer :: j
      position_of = 0
      do j = 1, size(slave_nodes)
         position_of(slave_nodes(j)) = j
      end do
   end function slave_positions

   !> Whether slave node j of `rows` takes part: D_j >= least_mortar_coverage a_j (false for
   !> a NaN, and for a node with no area).
   pure logical function mortar_covered(rows, j)
      type(mortar_rows_t), intent(in) :: rows
      integer, intent(in) :: j
      mortar_covered = covers(rows%dual_area(j), rows%tributary_area(j))
   end function mortar_covered

   !> D_j >= least_mortar_coverage a_j and D_j > 0 (both area).
   pure logical function covers(dual_area, tributary_area)
      real(dp), intent(in) :: dual_area, tributary_area
      covers = dual_area >= least_mortar_coverage*tributary_area .and. dual_area > 0.0_dp
   end function covers

   !> n_j: minus the normalised sum of the unit outward normals of the slave faces at node j
   !> (at the node's corner of each face), i.e. out of the master body. A face with no normal at
   !> the node's corner (zero area, or a node coinciding with a neighbour: face_normal gives the
   !> zero vector) adds nothing; a node with no normal at all keeps n_j = 0.
   function slave_nodal_normals(coords, position_of, slave_faces) result(normal)
      real(dp), intent(in) :: coords(:, :)
      integer, intent(in) :: position_of(:)   !! slave_positions'
      integer, intent(in) :: slave_faces(:, :)
      real(dp) :: normal(3, maxval(position_of))
      integer :: f, a, j
      real(dp) :: length
      normal = 0.0_dp
      do f = 1, size(slave_faces, 2)
         do a = 1, 4
            j = position_of(slave_faces(a, f))
            normal(:, j) = normal(:, j) - face_normal(coords(:, slave_faces(:, f)), [face_node_xi(a), face_node_eta(a)])
         end do
      end do
      do j = 1, size(normal, 2)
         length = norm2(normal(:, j))
         if (length > 0.0_dp) normal(:, j) = normal(:, j)/length
      end do
   end function slave_nodal_normals

   !> Slave node j of `rows` (reference tributary area `area`) as mortar_node_contact takes it,
   !> without positions; with `committed` (friction) also the committed row and traction. A
   !> node not in contact at the last converged increment (`committed_closed` false: open
   !> there, or not covered at the set-up) or not covered then (mortar_covered) starts from the
   !> current row: no slip increment, so that its motion before it touches is not taken as slip
   !> (as a node-to-segment node that closes starts from its closest point).
   subroutine mortar_node(rows, j, area, node, committed, committed_traction, committed_closed, committed_row)
      type(mortar_rows_t), intent(in) :: rows
      integer, intent(in) :: j
      real(dp), intent(in) :: area
      type(mortar_node_t), intent(out) :: node
      type(mortar_rows_t), intent(in), optional :: committed
      real(dp), intent(in), optional :: committed_traction(3)
      logical, intent(in), optional :: committed_closed   !! with `committed`
      !> the node's row in `committed` (default j; rows of a part of the slave surface)
      integer, intent(in), optional :: committed_row
      integer, allocatable :: nodes(:)
      real(dp), allocatable :: weight(:), committed_weight(:)
      integer :: k, n, position, jc
      node%nodes = rows%nodes(rows%start(j) + 1:rows%start(j + 1))
      node%weight = rows%weight(rows%start(j) + 1:rows%start(j + 1))
      node%committed_weight = node%weight
      node%dual_area = rows%dual_area(j)
      node%area = area
      node%tributary_area = rows%tributary_area(j)
      node%normal = rows%normal(:, j)
      if (.not. present(committed)) return
      node%committed_traction = committed_traction
      jc = j
      if (present(committed_row)) jc = committed_row
      if (.not. (committed_closed .and. mortar_covered(committed, jc))) return
      node%fresh = .false.
      ! the union of the two rows, current row first (joined once, not grown per entry)
      n = size(node%nodes)
      allocate (nodes(n + committed%start(jc + 1) - committed%start(jc)))
      allocate (weight(size(nodes)), committed_weight(size(nodes)))
      nodes(:n) = node%nodes
      weight(:n) = node%weight
      committed_weight = 0.0_dp
      do k = committed%start(jc) + 1, committed%start(jc + 1)
         position = findloc(nodes(:n), committed%nodes(k), dim=1)
         if (position == 0) then
            n = n + 1
            nodes(n) = committed%nodes(k)
            weight(n) = 0.0_dp
            position = n
         end if
         committed_weight(position) = committed%weight(k)
      end do
      node%nodes = nodes(:n)
      node%weight = weight(:n)
      node%committed_weight = committed_weight(:n)
   end subroutine mortar_node

   !> One slave node: the result (gap g_j / D_j; pressure p_j D_j / A_j, the node's normal
   !> force over its reference tributary area, as node-to-segment contact writes it, where
   !> p_j is per current area; the traction t_j the same way; normal n_j; status; the plastic
   !> slip (|t_trial| - |t|) / eps_T of the increment), the internal force fint = -(forces on
   !> the nodes) (3 per node of `node`, node-major) and its tangent with the mortar
   !> coefficients and n_j fixed (force/length). A node with D_j < least_mortar_coverage a_j is
   !> open with gap huge; a node the law does not make active is open with its gap.
   !> friction_scale multiplies the pressure the friction law sees (friction continuation);
   !> branch: the friction branch (frix_friction_law).
   subroutine mortar_node_contact(parameters, node, friction_scale, branch, result, fint, tangent)
      type(contact_parameters_t), intent(in) :: parameters
      type(mortar_node_t), intent(in) :: node
      real(dp), intent(in) :: friction_scale
      integer, intent(in) :: branch
      type(contact_point_result_t), intent(out) :: result
      real(dp), intent(out) :: fint(:)         !! 3 size(node%nodes)
      real(dp), intent(out) :: tangent(:, :)   !! (3 size(node%nodes)) squared
      type(dual_t) :: gap(1), pressure
      real(dp) :: traction(3), d_traction(3, 3), d_pressure(3), slip_area(3)
      integer :: k, l
      fint = 0.0_dp
      tangent = 0.0_dp
      result%normal = node%normal
      result%gap = huge(1.0_dp)
      if (.not. covers(node%dual_area, node%tributary_area)) return
      associate (c => node%weight, n => node%normal, dual_area => node%dual_area)
         result%gap = dot_product(n, matmul(node%x, c))/dual_area
         if (.not. parameters%normal%active(result%gap, 0.0_dp)) return
         gap = dual_variable([result%gap], 1)
         pressure = parameters%normal%pressure(gap(1), 0.0_dp)
         result%pressure = pressure%value*dual_area/node%area
         result%status = contact_slip   ! frictionless, as node-to-segment's
         result%law_status = contact_slip
         traction = 0.0_dp
         d_traction = 0.0_dp
         d_pressure = 0.0_dp
         ! a fresh node: slip 0 and t^n = 0 give t = 0 in stick, its derivatives 0 (the row it
         ! starts from moves with it)
         if (node%fresh .and. .not. parameters%friction%frictionless()) then
            result%status = contact_stick
            result%law_status = contact_stick
         end if
         if (.not. (parameters%friction%frictionless() .or. node%fresh)) then
            slip_area = matmul(node%x, node%committed_weight - c)
            call friction_return(parameters, node, slip_area, pressure%value, friction_scale, branch, result, &
                                 traction, d_traction, d_pressure)
         end if
         do k = 1, size(c)
            fint(3*k - 2:3*k) = -c(k)*(pressure%value*n + traction)
         end do
         tangent = mortar_row_stiffness_of(c, n, -pressure%gradient(1)/dual_area)
         if (parameters%friction%frictionless() .or. node%fresh) return
         ! d t / d x_l = d_traction (-eps_T/D_j) P c^n_l + d_pressure (dp_j/dx_l) (P u_j to first
         ! order: header), dp_j / dx_l = p_N'(g) c_l n^T / D_j; K_kl -= c_k d t / d x_l
         ! d t / d t_trial on the tangent plane's part of the slip: d_traction (I - n n)
         d_traction = d_traction - matmul(d_traction, spread(n, 2, 3)*spread(n, 1, 3))
         do l = 1, size(c)
            associate (column => -parameters%tangential_penalty/dual_area*node%committed_weight(l)*d_traction + &
                                 spread(d_pressure, 2, 3)*spread(pressure%gradient(1)*c(l)/dual_area*n, 1, 3))
               do k = 1, size(c)
                  tangent(3*k - 2:3*k, 3*l - 2:3*l) = tangent(3*k - 2:3*k, 3*l - 2:3*l) - c(k)*column
               end do
            end associate
         end do
      end associate
   end subroutine mortar_node_contact

   !> The friction law's traction t_j (force/area) from the trial P t^n - eps_T P u_j / D_j
   !> (u_j = slip_area, length x area) and the pressure p_j (times friction_scale), with
   !> d t / d t_trial and d t / d p_j; the result's traction (per reference area, as the
   !> pressure), status and plastic slip.
   subroutine friction_return(parameters, node, slip_area, pressure, friction_scale, branch, result, traction, &
                              d_traction, d_pressure)
      type(contact_parameters_t), intent(in) :: parameters
      type(mortar_node_t), intent(in) :: node
      real(dp), intent(in) :: slip_area(3), pressure, friction_scale
      integer, intent(in) :: branch
      type(contact_point_result_t), intent(inout) :: result
      real(dp), intent(out) :: traction(3), d_traction(3, 3), d_pressure(3)
      type(dual_t) :: trial(4), returned(3)
      real(dp) :: projected(3)
      logical :: slipping, law_slipping
      integer :: k
      associate (n => node%normal)
         projected = node%committed_traction - dot_product(node%committed_traction, n)*n &
                     - parameters%tangential_penalty/node%dual_area*(slip_area - dot_product(slip_area, n)*n)
      end associate
      trial = dual_variable([projected, friction_scale*pressure], 1)
      call parameters%friction%return_map(trial(1:3), trial(4), branch, returned, slipping, law_slipping)
      do k = 1, 3
         traction(k) = returned(k)%value
         d_traction(k, :) = returned(k)%gradient(1:3)
         d_pressure(k) = friction_scale*returned(k)%gradient(4)
      end do
      result%traction = traction*node%dual_area/node%area
      result%status = merge(contact_slip, contact_stick, slipping)
      result%law_status = merge(contact_slip, contact_stick, law_slipping)
      if (slipping) result%slip_increment = (norm2(projected) - norm2(traction))/parameters%tangential_penalty
   end subroutine friction_return

   !> factor (c n)(c n)^T (3 size(c) squared).
   pure function mortar_row_stiffness_of(c, n, factor) result(stiffness)
      real(dp), intent(in) :: c(:), n(3), factor
      real(dp), allocatable :: stiffness(:, :)
      real(dp) :: v(3*size(c))
      integer :: k
      do k = 1, size(c)
         v(3*k - 2:3*k) = c(k)*n
      end do
      stiffness = factor*spread(v, 2, 3*size(c))*spread(v, 1, 3*size(c))
   end function mortar_row_stiffness_of
end module frix_mortar_contact
