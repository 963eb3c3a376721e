!> The processes of a run: one in a serial run, P under `mpirun -n P frix DECK` in a frix built
!> with PETSc (docs/parallel.md). Every process reads the deck and holds the whole model and
!> state (replicated); the elements are divided among the processes in contiguous blocks of
!> the deck's element order (`owned_range`), each process evaluates its own, and the sums here
!> (MPI_Allreduce over MPI_COMM_WORLD) give every process the whole vector. Process 0 (the
!> root) alone writes output.
!>
!> MPI is started only when the launcher says there is more than one process
!> (OMPI_COMM_WORLD_SIZE of OpenMPI's mpirun, or PMI_SIZE): a serial run of a PETSc build
!> starts no MPI before PETSc does (SOLVER Petsc). Without PETSc (FRIX_WITH_PETSC undefined)
!> this module has no MPI: one process, and every reduction leaves its argument as it is.
#ifdef FRIX_WITH_PETSC
#define FRIX_WITH_MPI
#endif
module frix_process_group
#ifdef FRIX_WITH_MPI
   use mpi
#endif
   use frix_kinds, only: dp, i8
   use frix_error, only: error_t, fatal_error
#ifdef FRIX_WITH_MPI
   use frix_strings, only: to_string
#endif
   implicit none
   private

   public :: start_processes, finish_processes, n_processes, process_rank, is_root_process
   public :: owned_range, sum_over_processes, gather_owned_elements, agree_on_failure, agree_on_error
   public :: agree_on_message

   !> Sum over the processes, in place; every process gets the sum.
   interface sum_over_processes
      module procedure sum_vector, sum_matrix, sum_array3
   end interface sum_over_processes

   !> Values per element (the last dimension: the elements of the mesh) that each process
   !> holds for its own elements only (owned_range), whole on every process: the others'
   !> zeroed, then summed over the processes (exact: x + 0 = x).
   interface gather_owned_elements
      module procedure gather_matrix, gather_array3
   end interface gather_owned_elements

   integer, save :: ranks = 1        !! number of processes
   integer, save :: rank = 0         !! this process, 0-based
#ifdef FRIX_WITH_MPI
   logical, save :: mpi_started = .false.   !! MPI_Init called here
#endif

contains

   !> MPI started when launched on more than one process (module head).
   subroutine start_processes(error)
      type(error_t), allocatable, intent(out) :: error
#ifdef FRIX_WITH_MPI
      integer :: ierr
      if (mpi_started .or. launched_size() <= 1) return
      call MPI_Init(ierr)
      if (ierr /= MPI_SUCCESS) then
         call fatal_error(error, 'frix: MPI_Init failed, error code '//to_string(ierr))
         return
      end if
      mpi_started = .true.
      call MPI_Comm_size(MPI_COMM_WORLD, ranks, ierr)
      call MPI_Comm_rank(MPI_COMM_WORLD, rank, ierr)
#endif
   end subroutine start_processes

   !> MPI_Finalize when start_processes began MPI (after PETSc's finalization).
   subroutine finish_processes()
#ifdef FRIX_WITH_MPI
      integer :: ierr
      if (mpi_started) call MPI_Finalize(ierr)
      mpi_started = .false.
#endif
   end subroutine finish_processes

#ifdef FRIX_WITH_MPI
   !> The number of processes the launcher started (1 without one).
   integer function launched_size()
      character(len=32) :: value
      integer :: length, status, k
      launched_size = 1
      do k = 1, 2
         call get_environment_variable(trim(merge('OMPI_COMM_WORLD_SIZE', 'PMI_SIZE            ', k == 1)), &
                                       value, length, status)
         if (status /= 0 .or. length == 0) cycle
         read (value, *, iostat=status) launched_size
         if (status /= 0) launched_size = 1
         return
      end do
   end function launched_size

#endif

   integer function n_processes()
      n_processes = ranks
   end function n_processes

   !> This process, 0 to n_processes() - 1.
   integer function process_rank()
      process_rank = rank
   end function process_rank

   !> Whether this is process 0, the one that writes output.
   logical function is_root_process()
      is_root_process = rank == 0
   end function is_root_process

   !> This process's share of items 1..n: the contiguous block first..last (ranks in order,
   !> sizes differing by one at most); 1..n in a serial run.
   subroutine owned_range(n, first, last)
      integer, intent(in) :: n
      integer, intent(out) :: first, last
      first = int(int(rank, i8)*n/ranks) + 1
      last = int(int(rank + 1, i8)*n/ranks)
   end subroutine owned_range

   subroutine sum_vector(x)
      real(dp), intent(inout), contiguous :: x(:)
#ifdef FRIX_WITH_MPI
      integer :: ierr
      if (ranks > 1) call MPI_Allreduce(MPI_IN_PLACE, x, size(x), MPI_DOUBLE_PRECISION, MPI_SUM, MPI_COMM_WORLD, ierr)
#endif
   end subroutine sum_vector

   subroutine sum_matrix(x)
      real(dp), intent(inout), contiguous :: x(:, :)
#ifdef FRIX_WITH_MPI
      integer :: ierr
      if (ranks > 1) call MPI_Allreduce(MPI_IN_PLACE, x, size(x), MPI_DOUBLE_PRECISION, MPI_SUM, MPI_COMM_WORLD, ierr)
#endif
   end subroutine sum_matrix

   subroutine sum_array3(x)
      real(dp), intent(inout), contiguous :: x(:, :, :)
#ifdef FRIX_WITH_MPI
      integer :: ierr
      if (ranks > 1) call MPI_Allreduce(MPI_IN_PLACE, x, size(x), MPI_DOUBLE_PRECISION, MPI_SUM, MPI_COMM_WORLD, ierr)
#endif
   end subroutine sum_array3

   subroutine gather_matrix(values)
      real(dp), intent(inout), contiguous :: values(:, :)   !! (:, n_elements)
      integer :: first, last
      if (ranks <= 1) return
      call owned_range(size(values, 2), first, last)
      values(:, :first - 1) = 0.0_dp
      values(:, last + 1:) = 0.0_dp
      call sum_over_processes(values)
   end subroutine gather_matrix

   subroutine gather_array3(values)
      real(dp), intent(inout), contiguous :: values(:, :, :)   !! (:, :, n_elements)
      integer :: first, last
      if (ranks <= 1) return
      call owned_range(size(values, 3), first, last)
      values(:, :, :first - 1) = 0.0_dp
      values(:, :, last + 1:) = 0.0_dp
      call sum_over_processes(values)
   end subroutine gather_array3

   !> Whether `failed` holds on any process.
   logical function agree_on_failure(failed) result(any_failed)
      logical, intent(in) :: failed
#ifdef FRIX_WITH_MPI
      integer :: ierr
#endif
      any_failed = failed
#ifdef FRIX_WITH_MPI
      if (ranks > 1) call MPI_Allreduce(failed, any_failed, 1, MPI_LOGICAL, MPI_LOR, MPI_COMM_WORLD, ierr)
#endif
   end function agree_on_failure

   !> The failure of the lowest process that has one, on every process (so that all take the
   !> same branch); unallocated everywhere when no process has one.
   subroutine agree_on_error(error)
      type(error_t), allocatable, intent(inout) :: error
      character(len=:), allocatable :: message
      if (ranks <= 1) return
      if (allocated(error)) call move_alloc(error%message, message)
      call agree_on_message(message)
      if (allocated(message)) then
         if (.not. allocated(error)) allocate (error)
         call move_alloc(message, error%message)
      else if (allocated(error)) then
         deallocate (error)
      end if
   end subroutine agree_on_error

   !> agree_on_error for a failure given as its message (allocated: failed).
   subroutine agree_on_message(message)
      character(len=:), allocatable, intent(inout) :: message
#ifdef FRIX_WITH_MPI
      integer :: first, length, ierr
      if (ranks <= 1) return
      call MPI_Allreduce(merge(rank, ranks, allocated(message)), first, 1, MPI_INTEGER, MPI_MIN, MPI_COMM_WORLD, &
                         ierr)
      if (first == ranks) return
      length = 0
      if (rank == first) length = len(message)
      call MPI_Bcast(length, 1, MPI_INTEGER, first, MPI_COMM_WORLD, ierr)
      if (rank /= first) then
         if (allocated(message)) deallocate (message)
         allocate (character(len=length) :: message)
      end if
      call MPI_Bcast(message, length, MPI_CHARACTER, first, MPI_COMM_WORLD, ierr)
#endif
   end subroutine agree_on_message
end module frix_process_group
