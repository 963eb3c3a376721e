!> `SOLVER Petsc`: the Newton systems solved by PETSc's KSP (PETSc 3.18, Debian's petsc-dev),
!> by default a direct LU factorization by MUMPS (`-ksp_type preonly -pc_type lu
!> -pc_factor_mat_solver_type mumps`); every PETSc option (`-ksp_*`, `-pc_*`, `-mat_mumps_*`,
!> ...) given in the environment variable PETSC_OPTIONS replaces those defaults, e.g.
!> PETSC_OPTIONS="-ksp_type gmres -pc_type gamg -ksp_rtol 1e-10" for an iterative solve.
!>
!> The matrix is the node-blocked compressed sparse column matrix of frix_sparse_matrix,
!> handed to PETSc as a sequential AIJ matrix in compressed rows: the same index arrays read
!> as rows describe A^T (the pattern is structurally symmetric), so the values are gathered
!> through the mirror positions (`mirror_positions`) into an array PETSc uses in place
!> (MatCreateSeqAIJWithArrays), with block size 3 and the six rigid-body modes of the nodes'
!> positions as its near-null space (MatNullSpaceCreateRigidBody: what GAMG needs for
!> elasticity, PETSc manual, PCGAMG). Under `mpirun -n P` (frix_process_group,
!> docs/parallel.md) the matrix is a distributed AIJ instead, assembled from every process's
!> share (factorize_distributed), and the solution is copied to every process.
!>
!> Built with PETSc only when CMake's FRIX_PETSC is ON (compile definition FRIX_WITH_PETSC);
!> otherwise the type exists and `factorize` reports that this frix was built without PETSc.
#ifdef FRIX_WITH_PETSC
#include "petsc/finclude/petscksp.h"
#endif
module frix_petsc_solver
#ifdef FRIX_WITH_PETSC
   use petscksp
#endif
   use frix_kinds, only: dp, i8
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_system_matrix, only: system_matrix_t
   use frix_sparse_matrix, only: sparse_matrix_t
   use frix_process_group, only: n_processes, node_numbering, agree_on_failure
   use frix_linear_solver, only: linear_solver_t, wall_clock_seconds, begin_factorize, check_solve_sizes, &
                                 csc_matrix, add_elapsed_seconds, singular_matrix_message, solver_singular, &
                                 solver_failed
   implicit none
   private

   public :: petsc_solver_t, petsc_available, finish_petsc

#ifdef FRIX_WITH_PETSC
   logical, parameter :: petsc_available = .true.   !! this frix links PETSc
   !> PETSc was initialized by frix (and is finalized by finish_petsc)
   logical, save :: petsc_started = .false.
#else
   logical, parameter :: petsc_available = .false.  !! this frix links PETSc
#endif

   type, extends(linear_solver_t) :: petsc_solver_t
#ifdef FRIX_WITH_PETSC
      type(tMat), private :: a                      !! AIJ on row_ptr, columns, row_values
      type(tKSP), private :: ksp
      logical, private :: created = .false.
      PetscInt, allocatable, private :: row_ptr(:)  !! (0:n) 0-based row offsets
      PetscInt, allocatable, private :: columns(:)  !! 0-based column of every entry
      PetscScalar, allocatable, private :: row_values(:)  !! A in compressed rows
      integer, allocatable, private :: mirror(:)   !! CSC position of each compressed-row entry
      PetscScalar, allocatable, private :: coords(:)  !! (3 n_nodes) node positions, x y z per node
      !> a parallel run (frix_process_group): the PETSc row of every equation (0-based, the
      !> nodes numbered process by process, node_numbering), the rows this process owns,
      !> first_row..last_row, and its equations in their order (1-based frix equations), the
      !> solution and its copy on every process
      logical, private :: distributed = .false.
      PetscInt, allocatable, private :: petsc_row(:)   !! (0:n - 1)
      PetscInt, private :: first_row = 0, last_row = -1
      integer, allocatable, private :: owned_equations(:)
      type(tVec), private :: b, u, u_all
      type(tVecScatter), private :: to_all
#endif
   contains
      procedure :: name
      procedure :: factorize
      procedure :: solve
      procedure :: release
      procedure :: description
#ifdef FRIX_WITH_PETSC
      procedure :: set_node_coordinates
#endif
   end type petsc_solver_t

contains

   function name(solver) result(keyword)
      class(petsc_solver_t), intent(in) :: solver
      character(len=:), allocatable :: keyword
      keyword = 'PETSC'
   end function name

