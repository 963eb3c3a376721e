!> Tests of frix_hdf5_results on synthetic data: a results file with three increments is
!> written, listed and read back for restart (bitwise), and the error cases are exercised.
!>
!> Every written value is a closed formula of its indices, evaluated as one correctly rounded
!> division of an exact integer, so that tests/hdf5/h5py_layout_test.sh recomputes identical
!> binary64 numbers in numpy (k = running increment number 1..3, all indices 1-based):
!>   displacement(c, i) =  (1e6 k + 1e4 c + i) / 3          reaction(c, i) = -(1e6 k + 1e4 c + i) / 7
!>   stress(v, p, e)    =  (1e6 k + 1e4 v + 100 p + e) / 3  strain(v, p, e) = (1e6 k + 1e4 v + 100 p + e) / 11
!>   alpha(j, e)        =  (1e6 k + 100 j + e) / 13
!>   history(s, p, e)   =  (1e6 k + 1e4 s + 100 p + e) / 17
!>   time               =  k / 3;  (step, increment) = (1, 1), (1, 2), (2, 1)
!> Increment 3 also carries contact arrays: gap(n) = -n/9, traction(c, n) = (10 c + n)/9,
!> status(n) = mod(n, 2), n = 1..4.
module hdf5_roundtrip_suite
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_mesh, only: mesh_t
   use frix_hdf5_results, only: hdf5_results_t, read_restart, list_increments, read_increment_array
   use frix_hdf5_support, only: hdf5_location_t, create_group, close_group, write_attribute
   use hdf5, only: h5fopen_f, h5fclose_f, h5f_acc_rdwr_f
   use frix_testing, only: unittest_t, new_unittest, check, check_message_contains, output_path
   implicit none
   private

   public :: collect_hdf5_roundtrip, results_file_path

   integer, parameter :: n_points = 8, max_eas = 5, n_state = 2, n_slaves = 4
   integer, parameter :: increment_steps(3) = [1, 1, 2], increment_numbers(3) = [1, 2, 1]

