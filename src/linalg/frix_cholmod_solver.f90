!> Sparse Cholesky (CHOLMOD, SuiteSparse 5.12, supernodal LL', its 64-bit interface
!> `cholmod_l_*`) for symmetric positive definite systems. Only the upper triangle of the full
!> CSC storage is read (stype = 1). The
!> fill-reducing ordering is METIS nested dissection of the node graph
!> (frix_metis_ordering), handed to CHOLMOD as a user permutation. cholmod_common lives in
!> the C glue cholmod_shim.c behind an opaque handle.
!>
!> Do not copy a cholmod_solver_t (assignment would share the handle); pass it around.
module frix_cholmod_solver
   use, intrinsic :: iso_c_binding, only: c_int, c_int64_t, c_double, c_ptr, c_null_ptr, c_associated
   use frix_kinds, only: dp, i8
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_system_matrix, only: system_matrix_t
   use frix_sparse_matrix, only: sparse_matrix_t
   use frix_linear_solver, only: linear_solver_t, wall_clock_seconds, singular_matrix_message, begin_factorize, &
                                 check_solve_sizes, csc_matrix, add_elapsed_seconds, pivot_ratio_detail, failure_of_size, &
                                 solver_not_positive_definite, solver_too_large, solver_out_of_memory, solver_failed
   use frix_metis_ordering, only: metis_dof_permutation
   implicit none
   private

   public :: cholmod_solver_t, cholmod_failure

   !> Common->status values of cholmod_core.h (SuiteSparse 5.12)
   integer(c_int), parameter :: cholmod_not_posdef = 1, cholmod_out_of_memory = -2, cholmod_too_large = -3
   !> CHOLMOD_TOO_LARGE from the 64-bit interface: a size overflowed its integers (size_t,
   !> SuiteSparse_long), which no factor that fits in memory reaches
   character(len=*), parameter :: cholmod_limit = 'the size of the factor overflows CHOLMOD''s 64-bit integers'

   !> CHOLMOD behind linear_solver_t.
   type, extends(linear_solver_t) :: cholmod_solver_t
      type(c_ptr), private :: handle = c_null_ptr   !! frix_cholmod_t* of cholmod_shim.c
   contains
      procedure :: name
      procedure :: factorize
      procedure :: solve
      procedure :: release
      final :: finalize
   end type cholmod_solver_t

   interface
      function frix_cholmod_create() bind(C, name='frix_cholmod_create') result(handle)
         import :: c_ptr
         type(c_ptr) :: handle
      end function frix_cholmod_create

      subroutine frix_cholmod_destroy(handle) bind(C, name='frix_cholmod_destroy')
         import :: c_ptr
         type(c_ptr), value :: handle
      end subroutine frix_cholmod_destroy

      function frix_cholmod_analyse(handle, n, col_ptr, row_index, values, permutation, lnz) &
         bind(C, name='frix_cholmod_analyse') result(status)
         import :: c_ptr, c_int, c_int64_t, c_double
         type(c_ptr), value :: handle
         integer(c_int64_t), value :: n
         integer(c_int64_t), intent(in) :: col_ptr(*), row_index(*), permutation(*)
         real(c_double), intent(in) :: values(*)
         real(c_double), intent(out) :: lnz
         integer(c_int) :: status
      end function frix_cholmod_analyse

      function frix_cholmod_factorize(handle, n, col_ptr, row_index, values, failed, min_pivot, max_pivot) &
         bind(C, name='frix_cholmod_factorize') result(status)
         import :: c_ptr, c_int, c_int64_t, c_double
         type(c_ptr), value :: handle
         integer(c_int64_t), value :: n
         integer(c_int64_t), intent(in) :: col_ptr(*), row_index(*)
         real(c_double), intent(in) :: values(*)
         integer(c_int64_t), intent(out) :: failed
         real(c_double), intent(out) :: min_pivot, max_pivot
         integer(c_int) :: status
      end function frix_cholmod_factorize

      function frix_cholmod_solve(handle, n, rhs, x) bind(C, name='frix_cholmod_solve') result(status)
         import :: c_ptr, c_int, c_int64_t, c_double
         type(c_ptr), value :: handle
         integer(c_int64_t), value :: n
         real(c_double), intent(in) :: rhs(*)
         real(c_double), intent(out) :: x(*)
         integer(c_int) :: status
      end function frix_cholmod_solve

      subroutine frix_cholmod_memory(handle, peak, in_use) bind(C, name='frix_cholmod_memory')
         import :: c_ptr, c_double
         type(c_ptr), value :: handle
         real(c_double), intent(out) :: peak, in_use
      end subroutine frix_cholmod_memory
   end interface

