!> The processes of a run: one in a serial run, P under `mpirun -n P frix DECK` in a frix built
!> with PETSc (docs/parallel.md). Every process reads the deck and holds the whole model and
!> state (replicated); the elements and nodes are divided among the processes by a METIS
!> partition of the mesh (`partition_mesh`; contiguous blocks of the element and node numbers
!> when METIS cannot make one), each process evaluates its own elements (`owns_element`),
!> and the sums here (MPI_Allreduce over MPI_COMM_WORLD) give every process the whole
!> vector. The matrix rows of a process are those of its nodes (`node_numbering`). Process 0
!> (the root) alone writes output.
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
   use frix_metis_ordering, only: metis_mesh_partition
   use frix_strings, only: to_string
   implicit none
   private

   public :: start_processes, finish_processes, n_processes, is_root_process
   public :: partition_mesh, owns_element, node_numbering, partition_summary
   public :: sum_over_processes, gather_owned_elements, agree_on_failure, agree_on_error, agree_on_message

   !> Sum over the processes, in place; every process gets the sum.
   interface sum_over_processes
      module procedure sum_vector, sum_matrix, sum_array3
   end interface sum_over_processes

   !> Values per element (the last dimension: the elements of the mesh) that each process
   !> holds for its own elements only (owns_element), whole on every process: the others'
   !> zeroed, then summed over the processes (exact: x + 0 = x).
   interface gather_owned_elements
      module procedure gather_matrix, gather_array3
   end interface gather_owned_elements

   integer, save :: ranks = 1        !! number of processes
   integer, save :: rank = 0         !! this process, 0-based
   !> the process owning each element and each node (partition_mesh); unallocated in a
   !> serial run
   integer, allocatable, save :: element_owner(:), node_owner(:)
   logical, save :: metis_partition = .false.   !! made by METIS (else contiguous blocks)
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

   !> Whether this is process 0, the one that writes output.
   logical function is_root_process()
      is_root_process = rank == 0
   end function is_root_process

   !> The partition of the mesh among the processes (every process calls it, with the same
   !> mesh): METIS_PartMeshDual computed by process 0 and sent to the others; contiguous
   !> blocks of the element and of the node numbers when the mesh has fewer elements than
   !> processes or METIS fails. Nothing in a serial run.
   subroutine partition_mesh(connectivity, n_nodes)
      integer, intent(in) :: connectivity(:, :)   !! (nodes per element, n_elements), 0: padding
      integer, intent(in) :: n_nodes
      type(error_t), allocatable :: error
#ifdef FRIX_WITH_MPI
      integer :: ierr
#endif
      if (ranks <= 1) return
      if (rank == 0) then
         if (size(connectivity, 2) >= ranks) &
            call metis_mesh_partition(connectivity, n_nodes, ranks, element_owner, node_owner, error)
         metis_partition = size(connectivity, 2) >= ranks .and. .not. allocated(error)
         if (.not. metis_partition) then
            call block_owners(size(connectivity, 2), element_owner)
            call block_owners(n_nodes, node_owner)
         end if
      else
         allocate (element_owner(size(connectivity, 2)), node_owner(n_nodes))
      end if
#ifdef FRIX_WITH_MPI
      call MPI_Bcast(element_owner, size(element_owner), MPI_INTEGER, 0, MPI_COMM_WORLD, ierr)
      call MPI_Bcast(node_owner, size(node_owner), MPI_INTEGER, 0, MPI_COMM_WORLD, ierr)
#endif
   end subroutine partition_mesh

   !> For the run's banner: how the mesh is divided, e.g. "2 MPI processes, a METIS partition:
   !> elements 62 62, nodes 170 152"; '' in a serial run (process 0's view).
   function partition_summary() result(text)
      character(len=:), allocatable :: text
      integer :: r
      text = ''
      if (.not. allocated(element_owner)) return
      text = to_string(ranks)//' MPI processes, '//trim(merge('a METIS partition   ', 'contiguous blocks   ', &
                                                                metis_partition))//': elements'
      do r = 0, ranks - 1
         text = text//' '//to_string(count(element_owner == r))
      end do
      text = text//', nodes'
      do r = 0, ranks - 1
         text = text//' '//to_string(count(node_owner == r))
      end do
   end function partition_summary

   !> owner(k) = the process of item k when items 1..n are divided in contiguous blocks (ranks
   !> in order, sizes differing by one at most).
   subroutine block_owners(n, owner)
      integer, intent(in) :: n
      integer, allocatable, intent(out) :: owner(:)
      integer :: r, first, last
      allocate (owner(n))
      do r = 0, ranks - 1
         first = int(int(r, i8)*n/ranks) + 1
         last = int(int(r + 1, i8)*n/ranks)
         owner(first:last) = r
      end do
   end subroutine block_owners

   !> Whether this process evaluates element e (every element in a serial run).
   pure logical function owns_element(e)
      integer, intent(in) :: e
      owns_element = .true.
      if (allocated(element_owner)) owns_element = element_owner(e) == rank
   end function owns_element

   !> The numbering of the nodes that gives every process a contiguous block of them, its
   !> own: position(a) (0-based) of node a, the processes' nodes one process after the other,
   !> each in increasing node number; this process's nodes are at first..last. The identity
   !> in a serial run.
   subroutine node_numbering(n_nodes, position, first, last)
      integer, intent(in) :: n_nodes
      integer, allocatable, intent(out) :: position(:)
      integer, intent(out) :: first, last
      integer, allocatable :: next(:)
      integer :: a, r, count
      allocate (position(n_nodes))
      if (.not. allocated(node_owner)) then
         position = [(a - 1, a = 1, n_nodes)]
         first = 0
         last = n_nodes - 1
         return
      end if
      allocate (next(0:ranks - 1), source=0)
      do a = 1, n_nodes
         next(node_owner(a)) = next(node_owner(a)) + 1
      end do
      ! next(r): the first position of process r's nodes
      first = 0
      do r = 0, ranks - 1
         count = next(r)
         next(r) = first
         first = first + count
      end do
      first = next(rank)
      do a = 1, n_nodes
         position(a) = next(node_owner(a))
         next(node_owner(a)) = next(node_owner(a)) + 1
      end do
      last = next(rank) - 1
   end subroutine node_numbering

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
      integer :: e
      if (ranks <= 1) return
      do e = 1, size(values, 2)
         if (.not. owns_element(e)) values(:, e) = 0.0_dp
      end do
      call sum_over_processes(values)
   end subroutine gather_matrix

   subroutine gather_array3(values)
      real(dp), intent(inout), contiguous :: values(:, :, :)   !! (:, :, n_elements)
      integer :: e
      if (ranks <= 1) return
      do e = 1, size(values, 3)
         if (.not. owns_element(e)) values(:, :, e) = 0.0_dp
      end do
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