contains

   subroutine collect_hdf5_roundtrip(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('write three increments', test_write), &
               new_unittest('list increments', test_list), &
               new_unittest('restart increment 2 bitwise', test_restart_bitwise), &
               new_unittest('restart with mesh connectivity check', test_restart_with_mesh), &
               new_unittest('contact and reaction arrays read back', test_read_arrays), &
               new_unittest('incomplete increment group ignored', test_incomplete_group), &
               new_unittest('error: increment not in file', test_wrong_step), &
               new_unittest('error: node count differs', test_wrong_node_count), &
               new_unittest('error: element count differs', test_wrong_element_count), &
               new_unittest('error: EAS parameter count differs', test_wrong_alpha_shape), &
               new_unittest('error: history shape differs', test_wrong_history_shape), &
               new_unittest('error: connectivity differs', test_wrong_connectivity), &
               new_unittest('error: missing file', test_missing_file), &
               new_unittest('error: not an HDF5 file', test_not_hdf5), &
               new_unittest('error: write with wrong shapes or unopened', test_write_errors), &
               new_unittest('error: unwritable path', test_unwritable), &
               new_unittest('error: set name with slash', test_bad_set_name)]
   end subroutine collect_hdf5_roundtrip

   !> The file checked by h5py_layout_test.sh.
   function results_file_path() result(path)
      character(len=:), allocatable :: path
      path = output_path('hdf5_roundtrip.h5')
   end function results_file_path

   !> Two unit cubes side by side along x (node i at x = mod(i-1,3), y = mod((i-1)/3,2),
   !> z = (i-1)/6, user id 100 + i; elements ids 7, 9, blocks 1, 2), with sets and a surface.
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
      mesh%connectivity = reshape([1, 2, 5, 4, 7, 8, 11, 10, &
                                   2, 3, 6, 5, 8, 9, 12, 11], [8, 2])
      mesh%element_ids = [7, 9]
      mesh%element_block = [1, 2]
      allocate (mesh%node_sets(2), mesh%element_sets(1), mesh%surfaces(2))
      mesh%node_sets(1)%name = 'FIXED'
      mesh%node_sets(1)%nodes = [1, 4, 7, 10]
      mesh%node_sets(2)%name = 'empty set'
      allocate (mesh%node_sets(2)%nodes(0))
      mesh%element_sets(1)%name = 'RIGHT'
      mesh%element_sets(1)%elements = [2]
      mesh%surfaces(1)%name = 'TOP'
      mesh%surfaces(1)%elements = [1, 2]
      mesh%surfaces(1)%faces = [2, 2]
      mesh%surfaces(2)%name = 'END'
      mesh%surfaces(2)%elements = [2]
      mesh%surfaces(2)%faces = [4]
   end function two_element_mesh

   !> (1e6 k + 1e4 c + i) / divisor for a nodal (3, n_nodes) array.
   pure function nodal_field(k, n_nodes, divisor) result(values)
      integer, intent(in) :: k, n_nodes
      real(dp), intent(in) :: divisor
      real(dp) :: values(3, n_nodes)
      integer :: c, i
      do i = 1, n_nodes
         do c = 1, 3
            values(c, i) = real(1000000*k + 10000*c + i, dp)/divisor
         end do
      end do
   end function nodal_field

   !> (1e6 k + 1e4 a + 100 b + e) / divisor for a (n_a, n_b, n_elements) array.
   pure function point_field(k, n_a, n_b, n_elements, divisor) result(values)
      integer, intent(in) :: k, n_a, n_b, n_elements
      real(dp), intent(in) :: divisor
      real(dp) :: values(n_a, n_b, n_elements)
      integer :: a, b, e
      do e = 1, n_elements
         do b = 1, n_b
            do a = 1, n_a
               values(a, b, e) = real(1000000*k + 10000*a + 100*b + e, dp)/divisor
            end do
         end do
      end do
   end function point_field

   pure function alpha_of(k, n_elements) result(values)
      integer, intent(in) :: k, n_elements
      real(dp) :: values(max_eas, n_elements)
      integer :: j, e
      do e = 1, n_elements
         do j = 1, max_eas
            values(j, e) = real(1000000*k + 100*j + e, dp)/13.0_dp
         end do
      end do
   end function alpha_of

   !> Write the three increments once per run (later tests reuse the file).
   subroutine ensure_written(error)
      type(error_t), allocatable, intent(out) :: error
      logical, save :: written = .false.
      type(hdf5_results_t) :: results
      type(mesh_t) :: mesh
      real(dp) :: traction(3, n_slaves)
      integer :: k, c, n
      if (written) return
      mesh = two_element_mesh()
      call results%create(results_file_path(), mesh, 'roundtrip test'//new_line('a')//'second title line', &
                          'tests/hdf5/none.dck', '0.1.0', error)
      if (allocated(error)) return
      do k = 1, 3
         if (k == 3) then
            do n = 1, n_slaves
               do c = 1, 3
                  traction(c, n) = real(10*c + n, dp)/9.0_dp
               end do
            end do
            call results%add_contact_array('gap', [(-real(n, dp)/9.0_dp, n=1, n_slaves)])
            call results%add_contact_array('traction', traction)
            call results%add_contact_array('status', [(mod(n, 2), n=1, n_slaves)])
         end if
         call results%write_increment(increment_steps(k), increment_numbers(k), real(k, dp)/3.0_dp, &
                                      nodal_field(k, mesh%n_nodes, 3.0_dp), nodal_field(k, mesh%n_nodes, -7.0_dp), &
                                      point_field(k, 6, n_points, mesh%n_elements, 3.0_dp), &
                                      point_field(k, 6, n_points, mesh%n_elements, 11.0_dp), &
                                      alpha_of(k, mesh%n_elements), &
                                      point_field(k, n_state, n_points, mesh%n_elements, 17.0_dp), error)
         if (allocated(error)) return
      end do
      if (results%n_written() /= 3) then
         call fatal_error(error, 'n_written is '//to_string(results%n_written())//', expected 3')
         return
      end if
      call results%close(error)
      if (allocated(error)) return
      written = .true.
   end subroutine ensure_written

   subroutine test_write(error)
      type(error_t), allocatable, intent(out) :: error
      logical :: exists
      call ensure_written(error)
      if (allocated(error)) return
      inquire (file=results_file_path(), exist=exists)
      call check(error, exists, 'the results file was not created')
   end subroutine test_write

   subroutine test_list(error)
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: steps(:), increments(:)
      real(dp), allocatable :: times(:)
      call ensure_written(error)
      if (allocated(error)) return
      call list_increments(results_file_path(), steps, increments, times, error)
      if (allocated(error)) return
      call check(error, size(steps) == 3, 'expected 3 increments, got '//to_string(size(steps)))
      if (allocated(error)) return
      call check(error, all(steps == increment_steps) .and. all(increments == increment_numbers), &
                 'steps/increments differ from (1,1), (1,2), (2,1)')
      if (allocated(error)) return
      call check(error, all(times == [1.0_dp, 2.0_dp, 3.0_dp]/3.0_dp), 'times differ bitwise from k/3')
   end subroutine test_list

   !> Restart state sized as create_analysis_state sizes it: u(3 n_nodes), alpha(max_eas,
   !> n_elements), history(n_state, n_points, n_elements), filled with a marker.
   subroutine fresh_state(n_nodes, n_elements, time, u, alpha, history)
      integer, intent(in) :: n_nodes, n_elements
      real(dp), intent(out) :: time
      real(dp), allocatable, intent(out) :: u(:), alpha(:, :), history(:, :, :)
      time = -1.0_dp
      allocate (u(3*n_nodes), source=-1.0_dp)
      allocate (alpha(max_eas, n_elements), source=-1.0_dp)
      allocate (history(n_state, n_points, n_elements), source=-1.0_dp)
   end subroutine fresh_state

   subroutine test_restart_bitwise(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: u(:), alpha(:, :), history(:, :, :)
      real(dp) :: time
      call ensure_written(error)
      if (allocated(error)) return
      call fresh_state(12, 2, time, u, alpha, history)
      call read_restart(results_file_path(), 1, 2, time, u, alpha, history, error)
      if (allocated(error)) return
      call check(error, time == 2.0_dp/3.0_dp, 'time is not 2/3 bitwise')
      if (allocated(error)) return
      call check(error, all(u == reshape(nodal_field(2, 12, 3.0_dp), [36])), 'u differs from increment 2')
      if (allocated(error)) return
      call check(error, all(alpha == alpha_of(2, 2)), 'alpha differs from increment 2')
      if (allocated(error)) return
      call check(error, all(history == point_field(2, n_state, n_points, 2, 17.0_dp)), &
                 'history differs from increment 2')
   end subroutine test_restart_bitwise

   subroutine test_restart_with_mesh(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: u(:), alpha(:, :), history(:, :, :)
      real(dp) :: time
      call ensure_written(error)
      if (allocated(error)) return
      call fresh_state(12, 2, time, u, alpha, history)
      call read_restart(results_file_path(), 2, 1, time, u, alpha, history, error, mesh=two_element_mesh())
      if (allocated(error)) return
      call check(error, time == 1.0_dp .and. all(u == reshape(nodal_field(3, 12, 3.0_dp), [36])) .and. &
                 all(alpha == alpha_of(3, 2)) .and. all(history == point_field(3, n_state, n_points, 2, 17.0_dp)), &
                 'state of step 2 increment 1 differs from increment 3')
   end subroutine test_restart_with_mesh

   subroutine test_read_arrays(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: read_error
      real(dp) :: traction(3, n_slaves), gap(1, n_slaves), reaction(3, 12)
      integer :: c, n
      call ensure_written(error)
      if (allocated(error)) return
      call read_increment_array(results_file_path(), 2, 1, 'contact/traction', traction, error)
      if (allocated(error)) return
      do n = 1, n_slaves
         do c = 1, 3
            if (traction(c, n) /= real(10*c + n, dp)/9.0_dp) then
               call fatal_error(error, 'contact/traction differs at ('//to_string(c)//', '//to_string(n)//')')
               return
            end if
         end do
      end do
      call read_increment_array(results_file_path(), 2, 1, 'contact/gap', gap, error)
      if (allocated(error)) return
      call check(error, all(gap(1, :) == [(-real(n, dp)/9.0_dp, n=1, n_slaves)]), 'contact/gap differs')
      if (allocated(error)) return
      call read_increment_array(results_file_path(), 1, 1, 'reaction', reaction, error)
      if (allocated(error)) return
      call check(error, all(reaction == nodal_field(1, 12, -7.0_dp)), 'reaction of increment 1 differs')
      if (allocated(error)) return
      call read_increment_array(results_file_path(), 1, 2, 'contact/gap', gap, read_error)
      call check_message_contains(error, read_error, 'cannot open dataset "/increments/000002/contact/gap"')
   end subroutine test_read_arrays

   !> A group without the `complete` mark (as left by a run killed while writing it) is skipped.
   subroutine test_incomplete_group(error)
      type(error_t), allocatable, intent(out) :: error
      type(hdf5_results_t) :: results
      type(hdf5_location_t) :: file, group
      integer, allocatable :: steps(:), increments(:)
      real(dp), allocatable :: times(:)
      integer :: status
      call results%create(output_path('incomplete.h5'), two_element_mesh(), 'title', 'deck', '0.1.0', error)
      if (allocated(error)) return
      call results%write_increment(1, 1, 0.5_dp, nodal_field(1, 12, 3.0_dp), nodal_field(1, 12, 3.0_dp), &
                                   point_field(1, 6, n_points, 2, 3.0_dp), point_field(1, 6, n_points, 2, 3.0_dp), &
                                   alpha_of(1, 2), point_field(1, n_state, n_points, 2, 17.0_dp), error)
      if (allocated(error)) return
      call results%close(error)
      if (allocated(error)) return
      call h5fopen_f(output_path('incomplete.h5'), h5f_acc_rdwr_f, file%id, status)
      call check(error, status == 0, 'cannot reopen incomplete.h5')
      if (allocated(error)) return
      file%file_path = output_path('incomplete.h5')
      file%name = '/'
      call create_group(file, 'increments/000002', group, error)
      if (.not. allocated(error)) call write_attribute(group, 'step', 1, error)
      if (.not. allocated(error)) call write_attribute(group, 'increment', 2, error)
      if (.not. allocated(error)) call close_group(group, error)
      call h5fclose_f(file%id, status)
      if (allocated(error)) return
      call list_increments(output_path('incomplete.h5'), steps, increments, times, error)
      if (allocated(error)) return
      call check(error, size(steps) == 1, 'expected the incomplete group to be ignored, got '// &
                 to_string(size(steps))//' increments')
   end subroutine test_incomplete_group

   subroutine test_wrong_step(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: restart_error
      real(dp), allocatable :: u(:), alpha(:, :), history(:, :, :)
      real(dp) :: time
      call ensure_written(error)
      if (allocated(error)) return
      call fresh_state(12, 2, time, u, alpha, history)
      call read_restart(results_file_path(), 5, 1, time, u, alpha, history, restart_error)
      call check_message_contains(error, restart_error, 'no increment 1 of step 5; available (step/increment): 1/1 1/2 2/1')
      if (allocated(error)) return
      call check(error, time == -1.0_dp .and. all(u == -1.0_dp), 'state changed although the restart failed')
   end subroutine test_wrong_step

   subroutine test_wrong_node_count(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: restart_error
      real(dp), allocatable :: u(:), alpha(:, :), history(:, :, :)
      real(dp) :: time
      call ensure_written(error)
      if (allocated(error)) return
      call fresh_state(13, 2, time, u, alpha, history)
      call read_restart(results_file_path(), 1, 2, time, u, alpha, history, restart_error)
      call check_message_contains(error, restart_error, 'has 12 nodes and 2 elements, the current model 13 nodes')
   end subroutine test_wrong_node_count

   subroutine test_wrong_element_count(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: restart_error
      real(dp), allocatable :: u(:), alpha(:, :), history(:, :, :)
      real(dp) :: time
      call ensure_written(error)
      if (allocated(error)) return
      call fresh_state(12, 3, time, u, alpha, history)
      call read_restart(results_file_path(), 1, 2, time, u, alpha, history, restart_error)
      call check_message_contains(error, restart_error, 'the current model 12 nodes and 3 elements')
   end subroutine test_wrong_element_count

   subroutine test_wrong_alpha_shape(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: restart_error
      real(dp), allocatable :: u(:), alpha(:, :), history(:, :, :)
      real(dp) :: time
      call ensure_written(error)
      if (allocated(error)) return
      call fresh_state(12, 2, time, u, alpha, history)
      deallocate (alpha)
      allocate (alpha(9, 2), source=-1.0_dp)
      call read_restart(results_file_path(), 1, 2, time, u, alpha, history, restart_error)
      call check_message_contains(error, restart_error, '"/increments/000002/alpha" in "'//results_file_path()// &
                                  '" has shape (2, 5), the current model needs (2, 9)')
      if (allocated(error)) return
      call check(error, all(u == -1.0_dp), 'u changed although the restart failed')
   end subroutine test_wrong_alpha_shape

   subroutine test_wrong_history_shape(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: restart_error
      real(dp), allocatable :: u(:), alpha(:, :), history(:, :, :)
      real(dp) :: time
      call ensure_written(error)
      if (allocated(error)) return
      call fresh_state(12, 2, time, u, alpha, history)
      deallocate (history)
      allocate (history(3, n_points, 2), source=-1.0_dp)
      call read_restart(results_file_path(), 1, 2, time, u, alpha, history, restart_error)
      call check_message_contains(error, restart_error, 'has shape (2, 8, 2), the current model needs (2, 8, 3)')
   end subroutine test_wrong_history_shape

   subroutine test_wrong_connectivity(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: restart_error
      real(dp), allocatable :: u(:), alpha(:, :), history(:, :, :)
      real(dp) :: time
      type(mesh_t) :: mesh
      call ensure_written(error)
      if (allocated(error)) return
      mesh = two_element_mesh()
      mesh%connectivity(1:4, 2) = mesh%connectivity([4, 1, 2, 3], 2)
      call fresh_state(12, 2, time, u, alpha, history)
      call read_restart(results_file_path(), 1, 2, time, u, alpha, history, restart_error, mesh=mesh)
      call check_message_contains(error, restart_error, 'differs from the current mesh')
   end subroutine test_wrong_connectivity

   subroutine test_missing_file(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: restart_error
      real(dp), allocatable :: u(:), alpha(:, :), history(:, :, :), times(:)
      integer, allocatable :: steps(:), increments(:)
      real(dp) :: time
      call fresh_state(12, 2, time, u, alpha, history)
      call read_restart(output_path('no_such_file.h5'), 1, 1, time, u, alpha, history, restart_error)
      call check_message_contains(error, restart_error, 'no_such_file.h5" does not exist')
      if (allocated(error)) return
      call list_increments(output_path('no_such_file.h5'), steps, increments, times, restart_error)
      call check_message_contains(error, restart_error, 'no_such_file.h5" does not exist')
   end subroutine test_missing_file

   subroutine test_not_hdf5(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: restart_error
      real(dp), allocatable :: u(:), alpha(:, :), history(:, :, :)
      real(dp) :: time
      integer :: unit
      open (newunit=unit, file=output_path('not_hdf5.h5'), status='replace', action='write')
      write (unit, '(a)') 'this is a text file, not HDF5'
      close (unit)
      call fresh_state(12, 2, time, u, alpha, history)
      call read_restart(output_path('not_hdf5.h5'), 1, 1, time, u, alpha, history, restart_error)
      call check_message_contains(error, restart_error, 'not_hdf5.h5" is not an HDF5 file')
   end subroutine test_not_hdf5

   subroutine test_write_errors(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: write_error
      type(hdf5_results_t) :: results
      type(mesh_t) :: mesh
      mesh = two_element_mesh()
      call results%write_increment(1, 1, 0.0_dp, nodal_field(1, 12, 3.0_dp), nodal_field(1, 12, 3.0_dp), &
                                   point_field(1, 6, n_points, 2, 3.0_dp), point_field(1, 6, n_points, 2, 3.0_dp), &
                                   alpha_of(1, 2), point_field(1, n_state, n_points, 2, 17.0_dp), write_error)
      call check_message_contains(error, write_error, 'before the results file was created')
      if (allocated(error)) return
      call results%create(output_path('write_errors.h5'), mesh, 'title', 'deck', '0.1.0', error)
      if (allocated(error)) return
      call results%write_increment(1, 1, 0.0_dp, nodal_field(1, 11, 3.0_dp), nodal_field(1, 11, 3.0_dp), &
                                   point_field(1, 6, n_points, 2, 3.0_dp), point_field(1, 6, n_points, 2, 3.0_dp), &
                                   alpha_of(1, 2), point_field(1, n_state, n_points, 2, 17.0_dp), write_error)
      call check_message_contains(error, write_error, 'displacement and reaction must be (3, 12)')
      if (allocated(error)) return
      call results%write_increment(1, 1, 0.0_dp, nodal_field(1, 12, 3.0_dp), nodal_field(1, 12, 3.0_dp), &
                                   point_field(1, 6, n_points, 2, 3.0_dp), point_field(1, 6, n_points, 2, 3.0_dp), &
                                   alpha_of(1, 3), point_field(1, n_state, n_points, 2, 17.0_dp), write_error)
      call check_message_contains(error, write_error, 'alpha and history must have 2 elements')
      if (allocated(error)) return
      call results%add_contact_array('a/b', [1.0_dp])
      call results%write_increment(1, 1, 0.0_dp, nodal_field(1, 12, 3.0_dp), nodal_field(1, 12, 3.0_dp), &
                                   point_field(1, 6, n_points, 2, 3.0_dp), point_field(1, 6, n_points, 2, 3.0_dp), &
                                   alpha_of(1, 2), point_field(1, n_state, n_points, 2, 17.0_dp), write_error)
      call check_message_contains(error, write_error, 'contact array name "a/b"')
      if (allocated(error)) return
      call check(error, results%n_written() == 0, 'a rejected increment was counted')
      if (allocated(error)) return
      call results%close(error)
   end subroutine test_write_errors

   subroutine test_unwritable(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: create_error
      type(hdf5_results_t) :: results
      call results%create(output_path('no_such_folder/results.h5'), two_element_mesh(), 'title', 'deck', '0.1.0', &
                          create_error)
      call check_message_contains(error, create_error, 'cannot create results file "'// &
                                  output_path('no_such_folder/results.h5')//'"')
   end subroutine test_unwritable

   subroutine test_bad_set_name(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: create_error
      type(hdf5_results_t) :: results
      type(mesh_t) :: mesh
      mesh = two_element_mesh()
      mesh%element_sets(1)%name = 'LEFT/RIGHT'
      call results%create(output_path('bad_set_name.h5'), mesh, 'title', 'deck', '0.1.0', create_error)
      call check_message_contains(error, create_error, 'element set name "LEFT/RIGHT"')
   end subroutine test_bad_set_name
end module hdf5_roundtrip_suite
