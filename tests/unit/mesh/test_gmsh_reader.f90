!> Tests of frix_gmsh_reader on the files of tests/unit/mesh/data (made by gmsh 4.8 from the
!> .geo files there; error files are copies of block_v22.msh / block_v41.msh with one line
!> changed, see data/README.md).
!>
!> block.geo: x in [0, 2], y and z in [0, 1], two unit-cube HEX8. Node ids and connectivity
!> quoted below are read off block_v22.msh.
module test_gmsh_reader
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close, check_message_contains
   use frix_strings, only: to_string
   use frix_mesh, only: mesh_t, hex8_face_nodes
   use frix_gmsh_reader, only: read_gmsh
   use test_data_location, only: data_path
   implicit none
   private

   public :: collect_gmsh_reader, collect_gmsh_errors, read_block

contains

   subroutine collect_gmsh_reader(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('v22_counts_and_coordinates', test_v22_counts), &
               new_unittest('v22_node_and_element_sets', test_v22_sets), &
               new_unittest('v22_surface_normals', test_v22_surface_normals), &
               new_unittest('v41_equals_v22', test_v41_equals_v22), &
               new_unittest('no_physical_groups', test_no_groups), &
               new_unittest('hexahedra_in_two_volumes', test_two_volumes)]
   end subroutine collect_gmsh_reader

   subroutine collect_gmsh_errors(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('missing_file', test_missing_file), &
               new_unittest('not_a_gmsh_file', test_not_gmsh), &
               new_unittest('bad_number_v22', test_bad_number_v22), &
               new_unittest('bad_number_v41', test_bad_number_v41), &
               new_unittest('unknown_version', test_version), &
               new_unittest('binary', test_binary), &
               new_unittest('truncated', test_truncated), &
               new_unittest('undefined_node', test_undefined_node), &
               new_unittest('duplicate_node', test_duplicate_node), &
               new_unittest('bad_count_v22', test_count_v22), &
               new_unittest('bad_count_v41', test_count_v41), &
               new_unittest('tetrahedron_in_volume', test_tetrahedron), &
               new_unittest('second_order_in_volume', test_second_order), &
               new_unittest('quad_matching_no_face', test_unmatched_quad), &
               new_unittest('quad_on_interior_face', test_interior_face)]
   end subroutine collect_gmsh_errors

   !> Read data file `name`; error if the read fails.
   subroutine read_block(name, mesh, error)
      character(len=*), intent(in) :: name
      type(mesh_t), intent(out) :: mesh
      type(error_t), allocatable, intent(out) :: error
      call read_gmsh(data_path(name), mesh, error)
   end subroutine read_block

   subroutine test_v22_counts(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      integer :: node
      call read_block('block_v22.msh', mesh, error)
      if (allocated(error)) return
      call check(error, mesh%n_nodes == 12 .and. mesh%n_elements == 2, &
                 'a 2x1x1 block of HEX8 has 12 nodes and 2 elements, got '// &
                 to_string(mesh%n_nodes)//' and '//to_string(mesh%n_elements))
      if (allocated(error)) return
      call check(error, all(mesh%node_ids == [(node, node=1, 12)]), 'node ids 1..12 in file order')
      if (allocated(error)) return
      call check(error, all(mesh%element_ids == [9, 10]), 'hexahedra keep gmsh ids 9 and 10')
      if (allocated(error)) return
      call check(error, all(mesh%connectivity(:, 1) == [1, 9, 10, 3, 5, 11, 12, 8]), 'connectivity of element 9')
      if (allocated(error)) return
      call check(error, all(mesh%connectivity(:, 2) == [9, 2, 4, 10, 11, 6, 7, 12]), 'connectivity of element 10')
      if (allocated(error)) return
      call check(error, all(mesh%element_block == 0), 'element blocks left 0')
      if (allocated(error)) return
      ! node 7 is the corner (2, 1, 1), node 9 the mid-edge point (1, 0, 0)
      call check(error, all(mesh%coords(:, 7) == [2.0_dp, 1.0_dp, 1.0_dp]), 'node 7 at (2, 1, 1)')
      if (allocated(error)) return
      call check(error, all(mesh%coords(:, 9) == [1.0_dp, 0.0_dp, 0.0_dp]), 'node 9 at (1, 0, 0)')
   end subroutine test_v22_counts

   subroutine test_v22_sets(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      call read_block('block_v22.msh', mesh, error)
      if (allocated(error)) return
      call check_sets(mesh, error)
   end subroutine test_v22_sets

   !> Sets of block.geo, ordered by (dim, tag): origin 0:5, the unnamed curve 1:7, bottom 2:2,
   !> top 2:3, left 2:4, block 3:1. Node lists are those of the planes z = 0, z = 1, x = 0.
   subroutine check_sets(mesh, error)
      type(mesh_t), intent(in) :: mesh
      type(error_t), allocatable, intent(out) :: error
      integer :: node
      call check(error, size(mesh%node_sets) == 6 .and. size(mesh%element_sets) == 1 .and. &
                 size(mesh%surfaces) == 3, '6 node sets, 1 element set, 3 surfaces')
      if (allocated(error)) return
      call check(error, mesh%node_sets(1)%name == 'origin' .and. mesh%node_sets(2)%name == '1:7' .and. &
                 mesh%node_sets(3)%name == 'bottom' .and. mesh%node_sets(6)%name == 'block', &
                 'node set names in (dim, tag) order, unnamed group "1:7"')
      if (allocated(error)) return
      call check(error, all(mesh%node_sets(1)%nodes == [1]), 'origin holds node 1')
      if (allocated(error)) return
      call check(error, all(mesh%node_ids(mesh%node_sets(2)%nodes) == [1, 2, 9]), 'edge y = z = 0: nodes 1, 2, 9')
      if (allocated(error)) return
      call check(error, all(mesh%coords(3, mesh%node_sets(mesh%find_node_set('bottom'))%nodes) == 0) .and. &
                 size(mesh%node_sets(mesh%find_node_set('bottom'))%nodes) == 6, 'bottom: the 6 nodes with z = 0')
      if (allocated(error)) return
      call check(error, all(mesh%coords(3, mesh%node_sets(mesh%find_node_set('top'))%nodes) == 1) .and. &
                 size(mesh%node_sets(mesh%find_node_set('top'))%nodes) == 6, 'top: the 6 nodes with z = 1')
      if (allocated(error)) return
      call check(error, all(mesh%coords(1, mesh%node_sets(mesh%find_node_set('left'))%nodes) == 0) .and. &
                 size(mesh%node_sets(mesh%find_node_set('left'))%nodes) == 4, 'left: the 4 nodes with x = 0')
      if (allocated(error)) return
      call check(error, all(mesh%node_sets(6)%nodes == [(node, node=1, 12)]), 'block: all nodes')
      if (allocated(error)) return
      call check(error, mesh%element_sets(1)%name == 'block' .and. all(mesh%element_sets(1)%elements == [1, 2]), &
                 'element set block = both hexahedra')
      if (allocated(error)) return
      call check(error, mesh%surfaces(1)%name == 'bottom' .and. mesh%surfaces(2)%name == 'top' .and. &
                 mesh%surfaces(3)%name == 'left', 'surface names')
      if (allocated(error)) return
      ! by the face table of frix_mesh: z = 0 is face 1 (zeta = -1), z = 1 face 2, x = 0 face 6
      call check(error, all(mesh%surfaces(1)%elements == [1, 2]) .and. all(mesh%surfaces(1)%faces == 1), &
                 'bottom = face 1 of both elements')
      if (allocated(error)) return
      call check(error, all(mesh%surfaces(2)%elements == [1, 2]) .and. all(mesh%surfaces(2)%faces == 2), &
                 'top = face 2 of both elements')
      if (allocated(error)) return
      call check(error, all(mesh%surfaces(3)%elements == [1]) .and. all(mesh%surfaces(3)%faces == 6), &
                 'left = face 6 of element 1')
   end subroutine check_sets

   !> The outward normal of a face, (x3 - x1) x (x4 - x2) of its nodes in hex8_face_nodes
   !> order, normalised, must be -z on "bottom", +z on "top", -x on "left" (exact for unit cubes).
   subroutine test_v22_surface_normals(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      call read_block('block_v22.msh', mesh, error)
      if (allocated(error)) return
      call check_normals(mesh, 'bottom', [0.0_dp, 0.0_dp, -1.0_dp], error)
      if (allocated(error)) return
      call check_normals(mesh, 'top', [0.0_dp, 0.0_dp, 1.0_dp], error)
      if (allocated(error)) return
      call check_normals(mesh, 'left', [-1.0_dp, 0.0_dp, 0.0_dp], error)
   end subroutine test_v22_surface_normals

   subroutine check_normals(mesh, name, expected, error)
      type(mesh_t), intent(in) :: mesh
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: expected(3)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: x(3, 4), diagonal_1(3), diagonal_2(3), normal(3)
      integer :: surface, i, k
      surface = mesh%find_surface(name)
      call check(error, surface > 0, 'surface '//name//' exists')
      if (allocated(error)) return
      do i = 1, size(mesh%surfaces(surface)%elements)
         associate (element => mesh%surfaces(surface)%elements(i), face => mesh%surfaces(surface)%faces(i))
            x = mesh%coords(:, mesh%connectivity(hex8_face_nodes(:, face), element))
         end associate
         diagonal_1 = x(:, 3) - x(:, 1)
         diagonal_2 = x(:, 4) - x(:, 2)
         normal = [diagonal_1(2)*diagonal_2(3) - diagonal_1(3)*diagonal_2(2), &
                   diagonal_1(3)*diagonal_2(1) - diagonal_1(1)*diagonal_2(3), &
                   diagonal_1(1)*diagonal_2(2) - diagonal_1(2)*diagonal_2(1)]
         normal = normal/norm2(normal)
         do k = 1, 3
            call check_close(error, normal(k), expected(k), 0.0_dp, 1.0e-14_dp, &
                             name//' face '//to_string(i)//' normal component '//to_string(k))
            if (allocated(error)) return
         end do
      end do
   end subroutine check_normals

   subroutine test_v41_equals_v22(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: v22, v41
      integer :: i
      call read_block('block_v22.msh', v22, error)
      if (allocated(error)) return
      call read_block('block_v41.msh', v41, error)
      if (allocated(error)) return
      call check(error, v41%n_nodes == v22%n_nodes .and. v41%n_elements == v22%n_elements, 'same counts')
      if (allocated(error)) return
      call check(error, all(v41%node_ids == v22%node_ids) .and. all(v41%coords == v22%coords), 'same nodes')
      if (allocated(error)) return
      call check(error, all(v41%element_ids == v22%element_ids) .and. all(v41%connectivity == v22%connectivity), &
                 'same elements')
      if (allocated(error)) return
      call check(error, size(v41%node_sets) == size(v22%node_sets), 'same number of node sets')
      if (allocated(error)) return
      do i = 1, size(v22%node_sets)
         call check(error, v41%node_sets(i)%name == v22%node_sets(i)%name .and. &
                    size(v41%node_sets(i)%nodes) == size(v22%node_sets(i)%nodes), 'node set '//v22%node_sets(i)%name)
         if (allocated(error)) return
         call check(error, all(v41%node_sets(i)%nodes == v22%node_sets(i)%nodes), 'nodes of '//v22%node_sets(i)%name)
         if (allocated(error)) return
      end do
      call check(error, size(v41%surfaces) == size(v22%surfaces), 'same number of surfaces')
      if (allocated(error)) return
      do i = 1, size(v22%surfaces)
         call check(error, v41%surfaces(i)%name == v22%surfaces(i)%name .and. &
                    size(v41%surfaces(i)%faces) == size(v22%surfaces(i)%faces), 'surface '//v22%surfaces(i)%name)
         if (allocated(error)) return
         call check(error, all(v41%surfaces(i)%elements == v22%surfaces(i)%elements) .and. &
                    all(v41%surfaces(i)%faces == v22%surfaces(i)%faces), 'faces of '//v22%surfaces(i)%name)
         if (allocated(error)) return
      end do
      ! and the 4.1 file passes the same set checks on its own
      call check_sets(v41, error)
   end subroutine test_v41_equals_v22

   !> Without physical groups gmsh 2.2 writes every element: keep the hexahedra, make no sets.
   subroutine test_no_groups(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      call read_block('block_no_groups_v22.msh', mesh, error)
      if (allocated(error)) return
      call check(error, mesh%n_nodes == 12 .and. mesh%n_elements == 2, '12 nodes, 2 hexahedra')
      if (allocated(error)) return
      call check(error, size(mesh%node_sets) == 0 .and. size(mesh%element_sets) == 0 .and. &
                 size(mesh%surfaces) == 0, 'no sets')
      if (allocated(error)) return
      call check(error, all(mesh%connectivity(:, 1) == [1, 9, 10, 3, 5, 11, 12, 8]), 'connectivity of the first hexahedron')
   end subroutine test_no_groups

   !> One volume in physical volumes "block" (3:1) and "again" (3:8): format 2.2 writes each
   !> hexahedron twice with new ids (9 = 10 and 11 = 12 in the file), 4.1 once (9, 10). Both
   !> must give two hexahedra, each in both element sets.
   subroutine test_two_volumes(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: v22, v41
      call read_block('block_two_volumes_v22.msh', v22, error)
      if (allocated(error)) return
      call read_block('block_two_volumes_v41.msh', v41, error)
      if (allocated(error)) return
      call check(error, v22%n_elements == 2 .and. v41%n_elements == 2, 'two hexahedra in each format, got '// &
                 to_string(v22%n_elements)//' and '//to_string(v41%n_elements))
      if (allocated(error)) return
      call check(error, all(v22%element_ids == [9, 11]) .and. all(v41%element_ids == [9, 10]), &
                 'first copies kept: ids 9, 11 (2.2) and 9, 10 (4.1)')
      if (allocated(error)) return
      call check(error, all(v22%connectivity == v41%connectivity), 'same connectivity')
      if (allocated(error)) return
      call check(error, size(v22%element_sets) == 2 .and. size(v41%element_sets) == 2, 'two element sets')
      if (allocated(error)) return
      call check(error, v22%element_sets(2)%name == 'again' .and. all(v22%element_sets(1)%elements == [1, 2]) .and. &
                 all(v22%element_sets(2)%elements == [1, 2]), '2.2: both hexahedra in "block" and "again"')
      if (allocated(error)) return
      call check(error, v41%element_sets(2)%name == 'again' .and. all(v41%element_sets(1)%elements == [1, 2]) .and. &
                 all(v41%element_sets(2)%elements == [1, 2]), '4.1: both hexahedra in "block" and "again"')
      if (allocated(error)) return
      call check(error, all(v22%surfaces(1)%elements == [1, 2]) .and. all(v22%surfaces(1)%faces == 1), &
                 'bottom faces on the kept hexahedra')
   end subroutine test_two_volumes

   ! ---- errors ---------------------------------------------------------------------------

   !> Read `name`, expecting an error containing "name:" followed by `fragment`.
   subroutine expect_error(name, fragment, error)
      character(len=*), intent(in) :: name, fragment
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      type(error_t), allocatable :: read_error
      call read_gmsh(data_path(name), mesh, read_error)
      call check_message_contains(error, read_error, name//':'//fragment)
   end subroutine expect_error

   subroutine test_missing_file(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error('no_such_mesh.msh', ' cannot open file', error)
   end subroutine test_missing_file

   subroutine test_not_gmsh(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error('error_not_gmsh.msh', '1: expected $MeshFormat, got "NODE"', error)
   end subroutine test_not_gmsh

   subroutine test_bad_number_v22(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error('error_bad_number_v22.msh', '17: expected a number, got "abc"', error)
   end subroutine test_bad_number_v22

   subroutine test_bad_number_v41(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error('error_bad_number_v41.msh', '55: expected a number, got "0x"', error)
   end subroutine test_bad_number_v41

   subroutine test_version(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error('error_version.msh', '2: unknown msh format version "3.0"', error)
   end subroutine test_version

   subroutine test_binary(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error('error_binary.msh', '2: binary msh files are not supported', error)
   end subroutine test_binary

   subroutine test_truncated(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error('error_truncated.msh', '13: $Nodes declares 12 entries but only 7 lines follow '// &
                        '(truncated file or bad count)', error)
      if (allocated(error)) return
      call expect_error('error_truncated_end.msh', '38: truncated file: end of file inside section $Elements '// &
                        '(no $EndElements)', error)
   end subroutine test_truncated

   subroutine test_undefined_node(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error('error_undefined_node.msh', '38: element 10 references node 99, which is not defined', error)
   end subroutine test_undefined_node

   subroutine test_duplicate_node(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error('error_duplicate_node.msh', '25: duplicate node id 11 (first defined on line 24)', error)
   end subroutine test_duplicate_node

   subroutine test_count_v22(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error('error_count_v22.msh', '26: bad counts: "$EndNodes" inside section $Nodes', error)
   end subroutine test_count_v22

   subroutine test_count_v41(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error('error_count_v41.msh', '80: bad counts: the node blocks hold more than the 12 nodes', error)
   end subroutine test_count_v41

   subroutine test_tetrahedron(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error('error_tetrahedron.msh', '39: only 8-node hexahedra are supported: element 11 has type 4', error)
   end subroutine test_tetrahedron

   !> gmsh -order 2 gives 27-node hexahedra (type 12) in the volume and 9-node quadrilaterals
   !> on the surfaces: the volume's error comes first.
   subroutine test_second_order(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error('block_order2_v41.msh', '178: only 8-node hexahedra are supported: element 9 has type 12', error)
   end subroutine test_second_order

   subroutine test_unmatched_quad(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error('error_unmatched_quad.msh', '32: quadrilateral 4 matches no face of a hexahedron', error)
   end subroutine test_unmatched_quad

   subroutine test_interior_face(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error('error_interior_face.msh', '32: quadrilateral 4 lies on a face shared by two hexahedra', error)
   end subroutine test_interior_face
end module test_gmsh_reader
