!> Checked wrappers around the HDF5 1.10 Fortran API used by the results file
!> (`frix_hdf5_file`, `frix_hdf5_results`, `frix_hdf5_restart`): groups, datasets and
!> attributes. Every HDF5 return code is tested and a failure becomes an `error_t`
!> naming the file and the object ("HDF5: cannot <action> "<object>" in "<file>"").
!>
!> Arrays are written in Fortran (column-major) order with the Fortran shape reversed in the
!> HDF5 dataspace, as the HDF5 Fortran library does: a Fortran array (3, n) is a C/h5py array
!> (n, 3) with identical bytes. Reals are H5T_NATIVE_DOUBLE (IEEE binary64, exact round trip),
!> integers are the native Fortran default integer (int32). Strings are fixed-length,
!> NUL-terminated C strings (h5py returns them as `bytes`).
!> Empty arrays (a zero extent) are stored as datasets with a zero dimension and no data.
module frix_hdf5_support
   use, intrinsic :: iso_c_binding, only: c_loc, c_ptr, c_null_char, c_f_pointer, c_signed_char, c_size_t
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use hdf5, only: hid_t, hsize_t, size_t, h5open_f, h5close_f, h5dont_atexit_f, h5eset_auto_f, &
                   h5gcreate_f, h5gopen_f, h5gclose_f, h5lexists_f, &
                   h5screate_simple_f, h5screate_f, h5sclose_f, h5s_scalar_f, &
                   h5sget_simple_extent_ndims_f, h5sget_simple_extent_dims_f, &
                   h5dcreate_f, h5dopen_f, h5dclose_f, h5dwrite_f, h5dread_f, h5dget_space_f, &
                   h5acreate_f, h5aopen_f, h5aclose_f, h5awrite_f, h5aread_f, h5aexists_f, &
                   h5tcopy_f, h5tset_size_f, h5tset_strpad_f, h5tclose_f, h5t_str_nullterm_f, &
                   h5t_native_double, h5t_native_integer, h5t_native_character, &
                   h5dget_type_f, h5tget_class_f, h5t_integer_f, h5t_float_f
   implicit none
   private

   public :: hid_t
   public :: hdf5_location_t, hdf5_initialize, hdf5_finalize, note_failed_close
   public :: create_group, open_group, close_group, close_group_after, link_exists
   public :: write_dataset, read_dataset, dataset_shape
   public :: write_attribute, read_attribute, attribute_exists

   !> An open HDF5 file or group together with the names used in error messages.
   type :: hdf5_location_t
      integer(hid_t) :: id = -1
      character(len=:), allocatable :: file_path   !! the file, as given by the caller
      character(len=:), allocatable :: name        !! absolute HDF5 path of the object, '/' for the file
   end type hdf5_location_t

   !> Write a dataset `name` below a location: real(dp) of rank 1-3, default integer of rank 1-2.
   !> (A non-contiguous actual argument is copied in first.)
   interface write_dataset
      module procedure write_real_1, write_real_2, write_real_3, write_integer_1, write_integer_2
   end interface write_dataset

   !> Read a dataset whose Fortran shape must equal the shape of the (already sized) array;
   !> the array is left unchanged on error.
   interface read_dataset
      module procedure read_real_1, read_real_2, read_real_3, read_integer_2
   end interface read_dataset

   !> Scalar attribute: text, default integer or real(dp).
   interface write_attribute
      module procedure write_attribute_text, write_attribute_integer, write_attribute_real
   end interface write_attribute

   !> Scalar numeric attribute (HDF5 converts between numeric types).
   interface read_attribute
      module procedure read_attribute_integer, read_attribute_real
   end interface read_attribute

   logical, save :: library_open = .false.   !! hdf5_initialize has opened the library
   logical, save :: close_failed = .false.   !! a file's H5Fclose failed (note_failed_close)

