!> Process control for the program's main only.
module frix_process
   use, intrinsic :: iso_c_binding, only: c_int
   implicit none
   private

   public :: exit_with_status

   interface
      subroutine frix_exit_c(status) bind(C, name='frix_exit_c')
         import :: c_int
         integer(c_int), value :: status
      end subroutine frix_exit_c
   end interface

contains

   !> End the program with exit status `status` (0 success, 1 failed run, 2 usage error).
   subroutine exit_with_status(status)
      integer, intent(in) :: status
      flush (0)
      flush (6)
      call frix_exit_c(int(status, c_int))
   end subroutine exit_with_status
end module frix_process
