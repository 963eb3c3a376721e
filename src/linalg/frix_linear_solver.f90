!> The one interface of the linear solvers (one concrete type per file behind it: CHOLMOD,
!> UMFPACK, and the guarded CHOLMOD of frix_auto_solver; the registry frix_linear_solver_registry). Usage: `factorize(matrix, error)` after every change of values (the
!> symbolic analysis is redone only when `matrix%pattern_id` changed), then any number of
!> `solve(matrix, rhs, x, error)`; `release()` frees the factors.
module frix_linear_solver
   use frix_kinds, only: dp, i8
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_system_matrix, only: system_matrix_t
   use frix_sparse_matrix, only: sparse_matrix_t
   implicit none
   private

   public :: linear_solver_t, wall_clock_seconds, singular_matrix_message
   public :: begin_factorize, check_solve_sizes, csc_matrix, add_elapsed_seconds, pivot_ratio_detail
   public :: solver_ok, solver_not_positive_definite, solver_singular, solver_too_large, &
             solver_out_of_memory, solver_failed, failure_of_size

   !> What went wrong in the last factorize (linear_solver_t%failure): frix_auto_solver falls
   !> back from CHOLMOD to UMFPACK only for a matrix that is not positive definite; every
   !> other failure is reported as it is.
   integer, parameter :: solver_ok = 0
   integer, parameter :: solver_not_positive_definite = 1  !! a zero or negative Cholesky pivot
   integer, parameter :: solver_singular = 2               !! a zero LU pivot, or pivots below the ratio
   integer, parameter :: solver_too_large = 3              !! beyond the solver's integer range
   integer, parameter :: solver_out_of_memory = 4
   integer, parameter :: solver_failed = 5                 !! any other status of the library

   !> Abstract direct solver. Timings are wall clock seconds (system_clock).
   type, abstract :: linear_solver_t
      real(dp) :: analyse_seconds = 0.0_dp          !! accumulated symbolic analysis time [s]
      real(dp) :: factorize_seconds = 0.0_dp        !! accumulated numeric factorization time [s]
      real(dp) :: solve_seconds = 0.0_dp            !! accumulated solve time [s]
      real(dp) :: last_analyse_seconds = 0.0_dp     !! time of the last analysis [s]
      real(dp) :: last_factorize_seconds = 0.0_dp   !! time of the last factorization [s]
      real(dp) :: last_solve_seconds = 0.0_dp       !! time of the last solve [s]
      integer :: n_analyses = 0                     !! symbolic analyses done
      integer :: n_factorizations = 0               !! numeric factorizations done (successful or not)
      integer :: n_solves = 0                       !! solves done
      !> 1-based equation where a zero/negative/tiny pivot was found by the last factorize,
      !> 0 if none or unknown. Node = (equation-1)/3 + 1, direction = mod(equation-1, 3) + 1.
      integer :: failed_equation = 0
      integer :: failure = solver_ok   !! solver_ok, solver_not_positive_definite, ... of the last factorize
      !> A factorization whose smallest pivot is below `singular_pivot_ratio` times the
      !> largest (|u_kk| for LU, l_kk^2 for Cholesky) is reported as singular: a condition
      !> number above 1/ratio leaves no correct digit worth having in double precision.
      real(dp) :: singular_pivot_ratio = 1.0e-12_dp
      integer(i8) :: peak_memory_bytes = 0          !! peak memory of the solver's last analysis+factorization
      integer(i8) :: factor_entries = 0             !! entries of the factor(s) of the last factorization
      integer :: analysed_pattern_id = 0            !! pattern_id of the matrix analysed last (0: none)
      integer :: factorized_pattern_id = 0          !! pattern_id of the valid factorization (0: none)
   contains
      procedure(name_interface), deferred :: name
      procedure(factorize_interface), deferred :: factorize
      procedure(solve_interface), deferred :: solve
      procedure(release_interface), deferred :: release
      !> Called by the Newton loop at the start of every load increment; no-op by default.
      procedure :: new_matrix
      procedure :: set_node_coordinates
      procedure :: begin_increment
      !> Called by the Newton loop when the matrix about to be factorized is unsymmetric
      !> although the system was expected symmetric; no-op by default.
      procedure :: expect_unsymmetric
      !> What the run's statistics print after "linear solver": the name by default.
      procedure :: description
      !> Adds the solver's (and any inner solver's) accumulated seconds and factorizations.
      procedure :: add_totals
   end type linear_solver_t

   abstract interface
      !> Keyword of the solver ('CHOLMOD', 'UMFPACK').
      function name_interface(solver) result(name)
         import :: linear_solver_t
         class(linear_solver_t), intent(in) :: solver
         character(len=:), allocatable :: name
      end function name_interface

      !> Symbolic analysis when `matrix%pattern_id` differs from the one analysed last, then
      !> numeric factorization. A singular (or, for Cholesky, not positive definite) matrix
      !> gives an error and sets `failed_equation`.
      subroutine factorize_interface(solver, matrix, error)
         import :: linear_solver_t, system_matrix_t, error_t
         class(linear_solver_t), intent(inout) :: solver
         class(system_matrix_t), intent(in), target :: matrix
         type(error_t), allocatable, intent(out) :: error
      end subroutine factorize_interface

      !> x = A^-1 rhs with the factors of the last successful `factorize` of `matrix`.
      subroutine solve_interface(solver, matrix, rhs, x, error)
         import :: linear_solver_t, system_matrix_t, error_t, dp
         class(linear_solver_t), intent(inout) :: solver
         class(system_matrix_t), intent(in), target :: matrix
         real(dp), intent(in), target :: rhs(:)        !! (n)
         real(dp), intent(out), target :: x(:)         !! (n)
         type(error_t), allocatable, intent(out) :: error
      end subroutine solve_interface

      !> Free the factors and the symbolic analysis (the next factorize analyses again).
      subroutine release_interface(solver)
         import :: linear_solver_t
         class(linear_solver_t), intent(inout) :: solver
      end subroutine release_interface
   end interface

