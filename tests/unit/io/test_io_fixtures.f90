!> Shared data of the writer suites: a two-element mesh and fields given by closed formulas,
!> so that a reader (tests/vtk_readback_test.sh) can recompute every written value.
module test_io_fixtures
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_mesh, only: mesh_t
   implicit none
   private

   public :: two_element_mesh, linear_displacement, read_lines

contains

   !> Two unit cubes side by side along x: [0,1]x[0,1]x[0,1] and [1,2]x[0,1]x[0,1].
   !> Node i (internal) has coordinates x = mod(i-1,3), y = mod((i-1)/3,2), z = (i-1)/6 and user
   !> id 100 + i; elements have user ids 7 and 9 and blocks 1 and 2.
   function two_element_mesh() result(mesh)
      type(mesh_t) :: mesh
      integer :: i
      mesh%n_nodes = 12
      mesh%n_elements = 2
      allocate (mesh%coords(3, 12), mesh%node_ids(12))
      do i = 1, 12
         mesh%coords(:, i) = real([mod(i - 1, 3), mod((i - 1)/3, 2), (i - 1)/6], dp)
         mesh%node_ids(i) = 100 + i
      end do
      ! VTK order: bottom face counter-clockwise seen from +z, then the top face.
      mesh%connectivity = reshape([1, 2, 5, 4, 7, 8, 11, 10, &
                                   2, 3, 6, 5, 8, 9, 12, 11], [8, 2])
      mesh%element_ids = [7, 9]
      mesh%element_block = [1, 2]
   end function two_element_mesh

   !> u = factor * (1e-3 x, -2e-3 y, 3e-3 z + 1e-4 x) at every node, (3, n_nodes).
   pure function linear_displacement(mesh, factor) result(displacement)
      type(mesh_t), intent(in) :: mesh
      real(dp), intent(in) :: factor
      real(dp) :: displacement(3, mesh%n_nodes)
      displacement(1, :) = factor*1.0e-3_dp*mesh%coords(1, :)
      displacement(2, :) = -factor*2.0e-3_dp*mesh%coords(2, :)
      displacement(3, :) = factor*(3.0e-3_dp*mesh%coords(3, :) + 1.0e-4_dp*mesh%coords(1, :))
   end function linear_displacement

   !> Lines of a text file (at most 200 characters each are kept).
   subroutine read_lines(path, lines, error)
      character(len=*), intent(in) :: path
      character(len=200), allocatable, intent(out) :: lines(:)
      type(error_t), allocatable, intent(out) :: error
      character(len=200) :: line
      integer :: unit, stat
      allocate (lines(0))
      open (newunit=unit, file=path, status='old', action='read', iostat=stat)
      if (stat /= 0) then
         call fatal_error(error, 'cannot reopen '//path)
         return
      end if
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         lines = [character(len=200) :: lines, line]
      end do
      close (unit)
   end subroutine read_lines
end module test_io_fixtures
