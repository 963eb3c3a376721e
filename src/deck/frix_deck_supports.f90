!> Checks of a valid model that need its ties and supports, run by read_deck (and so by
!> `frix --check`) and reported at deck lines:
!> - the ties' nodes (frix_tie_constraints' check_tie_nodes: a node tied twice, chained ties),
!>   at the line of the TIE concerned;
!> - the supports: every body of the mesh (connected through shared nodes), together with the
!>   bodies tied to it, must be held in each direction x, y, z by at least one Dirichlet
!>   condition, or it can move as a rigid body and the stiffness matrix is singular. Bodies
!>   with a node on a surface of a contact PAIR are not checked: contact may hold them. A TIE
!>   holds nothing by itself: it joins the bodies it connects, and a TIE between two faces of
!>   one body (a periodic or seam tie) leaves that body to its own supports. Necessary, not
!>   sufficient: a body held at one node can still rotate; the factorization then names the
!>   node where it broke down. Reported at the line that created the body's first element.
!>   A kinematic coupling holds its coupled nodes' bodies where its reference node is fixed; an
!>   element that resists a translation itself (element_t%resists_translation: the radial one
!>   of axisymmetric elements) holds its body in that direction.
module frix_deck_supports
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_mesh_checks, only: connected_components
   use frix_model, only: model_t
   use frix_external_loads, only: prescribed_displacements
   use frix_contact_assembly, only: check_ties
   use frix_deck_context, only: deck_reader_t
   implicit none
   private

   public :: check_ties_and_supports

   character(len=1), parameter :: axis(3) = ['x', 'y', 'z']

