!> Node-to-surface frictional contact kernel: one slave node against one bilinear master face
!> of a deformable body, or against a fixed analytical rigid plane. Penalty regularisation in
!> the tangential direction, Coulomb friction with elastic stick (anchor form), the normal
!> pressure from the pair's normal contact law (frix_normal_contact_law; penalty by default),
!> consistent tangent by forward automatic differentiation (frix_dual_number). The formulation
!> and its decisions are written out in docs/contact.md.
!>
!> Kinematics (Wriggers, *Computational Contact Mechanics*, 2nd ed., 2006, 4.1 and 8.3):
!>   closest point xi* of x_s on the face, n = (x_,1 x x_,2)/|x_,1 x x_,2| at xi* (outward
!>   from the master body), normal gap g = (x_s - x(xi*)) . n (g < 0: penetration).
!> Normal: p_N = p_N(g, lambda) >= 0 (force/area, compressive positive) from the normal contact
!>   law, lambda the node's Lagrange multiplier (0 unless given); the penalty law's
!>   p_N = eps_N max(0, -g). The node is open (no force) where the law says it is not active.
!> Friction: the slip history is an anchor, a material point of the master surface (face
!>   coordinates xi_A, or a point of the rigid plane); x_A = x(xi_A) moves with the face.
!>   Elastic tangential gap g_T = (I - n n)(x_s - x_A), trial traction t_trial = -eps_T g_T,
!>   return mapping by the friction law (frix_friction_law). The anchor passed in is the
!>   COMMITTED one (last converged increment); the updated anchor is returned for commit:
!>   on slip, the face point x(xi*) + t/eps_T (with x(xi*) replaced by the foot x_s - g n when
!>   clamped) projected onto the face, where -eps_T g_T equals t.
!>   The anchor may lie on another face than the contact face (the node slid onto a
!>   neighbouring face since the last converged increment): x_A = sum N_a(xi_A) x_a over THAT
!>   face's nodes, which then enter the linearization as 12 more unknowns.
!> Smoothed normals (optional: x_ring and patch_faces given): the normal field of the master
!>   surface is made continuous across its facets by interpolating averaged nodal normals,
!>   n(xi) = m/|m|, m = sum_a N_a(xi) n_a, n_a = the normalised sum of the unit normals at node a
!>   of the patch faces around it (the patch is the caller's: frix_contact_patches keeps the
!>   adjacent faces within the pair's feature angle, NORMALS Auto, or all of them, Smoothed;
!>   the nodal-normal field of Abaqus' finite-sliding surfaces;
!>   Yang, Laursen & Meng, IJNME 62 (2005), and Wriggers 2006, 9.5, for the smoothing idea).
!>   The contact point xi* is the normal projection along that field, x_s - x(xi*) parallel
!>   to n(xi*): r_k = d . a_k - (d . n)(n . a_k) = 0 (d = x_s - x(xi), k = 1, 2), solved by
!>   Newton in plain reals (frix_smoothed_normals); g = d . n(xi*). Where that point lies outside
!>   the face (or is not found) and `clamp` is set, the facet's clamped closest point (which
!>   may lie inside the face) is the contact point, with the smoothed normal there; its
!>   derivative is the facet one. The 4 nodal normals are dual unknowns (after those of the
!>   nodes); their derivatives are chained with the nodal normals' closed-form derivatives
!>   (chain_nodal_normals), so the nodes around the face enter the tangent (up to
!>   max_ring_nodes more columns) without being dual unknowns, and the tangent is
!>   unsymmetric also without friction. On a flat surface n(xi) is the facet normal and
!>   everything equals the facet formulation.
!> Forces: on the slave f = A_s (p_N n + t); on master node a: -N_a(xi*) f. The kernel returns
!>   the contribution to the INTERNAL force vector (frix: residual = fext - fint),
!>   fint = -(forces on the nodes), node-major [slave xyz, master 1 xyz, ..., master 4 xyz,
!>   (anchor face node 1 xyz, ..., 4 xyz: zero force)], and tangent = d fint / d u (exact
!>   derivative of the discrete algorithm, unsymmetric in slip), both in force units
!>   (tangent: force/length).
module frix_contact_kernel
   use frix_kinds, only: dp
   use frix_dual_number, only: dual_t, dual_constant, dual_variable, dual_dot, dual_cross, dual_norm, set_dual_length, &
                               operator(+), operator(-), operator(*), operator(/), operator(**)
   use frix_face_projection, only: face_node_xi, face_node_eta, face_shape_functions, face_position, &
                                   face_normal, project_onto_face, closest_point_in_face, face_contains
   use frix_smoothed_normals, only: patch_normals, patch_normal_derivatives, smooth_projection, smooth_normal_at
   use frix_contact_parameters, only: contact_parameters_t
   use frix_friction_law, only: branch_free
   use frix_free_edge_zone, only: extension_zone, fade_start, edge_nodes, clamped_on_edge
   implicit none
   private

   public :: contact_point_result_t, node_face_contact, node_plane_contact, add_touching_stiffness
   public :: max_ring_nodes
   public :: contact_open, contact_stick, contact_slip

   !> not active (penalty: g >= 0), or outside the face without clamp: no force
   integer, parameter :: contact_open = 0
   integer, parameter :: contact_stick = 1  !! active and the trial traction is admissible
   integer, parameter :: contact_slip = 2   !! active and the trial traction was returned (or frictionless)

   !> Everything the caller needs to know about one slave node after an evaluation.
   type :: contact_point_result_t
      real(dp) :: gap = 0.0_dp             !! g (length), < 0 penetration
      real(dp) :: pressure = 0.0_dp        !! p_N (force/area), >= 0
      real(dp) :: traction(3) = 0.0_dp     !! tangential traction t on the slave (force/area)
      real(dp) :: normal(3) = 0.0_dp       !! n at the contact point (out of the master body)
      integer :: status = contact_open     !! contact_open, contact_stick or contact_slip
      !> the status the friction law itself chooses; differs from `status` only where the
      !> caller imposed a friction branch
      integer :: law_status = contact_open
      logical :: outside = .false.         !! closest point beyond an edge (|xi_k| > 1 + tol) or not found
      logical :: clamped = .false.         !! the clamped closest point (on an edge/corner) was used
      real(dp) :: xi(2) = 0.0_dp           !! face coordinates of the contact point
      real(dp) :: new_anchor_xi(2) = 0.0_dp  !! anchor to commit (face contact)
      real(dp) :: new_anchor(3) = 0.0_dp   !! current position of the anchor to commit
      !> |x_A,new - x_A,old| in the master's current configuration: add it to the node's
      !> accumulated slip when the increment is committed (0 in stick).
      real(dp) :: slip_increment = 0.0_dp
   end type contact_point_result_t

   !> Dual Newton iterations applied after the real projection has converged (residual at
   !> round-off): one step started with zero gradient already returns the implicit-function
   !> derivative dxi*/dq = -H^{-1} dr/dq exactly; a second one changes nothing but costs 2.5
   !> microseconds.
   integer, parameter :: dual_newton_iterations = 1

   !> Most ring nodes a smoothed-normal patch may have besides the face's 4; 12 is the ring of a
   !> face whose 4 nodes each have 4 faces around them (a structured quadrilateral surface).
   !> The ring nodes enter the tangent through the nodal normals' derivatives, not as dual
   !> unknowns, so this bounds only the callers' arrays.
   integer, parameter :: max_ring_nodes = 12

