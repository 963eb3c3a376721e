!> The HDF5 results file as a whole (docs/hdf5-layout.md), shared by its writer
!> (frix_hdf5_results) and its readers (frix_hdf5_restart): creating, opening read-only,
!> reopening for an increment, flushing and closing it with checked HDF5 1.10 calls, the
!> layout version, and the names of the increment groups (/increments/000001, 000002, ...).
module frix_hdf5_file
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_long_long, c_null_char, c_double
   use, intrinsic :: iso_fortran_env, only: output_unit
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_text_output, only: system_reason
   use frix_strings, only: zero_padded, to_string
   use frix_hdf5_support, only: hdf5_location_t, hdf5_initialize, hdf5_finalize, note_failed_close
   use hdf5, only: h5fcreate_f, h5fopen_f, h5fclose_f, h5fflush_f, h5fis_hdf5_f, &
                   h5f_acc_trunc_f, h5f_acc_rdonly_f, h5f_acc_rdwr_f, h5f_scope_global_f
   implicit none
   private

   public :: hdf5_layout_version, increment_group_name
   public :: create_file, open_for_reading, open_for_writing, flush_file, close_file, hdf5_finalize, check_room

   integer, parameter :: hdf5_layout_version = 1   !! root attribute `layout_version`; bump on incompatible change
   integer, parameter :: increment_digits = 6       !! increment group names: 000001, 000002, ...
   !> seconds the writer waits for a reader to close the file (FRIX_HDF5_LOCK_WAIT overrides)
   real(dp), parameter :: default_lock_wait = 60.0_dp
   real(dp), parameter :: retry_interval = 0.1_dp   !! seconds between two attempts

   interface
      !> 0 when the file at `path` can grow by `bytes`, else the errno (frix_disk_space.c).
      integer(c_int) function c_room_to_grow(path, bytes) bind(c, name='frix_room_to_grow')
         import :: c_int, c_char, c_long_long
         character(kind=c_char), intent(in) :: path(*)
         integer(c_long_long), value :: bytes
      end function c_room_to_grow

      !> Pause for `seconds` (frix_pause.c).
      subroutine c_pause(seconds) bind(c, name='frix_pause_c')
         import :: c_double
         real(c_double), value :: seconds
      end subroutine c_pause
   end interface

