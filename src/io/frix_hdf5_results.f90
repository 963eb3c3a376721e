!> HDF5 results file of a run and restart reading. One file holds the mesh once and one group
!> per converged increment; layout (h5py shapes, i.e. the Fortran shapes reversed), see
!> docs/hdf5-layout.md:
!>   /                      attributes frix_version, deck_path, title, layout_version
!>   /mesh/coordinates      (n_nodes, 3) reference coordinates
!>   /mesh/node_ids, /mesh/element_ids, /mesh/element_block     user ids, block index
!>   /mesh/connectivity     (n_elements, 8) 1-based internal node numbers, HEX8 order of frix_mesh
!>   /mesh/node_sets/<name>, /mesh/element_sets/<name>          1-based internal numbers
!>   /mesh/surfaces/<name>/elements, .../faces                  element number, local face 1..6
!>   /increments/<NNNNNN>/  running number 000001, 000002, ... in the order written;
!>       attributes step, increment, time, complete (= 1, written last)
!>       displacement, reaction (n_nodes, 3); stress, strain (n_elements, n_points, 6) Cauchy
!>       stress / strain with engineering shears, frix Voigt order xx yy zz xy xz yz;
!>       alpha (n_elements, max_eas); history (n_elements, n_points, n_state);
!>       optional group contact/ with the caller's named arrays.
!> The file is flushed (H5Fflush, global scope) after every increment so that a run that stops
!> keeps the converged increments. A group without the `complete` attribute (a run stopped
!> while writing it) is ignored by the readers.
!>
!> Restart: `read_restart` returns time, displacements, EAS parameters and material history of
!> one increment after checking them against the current model's array shapes. A restarted run
!> writes a new results file (it does not append to the old one).
module frix_hdf5_results
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string, zero_padded
   use frix_mesh, only: mesh_t
   use frix_hdf5_support, only: hid_t, hdf5_location_t, hdf5_initialize, create_group, open_group, close_group, &
                                close_group_after, &
                                link_exists, write_dataset, read_dataset, dataset_shape, write_attribute, &
                                read_attribute, attribute_exists
   use hdf5, only: h5fcreate_f, h5fopen_f, h5fclose_f, h5fflush_f, h5fis_hdf5_f, &
                   h5f_acc_trunc_f, h5f_acc_rdonly_f, h5f_scope_global_f
   implicit none
   private

   public :: hdf5_results_t, read_restart, list_increments, read_increment_array
   public :: hdf5_layout_version

   integer, parameter :: hdf5_layout_version = 1   !! root attribute `layout_version`; bump on incompatible change
   integer, parameter :: increment_digits = 6       !! increment group names: 000001, 000002, ...

   !> A caller-given array written into the `contact` group of the next increment.
   type :: named_array_t
      character(len=:), allocatable :: name
      real(dp), allocatable :: reals(:, :)        !! real data, Fortran shape (n_components, n)
      integer, allocatable :: integers(:, :)      !! or integer data
      logical :: rank_one = .false.               !! written as a 1-D dataset (n)
   end type named_array_t

   !> An HDF5 results file being written. Usage: `create`; per converged increment optionally
   !> `add_contact_array` (any number), then `write_increment`; at the end `close`.
   type :: hdf5_results_t
      private
      type(hdf5_location_t) :: file
      integer :: n_nodes = 0
      integer :: n_elements = 0
      integer :: n_increments = 0                 !! increment groups written so far
      type(named_array_t), allocatable :: contact(:)
      type(named_array_t), allocatable :: fields(:)   !! named integration-point fields
   contains
      procedure :: create => results_create
      procedure :: write_increment => results_write_increment
      procedure :: close => results_close
      procedure :: n_written => results_n_written
      procedure :: add_point_field
      procedure, private :: add_contact_real_1, add_contact_real_2, add_contact_integer_1
      generic :: add_contact_array => add_contact_real_1, add_contact_real_2, add_contact_integer_1
   end type hdf5_results_t

