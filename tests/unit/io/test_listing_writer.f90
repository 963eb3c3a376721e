!> The listing writer: a listing of the two-element mesh is read back with the column layout
!> of docs/listing-format.md (key in columns 1-10, values in 18-wide es18.9e3 fields).
module test_listing_writer
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_mesh, only: mesh_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close, check_message_contains, output_path
   use frix_listing_writer, only: listing_t
   use test_io_fixtures, only: two_element_mesh, linear_displacement, read_lines
   implicit none
   private

   public :: collect_listing_writer

   !> es18.9e3 keeps 10 significant digits: rounding error at most 5e-10 relative.
   real(dp), parameter :: print_tol = 5.0e-10_dp

contains

   subroutine collect_listing_writer(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('documented columns read back', test_columns), &
               new_unittest('block title must not start with a blank', test_bad_title), &
               new_unittest('writing an unopened listing is an error', test_not_open), &
               new_unittest('unwritable path is an error', test_unwritable)]
   end subroutine collect_listing_writer

   subroutine test_columns(error)
      type(error_t), allocatable, intent(out) :: error
      type(listing_t) :: listing
      type(mesh_t) :: mesh
      real(dp) :: displacement(3, 12), reaction(3, 12), norms(2, 3), values(3), time
      logical :: constrained(3, 12)
      character(len=200), allocatable :: lines(:)
      character(len=:), allocatable :: path
      character(len=10) :: key_text
      character(len=4) :: word_step
      character(len=11) :: word_increment
      character(len=6) :: word_time
      character(len=12) :: word_iterations
      integer, parameter :: fixed_nodes(4) = [1, 4, 7, 10]
      integer :: i, line, node_id, step, increment, iterations, stat
      mesh = two_element_mesh()
      displacement = linear_displacement(mesh, 1.0_dp)
      ! Reactions at the face x = 0 (nodes 1, 4, 7, 10), x direction, -0.25 each; zero elsewhere.
      constrained = .false.
      constrained(1, fixed_nodes) = .true.
      reaction = 0.0_dp
      reaction(1, fixed_nodes) = -0.25_dp
      norms = reshape([1.0_dp, 2.0e3_dp, 1.0e-4_dp, 3.0e-2_dp, 1.0e-11_dp, 4.0e-16_dp], [2, 3])
      path = output_path('test_io_listing.lst')
      call listing%open(path, 'two_elements.dat', '0.1.0', error)
      if (allocated(error)) return
      call listing%write_increment_header(1, 2, 0.75_dp, 3, error)
      if (allocated(error)) return
      call listing%write_iteration_log([character(len=13) :: 'RESIDUAL_NORM', 'ENERGY_NORM'], norms, error)
      if (allocated(error)) return
      call listing%write_displacements(mesh, displacement, error)
      if (allocated(error)) return
      call listing%write_reactions(mesh, reaction, constrained, error)
      if (allocated(error)) return
      call listing%close(error)
      if (allocated(error)) return

      call read_lines(path, lines, error)
      if (allocated(error)) return
      ! 3 comments; header; log title + header + 3; displacements title + header + 12;
      ! reactions title + header + 4; sum title + header + 1.
      call check(error, size(lines) == 3 + 1 + 5 + 14 + 6 + 3, 'line count '//to_string(size(lines)))
      if (allocated(error)) return
      call check(error, all(lines(1:3)(1:1) == '#'), 'run header lines start with #')
      if (allocated(error)) return

      read (lines(4), '(a4,i6,a11,i6,a6,es18.9e3,a12,i6)', iostat=stat) word_step, step, word_increment, increment, &
         word_time, time, word_iterations, iterations
      call check(error, stat == 0 .and. word_step == 'STEP' .and. word_increment == '  INCREMENT' .and. &
                 word_time == '  TIME' .and. word_iterations == '  ITERATIONS' .and. step == 1 .and. increment == 2 &
                 .and. iterations == 3 .and. abs(time - 0.75_dp) <= print_tol, 'increment header: '//trim(lines(4)))
      if (allocated(error)) return

      call check(error, lines(5) == 'ITERATION LOG' .and. lines(6) == '      ITER     RESIDUAL_NORM       ENERGY_NORM', &
                 'iteration log title/header: '//trim(lines(6)))
      if (allocated(error)) return
      do i = 1, 3
         read (lines(6 + i), '(i10,2es18.9e3)') node_id, values(1:2)
         call check(error, node_id == i - 1 .and. all(abs(values(1:2) - norms(:, i)) <= print_tol*abs(norms(:, i))), &
                    'iteration row '//trim(lines(6 + i)))
         if (allocated(error)) return
      end do

      call check(error, lines(10) == 'NODAL DISPLACEMENTS' .and. &
                 lines(11) == '      NODE                UX                UY                UZ', &
                 'displacement title/header: '//trim(lines(11)))
      if (allocated(error)) return
      do i = 1, 12
         line = 11 + i
         read (lines(line), '(i10,3es18.9e3)') node_id, values
         call check(error, node_id == 100 + i .and. len_trim(lines(line)) == 64, 'displacement row '//trim(lines(line)))
         if (allocated(error)) return
         call check(error, all(abs(values - displacement(:, i)) <= print_tol*maxval(abs(displacement(:, i)))), &
                    'displacement values '//trim(lines(line)))
         if (allocated(error)) return
      end do

      call check(error, lines(24) == 'REACTIONS (constrained DOFs only)' .and. &
                 lines(25) == '      NODE                RX                RY                RZ', &
                 'reaction title/header: '//trim(lines(25)))
      if (allocated(error)) return
      do i = 1, 4
         read (lines(25 + i), '(i10,3es18.9e3)') node_id, values
         call check(error, node_id == 100 + fixed_nodes(i) .and. all(values == [-0.25_dp, 0.0_dp, 0.0_dp]), &
                    'reaction row '//trim(lines(25 + i)))
         if (allocated(error)) return
      end do

      call check(error, lines(30) == 'SUM OF REACTIONS', 'sum title: '//trim(lines(30)))
      if (allocated(error)) return
      read (lines(32), '(a10,3es18.9e3)') key_text, values
      call check(error, adjustl(key_text) == 'TOTAL' .and. all(values == [-1.0_dp, 0.0_dp, 0.0_dp]), &
                 'sum row '//trim(lines(32)))
      if (allocated(error)) return
      ! Block titles are exactly the lines whose first character is not a blank (docs/listing-format.md).
      call check(error, count(lines(:)(1:1) /= ' ' .and. lines(:)(1:1) /= '#') == 5, 'five block titles')
   end subroutine test_columns

   subroutine test_bad_title(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: write_error
      type(listing_t) :: listing
      call listing%open(output_path('test_io_bad_title.lst'), 'x.dat', '0.1.0', error)
      if (allocated(error)) return
      call listing%write_table(' CONTACT', 'NODE', ['GAP'], [1], reshape([0.0_dp], [1, 1]), write_error)
      call check_message_contains(error, write_error, 'must start with a non-blank')
      if (allocated(error)) return
      call listing%write_table('CONTACT', 'NODE', ['GAP'], [1, 2], reshape([0.0_dp], [1, 1]), write_error)
      call check_message_contains(error, write_error, 'expected (1, 2)')
      if (allocated(error)) return
      call listing%close(error)
   end subroutine test_bad_title

   subroutine test_not_open(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: write_error
      type(listing_t) :: listing
      call listing%write_increment_header(1, 1, 1.0_dp, 1, write_error)
      call check_message_contains(error, write_error, 'before it was opened')
   end subroutine test_not_open

   subroutine test_unwritable(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: open_error
      type(listing_t) :: listing
      call listing%open('/nonexistent_frix_folder/run.lst', 'x.dat', '0.1.0', open_error)
      call check_message_contains(error, open_error, 'cannot open listing "/nonexistent_frix_folder/run.lst"')
      if (allocated(error)) return
      call check(error, .not. listing%is_open(), 'listing not open after a failed open')
   end subroutine test_unwritable
end module test_listing_writer