contains

   function name(solver) result(keyword)
      class(cholmod_solver_t), intent(in) :: solver
      character(len=:), allocatable :: keyword
      keyword = 'CHOLMOD'
   end function name

   !> METIS ordering + symbolic analysis when the pattern changed, then numeric LL'.
   !> Not positive definite (failed pivot) or a pivot ratio below singular_pivot_ratio gives
   !> an error naming the original equation.
   subroutine factorize(solver, matrix, error)
      class(cholmod_solver_t), intent(inout) :: solver
      class(system_matrix_t), intent(in), target :: matrix
      type(error_t), allocatable, intent(out) :: error
      integer(i8), allocatable :: permutation(:)
      integer(c_int) :: status
      integer(c_int64_t) :: failed
      real(c_double) :: lnz, min_pivot, max_pivot, peak, in_use
      real(dp) :: start
      type(sparse_matrix_t), pointer :: csc
      integer(i8), pointer, contiguous :: col_ptr(:), row_index(:)
      real(dp), pointer, contiguous :: values(:)

      call begin_factorize(solver, matrix, error)
      if (.not. allocated(error)) call csc_matrix(solver, matrix, csc, error)
      if (allocated(error)) return
      call csc%csc_arrays(col_ptr, row_index, values)
      if (.not. c_associated(solver%handle)) solver%handle = frix_cholmod_create()
      if (.not. c_associated(solver%handle)) then
         call fatal_error(error, 'CHOLMOD: out of memory creating cholmod_common')
         return
      end if

      if (matrix%pattern_id /= solver%analysed_pattern_id) then
         start = wall_clock_seconds()
         solver%analysed_pattern_id = 0
         call metis_dof_permutation(csc, permutation, error)
         if (allocated(error)) return
         status = frix_cholmod_analyse(solver%handle, int(matrix%n, c_int64_t), col_ptr, row_index, &
                                       values, permutation, lnz)
         call add_elapsed_seconds(start, solver%last_analyse_seconds, solver%analyse_seconds)
         if (status < 0) then
            call cholmod_failure(error, status, 'symbolic analysis', matrix%n, lnz, solver%failure)
            return
         end if
         solver%n_analyses = solver%n_analyses + 1
         solver%analysed_pattern_id = matrix%pattern_id
         solver%factor_entries = int(lnz, i8)
      end if

      start = wall_clock_seconds()
      status = frix_cholmod_factorize(solver%handle, int(matrix%n, c_int64_t), col_ptr, row_index, &
                                      values, failed, min_pivot, max_pivot)
      call add_elapsed_seconds(start, solver%last_factorize_seconds, solver%factorize_seconds, solver%n_factorizations)
      call frix_cholmod_memory(solver%handle, peak, in_use)
      solver%peak_memory_bytes = int(peak, i8)

      if (status == cholmod_not_posdef) then
         solver%failure = solver_not_positive_definite
         solver%failed_equation = int(failed) + 1
         if (failed < 0) solver%failed_equation = 0
         call singular_matrix_message(error, 'CHOLMOD', 'singular or not positive definite', &
                                      solver%failed_equation, 'zero or negative pivot')
         return
      else if (status < 0) then
         call cholmod_failure(error, status, 'numeric factorization', matrix%n, real(solver%factor_entries, dp), &
                              solver%failure)
         return
      end if
      if (.not. (min_pivot > solver%singular_pivot_ratio*max_pivot)) then
         ! (LL' cannot tell a singular matrix from an indefinite one: UMFPACK may)
         solver%failure = solver_not_positive_definite
         solver%failed_equation = int(failed) + 1
         call singular_matrix_message(error, 'CHOLMOD', 'singular or not positive definite', &
                                      solver%failed_equation, &
                                      pivot_ratio_detail(real(min_pivot/max(max_pivot, tiny(1.0_dp)), dp), &
                                                         solver%singular_pivot_ratio))
         return
      end if
      solver%factorized_pattern_id = matrix%pattern_id
   end subroutine factorize

   !> The error and failure kind of a negative CHOLMOD status (too large, out of memory,
   !> other) in `stage`, for a system of n equations whose factor has `factor_entries`
   !> entries (0 if unknown).
   subroutine cholmod_failure(error, status, stage, n, factor_entries, failure)
      type(error_t), allocatable, intent(out) :: error
      integer(c_int), intent(in) :: status
      character(len=*), intent(in) :: stage
      integer, intent(in) :: n
      real(dp), intent(in) :: factor_entries
      integer, intent(out) :: failure
      select case (status)
      case (cholmod_too_large)
         failure = solver_too_large
      case (cholmod_out_of_memory)
         failure = solver_out_of_memory
      case default
         failure = solver_failed
         call fatal_error(error, 'CHOLMOD: '//stage//' failed, status '//to_string(int(status)))
         return
      end select
      call failure_of_size(error, 'CHOLMOD', failure, stage, n, factor_entries, cholmod_limit)
   end subroutine cholmod_failure

   subroutine solve(solver, matrix, rhs, x, error)
      class(cholmod_solver_t), intent(inout) :: solver
      class(system_matrix_t), intent(in), target :: matrix
      real(dp), intent(in), target :: rhs(:)
      real(dp), intent(out), target :: x(:)
      type(error_t), allocatable, intent(out) :: error
      integer(c_int) :: status
      real(dp) :: start

      call check_solve_sizes(solver, matrix, size(rhs), size(x), error)
      if (allocated(error)) return
      start = wall_clock_seconds()
      status = frix_cholmod_solve(solver%handle, int(matrix%n, c_int64_t), rhs, x)
      call add_elapsed_seconds(start, solver%last_solve_seconds, solver%solve_seconds, solver%n_solves)
      if (status < 0) call fatal_error(error, 'CHOLMOD: solve failed, status '//to_string(int(status)))
   end subroutine solve

   !> Free factor and cholmod_common; the next factorize starts afresh (new analysis).
   subroutine release(solver)
      class(cholmod_solver_t), intent(inout) :: solver
      if (c_associated(solver%handle)) call frix_cholmod_destroy(solver%handle)
      solver%handle = c_null_ptr
      solver%analysed_pattern_id = 0
      solver%factorized_pattern_id = 0
   end subroutine release

   subroutine finalize(solver)
      type(cholmod_solver_t), intent(inout) :: solver
      call solver%release()
   end subroutine finalize
end module frix_cholmod_solver
