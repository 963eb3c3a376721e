!> Tests of frix_text_scanner: lines, tokens, numbers, strings and the "file:line:" messages.
module test_text_scanner
   use frix_kinds, only: dp, i8
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close, check_message_contains
   use frix_text_scanner, only: text_scanner_t, text_scanner_from_string, open_text_file
   implicit none
   private

   public :: collect_text_scanner

   character(len=*), parameter :: lf = new_line('a')

contains

   subroutine collect_text_scanner(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('lines_and_tokens', test_lines_and_tokens), &
               new_unittest('integers', test_integers), &
               new_unittest('reals', test_reals), &
               new_unittest('bad_number_names_file_and_line', test_bad_number), &
               new_unittest('quoted_strings', test_quoted_strings), &
               new_unittest('caret_message', test_caret_message), &
               new_unittest('missing_file', test_missing_file)]
   end subroutine collect_text_scanner

   subroutine test_lines_and_tokens(error)
      type(error_t), allocatable, intent(out) :: error
      type(text_scanner_t) :: scanner
      character(len=:), allocatable :: token
      logical :: found
      ! CRLF line end, a tab, a blank line, no final line feed
      scanner = text_scanner_from_string('t.txt', 'alpha  beta'//achar(13)//lf//achar(9)//'gamma'//lf//lf//'delta')
      call check(error, scanner%n_lines == 4, 'four lines')
      if (allocated(error)) return
      call check(error, scanner%next_line(), 'first line')
      if (allocated(error)) return
      call scanner%next_token(token, found)
      call check(error, found .and. token == 'alpha', 'token alpha, got "'//token//'"')
      if (allocated(error)) return
      call check(error, scanner%peek_token() == 'beta', 'peek beta')
      if (allocated(error)) return
      call scanner%next_token(token, found)
      call check(error, found .and. token == 'beta', 'token beta without the carriage return, got "'//token//'"')
      if (allocated(error)) return
      call check(error, scanner%at_end_of_line(), 'end of line 1')
      if (allocated(error)) return
      call scanner%next_token(token, found)
      call check(error, .not. found, 'no third token')
      if (allocated(error)) return
      call check(error, scanner%next_line(), 'second line')
      if (allocated(error)) return
      call scanner%next_token(token, found)
      call check(error, token == 'gamma' .and. scanner%token_column == 2, 'gamma at column 2')
      if (allocated(error)) return
      call check(error, scanner%next_line(), 'third line')
      if (allocated(error)) return
      call check(error, scanner%is_blank_line(), 'blank third line')
      if (allocated(error)) return
      call check(error, scanner%next_line(), 'fourth line')
      if (allocated(error)) return
      call check(error, scanner%line() == 'delta', 'fourth line "delta"')
      if (allocated(error)) return
      call check(error, scanner%line_number == 4 .and. scanner%remaining_lines() == 0, 'line 4, none left')
      if (allocated(error)) return
      call check(error, .not. scanner%next_line(), 'no fifth line')
   end subroutine test_lines_and_tokens

   subroutine test_integers(error)
      type(error_t), allocatable, intent(out) :: error
      type(text_scanner_t) :: scanner
      type(error_t), allocatable :: scan_error
      integer :: value
      integer(i8) :: wide
      logical :: found
      scanner = text_scanner_from_string('t.txt', '17 -4 +9 2147483647 2147483648 12345678901234 1.5')
      found = scanner%next_line()
      call scanner%read_integer(value, error)
      if (allocated(error)) return
      call check(error, value == 17, '17')
      if (allocated(error)) return
      call scanner%read_integer(value, error)
      if (allocated(error)) return
      call check(error, value == -4, '-4')
      if (allocated(error)) return
      call scanner%read_integer(value, error)
      if (allocated(error)) return
      call check(error, value == 9, '+9')
      if (allocated(error)) return
      call scanner%read_integer(value, error)
      if (allocated(error)) return
      call check(error, value == huge(value), 'largest default integer')
      if (allocated(error)) return
      call scanner%read_integer(value, scan_error)
      call check_message_contains(error, scan_error, 't.txt:1: integer out of range, got "2147483648"')
      if (allocated(error)) return
      call scanner%read_integer_i8(wide, error)
      if (allocated(error)) return
      call check(error, wide == 12345678901234_i8, '64-bit integer')
      if (allocated(error)) return
      call scanner%read_integer(value, scan_error)
      call check_message_contains(error, scan_error, 't.txt:1: expected an integer, got "1.5"')
      if (allocated(error)) return
      call scanner%read_integer(value, scan_error)
      call check_message_contains(error, scan_error, 'expected an integer, got end of line')
   end subroutine test_integers

   subroutine test_reals(error)
      type(error_t), allocatable, intent(out) :: error
      type(text_scanner_t) :: scanner
      type(error_t), allocatable :: scan_error
      real(dp) :: values(6)
      ! expected values are the decimal literals themselves
      real(dp), parameter :: expected(6) = [1.0_dp, -2.5_dp, 1.0e-3_dp, -250.0_dp, 0.1_dp, 6.02214076e23_dp]
      integer :: k
      logical :: found
      scanner = text_scanner_from_string('t.txt', '1 -2.5 1e-3 -2.5D+2 .1 6.02214076E+23 Infinity NaN e 1.0.0')
      found = scanner%next_line()
      do k = 1, 6
         call scanner%read_real(values(k), error)
         if (allocated(error)) return
         ! the text is the exact decimal: the reader must give the correctly rounded double
         call check_close(error, values(k), expected(k), 0.0_dp, 0.0_dp, 'real number '//achar(48 + k))
         if (allocated(error)) return
      end do
      call scanner%read_real(values(1), scan_error)
      call check_message_contains(error, scan_error, 'expected a number, got "Infinity"')
      if (allocated(error)) return
      call scanner%read_real(values(1), scan_error)
      call check_message_contains(error, scan_error, 'expected a number, got "NaN"')
      if (allocated(error)) return
      call scanner%read_real(values(1), scan_error)
      call check_message_contains(error, scan_error, 'expected a number, got "e"')
      if (allocated(error)) return
      call scanner%read_real(values(1), scan_error)
      call check_message_contains(error, scan_error, 'expected a number, got "1.0.0"')
   end subroutine test_reals

   subroutine test_bad_number(error)
      type(error_t), allocatable, intent(out) :: error
      type(text_scanner_t) :: scanner
      type(error_t), allocatable :: scan_error
      real(dp) :: value
      integer :: skipped
      logical :: found
      scanner = text_scanner_from_string('mesh.msh', '1 0 0 0'//lf//'2 1 abc 0')
      found = scanner%next_line()
      found = scanner%next_line()
      call scanner%skip_tokens(2, skipped)
      call scanner%read_real(value, scan_error)
      call check_message_contains(error, scan_error, 'mesh.msh:2: expected a number, got "abc"')
   end subroutine test_bad_number

   subroutine test_quoted_strings(error)
      type(error_t), allocatable, intent(out) :: error
      type(text_scanner_t) :: scanner
      type(error_t), allocatable :: scan_error
      character(len=:), allocatable :: text
      integer :: skipped
      logical :: found
      scanner = text_scanner_from_string('t.txt', '2 7 "upper face" bare "unterminated')
      found = scanner%next_line()
      call scanner%skip_tokens(2, skipped)
      call scanner%read_string(text, error)
      if (allocated(error)) return
      call check(error, text == 'upper face', 'quoted string with a blank, got "'//text//'"')
      if (allocated(error)) return
      call scanner%read_string(text, error)
      if (allocated(error)) return
      call check(error, text == 'bare', 'bare word')
      if (allocated(error)) return
      call scanner%read_string(text, scan_error)
      call check_message_contains(error, scan_error, 't.txt:1:23: missing closing quote')
   end subroutine test_quoted_strings

   subroutine test_caret_message(error)
      type(error_t), allocatable, intent(out) :: error
      type(text_scanner_t) :: scanner
      type(error_t), allocatable :: scan_error
      character(len=:), allocatable :: token
      logical :: found
      scanner = text_scanner_from_string('deck.dat', 'MAT 1 YOUNG 1e5'//lf//'NUMSTEP  x3')
      found = scanner%next_line()
      found = scanner%next_line()
      call scanner%next_token(token, found)
      call scanner%next_token(token, found)
      call scanner%fail_at_token(scan_error, 'expected an integer')
      ! column 10 is where "x3" starts; the caret line has 3 blanks of indent + 9 before "^"
      call check_message_contains(error, scan_error, 'deck.dat:2:10: expected an integer'//lf// &
                                  '   NUMSTEP  x3'//lf//'            ^')
      if (allocated(error)) return
      call scanner%expect_end_of_line(scan_error)
      call check(error, .not. allocated(scan_error), 'end of line after the last token')
   end subroutine test_caret_message

   subroutine test_missing_file(error)
      type(error_t), allocatable, intent(out) :: error
      type(text_scanner_t) :: scanner
      type(error_t), allocatable :: open_error
      call open_text_file('no/such/file.msh', scanner, open_error)
      call check_message_contains(error, open_error, 'no/such/file.msh: cannot open file')
   end subroutine test_missing_file
end module test_text_scanner
