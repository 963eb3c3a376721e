!> Contact in the global system: the contact search (which master face each slave node
!> touches), the slip history of every slave node, and the assembly of the node-to-segment
!> contributions of src/contact/frix_contact_kernel.f90 into the internal force and tangent.
!>
!> Each contact pair of the deck gives one pass (slave nodes against master faces or a rigid
!> plane); PASSES 2 adds the reverse pass (the master's nodes against the slave's faces).
!> Search: at every Newton iteration, each slave node is given the master face whose closest
!> point (clamped to the face: an edge or corner point when the node lies beyond the face) is
!> nearest; the current face is kept on ties, so that a node on an edge shared by two faces
!> does not chatter between them. Candidates come from a uniform bucket grid of the master
!> faces' current bounding boxes, rebuilt every iteration (linear cost). A node farther above
!> the master surface than the search band (max(GAPTOL, half the mean master face size)) gets
!> no face.
!> Touching nodes (0 <= g <= GAPTOL) carry no force but get the penalty stiffness
!> A (eps_N n n + eps_T (I - n n)) (eps_T only with friction; split on the master nodes by
!> N_a) in the predictor, the first iteration of each increment, so that bodies that touch
!> without load, as at the start of an analysis, are supported, also sideways by friction.
!> Later iterations use the consistent tangent only: a stiffness without force would hold a
!> node that has to lift off and stall the iterations.
!> Slip history: every slave node starts with the closest point of its reference position as
!> anchor (master face and face coordinates, or a point of the rigid plane), so friction acts
!> from the first increment; the anchor is committed at every converged increment; when a node
!> has moved to another face, its anchor stays a material point of the old face (whose nodes
!> then enter the node's tangent) until a converged increment carries it over onto the new face.
module frix_contact_assembly
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_mesh, only: hex8_face_nodes, mesh_t, surface_t
   use frix_model, only: model_t
   use frix_sparse_matrix, only: sparse_matrix_t
   use frix_surface_load, only: face_area_weights
   use frix_face_projection, only: face_position, face_normal, closest_point_in_face, &
                                   face_shape_functions
   use frix_contact_kernel, only: contact_point_result_t, node_face_contact, node_plane_contact, &
                                  contact_open, contact_stick, contact_slip, patch_normals, smooth_projection, &
                                  smooth_normal_at, max_ring_nodes
   use frix_face_projection, only: face_contains
   use frix_strings, only: to_string
   use frix_friction_law, only: branch_free, branch_stick, branch_slip
   implicit none
   private

   public :: contact_system_t, setup_contact, search_contact, assemble_contact, commit_contact
   public :: contact_counts, contact_nodal_fields, contact_pass_table, contact_table_labels
   public :: contact_history_rows, get_contact_history, set_contact_history
   public :: reset_friction_branches, release_inconsistent_branches, largest_patch_ring

   !> One pass: the nodes of a slave surface against the faces of a master surface or a plane.
   type :: contact_pass_t
      integer :: pair = 0                      !! index into model%contact_pairs
      logical :: rigid = .false.               !! master is the pair's rigid plane
      integer, allocatable :: slave_nodes(:)   !! internal node numbers
      real(dp), allocatable :: area(:)         !! tributary area of each slave node (reference)
      integer, allocatable :: faces(:, :)      !! (4, n_faces) master face nodes, outward order
      real(dp) :: band = 0.0_dp                !! search band above the master surface (length)
      !> smoothed normals (NORMALS Smoothed): the patch of every master face f, i.e. the faces
      !> around its 4 nodes: ring_nodes(ring_start(f) + 1 : ring_start(f + 1)) are the patch's
      !> nodes other than the face's own, patch_faces(:, patch_start(f) + 1 : patch_start(f + 1))
      !> its faces in local node numbers (1-4 the face's nodes, 4 + j ring node j)
      logical :: smooth = .false.
      integer, allocatable :: ring_start(:), ring_nodes(:), patch_start(:), patch_faces(:, :)
      ! the current iterate
      integer, allocatable :: face(:)          !! master face of each slave node, 0: none
      !> friction branch imposed on each slave node in this increment (branch_free: the law
      !> decides; branch_stick after a slip reversal, see slip_reversed)
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
   end type contact_pass_t

   type :: contact_system_t
      type(contact_pass_t), allocatable :: passes(:)
      integer, allocatable :: extra_pairs(:, :)   !! (2, n) node pairs added to the sparse pattern
      integer :: n_extra = 0
      logical :: frictional = .false.             !! some pair has friction
      !> friction or smoothed normals: the contact tangent is unsymmetric
      logical :: unsymmetric = .false.
      !> factor on the pressure every friction law sees, i.e. on mu for Coulomb; 1 except in
      !> the stages of the driver's friction continuation
      real(dp) :: friction_scale = 1.0_dp
   end type contact_system_t

   !> Columns of `contact_pass_table` (listing, CSV).
   character(len=*), parameter :: contact_table_labels(7) = [character(len=10) :: 'GAP', 'PRESSURE', &
                                                              'TRACTION_X', 'TRACTION_Y', 'TRACTION_Z', &
                                                              'SLIP', 'STATUS']

   integer, parameter :: contact_history_rows = 8  !! rows of get_contact_history

   real(dp), parameter :: tie_tolerance = 1.0e-10_dp  !! relative distance difference counted as a tie
   !> most nodes of one kernel call: slave, face, anchor face, smoothed-normal ring
   integer, parameter :: max_kernel_nodes = 9 + max_ring_nodes

contains

   !> Slave nodes, tributary areas and master faces of every pass.
   subroutine setup_contact(model, system, error)
      type(model_t), intent(in) :: model
      type(contact_system_t), intent(out) :: system
      type(error_t), allocatable, intent(out) :: error
      integer :: p, n_passes, k
      n_passes = 0
      do p = 1, size(model%contact_pairs)
         n_passes = n_passes + model%contact_pairs(p)%passes
      end do
      allocate (system%passes(n_passes))
      allocate (system%extra_pairs(2, 0))
      k = 0
      do p = 1, size(model%contact_pairs)
         associate (pair => model%contact_pairs(p))
            k = k + 1
            call setup_pass(model, p, pair%slave_surface, pair%master_surface, system%passes(k), error)
            if (allocated(error)) return
            if (pair%passes == 2) then
               k = k + 1
               call setup_pass(model, p, pair%master_surface, pair%slave_surface, system%passes(k), error)
               if (allocated(error)) return
            end if
            if (.not. pair%parameters%friction%frictionless()) system%frictional = .true.
            if (system%frictional .or. pair%parameters%smoothed_normals) system%unsymmetric = .true.
         end associate
      end do
   end subroutine setup_contact

   subroutine setup_pass(model, pair, slave_surface, master_surface, pass, error)
      type(model_t), intent(in) :: model
      integer, intent(in) :: pair, slave_surface, master_surface
      type(contact_pass_t), intent(out) :: pass
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: position_of(:)
      real(dp), allocatable :: node_area(:)
      real(dp) :: coords(3, 4), weights(4), size_sum
      integer :: k, a, node, n_slave
      integer :: face_nodes(4)

      pass%pair = pair
      pass%rigid = master_surface == 0
      allocate (position_of(model%mesh%n_nodes), source=0)
      allocate (node_area(model%mesh%n_nodes), source=0.0_dp)
      n_slave = 0
      associate (surface => model%mesh%surfaces(slave_surface))
         do k = 1, size(surface%elements)
            face_nodes = model%mesh%connectivity(hex8_face_nodes(:, surface%faces(k)), surface%elements(k))
            coords = model%mesh%coords(:, face_nodes)
            call face_area_weights(coords, weights)
            do a = 1, 4
               node = face_nodes(a)
               if (position_of(node) == 0) then
                  n_slave = n_slave + 1
                  position_of(node) = n_slave
               end if
               node_area(node) = node_area(node) + weights(a)
            end do
         end do
      end associate
      allocate (pass%slave_nodes(n_slave))
      do node = 1, model%mesh%n_nodes
         if (position_of(node) > 0) pass%slave_nodes(position_of(node)) = node
      end do
      pass%area = node_area(pass%slave_nodes)

      if (pass%rigid) then
         allocate (pass%faces(4, 0))
      else
         associate (surface => model%mesh%surfaces(master_surface))
            pass%faces = surface_faces(model%mesh, surface)
            size_sum = 0.0_dp
            do k = 1, size(surface%elements)
               coords = model%mesh%coords(:, pass%faces(:, k))
               size_sum = size_sum + 0.5_dp*(norm2(coords(:, 3) - coords(:, 1)) + &
                                             norm2(coords(:, 4) - coords(:, 2)))/sqrt(2.0_dp)
            end do
            pass%band = 0.5_dp*size_sum/max(1, size(surface%elements))
         end associate
         if (model%contact_pairs(pair)%parameters%smoothed_normals) then
            call build_patches(model, pass, error)
            if (allocated(error)) return
         end if
      end if
      pass%band = max(pass%band, model%contact_pairs(pair)%parameters%gap_tolerance)
      allocate (pass%face(n_slave), pass%anchor_face(n_slave), source=0)
      allocate (pass%branch(n_slave), source=branch_free)
      allocate (pass%released(n_slave), pass%slipped(n_slave), source=.false.)
      allocate (pass%slip_direction(3, n_slave), source=0.0_dp)
      allocate (pass%result(n_slave))
      allocate (pass%anchor_xi(2, n_slave), pass%anchor_point(3, n_slave), pass%slip(n_slave), &
                source=0.0_dp)
      allocate (pass%has_anchor(n_slave), source=.false.)
      if (pass%rigid) pass%face = 1   ! every slave node faces the plane
      call initial_anchors(model, pass)
   end subroutine setup_pass

   !> The smoothed-normal patches of a pass's master faces; an error if a face has more ring
   !> nodes than the kernel takes (the deck reader reports it first, at the NORMALS keyword).
   subroutine build_patches(model, pass, error)
      type(model_t), intent(in) :: model
      type(contact_pass_t), intent(inout) :: pass
      type(error_t), allocatable, intent(out) :: error
      integer :: f
      call surface_patches(model%mesh%n_nodes, pass%faces, pass%ring_start, pass%ring_nodes, &
                           pass%patch_start, pass%patch_faces)
      pass%smooth = .true.
      if (size(pass%faces, 2) == 0) return
      f = largest_ring_face(pass%ring_start)
      if (pass%ring_start(f + 1) - pass%ring_start(f) > max_ring_nodes) &
         call fatal_error(error, 'contact pair '//to_string(model%contact_pairs(pass%pair)%id)// &
                          ': NORMALS Smoothed: a master face has '// &
                          to_string(pass%ring_start(f + 1) - pass%ring_start(f))//' nodes around it, at most '// &
                          to_string(max_ring_nodes)//' are supported')
   end subroutine build_patches

   !> The face whose ring (surface_patches) has the most nodes (1 for no face).
   pure integer function largest_ring_face(ring_start) result(f)
      integer, intent(in) :: ring_start(:)
      f = 1
      if (size(ring_start) > 1) f = maxloc(ring_start(2:) - ring_start(:size(ring_start) - 1), dim=1)
   end function largest_ring_face

   !> The smoothed-normal patch of every face of a surface (faces(4, n), mesh node numbers):
   !> the faces that share a node with it. ring_nodes(ring_start(f) + 1 : ring_start(f + 1)) are
   !> the patch's nodes other than face f's own; patch_faces(:, patch_start(f) + 1 :
   !> patch_start(f + 1)) its faces (f among them) in local node numbers (1-4 face f's nodes,
   !> 4 + j ring node j), as node_face_contact takes them.
   pure subroutine surface_patches(n_nodes, faces, ring_start, ring_nodes, patch_start, patch_faces)
      integer, intent(in) :: n_nodes          !! nodes of the mesh
      integer, intent(in) :: faces(:, :)      !! (4, n_faces)
      integer, allocatable, intent(out) :: ring_start(:), ring_nodes(:), patch_start(:), patch_faces(:, :)
      integer, allocatable :: node_start(:), node_faces(:), fill(:), adjacent(:), local(:, :), ring(:)
      integer, allocatable :: grown(:, :), grown_ring(:)
      integer :: n_faces, f, g, a, b, k, node, n_adjacent, n_ring, position
      n_faces = size(faces, 2)
      ! faces around each node, compressed rows over the mesh's nodes
      allocate (node_start(n_nodes + 1), source=0)
      do f = 1, n_faces
         node_start(faces(:, f) + 1) = node_start(faces(:, f) + 1) + 1
      end do
      do node = 1, n_nodes
         node_start(node + 1) = node_start(node + 1) + node_start(node)
      end do
      allocate (node_faces(node_start(n_nodes + 1)))
      fill = node_start(:n_nodes)
      do f = 1, n_faces
         do a = 1, 4
            fill(faces(a, f)) = fill(faces(a, f)) + 1
            node_faces(fill(faces(a, f))) = f
         end do
      end do
      allocate (ring_start(n_faces + 1), patch_start(n_faces + 1))
      allocate (ring_nodes(max(1, max_ring_nodes*n_faces)), patch_faces(4, max(1, 9*n_faces)))
      ring_start(1) = 0
      patch_start(1) = 0
      do f = 1, n_faces
         allocate (adjacent(0), ring(0))
         do a = 1, 4
            node = faces(a, f)
            do k = node_start(node) + 1, node_start(node + 1)
               if (all(adjacent /= node_faces(k))) adjacent = [adjacent, node_faces(k)]
            end do
         end do
         n_adjacent = size(adjacent)
         allocate (local(4, n_adjacent))
         do g = 1, n_adjacent
            do b = 1, 4
               node = faces(b, adjacent(g))
               position = findloc(faces(:, f), node, dim=1)
               if (position == 0) then
                  position = findloc(ring, node, dim=1)
                  if (position == 0) then
                     ring = [ring, node]
                     position = size(ring)
                  end if
                  position = 4 + position
               end if
               local(b, g) = position
            end do
         end do
         n_ring = size(ring)
         if (ring_start(f) + n_ring > size(ring_nodes)) then
            allocate (grown_ring(2*(ring_start(f) + n_ring)))
            grown_ring(:ring_start(f)) = ring_nodes(:ring_start(f))
            call move_alloc(grown_ring, ring_nodes)
         end if
         ring_nodes(ring_start(f) + 1:ring_start(f) + n_ring) = ring
         ring_start(f + 1) = ring_start(f) + n_ring
         if (patch_start(f) + n_adjacent > size(patch_faces, 2)) then
            allocate (grown(4, 2*(patch_start(f) + n_adjacent)))
            grown(:, :patch_start(f)) = patch_faces(:, :patch_start(f))
            call move_alloc(grown, patch_faces)
         end if
         patch_faces(:, patch_start(f) + 1:patch_start(f) + n_adjacent) = local
         patch_start(f + 1) = patch_start(f) + n_adjacent
         deallocate (adjacent, ring, local)
      end do
   end subroutine surface_patches

   !> The faces of a surface of HEX8 element faces, as (4, n) mesh node numbers in outward
   !> (HEX8 face) order.
   pure function surface_faces(mesh, surface) result(faces)
      type(mesh_t), intent(in) :: mesh
      type(surface_t), intent(in) :: surface
      integer :: faces(4, size(surface%elements))
      integer :: k
      do k = 1, size(surface%elements)
         faces(:, k) = mesh%connectivity(hex8_face_nodes(:, surface%faces(k)), surface%elements(k))
      end do
   end function surface_faces

   !> The master surface's largest smoothed-normal ring: its size and the face that has it
   !> (for the deck reader's check of NORMALS Smoothed against max_ring_nodes).
   subroutine largest_patch_ring(mesh, surface, n_ring, face_nodes)
      type(mesh_t), intent(in) :: mesh
      type(surface_t), intent(in) :: surface
      integer, intent(out) :: n_ring          !! ring nodes of that face
      integer, intent(out) :: face_nodes(4)   !! mesh node numbers of that face
      integer, allocatable :: faces(:, :), ring_start(:), ring_nodes(:), patch_start(:), patch_faces(:, :)
      integer :: f
      n_ring = 0
      face_nodes = 0
      if (size(surface%elements) == 0) return
      faces = surface_faces(mesh, surface)
      call surface_patches(mesh%n_nodes, faces, ring_start, ring_nodes, patch_start, patch_faces)
      f = largest_ring_face(ring_start)
      n_ring = ring_start(f + 1) - ring_start(f)
      face_nodes = faces(:, f)
   end subroutine largest_patch_ring

   !> Anchors of the reference configuration: every slave node starts with the closest point
   !> of its reference position on the master (its foot point on the plane, or on the nearest
   !> master face within the search band), so that friction acts from the first increment
   !> and a body held sideways only by friction is supported from the first iteration.
   subroutine initial_anchors(model, pass)
      type(model_t), intent(in) :: model
      type(contact_pass_t), intent(inout) :: pass
      real(dp), allocatable :: zero(:)
      real(dp) :: x_slave(3), normal(3), xi(2), jacobian(2, 2)
      logical :: fixed(2), converged
      integer :: i, f
      associate (pair => model%contact_pairs(pass%pair))
         if (pass%rigid) then
            normal = pair%plane_normal
            do i = 1, size(pass%slave_nodes)
               x_slave = model%mesh%coords(:, pass%slave_nodes(i))
               pass%anchor_point(:, i) = x_slave - dot_product(x_slave - pair%plane_point, normal)*normal
            end do
            pass%has_anchor = .true.
            return
         end if
      end associate
      allocate (zero(3*model%mesh%n_nodes), source=0.0_dp)
      call assign_faces(model, pass, zero)
      do i = 1, size(pass%slave_nodes)
         if (pass%face(i) == 0) cycle
         call closest_point_in_face(model%mesh%coords(:, pass%faces(:, pass%face(i))), &
                                    model%mesh%coords(:, pass%slave_nodes(i)), 0.0_dp, pass%anchor_xi(:, i), fixed)
         if (pass%smooth) then
            ! the point along the smoothed normal, when it lies on the face
            f = pass%face(i)
            call smooth_projection(model%mesh%coords(:, pass%faces(:, f)), face_nodal_normals(model, pass, zero, f), &
                                   model%mesh%coords(:, pass%slave_nodes(i)), xi, converged, jacobian)
            if (converged) then
               if (face_contains(xi, model%contact_pairs(pass%pair)%parameters%edge_tolerance)) &
                  pass%anchor_xi(:, i) = xi
            end if
         end if
         pass%anchor_face(i) = pass%face(i)
         pass%has_anchor(i) = .true.
      end do
   end subroutine initial_anchors

   !> Assign master faces at displacements u and make sure the sparse pattern holds every
   !> (slave node, master face node) block; the pattern is rebuilt (a new symbolic analysis
   !> follows) only when a block is missing.
   subroutine search_contact(model, system, u, matrix, error)
      type(model_t), intent(in) :: model
      type(contact_system_t), intent(inout) :: system
      real(dp), intent(in) :: u(:)
      type(sparse_matrix_t), intent(inout) :: matrix
      type(error_t), allocatable, intent(out) :: error
      integer :: p, i, a, b, n_nodes, nodes(max_kernel_nodes), first_ring
      logical :: missing

      missing = .false.
      do p = 1, size(system%passes)
         if (system%passes(p)%rigid) cycle
         call assign_faces(model, system%passes(p), u)
         associate (pass => system%passes(p))
            do i = 1, size(pass%slave_nodes)
               if (pass%face(i) == 0) cycle
               call kernel_nodes(pass, i, nodes, n_nodes, first_ring)
               ! the pairs that can be missing: the slave with every other node, and the
               ! contact face's nodes with the anchor face's and the ring's (those within a
               ! face share an element)
               do a = 1, merge(5, 1, n_nodes > 5)
                  do b = max(a + 1, merge(2, 6, a == 1)), n_nodes
                     if (matrix%neighbour_index(nodes(a), nodes(b)) == 0) then
                        call add_extra_pair(system, nodes(a), nodes(b))
                        missing = .true.
                     end if
                  end do
               end do
            end do
         end associate
      end do
      if (missing) then
         call matrix%create_node_block_pattern(model%mesh%n_nodes, model%mesh%connectivity, &
                                               system%extra_pairs(:, :system%n_extra), error=error)
         if (allocated(error)) error%message = 'contact: rebuilding the sparse pattern: '//error%message
      end if
   end subroutine search_contact

   subroutine add_extra_pair(system, first, second)
      type(contact_system_t), intent(inout) :: system
      integer, intent(in) :: first, second
      integer, allocatable :: grown(:, :)
      if (system%n_extra == size(system%extra_pairs, 2)) then
         allocate (grown(2, max(64, 2*system%n_extra)))
         grown(:, :system%n_extra) = system%extra_pairs(:, :system%n_extra)
         call move_alloc(grown, system%extra_pairs)
      end if
      system%n_extra = system%n_extra + 1
      system%extra_pairs(:, system%n_extra) = [first, second]
   end subroutine add_extra_pair

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
         n_nodes = n_nodes + pass%ring_start(f + 1) - pass%ring_start(f)
         nodes(first_ring:n_nodes) = pass%ring_nodes(pass%ring_start(f) + 1:pass%ring_start(f + 1))
      end if
   end subroutine kernel_nodes

   !> The nearest master face of every slave node of a deformable pass (bucket grid search).
   subroutine assign_faces(model, pass, u)
      type(model_t), intent(in) :: model
      type(contact_pass_t), intent(inout) :: pass
      real(dp), intent(in) :: u(:)
      real(dp), allocatable :: lower(:, :), upper(:, :), node_normal(:, :)
      integer, allocatable :: cell_start(:), cell_faces(:), counts(:)
      real(dp) :: origin(3), cell_size, x_face(3, 4), x_slave(3), xi(2), distance, best
      real(dp) :: gap, closest(3), best_inside
      integer :: n_cells(3), f, i, c, k, best_face, cell(3), best_inside_face
      logical :: fixed(2), inside

      associate (faces => pass%faces)
         if (size(faces, 2) == 0) then
            pass%face = 0
            return
         end if
         allocate (lower(3, size(faces, 2)), upper(3, size(faces, 2)))
         do f = 1, size(faces, 2)
            x_face = current_face(model, u, faces(:, f))
            lower(:, f) = minval(x_face, dim=2) - pass%band
            upper(:, f) = maxval(x_face, dim=2) + pass%band
         end do
         origin = minval(lower, dim=2)
         cell_size = max(maxval(upper - lower), maxval(maxval(upper, dim=2) - origin)/200, tiny(1.0_dp))
         n_cells = max(1, min(ceiling((maxval(upper, dim=2) - origin)/cell_size), 200))
         ! faces per cell as compressed rows: count, prefix sums, fill
         allocate (counts(product(n_cells)), source=0)
         do f = 1, size(faces, 2)
            call visit_cells(f, .false.)
         end do
         allocate (cell_start(product(n_cells) + 1))
         cell_start(1) = 0
         do c = 1, product(n_cells)
            cell_start(c + 1) = cell_start(c) + counts(c)
         end do
         allocate (cell_faces(cell_start(product(n_cells) + 1)))
         counts = cell_start(:product(n_cells))
         do f = 1, size(faces, 2)
            call visit_cells(f, .true.)
         end do
         if (pass%smooth) then
            ! the averaged normal of every master node, once per search
            allocate (node_normal(3, model%mesh%n_nodes), source=0.0_dp)
            do f = 1, size(faces, 2)
               node_normal(:, faces(:, f)) = face_nodal_normals(model, pass, u, f)
            end do
         end if

         do i = 1, size(pass%slave_nodes)
            x_slave = model%mesh%coords(:, pass%slave_nodes(i)) + &
                      u(3*pass%slave_nodes(i) - 2:3*pass%slave_nodes(i))
            best = 0.5_dp*huge(1.0_dp)   ! best*(1 + tie_tolerance) must not overflow
            best_face = 0
            best_inside = best
            best_inside_face = 0
            cell = cell_of(x_slave)
            if (all(x_slave >= origin) .and. all(x_slave <= origin + n_cells*cell_size)) then
               c = cell(1) + n_cells(1)*((cell(2) - 1) + n_cells(2)*(cell(3) - 1))
               do k = cell_start(c) + 1, cell_start(c + 1)
                  f = cell_faces(k)
                  if (any(x_slave < lower(:, f)) .or. any(x_slave > upper(:, f))) cycle
                  x_face = current_face(model, u, faces(:, f))
                  if (pass%smooth) then
                     call smooth_candidate(f, x_face, x_slave, distance, gap, inside)
                     if (inside .and. gap <= pass%band) &
                        call keep_nearer(f, distance, pass%face(i), best_inside, best_inside_face)
                  end if
                  call closest_point_in_face(x_face, x_slave, 0.0_dp, xi, fixed)
                  closest = face_position(x_face, xi)
                  distance = norm2(x_slave - closest)
                  gap = dot_product(x_slave - closest, face_normal(x_face, xi))
                  if (gap > pass%band) cycle
                  call keep_nearer(f, distance, pass%face(i), best, best_face)
               end do
            end if
            ! smoothed normals: the nearest face whose normal projection lies inside it, else
            ! (beyond a free edge of the master surface, or no projection) the nearest face
            pass%face(i) = merge(best_inside_face, best_face, best_inside_face > 0)
         end do
      end associate
   contains
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

      !> Face f's normal projection along the smoothed normals: distance, gap, inside the face.
      subroutine smooth_candidate(f, x_face, x_slave, distance, gap, inside)
         integer, intent(in) :: f
         real(dp), intent(in) :: x_face(3, 4), x_slave(3)
         real(dp), intent(out) :: distance, gap
         logical, intent(out) :: inside
         real(dp) :: nodal(3, 4), xi(2), jacobian(2, 2), offset(3)
         logical :: converged
         nodal = node_normal(:, pass%faces(:, f))
         call smooth_projection(x_face, nodal, x_slave, xi, converged, jacobian)
         inside = converged
         if (converged) inside = face_contains(xi, model%contact_pairs(pass%pair)%parameters%edge_tolerance)
         distance = huge(1.0_dp)
         gap = huge(1.0_dp)
         if (.not. inside) return
         offset = x_slave - face_position(x_face, xi)
         distance = norm2(offset)
         gap = dot_product(offset, smooth_normal_at(nodal, xi))
      end subroutine smooth_candidate

      !> Count face f in every cell its box covers, or (fill) also store it there.
      subroutine visit_cells(f, fill)
         integer, intent(in) :: f
         logical, intent(in) :: fill
         integer :: lo(3), hi(3), ix, iy, iz, c
         lo = cell_of(lower(:, f))
         hi = cell_of(upper(:, f))
         do iz = lo(3), hi(3)
            do iy = lo(2), hi(2)
               do ix = lo(1), hi(1)
                  c = ix + n_cells(1)*((iy - 1) + n_cells(2)*(iz - 1))
                  counts(c) = counts(c) + 1
                  if (fill) cell_faces(counts(c)) = f
               end do
            end do
         end do
      end subroutine visit_cells

      pure function cell_of(point) result(index3)
         real(dp), intent(in) :: point(3)
         integer :: index3(3)
         real(dp) :: position(3)
         ! clamped before the conversion, which is undefined for reals beyond the integers
         position = min(real(n_cells, dp), max(1.0_dp, (point - origin)/cell_size + 1.0_dp))
         index3 = int(position)
      end function cell_of
   end subroutine assign_faces

   !> The averaged nodal normals of master face f's 4 nodes at displacements u (the kernel's
   !> patch_normals over the face's patch).
   pure function face_nodal_normals(model, pass, u, f) result(nodal)
      type(model_t), intent(in) :: model
      type(contact_pass_t), intent(in) :: pass
      real(dp), intent(in) :: u(:)
      integer, intent(in) :: f
      real(dp) :: nodal(3, 4)
      nodal = patch_normals(current_face(model, u, pass%faces(:, f)), &
                            current_nodes(model, u, pass%ring_nodes(pass%ring_start(f) + 1:pass%ring_start(f + 1))), &
                            pass%patch_faces(:, pass%patch_start(f) + 1:pass%patch_start(f + 1)))
   end function face_nodal_normals

   !> Current coordinates of nodes.
   pure function current_nodes(model, u, nodes) result(x)
      type(model_t), intent(in) :: model
      real(dp), intent(in) :: u(:)
      integer, intent(in) :: nodes(:)
      real(dp) :: x(3, size(nodes))
      integer :: a
      do a = 1, size(nodes)
         x(:, a) = model%mesh%coords(:, nodes(a)) + u(3*nodes(a) - 2:3*nodes(a))
      end do
   end function current_nodes

   !> Current coordinates of the 4 nodes of a face.
   pure function current_face(model, u, nodes) result(x_face)
      type(model_t), intent(in) :: model
      real(dp), intent(in) :: u(:)
      integer, intent(in) :: nodes(4)
      real(dp) :: x_face(3, 4)
      x_face = current_nodes(model, u, nodes)
   end function current_face

   !> Add the contact contributions at u to fint and (if present) to the tangent matrix.
   subroutine assemble_contact(model, system, u, fint, matrix, predictor)
      type(model_t), intent(in) :: model
      type(contact_system_t), intent(inout) :: system
      real(dp), intent(in) :: u(:)
      real(dp), intent(inout) :: fint(:)
      type(sparse_matrix_t), intent(inout), optional :: matrix
      logical, intent(in), optional :: predictor  !! first iteration of an increment: add the touching stiffness
      real(dp) :: x_slave(3), x_face(3, 4), force(3*max_kernel_nodes), tangent(3*max_kernel_nodes, 3*max_kernel_nodes)
      real(dp) :: force3(3), tangent3(3, 3), shape(4), d_xi(4), d_eta(4)
      ! absent (unallocated) unless the node's anchor lies on another face / normals are smoothed
      real(dp), allocatable :: x_anchor_face(:, :), x_ring(:, :)
      integer, allocatable :: patch(:, :)
      integer :: p, i, a, slave, nodes(max_kernel_nodes), n_nodes, n, node, attempt, first_ring, f
      real(dp) :: touch_normal, touch_tangential
      logical :: touching_stiffness

      touching_stiffness = .false.
      if (present(predictor)) touching_stiffness = predictor
      do p = 1, size(system%passes)
         associate (pass => system%passes(p), pair => model%contact_pairs(system%passes(p)%pair))
            touch_normal = pair%parameters%normal_penalty
            touch_tangential = 0.0_dp
            if (.not. pair%parameters%friction%frictionless()) &
               touch_tangential = pair%parameters%tangential_penalty
            do i = 1, size(pass%slave_nodes)
               slave = pass%slave_nodes(i)
               x_slave = model%mesh%coords(:, slave) + u(3*slave - 2:3*slave)
               if (pass%rigid) then
                  do attempt = 1, 2
                     call node_plane_contact(pair%parameters, x_slave, pair%plane_point, pair%plane_normal, &
                                             pass%area(i), pass%anchor_point(:, i), pass%has_anchor(i), &
                                             pass%result(i), force3, tangent3, branch=pass%branch(i), &
                                             friction_scale=system%friction_scale)
                     if (.not. present(matrix)) exit
                     if (.not. slip_reversed(pass, i)) exit
                  end do
                  if (touching_stiffness .and. pass%result(i)%status == contact_open .and. &
                      pass%result(i)%gap <= pair%parameters%gap_tolerance) then
                     call add_touching_stiffness(pass%area(i), touch_normal, touch_tangential, &
                                                 pair%plane_normal, [1.0_dp], tangent3)
                  end if
                  fint(3*slave - 2:3*slave) = fint(3*slave - 2:3*slave) + force3
                  if (present(matrix)) call matrix%add_element([slave], tangent3)
                  cycle
               end if
               if (pass%face(i) == 0) then
                  pass%result(i) = contact_point_result_t()
                  pass%result(i)%gap = huge(1.0_dp)
                  cycle
               end if
               call kernel_nodes(pass, i, nodes, n_nodes, first_ring)
               n = 3*n_nodes
               x_face = current_face(model, u, nodes(2:5))
               if (first_ring == 10) x_anchor_face = current_face(model, u, nodes(6:9))
               if (pass%smooth) then
                  f = pass%face(i)
                  x_ring = current_nodes(model, u, nodes(first_ring:n_nodes))
                  patch = pass%patch_faces(:, pass%patch_start(f) + 1:pass%patch_start(f + 1))
               end if
               do attempt = 1, 2
                  ! x_anchor_face: the node moved off its anchor's face, the anchor stays a point of that face
                  call node_face_contact(pair%parameters, x_slave, x_face, pass%area(i), pass%anchor_xi(:, i), &
                                         pass%has_anchor(i), .true., pass%result(i), force(:n), tangent(:n, :n), &
                                         x_anchor_face=x_anchor_face, branch=pass%branch(i), &
                                         friction_scale=system%friction_scale, x_ring=x_ring, patch_faces=patch)
                  if (.not. present(matrix)) exit
                  if (.not. slip_reversed(pass, i)) exit
               end do
               if (touching_stiffness .and. pass%result(i)%status == contact_open .and. &
                   pass%result(i)%gap >= 0.0_dp .and. pass%result(i)%gap <= pair%parameters%gap_tolerance) then
                  call face_shape_functions(pass%result(i)%xi, shape, d_xi, d_eta)
                  call add_touching_stiffness(pass%area(i), touch_normal, touch_tangential, &
                                              face_normal(x_face, pass%result(i)%xi), [1.0_dp, -shape], tangent(:15, :15))
               end if
               do a = 1, 5
                  node = nodes(a)
                  fint(3*node - 2:3*node) = fint(3*node - 2:3*node) + force(3*a - 2:3*a)
               end do
               if (present(matrix)) call matrix%add_element(nodes(:n_nodes), tangent(:n, :n))
               if (allocated(x_anchor_face)) deallocate (x_anchor_face)
               if (allocated(x_ring)) deallocate (x_ring, patch)
            end do
         end associate
      end do
   end subroutine assemble_contact

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

   !> Touching stiffness (no force): D = A (eps_N n n + eps_T (I - n n)) acting on the gap of
   !> the slave node relative to its contact point, K_ab += c_a c_b D over the kernel's nodes with
   !> c = [1, -N_1, ..., -N_4] on a master face, [1] against a rigid plane (force/length).
   pure subroutine add_touching_stiffness(area, normal_penalty, tangential_penalty, normal, weights, tangent)
      real(dp), intent(in) :: area, normal_penalty, tangential_penalty
      real(dp), intent(in) :: normal(3)       !! unit normal n
      real(dp), intent(in) :: weights(:)      !! c_a per node of the kernel
      real(dp), intent(inout) :: tangent(:, :)  !! (3 size(weights), 3 size(weights))
      real(dp) :: block(3, 3)
      integer :: a, b, k
      do k = 1, 3
         block(:, k) = area*(normal_penalty - tangential_penalty)*normal*normal(k)
         block(k, k) = block(k, k) + area*tangential_penalty
      end do
      do b = 1, size(weights)
         do a = 1, size(weights)
            tangent(3*a - 2:3*a, 3*b - 2:3*b) = tangent(3*a - 2:3*a, 3*b - 2:3*b) + weights(a)*weights(b)*block
         end do
      end do
   end subroutine add_touching_stiffness

   !> Accept the current contact state as converged: anchors and accumulated slip.
   subroutine commit_contact(system)
      type(contact_system_t), intent(inout) :: system
      integer :: p, i
      do p = 1, size(system%passes)
         associate (pass => system%passes(p))
            do i = 1, size(pass%slave_nodes)
               if (pass%face(i) == 0) then
                  pass%has_anchor(i) = .false.
                  cycle
               end if
               pass%has_anchor(i) = .true.
               pass%slip(i) = pass%slip(i) + pass%result(i)%slip_increment
               if (pass%rigid) then
                  pass%anchor_point(:, i) = pass%result(i)%new_anchor
               else
                  pass%anchor_face(i) = pass%face(i)
                  pass%anchor_xi(:, i) = pass%result(i)%new_anchor_xi
               end if
            end do
         end associate
      end do
   end subroutine commit_contact

   !> Start of an increment: the friction law decides every node's branch again.
   subroutine reset_friction_branches(system)
      type(contact_system_t), intent(inout) :: system
      integer :: p
      do p = 1, size(system%passes)
         system%passes(p)%branch = branch_free
         system%passes(p)%released = .false.
         system%passes(p)%slipped = .false.
      end do
   end subroutine reset_friction_branches

   !> At a converged iterate: the nodes held in stick after a slip reversal whose trial
   !> traction lies outside the friction cone (the law chooses slip) are handed back to the
   !> law for the rest of the increment. Returns how many: 0 means the iterate solves the
   !> true problem.
   integer function release_inconsistent_branches(system) result(n_released)
      type(contact_system_t), intent(inout) :: system
      integer :: p, i
      n_released = 0
      do p = 1, size(system%passes)
         associate (pass => system%passes(p))
            do i = 1, size(pass%slave_nodes)
               if (pass%branch(i) == branch_free .or. pass%result(i)%status == contact_open) cycle
               if (pass%result(i)%status == pass%result(i)%law_status) cycle
               pass%branch(i) = branch_free
               pass%released(i) = .true.
               n_released = n_released + 1
            end do
         end associate
      end do
   end function release_inconsistent_branches

   !> Slave nodes in contact (stick or slip) and slipping, over all passes.
   subroutine contact_counts(system, n_active, n_slipping)
      type(contact_system_t), intent(in) :: system
      integer, intent(out) :: n_active, n_slipping
      integer :: p
      n_active = 0
      n_slipping = 0
      do p = 1, size(system%passes)
         n_active = n_active + count(system%passes(p)%result%status /= contact_open)
         n_slipping = n_slipping + count(system%passes(p)%result%status == contact_slip)
      end do
   end subroutine contact_counts

   !> Nodal fields for output: pressure p_N (force/area), tangential traction (3), gap,
   !> status (0 open, 1 stick, 2 slip; -1 not a slave node), accumulated slip. Where a node is
   !> a slave of several passes, the pass with the larger pressure wins.
   subroutine contact_nodal_fields(system, n_nodes, pressure, traction, gap, status, slip)
      type(contact_system_t), intent(in) :: system
      integer, intent(in) :: n_nodes
      real(dp), allocatable, intent(out) :: pressure(:), traction(:, :), gap(:), status(:), slip(:)
      integer :: p, i, node
      allocate (pressure(n_nodes), gap(n_nodes), slip(n_nodes), source=0.0_dp)
      allocate (traction(3, n_nodes), source=0.0_dp)
      allocate (status(n_nodes), source=-1.0_dp)
      do p = 1, size(system%passes)
         associate (pass => system%passes(p))
            do i = 1, size(pass%slave_nodes)
               node = pass%slave_nodes(i)
               if (status(node) >= 0.0_dp .and. pressure(node) >= pass%result(i)%pressure) cycle
               pressure(node) = pass%result(i)%pressure
               traction(:, node) = pass%result(i)%traction
               gap(node) = merge(pass%result(i)%gap, 0.0_dp, pass%face(i) > 0)
               status(node) = real(pass%result(i)%status, dp)
               slip(node) = pass%slip(i)
            end do
         end associate
      end do
   end subroutine contact_nodal_fields

   !> The slave nodes of pass `p` and, per node, the columns of `contact_table_labels`: gap
   !> (length; 0 for a node with no master face), pressure, tangential traction x y z
   !> (force/area), accumulated slip (length) and status (0 open, 1 stick, 2 slip).
   !> `pair` is the deck id of the pass's contact pair.
   subroutine contact_pass_table(system, p, pair_index, nodes, values)
      type(contact_system_t), intent(in) :: system
      integer, intent(in) :: p
      integer, intent(out) :: pair_index
      integer, allocatable, intent(out) :: nodes(:)
      real(dp), allocatable, intent(out) :: values(:, :)
      integer :: i
      associate (pass => system%passes(p))
         pair_index = pass%pair
         nodes = pass%slave_nodes
         allocate (values(7, size(nodes)))
         do i = 1, size(nodes)
            values(1, i) = merge(pass%result(i)%gap, 0.0_dp, pass%face(i) > 0)
            values(2, i) = pass%result(i)%pressure
            values(3:5, i) = pass%result(i)%traction
            values(6, i) = pass%slip(i)
            values(7, i) = real(pass%result(i)%status, dp)
         end do
      end associate
   end subroutine contact_pass_table

   !> The committed slip history of pass p as a real table (contact_history_rows, n_slave) for
   !> restart files: anchor face, anchor face coordinates (2), anchor point (3, rigid plane),
   !> has-anchor flag (0/1), accumulated slip.
   subroutine get_contact_history(system, p, values)
      type(contact_system_t), intent(in) :: system
      integer, intent(in) :: p
      real(dp), allocatable, intent(out) :: values(:, :)
      associate (pass => system%passes(p))
         allocate (values(contact_history_rows, size(pass%slave_nodes)))
         values(1, :) = real(pass%anchor_face, dp)
         values(2:3, :) = pass%anchor_xi
         values(4:6, :) = pass%anchor_point
         values(7, :) = merge(1.0_dp, 0.0_dp, pass%has_anchor)
         values(8, :) = pass%slip
      end associate
   end subroutine get_contact_history

   !> Restore what get_contact_history stored.
   subroutine set_contact_history(system, p, values)
      type(contact_system_t), intent(inout) :: system
      integer, intent(in) :: p
      real(dp), intent(in) :: values(:, :)
      associate (pass => system%passes(p))
         pass%anchor_face = nint(values(1, :))
         pass%anchor_xi = values(2:3, :)
         pass%anchor_point = values(4:6, :)
         pass%has_anchor = values(7, :) > 0.5_dp
         pass%slip = values(8, :)
      end associate
   end subroutine set_contact_history
end module frix_contact_assembly