contains

   !> A matrix of the storage this solver factorizes, empty (no pattern): the compressed
   !> sparse columns of frix_sparse_matrix for the direct solvers.
   subroutine new_matrix(solver, matrix)
      class(linear_solver_t), intent(in) :: solver
      class(system_matrix_t), allocatable, intent(out) :: matrix
      allocate (sparse_matrix_t :: matrix)
   end subroutine new_matrix

   !> The nodes' positions, for a solver that builds the rigid-body modes (an algebraic
   !> multigrid's near-null space); the direct solvers do not need them.
   subroutine set_node_coordinates(solver, coords)
      class(linear_solver_t), intent(inout) :: solver
      real(dp), intent(in) :: coords(:, :)   !! (3, n_nodes)
   end subroutine set_node_coordinates

   !> `matrix` as the compressed sparse column matrix a direct solver reads; an error naming
   !> the solver for any other storage.
   subroutine csc_matrix(solver, matrix, csc, error)
      class(linear_solver_t), intent(in) :: solver
      class(system_matrix_t), intent(in), target :: matrix
      type(sparse_matrix_t), pointer, intent(out) :: csc
      type(error_t), allocatable, intent(out) :: error
      csc => null()
      select type (matrix)
      type is (sparse_matrix_t)
         csc => matrix
      class default
         call fatal_error(error, solver%name()//': needs the matrix in compressed sparse columns')
      end select
   end subroutine csc_matrix

   subroutine begin_increment(solver)
      class(linear_solver_t), intent(inout) :: solver
   end subroutine begin_increment

   subroutine expect_unsymmetric(solver)
      class(linear_solver_t), intent(inout) :: solver
   end subroutine expect_unsymmetric

   function description(solver) result(text)
      class(linear_solver_t), intent(in) :: solver
      character(len=:), allocatable :: text
      text = solver%name()
   end function description

   subroutine add_totals(solver, analyse, factorize, solve, factorizations)
      class(linear_solver_t), intent(in) :: solver
      real(dp), intent(inout) :: analyse, factorize, solve   !! seconds
      integer, intent(inout) :: factorizations
      analyse = analyse + solver%analyse_seconds
      factorize = factorize + solver%factorize_seconds
      solve = solve + solver%solve_seconds
      factorizations = factorizations + solver%n_factorizations
   end subroutine add_totals

   !> Wall clock time in seconds from an arbitrary origin (system_clock, 64-bit counter).
   function wall_clock_seconds() result(seconds)
      real(dp) :: seconds
      integer(i8) :: count, rate
      call system_clock(count, rate)
      seconds = real(count, dp)/real(rate, dp)
   end function wall_clock_seconds

   !> Common start of every `factorize`: forget the previous factorization (and failed
   !> equation), and give an error if `matrix` has no pattern.
   subroutine begin_factorize(solver, matrix, error)
      class(linear_solver_t), intent(inout) :: solver
      class(system_matrix_t), intent(in) :: matrix
      type(error_t), allocatable, intent(out) :: error
      solver%failed_equation = 0
      solver%failure = solver_ok
      solver%factorized_pattern_id = 0
      if (matrix%pattern_id == 0 .or. matrix%n == 0) then
         solver%failure = solver_failed
         call fatal_error(error, solver%name()//': the matrix has no pattern')
      end if
   end subroutine begin_factorize

   !> Common checks of every `solve`: a valid factorization of this `matrix` exists, and
   !> the right-hand side and solution have its size.
   subroutine check_solve_sizes(solver, matrix, rhs_size, x_size, error)
      class(linear_solver_t), intent(in) :: solver
      class(system_matrix_t), intent(in) :: matrix
      integer, intent(in) :: rhs_size   !! size of the right-hand side
      integer, intent(in) :: x_size     !! size of the solution
      type(error_t), allocatable, intent(out) :: error
      if (solver%factorized_pattern_id == 0 .or. solver%factorized_pattern_id /= matrix%pattern_id) then
         call fatal_error(error, solver%name()//': solve called without a successful factorize of this matrix')
      else if (rhs_size /= matrix%n .or. x_size /= matrix%n) then
         call fatal_error(error, solver%name()//': right-hand side or solution size differs from '// &
                          to_string(matrix%n))
      end if
   end subroutine check_solve_sizes

   !> Wall clock seconds since `start` (from wall_clock_seconds) into `last`, added to `total`;
   !> `count`, when present, is incremented (phases counted whether they succeeded or not).
   subroutine add_elapsed_seconds(start, last, total, count)
      real(dp), intent(in) :: start     !! wall_clock_seconds() at the start of the phase [s]
      real(dp), intent(out) :: last     !! duration of the phase [s]
      real(dp), intent(inout) :: total  !! accumulated duration of this phase [s]
      integer, intent(inout), optional :: count   !! number of times the phase was done
      last = wall_clock_seconds() - start
      total = total + last
      if (present(count)) count = count + 1
   end subroutine add_elapsed_seconds

   !> Detail text 'pivot ratio <ratio> below <limit>' of a nearly singular factorization.
   function pivot_ratio_detail(ratio, limit) result(detail)
      real(dp), intent(in) :: ratio   !! smallest / largest pivot found
      real(dp), intent(in) :: limit   !! the solver's singular_pivot_ratio
      character(len=:), allocatable :: detail
      detail = 'pivot ratio '//to_string(ratio)//' below '//to_string(limit)
   end function pivot_ratio_detail

   !> The error for a factorization that ran out of room: `kind` solver_too_large (the
   !> solver's integer range) or solver_out_of_memory; names the size of the system and of the
   !> factor when known (factor_entries > 0).
   subroutine failure_of_size(error, solver_name, kind, stage, n, factor_entries, limit)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: solver_name
      integer, intent(in) :: kind
      character(len=*), intent(in) :: stage   !! 'symbolic analysis', 'numeric factorization'
      integer, intent(in) :: n                !! equations
      real(dp), intent(in) :: factor_entries  !! predicted entries of the factor, 0 if unknown
      character(len=*), intent(in) :: limit   !! what the solver cannot exceed, for too large
      character(len=:), allocatable :: size_text
      character(len=10) :: entries
      size_text = to_string(n)//' equations'
      if (factor_entries > 0.0_dp) then
         write (entries, '(es10.3)') factor_entries
         size_text = size_text//', a factor of about '//trim(adjustl(entries))//' nonzeros'
      end if
      if (kind == solver_too_large) then
         call fatal_error(error, solver_name//': the problem is too large for the solver in its '//stage// &
                          ' ('//size_text//'; '//limit//'): use a coarser mesh')
      else
         call fatal_error(error, solver_name//': out of memory in the '//stage//' ('//size_text// &
                          '): use a coarser mesh or a machine with more memory')
      end if
   end subroutine failure_of_size

   !> The common error text for a singular or indefinite matrix, naming equation, node and
   !> direction (equation = 3*(node-1) + direction); `equation` 0 means unknown.
   subroutine singular_matrix_message(error, solver_name, condition, equation, detail)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: solver_name
      character(len=*), intent(in) :: condition  !! 'singular' or 'singular or not positive definite'
      integer, intent(in) :: equation
      character(len=*), intent(in) :: detail   !! e.g. 'zero pivot', 'pivot ratio 1e-17'
      if (equation > 0) then
         call fatal_error(error, solver_name//': matrix is '//condition//' at equation '// &
                          to_string(equation)//' (node '//to_string((equation - 1)/3 + 1)//', direction '// &
                          to_string(mod(equation - 1, 3) + 1)//'): '//detail)
      else
         call fatal_error(error, solver_name//': matrix is '//condition//': '//detail)
      end if
   end subroutine singular_matrix_message
end module frix_linear_solver
