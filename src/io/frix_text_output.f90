!> Checked writing of the text result files (listing, CSV files, VTK, POS3D): a `text_file_t`
!> is opened, receives lines, is flushed after each increment and closed; the first failure of
!> an open, write, flush or close is kept and returned as an error naming the file, the
!> operation and the system's reason, e.g. 'cannot write listing "results/s1_listing.txt": No
!> space left on device'. The lines go through POSIX writes (frix_text_file.c): libgfortran 12
!> reports no error when a formatted unit's data cannot reach the disk. A `description` is the
!> file's kind and quoted path, e.g. 'VTK file "results/s1_0001_0001.vtu"'.
module frix_text_output
   use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_associated, c_int, c_char, c_size_t, &
                                          c_null_char
   use frix_error, only: error_t, fatal_error
   implicit none
   private

   public :: real_edit, text_file_t, system_reason

   !> Edit descriptor of every real: 17 significant digits, so that binary64 round-trips exactly.
   character(len=*), parameter :: real_edit = 'es24.16e3'

   !> A text file open for writing. After the first failure every further `put` is skipped;
   !> `flush` and `close` return that failure.
   type :: text_file_t
      private
      type(c_ptr) :: handle = c_null_ptr
      character(len=:), allocatable :: description   !! kind and quoted path, for messages
      character(len=:), allocatable :: failure       !! message of the first failure
   contains
      procedure :: open => file_open
      procedure :: is_open => file_is_open
      procedure :: failed => file_failed
      procedure :: put => file_put
      procedure :: flush => file_flush
      procedure :: close => file_close
   end type text_file_t

   interface
      function c_open(path, mode, status) result(handle) bind(c, name='frix_text_open')
         import :: c_ptr, c_char, c_int
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), value :: mode   !! 0 replace, 1 append, 2 replace on a successful close
         integer(c_int), intent(out) :: status
         type(c_ptr) :: handle
      end function c_open
      integer(c_int) function c_put(handle, text, length) bind(c, name='frix_text_put')
         import :: c_ptr, c_char, c_size_t, c_int
         type(c_ptr), value :: handle
         character(kind=c_char), intent(in) :: text(*)
         integer(c_size_t), value :: length
      end function c_put
      integer(c_int) function c_flush(handle) bind(c, name='frix_text_flush')
         import :: c_ptr, c_int
         type(c_ptr), value :: handle
      end function c_flush
      integer(c_int) function c_close(handle, discard) bind(c, name='frix_text_close')
         import :: c_ptr, c_int
         type(c_ptr), value :: handle
         integer(c_int), value :: discard
      end function c_close
      subroutine c_reason(code, text, length) bind(c, name='frix_text_reason')
         import :: c_int, c_char, c_size_t
         integer(c_int), value :: code
         character(kind=c_char), intent(out) :: text(*)
         integer(c_size_t), value :: length
      end subroutine c_reason
   end interface

contains

   !> Open `path` for writing: replaced (created) by default, appended to when `append` is
   !> true; with `replacement` true it is written as `<path>.tmp`, which a successful close
   !> renames to `path` (and a failure removes), so that `path` always holds a whole version.
   !> A file still open is closed first (its failure, if any, is dropped).
   subroutine file_open(self, path, description, error, append, replacement)
      class(text_file_t), intent(inout) :: self
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: description   !! kind and quoted path, for messages
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: append       !! append to the file (default: replace)
      logical, intent(in), optional :: replacement  !! replace the file at the close
      type(error_t), allocatable :: ignored
      integer(c_int) :: status, mode
      if (self%is_open()) call self%close(ignored)
      if (allocated(self%failure)) deallocate (self%failure)
      self%description = description
      mode = 0
      if (present(append)) then
         if (append) mode = 1
      end if
      if (present(replacement)) then
         if (replacement) mode = 2
      end if
      self%handle = c_open(path//c_null_char, mode, status)
      if (status /= 0) then
         self%handle = c_null_ptr
         call fail(self, 'open', status)
         call fatal_error(error, self%failure)
      end if
   end subroutine file_open

   pure logical function file_is_open(self)
      class(text_file_t), intent(in) :: self
      file_is_open = c_associated(self%handle)
   end function file_is_open

   !> Whether a write, flush or close has failed (callers may stop producing lines).
   pure logical function file_failed(self)
      class(text_file_t), intent(in) :: self
      file_failed = allocated(self%failure)
   end function file_failed

   !> Write `text` as one line, unless an earlier operation failed or the file is not open.
   subroutine file_put(self, text)
      class(text_file_t), intent(inout) :: self
      character(len=*), intent(in) :: text
      integer(c_int) :: status
      if (allocated(self%failure) .or. .not. self%is_open()) return
      status = c_put(self%handle, text, len(text, kind=c_size_t))
      if (status /= 0) call fail(self, 'write', status)
   end subroutine file_put

   !> Push the lines written so far to the system; `error` is the first failure, if any.
   subroutine file_flush(self, error)
      class(text_file_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      integer(c_int) :: status
      if (.not. allocated(self%failure)) then
         if (.not. self%is_open()) then
            call fatal_error(error, 'cannot write '//self%description//': the file is not open')
            return
         end if
         status = c_flush(self%handle)
         if (status /= 0) call fail(self, 'write', status)
      end if
      if (allocated(self%failure)) call fatal_error(error, self%failure)
   end subroutine file_flush

   !> Close the file (no-op if it is not open), also after a failure; `error` is the first
   !> failure of the file's writes or of the close. With `discard` true a replacement is
   !> dropped (the file keeps its previous version), e.g. when its content is incomplete.
   subroutine file_close(self, error, discard)
      class(text_file_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: discard
      integer(c_int) :: status, dropping
      if (.not. self%is_open()) return
      dropping = 0
      if (present(discard)) dropping = merge(1, 0, discard)
      status = c_close(self%handle, dropping)
      self%handle = c_null_ptr
      if (status > 0) call fail(self, 'write', status)
      if (status < 0) call fail(self, 'close', -status)
      if (allocated(self%failure)) call fatal_error(error, self%failure)
   end subroutine file_close

   !> Keep the failure of `operation` with errno value `code` (the first one only).
   subroutine fail(self, operation, code)
      type(text_file_t), intent(inout) :: self
      character(len=*), intent(in) :: operation   !! open, write or close
      integer(c_int), intent(in) :: code
      if (allocated(self%failure)) return
      self%failure = 'cannot '//operation//' '//self%description//': '//system_reason(code)
   end subroutine fail

   !> The system's message of errno value `code`, e.g. 'No space left on device' for ENOSPC.
   function system_reason(code) result(reason)
      integer(c_int), intent(in) :: code
      character(len=:), allocatable :: reason
      character(len=200) :: text
      call c_reason(code, text, len(text, kind=c_size_t))
      reason = trim(text)
   end function system_reason
end module frix_text_output
