!> Process control for the program's main only.
module frix_process
   use, intrinsic :: iso_c_binding, only: c_int
   implicit none
   private

   public :: exit_with_status, keep_freed_memory

   interface
      subroutine frix_exit_c(status) bind(C, name='frix_exit_c')
         import :: c_int
         integer(c_int), value :: status
      end subroutine frix_exit_c

      subroutine frix_keep_freed_memory_c() bind(C, name='frix_keep_freed_memory_c')
      end subroutine frix_keep_freed_memory_c
   end interface

contains

   !> Keep freed heap memory in the process for reuse instead of returning it to the system
   !> (frix_heap.c): the numeric factorization of every Newton iteration then reuses the pages
   !> of the previous one. Call once, at the start of the program.
   subroutine keep_freed_memory()
      call frix_keep_freed_memory_c()
   end subroutine keep_freed_memory

   !> End the program with exit status `status` (0 success, 1 failed run, 2 usage error, 3 stopped
   !> by a signal).
   subroutine exit_with_status(status)
      integer, intent(in) :: status
      flush (0)
      flush (6)
      call frix_exit_c(int(status, c_int))
   end subroutine exit_with_status
end module frix_process
