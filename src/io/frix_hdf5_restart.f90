!> Reading back an HDF5 results file (layout in docs/hdf5-layout.md, written by
!> frix_hdf5_results): the list of its complete increments, the restart state of one increment
!> (time, total displacements and their RESET_DISPLACEMENT reference, EAS parameters, material
!> history), checked against the current
!> model's array shapes and mesh, and any real array of an increment (e.g. the contact state).
!> An increment group without the `complete` attribute (a run stopped while writing it) is
!> ignored; one whose `complete` is not 1 too. What a restart reads is validated: the
!> increment's time finite, real datasets stored as floating point, every value finite; an
!> error names the file, the increment and the dataset.
module frix_hdf5_restart
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_mesh, only: mesh_t
   use frix_hdf5_support, only: hdf5_location_t, open_group, close_group_after, link_exists, read_dataset, &
                                dataset_shape, read_attribute, attribute_exists
   use frix_hdf5_file, only: increment_group_name, open_for_reading, close_file
   use frix_finite_check, only: first_non_finite
   implicit none
   private

   public :: read_restart, list_increments, read_increment_array

contains

   !> Complete increment groups of an open file: running numbers, step, increment, time.
   subroutine scan_increments(file, numbers, steps, increments, times, error)
      type(hdf5_location_t), intent(in) :: file
      integer, allocatable, intent(out) :: numbers(:), steps(:), increments(:)
      real(dp), allocatable, intent(out) :: times(:)
      type(error_t), allocatable, intent(out) :: error
      type(hdf5_location_t) :: increments_group, group
      logical :: exists, complete
      integer :: k, step, increment, complete_value
      real(dp) :: time

      allocate (numbers(0), steps(0), increments(0), times(0))
      call open_group(file, 'increments', increments_group, error)
      if (allocated(error)) return
      k = 0
      do
         k = k + 1
         call link_exists(increments_group, increment_group_name(k), exists, error)
         if (allocated(error) .or. .not. exists) exit
         call open_group(increments_group, increment_group_name(k), group, error)
         if (allocated(error)) exit
         call attribute_exists(group, 'complete', complete, error)
         if (complete .and. .not. allocated(error)) then
            call read_attribute(group, 'complete', complete_value, error)
            complete = complete_value == 1
         end if
         if (complete .and. .not. allocated(error)) then
            call read_attribute(group, 'step', step, error)
            if (.not. allocated(error)) call read_attribute(group, 'increment', increment, error)
            if (.not. allocated(error)) call read_attribute(group, 'time', time, error)
            if (.not. allocated(error)) then
               numbers = [numbers, k]
               steps = [steps, step]
               increments = [increments, increment]
               times = [times, time]
            end if
         end if
         call close_group_after(group, error)
         if (allocated(error)) exit
      end do
      call close_group_after(increments_group, error)
   end subroutine scan_increments

   !> Step, increment number and time of every complete increment of the results file `path`,
   !> in the order written.
   subroutine list_increments(path, steps, increments, times, error)
      character(len=*), intent(in) :: path
      integer, allocatable, intent(out) :: steps(:), increments(:)
      real(dp), allocatable, intent(out) :: times(:)
      type(error_t), allocatable, intent(out) :: error
      type(hdf5_location_t) :: file
      integer, allocatable :: numbers(:)
      call open_for_reading(path, file, error)
      if (allocated(error)) return
      call scan_increments(file, numbers, steps, increments, times, error)
      call close_file(file, error)
   end subroutine list_increments

   !> Open the group of increment (step, increment) of an open file; the error lists the
   !> available increments when it is absent. The last match wins (there is normally one).
   subroutine open_increment(file, step, increment, group, time, error)
      type(hdf5_location_t), intent(in) :: file
      integer, intent(in) :: step, increment
      type(hdf5_location_t), intent(out) :: group
      real(dp), intent(out) :: time
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: numbers(:), steps(:), increments(:)
      real(dp), allocatable :: times(:)
      integer :: k, found
      time = 0.0_dp
      call scan_increments(file, numbers, steps, increments, times, error)
      if (allocated(error)) return
      found = 0
      do k = 1, size(numbers)
         if (steps(k) == step .and. increments(k) == increment) found = k
      end do
      if (found == 0) then
         call fatal_error(error, 'HDF5: results file "'//file%file_path//'" has no increment '// &
                          to_string(increment)//' of step '//to_string(step)//'; available (step/increment):'// &
                          available_text(steps, increments))
         return
      end if
      time = times(found)
      if (first_non_finite([time]) /= 0) then
         call fatal_error(error, 'HDF5: results file "'//file%file_path//'": increment '//to_string(increment)// &
                          ' of step '//to_string(step)//' has the non-finite time '//to_string(time))
         return
      end if
      call open_group(file, 'increments/'//increment_group_name(numbers(found)), group, error)
   end subroutine open_increment

   !> Error unless every entry of dataset `name` (just read into `values`) is finite.
   subroutine check_finite(file, step, increment, name, values, error)
      type(hdf5_location_t), intent(in) :: file
      integer, intent(in) :: step, increment
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: values(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: position
      position = first_non_finite(values)
      if (position == 0) return
      call fatal_error(error, 'HDF5: results file "'//file%file_path//'": dataset "'//name//'" of increment '// &
                       to_string(increment)//' of step '//to_string(step)//' has the non-finite value '// &
                       to_string(values(position))//' at entry '//to_string(position))
   end subroutine check_finite

   !> " step/increment step/increment ..." of the first increments, "none" without any.
   pure function available_text(steps, increments) result(available)
      integer, intent(in) :: steps(:), increments(:)
      character(len=:), allocatable :: available
      integer, parameter :: max_listed = 40
      integer :: k, n
      n = size(steps)
      if (n == 0) then
         available = 'none'
         return
      end if
      available = ''
      do k = 1, min(n, max_listed)
         available = available//' '//to_string(steps(k))//'/'//to_string(increments(k))
      end do
      if (n > max_listed) available = available//' ... ('//to_string(n - max_listed)//' more, up to '// &
                                      to_string(steps(n))//'/'//to_string(increments(n))//')'
   end function available_text

   !> Restart state of increment (selector_step, selector_increment) of the results file `path`:
   !> its time and the displacements, EAS parameters and material history written with it.
   !> The arrays come sized for the current model (as `analysis_state_t` allocates them); the
   !> file's mesh must have as many nodes and elements and the stored arrays the same shapes.
   !> With `mesh`, the connectivity must also be identical. Nothing is changed on error.
   !> The total displacements are `total_displacement` where the increment has it (written after
   !> a RESET_DISPLACEMENT step, with `reference_displacement`, returned in `reference`), else
   !> `displacement`; `reference` comes back unallocated when the increment has none.
   subroutine read_restart(path, selector_step, selector_increment, time, u, alpha, history, error, mesh, &
                           reference)
      character(len=*), intent(in) :: path
      integer, intent(in) :: selector_step, selector_increment
      real(dp), intent(inout) :: time             !! pseudo time of the increment
      real(dp), intent(inout) :: u(:)             !! (3 n_nodes) total displacements, node-major
      real(dp), intent(inout) :: alpha(:, :)      !! (max EAS parameters, n_elements)
      real(dp), intent(inout) :: history(:, :, :) !! (n_state, n_points, n_elements)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t), intent(in), optional :: mesh  !! the current mesh, to compare the connectivity
      real(dp), allocatable, intent(inout), optional :: reference(:)  !! (3 n_nodes) node-major
      type(hdf5_location_t) :: file
      call open_for_reading(path, file, error)
      if (allocated(error)) return
      call read_restart_open(file, selector_step, selector_increment, time, u, alpha, history, error, mesh, &
                             reference)
      call close_file(file, error)
      if (allocated(error)) error%message = 'restart from step '//to_string(selector_step)//' increment '// &
                                            to_string(selector_increment)//': '//error%message
   end subroutine read_restart

   subroutine read_restart_open(file, selector_step, selector_increment, time, u, alpha, history, error, mesh, &
                                reference)
      type(hdf5_location_t), intent(in) :: file
      integer, intent(in) :: selector_step, selector_increment
      real(dp), intent(inout) :: time, u(:), alpha(:, :), history(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t), intent(in), optional :: mesh
      real(dp), allocatable, intent(inout), optional :: reference(:)
      type(hdf5_location_t) :: group
      real(dp), allocatable :: new_u(:, :), new_alpha(:, :), new_history(:, :, :), new_reference(:, :)
      real(dp) :: new_time
      logical :: has_reference

      if (mod(size(u), 3) /= 0) then
         call fatal_error(error, 'the displacement vector has '//to_string(size(u))//' entries, not 3 per node')
         return
      end if
      call check_mesh(file, size(u)/3, size(alpha, 2), size(history, 3), error, mesh)
      if (allocated(error)) return
      call open_increment(file, selector_step, selector_increment, group, new_time, error)
      if (allocated(error)) return
      allocate (new_u(3, size(u)/3), new_alpha(size(alpha, 1), size(alpha, 2)), &
                new_history(size(history, 1), size(history, 2), size(history, 3)))
      call link_exists(group, 'total_displacement', has_reference, error)
      if (.not. allocated(error)) then
         if (has_reference) then
            allocate (new_reference(3, size(u)/3))
            call read_dataset(group, 'total_displacement', new_u, error)
            if (.not. allocated(error)) call read_dataset(group, 'reference_displacement', new_reference, error)
         else
            call read_dataset(group, 'displacement', new_u, error)
         end if
      end if
      if (.not. allocated(error)) call read_dataset(group, 'alpha', new_alpha, error)
      if (.not. allocated(error)) call read_dataset(group, 'history', new_history, error)
      call close_group_after(group, error)
      if (allocated(error)) return
      call check_finite(file, selector_step, selector_increment, 'displacement', reshape(new_u, [size(new_u)]), error)
      if (.not. allocated(error)) call check_finite(file, selector_step, selector_increment, 'alpha', &
                                                    reshape(new_alpha, [size(new_alpha)]), error)
      if (.not. allocated(error)) call check_finite(file, selector_step, selector_increment, 'history', &
                                                    reshape(new_history, [size(new_history)]), error)
      if (.not. allocated(error) .and. has_reference) &
         call check_finite(file, selector_step, selector_increment, 'reference_displacement', &
                           reshape(new_reference, [size(new_reference)]), error)
      if (allocated(error)) return
      time = new_time
      u = reshape(new_u, [size(u)])
      alpha = new_alpha
      history = new_history
      if (present(reference)) then
         if (allocated(reference)) deallocate (reference)
         if (has_reference) reference = reshape(new_reference, [size(u)])
      end if
   end subroutine read_restart_open

   !> The file's mesh must have n_nodes nodes and n_elements elements (and, with `mesh`, the
   !> same connectivity).
   subroutine check_mesh(file, n_nodes, n_elements, n_history_elements, error, mesh)
      type(hdf5_location_t), intent(in) :: file
      integer, intent(in) :: n_nodes, n_elements, n_history_elements
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t), intent(in), optional :: mesh
      type(hdf5_location_t) :: group
      integer, allocatable :: coordinates_shape(:), connectivity_shape(:), connectivity(:, :)

      if (n_history_elements /= n_elements) then
         call fatal_error(error, 'alpha has '//to_string(n_elements)//' elements, history '// &
                          to_string(n_history_elements))
         return
      end if
      if (present(mesh)) then
         if (mesh%n_nodes /= n_nodes .or. mesh%n_elements /= n_elements) then
            call fatal_error(error, 'the state arrays (' //to_string(n_nodes)//' nodes, '//to_string(n_elements)// &
                             ' elements) do not match the mesh ('//to_string(mesh%n_nodes)//' nodes, '// &
                             to_string(mesh%n_elements)//' elements)')
            return
         end if
      end if
      call open_group(file, 'mesh', group, error)
      if (allocated(error)) return
      call dataset_shape(group, 'coordinates', coordinates_shape, error)
      if (.not. allocated(error)) call dataset_shape(group, 'connectivity', connectivity_shape, error)
      if (.not. allocated(error)) then
         if (size(coordinates_shape) /= 2 .or. size(connectivity_shape) /= 2) then
            call fatal_error(error, 'HDF5: /mesh/coordinates or /mesh/connectivity of "'//file%file_path// &
                             '" is not two-dimensional')
         else if (coordinates_shape(2) /= n_nodes .or. connectivity_shape(2) /= n_elements) then
            call fatal_error(error, 'the mesh of "'//file%file_path//'" has '//to_string(coordinates_shape(2))// &
                             ' nodes and '//to_string(connectivity_shape(2))//' elements, the current model '// &
                             to_string(n_nodes)//' nodes and '//to_string(n_elements)//' elements')
         else if (present(mesh)) then
            ! as many rows as the file has (8 before meshes of larger cells): the same nodes,
            ! 0 in the rows past the narrower array's
            allocate (connectivity(connectivity_shape(1), n_elements))
            call read_dataset(group, 'connectivity', connectivity, error)
            if (.not. allocated(error)) then
               if (.not. same_connectivity(connectivity, mesh%connectivity)) &
                  call fatal_error(error, 'the connectivity in "'//file%file_path// &
                                   '" differs from the current mesh')
            end if
         end if
      end if
      call close_group_after(group, error)
   end subroutine check_mesh

   !> True when `first` and `second` hold the same nodes: equal in their common rows, 0 in the
   !> rows only one of them has.
   pure logical function same_connectivity(first, second) result(same)
      integer, intent(in) :: first(:, :), second(:, :)
      integer :: rows
      rows = min(size(first, 1), size(second, 1))
      same = size(first, 2) == size(second, 2)
      if (.not. same) return
      same = all(first(1:rows, :) == second(1:rows, :)) .and. all(first(rows + 1:, :) == 0) .and. &
             all(second(rows + 1:, :) == 0)
   end function same_connectivity

   !> Read a real 2-D dataset `name` of increment (step, increment), e.g. 'reaction' or
   !> 'contact/gap_traction' (for restoring contact state). `values` comes sized with the
   !> expected Fortran shape; a 1-D dataset (n) is read into values(1, n).
   subroutine read_increment_array(path, step, increment, name, values, error, found)
      character(len=*), intent(in) :: path
      integer, intent(in) :: step, increment
      character(len=*), intent(in) :: name       !! path relative to the increment group
      real(dp), intent(inout) :: values(:, :)
      type(error_t), allocatable, intent(out) :: error
      !> present: a missing dataset (a file of an older frix) is no error; `found` says whether
      !> `values` was read
      logical, intent(out), optional :: found
      type(hdf5_location_t) :: file, group
      integer, allocatable :: stored_shape(:)
      real(dp), allocatable :: flat(:)
      real(dp) :: time
      logical :: exists
      if (present(found)) found = .false.
      call open_for_reading(path, file, error)
      if (allocated(error)) return
      call open_increment(file, step, increment, group, time, error)
      exists = .true.
      if (.not. allocated(error) .and. present(found)) call path_exists(group, name, exists, error)
      if (.not. allocated(error) .and. .not. exists) then
         call close_group_after(group, error)
      else if (.not. allocated(error)) then
         if (present(found)) found = .true.
         call dataset_shape(group, name, stored_shape, error)
         if (.not. allocated(error)) then
            if (size(stored_shape) == 1 .and. size(values, 1) == 1) then
               allocate (flat(size(values, 2)))
               call read_dataset(group, name, flat, error)
               if (.not. allocated(error)) values(1, :) = flat
            else
               call read_dataset(group, name, values, error)
            end if
         end if
         if (.not. allocated(error)) call check_finite(file, step, increment, name, reshape(values, [size(values)]), error)
         call close_group_after(group, error)
      end if
      call close_file(file, error)
   end subroutine read_increment_array

   !> Whether every link of the relative path `name` ('a/b/c') exists below `group`.
   subroutine path_exists(group, name, exists, error)
      type(hdf5_location_t), intent(in) :: group
      character(len=*), intent(in) :: name
      logical, intent(out) :: exists
      type(error_t), allocatable, intent(out) :: error
      integer :: start, k
      start = 1
      do
         k = index(name(start:), '/')
         if (k == 0) exit
         call link_exists(group, name(:start + k - 2), exists, error)
         if (allocated(error) .or. .not. exists) return
         start = start + k
      end do
      call link_exists(group, name, exists, error)
   end subroutine path_exists
end module frix_hdf5_restart
