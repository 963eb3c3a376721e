!> Linear constraint equations eliminated from the Newton system: each constraint row makes a
!> global equation e (node-major, 3 per node) depend on master equations m_k,
!>
!>     u_e = sum_k w_k u_(m_k),
!>
!> a tie's slave direction on the master face's nodes in the same direction (frix_tie_constraints),
!> a coupled node's direction on its coupling's reference and rotation nodes
!> (frix_kinematic_coupling). With the map u = T u_r (T the identity but for the dependent
!> equations, whose rows hold the w_k) the Newton system K du = r becomes T^T K T du_r = T^T r
!> (Felippa, *Introduction to Finite Element Methods*, ch. 9, master-slave elimination), done in
!> place on the full pattern: row e is added, times w_k, to rows m_k and column e to columns
!> m_k; the dependent equations are then left with an empty row and column, which the Newton
!> solver treats like fixed ones, and their corrections are recovered as du_e = sum_k w_k du_(m_k).
!> The transformation keeps the matrix symmetric and needs the node pairs (node of m_k, n) for
!> every neighbour n of e's node in the sparse pattern (pattern_pairs; for pairs added later by
!> the contact search, master_nodes). A row acts only where
!> its equation has no Dirichlet condition (`dependent`); masters must not be dependent
!> themselves (no chains), which the callers check.
module frix_constraint_equations
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_system_matrix, only: system_matrix_t
   implicit none
   private

   public :: constraint_equations_t

   !> The constraint rows in compressed form: row r makes equation(r) depend on
   !> master(start(r)+1:start(r+1)) with weight(start(r)+1:start(r+1)).
   type :: constraint_equations_t
      integer :: n_rows = 0
      integer, allocatable :: equation(:)
      integer, allocatable :: start(:)
      integer, allocatable :: master(:)
      real(dp), allocatable :: weight(:)
   contains
      procedure :: add_row
      procedure :: empty
      procedure :: dependent_equations
      procedure :: condense_vector
      procedure :: expand_vector
      procedure :: condense_matrix
      procedure :: pattern_pairs
      procedure :: master_nodes
   end type constraint_equations_t

