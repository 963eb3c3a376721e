!> Line-oriented writing of text result files, shared by the VTK and POS3D writers: open for
!> writing, write lines until the first failure, then close, each failure turned into an
!> error naming the file. A `description` is the file's kind and quoted path, e.g.
!> 'VTK file "results/s1_0001_0001.vtu"'; messages read 'cannot open <description>: <iomsg>',
!> 'cannot write <description> (iostat N)', 'cannot close <description>'.
module frix_text_output
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   implicit none
   private

   public :: real_edit, open_for_writing, put, close_written_file

   !> Edit descriptor of every real: 17 significant digits, so that binary64 round-trips exactly.
   character(len=*), parameter :: real_edit = 'es24.16e3'

contains

   !> Open `path` for writing on a new unit: replaced (created) by default, or appended to
   !> an existing file when `append` is true.
   subroutine open_for_writing(path, description, unit, error, append)
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: description   !! kind and quoted path, for the message
      integer, intent(out) :: unit
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: append       !! append to an existing file (default: replace)
      character(len=256) :: message
      integer :: stat
      logical :: appending
      appending = .false.
      if (present(append)) appending = append
      if (appending) then
         open (newunit=unit, file=path, status='old', position='append', action='write', iostat=stat, iomsg=message)
      else
         open (newunit=unit, file=path, status='replace', action='write', iostat=stat, iomsg=message)
      end if
      if (stat /= 0) call fatal_error(error, 'cannot open '//description//': '//trim(message))
   end subroutine open_for_writing

   !> Write one line unless an earlier write failed (`stat` /= 0 skips everything after).
   subroutine put(unit, text, stat)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: text
      integer, intent(inout) :: stat
      if (stat /= 0) return
      write (unit, '(a)', iostat=stat) text
   end subroutine put

   !> Close `unit` after a sequence of writes whose first failure left `stat` /= 0; a write or
   !> close failure gives an error. With `close_iostat` true the close message also gives
   !> the iostat.
   subroutine close_written_file(unit, stat, description, error, close_iostat)
      integer, intent(in) :: unit
      integer, intent(in) :: stat                   !! iostat of the writes (0: all written)
      character(len=*), intent(in) :: description   !! kind and quoted path, for the message
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: close_iostat  !! append ' (iostat N)' to a close failure
      integer :: close_stat
      if (stat /= 0) then
         close (unit)
         call fatal_error(error, 'cannot write '//description//' (iostat '//to_string(stat)//')')
         return
      end if
      close (unit, iostat=close_stat)
      if (close_stat == 0) return
      if (present(close_iostat)) then
         if (close_iostat) then
            call fatal_error(error, 'cannot close '//description//' (iostat '//to_string(close_stat)//')')
            return
         end if
      end if
      call fatal_error(error, 'cannot close '//description)
   end subroutine close_written_file
end module frix_text_output