contains

   !> The ties' nodes, then the supports (module header).
   subroutine check_ties_and_supports(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(error_t), allocatable :: error
      integer :: pair
      if (model%mesh%n_elements == 0) return
      call check_ties(model, pair, error)
      if (allocated(error)) then
         if (pair > 0) then
            call reader%report(reader%lines(model%contact_pairs(pair)%line), 1, error%message)
         else
            call reader%diagnostics%in_deck(0, 1, error%message)
         end if
         return
      end if
      call check_supports(reader, model)
   end subroutine check_ties_and_supports

   !> One message per body (with the bodies tied to it) not held in every direction.
   subroutine check_supports(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      integer, allocatable :: body_of_node(:), group(:), first_element(:), element_count(:)
      logical, allocatable :: fixed(:), held(:, :), in_contact(:)
      real(dp), allocatable :: values(:)
      integer :: n_bodies, node, e, body, line, direction
      call connected_components(model%mesh, body_of_node, n_bodies)
      group = tie_groups(model, body_of_node, n_bodies)
      allocate (fixed(3*model%mesh%n_nodes), values(3*model%mesh%n_nodes))
      call prescribed_displacements(model, 0.0_dp, fixed, values)
      in_contact = pair_nodes(model)
      allocate (held(3, n_bodies), source=.false.)
      do node = 1, model%mesh%n_nodes
         body = group(body_of_node(node))
         held(:, body) = held(:, body) .or. fixed(3*node - 2:3*node) .or. in_contact(node)
      end do
      call hold_coupled_bodies(model, body_of_node, group, fixed, held)
      allocate (first_element(n_bodies), element_count(n_bodies), source=0)
      do e = 1, model%mesh%n_elements
         body = group(body_of_node(model%mesh%connectivity(1, e)))
         if (first_element(body) == 0) first_element(body) = e
         element_count(body) = element_count(body) + 1
         associate (element => model%blocks(model%mesh%element_block(e))%element%formulation)
            do direction = 1, 3
               if (element%resists_translation(direction)) held(direction, body) = .true.
            end do
         end associate
      end do
      do body = 1, n_bodies
         if (element_count(body) == 0 .or. all(held(:, body))) cycle   ! (0: not a group's representative)
         e = first_element(body)
         line = reader%element_line(e)
         call report_at(reader, line, reader%element_token(e), 'the body of element '// &
                        to_string(model%mesh%element_ids(e))//' ('//to_string(element_count(body))// &
                        ' elements'//tied_text(group, body)//') has no Dirichlet condition in '// &
                        free_directions(held(:, body))//': it can move as a rigid body (singular stiffness matrix)')
      end do
   end subroutine check_supports

   !> A kinematic coupling holds the bodies of its coupled nodes in the directions its
   !> reference node is fixed in (frix_kinematic_coupling).
   subroutine hold_coupled_bodies(model, body_of_node, group, fixed, held)
      type(model_t), intent(in) :: model
      integer, intent(in) :: body_of_node(:), group(:)
      logical, intent(in) :: fixed(:)
      logical, intent(inout) :: held(:, :)
      integer :: k, j, body
      do k = 1, size(model%couplings)
         associate (reference => model%couplings(k)%reference_node)
            do j = 1, size(model%couplings(k)%nodes)
               body = group(body_of_node(model%couplings(k)%nodes(j)))
               held(:, body) = held(:, body) .or. fixed(3*reference - 2:3*reference)
            end do
         end associate
      end do
   end subroutine hold_coupled_bodies

   !> For each body, the representative of the bodies joined to it by ties: the smallest body
   !> number of the group (merging two groups keeps the smaller of their two labels).
   function tie_groups(model, body_of_node, n_bodies) result(group)
      type(model_t), intent(in) :: model
      integer, intent(in) :: body_of_node(:), n_bodies
      integer, allocatable :: group(:)
      logical, allocatable :: touched(:)
      integer :: p, first, body, old
      group = [(body, body=1, n_bodies)]
      do p = 1, size(model%contact_pairs)
         if (.not. model%contact_pairs(p)%tied) cycle
         allocate (touched(n_bodies), source=.false.)
         call mark_bodies(model, model%contact_pairs(p)%slave_surface, body_of_node, touched)
         call mark_bodies(model, model%contact_pairs(p)%master_surface, body_of_node, touched)
         first = minval(group, mask=touched)
         do body = 1, n_bodies
            if (.not. touched(body) .or. group(body) == first) cycle
            old = group(body)
            where (group == old) group = first
         end do
         deallocate (touched)
      end do
   end function tie_groups

   !> `touched` set for the bodies with a face in surface `surface`.
   subroutine mark_bodies(model, surface, body_of_node, touched)
      type(model_t), intent(in) :: model
      integer, intent(in) :: surface, body_of_node(:)
      logical, intent(inout) :: touched(:)
      integer :: k
      associate (faces => model%mesh%surfaces(surface))
         do k = 1, size(faces%elements)
            touched(body_of_node(model%mesh%connectivity(1, faces%elements(k)))) = .true.
         end do
      end associate
   end subroutine mark_bodies

   !> Nodes on the surfaces of contact pairs that are not ties (bodies contact may hold).
   function pair_nodes(model) result(in_contact)
      type(model_t), intent(in) :: model
      logical, allocatable :: in_contact(:)
      integer :: p
      allocate (in_contact(model%mesh%n_nodes), source=.false.)
      do p = 1, size(model%contact_pairs)
         if (model%contact_pairs(p)%tied) cycle
         call mark_surface(model%contact_pairs(p)%slave_surface)
         call mark_surface(model%contact_pairs(p)%master_surface)   ! 0: rigid plane
      end do
   contains
      subroutine mark_surface(surface)
         integer, intent(in) :: surface
         integer :: k
         if (surface == 0) return
         associate (faces => model%mesh%surfaces(surface))
            do k = 1, size(faces%elements)
               in_contact(model%mesh%face_nodes(faces%elements(k), faces%faces(k))) = .true.
            end do
         end associate
      end subroutine mark_surface
   end function pair_nodes

   !> "direction y", "directions x and z", "directions x, y and z": those not `held`.
   function free_directions(held) result(text)
      logical, intent(in) :: held(3)
      character(len=:), allocatable :: text
      integer :: direction, n
      text = ''
      n = 0
      do direction = 3, 1, -1
         if (held(direction)) cycle
         n = n + 1
         if (n == 2) text = ' and '//text
         if (n == 3) text = ', '//text
         text = axis(direction)//text
      end do
      if (n == 1) then
         text = 'direction '//text
      else
         text = 'directions '//text
      end if
   end function free_directions

   !> ", with the body tied to it" or ", with the N bodies tied to it" for a group of bodies.
   function tied_text(group, body) result(text)
      integer, intent(in) :: group(:), body
      character(len=:), allocatable :: text
      text = ''
      if (count(group == body) == 2) text = ', with the body tied to it'
      if (count(group == body) > 2) text = ', with the '//to_string(count(group == body) - 1)//' bodies tied to it'
   end function tied_text

   !> A message at token `token` of deck line `line`, or without a line when 0.
   subroutine report_at(reader, line, token, what)
      type(deck_reader_t), intent(inout) :: reader
      integer, intent(in) :: line, token
      character(len=*), intent(in) :: what
      if (line > 0) then
         call reader%report(reader%lines(line), token, what)
      else
         call reader%diagnostics%in_deck(0, 1, what)
      end if
   end subroutine report_at
end module frix_deck_supports
