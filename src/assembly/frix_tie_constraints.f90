!> Tied contact by elimination (docs/contact.md, "Tied contact"). Each tied slave node s
!> follows the master surface with its dual mortar weights (frix_tie_pass, frix_tie_mortar):
!>
!>     u_s = sum_a w_sa u_a,   per direction c = x, y, z,
!>
!> except in the directions where s has a Dirichlet condition (these keep it). With the map
!> u = T u_r (T the identity but for the dependent equations (s, c), whose rows hold the w_a)
!> the Newton system K du = r becomes T^T K T du_r = T^T r (Felippa, *Introduction to Finite
!> Element Methods*, ch. 9, master-slave elimination), done in place on the full pattern:
!> row (s, c) is added, times w_a, to rows (a, c) and column (s, c) to columns (a, c); the
!> dependent equations are then left with an empty row and column, which the Newton solver
!> treats like fixed ones, and their corrections are recovered as du_s = sum_a w_a du_a.
!> The transformation keeps the matrix symmetric (CHOLMOD still applies) and needs the node
!> pairs (a, n) for every neighbour n of s in the sparse pattern (tie_pattern_pairs).
!> The bond force on the slave, f_s = -r_s before the elimination (r = f_ext - f_int), is the
!> tie's contact force: pressure and traction on the master's normal (record_tie_forces).
module frix_tie_constraints
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_mesh, only: mesh_t
   use frix_sparse_matrix, only: sparse_matrix_t
   use frix_face_projection, only: face_position, face_normal
   use frix_contact_kernel, only: contact_point_result_t, contact_stick
   use frix_contact_pass, only: contact_pass_t
   use frix_contact_search, only: current_nodes
   use frix_tie_pass, only: tie_masters, tie_weights
   implicit none
   private

   public :: check_tie_nodes, tie_pattern_pairs, dependent_equations
   public :: condense_matrix, condense_vector, expand_vector, record_tie_forces

