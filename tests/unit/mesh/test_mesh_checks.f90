!> Tests of frix_mesh_checks on the block of block_v22.msh (two unit cubes, x in [0, 2]).
module test_mesh_checks
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close, check_message_contains
   use frix_strings, only: to_string
   use frix_mesh, only: mesh_t
   use frix_id_map, only: id_map_t
   use frix_mesh_checks, only: check_element_jacobians, find_orphan_nodes, connected_components, &
                               build_node_lookup, build_element_lookup, mesh_bounding_box, node_to_elements, &
                               merge_meshes
   use test_gmsh_reader, only: read_block
   implicit none
   private

   public :: collect_mesh_checks

contains

   subroutine collect_mesh_checks(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('valid_block_has_positive_jacobians', test_valid_jacobians), &
               new_unittest('mirrored_element_flagged', test_mirrored_element), &
               new_unittest('mirrored_mesh_flags_all', test_mirrored_mesh), &
               new_unittest('concave_corner_flagged', test_concave_corner), &
               new_unittest('huge_coordinates_overflow', test_huge_coordinates), &
               new_unittest('orphan_node', test_orphan_node), &
               new_unittest('lookups', test_lookups), &
               new_unittest('bounding_box', test_bounding_box), &
               new_unittest('node_to_elements', test_node_to_elements), &
               new_unittest('merge_two_blocks_two_components', test_merge_components), &
               new_unittest('merge_clashing_ids', test_merge_clash)]
   end subroutine collect_mesh_checks

   subroutine test_valid_jacobians(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      integer, allocatable :: bad(:), overflowing(:)
      call read_block('block_v22.msh', mesh, error)
      if (allocated(error)) return
      call check_element_jacobians(mesh, bad, overflowing)
      call check(error, size(bad) == 0, 'no inverted element in block_v22.msh')
   end subroutine test_valid_jacobians

   !> Swapping the bottom and top node quadruples of element 2 mirrors it through its
   !> mid-plane: det J = -1/8 everywhere.
   subroutine test_mirrored_element(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      integer, allocatable :: bad(:), overflowing(:)
      call read_block('block_v22.msh', mesh, error)
      if (allocated(error)) return
      mesh%connectivity(:, 2) = mesh%connectivity([5, 6, 7, 8, 1, 2, 3, 4], 2)
      call check_element_jacobians(mesh, bad, overflowing)
      call check(error, size(bad) == 1, 'one element flagged, got '//to_string(size(bad)))
      if (allocated(error)) return
      call check(error, bad(1) == 2, 'element 2 flagged')
   end subroutine test_mirrored_element

   !> x -> -x (a geometry built mirrored) inverts every element.
   subroutine test_mirrored_mesh(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      integer, allocatable :: bad(:), overflowing(:)
      call read_block('block_v22.msh', mesh, error)
      if (allocated(error)) return
      mesh%coords(1, :) = -mesh%coords(1, :)
      call check_element_jacobians(mesh, bad, overflowing)
      call check(error, size(bad) == 2, 'both elements flagged, got '//to_string(size(bad)))
   end subroutine test_mirrored_mesh

   !> Corner (2, 1, 1) of element 2 (its local node 7, the cube [1,2]x[0,1]^2) pulled to
   !> (1.1, 0.1, 0.1): by hand, at that corner dx/dxi = (x7 - x8)/2, dx/deta = (x7 - x6)/2,
   !> dx/dzeta = (x7 - x3)/2 give det = det[(.1,-.9,-.9), (-.9,.1,-.9), (-.9,-.9,.1)]/8
   !> = -1.70/8 < 0, while the centre stays positive: the Gauss point beside that corner
   !> is negative too, so the check (Gauss points and centre) flags the element.
   subroutine test_concave_corner(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      integer, allocatable :: bad(:), overflowing(:)
      call read_block('block_v22.msh', mesh, error)
      if (allocated(error)) return
      mesh%coords(:, mesh%connectivity(7, 2)) = [1.1_dp, 0.1_dp, 0.1_dp]
      call check_element_jacobians(mesh, bad, overflowing)
      call check(error, size(bad) == 1, 'one element flagged, got '//to_string(size(bad)))
      if (allocated(error)) return
      call check(error, bad(1) == 2, 'element 2 flagged')
   end subroutine test_concave_corner

   !> The block scaled by 1e150: det J = (1e150/2)^3 overflows. It is reported as overflowing, not as inverted, and no trap fires in a build
   !> that traps overflow.
   subroutine test_huge_coordinates(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      integer, allocatable :: bad(:), overflowing(:)
      call read_block('block_v22.msh', mesh, error)
      if (allocated(error)) return
      mesh%coords = 1.0e150_dp*mesh%coords
      call check_element_jacobians(mesh, bad, overflowing)
      call check(error, size(bad) == 0, 'no element inverted, got '//to_string(size(bad)))
      if (allocated(error)) return
      call check(error, size(overflowing) == 2, 'both elements overflow, got '//to_string(size(overflowing)))
   end subroutine test_huge_coordinates

   subroutine test_orphan_node(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      integer, allocatable :: orphans(:)
      call read_block('block_v22.msh', mesh, error)
      if (allocated(error)) return
      call find_orphan_nodes(mesh, orphans)
      call check(error, size(orphans) == 0, 'no orphan in the block')
      if (allocated(error)) return
      ! element 2 removed: its 4 nodes with x = 2 (ids 2, 4, 6, 7) belong to no element
      mesh%n_elements = 1
      mesh%connectivity = mesh%connectivity(:, 1:1)
      call find_orphan_nodes(mesh, orphans)
      call check(error, size(orphans) == 4, 'four orphans, got '//to_string(size(orphans)))
      if (allocated(error)) return
      call check(error, all(mesh%node_ids(orphans) == [2, 4, 6, 7]), 'orphans are the nodes with x = 2')
   end subroutine test_orphan_node

   subroutine test_lookups(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      type(id_map_t) :: nodes, elements
      type(error_t), allocatable :: lookup_error
      call read_block('block_v22.msh', mesh, error)
      if (allocated(error)) return
      mesh%node_ids = 100 + 3*mesh%node_ids     ! non-consecutive ids 103, 106, ...
      call build_node_lookup(mesh, nodes, error)
      if (allocated(error)) return
      call check(error, nodes%lookup(103) == 1 .and. nodes%lookup(136) == 12 .and. nodes%lookup(104) == 0, &
                 'node ids 103 -> 1, 136 -> 12, 104 unknown')
      if (allocated(error)) return
      call build_element_lookup(mesh, elements, error)
      if (allocated(error)) return
      call check(error, elements%lookup(9) == 1 .and. elements%lookup(10) == 2 .and. elements%lookup(1) == 0, &
                 'element ids 9 -> 1, 10 -> 2, 1 unknown')
      if (allocated(error)) return
      mesh%node_ids(5) = mesh%node_ids(2)
      call build_node_lookup(mesh, nodes, lookup_error)
      call check_message_contains(error, lookup_error, 'duplicate node id 106')
   end subroutine test_lookups

   subroutine test_bounding_box(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      real(dp) :: lower(3), upper(3)
      call read_block('block_v22.msh', mesh, error)
      if (allocated(error)) return
      call mesh_bounding_box(mesh, lower, upper)
      ! block.geo: [0, 2] x [0, 1] x [0, 1]
      call check(error, all(lower == 0) .and. all(upper == [2.0_dp, 1.0_dp, 1.0_dp]), 'box [0,2]x[0,1]x[0,1]')
   end subroutine test_bounding_box

   subroutine test_node_to_elements(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      integer, allocatable :: offsets(:), elements(:)
      call read_block('block_v22.msh', mesh, error)
      if (allocated(error)) return
      call node_to_elements(mesh, offsets, elements)
      call check(error, size(offsets) == 13 .and. size(elements) == 16, '16 element-node pairs')
      if (allocated(error)) return
      ! node 9 (1, 0, 0) is shared by both cubes, node 1 (origin) only by the first, node 2 only by the second
      call check(error, all(elements(offsets(9):offsets(10) - 1) == [1, 2]), 'node 9 in elements 1 and 2')
      if (allocated(error)) return
      call check(error, all(elements(offsets(1):offsets(2) - 1) == [1]) .and. &
                 all(elements(offsets(2):offsets(3) - 1) == [2]), 'node 1 in element 1, node 2 in element 2')
   end subroutine test_node_to_elements

   !> The block plus a copy moved by 5 in x with ids + 100 and renamed sets: two components.
   subroutine test_merge_components(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh, copy
      integer, allocatable :: component(:)
      integer :: n_components, i
      real(dp) :: lower(3), upper(3)
      call read_block('block_v22.msh', mesh, error)
      if (allocated(error)) return
      call read_block('block_v22.msh', copy, error)
      if (allocated(error)) return
      copy%coords(1, :) = copy%coords(1, :) + 5
      copy%node_ids = copy%node_ids + 100
      copy%element_ids = copy%element_ids + 100
      do i = 1, size(copy%node_sets)
         copy%node_sets(i)%name = 'copy_'//copy%node_sets(i)%name
      end do
      do i = 1, size(copy%element_sets)
         copy%element_sets(i)%name = 'copy_'//copy%element_sets(i)%name
      end do
      do i = 1, size(copy%surfaces)
         copy%surfaces(i)%name = 'copy_'//copy%surfaces(i)%name
      end do
      call merge_meshes(mesh, copy, error)
      if (allocated(error)) return
      call check(error, mesh%n_nodes == 24 .and. mesh%n_elements == 4, '24 nodes, 4 elements')
      if (allocated(error)) return
      call check(error, all(mesh%connectivity(:, 3) == [1, 9, 10, 3, 5, 11, 12, 8] + 12), 'shifted connectivity')
      if (allocated(error)) return
      call check(error, size(mesh%surfaces) == 6 .and. all(mesh%surfaces(4)%elements == [3, 4]) .and. &
                 mesh%surfaces(4)%name == 'copy_bottom', 'shifted surface copy_bottom')
      if (allocated(error)) return
      call check(error, all(mesh%node_sets(mesh%find_node_set('copy_origin'))%nodes == [13]), 'shifted node set')
      if (allocated(error)) return
      call mesh_bounding_box(mesh, lower, upper)
      call check_close(error, upper(1), 7.0_dp, 0.0_dp, 0.0_dp, 'box reaches x = 2 + 5')
      if (allocated(error)) return
      call connected_components(mesh, component, n_components)
      call check(error, n_components == 2, 'two components, got '//to_string(n_components))
      if (allocated(error)) return
      call check(error, all(component(1:12) == 1) .and. all(component(13:24) == 2), 'nodes 1-12 in 1, 13-24 in 2')
      if (allocated(error)) return
      ! a third cube sharing the face x = 2 of the first block and x = 5 of the copy joins them
      mesh%connectivity = reshape([mesh%connectivity, [2, 13, 15, 4, 6, 17, 20, 7]], [8, 5])
      call mesh%set_cells([mesh%element_cell, mesh%element_cell(1)])   ! a HEX8 as the others
      mesh%n_elements = 5
      call connected_components(mesh, component, n_components)
      call check(error, n_components == 1, 'one component after joining, got '//to_string(n_components))
   end subroutine test_merge_components

   subroutine test_merge_clash(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh, copy
      type(error_t), allocatable :: merge_error
      call read_block('block_v22.msh', mesh, error)
      if (allocated(error)) return
      call read_block('block_v22.msh', copy, error)
      if (allocated(error)) return
      call merge_meshes(mesh, copy, merge_error)
      call check_message_contains(error, merge_error, 'node id 1 is defined twice')
      if (allocated(error)) return
      call check(error, mesh%n_nodes == 12 .and. mesh%n_elements == 2, 'target unchanged after a failed merge')
      if (allocated(error)) return
      copy%node_ids = copy%node_ids + 100
      copy%element_ids = copy%element_ids + 100
      call merge_meshes(mesh, copy, merge_error)
      call check_message_contains(error, merge_error, 'node set "origin" is defined twice')
   end subroutine test_merge_clash
end module test_mesh_checks
