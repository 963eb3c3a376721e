!> P1 micro-benchmark (bench/, never a test): times the global assembly of a deck's model,
!> in CPU seconds of this process as well as wall seconds, so that the one-core assembly
!> throughput can be measured on a machine shared with other jobs (wall time then counts
!> the time the process waits for a core; CPU time does not).
!>
!> Usage: p1_assembly_timer DECK [REPEATS [STRAIN [SHEAR]]]
!> With STRAIN and SHEAR (default 0) the displacement is u = (STRAIN x + SHEAR z, 0, 0), a
!> uniform uniaxial strain plus a simple shear gamma_xz = SHEAR (beyond the yield strain every
!> integration point of an elastoplastic material returns to the yield surface in every
!> assembly: the plastic branch's cost).
!> For REPEATS assemblies (default 5) of fint + tangent at that u it prints, per assembly,
!> the best CPU and wall time and the elements per CPU second; then the same for the
!> element kernel alone (evaluate, no scatter) to split kernel and scatter cost.
!> Output lines: `p1_assembly_timer: <key> <value>`.
program p1_assembly_timer
   use frix_kinds, only: dp, i8
   use frix_error, only: error_t
   use frix_model, only: model_t
   use frix_deck_reader, only: read_deck
   use frix_analysis_state, only: analysis_state_t, create_analysis_state
   use frix_sparse_matrix, only: sparse_matrix_t
   use frix_assembler, only: assemble_internal
   implicit none

   type(model_t) :: model
   type(analysis_state_t) :: state
   type(sparse_matrix_t) :: matrix
   type(error_t), allocatable :: error
   character(len=4096) :: deck_path, argument
   real(dp), allocatable :: fint(:)
   real(dp) :: cpu_start, cpu_end, wall_start, best_cpu, best_wall, kernel_cpu, kernel_wall
   real(dp) :: checksum, strain, shear
   integer :: repeats, r, n_elements, node

   if (command_argument_count() < 1) then
      write (*, '(a)') 'usage: p1_assembly_timer DECK [REPEATS [STRAIN [SHEAR]]]'
      error stop 2
   end if
   call get_command_argument(1, deck_path)
   repeats = 5
   if (command_argument_count() >= 2) then
      call get_command_argument(2, argument)
      read (argument, *) repeats
   end if
   strain = 0.0_dp
   if (command_argument_count() >= 3) then
      call get_command_argument(3, argument)
      read (argument, *) strain
   end if
   shear = 0.0_dp
   if (command_argument_count() >= 4) then
      call get_command_argument(4, argument)
      read (argument, *) shear
   end if

   call read_deck(trim(deck_path), model, error)
   if (allocated(error)) then
      write (*, '(a)') error%message
      error stop 1
   end if
   call create_analysis_state(model, state, error)
   if (allocated(error)) then
      write (*, '(a)') error%message
      error stop 1
   end if
   call matrix%create_node_block_pattern(model%mesh%n_nodes, model%mesh%connectivity, error=error)
   if (allocated(error)) then
      write (*, '(a)') error%message
      error stop 1
   end if
   allocate (fint(3*model%mesh%n_nodes))
   n_elements = model%mesh%n_elements
   do node = 1, model%mesh%n_nodes
      state%u(3*node - 2) = strain*model%mesh%coords(1, node) + shear*model%mesh%coords(3, node)
   end do

   ! warm-up: first touch of the matrix values and of every element's data
   call assemble_internal(model, state, fint, error, matrix=matrix)
   if (allocated(error)) then
      write (*, '(a)') error%message
      error stop 1
   end if

   best_cpu = huge(1.0_dp)
   best_wall = huge(1.0_dp)
   do r = 1, repeats
      wall_start = wall_seconds()
      call cpu_time(cpu_start)
      call assemble_internal(model, state, fint, error, matrix=matrix)
      call cpu_time(cpu_end)
      best_cpu = min(best_cpu, cpu_end - cpu_start)
      best_wall = min(best_wall, wall_seconds() - wall_start)
   end do
   call element_kernel_only(model, state, repeats, kernel_cpu, kernel_wall, checksum)

   write (*, '(a,i0)') 'p1_assembly_timer: elements ', n_elements
   write (*, '(a,i0)') 'p1_assembly_timer: repeats ', repeats
   write (*, '(a,es12.5)') 'p1_assembly_timer: strain ', strain
   write (*, '(a,es12.5)') 'p1_assembly_timer: assembly_cpu_seconds ', best_cpu
   write (*, '(a,es12.5)') 'p1_assembly_timer: assembly_wall_seconds ', best_wall
   write (*, '(a,f12.0)') 'p1_assembly_timer: elements_per_cpu_second ', n_elements/best_cpu
   write (*, '(a,es12.5)') 'p1_assembly_timer: kernel_cpu_seconds ', kernel_cpu
   write (*, '(a,es12.5)') 'p1_assembly_timer: kernel_wall_seconds ', kernel_wall
   write (*, '(a,f12.0)') 'p1_assembly_timer: kernel_elements_per_cpu_second ', n_elements/kernel_cpu
   write (*, '(a,es12.5)') 'p1_assembly_timer: scatter_and_rest_cpu_seconds ', best_cpu - kernel_cpu
   write (*, '(a,es12.5)') 'p1_assembly_timer: kernel_checksum ', checksum

contains

   !> Best CPU / wall time of `repeats` loops over every element's evaluate (fint and tangent,
   !> no scatter): the element kernel alone. checksum keeps the compiler from dropping work.
   subroutine element_kernel_only(model, state, repeats, best_cpu, best_wall, checksum)
      type(model_t), intent(in) :: model
      type(analysis_state_t), intent(inout) :: state
      integer, intent(in) :: repeats
      real(dp), intent(out) :: best_cpu, best_wall, checksum
      real(dp) :: coords(3, 8), displacement(3, 8), force(24), tangent(24, 24)
      real(dp) :: cpu_start, cpu_end, wall_start
      type(error_t), allocatable :: element_error
      integer :: e, r, a, block, n_enhanced, n_points, n_state
      best_cpu = huge(1.0_dp)
      best_wall = huge(1.0_dp)
      checksum = 0.0_dp
      do r = 1, repeats
         wall_start = wall_seconds()
         call cpu_time(cpu_start)
         do e = 1, model%mesh%n_elements
            block = model%mesh%element_block(e)
            associate (element => model%blocks(block)%element%formulation, &
                       material => model%materials(model%blocks(block)%material)%law, &
                       nodes => model%mesh%connectivity(:, e))
               n_enhanced = element%n_enhanced()
               n_points = element%n_points()
               n_state = material%n_state()
               do a = 1, 8
                  coords(:, a) = model%mesh%coords(:, nodes(a))
                  displacement(:, a) = state%u(3*nodes(a) - 2:3*nodes(a))
               end do
               call element%evaluate(material, coords, displacement, state%alpha(:n_enhanced, e), &
                                     state%committed_history(:n_state, :n_points, e), &
                                     state%history(:n_state, :n_points, e), force, &
                                     tangent=tangent, error=element_error)
               if (allocated(element_error)) then
                  write (*, '(a)') element_error%message
                  error stop 1
               end if
               checksum = checksum + tangent(1, 1)
            end associate
         end do
         call cpu_time(cpu_end)
         best_cpu = min(best_cpu, cpu_end - cpu_start)
         best_wall = min(best_wall, wall_seconds() - wall_start)
      end do
   end subroutine element_kernel_only

   !> Wall clock seconds from an arbitrary origin (64-bit system_clock).
   function wall_seconds() result(seconds)
      real(dp) :: seconds
      integer(i8) :: count, rate
      call system_clock(count, rate)
      seconds = real(count, dp)/real(rate, dp)
   end function wall_seconds
end program p1_assembly_timer
