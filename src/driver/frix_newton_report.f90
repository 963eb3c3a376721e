!> What the Newton iterations of one increment report (frix_newton_solver): convergence, the
!> per-iteration norms the listing and the progress lines show, the reason of a failure.
module frix_newton_report
   use frix_kinds, only: dp
   use frix_strings, only: to_string, padded
   implicit none
   private

   public :: newton_report_t, reserve_iteration_log, print_progress, norm_text

   !> What happened in one increment.
   type :: newton_report_t
      logical :: converged = .false.
      !> converged on both criteria (or the zero-residual rule), not on the residual alone
      !> (frix_newton_solver's residual_only)
      logical :: fully_converged = .false.
      integer :: iterations = 0
      !> per residual evaluation 0 .. max_iterations (0: before the first solve)
      real(dp), allocatable :: residual_norms(:)   !! ||r||
      real(dp), allocatable :: relative_norms(:)   !! ||r|| / reference
      real(dp), allocatable :: energy_norms(:)     !! |du . r| of the correction leading there
      integer, allocatable :: active(:)            !! contact: slave nodes in contact
      integer, allocatable :: slipping(:)          !! contact: slave nodes slipping
      character(len=:), allocatable :: failure     !! why it did not converge
      logical :: interrupted = .false.             !! stopped by SIGINT/SIGTERM (frix_stop_request)
   end type newton_report_t

contains

   !> Make the report's per-iteration log hold iterations 0 .. last, keeping what it holds
   !> (grown as the iterations go: MAXITER may be any positive integer).
   subroutine reserve_iteration_log(report, last)
      type(newton_report_t), intent(inout) :: report
      integer, intent(in) :: last
      call grow_real(report%residual_norms)
      call grow_real(report%relative_norms)
      call grow_real(report%energy_norms)
      call grow_integer(report%active)
      call grow_integer(report%slipping)
   contains
      subroutine grow_real(values)
         real(dp), allocatable, intent(inout) :: values(:)
         real(dp), allocatable :: grown(:)
         allocate (grown(0:last), source=0.0_dp)
         if (allocated(values)) grown(0:ubound(values, 1)) = values
         call move_alloc(grown, values)
      end subroutine grow_real
      subroutine grow_integer(values)
         integer, allocatable, intent(inout) :: values(:)
         integer, allocatable :: grown(:)
         allocate (grown(0:last), source=0)
         if (allocated(values)) grown(0:ubound(values, 1)) = values
         call move_alloc(grown, values)
      end subroutine grow_integer
   end subroutine reserve_iteration_log

   subroutine print_progress(label, time, iteration, residual_norm, relative_norm, energy, &
                             contact, active, slipping)
      character(len=*), intent(in) :: label
      real(dp), intent(in) :: time, residual_norm, relative_norm, energy
      integer, intent(in) :: iteration, active, slipping
      logical, intent(in) :: contact
      if (contact) then
         write (*, '(2x,a,"  t=",es12.5,a,"  |r|=",a,"  |r|/ref=",a,'// &
                '"  energy=",a,a)') label, time, '  iter'//padded(to_string(iteration), 3), norm_text(residual_norm), &
            norm_text(relative_norm), norm_text(energy), &
            '  contact'//padded(to_string(active), 6)//'  slip'//padded(to_string(slipping), 6)
      else
         write (*, '(2x,a,"  t=",es12.5,a,"  |r|=",a,"  |r|/ref=",a,'// &
                '"  energy=",a)') label, time, '  iter'//padded(to_string(iteration), 3), norm_text(residual_norm), &
            norm_text(relative_norm), norm_text(energy)
      end if
      flush (6)
   end subroutine print_progress

   !> A norm in 10 characters, es10.3 (" 1.234E-05"), or es10.3e3 ("1.234E+120") when the
   !> exponent has three digits (es10.3 would drop the letter E: "1.234+120").
   function norm_text(value) result(text)
      real(dp), intent(in) :: value
      character(len=10) :: text
      if (value == 0.0_dp .or. (abs(value) < 1.0e99_dp .and. abs(value) >= 1.0e-99_dp)) then
         write (text, '(es10.3)') value
      else
         write (text, '(es10.3e3)') value
      end if
   end function norm_text
end module frix_newton_report
