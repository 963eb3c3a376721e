!> One keyword line of an Abaqus/CalculiX .inp file, e.g. `*ELEMENT, TYPE=C3D8, ELSET=Pipe`:
!> the keyword and its parameters (Abaqus Keywords Reference, "Input syntax rules": fields
!> separated by commas, blanks ignored, keywords and parameter names case-insensitive,
!> a parameter either `NAME` or `NAME=value`). The keyword and the parameter names are kept in
!> upper case; the values as written (set names keep their spelling). Each field keeps its
!> column, so that a message can point at it (`file:line:col:` and a caret).
module frix_inp_keyword
   use frix_error, only: error_t
   use frix_strings, only: to_upper
   use frix_text_scanner, only: text_scanner_t
   implicit none
   private

   public :: inp_keyword_t, read_keyword_line

   type :: text_t
      character(len=:), allocatable :: text
   end type text_t

   type :: inp_keyword_t
      character(len=:), allocatable :: name      !! upper case, without the star, e.g. ELEMENT
      type(text_t), allocatable :: names(:)      !! parameter names, upper case
      type(text_t), allocatable :: values(:)     !! parameter values as written ('' if none)
      integer, allocatable :: columns(:)         !! column of each parameter on the line
   contains
      procedure :: has
      procedure :: value_of
      procedure :: column_of
      procedure :: check_parameters
   end type inp_keyword_t

contains

   !> Parse the scanner's current line, a keyword line (first non-blank character `*`, not `**`).
   subroutine read_keyword_line(scanner, keyword, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(inp_keyword_t), intent(out) :: keyword
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: line, field
      integer :: first, last, n_fields, equals
      line = scanner%line()
      allocate (keyword%names(0), keyword%values(0), keyword%columns(0))
      first = index(line, '*') + 1
      n_fields = 0
      do while (first <= len(line) + 1)
         last = index(line(first:), ',')
         if (last == 0) then
            last = len(line)
         else
            last = first + last - 2
         end if
         field = without_blanks(line(first:last))
         n_fields = n_fields + 1
         if (n_fields == 1) then
            keyword%name = to_upper(field)
            if (len(field) == 0) then
               scanner%token_column = first
               call scanner%fail_at_token(error, 'a keyword line without a keyword')
               return
            end if
         else if (len(field) > 0) then
            equals = index(field, '=')
            if (equals == 0) then
               call append(keyword, to_upper(field), '', first)
            else
               call append(keyword, to_upper(field(1:equals - 1)), field(equals + 1:), first)
            end if
         end if
         first = last + 2
      end do
   end subroutine read_keyword_line

   !> True if the parameter `name` (upper case) is given.
   logical function has(self, name)
      class(inp_keyword_t), intent(in) :: self
      character(len=*), intent(in) :: name
      has = self%column_of(name) > 0
   end function has

   !> The value of parameter `name` (upper case), '' if it is not given or has none.
   function value_of(self, name) result(value)
      class(inp_keyword_t), intent(in) :: self
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: value
      integer :: k
      value = ''
      do k = 1, size(self%names)
         if (self%names(k)%text == name) then
            value = self%values(k)%text
            return
         end if
      end do
   end function value_of

   !> Column of parameter `name` on the line, 0 if it is not given.
   integer function column_of(self, name) result(column)
      class(inp_keyword_t), intent(in) :: self
      character(len=*), intent(in) :: name
      integer :: k
      column = 0
      do k = 1, size(self%names)
         if (self%names(k)%text == name) then
            column = self%columns(k)
            return
         end if
      end do
   end function column_of

   !> Error at the first parameter not among `allowed` (upper-case names separated by blanks,
   !> each with `=` if it takes a value), or given twice, or with a value where it takes none
   !> (or none where it takes one).
   subroutine check_parameters(self, scanner, allowed, error)
      class(inp_keyword_t), intent(in) :: self
      type(text_scanner_t), intent(inout) :: scanner
      character(len=*), intent(in) :: allowed
      type(error_t), allocatable, intent(out) :: error
      integer :: k
      logical :: takes_value, known
      do k = 1, size(self%names)
         scanner%token_column = self%columns(k)
         known = index(' '//allowed//' ', ' '//self%names(k)%text//' ') > 0
         takes_value = index(' '//allowed//' ', ' '//self%names(k)%text//'= ') > 0
         if (.not. (known .or. takes_value)) then
            call scanner%fail_at_token(error, 'parameter '//self%names(k)%text//' of *'//self%name// &
                                       ' is not supported (supported: '//allowed//')')
         else if (self%column_of(self%names(k)%text) /= self%columns(k)) then
            call scanner%fail_at_token(error, 'parameter '//self%names(k)%text//' given twice')
         else if (takes_value .and. len(self%values(k)%text) == 0) then
            call scanner%fail_at_token(error, 'parameter '//self%names(k)%text//' needs a value ('// &
                                       self%names(k)%text//'=...)')
         else if (.not. takes_value .and. len(self%values(k)%text) > 0) then
            call scanner%fail_at_token(error, 'parameter '//self%names(k)%text//' takes no value')
         end if
         if (allocated(error)) return
      end do
   end subroutine check_parameters

   subroutine append(keyword, name, value, column)
      type(inp_keyword_t), intent(inout) :: keyword
      character(len=*), intent(in) :: name, value
      integer, intent(in) :: column
      type(text_t), allocatable :: names(:), values(:)
      integer :: n
      n = size(keyword%names)
      allocate (names(n + 1), values(n + 1))
      names(1:n) = keyword%names
      values(1:n) = keyword%values
      names(n + 1)%text = name
      values(n + 1)%text = value
      call move_alloc(names, keyword%names)
      call move_alloc(values, keyword%values)
      keyword%columns = [keyword%columns, column]
   end subroutine append

   pure function without_blanks(text) result(squeezed)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: squeezed
      integer :: i
      squeezed = ''
      do i = 1, len(text)
         if (text(i:i) /= ' ' .and. text(i:i) /= achar(9) .and. text(i:i) /= achar(13)) squeezed = squeezed//text(i:i)
      end do
   end function without_blanks
end module frix_inp_keyword
