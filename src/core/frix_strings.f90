!> Small string helpers shared by the readers, writers and messages.
module frix_strings
   use frix_kinds, only: dp, i8
   implicit none
   private

   public :: to_string, to_upper, to_lower
   public :: zero_padded, padded, scientific, fixed_point

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

   !> `text` right-justified in `width` characters, or whole when longer: the width of a
   !> fixed-width edit descriptor without its asterisks when the value does not fit.
   pure function padded(text, width) result(field)
      character(len=*), intent(in) :: text
      integer, intent(in) :: width
      character(len=:), allocatable :: field
      field = repeat(' ', max(0, width - len(text)))//text
   end function padded

   !> `value` in scientific notation with `digits` digits after the point, the exponent with
   !> two digits where they suffice (5.3846E+03) and three otherwise (1.0000E-300); NaN and
   !> Infinity as such. Unlike ESw.dE2 it never overflows to asterisks.
   pure function scientific(value, digits) result(text)
      real(dp), intent(in) :: value
      integer, intent(in) :: digits
      character(len=:), allocatable :: text
      character(len=64) :: buffer
      character(len=24) :: edit
      integer :: e
      write (edit, '("(es",i0,".",i0,"e3)")') digits + 10, digits
      write (buffer, edit) value
      text = trim(adjustl(buffer))
      e = index(text, 'E', back=.true.)
      if (e == 0 .or. len(text) /= e + 4) return
      if (text(e + 2:e + 2) == '0') text = text(1:e + 1)//text(e + 3:)
   end function scientific

   !> `value` with `decimals` digits after the point (F0.d, with a leading 0 before the point)
   !> below 1e15 in magnitude, else as `scientific`: no asterisks for any value.
   pure function fixed_point(value, decimals) result(text)
      real(dp), intent(in) :: value
      integer, intent(in) :: decimals
      character(len=:), allocatable :: text
      character(len=64) :: buffer
      character(len=24) :: edit
      if (.not. abs(value) < 1.0e15_dp) then
         text = scientific(value, decimals)
         return
      end if
      write (edit, '("(f",i0,".",i0,")")') 17 + decimals, decimals
      write (buffer, edit) value
      text = trim(adjustl(buffer))
   end function fixed_point

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
