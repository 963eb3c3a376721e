!> Checks and queries on a `mesh_t`: inverted elements, orphan nodes, connected components,
!> user-id look-ups, bounding box, node-to-element adjacency, and appending one mesh to another.
module frix_mesh_checks
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_mesh, only: mesh_t, node_set_t, element_set_t, surface_t
   use frix_id_map, only: id_map_t
   use frix_reference_cell, only: reference_cell_t
   use frix_cell_registry, only: cell_entry_t, cell_table
   implicit none
   private

   public :: check_element_jacobians, find_orphan_nodes, connected_components
   public :: build_node_lookup, build_element_lookup, mesh_bounding_box
   public :: node_to_elements, merge_meshes

contains

   !> Internal numbers of the elements whose Jacobian determinant det(dx/dxi) is <= 0 at one
   !> of the points of their cell's Gauss rule (HEX8: 2 x 2 x 2, xi = +-1/sqrt 3; TET4: the
   !> centroid) or at the cell's centroid (HEX8: xi = 0): where the element is integrated
   !> (inverted or degenerate elements). A strongly distorted HEX8 may have det < 0 at a corner
   !> and still be usable: the 7-element patch of MacNeal & Harder has one such element
   !> (tests/verification V1). The map is x(xi) = sum_a N_a(xi) x_a with the cell's shape
   !> functions. A mirrored mesh (node order clockwise) has det < 0 everywhere.
   !> `overflowing`: the elements whose determinant is not finite (coordinates so large that
   !> their products leave the range of real numbers); computed with the floating-point traps
   !> off (a build that traps overflow reports them too), the flags cleared on return.
   subroutine check_element_jacobians(mesh, bad_elements, overflowing)
      use, intrinsic :: ieee_exceptions, only: ieee_set_halting_mode, ieee_set_flag, ieee_usual
      use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
      type(mesh_t), intent(in) :: mesh
      integer, allocatable, intent(out) :: bad_elements(:)
      integer, allocatable, intent(out) :: overflowing(:)
      logical, allocatable :: is_bad(:), is_infinite(:)
      real(dp), allocatable :: x(:, :)
      real(dp) :: determinant
      integer :: element, point
      type(cell_entry_t), allocatable :: table(:)
      table = cell_table()
      call ieee_set_halting_mode(ieee_usual, .false.)
      allocate (is_bad(mesh%n_elements), is_infinite(mesh%n_elements), source=.false.)
      do element = 1, mesh%n_elements
         associate (cell => table(mesh%cell_of(element))%cell)
            x = mesh%coords(:, mesh%element_nodes(element))
            do point = 1, cell%n_points() + 1
               if (point <= cell%n_points()) then
                  determinant = jacobian_determinant(cell, x, cell%points(:, point))
               else
                  determinant = jacobian_determinant(cell, x, sum(cell%node_coordinates, dim=2)/cell%n_nodes)
               end if
               if (.not. ieee_is_finite(determinant)) then
                  is_infinite(element) = .true.
                  exit
               else if (determinant <= 0) then
                  is_bad(element) = .true.
                  exit
               end if
            end do
         end associate
      end do
      bad_elements = pack([(element, element=1, mesh%n_elements)], is_bad)
      overflowing = pack([(element, element=1, mesh%n_elements)], is_infinite)
      call ieee_set_flag(ieee_usual, .false.)
   end subroutine check_element_jacobians

   !> det(dx/dxi) of the cell's map x(xi) = sum_a N_a(xi) x_a with nodal coordinates x(3, n_nodes)
   !> at natural point xi. A cell of dimension 2 (the plane strain and axisymmetric elements,
   !> which lie in the x-y plane): the in-plane det(d(x, y)/d(xi, eta)), positive when its nodes
   !> run counter-clockwise seen from +z.
   pure real(dp) function jacobian_determinant(cell, x, xi) result(determinant)
      class(reference_cell_t), intent(in) :: cell
      real(dp), intent(in) :: x(:, :), xi(:)
      real(dp) :: values(cell%n_nodes), derivatives(3, cell%n_nodes), jacobian(3, 3)
      derivatives = 0.0_dp
      call cell%shape_functions(xi, values, derivatives(1:cell%dimension, :))
      jacobian = matmul(x, transpose(derivatives))    ! jacobian(i, k) = d x_i / d xi_k
      if (cell%dimension == 2) then
         determinant = jacobian(1, 1)*jacobian(2, 2) - jacobian(1, 2)*jacobian(2, 1)
         return
      end if
      determinant = jacobian(1, 1)*(jacobian(2, 2)*jacobian(3, 3) - jacobian(3, 2)*jacobian(2, 3)) &
                    - jacobian(1, 2)*(jacobian(2, 1)*jacobian(3, 3) - jacobian(3, 1)*jacobian(2, 3)) &
                    + jacobian(1, 3)*(jacobian(2, 1)*jacobian(3, 2) - jacobian(3, 1)*jacobian(2, 2))
   end function jacobian_determinant

   !> Internal numbers of the nodes that belong to no element (ascending).
   subroutine find_orphan_nodes(mesh, orphans)
      type(mesh_t), intent(in) :: mesh
      integer, allocatable, intent(out) :: orphans(:)
      logical, allocatable :: used(:)
      integer :: element, node
      allocate (used(mesh%n_nodes))
      used = .false.
      do element = 1, mesh%n_elements
         used(mesh%element_nodes(element)) = .true.
      end do
      orphans = pack([(node, node=1, mesh%n_nodes)], .not. used)
   end subroutine find_orphan_nodes

   !> Connected components of the mesh: two nodes are connected if a chain of elements
   !> sharing nodes joins them. Union-find with union by size and path halving (nearly linear).
   !> Components are numbered 1..n_components in the order of their lowest node; a node of
   !> no element is a component of its own.
   subroutine connected_components(mesh, component_of_node, n_components)
      type(mesh_t), intent(in) :: mesh
      integer, allocatable, intent(out) :: component_of_node(:)
      integer, intent(out) :: n_components
      integer, allocatable :: parent(:), tree_size(:), number_of_root(:)
      integer :: element, a, node, root
      allocate (parent(mesh%n_nodes), tree_size(mesh%n_nodes), number_of_root(mesh%n_nodes))
      do node = 1, mesh%n_nodes
         parent(node) = node
      end do
      tree_size = 1
      do element = 1, mesh%n_elements
         do a = 2, mesh%node_count(element)
            call unite(mesh%connectivity(1, element), mesh%connectivity(a, element))
         end do
      end do
      number_of_root = 0
      n_components = 0
      allocate (component_of_node(mesh%n_nodes))
      do node = 1, mesh%n_nodes
         root = find_root(node)
         if (number_of_root(root) == 0) then
            n_components = n_components + 1
            number_of_root(root) = n_components
         end if
         component_of_node(node) = number_of_root(root)
      end do

   contains

      integer function find_root(start) result(node_root)
         integer, intent(in) :: start
         node_root = start
         do while (parent(node_root) /= node_root)
            parent(node_root) = parent(parent(node_root))
            node_root = parent(node_root)
         end do
      end function find_root

      subroutine unite(first, second)
         integer, intent(in) :: first, second
         integer :: root_first, root_second
         root_first = find_root(first)
         root_second = find_root(second)
         if (root_first == root_second) return
         if (tree_size(root_first) < tree_size(root_second)) then
            parent(root_first) = root_second
            tree_size(root_second) = tree_size(root_second) + tree_size(root_first)
         else
            parent(root_second) = root_first
            tree_size(root_first) = tree_size(root_first) + tree_size(root_second)
         end if
      end subroutine unite
   end subroutine connected_components

   !> Map from user node ids (`mesh%node_ids`) to internal node numbers; `node_map%lookup(id)`
   !> is then 0 for an unknown id. Error if two nodes share an id.
   subroutine build_node_lookup(mesh, node_map, error)
      type(mesh_t), intent(in) :: mesh
      type(id_map_t), intent(out) :: node_map
      type(error_t), allocatable, intent(out) :: error
      integer :: duplicate
      if (mesh%n_nodes == 0) then
         call node_map%clear(0)
         return
      end if
      call node_map%build(mesh%node_ids(1:mesh%n_nodes), duplicate)
      if (duplicate /= 0) call fatal_error(error, 'duplicate node id '//to_string(mesh%node_ids(duplicate)))
   end subroutine build_node_lookup

   !> Map from user element ids (`mesh%element_ids`) to internal element numbers.
   !> Error if two elements share an id.
   subroutine build_element_lookup(mesh, element_map, error)
      type(mesh_t), intent(in) :: mesh
      type(id_map_t), intent(out) :: element_map
      type(error_t), allocatable, intent(out) :: error
      integer :: duplicate
      if (mesh%n_elements == 0) then
         call element_map%clear(0)
         return
      end if
      call element_map%build(mesh%element_ids(1:mesh%n_elements), duplicate)
      if (duplicate /= 0) call fatal_error(error, 'duplicate element id '//to_string(mesh%element_ids(duplicate)))
   end subroutine build_element_lookup

   !> Smallest box holding all nodes, in the units of the coordinates. For a mesh without
   !> nodes lower = +huge and upper = -huge.
   subroutine mesh_bounding_box(mesh, lower, upper)
      type(mesh_t), intent(in) :: mesh
      real(dp), intent(out) :: lower(3), upper(3)
      integer :: k
      lower = huge(1.0_dp)
      upper = -huge(1.0_dp)
      if (mesh%n_nodes == 0) return
      do k = 1, 3
         lower(k) = minval(mesh%coords(k, 1:mesh%n_nodes))
         upper(k) = maxval(mesh%coords(k, 1:mesh%n_nodes))
      end do
   end subroutine mesh_bounding_box

   !> Elements around each node in compressed form: the elements holding node n are
   !> elements(offsets(n) : offsets(n+1)-1), ascending. offsets has n_nodes + 1 entries.
   subroutine node_to_elements(mesh, offsets, elements)
      type(mesh_t), intent(in) :: mesh
      integer, allocatable, intent(out) :: offsets(:), elements(:)
      integer, allocatable :: next(:)
      integer :: element, a, node
      allocate (offsets(mesh%n_nodes + 1))
      offsets = 0
      do element = 1, mesh%n_elements
         do a = 1, mesh%node_count(element)
            node = mesh%connectivity(a, element)
            offsets(node + 1) = offsets(node + 1) + 1
         end do
      end do
      offsets(1) = 1
      do node = 1, mesh%n_nodes
         offsets(node + 1) = offsets(node + 1) + offsets(node)
      end do
      allocate (elements(offsets(mesh%n_nodes + 1) - 1))
      next = offsets(1:mesh%n_nodes)
      do element = 1, mesh%n_elements
         do a = 1, mesh%node_count(element)
            node = mesh%connectivity(a, element)
            elements(next(node)) = element
            next(node) = next(node) + 1
         end do
      end do
   end subroutine node_to_elements

   !> Append `source` to `target`: nodes, elements (with their blocks) and all sets, with
   !> source's internal numbers shifted past target's. Error, leaving target unchanged, if a
   !> node id, an element id or a set name (of the same kind) is in both meshes.
   subroutine merge_meshes(target, source, error)
      type(mesh_t), intent(inout) :: target
      type(mesh_t), intent(in) :: source
      type(error_t), allocatable, intent(out) :: error
      type(id_map_t) :: map
      integer :: i, n_nodes, n_elements, existing
      type(node_set_t), allocatable :: node_sets(:)
      type(element_set_t), allocatable :: element_sets(:)
      type(surface_t), allocatable :: surfaces(:)

      call build_node_lookup(target, map, error)
      if (allocated(error)) return
      do i = 1, source%n_nodes
         call map%insert(source%node_ids(i), target%n_nodes + i, existing)
         if (existing /= 0) then
            call fatal_error(error, 'node id '//to_string(source%node_ids(i))//' is defined twice')
            return
         end if
      end do
      call build_element_lookup(target, map, error)
      if (allocated(error)) return
      do i = 1, source%n_elements
         call map%insert(source%element_ids(i), target%n_elements + i, existing)
         if (existing /= 0) then
            call fatal_error(error, 'element id '//to_string(source%element_ids(i))//' is defined twice')
            return
         end if
      end do
      if (allocated(source%node_sets)) then
         do i = 1, size(source%node_sets)
            if (target%find_node_set(source%node_sets(i)%name) /= 0) then
               call fatal_error(error, 'node set "'//source%node_sets(i)%name//'" is defined twice')
               return
            end if
         end do
      end if
      if (allocated(source%element_sets)) then
         do i = 1, size(source%element_sets)
            if (target%find_element_set(source%element_sets(i)%name) /= 0) then
               call fatal_error(error, 'element set "'//source%element_sets(i)%name//'" is defined twice')
               return
            end if
         end do
      end if
      if (allocated(source%surfaces)) then
         do i = 1, size(source%surfaces)
            if (target%find_surface(source%surfaces(i)%name) /= 0) then
               call fatal_error(error, 'surface "'//source%surfaces(i)%name//'" is defined twice')
               return
            end if
         end do
      end if

      n_nodes = target%n_nodes
      n_elements = target%n_elements
      if (source%n_nodes > 0) then
         call append_real_columns(target%coords, n_nodes, source%coords(:, 1:source%n_nodes))
         call append_integers(target%node_ids, n_nodes, source%node_ids(1:source%n_nodes))
      end if
      if (source%n_elements > 0) then
         call append_integer_columns(target%connectivity, n_elements, &
                                     source%connectivity(:, 1:source%n_elements) + n_nodes)
         call append_integers(target%element_ids, n_elements, source%element_ids(1:source%n_elements))
         call append_cells(target, n_elements, source)
         if (.not. allocated(target%element_block)) allocate (target%element_block(n_elements), source=0)
         if (allocated(source%element_block)) then
            call append_integers(target%element_block, n_elements, source%element_block(1:source%n_elements))
         else
            call append_integers(target%element_block, n_elements, [(0, i=1, source%n_elements)])
         end if
      end if
      target%n_nodes = n_nodes + source%n_nodes
      target%n_elements = n_elements + source%n_elements

      if (.not. allocated(target%node_sets)) allocate (target%node_sets(0))
      if (.not. allocated(target%element_sets)) allocate (target%element_sets(0))
      if (.not. allocated(target%surfaces)) allocate (target%surfaces(0))
      if (allocated(source%node_sets)) then
         node_sets = source%node_sets
         do i = 1, size(node_sets)
            node_sets(i)%nodes = node_sets(i)%nodes + n_nodes
         end do
         target%node_sets = [target%node_sets, node_sets]
      end if
      if (allocated(source%element_sets)) then
         element_sets = source%element_sets
         do i = 1, size(element_sets)
            element_sets(i)%elements = element_sets(i)%elements + n_elements
         end do
         target%element_sets = [target%element_sets, element_sets]
      end if
      if (allocated(source%surfaces)) then
         surfaces = source%surfaces
         do i = 1, size(surfaces)
            surfaces(i)%elements = surfaces(i)%elements + n_elements
         end do
         target%surfaces = [target%surfaces, surfaces]
      end if
   end subroutine merge_meshes

   !> The cell types of source's elements after target's first `n_used` (a mesh without cell
   !> types is HEX8: its cell_of).
   subroutine append_cells(target, n_used, source)
      type(mesh_t), intent(inout) :: target
      integer, intent(in) :: n_used
      type(mesh_t), intent(in) :: source
      integer, allocatable :: cells(:)
      integer :: e
      if (.not. (allocated(target%element_cell) .or. allocated(source%element_cell))) return
      allocate (cells(n_used + source%n_elements))
      do e = 1, n_used
         cells(e) = target%cell_of(e)
      end do
      do e = 1, source%n_elements
         cells(n_used + e) = source%cell_of(e)
      end do
      call target%set_cells(cells)
   end subroutine append_cells

   ! ---- private: append to the first `n_used` entries of an allocatable array -------------

   subroutine append_integers(array, n_used, extra)
      integer, allocatable, intent(inout) :: array(:)
      integer, intent(in) :: n_used
      integer, intent(in) :: extra(:)
      integer, allocatable :: joined(:)
      allocate (joined(n_used + size(extra)))
      if (n_used > 0) joined(1:n_used) = array(1:n_used)
      joined(n_used + 1:) = extra
      call move_alloc(joined, array)
   end subroutine append_integers

   subroutine append_integer_columns(array, n_used, extra)
      integer, allocatable, intent(inout) :: array(:, :)
      integer, intent(in) :: n_used
      integer, intent(in) :: extra(:, :)
      integer, allocatable :: joined(:, :)
      integer :: rows
      ! as many rows as the wider of the two, 0 below a narrower one's (a connectivity)
      rows = size(extra, 1)
      if (n_used > 0) rows = max(rows, size(array, 1))
      allocate (joined(rows, n_used + size(extra, 2)), source=0)
      if (n_used > 0) joined(1:size(array, 1), 1:n_used) = array(:, 1:n_used)
      joined(1:size(extra, 1), n_used + 1:) = extra
      call move_alloc(joined, array)
   end subroutine append_integer_columns

   subroutine append_real_columns(array, n_used, extra)
      real(dp), allocatable, intent(inout) :: array(:, :)
      integer, intent(in) :: n_used
      real(dp), intent(in) :: extra(:, :)
      real(dp), allocatable :: joined(:, :)
      allocate (joined(size(extra, 1), n_used + size(extra, 2)))
      if (n_used > 0) joined(:, 1:n_used) = array(:, 1:n_used)
      joined(:, n_used + 1:) = extra
      call move_alloc(joined, array)
   end subroutine append_real_columns
end module frix_mesh_checks
