!> One contact pass: the nodes of a slave surface against the faces of a master surface or a
!> rigid plane, with each slave node's current master face, friction branch and kernel result,
!> and its committed history (anchor, accumulated slip, Lagrange multiplier of the normal law).
!> docs/contact.md, "In the global system".
module frix_contact_pass
   use frix_kinds, only: dp
   use frix_mesh, only: mesh_t, surface_t
   use frix_contact_kernel, only: contact_point_result_t, max_ring_nodes, contact_slip
   use frix_contact_patches, only: surface_patches_t, surface_faces, free_edges
   use frix_friction_law, only: branch_free, branch_stick
   use frix_tie_mortar, only: tie_coupling_t
   use frix_mortar_contact, only: mortar_rows_t
   implicit none
   private

   public :: contact_pass_t, max_kernel_nodes, set_slave_nodes, set_master_faces, start_pass_state
   public :: kernel_nodes, slip_reversed
   public :: set_plane_master_faces, pass_positions, pass_node, pass_coordinates, plane_edges

   !> most nodes of one kernel call: slave, face, anchor face, smoothed-normal ring
   integer, parameter :: max_kernel_nodes = 9 + max_ring_nodes

   !> One pass: the nodes of a slave surface against the faces of a master surface or a plane.
   type :: contact_pass_t
      integer :: pair = 0                      !! index of the pass's contact pair (the model's)
      logical :: rigid = .false.               !! master is the pair's rigid plane
      !> a TIE: each slave node with a master face (its closest point, for the output's
      !> normal) is bonded to the master nodes of `tie` by elimination (frix_tie_pass,
      !> frix_tie_constraints); no kernel, no search
      logical :: tied = .false.
      type(tie_coupling_t) :: tie
      !> DISCRETIZATION Mortar: the slave nodes' weighted gaps over the slave faces
      !> (4, n_slave_faces; mesh nodes, outward order) against the master faces, with the
      !> mortar rows of the current iterate (frix_mortar_contact, computed by the search); no
      !> kernel per node and face, pass%face(i) a master face overlapping node i's faces
      logical :: mortar = .false.
      integer, allocatable :: slave_faces(:, :)
      type(mortar_rows_t) :: mortar_rows
      !> mortar with friction: the rows and the tangential traction t^n (3, n_slave; force per
      !> current area, the friction law's) of the last converged increment
      type(mortar_rows_t) :: committed_mortar_rows
      real(dp), allocatable :: committed_mortar_traction(:, :)
      integer, allocatable :: slave_nodes(:)   !! internal node numbers
      real(dp), allocatable :: area(:)         !! tributary area of each slave node (reference)
      !> PASSES 2: the other pass of the pair (0 with one pass), the position of each mesh node
      !> among this pass's slave nodes (0: not one), and the force of the interface on each
      !> slave node from both passes at the last assembly (its own kernel's and the other
      !> pass's kernels' reactions on it; force units), from which the interface pressure is
      !> written (frix_contact_assembly's interface_traction)
      integer :: partner = 0
      integer, allocatable :: slave_index(:)
      real(dp), allocatable :: interface_force(:, :)
      integer, allocatable :: faces(:, :)      !! (4, n_faces) master face nodes, outward order
      !> (4, n_faces) edge k of face f (its nodes k and mod(k, 4) + 1) belongs to no other master
      !> face: a free edge, the master surface's boundary, beyond which a slave node is open
      !> (frix_contact_search's nearest_face; docs/contact.md, "Edges and corners")
      logical, allocatable :: free_edge(:, :)
      !> a master surface of plane elements' edges (docs/contact.md, "Plane bodies"): edge
      !> (n1, n2) is the face [lo(n1), lo(n2), hi(n2), hi(n1)] of corners at the edge's nodes
      !> moved by -h/2 and +h/2 along z (h = corner_height), so that the slave nodes, in z = 0,
      !> meet the faces' middle line. The corners are numbers beyond the mesh's n_nodes:
      !> n_nodes + k is corner k, at mesh node corner_node(k), lo for k <= size / 2, hi after;
      !> a corner moves with its node (pass_positions), and its force and stiffness go onto
      !> the node (pass_node)
      logical :: plane = .false.
      integer :: n_nodes = 0                   !! the mesh's nodes (plane: corners are beyond)
      integer, allocatable :: corner_node(:)
      real(dp) :: corner_height = 0.0_dp
      real(dp) :: band = 0.0_dp                !! search band above the master surface (length)
      real(dp) :: face_size = 0.0_dp           !! mean size of the master faces (reference, length)
      !> smoothed normals (NORMALS Smoothed or Auto): the patch of every master face (within the
      !> pair's feature angle)
      logical :: smooth = .false.
      type(surface_patches_t) :: patches
      ! the current iterate
      integer, allocatable :: face(:)          !! master face of each slave node, 0: none
      !> friction branch imposed on each slave node in this increment (branch_free: the law
      !> decides; branch_stick after a slip reversal, frix_contact_assembly's slip_reversed)
      integer, allocatable :: branch(:)
      logical, allocatable :: released(:)          !! imposed once and released: not again
      logical, allocatable :: slipped(:)           !! slipping at the last iterate
      real(dp), allocatable :: slip_direction(:, :)  !! (3, n_slave) t/|t| at the last iterate
      type(contact_point_result_t), allocatable :: result(:)
      ! the last converged increment
      integer, allocatable :: anchor_face(:)
      real(dp), allocatable :: anchor_xi(:, :)     !! (2, n_slave)
      real(dp), allocatable :: anchor_point(:, :)  !! (3, n_slave), rigid plane
      logical, allocatable :: has_anchor(:)
      real(dp), allocatable :: slip(:)             !! accumulated slip (length)
      !> Lagrange multiplier lambda of each slave node for the normal contact law (force/area,
      !> an estimate of p_N; 0 and unused by the penalty law): the current one, changed only
      !> by augmentations (frix_contact_augmentation), and the last converged increment's
      real(dp), allocatable :: multiplier(:), committed_multiplier(:)
      !> with augmented friction: the tangential multiplier lambda_T of each slave node (3, n:
      !> force/area, global components), current and committed, as `multiplier`
      real(dp), allocatable :: tangential_multiplier(:, :), committed_tangential_multiplier(:, :)
      !> augmented passes: the rates d lambda / dt and d lambda_T / dt of the last converged
      !> increment (force/area per unit pseudo time; 0 for a node not pressed at both its ends),
      !> from which the next increment's multipliers are predicted (PREDICT,
      !> frix_contact_augmentation's predict_multipliers)
      real(dp), allocatable :: multiplier_rate(:), tangential_multiplier_rate(:, :)
      !> augmented passes: the factors on eps_N and eps_T of the current solution (grown by
      !> frix_contact_augmentation's grow_penalties) and of the last converged increment, and
      !> the largest |gap| of a pressed node and stick slip (length) of the previous
      !> augmentation in the increment (< 0: none yet)
      real(dp) :: normal_scale = 1.0_dp, tangential_scale = 1.0_dp
      real(dp) :: committed_normal_scale = 1.0_dp, committed_tangential_scale = 1.0_dp
      real(dp) :: previous_penetration = -1.0_dp, previous_slip = -1.0_dp
   end type contact_pass_t

contains

   !> The slave nodes of a surface (in node order) and their tributary areas A_s: the
   !> reference-face integrals of N_a of its faces (`face_weights(:, k)` of face k, given by the
   !> faces' elements: element_t%face_weights) summed over the faces at each node.
   subroutine set_slave_nodes(mesh, surface, face_weights, pass)
      type(mesh_t), intent(in) :: mesh
      type(surface_t), intent(in) :: surface
      real(dp), intent(in) :: face_weights(:, :)   !! (face nodes, faces) integral of N_a dA0
      type(contact_pass_t), intent(inout) :: pass
      integer, allocatable :: position_of(:), face_nodes(:)
      real(dp), allocatable :: node_area(:)
      integer :: k, a, node, n_slave
      allocate (position_of(mesh%n_nodes), source=0)
      allocate (node_area(mesh%n_nodes), source=0.0_dp)
      n_slave = 0
      do k = 1, size(surface%elements)
         face_nodes = mesh%face_nodes(surface%elements(k), surface%faces(k))
         do a = 1, size(face_nodes)
            node = face_nodes(a)
            if (position_of(node) == 0) then
               n_slave = n_slave + 1
               position_of(node) = n_slave
            end if
            node_area(node) = node_area(node) + face_weights(a, k)
         end do
      end do
      allocate (pass%slave_nodes(n_slave))
      do node = 1, mesh%n_nodes
         if (position_of(node) > 0) pass%slave_nodes(position_of(node)) = node
      end do
      pass%area = node_area(pass%slave_nodes)
   end subroutine set_slave_nodes

   !> The master faces of a surface, their free edges and the search band's geometric part:
   !> half the mean face size, a face's size being the mean of its diagonals over sqrt(2)
   !> (reference, length).
   subroutine set_master_faces(mesh, surface, pass)
      type(mesh_t), intent(in) :: mesh
      type(surface_t), intent(in) :: surface
      type(contact_pass_t), intent(inout) :: pass
      real(dp) :: coords(3, 4), size_sum
      integer :: k
      pass%faces = surface_faces(mesh, surface)
      pass%free_edge = free_edges(mesh%n_nodes, pass%faces)
      size_sum = 0.0_dp
      do k = 1, size(surface%elements)
         coords = mesh%coords(:, pass%faces(:, k))
         size_sum = size_sum + 0.5_dp*(norm2(coords(:, 3) - coords(:, 1)) + &
                                       norm2(coords(:, 4) - coords(:, 2)))/sqrt(2.0_dp)
      end do
      pass%face_size = size_sum/max(1, size(surface%elements))
      pass%band = 0.5_dp*pass%face_size
   end subroutine set_master_faces

   !> The master faces of a surface of plane elements' edges (pass%plane: the corners of each
   !> edge's face at z = -h/2 and +h/2, h the mean edge length), their free edges and the
   !> search band's geometric part: half the mean edge length (reference, length). The edges
   !> run counter-clockwise around their elements, so that the face normal (x_3 - x_1) x
   !> (x_4 - x_2) = 4 h (n2 - n1) x e_z points out of the master body.
   subroutine set_plane_master_faces(mesh, surface, pass)
      type(mesh_t), intent(in) :: mesh
      type(surface_t), intent(in) :: surface
      type(contact_pass_t), intent(inout) :: pass
      integer, allocatable :: corner_of(:), edge(:)
      real(dp) :: length_sum
      integer :: k, a, n_master, n_edges
      n_edges = size(surface%elements)
      allocate (corner_of(mesh%n_nodes), source=0)
      do k = 1, n_edges
         edge = mesh%face_nodes(surface%elements(k), surface%faces(k))
         corner_of(edge) = 1
      end do
      n_master = 0
      do a = 1, mesh%n_nodes
         if (corner_of(a) == 0) cycle
         n_master = n_master + 1
         corner_of(a) = n_master
      end do
      pass%plane = .true.
      pass%n_nodes = mesh%n_nodes
      allocate (pass%corner_node(2*n_master))
      do a = 1, mesh%n_nodes
         if (corner_of(a) == 0) cycle
         pass%corner_node([corner_of(a), n_master + corner_of(a)]) = a
      end do
      allocate (pass%faces(4, n_edges))
      length_sum = 0.0_dp
      do k = 1, n_edges
         edge = mesh%face_nodes(surface%elements(k), surface%faces(k))
         pass%faces(:, k) = mesh%n_nodes + [corner_of(edge(1)), corner_of(edge(2)), &
                                            n_master + corner_of(edge(2)), n_master + corner_of(edge(1))]
         length_sum = length_sum + norm2(mesh%coords(:, edge(2)) - mesh%coords(:, edge(1)))
      end do
      pass%face_size = length_sum/max(1, n_edges)
      pass%corner_height = pass%face_size
      pass%free_edge = free_edges(mesh%n_nodes + 2*n_master, pass%faces)
      pass%band = 0.5_dp*pass%face_size
   end subroutine set_plane_master_faces

   !> Whether a surface's faces are edges of plane elements (the master of a plane pass). A
   !> model's elements are all plane or all solids.
   pure logical function plane_edges(mesh, surface)
      type(mesh_t), intent(in) :: mesh
      type(surface_t), intent(in) :: surface
      plane_edges = .false.
      if (size(surface%elements) == 0) return
      plane_edges = mesh%cell_dimension(surface%elements(1)) == 2
   end function plane_edges

   !> The mesh node of node `id` of a pass's faces or kernels (a plane pass's corner: its node).
   elemental integer function pass_node(pass, id) result(node)
      type(contact_pass_t), intent(in) :: pass
      integer, intent(in) :: id
      node = id
      if (pass%plane) then
         if (id > pass%n_nodes) node = pass%corner_node(id - pass%n_nodes)
      end if
   end function pass_node

   !> The current positions X + u of nodes `ids` of a pass's faces or kernels (mesh nodes, or
   !> a plane pass's corners: their node's position moved by -+h/2 along z). coords (3,
   !> n_nodes) reference coordinates, u (3 n_nodes) displacements node-major.
   pure function pass_positions(pass, coords, u, ids) result(x)
      type(contact_pass_t), intent(in) :: pass
      real(dp), intent(in) :: coords(:, :), u(:)
      integer, intent(in) :: ids(:)
      real(dp) :: x(3, size(ids))
      integer :: a, node
      do a = 1, size(ids)
         node = pass_node(pass, ids(a))
         x(:, a) = coords(:, node) + u(3*node - 2:3*node)
         if (node /= ids(a)) x(3, a) = x(3, a) + corner_z(pass, ids(a))
      end do
   end function pass_positions

   !> The reference coordinates of a pass's nodes: the mesh's (3, n_nodes), and for a plane
   !> pass its corners after them (3, n_nodes + number of corners).
   pure function pass_coordinates(pass, coords) result(x)
      type(contact_pass_t), intent(in) :: pass
      real(dp), intent(in) :: coords(:, :)
      real(dp), allocatable :: x(:, :)
      integer :: k
      if (.not. pass%plane) then
         x = coords
         return
      end if
      allocate (x(3, pass%n_nodes + size(pass%corner_node)))
      x(:, :pass%n_nodes) = coords
      do k = 1, size(pass%corner_node)
         x(:, pass%n_nodes + k) = coords(:, pass%corner_node(k))
         x(3, pass%n_nodes + k) = x(3, pass%n_nodes + k) + corner_z(pass, pass%n_nodes + k)
      end do
   end function pass_coordinates

   !> The z offset of a plane pass's corner `id`: -h/2 for the lower corners, +h/2 for the upper.
   pure real(dp) function corner_z(pass, id)
      type(contact_pass_t), intent(in) :: pass
      integer, intent(in) :: id
      corner_z = merge(-0.5_dp, 0.5_dp, id - pass%n_nodes <= size(pass%corner_node)/2)*pass%corner_height
   end function corner_z

   !> The per-node state of a pass whose slave nodes are set: no face, the law's branches, no
   !> anchor, no slip, zero multipliers.
   subroutine start_pass_state(pass)
      type(contact_pass_t), intent(inout) :: pass
      integer :: n_slave
      n_slave = size(pass%slave_nodes)
      allocate (pass%face(n_slave), pass%anchor_face(n_slave), source=0)
      allocate (pass%branch(n_slave), source=branch_free)
      allocate (pass%released(n_slave), pass%slipped(n_slave), source=.false.)
      allocate (pass%slip_direction(3, n_slave), source=0.0_dp)
      allocate (pass%result(n_slave))
      allocate (pass%anchor_xi(2, n_slave), pass%anchor_point(3, n_slave), pass%slip(n_slave), &
                pass%multiplier(n_slave), pass%committed_multiplier(n_slave), pass%multiplier_rate(n_slave), &
                source=0.0_dp)
      allocate (pass%tangential_multiplier(3, n_slave), pass%committed_tangential_multiplier(3, n_slave), &
                pass%tangential_multiplier_rate(3, n_slave), source=0.0_dp)
      allocate (pass%has_anchor(n_slave), source=.false.)
   end subroutine start_pass_state

   !> The nodes of slave i's contact kernel: the slave, its master face's 4 nodes, when its
   !> committed anchor lies on another face that face's 4 nodes, and with smoothed normals the
   !> face's ring, nodes(first_ring:n_nodes) (first_ring = 6 or 10).
   pure subroutine kernel_nodes(pass, i, nodes, n_nodes, first_ring)
      type(contact_pass_t), intent(in) :: pass
      integer, intent(in) :: i
      integer, intent(out) :: nodes(max_kernel_nodes), n_nodes, first_ring
      integer :: f
      nodes = 0
      f = pass%face(i)
      nodes(1) = pass%slave_nodes(i)
      nodes(2:5) = pass%faces(:, f)
      n_nodes = 5
      if (pass%has_anchor(i) .and. pass%anchor_face(i) /= f .and. pass%anchor_face(i) > 0) then
         nodes(6:9) = pass%faces(:, pass%anchor_face(i))
         n_nodes = 9
      end if
      first_ring = n_nodes + 1
      if (pass%smooth) then
         associate (ring_start => pass%patches%ring_start)
            n_nodes = n_nodes + ring_start(f + 1) - ring_start(f)
            nodes(first_ring:n_nodes) = pass%patches%ring_nodes(ring_start(f) + 1:ring_start(f + 1))
         end associate
      end if
   end subroutine kernel_nodes

   !> Slip reversal (called at each Newton iterate, after slave i's evaluation): a node that
   !> slipped at the previous iterate and now slips the opposite way (t . t_previous < 0) has
   !> its solution in between, in the stick zone of width 2 mu p_N / eps_T around its anchor.
   !> The slip branch cannot find it: its traction +-mu p_N jumps across the zone and its
   !> tangent has no stiffness along the slip (Newton alternates between the two sides, as
   !> for a relay). The node is then held in stick (linear in g_T: one Newton step lands in
   !> the zone) until a converged iterate where the law chooses slip releases it
   !> (release_inconsistent_branches). Returns .true. when the node has just been put in
   !> stick and must be evaluated again.
   logical function slip_reversed(pass, i) result(reversed)
      type(contact_pass_t), intent(inout) :: pass
      integer, intent(in) :: i
      real(dp) :: magnitude, direction(3)
      reversed = .false.
      magnitude = norm2(pass%result(i)%traction)
      if (pass%result(i)%status /= contact_slip .or. .not. magnitude > 0.0_dp) then
         pass%slipped(i) = .false.
         return
      end if
      direction = pass%result(i)%traction/magnitude
      if (pass%slipped(i) .and. pass%branch(i) == branch_free .and. .not. pass%released(i)) then
         reversed = dot_product(direction, pass%slip_direction(:, i)) < 0.0_dp
      end if
      pass%slipped(i) = .true.
      pass%slip_direction(:, i) = direction
      if (reversed) then
         pass%branch(i) = branch_stick
         pass%slipped(i) = .false.
      end if
   end function slip_reversed
end module frix_contact_pass
