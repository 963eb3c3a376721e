!> The VTK writer: structure of the written .vtu/.pvd (text checks here); the values are read
!> back with meshio by tests/vtk_readback_test.sh, which runs this suite first.
module test_vtk_writer
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_mesh, only: mesh_t
   use frix_testing, only: unittest_t, new_unittest, check, check_message_contains, output_path
   use frix_vtk_writer, only: vtk_series_t
   use test_io_fixtures, only: two_element_mesh, linear_displacement, read_lines
   implicit none
   private

   public :: collect_vtk_writer

contains

   subroutine collect_vtk_writer(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('series of two increments', test_series), &
               new_unittest('extra field of the wrong size is an error', test_wrong_field_size), &
               new_unittest('unwritable folder is an error', test_unwritable)]
   end subroutine collect_vtk_writer

   !> Two increments of the two-element mesh, files `vtk_two_elements*` (read by
   !> tests/vtk_readback_test.sh, which knows these formulas):
   !> increment k (time 0.5 k): displacement = linear_displacement(k), reaction (k, 0, 0) at
   !> node 1, stress at every point of element e = k e (1, 2, 3, 4, 5, 6) 1e3 and strain
   !> k e (1, 2, 3, 4, 5, 6) 1e-3 (frix Voigt, engineering shears); increment 1 also carries
   !> the point field contact_pressure = x and the cell field cell_marker = (10, 20).
   subroutine write_two_increments(series, error)
      type(vtk_series_t), intent(inout) :: series
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      real(dp) :: stress(6, 8, 2), strain(6, 8, 2), reaction(3, 12)
      integer :: k, e, g
      mesh = two_element_mesh()
      call series%open(output_path('vtk_two_elements'), error)
      if (allocated(error)) return
      do k = 1, 2
         do e = 1, 2
            do g = 1, 8
               stress(:, g, e) = k*e*[1.0_dp, 2.0_dp, 3.0_dp, 4.0_dp, 5.0_dp, 6.0_dp]*1.0e3_dp
               strain(:, g, e) = k*e*[1.0_dp, 2.0_dp, 3.0_dp, 4.0_dp, 5.0_dp, 6.0_dp]*1.0e-3_dp
            end do
         end do
         reaction = 0.0_dp
         reaction(1, 1) = real(k, dp)
         if (k == 1) then
            call series%add_point_field('contact_pressure', mesh%coords(1:1, :))
            call series%add_cell_field('cell_marker', reshape([10.0_dp, 20.0_dp], [1, 2]))
         end if
         call series%write_increment(mesh, 1, k, 0.5_dp*k, linear_displacement(mesh, real(k, dp)), reaction, &
                                     stress, strain, error)
         if (allocated(error)) return
      end do
   end subroutine write_two_increments

   subroutine test_series(error)
      type(error_t), allocatable, intent(out) :: error
      type(vtk_series_t) :: series
      character(len=200), allocatable :: lines(:)
      character(len=*), parameter :: names(*) = [character(len=20) :: 'displacement', 'reaction', 'stress', &
                                                  'strain', 'von_mises', 'element_id', 'block', 'TimeValue']
      integer :: i
      call write_two_increments(series, error)
      if (allocated(error)) return
      call check(error, series%n_written() == 2, 'two increments written')
      if (allocated(error)) return
      call read_lines(output_path('vtk_two_elements.pvd'), lines, error)
      if (allocated(error)) return
      call check(error, count(index(lines, '<DataSet timestep=') > 0) == 2 .and. &
                 count(index(lines, 'file="vtk_two_elements_0001_0002.vtu"') > 0) == 1, &
                 'pvd lists both increments by their relative file names')
      if (allocated(error)) return
      call read_lines(output_path('vtk_two_elements_0001_0001.vtu'), lines, error)
      if (allocated(error)) return
      call check(error, count(index(lines, '<Piece NumberOfPoints="12" NumberOfCells="2">') > 0) == 1, 'piece sizes')
      if (allocated(error)) return
      do i = 1, size(names)
         call check(error, count(index(lines, 'Name="'//trim(names(i))//'"') > 0) >= 1, 'array '//trim(names(i)))
         if (allocated(error)) return
      end do
      call check(error, count(index(lines, 'Name="contact_pressure"') > 0) == 1 .and. &
                 count(index(lines, 'Name="cell_marker"') > 0) == 1, 'extra fields in increment 1')
      if (allocated(error)) return
      call read_lines(output_path('vtk_two_elements_0001_0002.vtu'), lines, error)
      if (allocated(error)) return
      call check(error, count(index(lines, 'Name="contact_pressure"') > 0) == 0, &
                 'extra fields are dropped after the increment they were added to')
   end subroutine test_series

   subroutine test_wrong_field_size(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: write_error
      type(vtk_series_t) :: series
      type(mesh_t) :: mesh
      real(dp) :: gp(6, 8, 2)
      mesh = two_element_mesh()
      gp = 0.0_dp
      call series%open(output_path('vtk_wrong_size'), error)
      if (allocated(error)) return
      call series%add_point_field('gap', reshape([0.0_dp, 0.0_dp, 0.0_dp], [3, 1]))
      call series%write_increment(mesh, 1, 1, 1.0_dp, linear_displacement(mesh, 1.0_dp), 0.0_dp*mesh%coords, &
                                  gp, gp, write_error)
      call check_message_contains(error, write_error, 'point field "gap" has 1 values, the mesh 12 nodes')
      if (allocated(error)) return
      call check(error, series%n_written() == 0, 'nothing written')
   end subroutine test_wrong_field_size

   subroutine test_unwritable(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: open_error
      type(vtk_series_t) :: series
      call series%open('/nonexistent_frix_folder/run', open_error)
      call check_message_contains(error, open_error, 'cannot open ParaView collection "/nonexistent_frix_folder/run.pvd"')
   end subroutine test_unwritable
end module test_vtk_writer
