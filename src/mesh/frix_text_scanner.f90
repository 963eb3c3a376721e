!> A line-and-token scanner for plain-text input (gmsh msh files, input decks).
!>
!> The whole file is read into memory once (stream access), then walked line by line; tokens
!> are separated by blanks (space, tab; a trailing carriage return of CRLF files is dropped),
!> and by commas too where `commas_separate` is set (Abaqus/CalculiX .inp data lines).
!> Numbers are parsed from the token text with `iostat` checks, so malformed input never
!> raises a Fortran runtime error: every failure becomes an `error_t` whose message starts
!> with `file:line:` (or `file:line:col:` for `fail_at_token`), e.g.
!> `mesh.msh:17: expected a number, got "abc"`.
!> Line numbers and columns are 1-based.
module frix_text_scanner
   use frix_kinds, only: dp, i8
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private

   public :: text_scanner_t, open_text_file, text_scanner_from_string

   character(len=*), parameter :: tab = achar(9), carriage_return = achar(13), line_feed = achar(10)

   !> Scanner over the lines of one text. Call `next_line` before reading the first line.
   type :: text_scanner_t
      character(len=:), allocatable :: file_name   !! name used in messages (the path as given)
      integer :: line_number = 0                   !! current line, 0 before the first
      integer :: n_lines = 0                       !! number of lines of the text
      integer :: token_column = 0                  !! column of the last token scanned (0: none)
      logical :: commas_separate = .false.         !! commas separate tokens as blanks do
      character(len=:), allocatable, private :: text
      integer, private :: next_start = 1           !! start of the next line in `text`
      integer, private :: line_first = 1           !! current line is text(line_first:line_last)
      integer, private :: line_last = 0
      integer, private :: cursor = 1               !! next character of the current line to scan
   contains
      procedure :: next_line
      procedure :: line
      procedure :: rewind_line
      procedure :: is_blank_line
      procedure :: at_end_of_line
      procedure :: remaining_lines
      procedure :: next_token
      procedure :: peek_token
      procedure :: skip_tokens
      procedure :: read_integer
      procedure :: read_integer_i8
      procedure :: read_real
      procedure :: read_string
      procedure :: expect_end_of_line
      procedure :: location
      procedure :: fail
      procedure :: fail_at_token
   end type text_scanner_t

