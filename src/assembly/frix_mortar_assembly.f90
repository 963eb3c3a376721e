!> Mortar contact passes (DISCRETIZATION Mortar; docs/contact.md, "Mortar contact") in the
!> global system: at every Newton iteration the mortar rows of the slave nodes at the current
!> positions (frix_mortar_contact, run by frix_contact_assembly's search_contact), the node
!> pairs they need in the sparse pattern, each slave node's forces and tangent assembled into
!> fint and the matrix (frix_contact_assembly's assemble_contact), and with friction the
!> committed rows and tractions (commit, restart). In the predictor a touching node
!> (0 <= g_j / D_j <= GAPTOL) gets the stiffness (1 / D_j) c c^T (k_N n n + eps_T (I - n n))
!> without force (eps_T only with friction), as a touching node of node-to-segment contact.
module frix_mortar_assembly
   use frix_kinds, only: dp
   use frix_model, only: model_t
   use frix_system_matrix, only: system_matrix_t
   use frix_contact_pass, only: contact_pass_t
   use frix_contact_parameters, only: contact_parameters_t
   use frix_contact_kernel, only: contact_point_result_t, contact_open, add_touching_stiffness
   use frix_mortar_contact, only: mortar_rows, mortar_node_t, mortar_node, mortar_node_contact, mortar_covered
   implicit none
   private

   public :: search_mortar_pass, assemble_mortar_pass, commit_mortar_pass, restart_mortar_pass

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
      type(mortar_node_t) :: node
      integer :: i, a, b
      call mortar_rows(current_coordinates(model, u), pass%slave_nodes, pass%slave_faces, pass%faces, pass%band, &
                       pass%mortar_rows)
      pass%face = pass%mortar_rows%master_face
      allocate (missing(2, 64))
      n_missing = 0
      do i = 1, size(pass%slave_nodes)
         ! a node the master does not cover enough is open: no face (its results are not
         ! written, as for a node-to-segment node without a face)
         if (.not. mortar_covered(pass%mortar_rows, i)) pass%face(i) = 0
         if (pass%face(i) == 0) cycle
         call slave_node(pass, frictional, i, node)
         do a = 1, size(node%nodes)
            do b = a + 1, size(node%nodes)
               if (matrix%couples(node%nodes(a), node%nodes(b))) cycle
               if (n_missing == size(missing, 2)) missing = reshape(missing, [2, 2*n_missing], pad=[0])
               n_missing = n_missing + 1
               missing(:, n_missing) = [node%nodes(a), node%nodes(b)]
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
      real(dp), allocatable :: force(:), tangent(:, :)
      real(dp) :: tangential_penalty
      integer :: i, k, n
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
            call mortar_node_contact(parameters, node, friction_scale, pass%branch(i), pass%result(i), node_force, &
                                     node_tangent)
            if (touching .and. pass%result(i)%status == contact_open .and. pass%result(i)%gap >= 0.0_dp .and. &
                pass%result(i)%gap <= parameters%gap_tolerance) &
               call add_touching_stiffness(1.0_dp/node%dual_area, parameters%normal%stiffness(), tangential_penalty, &
                                           node%normal, node%weight, node_tangent)
            do k = 1, n
               fint(3*node%nodes(k) - 2:3*node%nodes(k)) = fint(3*node%nodes(k) - 2:3*node%nodes(k)) + &
                                                           node_force(3*k - 2:3*k)
            end do
            ! an open node's zero block is not added (its node pairs may lie outside the pattern)
            if (present(matrix) .and. any(node_tangent /= 0.0_dp)) call matrix%add_element(node%nodes, node_tangent)
         end associate
      end do
   end subroutine assemble_mortar_pass

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