#ifdef FRIX_WITH_PETSC
   !> The KSP and preconditioner types in use, e.g. "PETSC (preonly, lu mumps)".
   function description(solver) result(text)
      class(petsc_solver_t), intent(in) :: solver
      character(len=:), allocatable :: text
      character(len=64) :: ksp_type, pc_type, factor_type
      type(tPC) :: pc
      PetscErrorCode :: ierr
      text = solver%name()
      if (.not. solver%created) return
      call KSPGetType(solver%ksp, ksp_type, ierr)
      call KSPGetPC(solver%ksp, pc, ierr)
      call PCGetType(pc, pc_type, ierr)
      factor_type = ''
      if (trim(pc_type) == 'lu' .or. trim(pc_type) == 'cholesky') call PCFactorGetMatSolverType(pc, factor_type, ierr)
      text = text//' ('//trim(ksp_type)//', '//trim(pc_type)//trim(' '//factor_type)//')'
   end function description

   !> PETSc's initialization, once per run; its signal handlers stay off (frix's own handle
   !> SIGINT and SIGTERM: stop after the increment).
   subroutine start_petsc(error)
      type(error_t), allocatable, intent(out) :: error
      PetscErrorCode :: ierr
      PetscBool :: initialized
      call PetscInitialized(initialized, ierr)
      if (initialized) return
      call PetscOptionsSetValue(PETSC_NULL_OPTIONS, '-no_signal_handler', 'true', ierr)
      call PetscInitialize(PETSC_NULL_CHARACTER, ierr)
      if (ierr /= 0) then
         call fatal_error(error, 'PETSC: PetscInitialize failed, error code '//to_string(int(ierr)))
         return
      end if
      petsc_started = .true.
   end subroutine start_petsc

   !> PetscFinalize when frix started PETSc (at the end of a run).
   subroutine finish_petsc()
      PetscErrorCode :: ierr
      if (petsc_started) call PetscFinalize(ierr)
      petsc_started = .false.
   end subroutine finish_petsc

   !> A new pattern: the AIJ matrix on compressed rows and a KSP with frix's defaults (MUMPS
   !> LU) overridden by the PETSc options. Otherwise the values are gathered again.
   subroutine factorize(solver, matrix, error)
      class(petsc_solver_t), intent(inout) :: solver
      class(system_matrix_t), intent(in), target :: matrix
      type(error_t), allocatable, intent(out) :: error
      type(sparse_matrix_t), pointer :: csc
      integer(i8), pointer, contiguous :: col_ptr(:), row_index(:)
      real(dp), pointer, contiguous :: values(:)
      PetscErrorCode :: ierr
      real(dp) :: start

      call begin_factorize(solver, matrix, error)
      if (.not. allocated(error)) call csc_matrix(solver, matrix, csc, error)
      if (.not. allocated(error)) call start_petsc(error)
      if (allocated(error)) return
      call csc%csc_arrays(col_ptr, row_index, values)
      start = wall_clock_seconds()
      if (n_processes() > 1) then
         call factorize_distributed(solver, matrix, csc, col_ptr, row_index, values, start, error)
         return
      end if
      if (matrix%pattern_id /= solver%analysed_pattern_id) then
         call release(solver)
         solver%row_ptr = int(col_ptr, kind(solver%row_ptr))
         solver%columns = int(row_index, kind(solver%columns))
         call csc%mirror_positions(solver%mirror)
         solver%row_values = values(solver%mirror)
         call MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, int(matrix%n, kind(solver%row_ptr)), &
                                        int(matrix%n, kind(solver%row_ptr)), solver%row_ptr, solver%columns, &
                                        solver%row_values, solver%a, ierr)
         if (ierr == 0) call MatSetBlockSize(solver%a, 3, ierr)
         if (ierr == 0 .and. allocated(solver%coords)) then
            if (size(solver%coords) == matrix%n) call set_rigid_body_modes(solver, ierr)
         end if
         if (ierr == 0) call create_ksp(solver, PETSC_COMM_SELF, ierr)
         if (ierr /= 0) then
            solver%failure = solver_failed
            call fatal_error(error, 'PETSC: setting up the matrix and KSP failed, error code '//to_string(int(ierr)))
            return
         end if
         solver%created = .true.
         solver%n_analyses = solver%n_analyses + 1
         solver%analysed_pattern_id = matrix%pattern_id
      else
         solver%row_values = values(solver%mirror)
      end if
      call MatAssemblyBegin(solver%a, MAT_FINAL_ASSEMBLY, ierr)
      call MatAssemblyEnd(solver%a, MAT_FINAL_ASSEMBLY, ierr)
      call set_up_factors(solver, matrix%pattern_id, start, error)
   end subroutine factorize

   !> KSPSetUp on the assembled matrix (for LU: the numeric factorization); a failed
   !> factorization or preconditioner on any process is a singular matrix.
   subroutine set_up_factors(solver, pattern_id, start, error)
      class(petsc_solver_t), intent(inout) :: solver
      integer, intent(in) :: pattern_id
      real(dp), intent(in) :: start   !! wall clock at the start of factorize [s]
      type(error_t), allocatable, intent(out) :: error
      type(tPC) :: pc
      PCFailedReason :: failed
      PetscErrorCode :: ierr
      call KSPSetUp(solver%ksp, ierr)
      call add_elapsed_seconds(start, solver%last_factorize_seconds, solver%factorize_seconds, solver%n_factorizations)
      call KSPGetPC(solver%ksp, pc, ierr)
      call PCGetFailedReason(pc, failed, ierr)
      if (agree_on_failure(failed /= PC_NOERROR .or. ierr /= 0)) then
         solver%failure = solver_singular
         call singular_matrix_message(error, 'PETSC', 'singular', 0, &
                                      'the preconditioner failed (PCFailedReason '//to_string(int(failed))//')')
         return
      end if
      solver%factorized_pattern_id = pattern_id
   end subroutine set_up_factors

   subroutine set_node_coordinates(solver, coords)
      class(petsc_solver_t), intent(inout) :: solver
      real(dp), intent(in) :: coords(:, :)   !! (3, n_nodes)
      solver%coords = reshape(coords, [size(coords)])
   end subroutine set_node_coordinates

   !> The near-null space of the matrix: the rigid-body modes of the nodes' positions.
   subroutine set_rigid_body_modes(solver, ierr)
      class(petsc_solver_t), intent(inout) :: solver
      PetscErrorCode, intent(out) :: ierr
      type(tVec) :: positions
      type(tMatNullSpace) :: modes
      call VecCreateSeqWithArray(PETSC_COMM_SELF, 3, int(size(solver%coords), kind(solver%row_ptr)), &
                                 solver%coords, positions, ierr)
      if (ierr == 0) call MatNullSpaceCreateRigidBody(positions, modes, ierr)
      if (ierr == 0) call MatSetNearNullSpace(solver%a, modes, ierr)
      if (ierr == 0) call MatNullSpaceDestroy(modes, ierr)
      if (ierr == 0) call VecDestroy(positions, ierr)
   end subroutine set_rigid_body_modes

   !> KSPSolve on vectors that wrap rhs and x; an error when the KSP did not converge.
   subroutine solve(solver, matrix, rhs, x, error)
      class(petsc_solver_t), intent(inout) :: solver
      class(system_matrix_t), intent(in), target :: matrix
      real(dp), intent(in), target :: rhs(:)
      real(dp), intent(out), target :: x(:)
      type(error_t), allocatable, intent(out) :: error
      type(tVec) :: b, u
      KSPConvergedReason :: reason
      PetscErrorCode :: ierr
      real(dp) :: start
      call check_solve_sizes(solver, matrix, size(rhs), size(x), error)
      if (allocated(error)) return
      start = wall_clock_seconds()
      x = 0.0_dp
      if (solver%distributed) then
         call solve_distributed(solver, rhs, x, reason)
      else
         call VecCreateSeqWithArray(PETSC_COMM_SELF, 1, int(matrix%n, kind(solver%row_ptr)), rhs, b, ierr)
         call VecCreateSeqWithArray(PETSC_COMM_SELF, 1, int(matrix%n, kind(solver%row_ptr)), x, u, ierr)
         call KSPSolve(solver%ksp, b, u, ierr)
         call KSPGetConvergedReason(solver%ksp, reason, ierr)
         call VecDestroy(b, ierr)
         call VecDestroy(u, ierr)
      end if
      call add_elapsed_seconds(start, solver%last_solve_seconds, solver%solve_seconds, solver%n_solves)
      if (reason < 0) call fatal_error(error, 'PETSC: the KSP did not converge (KSPConvergedReason '// &
                                       to_string(int(reason))//')')
   end subroutine solve

   !> factorize in a parallel run (docs/parallel.md): every process holds the whole pattern and
   !> its own share of the values (its elements; process 0 also contact, loads and the
   !> Dirichlet diagonal); the matrix is a distributed AIJ (MPIAIJ) whose rows are those of
   !> the nodes of the processes' partition, renumbered so that each process owns a
   !> contiguous block of them (node_numbering), preallocated exactly from the pattern, and
   !> each process adds its share by MatSetValues(ADD_VALUES): its own rows whole, the entries
   !> it holds of other processes' rows where they are not zero (PETSc sends those at the
   !> assembly).
   subroutine factorize_distributed(solver, matrix, csc, col_ptr, row_index, values, start, error)
      class(petsc_solver_t), intent(inout) :: solver
      class(system_matrix_t), intent(in) :: matrix
      type(sparse_matrix_t), intent(in) :: csc
      integer(i8), intent(in) :: col_ptr(0:), row_index(:)
      real(dp), intent(in) :: values(:)
      real(dp), intent(in) :: start   !! wall clock at the start of factorize [s]
      type(error_t), allocatable, intent(out) :: error
      PetscErrorCode :: ierr
      if (matrix%pattern_id /= solver%analysed_pattern_id) then
         call release(solver)
         if (allocated(solver%row_ptr)) deallocate (solver%row_ptr)
         allocate (solver%row_ptr(0:matrix%n))   ! (indexed by the 0-based row)
         solver%row_ptr(:) = int(col_ptr, kind(solver%row_ptr))
         solver%columns = int(row_index, kind(solver%columns))
         call csc%mirror_positions(solver%mirror)
         call create_distributed(solver, matrix%n, matrix%n_nodes, ierr)
         if (ierr /= 0) then
            solver%failure = solver_failed
            call fatal_error(error, 'PETSC: setting up the distributed matrix and KSP failed, error code '// &
                             to_string(int(ierr)))
            return
         end if
         solver%created = .true.
         solver%n_analyses = solver%n_analyses + 1
         solver%analysed_pattern_id = matrix%pattern_id
      end if
      solver%row_values = values(solver%mirror)
      call add_share(solver, ierr)
      if (ierr /= 0) then
         solver%failure = solver_failed
         call fatal_error(error, 'PETSC: adding the values to the distributed matrix failed, error code '// &
                          to_string(int(ierr)))
         return
      end if
      call set_up_factors(solver, matrix%pattern_id, start, error)
   end subroutine factorize_distributed

   !> The MPIAIJ matrix preallocated from the pattern (solver%row_ptr, columns; the columns
   !> turned into PETSc's numbering), its vectors, the scatter of the solution to every
   !> process, and the KSP with frix's defaults.
   subroutine create_distributed(solver, n, n_nodes, ierr)
      class(petsc_solver_t), intent(inout) :: solver
      integer, intent(in) :: n, n_nodes
      PetscErrorCode, intent(out) :: ierr
      PetscInt, allocatable :: diagonal_count(:), off_count(:)
      PetscInt :: row, p, m, local
      integer, allocatable :: position(:)
      integer :: first_node, last_node, a, i, e
      call node_numbering(n_nodes, position, first_node, last_node)
      if (allocated(solver%petsc_row)) deallocate (solver%petsc_row)
      allocate (solver%petsc_row(0:n - 1))
      do a = 1, n_nodes
         do i = 0, 2
            solver%petsc_row(3*(a - 1) + i) = 3*position(a) + i
         end do
      end do
      solver%first_row = 3*first_node
      solver%last_row = 3*last_node + 2
      m = solver%last_row - solver%first_row + 1
      if (allocated(solver%owned_equations)) deallocate (solver%owned_equations)
      allocate (solver%owned_equations(m))
      do e = 0, n - 1
         if (owned_row(solver, solver%petsc_row(e))) &
            solver%owned_equations(solver%petsc_row(e) - solver%first_row + 1) = e + 1
      end do
      solver%columns = solver%petsc_row(solver%columns)
      allocate (diagonal_count(m), off_count(m), source=int(0, kind(m)))
      do row = 0, n - 1
         if (.not. owned_row(solver, solver%petsc_row(row))) cycle
         local = solver%petsc_row(row) - solver%first_row + 1
         do p = solver%row_ptr(row) + 1, solver%row_ptr(row + 1)
            if (owned_row(solver, solver%columns(p))) then
               diagonal_count(local) = diagonal_count(local) + 1
            else
               off_count(local) = off_count(local) + 1
            end if
         end do
      end do
      solver%distributed = .true.
      call MatCreate(PETSC_COMM_WORLD, solver%a, ierr)
      if (ierr == 0) call MatSetSizes(solver%a, m, m, int(n, kind(m)), int(n, kind(m)), ierr)
      if (ierr == 0) call MatSetBlockSize(solver%a, 3, ierr)
      if (ierr == 0) call MatSetType(solver%a, MATMPIAIJ, ierr)
      if (ierr == 0) call MatMPIAIJSetPreallocation(solver%a, int(0, kind(m)), diagonal_count, int(0, kind(m)), &
                                                    off_count, ierr)
      if (ierr == 0) call MatSetOption(solver%a, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE, ierr)
      if (ierr == 0 .and. allocated(solver%coords)) then
         if (size(solver%coords) == n) call set_distributed_rigid_body_modes(solver, m, n, ierr)
      end if
      if (ierr == 0) call MatCreateVecs(solver%a, solver%u, solver%b, ierr)
      if (ierr == 0) call VecScatterCreateToAll(solver%u, solver%to_all, solver%u_all, ierr)
      if (ierr == 0) call create_ksp(solver, PETSC_COMM_WORLD, ierr)
   end subroutine create_distributed

   !> Whether this process owns PETSc row `row` (0-based).
   pure logical function owned_row(solver, row)
      class(petsc_solver_t), intent(in) :: solver
      PetscInt, intent(in) :: row
      owned_row = row >= solver%first_row .and. row <= solver%last_row
   end function owned_row

   !> The KSP on solver%a with frix's defaults (MUMPS LU) overridden by the PETSc options.
   subroutine create_ksp(solver, communicator, ierr)
      class(petsc_solver_t), intent(inout) :: solver
      MPI_Comm, intent(in) :: communicator
      PetscErrorCode, intent(out) :: ierr
      type(tPC) :: pc
      call KSPCreate(communicator, solver%ksp, ierr)
      if (ierr == 0) call KSPSetOperators(solver%ksp, solver%a, solver%a, ierr)
      if (ierr == 0) call KSPSetType(solver%ksp, KSPPREONLY, ierr)
      if (ierr == 0) call KSPGetPC(solver%ksp, pc, ierr)
      if (ierr == 0) call PCSetType(pc, PCLU, ierr)
      if (ierr == 0) call PCFactorSetMatSolverType(pc, MATSOLVERMUMPS, ierr)
      if (ierr == 0) call KSPSetFromOptions(solver%ksp, ierr)
   end subroutine create_ksp

   !> This process's share of the values (solver%row_values, compressed rows of frix's
   !> equations; columns in PETSc's numbering) added to the zeroed distributed matrix, which
   !> is then assembled.
   subroutine add_share(solver, ierr)
      class(petsc_solver_t), intent(inout) :: solver
      PetscErrorCode, intent(out) :: ierr
      PetscInt :: r, row(1), p, first, last, k, n
      PetscInt, allocatable :: held_columns(:)
      PetscScalar, allocatable :: held_values(:)
      call MatZeroEntries(solver%a, ierr)
      n = ubound(solver%row_ptr, 1)
      allocate (held_columns(maxval(solver%row_ptr(1:n) - solver%row_ptr(0:n - 1))))
      allocate (held_values(size(held_columns)))
      do r = 0, n - 1
         row(1) = solver%petsc_row(r)
         first = solver%row_ptr(r) + 1
         last = solver%row_ptr(r + 1)
         if (owned_row(solver, row(1))) then
            call MatSetValues(solver%a, 1, row, last - first + 1, solver%columns(first:last), &
                              solver%row_values(first:last), ADD_VALUES, ierr)
         else
            k = 0
            do p = first, last
               if (solver%row_values(p) == 0.0_dp) cycle
               k = k + 1
               held_columns(k) = solver%columns(p)
               held_values(k) = solver%row_values(p)
            end do
            if (k > 0) call MatSetValues(solver%a, 1, row, k, held_columns(:k), held_values(:k), ADD_VALUES, ierr)
         end if
         if (ierr /= 0) return
      end do
      call MatAssemblyBegin(solver%a, MAT_FINAL_ASSEMBLY, ierr)
      call MatAssemblyEnd(solver%a, MAT_FINAL_ASSEMBLY, ierr)
   end subroutine add_share

   !> set_rigid_body_modes on the distributed rows: the positions of this process's nodes, in
   !> PETSc's numbering.
   subroutine set_distributed_rigid_body_modes(solver, m, n, ierr)
      class(petsc_solver_t), intent(inout) :: solver
      PetscInt, intent(in) :: m
      integer, intent(in) :: n
      PetscErrorCode, intent(out) :: ierr
      type(tVec) :: positions
      type(tMatNullSpace) :: modes
      PetscScalar, pointer :: local(:)
      call VecCreateMPI(PETSC_COMM_WORLD, m, int(n, kind(m)), positions, ierr)
      if (ierr == 0) call VecSetBlockSize(positions, 3, ierr)
      if (ierr == 0) call VecGetArrayF90(positions, local, ierr)
      if (ierr /= 0) return
      local = solver%coords(solver%owned_equations)
      call VecRestoreArrayF90(positions, local, ierr)
      if (ierr == 0) call MatNullSpaceCreateRigidBody(positions, modes, ierr)
      if (ierr == 0) call MatSetNearNullSpace(solver%a, modes, ierr)
      if (ierr == 0) call MatNullSpaceDestroy(modes, ierr)
      if (ierr == 0) call VecDestroy(positions, ierr)
   end subroutine set_distributed_rigid_body_modes

   !> KSPSolve of a parallel run: this process's rows of rhs (whole on every process) into the
   !> distributed right-hand side, the solution copied to every process (VecScatterCreateToAll,
   !> in PETSc's numbering) and put back in frix's.
   subroutine solve_distributed(solver, rhs, x, reason)
      class(petsc_solver_t), intent(inout) :: solver
      real(dp), intent(in) :: rhs(:)
      real(dp), intent(out) :: x(:)
      KSPConvergedReason, intent(out) :: reason
      PetscScalar, pointer :: local(:)
      PetscErrorCode :: ierr
      call VecGetArrayF90(solver%b, local, ierr)
      local = rhs(solver%owned_equations)
      call VecRestoreArrayF90(solver%b, local, ierr)
      call KSPSolve(solver%ksp, solver%b, solver%u, ierr)
      call KSPGetConvergedReason(solver%ksp, reason, ierr)
      call VecScatterBegin(solver%to_all, solver%u, solver%u_all, INSERT_VALUES, SCATTER_FORWARD, ierr)
      call VecScatterEnd(solver%to_all, solver%u, solver%u_all, INSERT_VALUES, SCATTER_FORWARD, ierr)
      call VecGetArrayReadF90(solver%u_all, local, ierr)
      x = local(solver%petsc_row + 1)
      call VecRestoreArrayReadF90(solver%u_all, local, ierr)
   end subroutine solve_distributed

   subroutine release(solver)
      class(petsc_solver_t), intent(inout) :: solver
      PetscErrorCode :: ierr
      if (solver%created) then
         call KSPDestroy(solver%ksp, ierr)
         call MatDestroy(solver%a, ierr)
      end if
      if (solver%created .and. solver%distributed) then
         call VecScatterDestroy(solver%to_all, ierr)
         call VecDestroy(solver%b, ierr)
         call VecDestroy(solver%u, ierr)
         call VecDestroy(solver%u_all, ierr)
      end if
      solver%distributed = .false.
      solver%created = .false.
      solver%analysed_pattern_id = 0
      solver%factorized_pattern_id = 0
   end subroutine release
#else
   function description(solver) result(text)
      class(petsc_solver_t), intent(in) :: solver
      character(len=:), allocatable :: text
      text = solver%name()
   end function description

   subroutine finish_petsc()
   end subroutine finish_petsc

   subroutine factorize(solver, matrix, error)
      class(petsc_solver_t), intent(inout) :: solver
      class(system_matrix_t), intent(in), target :: matrix
      type(error_t), allocatable, intent(out) :: error
      solver%failure = solver_failed
      call fatal_error(error, 'SOLVER Petsc: this frix was built without PETSc (scripts/setup.sh --petsc '// &
                       'builds one with it: CMake option FRIX_PETSC=ON)')
   end subroutine factorize

   subroutine solve(solver, matrix, rhs, x, error)
      class(petsc_solver_t), intent(inout) :: solver
      class(system_matrix_t), intent(in), target :: matrix
      real(dp), intent(in), target :: rhs(:)
      real(dp), intent(out), target :: x(:)
      type(error_t), allocatable, intent(out) :: error
      x = 0.0_dp
      call fatal_error(error, 'SOLVER Petsc: this frix was built without PETSc')
   end subroutine solve

   subroutine release(solver)
      class(petsc_solver_t), intent(inout) :: solver
      solver%analysed_pattern_id = 0
      solver%factorized_pattern_id = 0
   end subroutine release
#endif
end module frix_petsc_solver
