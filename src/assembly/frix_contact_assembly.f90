!> Contact in the global system: the contact passes of the model's contact pairs, the
!> assembly of the node-to-segment contributions of src/contact/frix_contact_kernel.f90 into
!> the internal force and the sparse tangent, and the slip history of every slave node
!> (commit, friction branches, output tables, restart). The search itself (which master face
!> each slave node touches) and the smoothed-normal patches are the contact library's
!> (frix_contact_search, frix_contact_patches; docs/contact.md); search_contact runs it and
!> extends the sparse pattern by the blocks the kernels need.
!>
!> Each contact pair of the deck gives one pass (slave nodes against master faces or a rigid
!> plane); PASSES 2 adds the reverse pass (the master's nodes against the slave's faces).
!> Touching nodes (0 <= g <= GAPTOL) carry no force but get the stiffness
!> A (k_N n n + eps_T (I - n n)) (k_N the normal law's stiffness per unit area, eps_N for the
!> penalty law; eps_T only with friction; split on the master nodes by N_a) in the predictor,
!> the first iteration of each increment, so that bodies that touch without load, as at the
!> start of an analysis, are supported, also sideways by friction.
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
   use frix_model, only: model_t
   use frix_mesh, only: surface_t
   use frix_system_matrix, only: system_matrix_t
   use frix_face_projection, only: face_normal, face_shape_functions
   use frix_contact_kernel, only: contact_point_result_t, node_face_contact, node_plane_contact, &
                                  contact_open, contact_slip, add_touching_stiffness
   use frix_contact_patches, only: surface_patches, check_patch_rings, patch_faces_of, surface_faces, &
                                   surface_is_curved, all_faces_angle
   use frix_contact_parameters, only: contact_parameters_t
   use frix_contact_pass, only: contact_pass_t, max_kernel_nodes, set_slave_nodes, set_master_faces, &
                                start_pass_state, kernel_nodes, slip_reversed, set_plane_master_faces, &
                                pass_positions, pass_node, pass_coordinates, plane_edges
   use frix_contact_search, only: assign_faces, initial_anchors, plane_anchors
   use frix_tie_pass, only: setup_tie
   use frix_mortar_assembly, only: search_mortar_pass, assemble_mortar_pass, commit_mortar_pass, restart_mortar_pass
   use frix_tie_constraints, only: check_tie_nodes
   use frix_strings, only: to_string
   use frix_friction_law, only: branch_free
   implicit none
   private

   public :: contact_system_t, setup_contact, search_contact, assemble_contact, commit_contact
   public :: contact_counts, contact_nodal_fields, contact_pass_table, contact_table_labels, contact_resultant
   public :: contact_history_rows, get_contact_history, set_contact_history, restart_mortar_rows
   public :: reset_friction_branches, release_inconsistent_branches
   public :: check_ties, add_pattern_pairs, contact_gaps

   type :: contact_system_t
      type(contact_pass_t), allocatable :: passes(:)
      integer, allocatable :: extra_pairs(:, :)   !! (2, n) node pairs added to the sparse pattern
      integer :: n_extra = 0
      !> the master nodes of each node with eliminated constraint rows (ties, couplings):
      !> constraint_masters(constraint_first(a)+1:constraint_first(a+1)); unallocated without
      !> such rows. A pair that the search adds at such a node brings the pairs of its masters.
      integer, allocatable :: constraint_first(:), constraint_masters(:)
      logical :: frictional = .false.             !! some pair has friction
      logical :: tied = .false.                   !! some pair is a TIE (frix_tie_constraints)
      !> friction or smoothed normals: the contact tangent is unsymmetric
      logical :: unsymmetric = .false.
      !> the tangent of the last assembly holds a node clamped onto an edge of its face whose
      !> tangent is unsymmetric beyond round-off (function unsymmetric): the gap of a clamped
      !> closest point is not a distance, so even a frictionless facet pass is then
      !> unsymmetric (docs/contact.md, "Edges and corners")
      logical :: clamped_unsymmetric = .false.
      !> factor on the pressure every friction law sees, i.e. on mu for Coulomb; 1 except in
      !> the stages of the driver's friction continuation
      real(dp) :: friction_scale = 1.0_dp
   end type contact_system_t

   !> Columns of `contact_pass_table` (listing, CSV): the traction is tangential to the normal
   !> NORMAL_X/Y/Z that was used (unit, out of the master body; facet, smoothed or the plane's).
   character(len=*), parameter :: contact_table_labels(10) = [character(len=10) :: 'GAP', 'PRESSURE', &
                                                               'TRACTION_X', 'TRACTION_Y', 'TRACTION_Z', &
                                                               'SLIP', 'STATUS', 'NORMAL_X', 'NORMAL_Y', &
                                                               'NORMAL_Z']

   integer, parameter :: contact_history_rows = 8  !! rows of get_contact_history

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
               call pair_passes(model%mesh%n_nodes, k - 1, k, system%passes)
            end if
            if (pair%tied) then
               system%tied = .true.
               cycle
            end if
            if (.not. pair%parameters%friction%frictionless()) system%frictional = .true.
            call check_penalties_set(pair%id, pair%parameters, error)
            if (allocated(error)) return
         end associate
      end do
      system%unsymmetric = system%frictional .or. any(system%passes%smooth)
      ! the ties' checks (the node pairs their elimination needs: the Newton solver's
      ! constraint equations, add_pattern_pairs)
      if (system%tied) call check_tie_nodes(model%mesh, system%passes, model%contact_pairs(system%passes%pair)%id, &
                                            error)
   end subroutine setup_contact

   !> An automatic penalty (a pair without EPSN or EPST) is set by the deck reader before the
   !> analysis (frix_deck_contact); one still 0 here is an error, not a penalty of 0.
   subroutine check_penalties_set(id, parameters, error)
      integer, intent(in) :: id   !! the pair's id
      type(contact_parameters_t), intent(in) :: parameters
      type(error_t), allocatable, intent(out) :: error
      logical :: unset
      unset = parameters%normal%automatic_penalty .and. .not. parameters%normal%penalty() > 0.0_dp
      unset = unset .or. (parameters%automatic_tangential_penalty .and. .not. parameters%tangential_penalty > 0.0_dp)
      if (unset) call fatal_error(error, 'contact pair '//to_string(id)//': its automatic penalty was not set')
   end subroutine check_penalties_set

   !> The checks of frix_tie_constraints on the ties of `model` alone, as the deck reader runs
   !> them: `error` and `pair`, the index of the contact pair (TIE) it is about.
   subroutine check_ties(model, pair, error)
      type(model_t), intent(in) :: model
      integer, intent(out) :: pair
      type(error_t), allocatable, intent(out) :: error
      type(contact_pass_t), allocatable :: passes(:)
      integer :: p, k, culprit
      pair = 0
      allocate (passes(count(model%contact_pairs%tied)))
      k = 0
      do p = 1, size(model%contact_pairs)
         if (.not. model%contact_pairs(p)%tied) cycle
         k = k + 1
         call setup_pass(model, p, model%contact_pairs(p)%slave_surface, model%contact_pairs(p)%master_surface, &
                         passes(k), error)
         if (allocated(error)) then
            pair = p
            return
         end if
      end do
      if (k == 0) return
      call check_tie_nodes(model%mesh, passes, model%contact_pairs(passes%pair)%id, error, culprit)
      if (culprit > 0) pair = passes(culprit)%pair
   end subroutine check_ties

   !> The eliminated constraint equations (frix_constraint_equations): the node pairs their
   !> elimination needs, kept among the extra pairs of every sparse pattern the contact search
   !> builds, and the master nodes of each constrained node (`first`, `masters`), with which
   !> every pair the search adds later at a constrained node brings the pairs of its masters.
   subroutine add_pattern_pairs(system, pairs, first, masters)
      type(contact_system_t), intent(inout) :: system
      integer, intent(in) :: pairs(:, :)   !! (2, n)
      integer, intent(in) :: first(:), masters(:)
      integer :: k
      do k = 1, size(pairs, 2)
         call add_extra_pair(system, pairs(1, k), pairs(2, k))
      end do
      if (size(masters) == 0) return
      system%constraint_first = first
      system%constraint_masters = masters
   end subroutine add_pattern_pairs

   !> The pair (first, second) and, where either node has constraint rows, the pairs of its
   !> masters with the other node and its masters (the elimination moves the constrained
   !> node's row and column onto its masters').
   subroutine add_contact_pair(system, first, second)
      type(contact_system_t), intent(inout) :: system
      integer, intent(in) :: first, second
      integer :: i, j
      call add_extra_pair(system, first, second)
      if (.not. allocated(system%constraint_first)) return
      associate (f => system%constraint_first, m => system%constraint_masters)
         do i = f(first) + 1, f(first + 1)
            call add_extra_pair(system, m(i), second)
            do j = f(second) + 1, f(second + 1)
               call add_extra_pair(system, m(i), m(j))
            end do
         end do
         do j = f(second) + 1, f(second + 1)
            call add_extra_pair(system, first, m(j))
         end do
      end associate
   end subroutine add_contact_pair

   !> Whether a pass's master surface gets smoothed normals: NORMALS Smoothed always, NORMALS
   !> Auto where the surface is curved (frix_contact_patches' surface_is_curved).
   logical function smoothed_master(coords, faces, parameters) result(smoothed)
      real(dp), intent(in) :: coords(:, :)
      integer, intent(in) :: faces(:, :)
      type(contact_parameters_t), intent(in) :: parameters
      smoothed = parameters%smoothed_normals
      if (smoothed .and. parameters%feature_angle < all_faces_angle) &
         smoothed = surface_is_curved(coords, faces, parameters%feature_angle)
   end function smoothed_master

   !> The two passes first and second of a PASSES 2 pair know each other and where the mesh's
   !> nodes are among their slave nodes (for the interface force, interface_traction).
   subroutine pair_passes(n_nodes, first, second, passes)
      integer, intent(in) :: n_nodes, first, second
      type(contact_pass_t), intent(inout) :: passes(:)
      integer :: p, i
      passes(first)%partner = second
      passes(second)%partner = first
      do p = first, second
         allocate (passes(p)%slave_index(n_nodes), source=0)
         do i = 1, size(passes(p)%slave_nodes)
            passes(p)%slave_index(passes(p)%slave_nodes(i)) = i
         end do
         allocate (passes(p)%interface_force(3, size(passes(p)%slave_nodes)), source=0.0_dp)
      end do
   end subroutine pair_passes

   !> The tributary areas of the nodes of each face of a surface, integral of N_a dA0 over the
   !> reference face, by the face's element (element_t%face_weights: a HEX8 face, or an edge
   !> of a plane element with its thickness or 2 pi r), (face nodes, faces).
   function surface_face_weights(model, surface) result(weights)
      type(model_t), intent(in) :: model
      type(surface_t), intent(in) :: surface
      real(dp), allocatable :: weights(:, :)
      integer, allocatable :: nodes(:)
      integer :: k, e
      allocate (weights(4, size(surface%elements)), source=0.0_dp)
      do k = 1, size(surface%elements)
         e = surface%elements(k)
         nodes = model%mesh%face_nodes(e, surface%faces(k))
         associate (element => model%blocks(model%mesh%element_block(e))%element%formulation)
            call element%face_weights(model%mesh%cells(model%mesh%face_cell_of(e))%cell, model%mesh%coords(:, nodes), &
                                      weights(:, k))
         end associate
      end do
   end function surface_face_weights

   !> Pass `pair` of the model (slave_surface against master_surface, 0 for the pair's rigid
   !> plane): slave nodes, master faces, search band, patches, initial anchors.
   subroutine setup_pass(model, pair, slave_surface, master_surface, pass, error)
      type(model_t), intent(in) :: model
      integer, intent(in) :: pair, slave_surface, master_surface
      type(contact_pass_t), intent(out) :: pass
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: coords(:, :)

      pass%pair = pair
      pass%rigid = master_surface == 0
      call set_slave_nodes(model%mesh, model%mesh%surfaces(slave_surface), &
                           surface_face_weights(model, model%mesh%surfaces(slave_surface)), pass)
      associate (contact_pair => model%contact_pairs(pair))
         if (contact_pair%tied) then
            call set_master_faces(model%mesh, model%mesh%surfaces(master_surface), pass)
            call start_pass_state(pass)
            call setup_tie(model%mesh%coords, surface_faces(model%mesh, model%mesh%surfaces(slave_surface)), &
                           contact_pair%tie_tolerance, pass)
            return
         end if
         if (contact_pair%mortar) then
            call set_master_faces(model%mesh, model%mesh%surfaces(master_surface), pass)
            pass%mortar = .true.
            pass%slave_faces = surface_faces(model%mesh, model%mesh%surfaces(slave_surface))
            pass%band = max(pass%band, contact_pair%parameters%gap_tolerance)
            call start_pass_state(pass)
            call restart_mortar_pass(model, pass, spread(0.0_dp, 1, 3*model%mesh%n_nodes), .false.)
            return
         end if
         if (pass%rigid) then
            allocate (pass%faces(4, 0))
         else
            if (plane_edges(model%mesh, model%mesh%surfaces(master_surface))) then
               call set_plane_master_faces(model%mesh, model%mesh%surfaces(master_surface), pass)
            else
               call set_master_faces(model%mesh, model%mesh%surfaces(master_surface), pass)
            end if
            coords = pass_coordinates(pass, model%mesh%coords)
            if (smoothed_master(coords, pass%faces, contact_pair%parameters)) then
               call surface_patches(coords, pass%faces, contact_pair%parameters%feature_angle, pass%patches)
               pass%smooth = .true.
               call check_patch_rings(pass%patches, error)
               if (allocated(error)) then
                  error%message = 'contact pair '//to_string(contact_pair%id)//': '//error%message
                  return
               end if
            end if
         end if
         pass%band = max(pass%band, contact_pair%parameters%gap_tolerance)
         call start_pass_state(pass)
         if (pass%rigid) then
            pass%face = 1   ! every slave node faces the plane
            call plane_anchors(model%mesh%coords, contact_pair%plane_point, contact_pair%plane_normal, pass)
         else
            call initial_anchors(model%mesh%coords, contact_pair%parameters%edge_tolerance, pass)
         end if
      end associate
   end subroutine setup_pass

   !> Assign master faces at displacements u and make sure the sparse pattern holds every
   !> (slave node, master face node) block; the pattern is rebuilt (a new symbolic analysis
   !> follows) only when a block is missing.
   subroutine search_contact(model, system, u, matrix, error)
      type(model_t), intent(in) :: model
      type(contact_system_t), intent(inout) :: system
      real(dp), intent(in) :: u(:)
      class(system_matrix_t), intent(inout) :: matrix
      type(error_t), allocatable, intent(out) :: error
      integer :: p, i, a, b, n_nodes, nodes(max_kernel_nodes), first_ring, n_pairs
      integer, allocatable :: pairs(:, :)
      logical :: missing

      missing = .false.
      do p = 1, size(system%passes)
         if (system%passes(p)%mortar) then
            call search_mortar_pass(model, system%passes(p), &
                                    .not. model%contact_pairs(system%passes(p)%pair)%parameters%friction%frictionless(), &
                                    u, matrix, pairs, n_pairs)
            do i = 1, n_pairs
               call add_contact_pair(system, pairs(1, i), pairs(2, i))
            end do
            missing = missing .or. n_pairs > 0
            cycle
         end if
         if (system%passes(p)%rigid .or. system%passes(p)%tied) cycle
         call assign_faces(model%mesh%coords, u, model%contact_pairs(system%passes(p)%pair)%parameters%edge_tolerance, &
                           system%passes(p))
         associate (pass => system%passes(p))
            do i = 1, size(pass%slave_nodes)
               if (pass%face(i) == 0) cycle
               call kernel_nodes(pass, i, nodes, n_nodes, first_ring)
               nodes(:n_nodes) = pass_node(pass, nodes(:n_nodes))   ! a plane pass's corners: their nodes
               ! the pairs that can be missing: the slave with every other node, and the
               ! contact face's nodes with the anchor face's and the ring's (those within a
               ! face share an element)
               do a = 1, merge(5, 1, n_nodes > 5)
                  do b = max(a + 1, merge(2, 6, a == 1)), n_nodes
                     if (.not. matrix%couples(nodes(a), nodes(b))) then
                        call add_contact_pair(system, nodes(a), nodes(b))
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

   !> Add the contact contributions at u to fint and (if present) to the tangent matrix.
   subroutine assemble_contact(model, system, u, fint, matrix, predictor, open_band)
      type(model_t), intent(in) :: model
      type(contact_system_t), intent(inout) :: system
      real(dp), intent(in) :: u(:)
      real(dp), intent(inout) :: fint(:)
      class(system_matrix_t), intent(inout), optional :: matrix
      logical, intent(in), optional :: predictor  !! first iteration of an increment: add the touching stiffness
      !> the touching stiffness also for open nodes with 0 <= g <= open_band (a singular tangent's retry)
      real(dp), intent(in), optional :: open_band
      real(dp) :: x_slave(3), x_face(3, 4), force(3*max_kernel_nodes), tangent(3*max_kernel_nodes, 3*max_kernel_nodes)
      real(dp) :: force3(3), tangent3(3, 3), shape(4), d_xi(4), d_eta(4)
      ! absent (unallocated) unless the node's anchor lies on another face / normals are smoothed
      real(dp), allocatable :: x_anchor_face(:, :), x_ring(:, :)
      ! absent (unallocated) unless the friction is augmented (TMETHOD Augmented)
      real(dp), allocatable :: lambda_t(:)
      integer, allocatable :: patch(:, :)
      integer :: p, i, a, slave, nodes(max_kernel_nodes), n_nodes, n, node, attempt, first_ring
      real(dp) :: touch_normal, touch_tangential, band
      type(contact_parameters_t) :: parameters   ! the pair's, with the pass's grown penalties
      logical :: touching_stiffness

      touching_stiffness = .false.
      if (present(predictor)) touching_stiffness = predictor
      if (present(matrix)) system%clamped_unsymmetric = .false.
      do p = 1, size(system%passes)
         if (allocated(system%passes(p)%interface_force)) system%passes(p)%interface_force = 0.0_dp
      end do
      do p = 1, size(system%passes)
         if (system%passes(p)%tied) cycle   ! frix_tie_constraints
         associate (pass => system%passes(p), pair => model%contact_pairs(system%passes(p)%pair))
            parameters = pass_parameters(pair%parameters, pass)
            if (pass%mortar) then
               call assemble_mortar_pass(model, pass, parameters, u, touching_stiffness, system%friction_scale, fint, &
                                         matrix)
               cycle
            end if
            band = -1.0_dp
            if (touching_stiffness) band = parameters%gap_tolerance
            if (present(open_band)) band = max(band, open_band)
            touch_normal = parameters%normal%stiffness()
            touch_tangential = 0.0_dp
            if (.not. parameters%friction%frictionless()) &
               touch_tangential = parameters%tangential_penalty
            do i = 1, size(pass%slave_nodes)
               slave = pass%slave_nodes(i)
               x_slave = model%mesh%coords(:, slave) + u(3*slave - 2:3*slave)
               if (parameters%tangential_augmented) lambda_t = pass%tangential_multiplier(:, i)
               if (pass%rigid) then
                  do attempt = 1, 2
                     call node_plane_contact(parameters, x_slave, pair%plane_point, pair%plane_normal, &
                                             pass%area(i), pass%anchor_point(:, i), pass%has_anchor(i), &
                                             pass%result(i), force3, tangent3, branch=pass%branch(i), &
                                             friction_scale=system%friction_scale, multiplier=pass%multiplier(i), &
                                             tangential_multiplier=lambda_t)
                     if (.not. present(matrix)) exit
                     if (.not. slip_reversed(pass, i)) exit
                  end do
                  if (pass%result(i)%status == contact_open .and. pass%result(i)%gap <= band) then
                     call add_touching_stiffness(pass%area(i), touch_normal, touch_tangential, &
                                                 pair%plane_normal, [1.0_dp], tangent3)
                     if (present(open_band)) force3 = force3 + pass%area(i)*touch_normal*pass%result(i)%gap* &
                                                      pair%plane_normal
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
               x_face = pass_positions(pass, model%mesh%coords, u, nodes(2:5))
               ! allocated here (their allocation tells the kernel they are present), then filled
               if (first_ring == 10) then
                  allocate (x_anchor_face(3, 4))
                  x_anchor_face(:, :) = pass_positions(pass, model%mesh%coords, u, nodes(6:9))
               end if
               if (pass%smooth) then
                  allocate (x_ring(3, n_nodes - first_ring + 1))
                  x_ring(:, :) = pass_positions(pass, model%mesh%coords, u, nodes(first_ring:n_nodes))
                  patch = patch_faces_of(pass%patches, pass%face(i))
               end if
               do attempt = 1, 2
                  ! x_anchor_face: the node moved off its anchor's face, the anchor stays a point of that face
                  call node_face_contact(parameters, x_slave, x_face, pass%area(i), pass%anchor_xi(:, i), &
                                         pass%has_anchor(i), .true., pass%result(i), force(:n), tangent(:n, :n), &
                                         x_anchor_face=x_anchor_face, branch=pass%branch(i), &
                                         friction_scale=system%friction_scale, x_ring=x_ring, patch_faces=patch, &
                                         multiplier=pass%multiplier(i), tangential_multiplier=lambda_t, &
                                         free_edges=pass%free_edge(:, pass%face(i)))
                  if (.not. present(matrix)) exit
                  if (.not. slip_reversed(pass, i)) exit
               end do
               if (pass%result(i)%status == contact_open .and. &
                   pass%result(i)%gap >= 0.0_dp .and. pass%result(i)%gap <= band) then
                  call face_shape_functions(pass%result(i)%xi, shape, d_xi, d_eta)
                  call add_touching_stiffness(pass%area(i), touch_normal, touch_tangential, &
                                              face_normal(x_face, pass%result(i)%xi), [1.0_dp, -shape], tangent(:15, :15))
                  if (present(open_band)) call add_gap_force(pass%area(i)*touch_normal*pass%result(i)%gap, &
                                                             face_normal(x_face, pass%result(i)%xi), shape, force(:15))
               end if
               ! a plane pass's corners: their force and stiffness onto their nodes (u_corner =
               ! u_node; add_element sums a node's repeated rows and columns)
               nodes(:n_nodes) = pass_node(pass, nodes(:n_nodes))
               do a = 1, 5
                  node = nodes(a)
                  fint(3*node - 2:3*node) = fint(3*node - 2:3*node) + force(3*a - 2:3*a)
               end do
               if (pass%partner > 0) call add_interface_force(system%passes, p, i, nodes(:5), force(:15))
               if (present(matrix)) then
                  call matrix%add_element(nodes(:n_nodes), tangent(:n, :n))
                  if (pass%result(i)%clamped .and. .not. system%clamped_unsymmetric) &
                     system%clamped_unsymmetric = unsymmetric(tangent(:n, :n))
               end if
               if (allocated(x_anchor_face)) deallocate (x_anchor_face)
               if (allocated(x_ring)) deallocate (x_ring, patch)
            end do
         end associate
      end do
   end subroutine assemble_contact

   !> Whether a node's tangent is unsymmetric beyond round-off: max |T - T'| > sqrt(eps) max |T|
   !> (an error of that size in the Newton step is below any residual tolerance).
   pure logical function unsymmetric(tangent)
      real(dp), intent(in) :: tangent(:, :)
      unsymmetric = maxval(abs(tangent - transpose(tangent))) > sqrt(epsilon(1.0_dp))*maxval(abs(tangent))
   end function unsymmetric

   !> The pair's parameters with eps_N and eps_T times the pass's penalty factors (augmented
   !> passes whose penalties grew: frix_contact_augmentation's grow_penalties).
   function pass_parameters(pair_parameters, pass) result(parameters)
      type(contact_parameters_t), intent(in) :: pair_parameters
      type(contact_pass_t), intent(in) :: pass
      type(contact_parameters_t) :: parameters
      parameters = pair_parameters
      if (pass%normal_scale /= 1.0_dp) &
         call parameters%normal%set_penalty(pass%normal_scale*parameters%normal%penalty())
      if (pass%tangential_scale /= 1.0_dp) &
         parameters%tangential_penalty = pass%tangential_scale*parameters%tangential_penalty
   end function pass_parameters

   !> PASSES 2: the kernel forces of slave i of pass p (fint entries of its slave and its
   !> master face's 4 nodes; the force on a node is -fint) added to the interface force of
   !> the slave node in pass p and of the master nodes in the partner pass.
   subroutine add_interface_force(passes, p, i, nodes, fint_entries)
      type(contact_pass_t), intent(inout) :: passes(:)
      integer, intent(in) :: p, i, nodes(5)
      real(dp), intent(in) :: fint_entries(15)
      integer :: a, j, q
      q = passes(p)%partner
      passes(p)%interface_force(:, i) = passes(p)%interface_force(:, i) - fint_entries(1:3)
      do a = 2, 5
         j = passes(q)%slave_index(nodes(a))
         if (j > 0) passes(q)%interface_force(:, j) = passes(q)%interface_force(:, j) - fint_entries(3*a - 2:3*a)
      end do
   end subroutine add_interface_force

   !> The pressure and tangential traction written for slave i of a pass (force/area): the
   !> kernel's with one pass; with PASSES 2 the interface's, from the force of both passes on
   !> the node (interface_force): p = f . n / A_s, t = (f - (f . n) n) / A_s, n the normal of
   !> the node's own kernel (out of the master body, towards the slave). Each pass of a
   !> two-pass pair carries part of the interface force, in shares that the penalties leave
   !> open where the meshes do not match (docs/contact.md); their sum is the interface's.
   pure subroutine interface_traction(pass, i, pressure, traction)
      type(contact_pass_t), intent(in) :: pass
      integer, intent(in) :: i
      real(dp), intent(out) :: pressure, traction(3)
      real(dp) :: normal(3), force(3)
      if (pass%partner == 0) then
         pressure = pass%result(i)%pressure
         traction = pass%result(i)%traction
         return
      end if
      normal = pass%result(i)%normal
      force = pass%interface_force(:, i)
      pressure = dot_product(force, normal)/pass%area(i)
      traction = (force - dot_product(force, normal)*normal)/pass%area(i)
   end subroutine interface_traction

   !> Accept the current contact state as converged: anchors (mortar passes: rows at the
   !> converged displacements u and tractions), accumulated slip, multipliers, and the
   !> multipliers' rates over the increment of length `dt` (pseudo time): (lambda_n -
   !> lambda_{n-1}) / dt for a node pressed (lambda > 0) at both ends of the increment, else 0.
   subroutine commit_contact(system, dt, model, u)
      type(contact_system_t), intent(inout) :: system
      real(dp), intent(in) :: dt
      type(model_t), intent(in) :: model
      real(dp), intent(in) :: u(:)   !! the converged displacements
      integer :: p, i
      do p = 1, size(system%passes)
         associate (pass => system%passes(p))
            do i = 1, size(pass%multiplier)
               if (dt > 0.0_dp .and. pass%multiplier(i) > 0.0_dp .and. pass%committed_multiplier(i) > 0.0_dp) then
                  pass%multiplier_rate(i) = (pass%multiplier(i) - pass%committed_multiplier(i))/dt
                  pass%tangential_multiplier_rate(:, i) = (pass%tangential_multiplier(:, i) - &
                                                           pass%committed_tangential_multiplier(:, i))/dt
               else
                  pass%multiplier_rate(i) = 0.0_dp
                  pass%tangential_multiplier_rate(:, i) = 0.0_dp
               end if
            end do
         end associate
         system%passes(p)%committed_multiplier = system%passes(p)%multiplier
         system%passes(p)%committed_tangential_multiplier = system%passes(p)%tangential_multiplier
         system%passes(p)%committed_normal_scale = system%passes(p)%normal_scale
         system%passes(p)%committed_tangential_scale = system%passes(p)%tangential_scale
         if (system%passes(p)%tied) cycle   ! a tie's foot points never change
         if (system%passes(p)%mortar) then
            call commit_mortar_pass(model, system%passes(p), u)
            cycle
         end if
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

   !> The force of a node taken as in contact at its gap g > 0 (the linear term of the penalty
   !> law k_N max(0, -g) on the predicted active set): f_int = A k_N g c_a n with c = (1, -N_a)
   !> (the kernel's sign convention, docs/contact.md "Forces"); `scaled_gap` = A k_N g.
   pure subroutine add_gap_force(scaled_gap, normal, shape, force)
      real(dp), intent(in) :: scaled_gap, normal(3), shape(4)
      real(dp), intent(inout) :: force(15)
      integer :: a
      force(1:3) = force(1:3) + scaled_gap*normal
      do a = 1, 4
         force(3*a + 1:3*a + 3) = force(3*a + 1:3*a + 3) - shape(a)*scaled_gap*normal
      end do
   end subroutine add_gap_force

   !> The gap g of every slave node of the contact passes (node-to-segment, rigid plane, mortar:
   !> the weighted gap g_j / D_j) at the last evaluation, pass after pass (huge where the node
   !> has no master face): what the line search compares before and after a step to find where
   !> open nodes first touch.
   subroutine contact_gaps(system, gaps)
      type(contact_system_t), intent(in) :: system
      real(dp), allocatable, intent(out) :: gaps(:)
      integer :: p, n
      n = 0
      do p = 1, size(system%passes)
         if (system%passes(p)%tied) cycle
         n = n + size(system%passes(p)%slave_nodes)
      end do
      allocate (gaps(n))
      n = 0
      do p = 1, size(system%passes)
         associate (pass => system%passes(p))
            if (pass%tied) cycle
            gaps(n + 1:n + size(pass%slave_nodes)) = pass%result(:size(pass%slave_nodes))%gap
            n = n + size(pass%slave_nodes)
         end associate
      end do
   end subroutine contact_gaps

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
   !> status (0 open, 1 stick, 2 slip; -1 not a slave node), accumulated slip, and the contact
   !> normal n (3, unit, out of the master body; zero without a master face) to which the
   !> traction is tangential. Where a node is a slave of several passes, the pass with the
   !> larger pressure wins.
   subroutine contact_nodal_fields(system, n_nodes, pressure, traction, gap, status, slip, normal)
      type(contact_system_t), intent(in) :: system
      integer, intent(in) :: n_nodes
      real(dp), allocatable, intent(out) :: pressure(:), traction(:, :), gap(:), status(:), slip(:), normal(:, :)
      real(dp) :: node_pressure, node_traction(3)
      integer :: p, i, node
      allocate (pressure(n_nodes), gap(n_nodes), slip(n_nodes), source=0.0_dp)
      allocate (traction(3, n_nodes), normal(3, n_nodes), source=0.0_dp)
      allocate (status(n_nodes), source=-1.0_dp)
      do p = 1, size(system%passes)
         associate (pass => system%passes(p))
            do i = 1, size(pass%slave_nodes)
               node = pass%slave_nodes(i)
               call interface_traction(pass, i, node_pressure, node_traction)
               if (status(node) >= 0.0_dp .and. pressure(node) >= node_pressure) cycle
               pressure(node) = node_pressure
               traction(:, node) = node_traction
               normal(:, node) = merge(pass%result(i)%normal, [0.0_dp, 0.0_dp, 0.0_dp], pass%face(i) > 0)
               gap(node) = merge(pass%result(i)%gap, 0.0_dp, pass%face(i) > 0)
               status(node) = real(pass%result(i)%status, dp)
               slip(node) = pass%slip(i)
            end do
         end associate
      end do
   end subroutine contact_nodal_fields

   !> The slave nodes of pass `p` and, per node, the columns of `contact_table_labels`: gap
   !> (length; 0 for a node with no master face), pressure, tangential traction x y z
   !> (force/area), accumulated slip (length), status (0 open, 1 stick, 2 slip) and the unit
   !> normal x y z the traction is tangential to (out of the master body; 0 with no face).
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
         allocate (values(size(contact_table_labels), size(nodes)))
         do i = 1, size(nodes)
            values(1, i) = merge(pass%result(i)%gap, 0.0_dp, pass%face(i) > 0)
            call interface_traction(pass, i, values(2, i), values(3:5, i))
            values(6, i) = pass%slip(i)
            values(7, i) = real(pass%result(i)%status, dp)
            values(8:10, i) = merge(pass%result(i)%normal, [0.0_dp, 0.0_dp, 0.0_dp], pass%face(i) > 0)
         end do
      end associate
   end subroutine contact_pass_table

   !> Resultant of the contact forces on the slave surface of contact pair `pair_index` (index
   !> into model%contact_pairs), from its first pass: sum of f_i = A_i (p_i n_i + t_i) over the
   !> slave nodes, A_i the node's tributary area, p_i its pressure (compressive positive) and
   !> t_i its tangential traction as written (interface_traction: with PASSES 2 the
   !> interface's), n_i the unit normal out of the master body. Component 1..3 of the
   !> resultant, or 0: the normal force sum A_i p_i. Statics: the resultant on the slave body
   !> balances the other loads on that body. 0 for a pair without a pass.
   real(dp) function contact_resultant(system, pair_index, component) result(value)
      type(contact_system_t), intent(in) :: system
      integer, intent(in) :: pair_index, component
      real(dp) :: pressure, traction(3)
      integer :: p, i
      value = 0.0_dp
      p = findloc(system%passes%pair, pair_index, dim=1)
      if (p == 0) return
      associate (pass => system%passes(p))
         do i = 1, size(pass%slave_nodes)
            call interface_traction(pass, i, pressure, traction)
            if (component == 0) then
               value = value + pass%area(i)*pressure
            else
               value = value + pass%area(i)*(pressure*pass%result(i)%normal(component) + traction(component))
            end if
         end do
      end associate
   end function contact_resultant

   !> The committed slip history of pass p as a real table (contact_history_rows, n_slave) for
   !> restart files: anchor face, anchor face coordinates (2), anchor point (3, rigid plane;
   !> a mortar pass: the committed traction t^n, force per current area), has-anchor flag
   !> (0/1), accumulated slip.
   subroutine get_contact_history(system, p, values)
      type(contact_system_t), intent(in) :: system
      integer, intent(in) :: p
      real(dp), allocatable, intent(out) :: values(:, :)
      associate (pass => system%passes(p))
         allocate (values(contact_history_rows, size(pass%slave_nodes)))
         values(1, :) = real(pass%anchor_face, dp)
         values(2:3, :) = pass%anchor_xi
         values(4:6, :) = pass%anchor_point
         if (pass%mortar) values(4:6, :) = pass%committed_mortar_traction
         values(7, :) = merge(1.0_dp, 0.0_dp, pass%has_anchor)
         values(8, :) = pass%slip
      end associate
   end subroutine get_contact_history

   !> Restore what get_contact_history stored (a mortar pass's committed rows then come from
   !> restart_mortar_rows).
   subroutine set_contact_history(system, p, values)
      type(contact_system_t), intent(inout) :: system
      integer, intent(in) :: p
      real(dp), intent(in) :: values(:, :)
      associate (pass => system%passes(p))
         pass%anchor_face = nint(values(1, :))
         pass%anchor_xi = values(2:3, :)
         pass%anchor_point = values(4:6, :)
         if (pass%mortar) then
            pass%committed_mortar_traction = values(4:6, :)
            pass%anchor_point = 0.0_dp
         end if
         pass%has_anchor = values(7, :) > 0.5_dp
         pass%slip = values(8, :)
      end associate
   end subroutine set_contact_history

   !> After a restart: the committed rows of the mortar passes at the committed displacements u
   !> (their tractions restored by set_contact_history).
   subroutine restart_mortar_rows(model, system, u)
      type(model_t), intent(in) :: model
      type(contact_system_t), intent(inout) :: system
      real(dp), intent(in) :: u(:)
      integer :: p
      do p = 1, size(system%passes)
         if (system%passes(p)%mortar) call restart_mortar_pass(model, system%passes(p), u, .true.)
      end do
   end subroutine restart_mortar_rows
end module frix_contact_assembly
