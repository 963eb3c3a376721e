!> Sparse LU (UMFPACK's 64-bit interface `umfpack_dl_*`, SuiteSparse 5.12) for unsymmetric
!> systems, bound directly through iso_c_binding: CSC is UMFPACK's native format (Ap = col_ptr,
!> Ai = row_index, Ax = values, 0-based SuiteSparse_long = int64). Ordering: METIS
!> (UMFPACK_ORDERING_METIS) with UMFPACK's automatic strategy, which takes the symmetric one for
!> the structurally symmetric node-block pattern; no iterative refinement. The Symbolic object
!> is reused while the matrix pattern_id is unchanged.
!>
!> Control/Info indices below are the C constants of umfpack.h; the Fortran arrays are
!> 1-based, so C index k is element k+1.
!> Do not copy an umfpack_solver_t (assignment would share the Symbolic/Numeric objects).
module frix_umfpack_solver
   use, intrinsic :: iso_c_binding, only: c_int64_t, c_double, c_ptr, c_null_ptr, c_associated, c_loc
   use frix_kinds, only: dp, i8
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_system_matrix, only: system_matrix_t
   use frix_sparse_matrix, only: sparse_matrix_t
   use frix_linear_solver, only: linear_solver_t, wall_clock_seconds, singular_matrix_message, begin_factorize, &
                                 check_solve_sizes, csc_matrix, add_elapsed_seconds, pivot_ratio_detail, failure_of_size, &
                                 solver_singular, solver_out_of_memory, solver_failed
   implicit none
   private

   public :: umfpack_solver_t
   public :: umfpack_strategy_auto, umfpack_strategy_unsymmetric, umfpack_strategy_symmetric
   public :: umfpack_ordering_amd, umfpack_ordering_metis

   integer, parameter :: umfpack_control = 20                  !! UMFPACK_CONTROL
   integer, parameter :: umfpack_info = 90                     !! UMFPACK_INFO
   integer, parameter :: umfpack_strategy = 5                  !! Control index UMFPACK_STRATEGY
   integer, parameter :: umfpack_irstep = 7                    !! Control index UMFPACK_IRSTEP
   integer, parameter :: umfpack_ordering = 10                 !! Control index UMFPACK_ORDERING
   integer, parameter :: umfpack_strategy_auto = 0             !! UMFPACK_STRATEGY_AUTO
   integer, parameter :: umfpack_strategy_unsymmetric = 1      !! UMFPACK_STRATEGY_UNSYMMETRIC
   integer, parameter :: umfpack_strategy_symmetric = 3        !! UMFPACK_STRATEGY_SYMMETRIC
   integer, parameter :: umfpack_ordering_amd = 1              !! UMFPACK_ORDERING_AMD (AMD or COLAMD)
   integer, parameter :: umfpack_ordering_metis = 3            !! UMFPACK_ORDERING_METIS
   integer, parameter :: umfpack_size_of_unit = 3              !! Info index UMFPACK_SIZE_OF_UNIT
   integer, parameter :: umfpack_peak_memory = 41              !! Info index UMFPACK_PEAK_MEMORY (units)
   integer, parameter :: umfpack_lnz = 43                      !! Info index UMFPACK_LNZ
   integer, parameter :: umfpack_unz = 44                      !! Info index UMFPACK_UNZ
   integer, parameter :: umfpack_rcond = 67                    !! Info index UMFPACK_RCOND (min/max |u_kk|)
   integer(c_int64_t), parameter :: umfpack_ok = 0             !! UMFPACK_OK
   integer(c_int64_t), parameter :: umfpack_warning_singular_matrix = 1  !! UMFPACK_WARNING_singular_matrix
   integer(c_int64_t), parameter :: umfpack_error_out_of_memory = -1     !! UMFPACK_ERROR_out_of_memory
   integer(c_int64_t), parameter :: umfpack_system_a = 0       !! UMFPACK_A: solve A x = b

   !> UMFPACK behind linear_solver_t.
   type, extends(linear_solver_t) :: umfpack_solver_t
      type(c_ptr), private :: symbolic = c_null_ptr
      type(c_ptr), private :: numeric = c_null_ptr
      real(c_double), private :: control(umfpack_control) = 0.0_c_double
      real(c_double) :: info(umfpack_info) = 0.0_c_double   !! UMFPACK Info of the last call
      !> Control settings, read at the next symbolic analysis (docs/performance.md, "UMFPACK
      !> on the unsymmetric path", for the measurements behind the defaults).
      integer :: strategy = umfpack_strategy_auto   !! UMFPACK_STRATEGY: umfpack_strategy_*
      integer :: ordering = umfpack_ordering_metis  !! UMFPACK_ORDERING: umfpack_ordering_*
      !> UMFPACK_IRSTEP: iterative refinement steps per solve (UMFPACK's default 2); none, as the
      !> Newton iteration corrects the same residual anyway
      integer :: refinement_steps = 0
   contains
      procedure :: name
      procedure :: factorize
      procedure :: solve
      procedure :: release
      final :: finalize
   end type umfpack_solver_t

   interface
      subroutine umfpack_dl_defaults(control) bind(C, name='umfpack_dl_defaults')
         import :: c_double
         real(c_double), intent(out) :: control(*)
      end subroutine umfpack_dl_defaults

      function umfpack_dl_symbolic(n_row, n_col, ap, ai, ax, symbolic, control, info) &
         bind(C, name='umfpack_dl_symbolic') result(status)
         import :: c_int64_t, c_double, c_ptr
         integer(c_int64_t), value :: n_row, n_col
         integer(c_int64_t), intent(in) :: ap(*), ai(*)
         real(c_double), intent(in) :: ax(*)
         type(c_ptr), intent(out) :: symbolic
         real(c_double), intent(in) :: control(*)
         real(c_double), intent(out) :: info(*)
         integer(c_int64_t) :: status
      end function umfpack_dl_symbolic

      function umfpack_dl_numeric(ap, ai, ax, symbolic, numeric, control, info) &
         bind(C, name='umfpack_dl_numeric') result(status)
         import :: c_int64_t, c_double, c_ptr
         integer(c_int64_t), intent(in) :: ap(*), ai(*)
         real(c_double), intent(in) :: ax(*)
         type(c_ptr), value :: symbolic
         type(c_ptr), intent(out) :: numeric
         real(c_double), intent(in) :: control(*)
         real(c_double), intent(out) :: info(*)
         integer(c_int64_t) :: status
      end function umfpack_dl_numeric

      function umfpack_dl_solve(system, ap, ai, ax, x, b, numeric, control, info) &
         bind(C, name='umfpack_dl_solve') result(status)
         import :: c_int64_t, c_double, c_ptr
         integer(c_int64_t), value :: system
         integer(c_int64_t), intent(in) :: ap(*), ai(*)
         real(c_double), intent(in) :: ax(*)
         real(c_double), intent(out) :: x(*)
         real(c_double), intent(in) :: b(*)
         type(c_ptr), value :: numeric
         real(c_double), intent(in) :: control(*)
         real(c_double), intent(out) :: info(*)
         integer(c_int64_t) :: status
      end function umfpack_dl_solve

      subroutine umfpack_dl_free_symbolic(symbolic) bind(C, name='umfpack_dl_free_symbolic')
         import :: c_ptr
         type(c_ptr), intent(inout) :: symbolic
      end subroutine umfpack_dl_free_symbolic

      subroutine umfpack_dl_free_numeric(numeric) bind(C, name='umfpack_dl_free_numeric')
         import :: c_ptr
         type(c_ptr), intent(inout) :: numeric
      end subroutine umfpack_dl_free_numeric

      !> Every array argument may be NULL (not returned); used here for Q and diag(U) only.
      function umfpack_dl_get_numeric(lp, lj, lx, up, ui, ux, p, q, dx, do_recip, rs, numeric) &
         bind(C, name='umfpack_dl_get_numeric') result(status)
         import :: c_int64_t, c_ptr
         type(c_ptr), value :: lp, lj, lx, up, ui, ux, p, q, dx, do_recip, rs
         type(c_ptr), value :: numeric
         integer(c_int64_t) :: status
      end function umfpack_dl_get_numeric
   end interface

contains

   function name(solver) result(keyword)
      class(umfpack_solver_t), intent(in) :: solver
      character(len=:), allocatable :: keyword
      keyword = 'UMFPACK'
   end function name

   !> umfpack_dl_symbolic when the pattern changed, then umfpack_dl_numeric. A singular
   !> matrix (UMFPACK_WARNING_singular_matrix, or min/max |u_kk| below singular_pivot_ratio)
   !> gives an error naming the original column of the smallest pivot.
   subroutine factorize(solver, matrix, error)
      class(umfpack_solver_t), intent(inout) :: solver
      class(system_matrix_t), intent(in), target :: matrix
      type(error_t), allocatable, intent(out) :: error
      integer(c_int64_t) :: status
      real(dp) :: start
      type(sparse_matrix_t), pointer :: csc
      integer(i8), pointer, contiguous :: col_ptr(:), row_index(:)
      real(dp), pointer, contiguous :: values(:)

      call begin_factorize(solver, matrix, error)
      if (.not. allocated(error)) call csc_matrix(solver, matrix, csc, error)
      if (allocated(error)) return
      call csc%csc_arrays(col_ptr, row_index, values)
      if (c_associated(solver%numeric)) call umfpack_dl_free_numeric(solver%numeric)

      if (matrix%pattern_id /= solver%analysed_pattern_id) then
         if (c_associated(solver%symbolic)) call umfpack_dl_free_symbolic(solver%symbolic)
         solver%analysed_pattern_id = 0
         call umfpack_dl_defaults(solver%control)
         solver%control(umfpack_strategy + 1) = real(solver%strategy, c_double)
         solver%control(umfpack_ordering + 1) = real(solver%ordering, c_double)
         solver%control(umfpack_irstep + 1) = real(solver%refinement_steps, c_double)
         start = wall_clock_seconds()
         status = umfpack_dl_symbolic(int(matrix%n, c_int64_t), int(matrix%n, c_int64_t), col_ptr, &
                                      row_index, values, solver%symbolic, solver%control, solver%info)
         call add_elapsed_seconds(start, solver%last_analyse_seconds, solver%analyse_seconds)
         if (status /= umfpack_ok) then
            call umfpack_failure(error, status, 'symbolic analysis', matrix%n, solver%failure)
            return
         end if
         solver%n_analyses = solver%n_analyses + 1
         solver%analysed_pattern_id = matrix%pattern_id
      end if

      start = wall_clock_seconds()
      status = umfpack_dl_numeric(col_ptr, row_index, values, solver%symbolic, &
                                  solver%numeric, solver%control, solver%info)
      call add_elapsed_seconds(start, solver%last_factorize_seconds, solver%factorize_seconds, solver%n_factorizations)
      solver%peak_memory_bytes = int(solver%info(umfpack_peak_memory + 1)*solver%info(umfpack_size_of_unit + 1), i8)
      solver%factor_entries = int(solver%info(umfpack_lnz + 1) + solver%info(umfpack_unz + 1), i8)

      if (status == umfpack_warning_singular_matrix) then
         solver%failure = solver_singular
         solver%failed_equation = smallest_pivot_column(solver, matrix%n)
         call singular_matrix_message(error, 'UMFPACK', 'singular', solver%failed_equation, 'zero pivot')
         return
      else if (status /= umfpack_ok .and. status < 0) then
         call umfpack_failure(error, status, 'numeric factorization', matrix%n, solver%failure)
         return
      end if
      if (.not. (solver%info(umfpack_rcond + 1) > solver%singular_pivot_ratio)) then
         solver%failure = solver_singular
         solver%failed_equation = smallest_pivot_column(solver, matrix%n)
         call singular_matrix_message(error, 'UMFPACK', 'singular', solver%failed_equation, &
                                      pivot_ratio_detail(real(solver%info(umfpack_rcond + 1), dp), &
                                                         solver%singular_pivot_ratio))
         return
      end if
      solver%factorized_pattern_id = matrix%pattern_id
   end subroutine factorize

   !> The error and failure kind of a failed UMFPACK status in `stage` for n equations: out of
   !> memory (UMFPACK_ERROR_out_of_memory; with 64-bit indices no factor that fits in memory
   !> overflows them), or any other status.
   subroutine umfpack_failure(error, status, stage, n, failure)
      type(error_t), allocatable, intent(out) :: error
      integer(c_int64_t), intent(in) :: status
      character(len=*), intent(in) :: stage
      integer, intent(in) :: n
      integer, intent(out) :: failure
      if (status == umfpack_error_out_of_memory) then
         failure = solver_out_of_memory
         call failure_of_size(error, 'UMFPACK', failure, stage, n, 0.0_dp, '')
      else
         failure = solver_failed
         call fatal_error(error, 'UMFPACK: '//stage//' failed, status '//to_string(int(status)))
      end if
   end subroutine umfpack_failure

   !> 1-based original column of the pivot of smallest |u_kk| (column permutation Q of
   !> P R A Q = L U), 0 if UMFPACK cannot return it.
   function smallest_pivot_column(solver, n) result(column)
      class(umfpack_solver_t), intent(in) :: solver
      integer, intent(in) :: n
      integer :: column
      integer(c_int64_t), allocatable, target :: q(:)
      real(c_double), allocatable, target :: diagonal(:)
      integer(c_int64_t) :: status
      allocate (q(n), diagonal(n))
      column = 0
      status = umfpack_dl_get_numeric(c_null_ptr, c_null_ptr, c_null_ptr, c_null_ptr, c_null_ptr, c_null_ptr, &
                                      c_null_ptr, c_loc(q), c_loc(diagonal), c_null_ptr, c_null_ptr, solver%numeric)
      if (status /= umfpack_ok) return
      column = int(q(minloc(abs(diagonal), dim=1))) + 1
   end function smallest_pivot_column

   subroutine solve(solver, matrix, rhs, x, error)
      class(umfpack_solver_t), intent(inout) :: solver
      class(system_matrix_t), intent(in), target :: matrix
      real(dp), intent(in), target :: rhs(:)
      real(dp), intent(out), target :: x(:)
      type(error_t), allocatable, intent(out) :: error
      integer(c_int64_t) :: status
      real(dp) :: start
      type(sparse_matrix_t), pointer :: csc
      integer(i8), pointer, contiguous :: col_ptr(:), row_index(:)
      real(dp), pointer, contiguous :: values(:)

      call check_solve_sizes(solver, matrix, size(rhs), size(x), error)
      if (.not. allocated(error)) call csc_matrix(solver, matrix, csc, error)
      if (allocated(error)) return
      call csc%csc_arrays(col_ptr, row_index, values)
      start = wall_clock_seconds()
      status = umfpack_dl_solve(umfpack_system_a, col_ptr, row_index, values, x, rhs, &
                                solver%numeric, solver%control, solver%info)
      call add_elapsed_seconds(start, solver%last_solve_seconds, solver%solve_seconds, solver%n_solves)
      if (status /= umfpack_ok) call fatal_error(error, 'UMFPACK: solve failed, status '//to_string(int(status)))
   end subroutine solve

   !> Free Numeric and Symbolic; the next factorize analyses again.
   subroutine release(solver)
      class(umfpack_solver_t), intent(inout) :: solver
      if (c_associated(solver%numeric)) call umfpack_dl_free_numeric(solver%numeric)
      if (c_associated(solver%symbolic)) call umfpack_dl_free_symbolic(solver%symbolic)
      solver%numeric = c_null_ptr
      solver%symbolic = c_null_ptr
      solver%analysed_pattern_id = 0
      solver%factorized_pattern_id = 0
   end subroutine release

   subroutine finalize(solver)
      type(umfpack_solver_t), intent(inout) :: solver
      call solver%release()
   end subroutine finalize
end module frix_umfpack_solver
