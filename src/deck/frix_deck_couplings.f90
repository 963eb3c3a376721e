!> The COUPLINGS section (docs/deck-format.md, docs/couplings.md): kinematic (rigid) couplings
!> of a surface's or a node set's nodes to a reference node and a rotation node,
!>
!>     COUPLING <id> KINEMATIC SURFACE|SET <name> REF_NODE <id> ROT_NODE <id>
!>
!> and their checks against each other, the Dirichlet conditions and the contact conditions
!> (read before it): the elimination (frix_constraint_equations) admits no chains, so a
!> coupled node is coupled once and is neither a reference or rotation node, nor on a surface
!> of a TIE, nor prescribed by a Dirichlet condition (contact PAIRs may hold coupled nodes).
module frix_deck_couplings
   use frix_strings, only: to_string
   use frix_mesh_checks, only: find_orphan_nodes
   use frix_mesh_selection, only: sorted_unique
   use frix_model, only: model_t, kinematic_coupling_t
   use frix_deck_tokens, only: deck_line_t
   use frix_deck_context, only: deck_reader_t, s_couplings
   implicit none
   private

   public :: read_couplings

contains

   !> Every COUPLING line into model%couplings; a line with a mistake is reported and left out.
   subroutine read_couplings(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(kinematic_coupling_t) :: coupling
      integer :: i, position
      logical :: ok
      allocate (model%couplings(0))
      i = 0
      do while (reader%next_line(s_couplings, i, position, ok))
         associate (line => reader%lines(i))
            call read_coupling_line(reader, model, line, position, coupling, ok)
            if (ok) call check_roles(reader, model, line, coupling, ok)
            if (ok) call check_coupled_nodes(reader, model, line, coupling, ok)
            if (.not. ok) cycle
            coupling%line = line%number
            model%couplings = [model%couplings, coupling]
         end associate
      end do
   end subroutine read_couplings

   !> The tokens of one line: id, KINEMATIC, the coupled nodes, REF_NODE, ROT_NODE.
   subroutine read_coupling_line(reader, model, line, position, coupling, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      type(kinematic_coupling_t), intent(out) :: coupling
      logical, intent(inout) :: ok
      integer :: k
      call reader%expect_keyword(line, position, 'COUPLING', ok)
      call reader%take_integer(line, position, 'a coupling id', coupling%id, ok)
      if (.not. ok) return
      do k = 1, size(model%couplings)
         if (model%couplings(k)%id /= coupling%id) cycle
         call reader%report(line, position - 1, 'duplicate coupling id (first at line '// &
                            to_string(model%couplings(k)%line)//')')
         ok = .false.
         return
      end do
      if (position <= line%n_tokens()) then
         if (line%keyword(position) /= 'KINEMATIC') then
            call reader%report(line, position, 'unknown coupling type (expected KINEMATIC)')
            ok = .false.
            return
         end if
      end if
      call reader%expect_keyword(line, position, 'KINEMATIC', ok)
      call take_coupled_nodes(reader, model, line, position, coupling%nodes, ok)
      call reader%expect_keyword(line, position, 'REF_NODE', ok)
      call take_node(reader, line, position, 'a reference node id', coupling%reference_node, ok)
      call reader%expect_keyword(line, position, 'ROT_NODE', ok)
      call take_node(reader, line, position, 'a rotation node id', coupling%rotation_node, ok)
      call reader%expect_end(line, position, ok)
   end subroutine read_coupling_line

   !> `SURFACE <name>` (the nodes of its faces) or `SET <name>` (a node set): the coupled nodes,
   !> sorted.
   subroutine take_coupled_nodes(reader, model, line, position, nodes, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      integer, allocatable, intent(out) :: nodes(:)
      logical, intent(inout) :: ok
      character(len=:), allocatable :: kind, name
      integer :: k, j
      allocate (nodes(0))
      call reader%take_word(line, position, 'SURFACE <name> or SET <name>', kind, ok)
      if (ok) kind = line%keyword(position - 1)
      if (ok .and. kind /= 'SURFACE' .and. kind /= 'SET') then
         call reader%report(line, position - 1, 'expected SURFACE <name> or SET <name>')
         ok = .false.
      end if
      call reader%take_word(line, position, 'a '//selection_name(kind)//' name', name, ok)
      if (.not. ok) return
      if (kind == 'SURFACE') then
         k = model%mesh%find_surface(name)
         if (k > 0) then
            associate (faces => model%mesh%surfaces(k))
               nodes = sorted_unique([(model%mesh%face_nodes(faces%elements(j), faces%faces(j)), &
                                       j=1, size(faces%elements))])
            end associate
         end if
      else
         k = model%mesh%find_node_set(name)
         if (k > 0) nodes = sorted_unique(model%mesh%node_sets(k)%nodes)
      end if
      if (k == 0) then
         ok = .false.
         if (.not. reader%mesh_failed) call reader%report(line, position - 1, &
                                                          'unknown '//selection_name(kind))
      else if (size(nodes) == 0) then
         ok = .false.
         call reader%report(line, position - 1, 'the '//selection_name(kind)// &
                            ' has no node')
      end if
   end subroutine take_coupled_nodes

   !> 'surface' or 'node set', for messages about a `SURFACE` or `SET` selection.
   function selection_name(kind) result(name)
      character(len=*), intent(in) :: kind
      character(len=:), allocatable :: name
      name = 'node set'
      if (kind == 'SURFACE') name = 'surface'
   end function selection_name

   !> A node id (defined) -> its internal number.
   subroutine take_node(reader, line, position, what, node, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      character(len=*), intent(in) :: what
      integer, intent(out) :: node
      logical, intent(inout) :: ok
      integer :: id
      node = 0
      call reader%take_integer(line, position, what, id, ok)
      if (.not. ok) return
      node = reader%node_map%lookup(id)
      if (node > 0) return
      ok = .false.
      if (.not. reader%mesh_failed) call reader%report(line, position - 1, 'undefined node '//to_string(id))
   end subroutine take_node

   !> The reference and rotation nodes: two nodes, not among the coupled ones, each serving
   !> one coupling in one role; the rotation node belongs to no element (its displacements
   !> are rotations).
   subroutine check_roles(reader, model, line, coupling, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      type(kinematic_coupling_t), intent(in) :: coupling
      logical, intent(inout) :: ok
      integer, allocatable :: orphans(:)
      integer :: ref_token, rot_token, k
      character(len=:), allocatable :: role
      ref_token = token_after(line, 'REF_NODE')
      rot_token = token_after(line, 'ROT_NODE')
      if (coupling%reference_node == coupling%rotation_node) then
         call fail(rot_token, 'the rotation node must differ from the reference node')
         return
      end if
      if (any(coupling%nodes == coupling%reference_node)) &
         call fail(ref_token, 'the reference node is one of the coupled nodes')
      if (any(coupling%nodes == coupling%rotation_node)) &
         call fail(rot_token, 'the rotation node is one of the coupled nodes')
      call find_orphan_nodes(model%mesh, orphans)
      if (.not. any(orphans == coupling%rotation_node)) &
         call fail(rot_token, 'the rotation node belongs to an element (its displacements are the rotations: '// &
                   'give it a node of its own in NODE COORDS)')
      do k = 1, size(model%couplings)
         role = coupling_node(model%couplings(k), coupling%reference_node)
         if (len(role) > 0) call fail(ref_token, 'node '//node_id(coupling%reference_node)//' is already '// &
                                      role//' of COUPLING '//to_string(model%couplings(k)%id))
         role = coupling_node(model%couplings(k), coupling%rotation_node)
         if (len(role) > 0) call fail(rot_token, 'node '//node_id(coupling%rotation_node)//' is already '// &
                                      role//' of COUPLING '//to_string(model%couplings(k)%id))
      end do
   contains
      subroutine fail(token, message)
         integer, intent(in) :: token
         character(len=*), intent(in) :: message
         if (.not. ok) return
         call reader%report(line, token, message)
         ok = .false.
      end subroutine fail

      function node_id(node) result(text)
         integer, intent(in) :: node
         character(len=:), allocatable :: text
         text = to_string(model%mesh%node_ids(node))
      end function node_id
   end subroutine check_roles

   !> The role of `node` in `coupling`: 'the reference node', 'the rotation node', 'a coupled
   !> node', or '' (none).
   function coupling_node(coupling, node) result(role)
      type(kinematic_coupling_t), intent(in) :: coupling
      integer, intent(in) :: node
      character(len=:), allocatable :: role
      role = ''
      if (coupling%reference_node == node) role = 'the reference node'
      if (coupling%rotation_node == node) role = 'the rotation node'
      if (any(coupling%nodes == node)) role = 'a coupled node'
   end function coupling_node

   !> The coupled nodes: none coupled or reference/rotation node of an earlier coupling, none
   !> with a Dirichlet condition, none on a surface of a TIE (reported at the set's name with
   !> the first such node).
   subroutine check_coupled_nodes(reader, model, line, coupling, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      type(kinematic_coupling_t), intent(in) :: coupling
      logical, intent(inout) :: ok
      character(len=:), allocatable :: role, conflict
      integer :: j, k
      conflict = ''
      do j = 1, size(coupling%nodes)
         associate (node => coupling%nodes(j))
            do k = 1, size(model%couplings)
               role = coupling_node(model%couplings(k), node)
               if (len(role) > 0) conflict = 'is already '//role//' of COUPLING '//to_string(model%couplings(k)%id)
               if (len(conflict) > 0) exit
            end do
            if (len(conflict) == 0) conflict = dirichlet_conflict(model, node)
            if (len(conflict) == 0) conflict = tie_conflict(model, node)
            if (len(conflict) == 0) cycle
            call reader%report(line, 5, 'coupled node '//to_string(model%mesh%node_ids(node))//' '//conflict)
            ok = .false.
            return
         end associate
      end do
      ! the reference node must not depend on a TIE either
      conflict = tie_conflict(model, coupling%reference_node, slave_only=.true.)
      if (len(conflict) == 0) return
      call reader%report(line, token_after(line, 'REF_NODE'), 'the reference node '//conflict)
      ok = .false.
   end subroutine check_coupled_nodes

   !> '' or why `node` cannot be coupled: a Dirichlet condition.
   function dirichlet_conflict(model, node) result(conflict)
      type(model_t), intent(in) :: model
      integer, intent(in) :: node
      character(len=:), allocatable :: conflict
      integer :: k
      conflict = ''
      do k = 1, size(model%dirichlet)
         if (.not. any(model%dirichlet(k)%nodes == node)) cycle
         conflict = 'has a Dirichlet condition (line '//to_string(model%dirichlet(k)%line)// &
                    '): prescribe the reference node or the rotation node instead'
         return
      end do
   end function dirichlet_conflict

   !> '' or why `node` cannot be coupled: it is on a surface of a TIE (its row and the tie's
   !> would chain); with `slave_only` only a TIE's slave surface counts.
   function tie_conflict(model, node, slave_only) result(conflict)
      type(model_t), intent(in) :: model
      integer, intent(in) :: node
      logical, intent(in), optional :: slave_only
      character(len=:), allocatable :: conflict
      integer :: p
      logical :: slaves
      slaves = .false.
      if (present(slave_only)) slaves = slave_only
      conflict = ''
      do p = 1, size(model%contact_pairs)
         associate (pair => model%contact_pairs(p))
            if (.not. pair%tied) cycle
            if (on_surface(model, pair%slave_surface, node)) then
               conflict = 'is on the slave surface of TIE '//to_string(pair%id)
            else if (.not. slaves .and. on_surface(model, pair%master_surface, node)) then
               conflict = 'is on the master surface of TIE '//to_string(pair%id)
            end if
            if (len(conflict) == 0) cycle
            conflict = conflict//' (chained constraints are not supported)'
            return
         end associate
      end do
   end function tie_conflict

   !> Whether `node` is a node of a face of surface `surface` (0: a rigid plane, no nodes).
   logical function on_surface(model, surface, node)
      type(model_t), intent(in) :: model
      integer, intent(in) :: surface, node
      integer :: j
      on_surface = .false.
      if (surface == 0) return
      associate (faces => model%mesh%surfaces(surface))
         do j = 1, size(faces%elements)
            if (any(model%mesh%face_nodes(faces%elements(j), faces%faces(j)) == node)) then
               on_surface = .true.
               return
            end if
         end do
      end associate
   end function on_surface

   !> The token after keyword `keyword` on the line (1 if absent).
   integer function token_after(line, keyword) result(position)
      type(deck_line_t), intent(in) :: line
      character(len=*), intent(in) :: keyword
      integer :: k
      position = 1
      do k = 1, line%n_tokens() - 1
         if (line%keyword(k) == keyword) position = k + 1
      end do
   end function token_after
end module frix_deck_couplings
