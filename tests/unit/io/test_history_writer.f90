!> The history writer: header labels and rows of `<base>_history.csv` read back.
module test_history_writer
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_mesh, only: mesh_t
   use frix_testing, only: unittest_t, new_unittest, check, check_message_contains, output_path
   use frix_history_writer, only: history_t, history_dof_code, history_label, history_uz, history_rx, history_ux
   use test_io_fixtures, only: two_element_mesh, linear_displacement, read_lines
   implicit none
   private

   public :: collect_history_writer

contains

   subroutine collect_history_writer(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('header and rows read back', test_rows), &
               new_unittest('DOF names and labels', test_names), &
               new_unittest('unknown node and DOF are reported', test_unknown_node)]
   end subroutine collect_history_writer

   subroutine test_rows(error)
      type(error_t), allocatable, intent(out) :: error
      type(history_t) :: history
      type(mesh_t) :: mesh
      real(dp) :: reaction(3, 12), row(6)
      character(len=200), allocatable :: lines(:)
      character(len=:), allocatable :: base
      integer :: increment, stat
      mesh = two_element_mesh()
      reaction = 0.0_dp
      reaction(1, 4) = -0.125_dp
      base = output_path('test_io')
      ! Node 112 (internal 12, at (2,1,1)) UZ and node 104 (internal 4) RX, UX.
      call history%open(base, mesh, [112, 104, 104], [history_uz, history_rx, history_ux], error)
      if (allocated(error)) return
      do increment = 1, 2
         call history%append(1, increment, 0.5_dp*increment, linear_displacement(mesh, real(increment, dp)), &
                             increment*reaction, error)
         if (allocated(error)) return
      end do
      call history%close(error)
      if (allocated(error)) return
      call read_lines(base//'_history.csv', lines, error)
      if (allocated(error)) return
      call check(error, size(lines) == 3, 'three lines, got '//to_string(size(lines)))
      if (allocated(error)) return
      call check(error, lines(1) == 'step,increment,time,u3_n112,r1_n104,u1_n104', 'header: '//trim(lines(1)))
      if (allocated(error)) return
      do increment = 1, 2
         read (lines(1 + increment), *, iostat=stat) row
         ! u_z = f (3e-3 z + 1e-4 x) at (2,1,1); u_x = f 1e-3 x at node 4 = (0,1,0), i.e. 0.
         ! The writer keeps 17 digits: the values come back to the last bit (compared at 1e-15).
         call check(error, stat == 0 .and. row(1) == 1.0_dp .and. row(2) == increment .and. &
                    row(3) == 0.5_dp*increment .and. abs(row(4) - increment*3.2e-3_dp) <= 1.0e-15_dp*3.2e-3_dp .and. &
                    row(5) == -0.125_dp*increment .and. row(6) == 0.0_dp, 'row '//trim(lines(1 + increment)))
         if (allocated(error)) return
      end do
   end subroutine test_rows

   subroutine test_names(error)
      type(error_t), allocatable, intent(out) :: error
      call check(error, history_dof_code('uz') == 3 .and. history_dof_code(' RY') == 5 .and. history_dof_code('UW') == 0, &
                 'DOF codes')
      if (allocated(error)) return
      call check(error, history_label(31, 3) == 'u3_n31' .and. history_label(5, 4) == 'r1_n5', 'labels')
   end subroutine test_names

   subroutine test_unknown_node(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: open_error
      type(history_t) :: history
      call history%open(output_path('test_io_bad'), two_element_mesh(), [999, 101], [1, 7], open_error)
      call check_message_contains(error, open_error, 'node 999 is not in the mesh')
      if (allocated(error)) return
      call check_message_contains(error, open_error, 'DOF code 7 of node 101')
   end subroutine test_unknown_node
end module test_history_writer