contains

   !> Name of the group of the `number`-th increment written, below /increments.
   pure function increment_group_name(number) result(name)
      integer, intent(in) :: number
      character(len=:), allocatable :: name
      name = zero_padded(number, increment_digits)
   end function increment_group_name

   !> Create (or truncate) the results file `path` and flush it at once: from then on a run
   !> killed at any point leaves a file that opens (HDF5 keeps the superblock and the root
   !> group in its cache until a flush; killed before, the file held the superblock only,
   !> "truncated file: eof = 96, stored_eof = 2048").
   subroutine create_file(path, file, error)
      character(len=*), intent(in) :: path
      type(hdf5_location_t), intent(inout) :: file
      type(error_t), allocatable, intent(out) :: error
      integer :: status
      call hdf5_initialize(error)
      if (allocated(error)) return
      call h5fcreate_f(path, h5f_acc_trunc_f, file%id, status)
      call name_file(path, status, 'create', file, error)
      if (allocated(error)) return
      call flush_file(file, error)
      if (allocated(error)) call close_file(file, error)
   end subroutine create_file

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
      call name_file(path, status, 'open', file, error)
   end subroutine open_for_reading

   !> Reopen the results file `path` for writing (frix_hdf5_results closes it after every
   !> increment, so that readers can open it between increments). HDF5 locks an open file
   !> (since 1.10): while a reader holds it open, the opening fails; it is tried again every
   !> 0.1 s, with one note on standard output, for up to 60 s (or the seconds of the
   !> environment variable FRIX_HDF5_LOCK_WAIT), then the error names the file and the cause.
   subroutine open_for_writing(path, file, error)
      character(len=*), intent(in) :: path
      type(hdf5_location_t), intent(inout) :: file
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: waited, limit
      integer :: status
      logical :: exists
      inquire (file=path, exist=exists)
      if (.not. exists) then
         call fatal_error(error, 'HDF5: results file "'//path//'" no longer exists, cannot write an increment')
         return
      end if
      waited = 0.0_dp
      limit = lock_wait()
      do
         call h5fopen_f(path, h5f_acc_rdwr_f, file%id, status)
         if (status == 0 .or. waited >= limit) exit
         if (waited == 0.0_dp) then
            write (output_unit, '(a)') 'frix: waiting for "'//path//'": another process holds it open '// &
               '(HDF5 file locking); retrying for up to '//to_string(nint(limit))//' s'
            flush (output_unit)
         end if
         call c_pause(real(retry_interval, c_double))
         waited = waited + retry_interval
      end do
      if (status /= 0) then
         file%id = -1
         call fatal_error(error, 'HDF5: cannot reopen results file "'//path//'" to write an increment: '// &
                          'another process holds it open (a reader must close it between increments, '// &
                          'docs/output.md) or it is no longer writable')
         return
      end if
      call name_file(path, status, 'reopen', file, error)
   end subroutine open_for_writing

   !> Seconds to wait for a reader to close the file: FRIX_HDF5_LOCK_WAIT if it is a number
   !> in [0, 1e6], else default_lock_wait.
   real(dp) function lock_wait()
      character(len=32) :: text
      integer :: length, status, io
      real(dp) :: value
      lock_wait = default_lock_wait
      call get_environment_variable('FRIX_HDF5_LOCK_WAIT', text, length, status)
      if (status /= 0 .or. length == 0) return
      read (text, *, iostat=io) value
      if (io == 0 .and. value >= 0.0_dp .and. value <= 1.0e6_dp) lock_wait = value
   end function lock_wait

   !> After h5fcreate_f or h5fopen_f returned `status`: the error "cannot <action> ..." on
   !> failure (the file is then not open), otherwise the names of `file` for messages.
   subroutine name_file(path, status, action, file, error)
      character(len=*), intent(in) :: path
      integer, intent(in) :: status
      character(len=*), intent(in) :: action   !! 'create', 'open' or 'reopen'
      type(hdf5_location_t), intent(inout) :: file
      type(error_t), allocatable, intent(out) :: error
      if (status /= 0) then
         file%id = -1
         call fatal_error(error, 'HDF5: cannot '//action//' results file "'//path//'"')
         return
      end if
      file%file_path = path
      file%name = '/'
   end subroutine name_file

   !> Flush the whole file to disk (H5Fflush, global scope).
   subroutine flush_file(file, error)
      type(hdf5_location_t), intent(in) :: file
      type(error_t), allocatable, intent(out) :: error
      integer :: status
      call h5fflush_f(file%id, h5f_scope_global_f, status)
      if (status /= 0) call fatal_error(error, 'HDF5: cannot flush results file "'//file%file_path//'"')
   end subroutine flush_file

   !> The error "cannot write <what> ...: <reason>" unless the file can grow by `bytes`: asked
   !> before writing, so that a full disk stops the writing before it starts (a file whose
   !> writes fail half-way is not closed cleanly by HDF5 1.10).
   subroutine check_room(file, bytes, what, error)
      type(hdf5_location_t), intent(in) :: file
      integer(c_long_long), intent(in) :: bytes
      character(len=*), intent(in) :: what   !! e.g. 'increment 3'
      type(error_t), allocatable, intent(out) :: error
      integer(c_int) :: status
      status = c_room_to_grow(file%file_path//c_null_char, bytes)
      if (status /= 0) call fatal_error(error, 'HDF5: cannot write '//what//' into results file "'// &
                                        file%file_path//'": '//system_reason(status))
   end subroutine check_room

   !> Close `file` (no-op if it is not open), also after work on it that may have failed:
   !> `error` keeps the work's error if there is one, otherwise it receives the close's.
   subroutine close_file(file, error)
      type(hdf5_location_t), intent(inout) :: file
      type(error_t), allocatable, intent(inout) :: error
      integer :: status
      if (file%id < 0) return
      call h5fclose_f(file%id, status)
      file%id = -1
      if (status /= 0) call note_failed_close()
      if (status /= 0 .and. .not. allocated(error)) &
         call fatal_error(error, 'HDF5: cannot close results file "'//file%file_path//'"')
   end subroutine close_file
end module frix_hdf5_file