contains

   !> Append the row u_equation = sum_k weights(k) u_masters(k).
   subroutine add_row(self, equation, masters, weights)
      class(constraint_equations_t), intent(inout) :: self
      integer, intent(in) :: equation, masters(:)
      real(dp), intent(in) :: weights(:)
      integer :: n_terms
      if (.not. allocated(self%equation)) then
         allocate (self%equation(16), self%start(17), self%master(64), self%weight(64))
         self%start(1) = 0
      end if
      if (self%n_rows == size(self%equation)) then
         self%equation = [self%equation, self%equation]
         self%start = [self%start, self%start(2:)]
      end if
      n_terms = self%start(self%n_rows + 1)
      do while (n_terms + size(masters) > size(self%master))
         self%master = [self%master, self%master]
         self%weight = [self%weight, self%weight]
      end do
      self%n_rows = self%n_rows + 1
      self%equation(self%n_rows) = equation
      self%master(n_terms + 1:n_terms + size(masters)) = masters
      self%weight(n_terms + 1:n_terms + size(masters)) = weights
      self%start(self%n_rows + 1) = n_terms + size(masters)
   end subroutine add_row

   !> Whether there is no row.
   pure logical function empty(self)
      class(constraint_equations_t), intent(in) :: self
      empty = self%n_rows == 0
   end function empty

   !> dependent(e) for every equation a row eliminates: those without a Dirichlet condition
   !> (`fixed`).
   subroutine dependent_equations(self, fixed, dependent)
      class(constraint_equations_t), intent(in) :: self
      logical, intent(in) :: fixed(:)
      logical, intent(out) :: dependent(:)
      integer :: r
      dependent = .false.
      do r = 1, self%n_rows
         dependent(self%equation(r)) = .not. fixed(self%equation(r))
      end do
   end subroutine dependent_equations

   !> v <- T^T v: v(m_k) += w_k v(e), v(e) = 0 for every dependent equation e, row by row.
   subroutine condense_vector(self, dependent, v)
      class(constraint_equations_t), intent(in) :: self
      logical, intent(in) :: dependent(:)
      real(dp), intent(inout) :: v(:)
      integer :: r, k
      do r = 1, self%n_rows
         associate (e => self%equation(r))
            if (.not. dependent(e)) cycle
            do k = self%start(r) + 1, self%start(r + 1)
               v(self%master(k)) = v(self%master(k)) + self%weight(k)*v(e)
            end do
            v(e) = 0.0_dp
         end associate
      end do
   end subroutine condense_vector

   !> v <- T v: v(e) = sum_k w_k v(m_k) for every dependent equation e (a correction of the
   !> eliminated system extended to the dependent equations, or a displacement made to satisfy
   !> the constraints).
   subroutine expand_vector(self, dependent, v)
      class(constraint_equations_t), intent(in) :: self
      logical, intent(in) :: dependent(:)
      real(dp), intent(inout) :: v(:)
      integer :: r
      do r = 1, self%n_rows
         if (.not. dependent(self%equation(r))) cycle
         associate (masters => self%master(self%start(r) + 1:self%start(r + 1)), &
                    weights => self%weight(self%start(r) + 1:self%start(r + 1)))
            v(self%equation(r)) = dot_product(weights, v(masters))
         end associate
      end do
   end subroutine expand_vector

   !> K <- T^T K T on the full pattern, in place (module header): all row operations first,
   !> then the column operations, so that K(m, m') receives w w' K(e, e') for pairs of dependent
   !> equations. The dependent rows and columns are left zero. Error: a node pair the
   !> elimination needs is not in the pattern (a constrained node also in a contact kernel).
   subroutine condense_matrix(self, dependent, matrix, error)
      class(constraint_equations_t), intent(in) :: self
      logical, intent(in) :: dependent(:)
      class(system_matrix_t), intent(inout) :: matrix
      type(error_t), allocatable, intent(out) :: error
      call move_dependent(self, dependent, matrix, .true., error)
      if (.not. allocated(error)) call move_dependent(self, dependent, matrix, .false., error)
   end subroutine condense_matrix

   !> The rows (`rows`) or the columns of every dependent equation moved onto its masters'.
   subroutine move_dependent(self, dependent, matrix, rows, error)
      type(constraint_equations_t), intent(in) :: self
      logical, intent(in) :: dependent(:), rows
      class(system_matrix_t), intent(inout) :: matrix
      type(error_t), allocatable, intent(inout) :: error
      integer :: r, missing(2)
      do r = 1, self%n_rows
         if (.not. dependent(self%equation(r))) cycle
         associate (masters => self%master(self%start(r) + 1:self%start(r + 1)), &
                    weights => self%weight(self%start(r) + 1:self%start(r + 1)))
            call matrix%move_equation(self%equation(r), masters, weights, rows, missing)
         end associate
         if (missing(1) /= 0) then
            call missing_pair(missing(1), missing(2), error)
            return
         end if
      end do
   end subroutine move_dependent

   !> Node of global equation e (3 DOFs per node).
   elemental integer function node_of(e)
      integer, intent(in) :: e
      node_of = (e + 2)/3
   end function node_of

   subroutine missing_pair(first, second, error)
      integer, intent(in) :: first, second
      type(error_t), allocatable, intent(inout) :: error
      call fatal_error(error, 'constraint elimination: the node pair ('//to_string(first)//', '// &
                       to_string(second)//') is not in the sparse pattern')
   end subroutine missing_pair

   !> The node pairs the elimination needs in the sparse pattern, from the element connectivity
   !> (`connectivity(:, e)`, 0 for no node): (a, n) for every master node a of a constrained node
   !> s and every node n of an element at s, and (a, b) when n is itself constrained with master
   !> node b. Every row is counted, whatever the Dirichlet conditions. Pairs that contact adds
   !> later at a constrained node come with their masters' through master_nodes
   !> (frix_contact_assembly); a missing pair is reported by condense_matrix.
   subroutine pattern_pairs(self, n_nodes, connectivity, pairs)
      class(constraint_equations_t), intent(in) :: self
      integer, intent(in) :: n_nodes, connectivity(:, :)
      integer, allocatable, intent(out) :: pairs(:, :)   !! (2, n)
      integer, allocatable :: first(:), masters(:)
      integer :: e, k, l, n_pairs
      allocate (pairs(2, 0))
      if (self%n_rows == 0) return
      call master_nodes(self, n_nodes, first, masters)
      deallocate (pairs)
      allocate (pairs(2, 64))
      n_pairs = 0
      do e = 1, size(connectivity, 2)
         associate (nodes => connectivity(:, e))
            do k = 1, size(nodes)
               if (nodes(k) == 0) cycle
               if (first(nodes(k)) == first(nodes(k) + 1)) cycle
               do l = 1, size(nodes)
                  if (nodes(l) == 0) cycle
                  call add_pairs(masters(first(nodes(k)) + 1:first(nodes(k) + 1)), [nodes(l)])
                  call add_pairs(masters(first(nodes(k)) + 1:first(nodes(k) + 1)), &
                                 masters(first(nodes(l)) + 1:first(nodes(l) + 1)))
               end do
            end do
         end associate
      end do
      pairs = pairs(:, :n_pairs)
   contains
      subroutine add_pairs(left, right)
         integer, intent(in) :: left(:), right(:)
         integer, allocatable :: grown(:, :)
         integer :: i, j
         do i = 1, size(left)
            do j = 1, size(right)
               if (n_pairs == size(pairs, 2)) then
                  allocate (grown(2, 2*n_pairs))
                  grown(:, :n_pairs) = pairs(:, :n_pairs)
                  call move_alloc(grown, pairs)
               end if
               n_pairs = n_pairs + 1
               pairs(:, n_pairs) = [left(i), right(j)]
            end do
         end do
      end subroutine add_pairs
   end subroutine pattern_pairs

   !> For every node, the distinct master nodes of its rows: masters(first(s)+1:first(s+1))
   !> (none for a node without rows; `masters` empty without any row).
   subroutine master_nodes(self, n_nodes, first, masters)
      class(constraint_equations_t), intent(in) :: self
      integer, intent(in) :: n_nodes
      integer, allocatable, intent(out) :: first(:), masters(:)
      integer, allocatable :: rows_of(:), row_list(:), fill(:)
      integer :: r, s, k, a, n_masters
      if (self%n_rows == 0) then
         allocate (first(n_nodes + 1), source=0)
         allocate (masters(0))
         return
      end if
      ! the rows of each node (CSR), then their master nodes without repetition
      allocate (rows_of(n_nodes + 1), source=0)
      do r = 1, self%n_rows
         s = node_of(self%equation(r))
         rows_of(s + 1) = rows_of(s + 1) + 1
      end do
      do s = 1, n_nodes
         rows_of(s + 1) = rows_of(s + 1) + rows_of(s)
      end do
      allocate (row_list(rows_of(n_nodes + 1)))
      fill = rows_of(:n_nodes)
      do r = 1, self%n_rows
         s = node_of(self%equation(r))
         fill(s) = fill(s) + 1
         row_list(fill(s)) = r
      end do
      allocate (first(n_nodes + 1), masters(self%start(self%n_rows + 1)))
      first(1) = 0
      n_masters = 0
      do s = 1, n_nodes
         do k = rows_of(s) + 1, rows_of(s + 1)
            r = row_list(k)
            do a = self%start(r) + 1, self%start(r + 1)
               if (any(masters(first(s) + 1:n_masters) == node_of(self%master(a)))) cycle
               n_masters = n_masters + 1
               masters(n_masters) = node_of(self%master(a))
            end do
         end do
         first(s + 1) = n_masters
      end do
      masters = masters(:n_masters)
   end subroutine master_nodes
end module frix_constraint_equations
