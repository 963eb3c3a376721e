!> Tests of frix_block_generator: counts, coordinates, ids and the orientation of the sides.
module test_block_generator
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close
   use frix_mesh, only: mesh_t, hex8_face_nodes
   use frix_block_generator, only: generate_block, block_side_names
   implicit none
   private
   public :: collect_block_generator

contains

   subroutine collect_block_generator(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('counts_and_ids', test_counts_and_ids), &
               new_unittest('coordinates', test_coordinates), &
               new_unittest('side_sets', test_side_sets), &
               new_unittest('outward_faces', test_outward_faces), &
               new_unittest('bad_divisions', test_bad_divisions)]
   end subroutine collect_block_generator

   !> (nx+1)(ny+1)(nz+1) nodes, nx ny nz elements, ids from the given first ids.
   subroutine test_counts_and_ids(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: block
      call generate_block('b', [0.0_dp, 0.0_dp, 0.0_dp], [3.0_dp, 2.0_dp, 1.0_dp], [3, 2, 4], 101, 7, block, error)
      if (allocated(error)) return
      call check(error, block%n_nodes == 4*3*5 .and. block%n_elements == 3*2*4, 'node / element counts')
      if (allocated(error)) return
      call check(error, block%node_ids(1) == 101 .and. block%node_ids(60) == 160, 'node ids from 101')
      if (allocated(error)) return
      call check(error, block%element_ids(1) == 7 .and. block%element_ids(24) == 30, 'element ids from 7')
   end subroutine test_counts_and_ids

   !> Node (i, j, k) = 1 + i + (nx+1)(j + (ny+1) k) sits at origin + (i lx/nx, j ly/ny, k lz/nz).
   subroutine test_coordinates(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: block
      integer :: n
      call generate_block('b', [1.0_dp, -1.0_dp, 2.0_dp], [3.0_dp, 2.0_dp, 1.0_dp], [3, 2, 4], 1, 1, block, error)
      if (allocated(error)) return
      n = 1 + 2 + 4*(1 + 3*3)   ! i = 2, j = 1, k = 3
      call check_close(error, block%coords(1, n), 1.0_dp + 2.0_dp, 1.0e-15_dp, 0.0_dp, 'x of node (2,1,3)')
      if (allocated(error)) return
      call check_close(error, block%coords(2, n), -1.0_dp + 1.0_dp, 0.0_dp, 1.0e-15_dp, 'y of node (2,1,3)')
      if (allocated(error)) return
      call check_close(error, block%coords(3, n), 2.0_dp + 0.75_dp, 1.0e-15_dp, 0.0_dp, 'z of node (2,1,3)')
   end subroutine test_coordinates

   !> Side node sets hold (ny+1)(nz+1) etc. nodes on the plane; side surfaces ny nz etc. faces.
   subroutine test_side_sets(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: block
      integer :: expected_nodes(6), expected_faces(6), side, set
      real(dp) :: plane(6)
      integer :: axis(6)
      call generate_block('b', [0.0_dp, 0.0_dp, 0.0_dp], [3.0_dp, 2.0_dp, 1.0_dp], [3, 2, 4], 1, 1, block, error)
      if (allocated(error)) return
      expected_nodes = [3*5, 3*5, 4*5, 4*5, 4*3, 4*3]
      expected_faces = [2*4, 2*4, 3*4, 3*4, 3*2, 3*2]
      plane = [0.0_dp, 3.0_dp, 0.0_dp, 2.0_dp, 0.0_dp, 1.0_dp]
      axis = [1, 1, 2, 2, 3, 3]
      do side = 1, 6
         set = block%find_node_set('b_'//trim(block_side_names(side)))
         call check(error, set > 0, 'node set b_'//trim(block_side_names(side))//' exists')
         if (allocated(error)) return
         call check(error, size(block%node_sets(set)%nodes) == expected_nodes(side), 'node count of a side')
         if (allocated(error)) return
         call check(error, all(abs(block%coords(axis(side), block%node_sets(set)%nodes) - plane(side)) < 1.0e-14_dp), &
                    'side nodes on their plane')
         if (allocated(error)) return
         set = block%find_surface('b_'//trim(block_side_names(side)))
         call check(error, set > 0, 'surface exists')
         if (allocated(error)) return
         call check(error, size(block%surfaces(set)%faces) == expected_faces(side), 'face count of a side')
         if (allocated(error)) return
      end do
      call check(error, size(block%node_sets(block%find_node_set('b'))%nodes) == block%n_nodes .and. &
                 size(block%element_sets(block%find_element_set('b'))%elements) == block%n_elements, 'whole-block sets')
   end subroutine test_side_sets

   !> The normal (a2 - a1) x (a4 - a1) of every side face, from frix_mesh's face node order,
   !> points out of the block: -x on xmin, +x on xmax, etc.
   subroutine test_outward_faces(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: block
      real(dp), parameter :: outward(3, 6) = reshape([-1, 0, 0, 1, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, -1, 0, 0, 1]*1.0_dp, [3, 6])
      real(dp) :: a(3, 4), normal(3)
      integer :: side, k, set, e
      call generate_block('b', [0.0_dp, 0.0_dp, 0.0_dp], [1.0_dp, 2.0_dp, 3.0_dp], [2, 2, 2], 1, 1, block, error)
      if (allocated(error)) return
      do side = 1, 6
         set = block%find_surface('b_'//trim(block_side_names(side)))
         do k = 1, size(block%surfaces(set)%faces)
            e = block%surfaces(set)%elements(k)
            a = block%coords(:, block%connectivity(hex8_face_nodes(:, block%surfaces(set)%faces(k)), e))
            normal = cross(a(:, 2) - a(:, 1), a(:, 4) - a(:, 1))
            normal = normal/norm2(normal)
            call check(error, all(abs(normal - outward(:, side)) < 1.0e-12_dp), &
                       'outward normal of side '//trim(block_side_names(side)))
            if (allocated(error)) return
         end do
      end do
   end subroutine test_outward_faces

   subroutine test_bad_divisions(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: block
      type(error_t), allocatable :: generator_error
      call generate_block('b', [0.0_dp, 0.0_dp, 0.0_dp], [1.0_dp, 1.0_dp, 1.0_dp], [0, 1, 1], 1, 1, block, generator_error)
      call check(error, allocated(generator_error), 'DIVISIONS 0 must be rejected')
   end subroutine test_bad_divisions

   pure function cross(a, b) result(c)
      real(dp), intent(in) :: a(3), b(3)
      real(dp) :: c(3)
      c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
   end function cross
end module test_block_generator
