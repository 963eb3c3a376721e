!> Tests of frix_gmsh_reader on the files of tests/unit/mesh/data (made by gmsh 4.8 from the
!> .geo files there; error files are copies of block_v22.msh / block_v41.msh with one line
!> changed, see data/README.md).
!>
!> block.geo: x in [0, 2], y and z in [0, 1], two unit-cube HEX8. Node ids and connectivity
!> quoted below are read off block_v22.msh.
!>
!> The malformed-input tests at the end write their files themselves (output_path): a one-
!> hexahedron cube (cube_v22, cube_v41) with one line changed, as in tests/errors/gmsh_*.msh.
module test_gmsh_reader
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close, check_message_contains, output_path
   use frix_strings, only: to_string
   use frix_mesh, only: mesh_t
   use frix_gmsh_reader, only: read_gmsh
   use test_data_location, only: data_path
   implicit none
   private

   public :: collect_gmsh_reader, collect_gmsh_errors, read_block, replaced, write_text, delete_file

   character(len=*), parameter :: nl = new_line('a')

contains

   subroutine collect_gmsh_reader(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('v22_counts_and_coordinates', test_v22_counts), &
               new_unittest('v22_node_and_element_sets', test_v22_sets), &
               new_unittest('v22_surface_normals', test_v22_surface_normals), &
               new_unittest('v41_equals_v22', test_v41_equals_v22), &
               new_unittest('no_physical_groups', test_no_groups), &
               new_unittest('hexahedra_in_two_volumes', test_two_volumes), &
               new_unittest('cube_files_are_valid', test_cube_files), &
               new_unittest('parametric_nodes_v41', test_parametric_nodes), &
               new_unittest('tetrahedra_v41', test_tetrahedra), &
               new_unittest('hexahedra_and_a_tetrahedron', test_tetrahedron), &
               new_unittest('tet10_node_order', test_tet10)]
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
               new_unittest('second_order_in_volume', test_second_order), &
               new_unittest('quad_matching_no_face', test_unmatched_quad), &
               new_unittest('quad_on_interior_face', test_interior_face), &
               new_unittest('second_physical_names', test_second_physical_names), &
               new_unittest('second_entities', test_second_entities), &
               new_unittest('second_mesh_format', test_second_mesh_format), &
               new_unittest('second_nodes_and_elements', test_second_nodes_elements), &
               new_unittest('entities_after_elements', test_entities_after_elements), &
               new_unittest('physical_tag_not_positive', test_physical_tag_sign), &
               new_unittest('physical_name_dimension', test_physical_name_dimension), &
               new_unittest('physical_group_named_twice', test_named_twice), &
               new_unittest('count_overflow_v41', test_count_overflow), &
               new_unittest('bad_parametric_flag', test_parametric_flag), &
               new_unittest('stray_section_end', test_stray_end), &
               new_unittest('coordinates_not_finite', test_coordinates_not_finite)]
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

   !> The outward normal of a face, (x3 - x1) x (x4 - x2) of its nodes in the cell's face order
   !> ((x2 - x1) x (x3 - x1) on a triangle), normalised, must be -z on "bottom", +z on "top", -x on "left" (exact for unit cubes).
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
      real(dp), allocatable :: x(:, :)
      real(dp) :: diagonal_1(3), diagonal_2(3), normal(3)
      integer :: surface, i, k
      surface = mesh%find_surface(name)
      call check(error, surface > 0, 'surface '//name//' exists')
      if (allocated(error)) return
      do i = 1, size(mesh%surfaces(surface)%elements)
         associate (element => mesh%surfaces(surface)%elements(i), face => mesh%surfaces(surface)%faces(i))
            x = mesh%coords(:, mesh%face_nodes(element, face))
         end associate
         ! a quadrilateral's diagonals, a triangle's two edges from node 1
         if (size(x, 2) == 3) then
            diagonal_1 = x(:, 2) - x(:, 1)
            diagonal_2 = x(:, 3) - x(:, 1)
         else
            diagonal_1 = x(:, 3) - x(:, 1)
            diagonal_2 = x(:, 4) - x(:, 2)
         end if
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

   !> A unit cube of 24 tetrahedra (cube_tet_v41.msh): every element a TET4 with positive volume,
   !> the volumes summing to 1; the physical surface "bottom" is 4 triangles matched to TET4
   !> faces turning outward (-z); its node set holds the nodes at z = 0.
   subroutine test_tetrahedra(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      type(error_t), allocatable :: read_error
      real(dp) :: x(3, 4), volume, total
      integer :: e, k
      call read_gmsh(data_path('cube_tet_v41.msh'), mesh, read_error)
      call check(error, .not. allocated(read_error), 'cube_tet_v41.msh is read')
      if (allocated(error)) return
      call check(error, mesh%n_elements == 24 .and. all([(mesh%cell_name(e) == 'TET4', e=1, 24)]), '24 TET4')
      if (allocated(error)) return
      total = 0
      do e = 1, mesh%n_elements
         x = mesh%coords(:, mesh%element_nodes(e))
         do k = 2, 4
            x(:, k) = x(:, k) - x(:, 1)
         end do
         volume = dot_product(x(:, 2), [x(2, 3)*x(3, 4) - x(3, 3)*x(2, 4), x(3, 3)*x(1, 4) - x(1, 3)*x(3, 4), &
                                        x(1, 3)*x(2, 4) - x(2, 3)*x(1, 4)])/6
         call check(error, volume > 0, 'element '//to_string(e)//' volume '//to_string(volume))
         if (allocated(error)) return
         total = total + volume
      end do
      call check_close(error, total, 1.0_dp, 0.0_dp, 1.0e-14_dp, 'volume of the cube')
      if (allocated(error)) return
      call check(error, size(mesh%surfaces(mesh%find_surface('bottom'))%faces) == 4, '4 bottom triangles')
      if (allocated(error)) return
      call check_normals(mesh, 'bottom', [0.0_dp, 0.0_dp, -1.0_dp], error)
      if (allocated(error)) return
      associate (bottom => mesh%node_sets(mesh%find_node_set('bottom'))%nodes)
         call check(error, size(bottom) == count(mesh%coords(3, :) == 0) .and. all(mesh%coords(3, bottom) == 0), &
                    'bottom node set')
      end associate
   end subroutine test_tetrahedra

   !> Two hexahedra and a tetrahedron (type 4) in one physical volume: read, each with its cell.
   subroutine test_tetrahedron(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      type(error_t), allocatable :: read_error
      call read_gmsh(data_path('mixed_hex_tet.msh'), mesh, read_error)
      call check(error, .not. allocated(read_error), 'a tetrahedron is read')
      if (allocated(error)) return
      call check(error, mesh%n_elements == 3 .and. mesh%cell_name(1) == 'HEX8' .and. mesh%cell_name(3) == 'TET4' &
                 .and. all(mesh%element_nodes(3) == [1, 2, 3, 5]), 'the tetrahedron''s cell and nodes')
   end subroutine test_tetrahedron

   !> One 10-node tetrahedron written by gmsh (tet10_gmsh.geo): read as a TET10 whose mid-edge
   !> nodes 5-10 sit at the middle of the edges 1-2, 2-3, 3-1, 1-4, 2-4, 3-4 (VTK / C3D10 order:
   !> gmsh's nodes 9 and 10 swapped), 10 connectivity rows, and its 6-node triangle on z = 0
   !> matched to one face. (gmsh places mid-edge nodes to about 1e-12.)
   subroutine test_tet10(error)
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: edge_corners(2, 5:10) = reshape([1, 2, 2, 3, 3, 1, 1, 4, 2, 4, 3, 4], [2, 6])
      type(mesh_t) :: mesh
      type(error_t), allocatable :: read_error
      integer, allocatable :: nodes(:)
      integer :: m, s
      call read_gmsh(data_path('tet10_gmsh.msh'), mesh, read_error)
      call check(error, .not. allocated(read_error), 'a 10-node tetrahedron is read')
      if (allocated(error)) return
      call check(error, mesh%n_elements == 1 .and. mesh%cell_name(1) == 'TET10' .and. &
                 size(mesh%connectivity, 1) == 10, 'one TET10, 10 connectivity rows')
      if (allocated(error)) return
      nodes = mesh%element_nodes(1)
      do m = 5, 10
         call check(error, all(abs(mesh%coords(:, nodes(m)) - 0.5_dp*(mesh%coords(:, nodes(edge_corners(1, m))) + &
                                                                      mesh%coords(:, nodes(edge_corners(2, m))))) &
                               < 1.0e-9_dp), 'node '//to_string(m)//' is not on its edge''s middle')
         if (allocated(error)) return
      end do
      s = mesh%find_surface('base')
      call check(error, s > 0, 'surface base')
      if (allocated(error)) return
      call check(error, size(mesh%surfaces(s)%faces) == 1 .and. &
                 all(abs(mesh%coords(3, mesh%face_nodes(1, mesh%surfaces(s)%faces(1)))) < 1.0e-12_dp), &
                 'the triangle is the face z = 0')
   end subroutine test_tet10

   !> gmsh -order 2 gives 27-node hexahedra (type 12) in the volume and 9-node quadrilaterals
   !> on the surfaces: the volume's error comes first.
   subroutine test_second_order(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error('block_order2_v41.msh', '178: only 8-node hexahedra (type 5), 4-node '// &
                        'tetrahedra (type 4) and 10-node tetrahedra (type 11) are supported: element 9 has type 12', error)
   end subroutine test_second_order

   subroutine test_unmatched_quad(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error('error_unmatched_quad.msh', '32: surface element 4 matches no face of a volume element', error)
   end subroutine test_unmatched_quad

   subroutine test_interior_face(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error('error_interior_face.msh', '32: surface element 4 lies on a face shared by two volume elements', error)
   end subroutine test_interior_face

   ! ---- malformed input (files written by the tests) ---------------------------------------

   !> A unit cube: nodes 1..8, hexahedron 2 in physical volume "cube" (3:1), quadrilateral 1
   !> on its face z = 0 in physical surface "bottom" (2:2). Format 2.2; lines: 1-3 $MeshFormat,
   !> 4-8 $PhysicalNames, 9-19 $Nodes, 20-24 $Elements.
   function cube_v22() result(text)
      character(len=:), allocatable :: text
      text = '$MeshFormat'//nl//'2.2 0 8'//nl//'$EndMeshFormat'//nl// &
             '$PhysicalNames'//nl//'2'//nl//'2 2 "bottom"'//nl//'3 1 "cube"'//nl//'$EndPhysicalNames'//nl// &
             '$Nodes'//nl//'8'//nl//'1 0 0 0'//nl//'2 1 0 0'//nl//'3 1 1 0'//nl//'4 0 1 0'//nl// &
             '5 0 0 1'//nl//'6 1 0 1'//nl//'7 1 1 1'//nl//'8 0 1 1'//nl//'$EndNodes'//nl// &
             '$Elements'//nl//'2'//nl//'1 3 2 2 1 1 4 3 2'//nl//'2 5 2 1 1 1 2 3 4 5 6 7 8'//nl// &
             '$EndElements'//nl
   end function cube_v22

   !> The same cube in format 4.1: surface entity 1 (physical 2), volume entity 1 (physical 1).
   !> Lines: 1-3 $MeshFormat, 4-8 $PhysicalNames, 9-13 $Entities, 14-33 $Nodes, 34-40 $Elements.
   function cube_v41() result(text)
      character(len=:), allocatable :: text
      text = '$MeshFormat'//nl//'4.1 0 8'//nl//'$EndMeshFormat'//nl// &
             '$PhysicalNames'//nl//'2'//nl//'2 2 "bottom"'//nl//'3 1 "cube"'//nl//'$EndPhysicalNames'//nl// &
             '$Entities'//nl//'0 0 1 1'//nl//'1 0 0 0 1 1 0 1 2 0'//nl//'1 0 0 0 1 1 1 1 1 0'//nl// &
             '$EndEntities'//nl// &
             '$Nodes'//nl//'1 8 1 8'//nl//'3 1 0 8'//nl//'1'//nl//'2'//nl//'3'//nl//'4'//nl//'5'//nl// &
             '6'//nl//'7'//nl//'8'//nl//'0 0 0'//nl//'1 0 0'//nl//'1 1 0'//nl//'0 1 0'//nl// &
             '0 0 1'//nl//'1 0 1'//nl//'1 1 1'//nl//'0 1 1'//nl//'$EndNodes'//nl// &
             '$Elements'//nl//'2 2 1 2'//nl//'2 1 3 1'//nl//'1 1 4 3 2'//nl//'3 1 5 1'//nl// &
             '2 1 2 3 4 5 6 7 8'//nl//'$EndElements'//nl
   end function cube_v41

   !> `text` with its first `old` replaced by `new` (unchanged if `old` does not occur: the
   !> test then fails for want of the expected error).
   function replaced(text, old, new) result(changed)
      character(len=*), intent(in) :: text, old, new
      character(len=:), allocatable :: changed
      integer :: at
      at = index(text, old)
      if (at == 0) then
         changed = text
      else
         changed = text(1:at - 1)//new//text(at + len(old):)
      end if
   end function replaced

   !> Write `text` to the file `name`, read it with read_gmsh, delete it.
   subroutine read_text(name, text, mesh, read_error, error)
      character(len=*), intent(in) :: name, text
      type(mesh_t), intent(out) :: mesh
      type(error_t), allocatable, intent(out) :: read_error, error
      call write_text(name, text, error)
      if (allocated(error)) return
      call read_gmsh(output_path(name), mesh, read_error)
      call delete_file(name)
   end subroutine read_text

   !> Write `text` to the file `name` (output_path) as it is.
   subroutine write_text(name, text, error)
      character(len=*), intent(in) :: name, text
      type(error_t), allocatable, intent(out) :: error
      integer :: unit, status
      open (newunit=unit, file=output_path(name), status='replace', access='stream', form='unformatted', &
            action='write', iostat=status)
      call check(error, status == 0, 'cannot write '//output_path(name))
      if (allocated(error)) return
      write (unit) text
      close (unit)
   end subroutine write_text

   !> Delete the file `name` (output_path) if it exists.
   subroutine delete_file(name)
      character(len=*), intent(in) :: name
      integer :: unit, status
      open (newunit=unit, file=output_path(name), status='old', iostat=status)
      if (status == 0) close (unit, status='delete')
   end subroutine delete_file

   !> Read `text` (written to `name`), expecting an error containing "name:" then `fragment`.
   subroutine expect_text_error(name, text, fragment, error)
      character(len=*), intent(in) :: name, text, fragment
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      type(error_t), allocatable :: read_error
      call read_text(name, text, mesh, read_error, error)
      if (allocated(error)) return
      call check_message_contains(error, read_error, name//':'//fragment)
   end subroutine expect_text_error

   !> Both cube files read: 8 nodes, one hexahedron, sets "bottom" (face 1) and "cube".
   subroutine test_cube_files(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: v22, v41
      type(error_t), allocatable :: read_error
      call read_text('gmsh_test_cube_v22.msh', cube_v22(), v22, read_error, error)
      if (allocated(error)) return
      if (allocated(read_error)) call move_alloc(read_error, error)
      if (allocated(error)) return
      call read_text('gmsh_test_cube_v41.msh', cube_v41(), v41, read_error, error)
      if (allocated(error)) return
      if (allocated(read_error)) call move_alloc(read_error, error)
      if (allocated(error)) return
      call check(error, v22%n_nodes == 8 .and. v22%n_elements == 1 .and. v41%n_nodes == 8 .and. &
                 v41%n_elements == 1, '8 nodes and 1 hexahedron in each format')
      if (allocated(error)) return
      call check(error, all(v22%coords == v41%coords) .and. all(v22%connectivity == v41%connectivity), &
                 'same nodes and hexahedron')
      if (allocated(error)) return
      call check(error, size(v41%surfaces) == 1 .and. size(v41%element_sets) == 1, 'one surface, one element set')
      if (allocated(error)) return
      call check(error, v41%surfaces(1)%name == 'bottom' .and. all(v41%surfaces(1)%faces == 1) .and. &
                 v41%element_sets(1)%name == 'cube', 'surface "bottom" on face 1, element set "cube"')
   end subroutine test_cube_files

   !> gmsh -save_parametric: `dim` parametric coordinates after x y z (u v on a surface), read
   !> and dropped; the mesh is that of the plain file.
   subroutine test_parametric_nodes(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: plain, parametric
      type(error_t), allocatable :: read_error
      character(len=:), allocatable :: text
      text = replaced(cube_v41(), '$Nodes'//nl//'1 8 1 8'//nl//'3 1 0 8'//nl//'1'//nl//'2'//nl//'3'//nl//'4'//nl// &
                      '5'//nl//'6'//nl//'7'//nl//'8'//nl//'0 0 0'//nl//'1 0 0'//nl//'1 1 0'//nl//'0 1 0'//nl, &
                      '$Nodes'//nl//'2 8 1 8'//nl//'2 1 1 4'//nl//'1'//nl//'2'//nl//'3'//nl//'4'//nl// &
                      '0 0 0 0 0'//nl//'1 0 0 1 0'//nl//'1 1 0 1 1'//nl//'0 1 0 0 1'//nl// &
                      '3 1 0 4'//nl//'5'//nl//'6'//nl//'7'//nl//'8'//nl)
      call read_text('gmsh_test_parametric.msh', text, parametric, read_error, error)
      if (allocated(error)) return
      if (allocated(read_error)) call move_alloc(read_error, error)
      if (allocated(error)) return
      call read_text('gmsh_test_plain.msh', cube_v41(), plain, read_error, error)
      if (allocated(error)) return
      if (allocated(read_error)) call move_alloc(read_error, error)
      if (allocated(error)) return
      call check(error, parametric%n_nodes == 8 .and. all(parametric%coords == plain%coords) .and. &
                 all(parametric%connectivity == plain%connectivity), 'parametric coordinates dropped')
   end subroutine test_parametric_nodes

   subroutine test_second_physical_names(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: names = '$PhysicalNames'//nl//'1'//nl//'2 2 "floor"'//nl//'$EndPhysicalNames'//nl
      call expect_text_error('gmsh_test_names_v22.msh', replaced(cube_v22(), '$Nodes', names//'$Nodes'), &
                             '9: a second $PhysicalNames section (the first is on line 4)', error)
      if (allocated(error)) return
      call expect_text_error('gmsh_test_names_v41.msh', replaced(cube_v41(), '$Elements', names//'$Elements'), &
                             '34: a second $PhysicalNames section (the first is on line 4)', error)
   end subroutine test_second_physical_names

   subroutine test_second_entities(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_text_error('gmsh_test_entities.msh', replaced(cube_v41(), '$Nodes', &
                             '$Entities'//nl//'0 0 0 0'//nl//'$EndEntities'//nl//'$Nodes'), &
                             '14: a second $Entities section (the first is on line 9)', error)
   end subroutine test_second_entities

   subroutine test_second_mesh_format(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_text_error('gmsh_test_format.msh', replaced(cube_v22(), '$PhysicalNames', &
                             '$MeshFormat'//nl//'4.1 0 8'//nl//'$EndMeshFormat'//nl//'$PhysicalNames'), &
                             '4: a second $MeshFormat section (the first is on line 1)', error)
   end subroutine test_second_mesh_format

   subroutine test_second_nodes_elements(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_text_error('gmsh_test_nodes.msh', cube_v22()//'$Nodes'//nl//'0'//nl//'$EndNodes'//nl, &
                             '25: a second $Nodes section (the first is on line 9)', error)
      if (allocated(error)) return
      call expect_text_error('gmsh_test_elements.msh', cube_v41()//'$Elements'//nl//'0 0 0 0'//nl// &
                             '$EndElements'//nl, '41: a second $Elements section (the first is on line 34)', error)
   end subroutine test_second_nodes_elements

   !> In 4.1 the physical groups of an element block are those of its entity.
   subroutine test_entities_after_elements(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: entities = '$Entities'//nl//'0 0 1 1'//nl//'1 0 0 0 1 1 0 1 2 0'//nl// &
                                                '1 0 0 0 1 1 1 1 1 0'//nl//'$EndEntities'//nl
      call expect_text_error('gmsh_test_entities_last.msh', replaced(cube_v41(), entities, '')//entities, &
                             '36: $Entities after $Elements (line 29)', error)
   end subroutine test_entities_after_elements

   subroutine test_physical_tag_sign(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_text_error('gmsh_test_tag_name.msh', replaced(cube_v22(), '2 2 "bottom"', '2 -2 "bottom"'), &
                             '6: expected a positive physical tag, got "-2"', error)
      if (allocated(error)) return
      call expect_text_error('gmsh_test_tag_zero.msh', replaced(cube_v22(), '2 2 "bottom"', '2 0 "bottom"'), &
                             '6: expected a positive physical tag, got "0"', error)
      if (allocated(error)) return
      call expect_text_error('gmsh_test_tag_element.msh', replaced(cube_v22(), '1 3 2 2 1', '1 3 2 -2 1'), &
                             '22: expected a positive physical tag, got "-2"', error)
      if (allocated(error)) return
      call expect_text_error('gmsh_test_tag_entity.msh', replaced(cube_v41(), '1 0 0 0 1 1 0 1 2 0', &
                             '1 0 0 0 1 1 0 1 -2 0'), '11: expected a positive physical tag, got "-2"', error)
   end subroutine test_physical_tag_sign

   subroutine test_physical_name_dimension(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_text_error('gmsh_test_name_dim.msh', replaced(cube_v22(), '2 2 "bottom"', '4 2 "bottom"'), &
                             '6: expected a dimension 0..3, got "4"', error)
      if (allocated(error)) return
      call expect_text_error('gmsh_test_name_dim_neg.msh', replaced(cube_v41(), '2 2 "bottom"', '-1 2 "bottom"'), &
                             '6: expected a dimension 0..3, got "-1"', error)
   end subroutine test_physical_name_dimension

   subroutine test_named_twice(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_text_error('gmsh_test_named_twice.msh', replaced(cube_v22(), '2'//nl//'2 2 "bottom"', &
                             '3'//nl//'2 2 "bottom"'//nl//'2 2 "floor"'), &
                             '7: physical group 2:2 is named twice (first on line 6)', error)
   end subroutine test_named_twice

   !> Counts whose sums overflow default integers: four entity counts, a node or element block
   !> beyond its section's count.
   subroutine test_count_overflow(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_text_error('gmsh_test_entity_sum.msh', replaced(cube_v41(), '0 0 1 1', &
                             '2147483647 2147483647 1 1'), '10: $Entities declares 4294967296 entities', error)
      if (allocated(error)) return
      call expect_text_error('gmsh_test_node_block.msh', replaced(replaced(cube_v41(), '1 8 1 8', '2 8 1 8'), &
                             '0 1 1'//nl//'$EndNodes', '0 1 1'//nl//'3 1 0 2147483647'//nl//'$EndNodes'), &
                             '33: bad counts: the node blocks hold more than the 8 nodes declared on line 15', error)
      if (allocated(error)) return
      call expect_text_error('gmsh_test_element_block.msh', replaced(cube_v41(), '3 1 5 1', '3 1 5 2147483647'), &
                             '38: bad counts: the element blocks hold more than the 2 elements declared '// &
                             'on line 35', error)
   end subroutine test_count_overflow

   subroutine test_parametric_flag(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_text_error('gmsh_test_parametric_flag.msh', replaced(cube_v41(), '3 1 0 8', '3 1 2 8'), &
                             '16: expected parametric 0 or 1, got "2"', error)
      if (allocated(error)) return
      call expect_text_error('gmsh_test_parametric_short.msh', replaced(cube_v41(), '3 1 0 8', '3 1 1 8'), &
                             '25: expected a number, got end of line', error)
   end subroutine test_parametric_flag

   subroutine test_stray_end(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_text_error('gmsh_test_stray_end.msh', replaced(cube_v22(), '$Nodes', '$EndNodes'//nl//'$Nodes'), &
                             '9: "$EndNodes" outside its section', error)
   end subroutine test_stray_end

   subroutine test_coordinates_not_finite(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_text_error('gmsh_test_nan.msh', replaced(cube_v22(), '7 1 1 1', '7 1 NaN 1'), &
                             '17: expected a number, got "NaN"', error)
      if (allocated(error)) return
      call expect_text_error('gmsh_test_inf.msh', replaced(cube_v41(), '1 1 1'//nl//'0 1 1', '1 1 -Inf'//nl//'0 1 1'), &
                             '31: expected a number, got "-Inf"', error)
      if (allocated(error)) return
      call expect_text_error('gmsh_test_1e400.msh', replaced(cube_v22(), '7 1 1 1', '7 1 1e400 1'), &
                             '17: number out of range, got "1e400"', error)
   end subroutine test_coordinates_not_finite
end module test_gmsh_reader
