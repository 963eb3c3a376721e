!> Error handling in the style of fpm: a fallible procedure ends with
!> `type(error_t), allocatable, intent(out) :: error`; callers write
!> `if (allocated(error)) return`; only the program's main prints and stops.
module frix_error
   implicit none
   private

   public :: error_t, fatal_error, append_error

   !> An error travelling up to the program's main. `message` may hold several lines
   !> (the deck reader reports every mistake of a deck at once).
   type :: error_t
      character(len=:), allocatable :: message
   end type error_t

contains

   !> Allocate `error` with `message`.
   pure subroutine fatal_error(error, message)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: message
      allocate (error)
      error%message = message
   end subroutine fatal_error

   !> Add a line to `error`, allocating it if it is not yet allocated.
   pure subroutine append_error(error, message)
      type(error_t), allocatable, intent(inout) :: error
      character(len=*), intent(in) :: message
      if (.not. allocated(error)) then
         allocate (error)
         error%message = message
      else
         error%message = error%message//new_line('a')//message
      end if
   end subroutine append_error
end module frix_error