contains

   !> Create (or truncate) the file `path`, write the root attributes and the mesh group.
   subroutine results_create(self, path, mesh, title, deck_path, version, error)
      class(hdf5_results_t), intent(inout) :: self
      character(len=*), intent(in) :: path
      type(mesh_t), intent(in) :: mesh
      character(len=*), intent(in) :: title       !! the deck's title (header comment lines)
      character(len=*), intent(in) :: deck_path   !! the deck as given on the command line
      character(len=*), intent(in) :: version     !! frix version, e.g. '0.1.0'
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: close_error
      integer :: status

      if (self%file%id >= 0) then
         call fatal_error(error, 'HDF5: results file "'//self%file%file_path//'" is already open, cannot create "'// &
                          path//'"')
         return
      end if
      if (.not. (allocated(mesh%coords) .and. allocated(mesh%node_ids) .and. allocated(mesh%connectivity) &
                 .and. allocated(mesh%element_ids) .and. allocated(mesh%element_block))) then
         call fatal_error(error, 'HDF5 output: the mesh lacks coordinates, node ids, connectivity, element ids or blocks')
         return
      end if
      call hdf5_initialize(error)
      if (allocated(error)) return
      call h5fcreate_f(path, h5f_acc_trunc_f, self%file%id, status)
      if (status /= 0) then
         self%file%id = -1
         call fatal_error(error, 'HDF5: cannot create results file "'//path//'"')
         return
      end if
      self%file%file_path = path
      self%file%name = '/'
      self%n_nodes = mesh%n_nodes
      self%n_elements = mesh%n_elements
      self%n_increments = 0
      if (allocated(self%contact)) deallocate (self%contact)
      if (allocated(self%fields)) deallocate (self%fields)
      allocate (self%contact(0), self%fields(0))

      call write_header(self%file, mesh, title, deck_path, version, error)
      if (.not. allocated(error)) call flush_file(self%file, error)
      if (allocated(error)) call self%close(close_error)   ! keep the first error
   end subroutine results_create

   subroutine write_header(file, mesh, title, deck_path, version, error)
      type(hdf5_location_t), intent(in) :: file
      type(mesh_t), intent(in) :: mesh
      character(len=*), intent(in) :: title, deck_path, version
      type(error_t), allocatable, intent(out) :: error
      type(hdf5_location_t) :: group

      call write_attribute(file, 'frix_version', version, error)
      if (allocated(error)) return
      call write_attribute(file, 'deck_path', deck_path, error)
      if (allocated(error)) return
      call write_attribute(file, 'title', title, error)
      if (allocated(error)) return
      call write_attribute(file, 'layout_version', hdf5_layout_version, error)
      if (allocated(error)) return

      call create_group(file, 'mesh', group, error)
      if (allocated(error)) return
      call write_mesh(group, mesh, error)
      call close_group_after(group, error)
      if (allocated(error)) return
      call create_group(file, 'increments', group, error)
      if (allocated(error)) return
      call close_group(group, error)
   end subroutine write_header

   !> The datasets of /mesh and its set groups.
   subroutine write_mesh(group, mesh, error)
      type(hdf5_location_t), intent(in) :: group
      type(mesh_t), intent(in) :: mesh
      type(error_t), allocatable, intent(out) :: error
      type(hdf5_location_t) :: sets, surface
      integer :: i

      call write_dataset(group, 'coordinates', mesh%coords, error)
      if (allocated(error)) return
      call write_dataset(group, 'node_ids', mesh%node_ids, error)
      if (allocated(error)) return
      call write_dataset(group, 'connectivity', mesh%connectivity, error)
      if (allocated(error)) return
      call write_dataset(group, 'element_ids', mesh%element_ids, error)
      if (allocated(error)) return
      call write_dataset(group, 'element_block', mesh%element_block, error)
      if (allocated(error)) return

      call create_group(group, 'node_sets', sets, error)
      if (allocated(error)) return
      if (allocated(mesh%node_sets)) then
         do i = 1, size(mesh%node_sets)
            call check_object_name(mesh%node_sets(i)%name, 'node set', error)
            if (.not. allocated(error)) call write_dataset(sets, mesh%node_sets(i)%name, mesh%node_sets(i)%nodes, error)
            if (allocated(error)) exit
         end do
      end if
      call close_group_after(sets, error)
      if (allocated(error)) return

      call create_group(group, 'element_sets', sets, error)
      if (allocated(error)) return
      if (allocated(mesh%element_sets)) then
         do i = 1, size(mesh%element_sets)
            call check_object_name(mesh%element_sets(i)%name, 'element set', error)
            if (.not. allocated(error)) &
               call write_dataset(sets, mesh%element_sets(i)%name, mesh%element_sets(i)%elements, error)
            if (allocated(error)) exit
         end do
      end if
      call close_group_after(sets, error)
      if (allocated(error)) return

      call create_group(group, 'surfaces', sets, error)
      if (allocated(error)) return
      if (allocated(mesh%surfaces)) then
         do i = 1, size(mesh%surfaces)
            call check_object_name(mesh%surfaces(i)%name, 'surface', error)
            if (allocated(error)) exit
            call create_group(sets, mesh%surfaces(i)%name, surface, error)
            if (allocated(error)) exit
            call write_dataset(surface, 'elements', mesh%surfaces(i)%elements, error)
            if (.not. allocated(error)) call write_dataset(surface, 'faces', mesh%surfaces(i)%faces, error)
            call close_group_after(surface, error)
            if (allocated(error)) exit
         end do
      end if
      call close_group_after(sets, error)
   end subroutine write_mesh

   !> A set or array name must be usable as an HDF5 link name: not empty, not '.', no '/'.
   subroutine check_object_name(name, what, error)
      character(len=*), intent(in) :: name, what
      type(error_t), allocatable, intent(out) :: error
      if (len(name) == 0 .or. name == '.' .or. index(name, '/') > 0) &
         call fatal_error(error, 'HDF5 output: '//what//' name "'//name//'" cannot be an HDF5 name '// &
                          '(empty, "." or containing "/")')
   end subroutine check_object_name

   !> Number of increments written to the open file.
   pure integer function results_n_written(self)
      class(hdf5_results_t), intent(in) :: self
      results_n_written = self%n_increments
   end function results_n_written

   !> Add a real per-entity array values(n) (e.g. per slave node gap) to the `contact` group
   !> of the next increment; h5py shape (n).
   subroutine add_contact_real_1(self, name, values)
      class(hdf5_results_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: values(:)
      type(named_array_t) :: item
      item%name = name
      item%reals = reshape(values, [1, size(values)])
      item%rank_one = .true.
      call append_contact(self, item)
   end subroutine add_contact_real_1

   !> Add a real array values(n_components, n) (e.g. per slave node traction (3, n)) to the
   !> `contact` group of the next increment; h5py shape (n, n_components).
   subroutine add_contact_real_2(self, name, values)
      class(hdf5_results_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: values(:, :)
      type(named_array_t) :: item
      item%name = name
      item%reals = values
      call append_contact(self, item)
   end subroutine add_contact_real_2

   !> Add an integer array values(n) (e.g. slave node numbers, stick/slip status) to the
   !> `contact` group of the next increment; h5py shape (n).
   subroutine add_contact_integer_1(self, name, values)
      class(hdf5_results_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      integer, intent(in) :: values(:)
      type(named_array_t) :: item
      item%name = name
      item%integers = reshape(values, [1, size(values)])
      item%rank_one = .true.
      call append_contact(self, item)
   end subroutine add_contact_integer_1

   !> Add a named scalar per integration point, values(n_points, n_elements) (a material's
   !> history variable such as an equivalent plastic strain), to the `fields` group of the next
   !> increment; h5py shape (n_elements, n_points).
   subroutine add_point_field(self, name, values)
      class(hdf5_results_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: values(:, :)
      type(named_array_t) :: item
      item%name = name
      item%reals = values
      call append_item(self%fields, item)
   end subroutine add_point_field

   subroutine append_contact(self, item)
      type(hdf5_results_t), intent(inout) :: self
      type(named_array_t), intent(inout) :: item
      call append_item(self%contact, item)
   end subroutine append_contact

   !> items = [items, item], moving item's arrays (an array constructor of this type would
   !> leak their copies with gfortran 12).
   subroutine append_item(items, item)
      type(named_array_t), allocatable, intent(inout) :: items(:)
      type(named_array_t), intent(inout) :: item
      type(named_array_t), allocatable :: grown(:)
      integer :: i, n
      if (.not. allocated(items)) allocate (items(0))
      n = size(items)
      allocate (grown(n + 1))
      do i = 1, n
         call move_alloc(items(i)%name, grown(i)%name)
         if (allocated(items(i)%reals)) call move_alloc(items(i)%reals, grown(i)%reals)
         if (allocated(items(i)%integers)) call move_alloc(items(i)%integers, grown(i)%integers)
         grown(i)%rank_one = items(i)%rank_one
      end do
      call move_alloc(item%name, grown(n + 1)%name)
      if (allocated(item%reals)) call move_alloc(item%reals, grown(n + 1)%reals)
      if (allocated(item%integers)) call move_alloc(item%integers, grown(n + 1)%integers)
      grown(n + 1)%rank_one = item%rank_one
      call move_alloc(grown, items)
   end subroutine append_item

   !> Write one converged increment as group /increments/<NNNNNN> and flush the file. The
   !> contact arrays added since the previous increment are written with it and then dropped.
   subroutine results_write_increment(self, step, increment, time, displacement, reaction, stress, strain, &
                                      alpha, history, error)
      class(hdf5_results_t), intent(inout) :: self
      integer, intent(in) :: step, increment      !! step number and increment number within the step
      real(dp), intent(in) :: time                !! pseudo time (load factor) of the increment
      real(dp), intent(in) :: displacement(:, :)  !! (3, n_nodes) total displacements
      real(dp), intent(in) :: reaction(:, :)      !! (3, n_nodes) reactions, zero at free DOFs
      real(dp), intent(in) :: stress(:, :, :)     !! (6, n_points, n_elements) Cauchy, frix Voigt
      real(dp), intent(in) :: strain(:, :, :)     !! (6, n_points, n_elements) engineering shears
      real(dp), intent(in) :: alpha(:, :)         !! (max EAS parameters, n_elements)
      real(dp), intent(in) :: history(:, :, :)    !! (n_state, n_points, n_elements)
      type(error_t), allocatable, intent(out) :: error
      type(hdf5_location_t) :: increments, group

      if (self%file%id < 0) then
         call fatal_error(error, 'HDF5 output: increment written before the results file was created')
         return
      end if
      call check_increment_shapes(self, displacement, reaction, stress, strain, alpha, history, error)
      if (allocated(error)) return

      call open_group(self%file, 'increments', increments, error)
      if (allocated(error)) return
      call create_group(increments, zero_padded(self%n_increments + 1, increment_digits), group, error)
      if (.not. allocated(error)) then
         call write_increment_group(self, group, step, increment, time, displacement, reaction, stress, strain, &
                                    alpha, history, error)
         call close_group_after(group, error)
      end if
      call close_group_after(increments, error)
      if (allocated(error)) return
      self%n_increments = self%n_increments + 1
      deallocate (self%contact, self%fields)
      allocate (self%contact(0), self%fields(0))
      call flush_file(self%file, error)
   end subroutine results_write_increment

   subroutine check_increment_shapes(self, displacement, reaction, stress, strain, alpha, history, error)
      type(hdf5_results_t), intent(in) :: self
      real(dp), intent(in) :: displacement(:, :), reaction(:, :), stress(:, :, :), strain(:, :, :)
      real(dp), intent(in) :: alpha(:, :), history(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      if (any(shape(displacement) /= [3, self%n_nodes]) .or. any(shape(reaction) /= [3, self%n_nodes])) then
         call fatal_error(error, 'HDF5 output: displacement and reaction must be (3, '//to_string(self%n_nodes)//')')
      else if (size(stress, 1) /= 6 .or. size(stress, 3) /= self%n_elements .or. any(shape(strain) /= shape(stress))) then
         call fatal_error(error, 'HDF5 output: stress and strain must be (6, n_points, '//to_string(self%n_elements)//')')
      else if (size(alpha, 2) /= self%n_elements .or. size(history, 3) /= self%n_elements) then
         call fatal_error(error, 'HDF5 output: alpha and history must have '//to_string(self%n_elements)// &
                          ' elements in their last dimension')
      end if
      if (allocated(error)) return
      do i = 1, size(self%contact)
         call check_object_name(self%contact(i)%name, 'contact array', error)
         if (allocated(error)) return
      end do
      do i = 1, size(self%fields)
         call check_object_name(self%fields(i)%name, 'field', error)
         if (allocated(error)) return
         if (size(self%fields(i)%reals, 2) /= self%n_elements) then
            call fatal_error(error, 'HDF5 output: field "'//self%fields(i)%name//'" must have '// &
                             to_string(self%n_elements)//' elements in its last dimension')
            return
         end if
      end do
   end subroutine check_increment_shapes

   subroutine write_increment_group(self, group, step, increment, time, displacement, reaction, stress, strain, &
                                    alpha, history, error)
      type(hdf5_results_t), intent(in) :: self
      type(hdf5_location_t), intent(in) :: group
      integer, intent(in) :: step, increment
      real(dp), intent(in) :: time
      real(dp), intent(in) :: displacement(:, :), reaction(:, :), stress(:, :, :), strain(:, :, :)
      real(dp), intent(in) :: alpha(:, :), history(:, :, :)
      type(error_t), allocatable, intent(out) :: error

      call write_attribute(group, 'step', step, error)
      if (allocated(error)) return
      call write_attribute(group, 'increment', increment, error)
      if (allocated(error)) return
      call write_attribute(group, 'time', time, error)
      if (allocated(error)) return
      call write_dataset(group, 'displacement', displacement, error)
      if (allocated(error)) return
      call write_dataset(group, 'reaction', reaction, error)
      if (allocated(error)) return
      call write_dataset(group, 'stress', stress, error)
      if (allocated(error)) return
      call write_dataset(group, 'strain', strain, error)
      if (allocated(error)) return
      call write_dataset(group, 'alpha', alpha, error)
      if (allocated(error)) return
      call write_dataset(group, 'history', history, error)
      if (allocated(error)) return

      call write_named_arrays(group, 'contact', self%contact, error)
      if (allocated(error)) return
      call write_named_arrays(group, 'fields', self%fields, error)
      if (allocated(error)) return
      ! written last: readers ignore a group without it (a run stopped while writing it)
      call write_attribute(group, 'complete', 1, error)
   end subroutine write_increment_group

   !> The group `name` of an increment holding `items` (none: no group).
   subroutine write_named_arrays(increment, name, items, error)
      type(hdf5_location_t), intent(in) :: increment
      character(len=*), intent(in) :: name
      type(named_array_t), intent(in) :: items(:)
      type(error_t), allocatable, intent(out) :: error
      type(hdf5_location_t) :: group
      integer :: i
      if (size(items) == 0) return
      call create_group(increment, name, group, error)
      if (allocated(error)) return
      do i = 1, size(items)
         associate (item => items(i))
            if (allocated(item%reals)) then
               if (item%rank_one) then
                  call write_dataset(group, item%name, item%reals(1, :), error)
               else
                  call write_dataset(group, item%name, item%reals, error)
               end if
            else
               call write_dataset(group, item%name, item%integers(1, :), error)
            end if
         end associate
         if (allocated(error)) exit
      end do
      call close_group_after(group, error)
   end subroutine write_named_arrays

   !> Close the file (no-op if it is not open).
   subroutine results_close(self, error)
      class(hdf5_results_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      call close_file(self%file, error)
   end subroutine results_close

   subroutine flush_file(file, error)
      type(hdf5_location_t), intent(in) :: file
      type(error_t), allocatable, intent(out) :: error
      integer :: status
      call h5fflush_f(file%id, h5f_scope_global_f, status)
      if (status /= 0) call fatal_error(error, 'HDF5: cannot flush results file "'//file%file_path//'"')
   end subroutine flush_file

   !> Open an existing results file read-only, with distinct messages for a missing file and
   !> a file that is not HDF5.
   subroutine open_for_reading(path, file, error)
      character(len=*), intent(in) :: path
      type(hdf5_location_t), intent(out) :: file
      type(error_t), allocatable, intent(out) :: error
      logical :: exists, is_hdf5
      integer :: status
      inquire (file=path, exist=exists)
      if (.not. exists) then
         call fatal_error(error, 'HDF5: results file "'//path//'" does not exist')
         return
      end if
      call hdf5_initialize(error)
      if (allocated(error)) return
      call h5fis_hdf5_f(path, is_hdf5, status)
      if (status /= 0) then
         call fatal_error(error, 'HDF5: cannot read results file "'//path//'"')
         return
      end if
      if (.not. is_hdf5) then
         call fatal_error(error, 'HDF5: "'//path//'" is not an HDF5 file')
         return
      end if
      call h5fopen_f(path, h5f_acc_rdonly_f, file%id, status)
      if (status /= 0) then
         file%id = -1
         call fatal_error(error, 'HDF5: cannot open results file "'//path//'"')
         return
      end if
      file%file_path = path
      file%name = '/'
   end subroutine open_for_reading

   subroutine close_file(file, error)
      type(hdf5_location_t), intent(inout) :: file
      type(error_t), allocatable, intent(out) :: error
      integer :: status
      if (file%id < 0) return
      call h5fclose_f(file%id, status)
      file%id = -1
      if (status /= 0) call fatal_error(error, 'HDF5: cannot close results file "'//file%file_path//'"')
   end subroutine close_file

   !> Close `file` after work on it that may have failed: `error` keeps the work's error if
   !> there is one, otherwise it receives the close's.
   subroutine close_file_after(file, error)
      type(hdf5_location_t), intent(inout) :: file
      type(error_t), allocatable, intent(inout) :: error
      type(error_t), allocatable :: close_error
      call close_file(file, close_error)
      if (.not. allocated(error)) call move_alloc(close_error, error)
   end subroutine close_file_after

   !> Complete increment groups of an open file: running numbers, step, increment, time.
   subroutine scan_increments(file, numbers, steps, increments, times, error)
      type(hdf5_location_t), intent(in) :: file
      integer, allocatable, intent(out) :: numbers(:), steps(:), increments(:)
      real(dp), allocatable, intent(out) :: times(:)
      type(error_t), allocatable, intent(out) :: error
      type(hdf5_location_t) :: increments_group, group
      logical :: exists, complete
      integer :: k, step, increment
      real(dp) :: time

      allocate (numbers(0), steps(0), increments(0), times(0))
      call open_group(file, 'increments', increments_group, error)
      if (allocated(error)) return
      k = 0
      do
         k = k + 1
         call link_exists(increments_group, zero_padded(k, increment_digits), exists, error)
         if (allocated(error) .or. .not. exists) exit
         call open_group(increments_group, zero_padded(k, increment_digits), group, error)
         if (allocated(error)) exit
         call attribute_exists(group, 'complete', complete, error)
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
      call close_file_after(file, error)
   end subroutine list_increments

   !> Open the group of increment (step, increment) of an open file; the error lists the
   !> available increments when it is absent. The last match wins (there is normally one).
   subroutine open_increment(file, step, increment, group, time, error)
      type(hdf5_location_t), intent(in) :: file
      integer, intent(in) :: step, increment
      type(hdf5_location_t), intent(out) :: group
      real(dp), intent(out) :: time
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: max_listed = 40
      integer, allocatable :: numbers(:), steps(:), increments(:)
      real(dp), allocatable :: times(:)
      character(len=:), allocatable :: available
      integer :: k, found
      time = 0.0_dp
      call scan_increments(file, numbers, steps, increments, times, error)
      if (allocated(error)) return
      found = 0
      do k = 1, size(numbers)
         if (steps(k) == step .and. increments(k) == increment) found = k
      end do
      if (found == 0) then
         if (size(numbers) == 0) then
            available = 'none'
         else
            available = ''
            do k = 1, min(size(numbers), max_listed)
               available = available//' '//to_string(steps(k))//'/'//to_string(increments(k))
            end do
            if (size(numbers) > max_listed) &
               available = available//' ... ('//to_string(size(numbers) - max_listed)//' more, up to '// &
                           to_string(steps(size(numbers)))//'/'//to_string(increments(size(numbers)))//')'
         end if
         call fatal_error(error, 'HDF5: results file "'//file%file_path//'" has no increment '// &
                          to_string(increment)//' of step '//to_string(step)//'; available (step/increment):'// &
                          available)
         return
      end if
      time = times(found)
      call open_group(file, 'increments/'//zero_padded(numbers(found), increment_digits), group, error)
   end subroutine open_increment

   !> Restart state of increment (selector_step, selector_increment) of the results file `path`:
   !> its time and the displacements, EAS parameters and material history written with it.
   !> The arrays come sized for the current model (as `analysis_state_t` allocates them); the
   !> file's mesh must have as many nodes and elements and the stored arrays the same shapes.
   !> With `mesh`, the connectivity must also be identical. Nothing is changed on error.
   subroutine read_restart(path, selector_step, selector_increment, time, u, alpha, history, error, mesh)
      character(len=*), intent(in) :: path
      integer, intent(in) :: selector_step, selector_increment
      real(dp), intent(inout) :: time             !! pseudo time of the increment
      real(dp), intent(inout) :: u(:)             !! (3 n_nodes) total displacements, node-major
      real(dp), intent(inout) :: alpha(:, :)      !! (max EAS parameters, n_elements)
      real(dp), intent(inout) :: history(:, :, :) !! (n_state, n_points, n_elements)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t), intent(in), optional :: mesh  !! the current mesh, to compare the connectivity
      type(hdf5_location_t) :: file
      call open_for_reading(path, file, error)
      if (allocated(error)) return
      call read_restart_open(file, selector_step, selector_increment, time, u, alpha, history, error, mesh)
      call close_file_after(file, error)
      if (allocated(error)) error%message = 'restart from step '//to_string(selector_step)//' increment '// &
                                            to_string(selector_increment)//': '//error%message
   end subroutine read_restart

   subroutine read_restart_open(file, selector_step, selector_increment, time, u, alpha, history, error, mesh)
      type(hdf5_location_t), intent(in) :: file
      integer, intent(in) :: selector_step, selector_increment
      real(dp), intent(inout) :: time, u(:), alpha(:, :), history(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t), intent(in), optional :: mesh
      type(hdf5_location_t) :: group
      real(dp), allocatable :: new_u(:, :), new_alpha(:, :), new_history(:, :, :)
      real(dp) :: new_time

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
      call read_dataset(group, 'displacement', new_u, error)
      if (.not. allocated(error)) call read_dataset(group, 'alpha', new_alpha, error)
      if (.not. allocated(error)) call read_dataset(group, 'history', new_history, error)
      call close_group_after(group, error)
      if (allocated(error)) return
      time = new_time
      u = reshape(new_u, [size(u)])
      alpha = new_alpha
      history = new_history
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
            allocate (connectivity(8, n_elements))
            call read_dataset(group, 'connectivity', connectivity, error)
            if (.not. allocated(error)) then
               if (any(connectivity /= mesh%connectivity)) &
                  call fatal_error(error, 'the connectivity in "'//file%file_path// &
                                   '" differs from the current mesh')
            end if
         end if
      end if
      call close_group_after(group, error)
   end subroutine check_mesh

   !> Read a real 2-D dataset `name` of increment (step, increment), e.g. 'reaction' or
   !> 'contact/gap_traction' (for restoring contact state). `values` comes sized with the
   !> expected Fortran shape; a 1-D dataset (n) is read into values(1, n).
   subroutine read_increment_array(path, step, increment, name, values, error)
      character(len=*), intent(in) :: path
      integer, intent(in) :: step, increment
      character(len=*), intent(in) :: name       !! path relative to the increment group
      real(dp), intent(inout) :: values(:, :)
      type(error_t), allocatable, intent(out) :: error
      type(hdf5_location_t) :: file, group
      integer, allocatable :: stored_shape(:)
      real(dp), allocatable :: flat(:)
      real(dp) :: time
      call open_for_reading(path, file, error)
      if (allocated(error)) return
      call open_increment(file, step, increment, group, time, error)
      if (.not. allocated(error)) then
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
         call close_group_after(group, error)
      end if
      call close_file_after(file, error)
   end subroutine read_increment_array
end module frix_hdf5_results
