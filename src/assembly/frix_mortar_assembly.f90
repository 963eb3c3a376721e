!> Mortar contact passes (DISCRETIZATION Mortar; docs/contact.md, "Mortar contact") in the
!> global system: at every Newton iteration the mortar rows of the slave nodes at the current
!> positions (frix_mortar_contact, run by frix_contact_assembly's search_contact), the node
!> pairs they need in the sparse pattern, each slave node's forces and tangent assembled into
!> fint and the matrix (frix_contact_assembly's assemble_contact), and with friction the
!> committed rows and tractions (commit, restart). In the predictor a touching node
!> (0 <= g_j / D_j <= GAPTOL) gets the stiffness (1 / D_j) c c^T (k_N n n + eps_T (I - n n))
!> without force (eps_T only with friction), as a touching node of node-to-segment contact.
!> A node in contact whose patch is curved (faces turned by more than curved_angle) gets the
!> complete tangent (complete_tangent: the derivatives of D, M, a_j and n_j included); a node
!> whose slip reverses between iterates is held in stick (frix_contact_pass's slip_reversed),
!> as in node-to-segment contact.
module frix_mortar_assembly
   use frix_kinds, only: dp
   use frix_model, only: model_t
   use frix_system_matrix, only: system_matrix_t
   use frix_contact_pass, only: contact_pass_t, slip_reversed
   use frix_contact_parameters, only: contact_parameters_t
   use frix_contact_kernel, only: contact_point_result_t, contact_open, add_touching_stiffness
   use frix_mortar_contact, only: mortar_rows_t, mortar_rows, mortar_node_t, mortar_node, mortar_node_contact, &
                                  mortar_covered
   use frix_mortar_segments, only: segment_integrals
   use frix_face_projection, only: face_normal
   use frix_contact_patches, only: faces_around_nodes
   use frix_mesh_selection, only: sorted_unique
   implicit none
   private

   public :: search_mortar_pass, assemble_mortar_pass, commit_mortar_pass, restart_mortar_pass

   !> The part of the surfaces a slave node's row depends on: the slave faces at the node, their
   !> nodes (the node itself at place j), the master faces overlapping them, and the block of
   !> nodes its force depends on (those, and with friction its committed row's).
   type :: mortar_patch_t
      integer, allocatable :: slave_faces(:, :), slave_nodes(:), master_faces(:, :), block(:)
      integer :: j = 0
      !> the faces' normals turn by more than curved_angle against each other: the node gets
      !> the complete tangent (complete_tangent)
      logical :: curved = .false.
   end type mortar_patch_t

   !> Angle (rad) between the normals of two slave faces at a node, or of two master faces paired
   !> with them, above which the node's tangent is the complete one. The first-order tangent leaves out terms of relative order h / R
   !> (docs/contact.md, "Tangent"), which is about this angle between neighbouring faces; with
   !> it the flat patch tests converge in 2 iterations and Hertz (faces 0.008 rad apart) in 30,
   !> and with the complete tangent there the cost of the differences dominates the run.
   real(dp), parameter :: curved_angle = 0.05_dp

   !> Step of the central differences of the complete tangent, relative to the square root of
   !> the node's tributary area (a length): the truncation error goes as its square (1e-12),
   !> the round-off of the forces (eps_N times 1e-16 of the coordinates) over it stays below
   !> 1e-8 of the entries.
   real(dp), parameter :: relative_step = 1.0e-6_dp

contains

   !> The mortar rows of `pass` at displacements u (current configuration), pass%face(i) a
   !> master face overlapping slave i's faces (0: none, or the node not covered enough:
   !> mortar_covered), and the node pairs (2, n_missing) of
   !> the covered slave nodes' rows (with friction joined with their committed rows) that
   !> `matrix`'s pattern lacks.
   subroutine search_mortar_pass(model, pass, frictional, u, matrix, missing, n_missing)
      type(model_t), intent(in) :: model
      type(contact_pass_t), intent(inout) :: pass
      logical, intent(in) :: frictional
      real(dp), intent(in) :: u(:)
      class(system_matrix_t), intent(in) :: matrix
      integer, allocatable, intent(out) :: missing(:, :)
      integer, intent(out) :: n_missing
      type(mortar_patch_t) :: patch
      type(mortar_node_t) :: node
      real(dp), allocatable :: x(:, :)
      integer, allocatable :: face_start(:), node_faces(:)
      integer :: i, a, b
      x = current_coordinates(model, u)
      call mortar_rows(x, pass%slave_nodes, pass%slave_faces, pass%faces, pass%band, pass%mortar_rows)
      pass%face = pass%mortar_rows%master_face
      call faces_around_nodes(size(x, 2), pass%faces, face_start, node_faces)
      allocate (missing(2, 64))
      n_missing = 0
      do i = 1, size(pass%slave_nodes)
         ! a node the master does not cover enough is open: no face (its results are not
         ! written, as for a node-to-segment node without a face)
         if (.not. mortar_covered(pass%mortar_rows, i)) pass%face(i) = 0
         if (pass%face(i) == 0) cycle
         call node_patch(pass, frictional, x, face_start, node_faces, i, patch)
         if (.not. patch%curved) then
            call slave_node(pass, frictional, i, node)
            patch%block = node%nodes
         end if
         do a = 1, size(patch%block)
            do b = a + 1, size(patch%block)
               if (matrix%couples(patch%block(a), patch%block(b))) cycle
               if (n_missing == size(missing, 2)) missing = reshape(missing, [2, 2*n_missing], pad=[0])
               n_missing = n_missing + 1
               missing(:, n_missing) = [patch%block(a), patch%block(b)]
            end do
         end do
      end do
   end subroutine search_mortar_pass

   !> Add the forces and (if `matrix` is present) tangents of the slave nodes of mortar pass
   !> `pass` at displacements u; `touching`: the predictor's touching stiffness;
   !> friction_scale: the factor on the pressure the friction law sees.
   subroutine assemble_mortar_pass(model, pass, parameters, u, touching, friction_scale, fint, matrix)
      type(model_t), intent(in) :: model
      type(contact_pass_t), intent(inout) :: pass
      type(contact_parameters_t), intent(in) :: parameters
      real(dp), intent(in) :: u(:)
      logical, intent(in) :: touching
      real(dp), intent(in) :: friction_scale
      real(dp), intent(inout) :: fint(:)
      class(system_matrix_t), intent(inout), optional :: matrix
      type(mortar_node_t) :: node
      type(mortar_patch_t) :: patch
      real(dp), allocatable :: force(:), tangent(:, :), x(:, :), patch_tangent(:, :)
      integer, allocatable :: face_start(:), node_faces(:)
      real(dp) :: tangential_penalty
      integer :: i, k, n, attempt
      tangential_penalty = 0.0_dp
      if (.not. parameters%friction%frictionless()) tangential_penalty = parameters%tangential_penalty
      ! room for a row's force and tangent, grown (not allocated per node) as longer rows come
      allocate (force(0), tangent(0, 0))
      do i = 1, size(pass%slave_nodes)
         if (pass%face(i) == 0) then
            pass%result(i) = contact_point_result_t()
            pass%result(i)%gap = huge(1.0_dp)
            cycle
         end if
         call slave_node(pass, tangential_penalty > 0.0_dp, i, node)
         n = size(node%nodes)
         allocate (node%x(3, n))
         do k = 1, n
            node%x(:, k) = model%mesh%coords(:, node%nodes(k)) + u(3*node%nodes(k) - 2:3*node%nodes(k))
         end do
         if (3*n > size(force)) then
            deallocate (force, tangent)
            allocate (force(3*n), tangent(3*n, 3*n))
         end if
         associate (node_force => force(:3*n), node_tangent => tangent(:3*n, :3*n))
            do attempt = 1, 2
               call mortar_node_contact(parameters, node, friction_scale, pass%branch(i), pass%result(i), node_force, &
                                        node_tangent)
               ! slip reversal, as for node-to-segment contact (frix_contact_pass's slip_reversed)
               if (.not. present(matrix)) exit
               if (.not. slip_reversed(pass, i)) exit
            end do
            if (touching .and. pass%result(i)%status == contact_open .and. pass%result(i)%gap >= 0.0_dp .and. &
                pass%result(i)%gap <= parameters%gap_tolerance) &
               call add_touching_stiffness(1.0_dp/node%dual_area, parameters%normal%stiffness(), tangential_penalty, &
                                           node%normal, node%weight, node_tangent)
            do k = 1, n
               fint(3*node%nodes(k) - 2:3*node%nodes(k)) = fint(3*node%nodes(k) - 2:3*node%nodes(k)) + &
                                                           node_force(3*k - 2:3*k)
            end do
            ! an open node's zero block is not added (its node pairs may lie outside the pattern)
            if (.not. present(matrix)) cycle
            if (pass%result(i)%status /= contact_open) then
               if (.not. allocated(x)) then
                  x = current_coordinates(model, u)
                  call faces_around_nodes(size(x, 2), pass%faces, face_start, node_faces)
               end if
               call node_patch(pass, tangential_penalty > 0.0_dp, x, face_start, node_faces, i, patch)
            end if
            if (pass%result(i)%status /= contact_open .and. patch%curved) then
               call complete_tangent(pass, parameters, tangential_penalty > 0.0_dp, x, i, friction_scale, patch, &
                                     patch_tangent)
               call matrix%add_element(patch%block, patch_tangent)
            else if (any(node_tangent /= 0.0_dp)) then
               call matrix%add_element(node%nodes, node_tangent)
            end if
         end associate
      end do
   end subroutine assemble_mortar_pass

   !> Slave node i's patch (mortar_patch_t) at the current positions x (3, n_nodes): the master
   !> faces that overlap one of the node's slave faces (segment_integrals, the pairing of
   !> mortar_rows). Such a face gives the node's current row its nodes, so the candidates are
   !> the master faces around the row's nodes (node_faces(face_start(n) + 1 : face_start(n + 1)),
   !> faces_around_nodes of pass%faces) whose box, widened by twice the band, meets that of the
   !> node's slave faces.
   subroutine node_patch(pass, frictional, x, face_start, node_faces, i, patch)
      type(contact_pass_t), intent(in) :: pass
      logical, intent(in) :: frictional
      real(dp), intent(in) :: x(:, :)
      integer, intent(in) :: face_start(:), node_faces(:)
      integer, intent(in) :: i
      type(mortar_patch_t), intent(out) :: patch
      real(dp) :: low(3), high(3), master_part(4, 4), slave_part(4, 4)
      integer, allocatable :: faces(:), around(:)
      integer :: f, g, k, c, node
      logical :: overlap, paired
      faces = pack([(f, f=1, size(pass%slave_faces, 2))], any(pass%slave_faces == pass%slave_nodes(i), dim=1))
      patch%slave_faces = pass%slave_faces(:, faces)
      allocate (patch%slave_nodes(0), patch%block(0))
      call add_unique(patch%slave_nodes, [pass%slave_nodes(i)])
      call add_unique(patch%slave_nodes, reshape(patch%slave_faces, [size(patch%slave_faces)]))
      patch%j = 1
      low = minval(x(:, patch%slave_nodes), dim=2) - 2.0_dp*pass%band
      high = maxval(x(:, patch%slave_nodes), dim=2) + 2.0_dp*pass%band
      deallocate (faces)
      allocate (faces(0), around(0))
      do k = pass%mortar_rows%start(i) + 1, pass%mortar_rows%start(i + 1)
         node = pass%mortar_rows%nodes(k)
         around = [around, node_faces(face_start(node) + 1:face_start(node + 1))]
      end do
      around = sorted_unique(around)   ! in face order, as the pairing of mortar_rows
      do c = 1, size(around)
         g = around(c)
         if (any(maxval(x(:, pass%faces(:, g)), dim=2) < low) .or. any(minval(x(:, pass%faces(:, g)), dim=2) > high)) &
            cycle
         paired = .false.
         do k = 1, size(patch%slave_faces, 2)
            call segment_integrals(x(:, patch%slave_faces(:, k)), x(:, pass%faces(:, g)), pass%band, master_part, &
                                   slave_part, overlap)
            paired = paired .or. overlap
         end do
         if (paired) faces = [faces, g]
      end do
      patch%master_faces = pass%faces(:, faces)
      patch%curved = faces_turn(x, patch%slave_faces, patch%master_faces)
      patch%block = patch%slave_nodes
      call add_unique(patch%block, reshape(patch%master_faces, [size(patch%master_faces)]))
      if (frictional .and. pass%has_anchor(i)) call add_unique(patch%block, &
         pass%committed_mortar_rows%nodes(pass%committed_mortar_rows%start(i) + 1:pass%committed_mortar_rows%start(i + 1)))
   end subroutine node_patch

   !> Whether the unit normals (at the centres) of two of the slave faces, or of two of the
   !> master faces, differ by more than curved_angle (a surface turning by about h / R from
   !> face to face).
   logical function faces_turn(x, slave_faces, master_faces) result(turn)
      real(dp), intent(in) :: x(:, :)
      integer, intent(in) :: slave_faces(:, :), master_faces(:, :)
      turn = surface_turns(x, slave_faces) .or. surface_turns(x, master_faces)
   end function faces_turn

   !> Whether the unit normals (at the centres) of two of `faces` differ by more than
   !> curved_angle (collapsed faces, of zero normal, compare as parallel).
   logical function surface_turns(x, faces) result(turn)
      real(dp), intent(in) :: x(:, :)
      integer, intent(in) :: faces(:, :)
      real(dp) :: normal(3, size(faces, 2))
      integer :: f, g
      do f = 1, size(faces, 2)
         normal(:, f) = face_normal(x(:, faces(:, f)), [0.0_dp, 0.0_dp])
      end do
      turn = .false.
      do f = 1, size(faces, 2)
         do g = f + 1, size(faces, 2)
            if (norm2(normal(:, f)) == 0.0_dp .or. norm2(normal(:, g)) == 0.0_dp) cycle
            turn = turn .or. dot_product(normal(:, f), normal(:, g)) < cos(curved_angle)
         end do
      end do
   end function surface_turns

   !> list = list and those of `more` not yet in it, in order.
   pure subroutine add_unique(list, more)
      integer, allocatable, intent(inout) :: list(:)
      integer, intent(in) :: more(:)
      integer :: k
      do k = 1, size(more)
         if (findloc(list, more(k), dim=1) == 0) list = [list, more(k)]
      end do
   end subroutine add_unique

   !> The complete tangent of slave node i's internal force on patch%block (the derivatives of
   !> D, M, a_j and n_j included, which the first-order tangent of mortar_node_contact leaves
   !> out; docs/contact.md, "Tangent"), by central differences of the node's force in each
   !> coordinate of the block's nodes.
   subroutine complete_tangent(pass, parameters, frictional, x, i, friction_scale, patch, tangent)
      type(contact_pass_t), intent(in) :: pass
      type(contact_parameters_t), intent(in) :: parameters
      logical, intent(in) :: frictional
      real(dp), intent(in) :: x(:, :)
      integer, intent(in) :: i
      real(dp), intent(in) :: friction_scale
      type(mortar_patch_t), intent(in) :: patch
      real(dp), allocatable, intent(inout) :: tangent(:, :)
      real(dp), allocatable :: moved(:, :), plus(:), minus(:)
      real(dp) :: step
      integer :: b, d, n
      n = 3*size(patch%block)
      if (allocated(tangent)) deallocate (tangent)
      allocate (tangent(n, n), plus(n), minus(n))
      step = relative_step*sqrt(pass%mortar_rows%tributary_area(i))
      moved = x
      do b = 1, size(patch%block)
         do d = 1, 3
            moved(d, patch%block(b)) = x(d, patch%block(b)) + step
            call patch_force(moved, plus)
            moved(d, patch%block(b)) = x(d, patch%block(b)) - step
            call patch_force(moved, minus)
            moved(d, patch%block(b)) = x(d, patch%block(b))
            tangent(:, 3*b - 3 + d) = (plus - minus)/(2.0_dp*step)
         end do
      end do
   contains
      !> Slave node i's internal force on patch%block (3 per node) at positions `at`: its row,
      !> D_j, a_j and n_j from its patch (the node's row depends on its own slave faces only),
      !> evaluated by mortar_node_contact with the node's committed row and traction.
      subroutine patch_force(at, force)
         real(dp), intent(in) :: at(:, :)
         real(dp), intent(out) :: force(:)
         type(mortar_rows_t) :: rows
         type(mortar_node_t) :: node
         type(contact_point_result_t) :: result
         real(dp), allocatable :: node_force(:), node_tangent(:, :)
         integer :: k, position
         call mortar_rows(at, patch%slave_nodes, patch%slave_faces, patch%master_faces, pass%band, rows)
         if (frictional) then
            call mortar_node(rows, patch%j, pass%area(i), node, pass%committed_mortar_rows, &
                             pass%committed_mortar_traction(:, i), pass%has_anchor(i), committed_row=i)
         else
            call mortar_node(rows, patch%j, pass%area(i), node)
         end if
         node%x = at(:, node%nodes)
         allocate (node_force(3*size(node%nodes)), node_tangent(3*size(node%nodes), 3*size(node%nodes)))
         call mortar_node_contact(parameters, node, friction_scale, pass%branch(i), result, node_force, node_tangent)
         force = 0.0_dp
         do k = 1, size(node%nodes)
            position = findloc(patch%block, node%nodes(k), dim=1)
            force(3*position - 2:3*position) = node_force(3*k - 2:3*k)
         end do
      end subroutine patch_force
   end subroutine complete_tangent

   !> Slave node i of `pass` as frix_mortar_contact evaluates it (positions not set); with
   !> friction joined with its committed row and traction where it was closed at the last
   !> converged increment (pass%has_anchor).
   subroutine slave_node(pass, frictional, i, node)
      type(contact_pass_t), intent(in) :: pass
      logical, intent(in) :: frictional
      integer, intent(in) :: i
      type(mortar_node_t), intent(out) :: node
      if (frictional) then
         call mortar_node(pass%mortar_rows, i, pass%area(i), node, pass%committed_mortar_rows, &
                          pass%committed_mortar_traction(:, i), pass%has_anchor(i))
      else
         call mortar_node(pass%mortar_rows, i, pass%area(i), node)
      end if
   end subroutine slave_node

   !> A converged increment at displacements u: the rows there (computed again, as a restart
   !> computes them, restart_mortar_pass, so that a restarted run continues exactly), each
   !> node's traction t_j (per current area: the written traction times A_j / D_j; 0 where
   !> open) and whether it is closed (pass%has_anchor, kept in the restart history) become the
   !> committed ones, and the plastic slip is accumulated.
   subroutine commit_mortar_pass(model, pass, u)
      type(model_t), intent(in) :: model
      type(contact_pass_t), intent(inout) :: pass
      real(dp), intent(in) :: u(:)
      integer :: i
      call restart_mortar_pass(model, pass, u, .true.)
      do i = 1, size(pass%slave_nodes)
         pass%committed_mortar_traction(:, i) = 0.0_dp
         pass%has_anchor(i) = pass%result(i)%status /= contact_open
         if (.not. pass%has_anchor(i)) cycle
         pass%committed_mortar_traction(:, i) = pass%result(i)%traction*pass%area(i)/pass%mortar_rows%dual_area(i)
         pass%slip(i) = pass%slip(i) + pass%result(i)%slip_increment
      end do
   end subroutine commit_mortar_pass

   !> The committed rows of a mortar pass at the committed displacements u (set-up: u = 0; a
   !> restart: the displacements read back), the tractions zero unless kept (`keep_traction`,
   !> restored from the restart history with pass%has_anchor); at the set-up a node the master
   !> covers counts as closed (pass%has_anchor), so that friction acts from the first increment
   !> on bodies touching at the start, as node-to-segment's initial anchors.
   subroutine restart_mortar_pass(model, pass, u, keep_traction)
      type(model_t), intent(in) :: model
      type(contact_pass_t), intent(inout) :: pass
      real(dp), intent(in) :: u(:)
      logical, intent(in) :: keep_traction
      integer :: i
      call mortar_rows(current_coordinates(model, u), pass%slave_nodes, pass%slave_faces, pass%faces, pass%band, &
                       pass%committed_mortar_rows)
      if (.not. keep_traction .or. .not. allocated(pass%committed_mortar_traction)) then
         if (allocated(pass%committed_mortar_traction)) deallocate (pass%committed_mortar_traction)
         allocate (pass%committed_mortar_traction(3, size(pass%slave_nodes)), source=0.0_dp)
         pass%has_anchor = [(mortar_covered(pass%committed_mortar_rows, i), i=1, size(pass%slave_nodes))]
      end if
   end subroutine restart_mortar_pass

   !> X + u (3, n_nodes).
   pure function current_coordinates(model, u) result(x)
      type(model_t), intent(in) :: model
      real(dp), intent(in) :: u(:)
      real(dp) :: x(3, model%mesh%n_nodes)
      x = model%mesh%coords + reshape(u, shape(model%mesh%coords))
   end function current_coordinates
end module frix_mortar_assembly