contains

   !> One slave node against one bilinear master face.
   !>
   !> The anchor is the committed slip history of the node: face coordinates (may lie slightly
   !> outside [-1, 1]^2) on this face, or on the face x_anchor_face when the node has moved
   !> off the face of its anchor; the anchor face's nodes are then unknowns 16-27 of the
   !> tangent (their force entries are zero), and a stick state commits the anchor's
   !> projection onto this face (the closest point of the bounded face if the projection
   !> fails). With has_anchor = .false. the anchor is the foot
   !> x_s - g n of the CURRENT position, moving with it: g_T = 0 identically, so the node
   !> sticks with zero traction and no tangential stiffness (a consistent fallback; callers
   !> should pass the committed anchor instead). For an open node the returned new anchor is the
   !> closest point of its current position, so committing it gives a node that closes in the
   !> next increment the closest point of its committed position as anchor.
   !> If the closest point lies outside the face by more than edge_tolerance, then without
   !> `clamp` nothing is computed (result%outside, status open, zero fint and tangent: the
   !> caller should try the neighbouring face); with `clamp` the closest point of the bounded
   !> face (on an edge or a corner) and the face normal there are used, and where that point
   !> lies on one of `free_edges` the force (pressure and traction) is faded over the extension
   !> zone's outer half (edge_fade).
   subroutine node_face_contact(parameters, x_slave, x_master, area, anchor_xi, has_anchor, clamp, &
                                result, fint, tangent, x_anchor_face, branch, friction_scale, x_ring, patch_faces, &
                                multiplier, tangential_multiplier, free_edges)
      type(contact_parameters_t), intent(in) :: parameters
      real(dp), intent(in) :: x_slave(3)      !! current slave position X + u
      real(dp), intent(in) :: x_master(3, 4)  !! current master face nodes, outward (HEX8 face) order
      real(dp), intent(in) :: area            !! A_s, the slave node's tributary area
      !> committed anchor: face coordinates on x_master, or on x_anchor_face when present
      real(dp), intent(in) :: anchor_xi(2)
      logical, intent(in) :: has_anchor       !! .false.: no committed anchor
      logical, intent(in) :: clamp            !! use the closest point of the bounded face
      type(contact_point_result_t), intent(out) :: result
      !> internal force contribution (force): exactly 15 entries, 27 with x_anchor_face
      real(dp), intent(out) :: fint(:)
      !> d fint / d u (force/length): exactly 15 x 15, 27 x 27 with x_anchor_face
      real(dp), intent(out) :: tangent(:, :)
      !> current nodes of the face that carries the anchor, when it is not x_master's face
      real(dp), intent(in), optional :: x_anchor_face(3, 4)
      !> friction branch to evaluate in contact (frix_friction_law: branch_free (default),
      !> branch_stick, branch_slip)
      integer, intent(in), optional :: branch
      !> factor f on the pressure the friction law sees (default 1): the slip threshold becomes
      !> f mu p_N, i.e. Coulomb with f mu (frix_driver's friction continuation)
      real(dp), intent(in), optional :: friction_scale
      !> smoothed normals: the patch's nodes besides x_master's (3, n_ring <= max_ring_nodes),
      !> unknowns after those of the face (and of the anchor face); zero force entries
      real(dp), intent(in), optional :: x_ring(:, :)
      !> smoothed normals: the faces of the patch (4, n), x_master's face among them, as local
      !> node numbers (1-4: x_master's nodes, 4 + j: x_ring(:, j)), outward (HEX8 face) order
      integer, intent(in), optional :: patch_faces(:, :)
      !> the node's Lagrange multiplier lambda for the normal law (force/area; default 0)
      real(dp), intent(in), optional :: multiplier
      !> augmented friction: the node's tangential multiplier lambda_T (force/area, global
      !> components; its part in the tangent plane counts); absent: the penalty's trial
      real(dp), intent(in), optional :: tangential_multiplier(3)
      !> which of the face's edges are free edges of the master surface (frix_free_edge_zone):
      !> a node clamped onto one has its force faded over the extension zone's outer half
      logical, intent(in), optional :: free_edges(4)
      type(dual_t) :: fade
      type(dual_t) :: xs(3), xm(3, 4), xa(3, 4), xi(2), shape(4), x(3), a1(3), a2(3), normal(3), gap
      type(dual_t) :: pressure, anchor_point(3), relative(3), traction(3), force(3), fd(15)
      type(dual_t) :: nodal(3, 4), residual(2)
      real(dp) :: inverse(2, 2), xi_start(2), used_anchor_xi(2), target(3), shape_real(4), d_xi(4), d_eta(4), old_anchor(3)
      real(dp) :: jacobian(2, 2), nodal_real(3, 4), lambda
      logical :: converged, fixed(2), anchor_fixed(2), slipping, other_face, smooth
      integer :: a, k, n_unknowns, n_direct, used_branch, previous_length

      other_face = present(x_anchor_face)
      smooth = present(patch_faces) .and. present(x_ring)
      used_branch = branch_free
      if (present(branch)) used_branch = branch
      lambda = 0.0_dp
      if (present(multiplier)) lambda = multiplier
      n_direct = merge(27, 15, other_face)
      n_unknowns = n_direct
      if (smooth) n_unknowns = n_direct + 3*size(x_ring, 2)
      fint = 0.0_dp
      tangent = 0.0_dp
      if (smooth) then
         nodal_real = patch_normals(x_master, x_ring, patch_faces)
         call smooth_projection(x_master, nodal_real, x_slave, xi_start, converged, jacobian)
      else
         call project_onto_face(x_master, x_slave, xi_start, converged)
      end if
      fixed = .false.
      result%outside = .not. (converged .and. face_contains(xi_start, parameters%edge_tolerance))
      if (result%outside) then
         if (.not. clamp) then
            result%xi = xi_start
            result%gap = huge(1.0_dp)
            if (converged) then
               if (smooth) then
                  result%normal = smooth_normal_at(nodal_real, xi_start)
               else
                  result%normal = face_normal(x_master, xi_start)
               end if
               result%gap = dot_product(x_slave - face_position(x_master, xi_start), result%normal)
            end if
            result%new_anchor_xi = xi_start
            result%new_anchor = face_position(x_master, xi_start)
            return
         end if
         call closest_point_in_face(x_master, x_slave, parameters%edge_tolerance, xi_start, fixed)
         result%clamped = .true.
      end if

      ! the duals' gradients as long as the unknowns seeded below (restored on return)
      call set_dual_length(merge(n_direct + 12, n_direct, smooth), previous_length)
      ! Seed the 15 unknowns: slave xyz, then master node a xyz at 3a+1..3a+3.
      xs = dual_variable(x_slave, 1)
      do a = 1, 4
         xm(:, a) = dual_variable(x_master(:, a), 3*a + 1)
      end do
      if (other_face) then
         do a = 1, 4
            xa(:, a) = dual_variable(x_anchor_face(:, a), 3*a + 13)
         end do
      else
         xa = xm
      end if
      if (smooth) then
         ! the nodal normals as unknowns n_direct + 1 .. n_direct + 12 (chain_nodal_normals)
         do a = 1, 4
            nodal(:, a) = dual_variable(nodal_real(:, a), n_direct + 3*a - 2)
         end do
      end if

      xi = dual_constant(xi_start)
      if (any(fixed)) then
         call edge_point(xs, xm, fixed, xi)
      else if (smooth .and. .not. result%clamped) then
         ! implicit-function derivative of r(xi*, q) = 0: dxi*/dq = -J^{-1} dr/dq
         call dual_smooth_residual(xs, xm, nodal, xi, residual)
         inverse = inverse_2x2(jacobian)
         xi(1) = xi(1) - (inverse(1, 1)*residual(1) + inverse(1, 2)*residual(2))
         xi(2) = xi(2) - (inverse(2, 1)*residual(1) + inverse(2, 2)*residual(2))
      else
         do k = 1, dual_newton_iterations
            call newton_step(xs, xm, xi)
         end do
      end if
      call face_geometry(xm, xi, shape, x, a1, a2)
      if (smooth) then
         normal = smooth_normal(nodal, shape)
      else
         normal = dual_cross(a1, a2)
         normal = normal/dual_norm(normal)
      end if
      gap = dual_dot(xs - x, normal)

      result%xi = xi%value
      result%normal = normal%value
      result%gap = gap%value
      if (.not. parameters%normal%active(gap%value, lambda)) then
         result%status = contact_open
         result%new_anchor_xi = result%xi
         result%new_anchor = x%value
         call set_dual_length(previous_length)
         return
      end if

      pressure = parameters%normal%pressure(gap, lambda)
      used_anchor_xi = result%xi
      old_anchor = x%value
      if (has_anchor) then
         call face_shape_functions(anchor_xi, shape_real, d_xi, d_eta)
         do k = 1, 3
            anchor_point(k) = dual_dot(dual_constant(shape_real), xa(k, :))
         end do
         old_anchor = anchor_point%value
         used_anchor_xi = anchor_xi
         if (other_face) then
            ! what a stick state commits: the anchor carried over onto the contact face
            call project_onto_face(x_master, old_anchor, used_anchor_xi, converged, initial_xi=result%xi)
            if (.not. converged) call closest_point_in_face(x_master, old_anchor, 0.0_dp, used_anchor_xi, anchor_fixed)
         end if
      end if
      if (parameters%friction%frictionless()) then
         traction = dual_constant(0.0_dp)
         result%status = contact_slip
         result%law_status = contact_slip
         result%new_anchor_xi = result%xi
      else
         if (.not. has_anchor) anchor_point = xs - gap*normal   ! the foot: g_T = 0 identically
         relative = xs - anchor_point
         call friction_response(parameters, relative, normal, pressure, used_branch, traction, slipping, &
                                result%law_status, friction_scale, tangential_multiplier)
         if (slipping) then
            result%status = contact_slip
            target = x_slave - result%gap*result%normal + &
                     (traction%value - tangential_part(tangential_multiplier, result%normal))/parameters%tangential_penalty
            call project_onto_face(x_master, target, result%new_anchor_xi, converged, initial_xi=result%xi)
            if (.not. converged) result%new_anchor_xi = result%xi
         else
            result%status = contact_stick
            result%new_anchor_xi = used_anchor_xi
         end if
      end if
      result%pressure = pressure%value
      result%traction = traction%value
      result%new_anchor = face_position(x_master, result%new_anchor_xi)
      if (has_anchor .and. result%status == contact_slip) &
         result%slip_increment = norm2(result%new_anchor - old_anchor)

      fade = dual_constant(1.0_dp)
      if (result%clamped .and. present(free_edges)) fade = edge_fade(xs, xm, x, normal, xi, fixed, free_edges)
      result%pressure = fade%value*result%pressure
      result%traction = fade%value*result%traction
      force = (fade*area)*(pressure*normal + traction)
      fd(1:3) = -force
      do a = 1, 4
         fd(3*a + 1:3*a + 3) = shape(a)*force
      end do
      do k = 1, 15
         fint(k) = fd(k)%value
         tangent(k, :n_direct) = fd(k)%gradient(:n_direct)
      end do
      if (smooth) call chain_nodal_normals(fd, n_direct, x_master, x_ring, patch_faces, tangent)
      call set_dual_length(previous_length)
   end subroutine node_face_contact

   !> The tangent's part through the nodal normals: d fint/d x_b += (d fint/d n_a)(d n_a/d x_b)
   !> for the patch's nodes b (the face's, columns 4-15, and the ring's, columns n_direct + 1
   !> on), d fint/d n_a from the duals' unknowns n_direct + 1 .. n_direct + 12.
   subroutine chain_nodal_normals(fd, n_direct, x_master, x_ring, patch_faces, tangent)
      type(dual_t), intent(in) :: fd(15)
      integer, intent(in) :: n_direct
      real(dp), intent(in) :: x_master(3, 4), x_ring(:, :)
      integer, intent(in) :: patch_faces(:, :)
      real(dp), intent(inout) :: tangent(:, :)
      real(dp) :: nodal(3, 4), derivative(12, 3*(4 + size(x_ring, 2))), by_normal(15, 12), chained(15, 3*(4 + size(x_ring, 2)))
      integer :: k
      call patch_normal_derivatives(x_master, x_ring, patch_faces, nodal, derivative)
      do k = 1, 15
         by_normal(k, :) = fd(k)%gradient(n_direct + 1:n_direct + 12)
      end do
      chained = matmul(by_normal, derivative)
      tangent(:15, 4:15) = tangent(:15, 4:15) + chained(:, :12)
      tangent(:15, n_direct + 1:n_direct + 3*size(x_ring, 2)) = chained(:, 13:)
   end subroutine chain_nodal_normals

   !> One slave node against a fixed rigid plane through `plane_point` with normal
   !> `plane_normal` (pointing out of the rigid body, towards the slave side; normalised here).
   !> g = (x_s - P) . n. The anchor is a point of the plane (projected onto it if it is not);
   !> with has_anchor = .false. the foot x_s - g n of the current position is used, moving
   !> with it (zero traction, no tangential stiffness, as for node_face_contact).
   !> fint = -A_s (p_N n + t) and tangent = d fint / d u_s (3 x 3). For an open node the new
   !> anchor is the foot point.
   subroutine node_plane_contact(parameters, x_slave, plane_point, plane_normal, area, anchor, has_anchor, &
                                 result, fint, tangent, branch, friction_scale, multiplier, tangential_multiplier)
      type(contact_parameters_t), intent(in) :: parameters
      real(dp), intent(in) :: x_slave(3)       !! current slave position X + u
      real(dp), intent(in) :: plane_point(3)   !! a point P of the plane
      real(dp), intent(in) :: plane_normal(3)  !! normal, out of the rigid body (any length > 0)
      real(dp), intent(in) :: area             !! A_s, the slave node's tributary area
      real(dp), intent(in) :: anchor(3)        !! committed anchor, a point of the plane
      logical, intent(in) :: has_anchor        !! .false.: no committed anchor
      type(contact_point_result_t), intent(out) :: result
      real(dp), intent(out) :: fint(3)         !! internal force contribution (force)
      real(dp), intent(out) :: tangent(3, 3)   !! d fint / d u_s (force/length)
      integer, intent(in), optional :: branch  !! friction branch, as for node_face_contact
      real(dp), intent(in), optional :: friction_scale  !! as for node_face_contact
      real(dp), intent(in), optional :: multiplier      !! as for node_face_contact
      real(dp), intent(in), optional :: tangential_multiplier(3)  !! as for node_face_contact
      type(dual_t) :: xs(3), gap, pressure, relative(3), traction(3), force(3)
      real(dp) :: normal(3), foot(3), used_anchor(3), lambda
      logical :: slipping
      integer :: k, used_branch, previous_length

      fint = 0.0_dp
      tangent = 0.0_dp
      used_branch = branch_free
      if (present(branch)) used_branch = branch
      lambda = 0.0_dp
      if (present(multiplier)) lambda = multiplier
      normal = unit(plane_normal)
      call set_dual_length(3, previous_length)   ! restored on return
      xs = dual_variable(x_slave, 1)
      gap = dual_dot(xs - plane_point, dual_constant(normal))
      foot = x_slave - gap%value*normal
      result%normal = normal
      result%gap = gap%value
      result%new_anchor = foot
      if (.not. parameters%normal%active(gap%value, lambda)) then
         result%status = contact_open
         call set_dual_length(previous_length)
         return
      end if

      pressure = parameters%normal%pressure(gap, lambda)
      used_anchor = foot
      if (has_anchor) used_anchor = anchor - dot_product(anchor - plane_point, normal)*normal
      if (parameters%friction%frictionless()) then
         traction = dual_constant(0.0_dp)
         result%status = contact_slip
         result%law_status = contact_slip
      else
         if (has_anchor) then
            relative = xs - used_anchor
         else
            relative = gap*normal   ! anchor at the foot: g_T = 0 identically
         end if
         call friction_response(parameters, relative, dual_constant(normal), pressure, used_branch, traction, &
                                slipping, result%law_status, friction_scale, tangential_multiplier)
         if (slipping) then
            result%status = contact_slip
            result%new_anchor = foot + (traction%value - tangential_part(tangential_multiplier, normal))/ &
                                parameters%tangential_penalty
         else
            result%status = contact_stick
            result%new_anchor = used_anchor
         end if
      end if
      result%pressure = pressure%value
      result%traction = traction%value
      if (has_anchor) result%slip_increment = norm2(result%new_anchor - used_anchor)

      force = area*(pressure*normal + traction)
      do k = 1, 3
         fint(k) = -force(k)%value
         tangent(k, :) = -force(k)%gradient(1:3)
      end do
      call set_dual_length(previous_length)
   end subroutine node_plane_contact

   !> Trial traction t_trial = -eps_T (I - n n) g_rel (g_rel: slave position relative to the
   !> anchor; force/area), plus (I - n n) lambda_T with augmented friction, and its return mapping on friction branch `branch`: the traction,
   !> whether the slip branch was evaluated, and the status the law itself chooses.
   pure subroutine friction_response(parameters, relative, normal, pressure, branch, traction, slipping, &
                                     law_status, friction_scale, tangential_multiplier)
      type(contact_parameters_t), intent(in) :: parameters
      type(dual_t), intent(in) :: relative(3), normal(3), pressure
      integer, intent(in) :: branch
      type(dual_t), intent(out) :: traction(3)
      logical, intent(out) :: slipping
      integer, intent(out) :: law_status
      real(dp), intent(in), optional :: friction_scale  !! as for node_face_contact
      !> augmented friction: the node's tangential multiplier lambda_T (force/area), whose part
      !> in the tangent plane is added to the trial traction
      real(dp), intent(in), optional :: tangential_multiplier(3)
      type(dual_t) :: trial(3), lambda(3)
      logical :: law_slipping
      real(dp) :: scale
      scale = 1.0_dp
      if (present(friction_scale)) scale = friction_scale
      trial = (-parameters%tangential_penalty)*(relative - dual_dot(relative, normal)*normal)
      if (present(tangential_multiplier)) then
         lambda = dual_constant(tangential_multiplier)
         trial = trial + (lambda - dual_dot(lambda, normal)*normal)
      end if
      call parameters%friction%return_map(trial, scale*pressure, branch, traction, slipping, law_slipping)
      law_status = merge(contact_slip, contact_stick, law_slipping)
   end subroutine friction_response

   !> The factor w on the force of a slave node xs clamped onto the point x of a free edge (or
   !> a corner on one) of face xm: 1 - 3 s^2 + 2 s^3 (frix_free_edge_zone's fade), the product
   !> over the free edges it is clamped onto. The distance beyond edge k is (xs - x) . m, m the
   !> unit outward normal of the edge in the face's tangent plane (e x n), as the search's
   !> beyond_free_edge measures it; the zone's length and m are differentiated with the face.
   pure function edge_fade(xs, xm, x, normal, xi, fixed, free) result(fade)
      type(dual_t), intent(in) :: xs(3), xm(3, 4), x(3), normal(3), xi(2)
      logical, intent(in) :: fixed(2), free(4)
      type(dual_t) :: fade, outward(3), zone, s
      integer :: k, first, second, after, before
      fade = dual_constant(1.0_dp)
      do k = 1, 4
         if (.not. (free(k) .and. clamped_on_edge(k, xi%value, fixed))) cycle
         call edge_nodes(k, first, second, after, before)
         outward = dual_cross(xm(:, second) - xm(:, first), normal)
         outward = outward/dual_norm(outward)
         zone = (0.5_dp*extension_zone)*(dual_norm(xm(:, after) - xm(:, second)) + &
                                         dual_norm(xm(:, first) - xm(:, before)))
         s = (dual_dot(xs - x, outward) - fade_start*zone)/((1.0_dp - fade_start)*zone)
         if (s%value <= 0.0_dp) cycle
         if (s%value >= 1.0_dp) then
            fade = dual_constant(0.0_dp)
         else
            fade = fade*(1.0_dp - s*s*(3.0_dp - 2.0_dp*s))
         end if
      end do
   end function edge_fade

   !> Shape functions, position and tangent vectors x_,1, x_,2 of the face at dual xi.
   pure subroutine face_geometry(xm, xi, shape, x, a1, a2)
      type(dual_t), intent(in) :: xm(3, 4), xi(2)
      type(dual_t), intent(out) :: shape(4), x(3), a1(3), a2(3)
      type(dual_t) :: d_xi(4), d_eta(4)
      integer :: k
      shape = 0.25_dp*((1.0_dp + xi(1)*face_node_xi)*(1.0_dp + xi(2)*face_node_eta))
      d_xi = (0.25_dp*face_node_xi)*(1.0_dp + xi(2)*face_node_eta)
      d_eta = (0.25_dp*face_node_eta)*(1.0_dp + xi(1)*face_node_xi)
      do k = 1, 3
         x(k) = dual_dot(shape, xm(k, :))
         a1(k) = dual_dot(d_xi, xm(k, :))
         a2(k) = dual_dot(d_eta, xm(k, :))
      end do
   end subroutine face_geometry

   !> One Newton step of the closest-point problem r_i = -(x_s - x) . x_,i = 0 in duals
   !> (same equations as frix_face_projection, exact Hessian). Started at the converged real
   !> xi* with zero gradient, it returns dxi*/dq = -H^{-1} dr/dq, the implicit-function
   !> derivative of the closest point.
   pure subroutine newton_step(xs, xm, xi)
      type(dual_t), intent(in) :: xs(3), xm(3, 4)
      type(dual_t), intent(inout) :: xi(2)
      type(dual_t) :: shape(4), x(3), a1(3), a2(3), a12(3), distance(3)
      type(dual_t) :: r1, r2, h11, h12, h22, determinant
      integer :: k
      call face_geometry(xm, xi, shape, x, a1, a2)
      do k = 1, 3
         a12(k) = dual_dot(dual_constant(0.25_dp*face_node_xi*face_node_eta), xm(k, :))
      end do
      distance = xs - x
      r1 = -dual_dot(distance, a1)
      r2 = -dual_dot(distance, a2)
      h11 = dual_dot(a1, a1)
      h22 = dual_dot(a2, a2)
      h12 = dual_dot(a1, a2) - dual_dot(distance, a12)
      determinant = h11*h22 - h12**2
      if (.not. (determinant%value > 0.0_dp)) return
      xi(1) = xi(1) - (h22*r1 - h12*r2)/determinant
      xi(2) = xi(2) - (h11*r2 - h12*r1)/determinant
   end subroutine newton_step

   !> Clamped closest point in duals: with xi_k held at +-1 the edge x = c + t e is straight,
   !> t* = (x_s - c) . e / (e . e) (c, e from the edge's midpoint and half-length vector);
   !> a corner (both held) is constant. xi holds the real clamped point on entry.
   pure subroutine edge_point(xs, xm, fixed, xi)
      type(dual_t), intent(in) :: xs(3), xm(3, 4)
      logical, intent(in) :: fixed(2)
      type(dual_t), intent(inout) :: xi(2)
      type(dual_t) :: shape(4), middle(3), a1(3), a2(3), edge(3)
      integer :: free
      if (all(fixed)) return
      free = 1
      if (fixed(1)) free = 2
      xi(free) = dual_constant(0.0_dp)
      call face_geometry(xm, xi, shape, middle, a1, a2)
      if (free == 1) then
         edge = a1
      else
         edge = a2
      end if
      xi(free) = dual_dot(xs - middle, edge)/dual_dot(edge, edge)
   end subroutine edge_point

   !> The smoothed normal n = m/|m|, m = sum_a N_a n_a, from the shape functions at xi.
   pure function smooth_normal(nodal, shape) result(normal)
      type(dual_t), intent(in) :: nodal(3, 4), shape(4)
      type(dual_t) :: normal(3)
      integer :: k
      do k = 1, 3
         normal(k) = dual_dot(shape, nodal(k, :))
      end do
      normal = normal/dual_norm(normal)
   end function smooth_normal

   !> Residual of the projection along the smoothed normal field: r_k = d . a_k - (d . n)(n . a_k),
   !> d = x_s - x(xi); zero when d is parallel to n(xi).
   pure subroutine dual_smooth_residual(xs, xm, nodal, xi, residual)
      type(dual_t), intent(in) :: xs(3), xm(3, 4), nodal(3, 4), xi(2)
      type(dual_t), intent(out) :: residual(2)
      type(dual_t) :: shape(4), x(3), a1(3), a2(3), normal(3), distance(3), normal_distance
      call face_geometry(xm, xi, shape, x, a1, a2)
      normal = smooth_normal(nodal, shape)
      distance = xs - x
      normal_distance = dual_dot(distance, normal)
      residual(1) = dual_dot(distance, a1) - normal_distance*dual_dot(normal, a1)
      residual(2) = dual_dot(distance, a2) - normal_distance*dual_dot(normal, a2)
   end subroutine dual_smooth_residual

   !> Inverse of a 2 x 2 matrix (Cramer's rule); the caller makes sure it is regular.
   pure function inverse_2x2(matrix) result(inverse)
      real(dp), intent(in) :: matrix(2, 2)
      real(dp) :: inverse(2, 2)
      inverse = reshape([matrix(2, 2), -matrix(2, 1), -matrix(1, 2), matrix(1, 1)], [2, 2]) &
                /(matrix(1, 1)*matrix(2, 2) - matrix(1, 2)*matrix(2, 1))
   end function inverse_2x2

   !> (I - n n) lambda_T, the tangent-plane part of a tangential multiplier (0 when absent):
   !> with augmented friction the anchor of a slipping node is where the trial traction
   !> lambda_T - eps_T g_T equals the returned traction t, g_T = (lambda_T - t) / eps_T.
   pure function tangential_part(tangential_multiplier, normal) result(part)
      real(dp), intent(in), optional :: tangential_multiplier(3)
      real(dp), intent(in) :: normal(3)
      real(dp) :: part(3)
      part = 0.0_dp
      if (present(tangential_multiplier)) &
         part = tangential_multiplier - dot_product(tangential_multiplier, normal)*normal
   end function tangential_part

   pure function unit(vector) result(direction)
      real(dp), intent(in) :: vector(3)
      real(dp) :: direction(3)
      direction = vector/norm2(vector)
   end function unit

   !> Touching stiffness (no force): D = A (k_N n n + eps_T (I - n n)) acting on the gap of
   !> the slave node relative to its contact point, K_ab += c_a c_b D over the nodes with
   !> c = [1, -N_1, ..., -N_4] on a master face, [1] against a rigid plane (force/length); a
   !> mortar row passes A = 1 / D_j and its coefficients c_jk (frix_mortar_assembly).
   pure subroutine add_touching_stiffness(area, normal_stiffness, tangential_penalty, normal, weights, tangent)
      real(dp), intent(in) :: area               !! A_s (area; 1 / D_j for a mortar row)
      real(dp), intent(in) :: normal_stiffness   !! k_N, the normal law's (force/area/length)
      real(dp), intent(in) :: tangential_penalty !! eps_T, 0 without friction (force/area/length)
      real(dp), intent(in) :: normal(3)       !! unit normal n
      real(dp), intent(in) :: weights(:)      !! c_a per node
      real(dp), intent(inout) :: tangent(:, :)  !! (3 size(weights), 3 size(weights))
      real(dp) :: block(3, 3)
      integer :: a, b, k
      do k = 1, 3
         block(:, k) = area*(normal_stiffness - tangential_penalty)*normal*normal(k)
         block(k, k) = block(k, k) + area*tangential_penalty
      end do
      do b = 1, size(weights)
         do a = 1, size(weights)
            tangent(3*a - 2:3*a, 3*b - 2:3*b) = tangent(3*a - 2:3*a, 3*b - 2:3*b) + weights(a)*weights(b)*block
         end do
      end do
   end subroutine add_touching_stiffness
end module frix_contact_kernel
