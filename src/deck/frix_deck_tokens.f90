!> Lines and tokens of an input deck, with the column of every token (for `file:line:col`
!> messages), and the number conversions of the deck, delegated to frix_text_scanner (syntax
!> check, then `iostat`), so no text can stop the program.
!>
!> Token rules: `//` starts a comment anywhere on a line; tokens are separated by blanks, tabs
!> or commas. Numbers: integers `[+-]digits`; reals in Fortran or C notation (1, -2.5, 1e-3,
!> 1.5D+2). NaN, Inf and values beyond the double range are "not a finite number"; integers
!> beyond the default integer range are "integer out of range".
module frix_deck_tokens
   use, intrinsic :: ieee_exceptions, only: ieee_set_flag, ieee_overflow
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_upper, to_lower
   use frix_text_scanner, only: text_scanner_t, text_scanner_from_string
   implicit none
   private

   public :: deck_line_t, split_line, parse_real, parse_integer, is_section_line, section_name

   !> One line of a deck: its number, its text (comment kept) and the token columns.
   type :: deck_line_t
      integer :: number = 0                   !! 1-based line number in the deck file
      character(len=:), allocatable :: text   !! the line as read, tabs kept
      integer, allocatable :: first(:)        !! first column of each token
      integer, allocatable :: last(:)         !! last column of each token
   contains
      procedure :: n_tokens
      procedure :: token
      procedure :: keyword
   end type deck_line_t

contains

   !> Number of tokens on the line (comments excluded).
   pure integer function n_tokens(self)
      class(deck_line_t), intent(in) :: self
      n_tokens = 0
      if (allocated(self%first)) n_tokens = size(self%first)
   end function n_tokens

   !> Text of token `i` as written.
   pure function token(self, i) result(text)
      class(deck_line_t), intent(in) :: self
      integer, intent(in) :: i
      character(len=:), allocatable :: text
      text = self%text(self%first(i):self%last(i))
   end function token

   !> Text of token `i` in upper case (keywords are case-insensitive).
   pure function keyword(self, i) result(text)
      class(deck_line_t), intent(in) :: self
      integer, intent(in) :: i
      character(len=:), allocatable :: text
      text = to_upper(self%text(self%first(i):self%last(i)))
   end function keyword

   !> Make a deck line from its text: find the comment and the tokens.
   pure function split_line(number, text) result(line)
      integer, intent(in) :: number
      character(len=*), intent(in) :: text
      type(deck_line_t) :: line
      integer :: i, n, end_of_content, start
      integer :: first(len(text)/2 + 1), last(len(text)/2 + 1)
      line%number = number
      line%text = text
      end_of_content = index(text, '//') - 1
      if (end_of_content < 0) end_of_content = len(text)
      n = 0
      start = 0
      do i = 1, end_of_content
         if (is_separator(text(i:i))) then
            if (start > 0) then
               n = n + 1
               first(n) = start
               last(n) = i - 1
               start = 0
            end if
         else if (start == 0) then
            start = i
         end if
      end do
      if (start > 0) then
         n = n + 1
         first(n) = start
         last(n) = end_of_content
      end if
      allocate (line%first(n), line%last(n))
      line%first(:) = first(1:n)
      line%last(:) = last(1:n)
   end function split_line

   pure logical function is_separator(character)
      character(len=1), intent(in) :: character
      is_separator = character == ' ' .or. character == achar(9) .or. character == ',' &
                     .or. character == achar(13)
   end function is_separator

   !> A section line starts with at least 6 dashes (after optional blanks).
   pure logical function is_section_line(text)
      character(len=*), intent(in) :: text
      is_section_line = index(adjustl(text), '------') == 1
   end function is_section_line

   !> Name of a section line in upper case with single blanks: `----NODE COORDS` -> NODE COORDS.
   pure function section_name(text) result(name)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: name
      character(len=:), allocatable :: rest
      integer :: i, comment
      rest = adjustl(text)
      comment = index(rest, '//')
      if (comment > 0) rest = rest(1:comment - 1)
      i = verify(rest, '-')
      if (i == 0) then
         name = ''
         return
      end if
      rest = to_upper(trim(rest(i:)))
      name = ''
      do i = 1, len(rest)
         if (is_separator(rest(i:i))) then
            if (len(name) > 0) then
               if (name(len(name):len(name)) /= ' ') name = name//' '
            end if
         else
            name = name//rest(i:i)
         end if
      end do
      name = trim(name)
   end function section_name

   !> Read a finite real from `text` (the number syntax is frix_text_scanner's). On failure
   !> `ok` is false and `message` says why: "expected a number" or "not a finite number"
   !> (NaN, Inf, or beyond the double range).
   subroutine parse_real(text, value, ok, message)
      character(len=*), intent(in) :: text
      real(dp), intent(out) :: value
      logical, intent(out) :: ok
      character(len=:), allocatable, intent(out) :: message
      type(text_scanner_t) :: scanner
      type(error_t), allocatable :: error
      character(len=:), allocatable :: word
      scanner = text_scanner_from_string('deck', text)
      ok = scanner%next_line()
      call scanner%read_real(value, error)
      ok = .not. allocated(error)
      if (ok) return
      value = 0.0_dp
      word = to_lower(text)
      if (len(word) > 0) then
         if (word(1:1) == '+' .or. word(1:1) == '-') word = word(2:)
      end if
      if (index(error%message, 'out of range') > 0 .or. word == 'nan' .or. word == 'inf' .or. &
          word == 'infinity' .or. index(word, 'nan(') == 1) then
         message = 'not a finite number'
         ! the overflow was reported as a deck mistake: do not leave the flag raised
         call ieee_set_flag(ieee_overflow, .false.)
      else
         message = 'expected a number'
      end if
   end subroutine parse_real

   !> Read a default integer from `text`; rejects text, reals and values beyond huge(1)
   !> ("expected an integer", "integer out of range").
   subroutine parse_integer(text, value, ok, message)
      character(len=*), intent(in) :: text
      integer, intent(out) :: value
      logical, intent(out) :: ok
      character(len=:), allocatable, intent(out) :: message
      type(text_scanner_t) :: scanner
      type(error_t), allocatable :: error
      scanner = text_scanner_from_string('deck', text)
      ok = scanner%next_line()
      call scanner%read_integer(value, error)
      ok = .not. allocated(error)
      if (ok) return
      value = 0
      if (index(error%message, 'out of range') > 0) then
         message = 'integer out of range'
      else
         message = 'expected an integer'
      end if
   end subroutine parse_integer
end module frix_deck_tokens
