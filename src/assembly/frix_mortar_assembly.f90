!> Mortar contact passes (DISCRETIZATION Mortar; docs/contact.md, "Mortar contact") in the
!> global system: at every Newton iteration the mortar rows of the slave nodes at the current
!> positions (frix_mortar_contact, run by frix_contact_assembly's search_contact), the node
!> pairs they need in the sparse pattern, and each slave node's forces and tangent assembled
!> into fint and the matrix (frix_contact_assembly's assemble_contact). In the predictor a
!> touching node (0 <= g_j / D_j <= GAPTOL) gets the stiffness k_N / D_j (c n_j)(c n_j)^T
!> without force, as a touching node of node-to-segment contact.
module frix_mortar_assembly
   use frix_kinds, only: dp
   use frix_model, only: model_t
   use frix_sparse_matrix, only: sparse_matrix_t
   use frix_contact_pass, only: contact_pass_t
   use frix_contact_parameters, only: contact_parameters_t
   use frix_contact_kernel, only: contact_point_result_t, contact_open
   use frix_mortar_contact, only: mortar_rows, mortar_node_contact, mortar_row_stiffness, least_mortar_coverage
   implicit none
   private

   public :: search_mortar_pass, assemble_mortar_pass

contains

   !> The mortar rows of `pass` at displacements u (current configuration), pass%face(i) a
   !> master face overlapping slave i's faces (0: none), and the node pairs (2, n_missing) of
   !> the rows of the covered slave nodes that `matrix`'s pattern lacks.
   subroutine search_mortar_pass(model, pass, u, matrix, missing, n_missing)
      type(model_t), intent(in) :: model
      type(contact_pass_t), intent(inout) :: pass
      real(dp), intent(in) :: u(:)
      type(sparse_matrix_t), intent(in) :: matrix
      integer, allocatable, intent(out) :: missing(:, :)
      integer, intent(out) :: n_missing
      integer :: i, a, b
      call mortar_rows(model%mesh%coords + reshape(u, shape(model%mesh%coords)), pass%slave_nodes, pass%slave_faces, &
                       pass%faces, pass%band, pass%mortar_rows)
      pass%face = pass%mortar_rows%master_face
      allocate (missing(2, 64))
      n_missing = 0
      associate (rows => pass%mortar_rows)
         do i = 1, size(pass%slave_nodes)
            if (.not. rows%dual_area(i) >= least_mortar_coverage*pass%area(i)) cycle
            associate (nodes => rows%nodes(rows%start(i) + 1:rows%start(i + 1)))
               do a = 1, size(nodes)
                  do b = a + 1, size(nodes)
                     if (matrix%neighbour_index(nodes(a), nodes(b)) /= 0) cycle
                     if (n_missing == size(missing, 2)) missing = reshape(missing, [2, 2*n_missing], pad=[0])
                     n_missing = n_missing + 1
                     missing(:, n_missing) = [nodes(a), nodes(b)]
                  end do
               end do
            end associate
         end do
      end associate
   end subroutine search_mortar_pass

   !> Add the forces and (if `matrix` is present) tangents of the slave nodes of mortar pass
   !> `pass` at displacements u; `touching`: the predictor's touching stiffness.
   subroutine assemble_mortar_pass(model, pass, parameters, u, touching, fint, matrix)
      type(model_t), intent(in) :: model
      type(contact_pass_t), intent(inout) :: pass
      type(contact_parameters_t), intent(in) :: parameters
      real(dp), intent(in) :: u(:)
      logical, intent(in) :: touching
      real(dp), intent(inout) :: fint(:)
      type(sparse_matrix_t), intent(inout), optional :: matrix
      real(dp), allocatable :: x(:, :), force(:), tangent(:, :)
      integer :: i, k, node
      associate (rows => pass%mortar_rows)
         do i = 1, size(pass%slave_nodes)
            if (pass%face(i) == 0) then
               pass%result(i) = contact_point_result_t()
               pass%result(i)%gap = huge(1.0_dp)
               cycle
            end if
            associate (nodes => rows%nodes(rows%start(i) + 1:rows%start(i + 1)))
               x = model%mesh%coords(:, nodes)
               do k = 1, size(nodes)
                  x(:, k) = x(:, k) + u(3*nodes(k) - 2:3*nodes(k))
               end do
               if (allocated(force)) deallocate (force, tangent)
               allocate (force(3*size(nodes)), tangent(3*size(nodes), 3*size(nodes)))
               call mortar_node_contact(parameters%normal, rows, i, x, pass%area(i), pass%result(i), force, tangent)
               if (touching .and. pass%result(i)%status == contact_open .and. pass%result(i)%gap >= 0.0_dp .and. &
                   pass%result(i)%gap <= parameters%gap_tolerance) &
                  tangent = tangent + mortar_row_stiffness(rows, i, parameters%normal%stiffness()/rows%dual_area(i))
               do k = 1, size(nodes)
                  node = nodes(k)
                  fint(3*node - 2:3*node) = fint(3*node - 2:3*node) + force(3*k - 2:3*k)
               end do
               if (present(matrix)) call matrix%add_element(nodes, tangent)
            end associate
         end do
      end associate
   end subroutine assemble_mortar_pass
end module frix_mortar_assembly
