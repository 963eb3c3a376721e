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
!> elasticity, PETSc manual, PCGAMG). One process; the distribution over MPI processes is not
!> done yet.
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
      type(tPC) :: pc
      PCFailedReason :: failed
      PetscErrorCode :: ierr
      real(dp) :: start

      call begin_factorize(solver, matrix, error)
      if (.not. allocated(error)) call csc_matrix(solver, matrix, csc, error)
      if (.not. allocated(error)) call start_petsc(error)
      if (allocated(error)) return
      call csc%csc_arrays(col_ptr, row_index, values)
      start = wall_clock_seconds()
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
         if (ierr == 0) call KSPCreate(PETSC_COMM_SELF, solver%ksp, ierr)
         if (ierr == 0) call KSPSetOperators(solver%ksp, solver%a, solver%a, ierr)
         if (ierr == 0) call KSPSetType(solver%ksp, KSPPREONLY, ierr)
         if (ierr == 0) call KSPGetPC(solver%ksp, pc, ierr)
         if (ierr == 0) call PCSetType(pc, PCLU, ierr)
         if (ierr == 0) call PCFactorSetMatSolverType(pc, MATSOLVERMUMPS, ierr)
         if (ierr == 0) call KSPSetFromOptions(solver%ksp, ierr)
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
      call KSPSetUp(solver%ksp, ierr)
      call add_elapsed_seconds(start, solver%last_factorize_seconds, solver%factorize_seconds, solver%n_factorizations)
      call KSPGetPC(solver%ksp, pc, ierr)
      call PCGetFailedReason(pc, failed, ierr)
      if (failed /= PC_NOERROR .or. ierr /= 0) then
         solver%failure = solver_singular
         call singular_matrix_message(error, 'PETSC', 'singular', 0, &
                                      'the preconditioner failed (PCFailedReason '//to_string(int(failed))//')')
         return
      end if
      solver%factorized_pattern_id = matrix%pattern_id
   end subroutine factorize

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
      call VecCreateSeqWithArray(PETSC_COMM_SELF, 1, int(matrix%n, kind(solver%row_ptr)), rhs, b, ierr)
      call VecCreateSeqWithArray(PETSC_COMM_SELF, 1, int(matrix%n, kind(solver%row_ptr)), x, u, ierr)
      call KSPSolve(solver%ksp, b, u, ierr)
      call KSPGetConvergedReason(solver%ksp, reason, ierr)
      call VecDestroy(b, ierr)
      call VecDestroy(u, ierr)
      call add_elapsed_seconds(start, solver%last_solve_seconds, solver%solve_seconds, solver%n_solves)
      if (reason < 0) call fatal_error(error, 'PETSC: the KSP did not converge (KSPConvergedReason '// &
                                       to_string(int(reason))//')')
   end subroutine solve

   subroutine release(solver)
      class(petsc_solver_t), intent(inout) :: solver
      PetscErrorCode :: ierr
      if (solver%created) then
         call KSPDestroy(solver%ksp, ierr)
         call MatDestroy(solver%a, ierr)
      end if
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
