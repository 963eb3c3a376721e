!> The history writer: header labels and rows of `<base>_history.csv` read back.
module test_history_writer
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_testing, only: unittest_t, new_unittest, check, check_message_contains, output_path
   use frix_history_writer, only: history_t, history_dof_code, history_label, set_history_label, &
                                  contact_history_label
   use test_io_fixtures, only: read_lines
   implicit none
   private

   public :: collect_history_writer

contains

   subroutine collect_history_writer(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('header and rows read back', test_rows), &
               new_unittest('DOF names and labels', test_names), &
               new_unittest('a row of the wrong length is reported', test_wrong_length)]
   end subroutine collect_history_writer

   subroutine test_rows(error)
      type(error_t), allocatable, intent(out) :: error
      type(history_t) :: history
      real(dp) :: row(6), values(3)
      character(len=200), allocatable :: lines(:)
      character(len=:), allocatable :: base
      integer :: increment, stat
      base = output_path('test_io')
      call history%open(base, [character(len=16) :: 'u3_n112', 'r1_sum_base', 'cn_pair1'], error)
      if (allocated(error)) return
      do increment = 1, 2
         ! values with 17 significant digits (1/3) and a power of two: they come back to the bit
         values = [increment/3.0_dp, -0.125_dp*increment, 0.0_dp]
         call history%append(1, increment, 0.5_dp*increment, values, error)
         if (allocated(error)) return
      end do
      call history%close(error)
      if (allocated(error)) return
      call read_lines(base//'_history.csv', lines, error)
      if (allocated(error)) return
      call check(error, size(lines) == 3, 'three lines, got '//to_string(size(lines)))
      if (allocated(error)) return
      call check(error, lines(1) == 'step,increment,time,u3_n112,r1_sum_base,cn_pair1', 'header: '//trim(lines(1)))
      if (allocated(error)) return
      do increment = 1, 2
         read (lines(1 + increment), *, iostat=stat) row
         call check(error, stat == 0 .and. row(1) == 1.0_dp .and. row(2) == increment .and. &
                    row(3) == 0.5_dp*increment .and. row(4) == increment/3.0_dp .and. &
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
      if (allocated(error)) return
      call check(error, set_history_label('base_zmin', 6, 'sum') == 'r3_sum_base_zmin' .and. &
                 set_history_label('top', 1, 'mean') == 'u1_mean_top', 'set labels')
      if (allocated(error)) return
      call check(error, contact_history_label(7, 2) == 'c2_pair7' .and. contact_history_label(7, 0) == 'cn_pair7', &
                 'contact labels')
   end subroutine test_names

   subroutine test_wrong_length(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: append_error
      type(history_t) :: history
      call history%open(output_path('test_io_bad'), [character(len=6) :: 'u1_n1', 'u2_n1'], error)
      if (allocated(error)) return
      call history%append(1, 1, 1.0_dp, [1.0_dp], append_error)
      call check_message_contains(error, append_error, '1 values for 2 columns')
      if (allocated(error)) return
      call history%close(error)
   end subroutine test_wrong_length
end module test_history_writer