contains

   !> An error when a node is tied twice (slave of two ties) or is a tied slave and the master
   !> node of a tie (chains of ties are not eliminated); `tie_ids` are the deck ids of the
   !> passes' pairs; `culprit`, if present, the pass whose tie the error is about (0 without one).
   subroutine check_tie_nodes(mesh, passes, tie_ids, error, culprit)
      type(mesh_t), intent(in) :: mesh
      type(contact_pass_t), intent(in) :: passes(:)
      integer, intent(in) :: tie_ids(:)
      type(error_t), allocatable, intent(out) :: error
      integer, intent(out), optional :: culprit
      integer, allocatable :: slave_of(:), master_of(:)
      integer :: p, i, node
      if (present(culprit)) culprit = 0
      allocate (slave_of(mesh%n_nodes), master_of(mesh%n_nodes), source=0)
      do p = 1, size(passes)
         if (.not. passes(p)%tied) cycle
         do i = 1, size(passes(p)%slave_nodes)
            if (passes(p)%face(i) == 0) cycle
            node = passes(p)%slave_nodes(i)
            if (slave_of(node) > 0) then
               call fatal_error(error, 'TIE '//to_string(tie_ids(p))//': node '//to_string(mesh%node_ids(node))// &
                                ' is already a slave node of TIE '//to_string(tie_ids(slave_of(node)))// &
                                ' (a node can be tied once)')
               if (present(culprit)) culprit = p
               return
            end if
            slave_of(node) = p
            master_of(tie_masters(passes(p), i)) = p
         end do
      end do
      node = findloc(slave_of > 0 .and. master_of > 0, .true., dim=1)
      if (node == 0) return
      call fatal_error(error, 'TIE '//to_string(tie_ids(slave_of(node)))//': node '// &
                       to_string(mesh%node_ids(node))//' is a slave node and a master node of TIE '// &
                       to_string(tie_ids(master_of(node)))//' (chained ties are not supported)')
      if (present(culprit)) culprit = slave_of(node)
   end subroutine check_tie_nodes

   !> The node pairs the elimination needs in the sparse pattern, from the mesh's element
   !> connectivity: (a, n) for every master node a of a tied slave s and every node n of an
   !> element at s, and (a, b) when n is itself a tied slave with master node b. Pairs that
   !> contact adds later at a tied slave are not foreseen: condense_matrix reports them.
   subroutine tie_pattern_pairs(mesh, passes, pairs)
      type(mesh_t), intent(in) :: mesh
      type(contact_pass_t), intent(in) :: passes(:)
      integer, allocatable, intent(out) :: pairs(:, :)   !! (2, n)
      integer, allocatable :: pass_of(:), index_of(:)
      integer :: e, k, l, n_pairs
      call tied_slaves(mesh%n_nodes, passes, pass_of, index_of)
      allocate (pairs(2, 64))
      n_pairs = 0
      do e = 1, mesh%n_elements
         associate (nodes => mesh%connectivity(:, e))
            do k = 1, size(nodes)
               if (nodes(k) == 0) cycle
               if (pass_of(nodes(k)) == 0) cycle
               do l = 1, size(nodes)
                  if (nodes(l) == 0) cycle
                  call add_pairs(masters_of(nodes(k)), [nodes(l)])
                  if (pass_of(nodes(l)) > 0) call add_pairs(masters_of(nodes(k)), masters_of(nodes(l)))
               end do
            end do
         end associate
      end do
      pairs = pairs(:, :n_pairs)
   contains
      function masters_of(node) result(nodes)
         integer, intent(in) :: node
         integer, allocatable :: nodes(:)
         nodes = tie_masters(passes(pass_of(node)), index_of(node))
      end function masters_of

      subroutine add_pairs(first, second)
         integer, intent(in) :: first(:), second(:)
         integer, allocatable :: grown(:, :)
         integer :: i, j
         do i = 1, size(first)
            do j = 1, size(second)
               if (n_pairs == size(pairs, 2)) then
                  allocate (grown(2, 2*n_pairs))
                  grown(:, :n_pairs) = pairs(:, :n_pairs)
                  call move_alloc(grown, pairs)
               end if
               n_pairs = n_pairs + 1
               pairs(:, n_pairs) = [first(i), second(j)]
            end do
         end do
      end subroutine add_pairs
   end subroutine tie_pattern_pairs

   !> For every mesh node that is a tied slave: its pass and its index there (0 elsewhere).
   subroutine tied_slaves(n_nodes, passes, pass_of, index_of)
      integer, intent(in) :: n_nodes
      type(contact_pass_t), intent(in) :: passes(:)
      integer, allocatable, intent(out) :: pass_of(:), index_of(:)
      integer :: p, i
      allocate (pass_of(n_nodes), index_of(n_nodes), source=0)
      do p = 1, size(passes)
         if (.not. passes(p)%tied) cycle
         do i = 1, size(passes(p)%slave_nodes)
            if (passes(p)%face(i) == 0) cycle
            pass_of(passes(p)%slave_nodes(i)) = p
            index_of(passes(p)%slave_nodes(i)) = i
         end do
      end do
   end subroutine tied_slaves

   !> dependent(e) for every equation eliminated by a tie: a tied slave's direction without a
   !> Dirichlet condition (`fixed`).
   subroutine dependent_equations(passes, fixed, dependent)
      type(contact_pass_t), intent(in) :: passes(:)
      logical, intent(in) :: fixed(:)
      logical, intent(out) :: dependent(:)
      integer :: p, i, s
      dependent = .false.
      do p = 1, size(passes)
         if (.not. passes(p)%tied) cycle
         do i = 1, size(passes(p)%slave_nodes)
            if (passes(p)%face(i) == 0) cycle
            s = passes(p)%slave_nodes(i)
            dependent(3*s - 2:3*s) = .not. fixed(3*s - 2:3*s)
         end do
      end do
   end subroutine dependent_equations

   !> v <- T^T v: v(a, c) += w_a v(s, c), v(s, c) = 0 for every dependent equation (s, c).
   subroutine condense_vector(passes, dependent, v)
      type(contact_pass_t), intent(in) :: passes(:)
      logical, intent(in) :: dependent(:)
      real(dp), intent(inout) :: v(:)
      integer :: p, i, s, c, a
      do p = 1, size(passes)
         if (.not. passes(p)%tied) cycle
         do i = 1, size(passes(p)%slave_nodes)
            if (passes(p)%face(i) == 0) cycle
            s = passes(p)%slave_nodes(i)
            associate (masters => tie_masters(passes(p), i), weights => tie_weights(passes(p), i))
               do c = 1, 3
                  if (.not. dependent(3*s - 3 + c)) cycle
                  do a = 1, size(masters)
                     v(3*masters(a) - 3 + c) = v(3*masters(a) - 3 + c) + weights(a)*v(3*s - 3 + c)
                  end do
                  v(3*s - 3 + c) = 0.0_dp
               end do
            end associate
         end do
      end do
   end subroutine condense_vector

   !> v <- T v: v(s, c) = sum_a w_a v(a, c) for every dependent equation (s, c) (a correction
   !> of the eliminated system extended to the slave nodes, or a displacement made to satisfy
   !> the ties).
   subroutine expand_vector(passes, dependent, v)
      type(contact_pass_t), intent(in) :: passes(:)
      logical, intent(in) :: dependent(:)
      real(dp), intent(inout) :: v(:)
      integer :: p, i, s, c
      do p = 1, size(passes)
         if (.not. passes(p)%tied) cycle
         do i = 1, size(passes(p)%slave_nodes)
            if (passes(p)%face(i) == 0) cycle
            s = passes(p)%slave_nodes(i)
            associate (masters => tie_masters(passes(p), i), weights => tie_weights(passes(p), i))
               do c = 1, 3
                  if (dependent(3*s - 3 + c)) v(3*s - 3 + c) = dot_product(weights, v(3*masters - 3 + c))
               end do
            end associate
         end do
      end do
   end subroutine expand_vector

   !> K <- T^T K T on the full pattern, in place (module header): all row operations first,
   !> then the column operations, so that K(a, b) receives w_a w_b K(s, s') for pairs of tied
   !> slaves. The dependent rows and columns are left zero. Error: a node pair the elimination
   !> needs is not in the pattern (a tied slave node also in a contact kernel).
   subroutine condense_matrix(passes, dependent, matrix, error)
      type(contact_pass_t), intent(in) :: passes(:)
      logical, intent(in) :: dependent(:)
      type(sparse_matrix_t), intent(inout) :: matrix
      type(error_t), allocatable, intent(out) :: error
      call move_dependent(passes, dependent, matrix, .true., error)
      if (.not. allocated(error)) call move_dependent(passes, dependent, matrix, .false., error)
   end subroutine condense_matrix

   !> The rows (`rows`) or the columns of every dependent equation moved onto its masters'.
   subroutine move_dependent(passes, dependent, matrix, rows, error)
      type(contact_pass_t), intent(in) :: passes(:)
      logical, intent(in) :: dependent(:), rows
      type(sparse_matrix_t), intent(inout) :: matrix
      type(error_t), allocatable, intent(inout) :: error
      integer :: p, i, s, c
      do p = 1, size(passes)
         if (.not. passes(p)%tied) cycle
         do i = 1, size(passes(p)%slave_nodes)
            if (passes(p)%face(i) == 0) cycle
            s = passes(p)%slave_nodes(i)
            if (.not. any(dependent(3*s - 2:3*s))) cycle
            associate (first => passes(p)%tie%start(i) + 1, last => passes(p)%tie%start(i + 1))
               do c = 1, 3
                  if (.not. dependent(3*s - 3 + c)) cycle
                  if (rows) then
                     call move_row(matrix, s, c, passes(p)%tie%nodes(first:last), passes(p)%tie%weight(first:last), &
                                   error)
                  else
                     call move_column(matrix, s, c, passes(p)%tie%nodes(first:last), &
                                      passes(p)%tie%weight(first:last), error)
                  end if
                  if (allocated(error)) return
               end do
            end associate
         end do
      end do
   end subroutine move_dependent

   !> Row (s, c) times w_a added to rows (a, c), then zeroed. The columns holding row s are
   !> those of s's neighbours n (the pattern is structurally symmetric).
   subroutine move_row(matrix, s, c, masters, weights, error)
      type(sparse_matrix_t), intent(inout) :: matrix
      integer, intent(in) :: s, c, masters(:)
      real(dp), intent(in) :: weights(:)
      type(error_t), allocatable, intent(inout) :: error
      integer :: k, n, i, a, source, target, k_master
      real(dp) :: value
      do k = matrix%node_ptr(s), matrix%node_ptr(s + 1) - 1
         n = matrix%node_adj(k)
         do i = 1, 3
            source = matrix%entry_position(n, matrix%neighbour_index(n, s), i, c)
            value = matrix%values(source)
            if (value == 0.0_dp) cycle
            do a = 1, size(masters)
               k_master = matrix%neighbour_index(n, masters(a))
               if (k_master == 0) then
                  call missing_pair(masters(a), n, error)
                  return
               end if
               target = matrix%entry_position(n, k_master, i, c)
               matrix%values(target) = matrix%values(target) + weights(a)*value
            end do
            matrix%values(source) = 0.0_dp
         end do
      end do
   end subroutine move_row

   !> Column (s, c) times w_a added to columns (a, c), then zeroed.
   subroutine move_column(matrix, s, c, masters, weights, error)
      type(sparse_matrix_t), intent(inout) :: matrix
      integer, intent(in) :: s, c, masters(:)
      real(dp), intent(in) :: weights(:)
      type(error_t), allocatable, intent(inout) :: error
      integer :: k, m, j, a, source, target, k_master
      real(dp) :: value
      do k = 1, matrix%node_ptr(s + 1) - matrix%node_ptr(s)
         m = matrix%node_adj(matrix%node_ptr(s) + k - 1)
         do j = 1, 3
            source = matrix%entry_position(s, k, c, j)
            value = matrix%values(source)
            if (value == 0.0_dp) cycle
            do a = 1, size(masters)
               k_master = matrix%neighbour_index(masters(a), m)
               if (k_master == 0) then
                  call missing_pair(masters(a), m, error)
                  return
               end if
               target = matrix%entry_position(masters(a), k_master, c, j)
               matrix%values(target) = matrix%values(target) + weights(a)*value
            end do
            matrix%values(source) = 0.0_dp
         end do
      end do
   end subroutine move_column

   subroutine missing_pair(first, second, error)
      integer, intent(in) :: first, second
      type(error_t), allocatable, intent(inout) :: error
      call fatal_error(error, 'tie: the node pair ('//to_string(first)//', '//to_string(second)// &
                       ') is not in the sparse pattern (a tied slave node in a contact pair as well?)')
   end subroutine missing_pair

   !> The bond force of every tied slave node from the residual r = f_ext - f_int before the
   !> elimination: f = -r on its dependent equations (0 in Dirichlet directions), written as
   !> the node's contact result: pressure p = f . n / A_s (compressive positive, negative in
   !> tension), tangential traction (f - (f . n) n) / A_s, n the master face's normal at the
   !> foot point (current), gap (x_s - x(xi_T)) . n, status stick.
   subroutine record_tie_forces(coords, u, dependent, residual, passes)
      real(dp), intent(in) :: coords(:, :), u(:)
      logical, intent(in) :: dependent(:)
      real(dp), intent(in) :: residual(:)
      type(contact_pass_t), intent(inout) :: passes(:)
      real(dp) :: x_face(3, 4), force(3), normal(3), x_slave(3)
      integer :: p, i, s
      do p = 1, size(passes)
         if (.not. passes(p)%tied) cycle
         associate (pass => passes(p))
            do i = 1, size(pass%slave_nodes)
               pass%result(i) = contact_point_result_t()
               if (pass%face(i) == 0) cycle
               s = pass%slave_nodes(i)
               x_face = current_nodes(coords, u, pass%faces(:, pass%face(i)))
               x_slave = coords(:, s) + u(3*s - 2:3*s)
               normal = face_normal(x_face, pass%anchor_xi(:, i))
               force = merge(-residual(3*s - 2:3*s), 0.0_dp, dependent(3*s - 2:3*s))
               pass%result(i)%pressure = dot_product(force, normal)/pass%area(i)
               pass%result(i)%traction = (force - dot_product(force, normal)*normal)/pass%area(i)
               pass%result(i)%normal = normal
               pass%result(i)%xi = pass%anchor_xi(:, i)
               pass%result(i)%gap = dot_product(x_slave - face_position(x_face, pass%anchor_xi(:, i)), normal)
               pass%result(i)%status = contact_stick
               pass%result(i)%law_status = contact_stick
               pass%result(i)%new_anchor_xi = pass%anchor_xi(:, i)
            end do
         end associate
      end do
   end subroutine record_tie_forces
end module frix_tie_constraints
