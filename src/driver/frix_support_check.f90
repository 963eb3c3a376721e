!> A check before the first factorization: every connected body of the mesh must be held in
!> each direction x, y, z by at least one Dirichlet condition, or it can move as a rigid body
!> and the stiffness matrix is singular. (Necessary, not sufficient: a body held at one node
!> can still rotate; the factorization then names the node where it broke down.)
module frix_support_check
   use frix_error, only: error_t, append_error
   use frix_strings, only: to_string
   use frix_model, only: model_t
   use frix_mesh_checks, only: connected_components
   implicit none
   private

   public :: check_rigid_body_support

contains

   !> `fixed` is the constrained-equation mask (3 per node, node-major). Bodies with a node in
   !> `in_contact` are not checked: contact may hold them.
   subroutine check_rigid_body_support(model, fixed, error, in_contact)
      type(model_t), intent(in) :: model
      logical, intent(in) :: fixed(:)
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in) :: in_contact(:)
      integer, allocatable :: component_of_node(:), first_node(:), element_count(:)
      logical, allocatable :: held(:, :), touches(:)
      integer :: n_components, node, component, direction, e
      character(len=1), parameter :: axis(3) = ['x', 'y', 'z']

      call connected_components(model%mesh, component_of_node, n_components)
      allocate (held(3, n_components), source=.false.)
      allocate (first_node(n_components), source=0)
      allocate (touches(n_components), source=.false.)
      allocate (element_count(n_components), source=0)
      do node = 1, model%mesh%n_nodes
         component = component_of_node(node)
         if (first_node(component) == 0) first_node(component) = node
         held(:, component) = held(:, component) .or. fixed(3*node - 2:3*node)
         touches(component) = touches(component) .or. in_contact(node)
      end do
      do e = 1, model%mesh%n_elements
         component = component_of_node(model%mesh%connectivity(1, e))
         element_count(component) = element_count(component) + 1
      end do
      do component = 1, n_components
         if (element_count(component) == 0) cycle   ! a node of no element: held by the driver
         if (touches(component)) cycle
         do direction = 1, 3
            if (.not. held(direction, component)) then
               call append_error(error, model%deck_path//': the body containing node '// &
                                 to_string(model%mesh%node_ids(first_node(component)))//' ('// &
                                 to_string(element_count(component))//' elements) has no '// &
                                 'Dirichlet condition in direction '//axis(direction)// &
                                 ': it can move as a rigid body (singular stiffness matrix)')
            end if
         end do
      end do
   end subroutine check_rigid_body_support
end module frix_support_check
