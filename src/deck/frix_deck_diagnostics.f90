!> Collects every mistake found in a deck and turns them into one error_t, in the form of
!> compilers and fpm:
!>
!>     <deck path>:<line>:<column>: error: <what> near "<token>"
!>        <source line>
!>        <caret under the column>
!>
!> Mistakes are reported sorted by line (stable: same-line mistakes keep their order); at most
!> `max_reported` are printed, followed by a line saying how many more were found.
module frix_deck_diagnostics
   use frix_error, only: error_t, append_error
   use frix_strings, only: to_string
   use frix_deck_tokens, only: deck_line_t
   implicit none
   private

   public :: deck_diagnostics_t

   integer, parameter :: max_reported = 100
   integer, parameter :: max_stored = 10000  !! beyond this, mistakes are only counted

   type :: diagnostic_t
      integer :: line = 0                     !! deck line, for sorting (huge: after all lines)
      character(len=:), allocatable :: text   !! formatted message, possibly several lines
   end type diagnostic_t

   type :: deck_diagnostics_t
      character(len=:), allocatable :: path   !! deck path as given (prefix of every message)
      type(diagnostic_t), allocatable :: items(:)
      integer :: count = 0
      integer :: n_dropped = 0                !! mistakes beyond max_stored
   contains
      procedure :: at_token
      procedure :: at_end_of_line
      procedure :: at_line
      procedure :: in_deck
      procedure :: has_errors
      procedure :: finish
   end type deck_diagnostics_t

contains

   !> Mistake at token `i` of `line`.
   subroutine at_token(self, line, i, what, note)
      class(deck_diagnostics_t), intent(inout) :: self
      type(deck_line_t), intent(in) :: line
      integer, intent(in) :: i
      character(len=*), intent(in) :: what
      character(len=*), intent(in), optional :: note  !! further lines printed after the caret
      call self%at_line(line, line%first(i), what//' near "'//line%token(i)//'"', note)
   end subroutine at_token

   !> A value is missing at the end of `line` (column just after the last token).
   subroutine at_end_of_line(self, line, what)
      class(deck_diagnostics_t), intent(inout) :: self
      type(deck_line_t), intent(in) :: line
      character(len=*), intent(in) :: what
      integer :: column
      column = 1
      if (line%n_tokens() > 0) column = line%last(line%n_tokens()) + 2
      call self%at_line(line, column, what//' near end of line')
   end subroutine at_end_of_line

   !> Mistake at `column` of `line`, with the source line and a caret.
   subroutine at_line(self, line, column, what, note)
      class(deck_diagnostics_t), intent(inout) :: self
      type(deck_line_t), intent(in) :: line
      integer, intent(in) :: column
      character(len=*), intent(in) :: what
      character(len=*), intent(in), optional :: note  !! further lines printed after the caret
      character(len=:), allocatable :: source, tail
      integer :: i
      source = line%text
      do i = 1, len(source)  ! tabs shown as one blank so that the caret lines up
         if (source(i:i) == achar(9) .or. source(i:i) == achar(13)) source(i:i) = ' '
      end do
      tail = ''
      if (present(note)) tail = new_line('a')//note
      call self%in_deck(line%number, column, what//new_line('a')//'    '//source// &
                        new_line('a')//'    '//repeat(' ', max(column - 1, 0))//'^'//tail)
   end subroutine at_line

   !> Mistake at a line (0: none) and column of the deck, without source echo. Lines after the
   !> first line of `what` are kept as they are (e.g. the mesh reader's own messages).
   subroutine in_deck(self, line_number, column, what)
      class(deck_diagnostics_t), intent(inout) :: self
      integer, intent(in) :: line_number, column
      character(len=*), intent(in) :: what
      type(diagnostic_t), allocatable :: grown(:)
      character(len=:), allocatable :: location
      if (self%count >= max_stored) then
         self%n_dropped = self%n_dropped + 1
         return
      end if
      if (.not. allocated(self%items)) allocate (self%items(16))
      if (self%count == size(self%items)) then
         allocate (grown(2*self%count))
         grown(1:self%count) = self%items
         call move_alloc(grown, self%items)
      end if
      if (line_number > 0) then
         location = self%path//':'//to_string(line_number)//':'//to_string(max(column, 1))//': '
      else
         location = self%path//': '
      end if
      self%count = self%count + 1
      self%items(self%count)%line = line_number
      if (line_number <= 0) self%items(self%count)%line = huge(1)
      self%items(self%count)%text = location//'error: '//what
   end subroutine in_deck

   pure logical function has_errors(self)
      class(deck_diagnostics_t), intent(in) :: self
      has_errors = self%count + self%n_dropped > 0
   end function has_errors

   !> Move the collected mistakes into `error` (left unallocated if there are none).
   subroutine finish(self, error)
      class(deck_diagnostics_t), intent(inout) :: self
      type(error_t), allocatable, intent(inout) :: error
      integer, allocatable :: order(:)
      integer :: i, j, key
      if (self%count == 0) return
      ! stable insertion sort by line (messages are few)
      order = [(i, i=1, self%count)]
      do i = 2, self%count
         key = order(i)
         j = i - 1
         do while (j >= 1)
            if (self%items(order(j))%line <= self%items(key)%line) exit
            order(j + 1) = order(j)
            j = j - 1
         end do
         order(j + 1) = key
      end do
      do i = 1, min(self%count, max_reported)
         call append_error(error, self%items(order(i))%text)
      end do
      if (self%count + self%n_dropped > max_reported) then
         call append_error(error, self%path//': error: '// &
                           to_string(self%count + self%n_dropped - max_reported)//' more errors not shown')
      end if
      call append_error(error, self%path//': '//to_string(self%count + self%n_dropped)// &
                        ' error(s) in the deck')
   end subroutine finish
end module frix_deck_diagnostics
