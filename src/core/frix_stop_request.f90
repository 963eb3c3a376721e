!> A request to stop the run, made by SIGINT (Ctrl-C) or SIGTERM (frix_stop_signals.c). The
!> program's main installs the handlers; the analysis polls `stop_requested` between Newton
!> iterations and increments and ends the run there, with its converged increments written.
module frix_stop_request
   use, intrinsic :: iso_c_binding, only: c_int
   implicit none
   private

   public :: install_stop_handlers, stop_requested, stop_signal_name

   interface
      subroutine frix_install_stop_handlers_c() bind(C, name='frix_install_stop_handlers_c')
      end subroutine frix_install_stop_handlers_c

      function frix_stop_signal_c() bind(C, name='frix_stop_signal_c') result(signal_number)
         import :: c_int
         integer(c_int) :: signal_number
      end function frix_stop_signal_c
   end interface

contains

   !> Let SIGINT and SIGTERM request a stop instead of killing the process (a second one kills).
   subroutine install_stop_handlers()
      call frix_install_stop_handlers_c()
   end subroutine install_stop_handlers

   !> Whether SIGINT or SIGTERM has been received.
   logical function stop_requested()
      stop_requested = frix_stop_signal_c() /= 0
   end function stop_requested

   !> 'SIGINT' or 'SIGTERM' (POSIX numbers 2 and 15), '' before any.
   function stop_signal_name() result(name)
      character(len=:), allocatable :: name
      select case (frix_stop_signal_c())
      case (0)
         name = ''
      case (2)
         name = 'SIGINT'
      case (15)
         name = 'SIGTERM'
      case default
         name = 'signal'
      end select
   end function stop_signal_name
end module frix_stop_request
