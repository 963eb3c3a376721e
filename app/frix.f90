!> frix: runs a CARAT-style input deck.
!>   frix DECK [--out DIR] [--check] [--quiet] [--restart FILE.h5 --from STEP.INCREMENT]
!>   frix --version   (version, compiler and libraries; exit status 0)
!> Exit status 0 on success, 1 on a deck error or a failed analysis, 2 on a usage error, 3 when
!> the run was stopped by SIGINT or SIGTERM (its converged increments written).
!> This is the only place where errors are printed.
program frix
   use frix_error, only: error_t
   use frix_driver, only: run_options_t, run_deck
   use frix_process, only: exit_with_status, keep_freed_memory
   use frix_stop_request, only: install_stop_handlers, stop_requested
   use frix_version_info, only: write_version_report
   use frix_process_group, only: start_processes, finish_processes, is_root_process
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   type(run_options_t) :: options
   type(error_t), allocatable :: error
   integer :: status

   call keep_freed_memory()
   call install_stop_handlers()
   call parse_command_line(options, status)
   if (status == 3) then
      call write_version_report(output_unit)
      call exit_with_status(0)
   end if
   if (status /= 0) then
      call print_usage()
      if (status == 1) call exit_with_status(0)
      call exit_with_status(2)
   end if
   call start_processes(error)
   if (.not. allocated(error)) then
      call silence_other_processes()
      call run_deck(options, error)
   end if
   call finish_processes()
   if (allocated(error)) then
      if (is_root_process()) write (0, '(a)') error%message
      if (stop_requested()) call exit_with_status(3)
      call exit_with_status(1)
   end if

contains

   !> Under `mpirun -n P` (docs/parallel.md) process 0 alone prints: the others' standard
   !> output goes to /dev/null (their errors are process 0's too).
   subroutine silence_other_processes()
      integer :: stat
      if (is_root_process()) return
      open (unit=output_unit, file='/dev/null', action='write', iostat=stat)
   end subroutine silence_other_processes

   subroutine parse_command_line(options, status)
      type(run_options_t), intent(out) :: options
      integer, intent(out) :: status  !! 0 ok, 1 help asked, 2 usage error, 3 version asked
      character(len=:), allocatable :: argument, value
      integer :: i, n
      status = 0
      n = command_argument_count()
      i = 0
      do while (i < n)
         i = i + 1
         argument = get_argument(i)
         select case (argument)
         case ('-h', '--help')
            status = 1
            return
         case ('--version')
            status = 3
            return
         case ('--check')
            options%check_only = .true.
         case ('--quiet')
            options%quiet = .true.
         case ('--restart')
            call option_value(i, n, '--restart needs the HDF5 file of an earlier run', &
                              options%restart_path, status)
            if (status /= 0) return
         case ('--from')
            call option_value(i, n, '--from needs STEP.INCREMENT, e.g. --from 2.3', value, status)
            if (status /= 0) return
            call parse_step_increment(value, options%restart_step, options%restart_increment, status)
            if (status /= 0) return
         case ('--out')
            call option_value(i, n, '--out needs a directory', options%output_directory, status)
            if (status /= 0) return
         case default
            if (argument(1:1) == '-') then
               write (0, '(a)') 'frix: unknown option "'//argument//'"'
               status = 2
               return
            end if
            if (allocated(options%deck_path)) then
               write (0, '(a)') 'frix: more than one deck given: "'//argument//'"'
               status = 2
               return
            end if
            options%deck_path = argument
         end select
      end do
      if (.not. allocated(options%deck_path)) then
         write (0, '(a)') 'frix: no deck given'
         status = 2
      else if (allocated(options%restart_path) .neqv. options%restart_step > 0) then
         write (0, '(a)') 'frix: --restart FILE and --from STEP.INCREMENT go together'
         status = 2
      end if
   end subroutine parse_command_line

   !> The value after option i (advancing i), or a usage error `missing` if there is none.
   subroutine option_value(i, n, missing, value, status)
      integer, intent(inout) :: i
      integer, intent(in) :: n
      character(len=*), intent(in) :: missing
      character(len=:), allocatable, intent(out) :: value
      integer, intent(out) :: status
      status = 0
      if (i == n) then
         write (0, '(a)') 'frix: '//missing
         status = 2
         return
      end if
      i = i + 1
      value = get_argument(i)
   end subroutine option_value

   !> "S.K" -> S, K (positive integers).
   subroutine parse_step_increment(text, step, increment, status)
      character(len=*), intent(in) :: text
      integer, intent(out) :: step, increment
      integer, intent(out) :: status
      integer :: dot, stat1, stat2
      status = 0
      step = 0
      increment = 0
      dot = index(text, '.')
      stat1 = 1
      stat2 = 1
      if (dot > 1 .and. dot < len(text)) then
         read (text(:dot - 1), *, iostat=stat1) step
         read (text(dot + 1:), *, iostat=stat2) increment
      end if
      if (stat1 /= 0 .or. stat2 /= 0 .or. step < 1 .or. increment < 1 .or. verify(text, '0123456789.') /= 0) then
         write (0, '(a)') 'frix: --from "'//text//'": expected STEP.INCREMENT with positive integers, e.g. 2.3'
         status = 2
      end if
   end subroutine parse_step_increment

   function get_argument(i) result(argument)
      integer, intent(in) :: i
      character(len=:), allocatable :: argument
      integer :: length
      call get_command_argument(i, length=length)
      allocate (character(len=length) :: argument)
      if (length > 0) call get_command_argument(i, argument)
   end function get_argument

   subroutine print_usage()
      write (*, '(a)') 'usage: frix DECK [--out DIR] [--check] [--quiet] [--restart FILE.h5 --from S.K]'
      write (*, '(a)') '       frix --version'
      write (*, '(a)') '  DECK       input deck (CARAT-style sections, see docs/deck-format.md)'
      write (*, '(a)') '  --out DIR  write results into DIR (default: beside the deck)'
      write (*, '(a)') '  --check    read and validate the deck, solve nothing'
      write (*, '(a)') '  --quiet    no progress lines'
      write (*, '(a)') '  --restart FILE.h5 --from S.K'
      write (*, '(a)') '             continue from converged increment K of step S stored in the'
      write (*, '(a)') '             HDF5 results of an earlier run (RESULTS: HDF5 Yes) of the same deck'
      write (*, '(a)') '  --version  print the version of frix, the compiler and the libraries, and exit'
   end subroutine print_usage
end program frix
