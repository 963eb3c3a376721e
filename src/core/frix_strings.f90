!> Small string helpers shared by the readers, writers and messages.
module frix_strings
   use frix_kinds, only: dp, i8
   implicit none
   private

   public :: to_string, to_upper, to_lower
   public :: zero_padded

   !> Text of an integer or a real, without padding.
   interface to_string
      module procedure int_to_string, int8_to_string, real_to_string
   end interface to_string

contains

   pure function int_to_string(value) result(text)
      integer, intent(in) :: value
      character(len=:), allocatable :: text
      character(len=24) :: buffer
      write (buffer, '(i0)') value
      text = trim(buffer)
   end function int_to_string

   pure function int8_to_string(value) result(text)
      integer(i8), intent(in) :: value
      character(len=:), allocatable :: text
      character(len=24) :: buffer
      write (buffer, '(i0)') value
      text = trim(buffer)
   end function int8_to_string

   !> Shortest round-trip-safe text is not needed for messages: 6 significant digits.
   pure function real_to_string(value) result(text)
      real(dp), intent(in) :: value
      character(len=:), allocatable :: text
      character(len=32) :: buffer
      write (buffer, '(g0.6)') value
      text = trim(adjustl(buffer))
   end function real_to_string

   !> `value` written with at least `digits` digits, zero-padded (names that sort in order).
   pure function zero_padded(value, digits) result(text)
      integer, intent(in) :: value, digits
      character(len=:), allocatable :: text
      character(len=24) :: buffer, edit
      write (edit, '("(i0.",i0,")")') digits
      write (buffer, edit) value
      text = trim(buffer)
   end function zero_padded

   pure function to_upper(text) result(upper)
      character(len=*), intent(in) :: text
      character(len=len(text)) :: upper
      integer :: i, code
      upper = text
      do i = 1, len(text)
         code = iachar(text(i:i))
         if (code >= iachar('a') .and. code <= iachar('z')) upper(i:i) = achar(code - 32)
      end do
   end function to_upper

   pure function to_lower(text) result(lower)
      character(len=*), intent(in) :: text
      character(len=len(text)) :: lower
      integer :: i, code
      lower = text
      do i = 1, len(text)
         code = iachar(text(i:i))
         if (code >= iachar('A') .and. code <= iachar('Z')) lower(i:i) = achar(code + 32)
      end do
   end function to_lower
end module frix_strings