contains

   !> Read the file at `path` into a new scanner. Errors: file missing or unreadable.
   subroutine open_text_file(path, scanner, error)
      character(len=*), intent(in) :: path
      type(text_scanner_t), intent(out) :: scanner
      type(error_t), allocatable, intent(out) :: error
      integer :: unit, status
      integer(i8) :: file_size
      character(len=256) :: message
      open (newunit=unit, file=path, access='stream', form='unformatted', action='read', &
            status='old', iostat=status, iomsg=message)
      if (status /= 0) then
         call fatal_error(error, path//': cannot open file: '//trim(message))
         return
      end if
      inquire (unit=unit, size=file_size)
      if (file_size < 0 .or. file_size > int(huge(1), i8)) then
         call fatal_error(error, path//': cannot determine the size of the file (or larger than 2 GiB)')
         close (unit)
         return
      end if
      allocate (character(len=int(file_size)) :: scanner%text)
      if (file_size > 0) then
         read (unit, iostat=status, iomsg=message) scanner%text
         if (status /= 0) then
            call fatal_error(error, path//': cannot read file: '//trim(message))
            close (unit)
            return
         end if
      end if
      close (unit)
      scanner%file_name = path
      call initialise(scanner)
   end subroutine open_text_file

   !> A scanner over `text` (lines separated by line feeds); `name` is used in messages.
   function text_scanner_from_string(name, text) result(scanner)
      character(len=*), intent(in) :: name, text
      type(text_scanner_t) :: scanner
      scanner%file_name = name
      scanner%text = text
      call initialise(scanner)
   end function text_scanner_from_string

   subroutine initialise(scanner)
      type(text_scanner_t), intent(inout) :: scanner
      integer :: i, n
      n = len(scanner%text)
      scanner%n_lines = 0
      do i = 1, n
         if (scanner%text(i:i) == line_feed) scanner%n_lines = scanner%n_lines + 1
      end do
      if (n > 0) then
         if (scanner%text(n:n) /= line_feed) scanner%n_lines = scanner%n_lines + 1
      end if
      scanner%line_number = 0
      scanner%next_start = 1
      scanner%line_first = 1
      scanner%line_last = 0
      scanner%cursor = 1
      scanner%token_column = 0
   end subroutine initialise

   !> Advance to the next line; `.false.` (and no change) at the end of the text.
   logical function next_line(self) result(found)
      class(text_scanner_t), intent(inout) :: self
      integer :: end_of_line
      found = self%next_start <= len(self%text)
      if (.not. found) return
      end_of_line = index(self%text(self%next_start:), line_feed)
      if (end_of_line == 0) then
         end_of_line = len(self%text) + 1
      else
         end_of_line = self%next_start + end_of_line - 1
      end if
      self%line_first = self%next_start
      self%line_last = end_of_line - 1
      if (self%line_last >= self%line_first) then
         if (self%text(self%line_last:self%line_last) == carriage_return) self%line_last = self%line_last - 1
      end if
      self%next_start = end_of_line + 1
      self%cursor = self%line_first
      self%line_number = self%line_number + 1
      self%token_column = 0
   end function next_line

   !> The current line (without its line end).
   function line(self) result(text)
      class(text_scanner_t), intent(in) :: self
      character(len=:), allocatable :: text
      text = self%text(self%line_first:self%line_last)
   end function line

   !> Restart token scanning at the beginning of the current line.
   subroutine rewind_line(self)
      class(text_scanner_t), intent(inout) :: self
      self%cursor = self%line_first
      self%token_column = 0
   end subroutine rewind_line

   !> True if the current line holds only blanks.
   logical function is_blank_line(self)
      class(text_scanner_t), intent(in) :: self
      is_blank_line = len_trim(blanks_to_spaces(self%text(self%line_first:self%line_last))) == 0
   end function is_blank_line

   !> True if no token remains on the current line.
   logical function at_end_of_line(self)
      class(text_scanner_t), intent(in) :: self
      integer :: position
      position = self%cursor
      do while (position <= self%line_last)
         if (.not. is_separator(self%text(position:position), self%commas_separate)) exit
         position = position + 1
      end do
      at_end_of_line = position > self%line_last
   end function at_end_of_line

   !> Number of lines after the current one.
   pure integer function remaining_lines(self)
      class(text_scanner_t), intent(in) :: self
      remaining_lines = self%n_lines - self%line_number
   end function remaining_lines

   !> Next blank-separated token of the current line; `found` is false at the end of the line.
   subroutine next_token(self, token, found)
      class(text_scanner_t), intent(inout) :: self
      character(len=:), allocatable, intent(out) :: token
      logical, intent(out) :: found
      integer :: first, last
      call scan_token(self, first, last)
      found = last >= first
      if (found) then
         token = self%text(first:last)
      else
         token = ''
      end if
   end subroutine next_token

   !> The next token without consuming it ('' at the end of the line).
   function peek_token(self) result(token)
      class(text_scanner_t), intent(in) :: self
      character(len=:), allocatable :: token
      integer :: cursor, first, last
      cursor = self%cursor
      call scan_positions(self%text, cursor, self%line_last, self%commas_separate, first, last)
      token = self%text(first:last)
   end function peek_token

   !> Skip `count` tokens (fewer if the line ends first; `skipped` tells how many).
   subroutine skip_tokens(self, count, skipped)
      class(text_scanner_t), intent(inout) :: self
      integer, intent(in) :: count
      integer, intent(out) :: skipped
      integer :: first, last
      skipped = 0
      do while (skipped < count)
         call scan_token(self, first, last)
         if (last < first) return
         skipped = skipped + 1
      end do
   end subroutine skip_tokens

   !> Read the next token as a default integer (optional sign, decimal digits).
   subroutine read_integer(self, value, error)
      class(text_scanner_t), intent(inout) :: self
      integer, intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      integer(i8) :: wide
      call read_integer_i8(self, wide, error)
      value = 0
      if (allocated(error)) return
      if (wide > huge(value) .or. wide < -huge(value)) then
         call self%fail(error, 'integer out of range, got "'//to_string(wide)//'"')
         return
      end if
      value = int(wide)
   end subroutine read_integer

   !> Read the next token as a 64-bit integer (optional sign, decimal digits).
   subroutine read_integer_i8(self, value, error)
      class(text_scanner_t), intent(inout) :: self
      integer(i8), intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      integer :: first, last, position, digit, start
      logical :: negative
      value = 0
      call scan_token(self, first, last)
      if (last < first) then
         call self%fail(error, 'expected an integer, got end of line')
         return
      end if
      negative = .false.
      start = first
      if (self%text(first:first) == '-' .or. self%text(first:first) == '+') then
         negative = self%text(first:first) == '-'
         start = first + 1
      end if
      if (start > last) then
         call self%fail(error, 'expected an integer, got "'//self%text(first:last)//'"')
         return
      end if
      do position = start, last
         digit = iachar(self%text(position:position)) - iachar('0')
         if (digit < 0 .or. digit > 9) then
            call self%fail(error, 'expected an integer, got "'//self%text(first:last)//'"')
            return
         end if
         if (value > (huge(value) - digit)/10) then
            call self%fail(error, 'integer out of range, got "'//self%text(first:last)//'"')
            return
         end if
         value = 10*value + digit
      end do
      if (negative) value = -value
   end subroutine read_integer_i8

   !> Read the next token as a finite real (Fortran or C notation: 1, -2.5, 1e-3, 1.5D+2).
   subroutine read_real(self, value, error)
      class(text_scanner_t), intent(inout) :: self
      real(dp), intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: width = 64
      character(len=width) :: buffer
      integer :: first, last, status
      value = 0
      call scan_token(self, first, last)
      if (last < first) then
         call self%fail(error, 'expected a number, got end of line')
         return
      end if
      ! The F edit descriptor alone would accept words such as "Infinity" and "NaN", and a
      ! lone "e": allow only the characters of a decimal number, and require a digit.
      if (last - first + 1 > width .or. &
          verify(self%text(first:last), '0123456789+-.eEdD') /= 0 .or. &
          scan(self%text(first:last), '0123456789') == 0) then
         call self%fail(error, 'expected a number, got "'//self%text(first:last)//'"')
         return
      end if
      buffer = self%text(first:last)
      call read_decimal(buffer, value, status)
      if (status /= 0) then
         value = 0
         call self%fail(error, 'expected a number, got "'//self%text(first:last)//'"')
         return
      end if
      if (.not. ieee_is_finite(value)) then
         value = 0
         call self%fail(error, 'number out of range, got "'//self%text(first:last)//'"')
      end if
   end subroutine read_real

   !> `value` from the decimal number in `buffer` (F edit descriptor), with the floating-point
   !> traps off: a number beyond the range of real(dp) (1e400) overflows inside the C library's
   !> conversion, which must give infinity (rejected by the caller) in every build, also in
   !> one that traps overflow (scripts/check.sh sanitize). The flags raised are cleared; the
   !> halting mode is restored on return (Fortran 2008, 14.5: by the compiler).
   subroutine read_decimal(buffer, value, status)
      use, intrinsic :: ieee_exceptions, only: ieee_set_halting_mode, ieee_set_flag, ieee_usual
      character(len=*), intent(in) :: buffer
      real(dp), intent(out) :: value
      integer, intent(out) :: status
      call ieee_set_halting_mode(ieee_usual, .false.)
      read (buffer, '(f64.0)', iostat=status) value
      call ieee_set_flag(ieee_usual, .false.)
   end subroutine read_decimal

   !> Read a string: a double-quoted text (may hold blanks; quotes removed) or a bare token.
   subroutine read_string(self, value, error)
      class(text_scanner_t), intent(inout) :: self
      character(len=:), allocatable, intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      integer :: first, last, closing
      call scan_positions(self%text, self%cursor, self%line_last, self%commas_separate, first, last)
      if (last < first) then
         value = ''
         call self%fail(error, 'expected a string, got end of line')
         return
      end if
      self%token_column = first - self%line_first + 1
      if (self%text(first:first) /= '"') then
         value = self%text(first:last)
         self%cursor = last + 1
         return
      end if
      closing = index(self%text(first + 1:self%line_last), '"')
      if (closing == 0) then
         value = ''
         call self%fail_at_token(error, 'missing closing quote')
         return
      end if
      closing = first + closing
      value = self%text(first + 1:closing - 1)
      self%cursor = closing + 1
   end subroutine read_string

   !> Error unless nothing but blanks remains on the current line.
   subroutine expect_end_of_line(self, error)
      class(text_scanner_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      integer :: first, last
      call scan_token(self, first, last)
      if (last >= first) call self%fail(error, 'expected end of line, got "'//self%text(first:last)//'"')
   end subroutine expect_end_of_line

   !> "file:line" of the current line.
   function location(self) result(text)
      class(text_scanner_t), intent(in) :: self
      character(len=:), allocatable :: text
      text = self%file_name//':'//to_string(self%line_number)
   end function location

   !> Error "file:line: message".
   subroutine fail(self, error, message)
      class(text_scanner_t), intent(in) :: self
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: message
      call fatal_error(error, self%location()//': '//message)
   end subroutine fail

   !> Error "file:line:col: message", then the line and a caret under the last token
   !> (the form of fpm's parse errors).
   subroutine fail_at_token(self, error, message)
      class(text_scanner_t), intent(in) :: self
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: message
      integer :: column
      column = max(1, self%token_column)
      call fatal_error(error, self%location()//':'//to_string(column)//': '//message//line_feed// &
                       '   '//blanks_to_spaces(self%line())//line_feed// &
                       '   '//repeat(' ', column - 1)//'^')
   end subroutine fail_at_token

   ! ---- private helpers -------------------------------------------------------------------

   subroutine scan_token(self, first, last)
      type(text_scanner_t), intent(inout) :: self
      integer, intent(out) :: first, last
      call scan_positions(self%text, self%cursor, self%line_last, self%commas_separate, first, last)
      if (last >= first) self%token_column = first - self%line_first + 1
   end subroutine scan_token

   !> Token text(first:last) starting at `cursor` (advanced past it); last < first if none.
   pure subroutine scan_positions(text, cursor, line_last, commas_separate, first, last)
      character(len=*), intent(in) :: text
      integer, intent(inout) :: cursor
      integer, intent(in) :: line_last
      logical, intent(in) :: commas_separate
      integer, intent(out) :: first, last
      do while (cursor <= line_last)
         if (.not. is_separator(text(cursor:cursor), commas_separate)) exit
         cursor = cursor + 1
      end do
      first = cursor
      do while (cursor <= line_last)
         if (is_separator(text(cursor:cursor), commas_separate)) exit
         cursor = cursor + 1
      end do
      last = cursor - 1
   end subroutine scan_positions

   elemental logical function is_separator(character, commas_separate)
      character(len=1), intent(in) :: character
      logical, intent(in) :: commas_separate
      is_separator = is_blank(character) .or. (commas_separate .and. character == ',')
   end function is_separator

   elemental logical function is_blank(character)
      character(len=1), intent(in) :: character
      is_blank = character == ' ' .or. character == tab .or. character == carriage_return
   end function is_blank

   pure function blanks_to_spaces(text) result(spaced)
      character(len=*), intent(in) :: text
      character(len=len(text)) :: spaced
      integer :: i
      spaced = text
      do i = 1, len(text)
         if (is_blank(text(i:i))) spaced(i:i) = ' '
      end do
   end function blanks_to_spaces
end module frix_text_scanner
