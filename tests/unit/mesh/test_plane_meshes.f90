!> Tests of the plane (2D) meshes of the gmsh and .inp readers: QUAD4 and TRI3 cells, their
!> element and node sets, and surfaces of element edges.
!>
!> data/plate2d_v22.msh and data/plate2d_v41.msh: gmsh 4.8.4 from data/plate2d.geo (x in
!> [0, 2], y in [0, 1]; 2 x 2 quadrilaterals in physical surface "quads" for x <= 1, 8
!> triangles in "tris" for x >= 1; physical curves "bottom" (y = 0), "right" (x = 2), "left"
!> (x = 0), physical point "origin"). The element ids and the local edges expected below are
!> read off the files: e.g. line 2 of "bottom" (nodes 1 7) is edge 1 (nodes 1-2) of
!> quadrilateral 18 `1 7 14 12` in plate2d_v22.msh, and line 8 of "left" (nodes 6 12) is edge
!> 4 (nodes 4-1) of quadrilateral 19 `12 14 11 6`.
!> tests/inp/plate2d.inp: 4 CPE4 and 3 CPE3 on [0, 2] x [0, 1]; its surfaces name the faces
!> S1..S4, which are the local edges 1..4 (quadrilateral edges 1-2, 2-3, 3-4, 4-1, triangle
!> edges 1-2, 2-3, 3-1; frix_quad4_cell, frix_tri3_cell).
!> Besides the lists, every surface edge is checked to lie on its side of the plate.
module test_plane_meshes
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_message_contains, output_path
   use frix_strings, only: to_string
   use frix_mesh, only: mesh_t
   use frix_mesh_selection, only: sort_nodes
   use frix_gmsh_reader, only: read_gmsh
   use frix_inp_reader, only: read_inp
   use test_data_location, only: data_path, tests_path
   use test_gmsh_reader, only: replaced, write_text, delete_file
   implicit none
   private

   public :: collect_plane_meshes, collect_plane_errors

   character(len=*), parameter :: nl = new_line('a')

   !> The expected ids of the plate of plate2d.geo in one of its files: the elements of the
   !> element sets and of the surfaces (in the surface's order), by user id.
   type :: plate_ids_t
      integer, allocatable :: quads(:), tris(:), bottom(:), right(:), left(:)
   end type plate_ids_t

contains

   subroutine collect_plane_meshes(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('gmsh_plate_v22', test_gmsh_v22), &
               new_unittest('gmsh_plate_v41', test_gmsh_v41), &
               new_unittest('gmsh_plane_without_groups', test_gmsh_no_groups), &
               new_unittest('gmsh_plane_z_round_off', test_gmsh_round_off), &
               new_unittest('inp_plate', test_inp_plate)]
   end subroutine collect_plane_meshes

   subroutine collect_plane_errors(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('gmsh_plane_node_off_plane', test_gmsh_off_plane), &
               new_unittest('gmsh_plane_line_matching_no_edge', test_gmsh_unmatched_line), &
               new_unittest('gmsh_plane_line_on_interior_edge', test_gmsh_interior_edge), &
               new_unittest('gmsh_plane_second_order_triangle', test_gmsh_tri6), &
               new_unittest('inp_plane_stress', test_inp_plane_stress), &
               new_unittest('inp_mixed_dimensions', test_inp_mixed), &
               new_unittest('inp_plane_node_off_plane', test_inp_off_plane)]
   end subroutine collect_plane_errors

   ! ---- gmsh -------------------------------------------------------------------------------

   !> Format 2.2 writes the 8 triangles (ids 10-17) before the 4 quadrilaterals (18-21).
   subroutine test_gmsh_v22(error)
      type(error_t), allocatable, intent(out) :: error
      type(plate_ids_t) :: ids
      ids%quads = [18, 19, 20, 21]
      ids%tris = [10, 11, 12, 13, 14, 15, 16, 17]
      ids%bottom = [10, 14, 18, 20]
      ids%right = [15, 17]
      ids%left = [18, 19]
      call check_plate('plate2d_v22.msh', ids, error)
   end subroutine test_gmsh_v22

   !> Format 4.1 writes the quadrilaterals (ids 10-13) before the triangles (14-21).
   subroutine test_gmsh_v41(error)
      type(error_t), allocatable, intent(out) :: error
      type(plate_ids_t) :: ids
      ids%quads = [10, 11, 12, 13]
      ids%tris = [14, 15, 16, 17, 18, 19, 20, 21]
      ids%bottom = [10, 12, 14, 18]
      ids%right = [19, 21]
      ids%left = [10, 11]
      call check_plate('plate2d_v41.msh', ids, error)
   end subroutine test_gmsh_v41

   !> The plate of plate2d.geo read from data file `name`: 15 nodes in the x-y plane, 12
   !> elements, the sets of its physical groups in (dim, tag) order, edges 1 on "bottom", 2 on
   !> "right", 4 on "left".
   subroutine check_plate(name, ids, error)
      character(len=*), intent(in) :: name
      type(plate_ids_t), intent(in) :: ids
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      type(error_t), allocatable :: read_error
      integer :: e
      call read_gmsh(data_path(name), mesh, read_error)
      call check(error, .not. allocated(read_error), 'read '//name)
      if (allocated(error)) return
      call check(error, mesh%n_nodes == 15 .and. mesh%n_elements == 12, 'plate: 15 nodes and 12 elements, got '// &
                 to_string(mesh%n_nodes)//' and '//to_string(mesh%n_elements))
      if (allocated(error)) return
      call check(error, all(mesh%coords(3, :) == 0.0_dp), 'plate: z = 0')
      if (allocated(error)) return
      do e = 1, mesh%n_elements
         call check(error, mesh%cell_dimension(e) == 2, 'plate: element '//to_string(e)//' of dimension 2')
         if (allocated(error)) return
         if (any(ids%quads == mesh%element_ids(e))) then
            call check(error, mesh%cell_name(e) == 'QUAD4', 'element id '//to_string(mesh%element_ids(e))//' QUAD4')
         else
            call check(error, mesh%cell_name(e) == 'TRI3', 'element id '//to_string(mesh%element_ids(e))//' TRI3')
         end if
         if (allocated(error)) return
      end do
      call check(error, set_names(mesh) == 'origin bottom right left quads tris | quads tris | bottom right left', &
                 'plate: set names "'//set_names(mesh)//'"')
      if (allocated(error)) return
      call check_list(mesh%element_ids(mesh%element_sets(1)%elements), ids%quads, 'element set quads', error)
      if (allocated(error)) return
      call check_list(mesh%element_ids(mesh%element_sets(2)%elements), ids%tris, 'element set tris', error)
      if (allocated(error)) return
      call check_node_sets(mesh, error)
      if (allocated(error)) return
      call check_surface(mesh, 1, ids%bottom, [1, 1, 1, 1], 2, 0.0_dp, error)
      if (allocated(error)) return
      call check_surface(mesh, 2, ids%right, [2, 2], 1, 2.0_dp, error)
      if (allocated(error)) return
      call check_surface(mesh, 3, ids%left, [4, 4], 1, 0.0_dp, error)
   end subroutine check_plate

   !> The node sets of plate2d.geo's groups by node id (read off plate2d_v22.msh: the nodes of
   !> the groups' elements).
   subroutine check_node_sets(mesh, error)
      type(mesh_t), intent(in) :: mesh
      type(error_t), allocatable, intent(out) :: error
      call check_list(node_ids(mesh, 1), [1], 'node set origin', error)
      if (allocated(error)) return
      call check_list(node_ids(mesh, 2), [1, 2, 3, 7, 8], 'node set bottom', error)
      if (allocated(error)) return
      call check_list(node_ids(mesh, 3), [3, 4, 9], 'node set right', error)
      if (allocated(error)) return
      call check_list(node_ids(mesh, 4), [1, 6, 12], 'node set left', error)
      if (allocated(error)) return
      call check_list(node_ids(mesh, 5), [1, 2, 5, 6, 7, 11, 12, 13, 14], 'node set quads', error)
      if (allocated(error)) return
      call check_list(node_ids(mesh, 6), [2, 3, 4, 5, 8, 9, 10, 13, 15], 'node set tris', error)
   end subroutine check_node_sets

   !> A plane mesh without physical groups (gmsh then writes every element): its cells, no sets.
   subroutine test_gmsh_no_groups(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      type(error_t), allocatable :: read_error
      character(len=:), allocatable :: text
      text = replaced(square_v22(), '1 1 2 2 1 1 2', '1 1 2 0 1 1 2')
      text = replaced(text, '2 1 2 2 1 2 3', '2 1 2 0 1 2 3')
      text = replaced(text, '3 3 2 1 1 1 2 5 6', '3 3 2 0 1 1 2 5 6')
      text = replaced(text, '4 3 2 1 1 2 3 4 5', '4 3 2 0 1 2 3 4 5')
      call read_text('plane_no_groups.msh', text, .false., mesh, read_error, error)
      if (allocated(error)) return
      call check(error, .not. allocated(read_error), 'read the square without groups')
      if (allocated(error)) return
      call check(error, mesh%n_elements == 2 .and. size(mesh%node_sets) == 0 .and. size(mesh%surfaces) == 0 .and. &
                 size(mesh%element_sets) == 0, 'square without groups: 2 elements, no sets')
      if (allocated(error)) return
      call check(error, mesh%cell_name(1) == 'QUAD4' .and. mesh%cell_name(2) == 'QUAD4', 'square: QUAD4 cells')
   end subroutine test_gmsh_no_groups

   !> A z of round-off size (1e-15 beside coordinates up to 2) is the plane's.
   subroutine test_gmsh_round_off(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      type(error_t), allocatable :: read_error
      call read_text('plane_round_off.msh', replaced(square_v22(), '4 2 1 0', '4 2 1 1e-15'), .false., mesh, &
                     read_error, error)
      if (allocated(error)) return
      call check(error, .not. allocated(read_error), 'z = 1e-15 accepted')
      if (allocated(error)) return
      call check_surface(mesh, 1, [3, 4], [1, 1], 2, 0.0_dp, error)
   end subroutine test_gmsh_round_off

   subroutine test_gmsh_off_plane(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_text_error('plane_off_plane.msh', replaced(square_v22(), '4 2 1 0', '4 2 1 0.001'), .false., &
                             '14: node 4 has z = ', error)
   end subroutine test_gmsh_off_plane

   subroutine test_gmsh_unmatched_line(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_text_error('plane_unmatched.msh', replaced(square_v22(), '1 1 2 2 1 1 2', '1 1 2 2 1 1 4'), &
                             .false., '20: line element 1 matches no edge of a plane element', error)
   end subroutine test_gmsh_unmatched_line

   subroutine test_gmsh_interior_edge(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_text_error('plane_interior.msh', replaced(square_v22(), '2 1 2 2 1 2 3', '2 1 2 2 1 2 5'), &
                             .false., '21: line element 2 lies on an edge shared by two plane elements '// &
                             '(an interior edge)', error)
   end subroutine test_gmsh_interior_edge

   !> A 6-node triangle (type 9) has no plane element.
   subroutine test_gmsh_tri6(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_text_error('plane_tri6.msh', replaced(square_v22(), '4 3 2 1 1 2 3 4 5', '4 9 2 1 1 2 3 4 5 6 1'), &
                             .false., '23: only 4-node quadrilaterals (type 3) and 3-node triangles (type 2) are '// &
                             'supported in a plane mesh (no volume elements): element 4 has type 9', error)
   end subroutine test_gmsh_tri6

   !> Two unit squares side by side, quadrilaterals 3 and 4 in physical surface "plate" (2:1),
   !> the lines 1 (nodes 1 2) and 2 (nodes 2 3) in physical curve "bottom" (1:2). Format 2.2;
   !> lines 11-16 the nodes, 20-23 the elements.
   function square_v22() result(text)
      character(len=:), allocatable :: text
      text = '$MeshFormat'//nl//'2.2 0 8'//nl//'$EndMeshFormat'//nl// &
             '$PhysicalNames'//nl//'2'//nl//'1 2 "bottom"'//nl//'2 1 "plate"'//nl//'$EndPhysicalNames'//nl// &
             '$Nodes'//nl//'6'//nl//'1 0 0 0'//nl//'2 1 0 0'//nl//'3 2 0 0'//nl//'4 2 1 0'//nl// &
             '5 1 1 0'//nl//'6 0 1 0'//nl//'$EndNodes'//nl// &
             '$Elements'//nl//'4'//nl//'1 1 2 2 1 1 2'//nl//'2 1 2 2 1 2 3'//nl//'3 3 2 1 1 1 2 5 6'//nl// &
             '4 3 2 1 1 2 3 4 5'//nl//'$EndElements'//nl
   end function square_v22

   ! ---- .inp -------------------------------------------------------------------------------

   subroutine test_inp_plate(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      type(error_t), allocatable :: read_error
      integer :: e
      call read_inp(tests_path('inp/plate2d.inp'), mesh, read_error)
      call check(error, .not. allocated(read_error), 'read tests/inp/plate2d.inp')
      if (allocated(error)) return
      call check(error, mesh%n_nodes == 11 .and. mesh%n_elements == 7, 'plate2d.inp: 11 nodes and 7 elements')
      if (allocated(error)) return
      call check(error, all(mesh%coords(3, :) == 0.0_dp), 'plate2d.inp: z = 0 (nodes given as id, x, y)')
      if (allocated(error)) return
      do e = 1, 7
         if (e <= 4) then
            call check(error, mesh%cell_name(e) == 'QUAD4', 'CPE4 element '//to_string(e)//' is a QUAD4')
         else
            call check(error, mesh%cell_name(e) == 'TRI3', 'CPE3 element '//to_string(e)//' is a TRI3')
         end if
         if (allocated(error)) return
      end do
      call check(error, set_names(mesh) == 'all origin | quads tris bottom_quads left_quads | bottom right top left', &
                 'plate2d.inp: set names "'//set_names(mesh)//'"')
      if (allocated(error)) return
      call check_list(mesh%element_sets(1)%elements, [1, 2, 3, 4], 'element set quads', error)
      if (allocated(error)) return
      call check_list(mesh%element_sets(2)%elements, [5, 6, 7], 'element set tris', error)
      if (allocated(error)) return
      call check_list(mesh%node_sets(2)%nodes, [1], 'node set origin', error)
      if (allocated(error)) return
      call check_surface(mesh, 1, [1, 2, 5], [1, 1, 1], 2, 0.0_dp, error)
      if (allocated(error)) return
      call check_surface(mesh, 2, [6], [2], 1, 2.0_dp, error)
      if (allocated(error)) return
      call check_surface(mesh, 3, [3, 4, 7], [3, 3, 2], 2, 1.0_dp, error)
      if (allocated(error)) return
      call check_surface(mesh, 4, [1, 3], [4, 4], 1, 0.0_dp, error)
   end subroutine test_inp_plate

   subroutine test_inp_plane_stress(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_text_error('plane_stress.inp', square_inp('CPS4'), .true., &
                             '6:10: element type CPS4 is a plane stress element, which frix does not offer', error)
   end subroutine test_inp_plane_stress

   !> A C3D8 before a CPE4: the second *ELEMENT is the error, naming the first.
   subroutine test_inp_mixed(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      text = '*NODE'//nl//'1, 0, 0, 0'//nl//'2, 1, 0, 0'//nl//'3, 1, 1, 0'//nl//'4, 0, 1, 0'//nl// &
             '5, 0, 0, 1'//nl//'6, 1, 0, 1'//nl//'7, 1, 1, 1'//nl//'8, 0, 1, 1'//nl// &
             '*ELEMENT, TYPE=C3D8'//nl//'1, 1, 2, 3, 4, 5, 6, 7, 8'//nl// &
             '*ELEMENT, TYPE=CPE4'//nl//'2, 1, 2, 3, 4'//nl
      call expect_text_error('mixed.inp', text, .true., '12:10: element type CPE4 is plane (2D), but the elements '// &
                             'of TYPE=C3D8 ('//output_path('mixed.inp')//':10) are solid (3D)', error)
   end subroutine test_inp_mixed

   subroutine test_inp_off_plane(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_text_error('off_plane.inp', replaced(square_inp('CAX4'), '3, 1, 1', '3, 1, 1, 0.5'), .true., &
                             '4: node 3 has z = ', error)
   end subroutine test_inp_off_plane

   !> A unit square of one element of type `element_type` (its *ELEMENT on line 6), nodes
   !> given as `id, x, y`.
   function square_inp(element_type) result(text)
      character(len=*), intent(in) :: element_type
      character(len=:), allocatable :: text
      text = '*NODE'//nl//'1, 0, 0'//nl//'2, 1, 0'//nl//'3, 1, 1'//nl//'4, 0, 1'//nl// &
             '*ELEMENT, TYPE='//element_type//', ELSET=plate'//nl//'1, 1, 2, 3, 4'//nl
   end function square_inp

   ! ---- helpers ----------------------------------------------------------------------------

   !> Surface k: its elements (by user id) and local edges as expected, and each edge's two
   !> nodes on the line x(axis) = value.
   subroutine check_surface(mesh, k, element_ids, edges, axis, value, error)
      type(mesh_t), intent(in) :: mesh
      integer, intent(in) :: k, element_ids(:), edges(:), axis
      real(dp), intent(in) :: value
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: nodes(:)
      integer :: j
      associate (surface => mesh%surfaces(k))
         call check_list(mesh%element_ids(surface%elements), element_ids, 'elements of surface '//surface%name, error)
         if (allocated(error)) return
         call check_list(surface%faces, edges, 'edges of surface '//surface%name, error)
         if (allocated(error)) return
         do j = 1, size(surface%elements)
            nodes = mesh%face_nodes(surface%elements(j), surface%faces(j))
            call check(error, size(nodes) == 2, 'surface '//surface%name//': 2-node edges')
            if (allocated(error)) return
            call check(error, all(abs(mesh%coords(axis, nodes) - value) < 1.0e-9_dp), 'surface '//surface%name// &
                       ': edge '//to_string(surface%faces(j))//' of element '// &
                       to_string(mesh%element_ids(surface%elements(j)))//' off its side')
            if (allocated(error)) return
         end do
      end associate
   end subroutine check_surface

   subroutine check_list(actual, expected, what, error)
      integer, intent(in) :: actual(:), expected(:)
      character(len=*), intent(in) :: what
      type(error_t), allocatable, intent(out) :: error
      call check(error, size(actual) == size(expected), what//': '//to_string(size(expected))//' entries, got '// &
                 to_string(size(actual)))
      if (allocated(error)) return
      call check(error, all(actual == expected), what//': other entries than expected')
   end subroutine check_list

   !> The node ids of node set k, sorted.
   function node_ids(mesh, k) result(ids)
      type(mesh_t), intent(in) :: mesh
      integer, intent(in) :: k
      integer, allocatable :: ids(:)
      ids = sort_nodes(mesh%node_ids(mesh%node_sets(k)%nodes))
   end function node_ids

   !> "node sets | element sets | surfaces", names separated by blanks.
   function set_names(mesh) result(text)
      type(mesh_t), intent(in) :: mesh
      character(len=:), allocatable :: text
      integer :: k
      text = ''
      do k = 1, size(mesh%node_sets)
         text = text//mesh%node_sets(k)%name//' '
      end do
      text = text//'|'
      do k = 1, size(mesh%element_sets)
         text = text//' '//mesh%element_sets(k)%name
      end do
      text = text//' |'
      do k = 1, size(mesh%surfaces)
         text = text//' '//mesh%surfaces(k)%name
      end do
   end function set_names

   !> Write `text` to the file `name`, read it (with read_inp if `inp`, else read_gmsh), delete it.
   subroutine read_text(name, text, inp, mesh, read_error, error)
      character(len=*), intent(in) :: name, text
      logical, intent(in) :: inp
      type(mesh_t), intent(out) :: mesh
      type(error_t), allocatable, intent(out) :: read_error, error
      call write_text(name, text, error)
      if (allocated(error)) return
      if (inp) then
         call read_inp(output_path(name), mesh, read_error)
      else
         call read_gmsh(output_path(name), mesh, read_error)
      end if
      call delete_file(name)
   end subroutine read_text

   !> Read `text` (written to `name`), expecting an error containing "<path>:" then `fragment`.
   subroutine expect_text_error(name, text, inp, fragment, error)
      character(len=*), intent(in) :: name, text, fragment
      logical, intent(in) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      type(error_t), allocatable :: read_error
      call read_text(name, text, inp, mesh, read_error, error)
      if (allocated(error)) return
      call check_message_contains(error, read_error, name//':'//fragment)
   end subroutine expect_text_error
end module test_plane_meshes