contains

   !> Initialise the HDF5 Fortran library (predefined types) and switch off HDF5's automatic
   !> printing of its error stack: errors are reported through `error_t` only. Idempotent.
   !> HDF5's own clean-up at exit is switched off (the library is closed by hdf5_finalize):
   !> when H5Fclose fails (a full disk), HDF5 1.10 frees the file but keeps its id, and its
   !> at-exit clean-up closes that id again (use after free, SIGSEGV in H5F__close_cb).
   subroutine hdf5_initialize(error)
      type(error_t), allocatable, intent(out) :: error
      integer :: status
      if (.not. library_open) call h5dont_atexit_f(status)   ! fails harmlessly once HDF5 is running
      call h5open_f(status)
      if (status /= 0) then
         call fatal_error(error, 'HDF5: cannot initialise the HDF5 library')
         return
      end if
      library_open = .true.
      call h5eset_auto_f(0, status)
      if (status /= 0) call fatal_error(error, 'HDF5: cannot switch off automatic error printing')
   end subroutine hdf5_initialize

   !> Close the HDF5 library at the end of a run (no-op if it was not opened), unless a file's
   !> close failed: the library's state then holds a freed file (hdf5_initialize), and it is
   !> left to the end of the process.
   subroutine hdf5_finalize()
      integer :: status
      if (.not. library_open .or. close_failed) return
      call h5close_f(status)
      library_open = .false.
   end subroutine hdf5_finalize

   !> Record that H5Fclose failed (see hdf5_finalize).
   subroutine note_failed_close()
      close_failed = .true.
   end subroutine note_failed_close

   !> Absolute HDF5 path of `name` below `parent`.
   pure function child_path(parent, name) result(path)
      type(hdf5_location_t), intent(in) :: parent
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: path
      if (parent%name == '/') then
         path = '/'//name
      else
         path = parent%name//'/'//name
      end if
   end function child_path

   !> The error "HDF5: cannot <action> "<object>" in "<file>"".
   subroutine hdf5_failure(error, action, location, name)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: action
      type(hdf5_location_t), intent(in) :: location
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: object
      object = location%name
      if (len(name) > 0) object = child_path(location, name)
      call fatal_error(error, 'HDF5: cannot '//action//' "'//object//'" in "'//location%file_path//'"')
   end subroutine hdf5_failure

   !> The error "HDF5: cannot <action> "<name>" of "<object>" in "<file>"" of attribute `name`.
   subroutine attribute_failure(error, action, location, name)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: action   !! e.g. 'write attribute'
      type(hdf5_location_t), intent(in) :: location
      character(len=*), intent(in) :: name
      call fatal_error(error, 'HDF5: cannot '//action//' "'//name//'" of "'//location%name//'" in "'// &
                       location%file_path//'"')
   end subroutine attribute_failure

   !> Create the group `name` below `parent`.
   subroutine create_group(parent, name, group, error)
      type(hdf5_location_t), intent(in) :: parent
      character(len=*), intent(in) :: name
      type(hdf5_location_t), intent(out) :: group
      type(error_t), allocatable, intent(out) :: error
      integer :: status
      call h5gcreate_f(parent%id, name, group%id, status)
      call name_group(parent, name, status, 'create group', group, error)
   end subroutine create_group

   !> Open the existing group `name` below `parent`.
   subroutine open_group(parent, name, group, error)
      type(hdf5_location_t), intent(in) :: parent
      character(len=*), intent(in) :: name
      type(hdf5_location_t), intent(out) :: group
      type(error_t), allocatable, intent(out) :: error
      integer :: status
      call h5gopen_f(parent%id, name, group%id, status)
      call name_group(parent, name, status, 'open group', group, error)
   end subroutine open_group

   !> After h5gcreate_f or h5gopen_f returned `status`: the error "cannot <action> ..." on
   !> failure, otherwise the file and object names of `group`.
   subroutine name_group(parent, name, status, action, group, error)
      type(hdf5_location_t), intent(in) :: parent
      character(len=*), intent(in) :: name
      integer, intent(in) :: status
      character(len=*), intent(in) :: action   !! 'create group' or 'open group'
      type(hdf5_location_t), intent(inout) :: group
      type(error_t), allocatable, intent(out) :: error
      if (status /= 0) then
         call hdf5_failure(error, action, parent, name)
         return
      end if
      group%file_path = parent%file_path
      group%name = child_path(parent, name)
   end subroutine name_group

   !> Close a group opened by `create_group` or `open_group` (no-op if not open).
   subroutine close_group(group, error)
      type(hdf5_location_t), intent(inout) :: group
      type(error_t), allocatable, intent(out) :: error
      integer :: status
      if (group%id < 0) return
      call h5gclose_f(group%id, status)
      if (status /= 0) call hdf5_failure(error, 'close group', group, '')
      group%id = -1
   end subroutine close_group

   !> Close `group` after work on it that may have failed: `error` keeps the work's error if
   !> there is one, otherwise it receives the close's.
   subroutine close_group_after(group, error)
      type(hdf5_location_t), intent(inout) :: group
      type(error_t), allocatable, intent(inout) :: error
      type(error_t), allocatable :: close_error
      call close_group(group, close_error)
      if (.not. allocated(error)) call move_alloc(close_error, error)
   end subroutine close_group_after

   !> Whether a link (group or dataset) `name` exists directly below `parent`.
   subroutine link_exists(parent, name, exists, error)
      type(hdf5_location_t), intent(in) :: parent
      character(len=*), intent(in) :: name
      logical, intent(out) :: exists
      type(error_t), allocatable, intent(out) :: error
      integer :: status
      exists = .false.
      call h5lexists_f(parent%id, name, exists, status)
      if (status /= 0) call hdf5_failure(error, 'look up', parent, name)
   end subroutine link_exists

   !> Create a dataset of `type_id` with Fortran shape `fortran_shape` (stored reversed) and
   !> write `buffer` (the array's first element, column-major) unless it is empty.
   subroutine write_raw(parent, name, type_id, fortran_shape, buffer, error)
      type(hdf5_location_t), intent(in) :: parent
      character(len=*), intent(in) :: name
      integer(hid_t), intent(in) :: type_id
      integer, intent(in) :: fortran_shape(:)
      type(c_ptr), intent(in) :: buffer
      type(error_t), allocatable, intent(out) :: error
      integer(hsize_t) :: dims(size(fortran_shape))
      integer(hid_t) :: space, dataset
      integer :: status, close_status
      ! The HDF5 Fortran library reverses the dimensions itself: dims are given in Fortran order.
      dims = int(fortran_shape, hsize_t)
      call h5screate_simple_f(size(dims), dims, space, status)
      if (status /= 0) then
         call hdf5_failure(error, 'create the dataspace of', parent, name)
         return
      end if
      call h5dcreate_f(parent%id, name, type_id, space, dataset, status)
      if (status /= 0) then
         call h5sclose_f(space, close_status)
         call hdf5_failure(error, 'create dataset', parent, name)
         return
      end if
      if (product(fortran_shape) > 0) call h5dwrite_f(dataset, type_id, buffer, status)
      call h5dclose_f(dataset, close_status)
      if (status == 0) status = close_status
      call h5sclose_f(space, close_status)
      if (status == 0) status = close_status
      if (status /= 0) call hdf5_failure(error, 'write dataset', parent, name)
   end subroutine write_raw

   subroutine write_real_1(parent, name, values, error)
      type(hdf5_location_t), intent(in) :: parent
      character(len=*), intent(in) :: name
      real(dp), intent(in), target, contiguous :: values(:)
      type(error_t), allocatable, intent(out) :: error
      call write_raw(parent, name, h5t_native_double, shape(values), c_loc(values), error)
   end subroutine write_real_1

   subroutine write_real_2(parent, name, values, error)
      type(hdf5_location_t), intent(in) :: parent
      character(len=*), intent(in) :: name
      real(dp), intent(in), target, contiguous :: values(:, :)
      type(error_t), allocatable, intent(out) :: error
      call write_raw(parent, name, h5t_native_double, shape(values), c_loc(values), error)
   end subroutine write_real_2

   subroutine write_real_3(parent, name, values, error)
      type(hdf5_location_t), intent(in) :: parent
      character(len=*), intent(in) :: name
      real(dp), intent(in), target, contiguous :: values(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      call write_raw(parent, name, h5t_native_double, shape(values), c_loc(values), error)
   end subroutine write_real_3

   subroutine write_integer_1(parent, name, values, error)
      type(hdf5_location_t), intent(in) :: parent
      character(len=*), intent(in) :: name
      integer, intent(in), target, contiguous :: values(:)
      type(error_t), allocatable, intent(out) :: error
      call write_raw(parent, name, h5t_native_integer, shape(values), c_loc(values), error)
   end subroutine write_integer_1

   subroutine write_integer_2(parent, name, values, error)
      type(hdf5_location_t), intent(in) :: parent
      character(len=*), intent(in) :: name
      integer, intent(in), target, contiguous :: values(:, :)
      type(error_t), allocatable, intent(out) :: error
      call write_raw(parent, name, h5t_native_integer, shape(values), c_loc(values), error)
   end subroutine write_integer_2

   !> Fortran shape of dataset `name` below `parent` (the reverse of what h5py shows).
   subroutine dataset_shape(parent, name, fortran_shape, error)
      type(hdf5_location_t), intent(in) :: parent
      character(len=*), intent(in) :: name
      integer, allocatable, intent(out) :: fortran_shape(:)
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: dataset
      integer :: status, close_status
      call h5dopen_f(parent%id, name, dataset, status)
      if (status /= 0) then
         call hdf5_failure(error, 'open dataset', parent, name)
         return
      end if
      call shape_of_open_dataset(dataset, fortran_shape, status)
      call h5dclose_f(dataset, close_status)
      if (status /= 0 .or. close_status /= 0) call hdf5_failure(error, 'query the shape of dataset', parent, name)
   end subroutine dataset_shape

   subroutine shape_of_open_dataset(dataset, fortran_shape, status)
      integer(hid_t), intent(in) :: dataset
      integer, allocatable, intent(out) :: fortran_shape(:)
      integer, intent(out) :: status
      integer(hid_t) :: space
      integer(hsize_t), allocatable :: dims(:), max_dims(:)
      integer :: rank, close_status
      allocate (fortran_shape(0))
      call h5dget_space_f(dataset, space, status)
      if (status /= 0) return
      call h5sget_simple_extent_ndims_f(space, rank, status)
      if (status == 0) then
         allocate (dims(rank), max_dims(rank))
         ! returns the rank in `status` on success, -1 on failure
         call h5sget_simple_extent_dims_f(space, dims, max_dims, status)
         if (status == rank) then
            status = 0
            fortran_shape = int(dims)
         else
            status = -1
         end if
      end if
      call h5sclose_f(space, close_status)
      if (status == 0) status = close_status
   end subroutine shape_of_open_dataset

   !> Open dataset `name`, check that its Fortran shape is `expected`, read it into the array
   !> at `values` (elements of `element_bytes` bytes), which is left unchanged on error.
   subroutine read_raw(parent, name, type_id, expected, element_bytes, values, error)
      type(hdf5_location_t), intent(in) :: parent
      character(len=*), intent(in) :: name
      integer(hid_t), intent(in) :: type_id
      integer, intent(in) :: expected(:)
      integer, intent(in) :: element_bytes
      type(c_ptr), intent(in) :: values
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: dataset
      integer :: status, close_status
      call h5dopen_f(parent%id, name, dataset, status)
      if (status /= 0) then
         call hdf5_failure(error, 'open dataset', parent, name)
         return
      end if
      call check_read_shape(parent, name, dataset, expected, error)
      if (.not. allocated(error)) call check_read_type(parent, name, dataset, type_id, error)
      if (.not. allocated(error)) &
         call read_open_dataset(dataset, type_id, int(product(expected), c_size_t)*element_bytes, values, status)
      call h5dclose_f(dataset, close_status)
      if (allocated(error)) return
      if (status == 0) status = close_status
      if (status /= 0) call hdf5_failure(error, 'read dataset', parent, name)
   end subroutine read_raw

   !> Error unless the open dataset `name` stores values of the class (floating point or
   !> integer) of the memory type `type_id`: HDF5 would convert an integer dataset into reals
   !> silently, which a restart must not accept.
   subroutine check_read_type(parent, name, dataset, type_id, error)
      type(hdf5_location_t), intent(in) :: parent
      character(len=*), intent(in) :: name
      integer(hid_t), intent(in) :: dataset, type_id
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: stored_type
      integer :: stored_class, wanted_class, status, close_status
      call h5dget_type_f(dataset, stored_type, status)
      if (status /= 0) then
         call hdf5_failure(error, 'query the type of dataset', parent, name)
         return
      end if
      call h5tget_class_f(stored_type, stored_class, status)
      call h5tclose_f(stored_type, close_status)
      if (status == 0) call h5tget_class_f(type_id, wanted_class, status)
      if (status /= 0 .or. close_status /= 0) then
         call hdf5_failure(error, 'query the type of dataset', parent, name)
      else if (stored_class /= wanted_class) then
         call fatal_error(error, 'HDF5: dataset "'//name//'" in "'//parent%file_path//'" holds '// &
                          class_text(stored_class)//' values, expected '//class_text(wanted_class))
      end if
   end subroutine check_read_type

   !> "integer", "floating-point" or "other" for an HDF5 type class.
   pure function class_text(type_class) result(text)
      integer, intent(in) :: type_class
      character(len=:), allocatable :: text
      if (type_class == h5t_integer_f) then
         text = 'integer'
      else if (type_class == h5t_float_f) then
         text = 'floating-point'
      else
         text = 'other (neither integer nor floating-point)'
      end if
   end function class_text

   !> Error unless the open dataset `name` has the Fortran shape `expected`.
   subroutine check_read_shape(parent, name, dataset, expected, error)
      type(hdf5_location_t), intent(in) :: parent
      character(len=*), intent(in) :: name
      integer(hid_t), intent(in) :: dataset
      integer, intent(in) :: expected(:)
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: found(:)
      integer :: status
      call shape_of_open_dataset(dataset, found, status)
      if (status /= 0) then
         call hdf5_failure(error, 'query the shape of dataset', parent, name)
      else if (size(found) /= size(expected)) then
         call fatal_error(error, 'HDF5: dataset "'//child_path(parent, name)//'" in "'//parent%file_path// &
                          '" has rank '//to_string(size(found))//', expected '//to_string(size(expected)))
      else if (any(found /= expected)) then
         call fatal_error(error, 'HDF5: dataset "'//child_path(parent, name)//'" in "'//parent%file_path// &
                          '" has shape '//shape_text(found)//', the current model needs '//shape_text(expected)// &
                          ' (shapes in h5py order)')
      end if
   end subroutine check_read_shape

   !> Read all `n_bytes` of an open dataset as `type_id` into a buffer, and copy them to
   !> `values` only if the read succeeds (`status` 0).
   subroutine read_open_dataset(dataset, type_id, n_bytes, values, status)
      integer(hid_t), intent(in) :: dataset, type_id
      integer(c_size_t), intent(in) :: n_bytes
      type(c_ptr), intent(in) :: values
      integer, intent(out) :: status
      integer(c_signed_char), allocatable, target :: buffer(:)
      integer(c_signed_char), pointer :: destination(:)
      type(c_ptr) :: buffer_address
      status = 0
      if (n_bytes == 0) return
      allocate (buffer(n_bytes))
      buffer_address = c_loc(buffer)   ! h5dread_f wants an intent(inout) C pointer
      call h5dread_f(dataset, type_id, buffer_address, status)
      if (status /= 0) return
      call c_f_pointer(values, destination, [n_bytes])
      destination = buffer
   end subroutine read_open_dataset

   !> "(n1, n2, ...)" in h5py (C) order, i.e. the Fortran shape reversed.
   pure function shape_text(fortran_shape) result(text)
      integer, intent(in) :: fortran_shape(:)
      character(len=:), allocatable :: text
      integer :: i
      text = '('
      do i = size(fortran_shape), 1, -1
         text = text//to_string(fortran_shape(i))
         if (i > 1) text = text//', '
      end do
      text = text//')'
   end function shape_text

   subroutine read_real_1(parent, name, values, error)
      type(hdf5_location_t), intent(in) :: parent
      character(len=*), intent(in) :: name
      real(dp), intent(inout), target, contiguous :: values(:)
      type(error_t), allocatable, intent(out) :: error
      call read_raw(parent, name, h5t_native_double, shape(values), storage_size(values)/8, c_loc(values), error)
   end subroutine read_real_1

   subroutine read_real_2(parent, name, values, error)
      type(hdf5_location_t), intent(in) :: parent
      character(len=*), intent(in) :: name
      real(dp), intent(inout), target, contiguous :: values(:, :)
      type(error_t), allocatable, intent(out) :: error
      call read_raw(parent, name, h5t_native_double, shape(values), storage_size(values)/8, c_loc(values), error)
   end subroutine read_real_2

   subroutine read_real_3(parent, name, values, error)
      type(hdf5_location_t), intent(in) :: parent
      character(len=*), intent(in) :: name
      real(dp), intent(inout), target, contiguous :: values(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      call read_raw(parent, name, h5t_native_double, shape(values), storage_size(values)/8, c_loc(values), error)
   end subroutine read_real_3

   subroutine read_integer_2(parent, name, values, error)
      type(hdf5_location_t), intent(in) :: parent
      character(len=*), intent(in) :: name
      integer, intent(inout), target, contiguous :: values(:, :)
      type(error_t), allocatable, intent(out) :: error
      call read_raw(parent, name, h5t_native_integer, shape(values), storage_size(values)/8, c_loc(values), error)
   end subroutine read_integer_2

   !> Create the scalar attribute `name` of `type_id` on `location` and write `buffer`.
   subroutine write_attribute_raw(location, name, type_id, buffer, error)
      type(hdf5_location_t), intent(in) :: location
      character(len=*), intent(in) :: name
      integer(hid_t), intent(in) :: type_id
      type(c_ptr), intent(in) :: buffer
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: space, attribute
      integer :: status, close_status
      call h5screate_f(h5s_scalar_f, space, status)
      if (status /= 0) then
         call attribute_failure(error, 'create the dataspace of attribute', location, name)
         return
      end if
      call h5acreate_f(location%id, name, type_id, space, attribute, status)
      if (status == 0) then
         call h5awrite_f(attribute, type_id, buffer, status)
         call h5aclose_f(attribute, close_status)
         if (status == 0) status = close_status
      end if
      call h5sclose_f(space, close_status)
      if (status == 0) status = close_status
      if (status /= 0) call attribute_failure(error, 'write attribute', location, name)
   end subroutine write_attribute_raw

   !> Text attribute: a fixed-length NUL-terminated (H5T_STR_NULLTERM) string of len(text) + 1 bytes.
   subroutine write_attribute_text(location, name, text, error)
      type(hdf5_location_t), intent(in) :: location
      character(len=*), intent(in) :: name
      character(len=*), intent(in) :: text
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable, target :: buffer
      integer(hid_t) :: string_type
      integer :: status, close_status
      buffer = text//c_null_char
      call h5tcopy_f(h5t_native_character, string_type, status)
      if (status == 0) call h5tset_size_f(string_type, int(len(buffer), size_t), status)
      if (status == 0) call h5tset_strpad_f(string_type, h5t_str_nullterm_f, status)
      if (status /= 0) then
         call attribute_failure(error, 'make the string type of attribute', location, name)
         return
      end if
      call write_attribute_raw(location, name, string_type, c_loc(buffer), error)
      call h5tclose_f(string_type, close_status)
      if (.not. allocated(error) .and. close_status /= 0) &
         call fatal_error(error, 'HDF5: cannot close the string type of attribute "'//name//'"')
   end subroutine write_attribute_text

   subroutine write_attribute_integer(location, name, value, error)
      type(hdf5_location_t), intent(in) :: location
      character(len=*), intent(in) :: name
      integer, intent(in) :: value
      type(error_t), allocatable, intent(out) :: error
      integer, target :: buffer
      buffer = value
      call write_attribute_raw(location, name, h5t_native_integer, c_loc(buffer), error)
   end subroutine write_attribute_integer

   subroutine write_attribute_real(location, name, value, error)
      type(hdf5_location_t), intent(in) :: location
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: value
      type(error_t), allocatable, intent(out) :: error
      real(dp), target :: buffer
      buffer = value
      call write_attribute_raw(location, name, h5t_native_double, c_loc(buffer), error)
   end subroutine write_attribute_real

   !> Whether `location` carries the attribute `name`.
   subroutine attribute_exists(location, name, exists, error)
      type(hdf5_location_t), intent(in) :: location
      character(len=*), intent(in) :: name
      logical, intent(out) :: exists
      type(error_t), allocatable, intent(out) :: error
      integer :: status
      exists = .false.
      call h5aexists_f(location%id, name, exists, status)
      if (status /= 0) call attribute_failure(error, 'look up attribute', location, name)
   end subroutine attribute_exists

   !> Read the scalar attribute `name` of `location` as `type_id` into `buffer`.
   subroutine read_attribute_raw(location, name, type_id, buffer, error)
      type(hdf5_location_t), intent(in) :: location
      character(len=*), intent(in) :: name
      integer(hid_t), intent(in) :: type_id
      type(c_ptr), intent(in) :: buffer
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: attribute
      type(c_ptr) :: destination
      integer :: status, close_status
      call h5aopen_f(location%id, name, attribute, status)
      if (status == 0) then
         destination = buffer   ! h5aread_f wants an intent(inout) C pointer
         call h5aread_f(attribute, type_id, destination, status)
         call h5aclose_f(attribute, close_status)
         if (status == 0) status = close_status
      end if
      if (status /= 0) call attribute_failure(error, 'read attribute', location, name)
   end subroutine read_attribute_raw

   subroutine read_attribute_integer(location, name, value, error)
      type(hdf5_location_t), intent(in) :: location
      character(len=*), intent(in) :: name
      integer, intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      integer, target :: buffer
      buffer = 0
      call read_attribute_raw(location, name, h5t_native_integer, c_loc(buffer), error)
      value = buffer
   end subroutine read_attribute_integer

   subroutine read_attribute_real(location, name, value, error)
      type(hdf5_location_t), intent(in) :: location
      character(len=*), intent(in) :: name
      real(dp), intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      real(dp), target :: buffer
      buffer = 0.0_dp
      call read_attribute_raw(location, name, h5t_native_double, c_loc(buffer), error)
      value = buffer
   end subroutine read_attribute_real
end module frix_hdf5_support
