!> CHOLMOD guarded by UMFPACK: the solver of a Newton system whose tangent is expected
!> symmetric positive definite (deck keyword Auto with a symmetric system, or Cholmod). When
!> CHOLMOD finds the matrix not positive definite (past a limit point, or with large
!> penetrations in the first contact iterations), the factorization is repeated with UMFPACK,
!> which stays in use until the end of the increment; the next increment (begin_increment)
!> tries CHOLMOD again. The same holds from the factorization on where the Newton loop says the
!> matrix is unsymmetric (expect_unsymmetric: CHOLMOD reads only the upper triangle, whose
!> symmetric completion is not the tangent). Both keep their symbolic analyses. Any other
!> failure (too large, out of memory, a singular matrix) is reported as it is.
!>
!> The statistics fields of the type are CHOLMOD's; add_totals adds UMFPACK's, and the
!> description names the factorizations done by UMFPACK.
module frix_auto_solver
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_system_matrix, only: system_matrix_t
   use frix_linear_solver, only: linear_solver_t, solver_not_positive_definite
   use frix_cholmod_solver, only: cholmod_solver_t
   use frix_umfpack_solver, only: umfpack_solver_t
   implicit none
   private

   public :: auto_solver_t

   type, extends(linear_solver_t) :: auto_solver_t
      type(cholmod_solver_t) :: primary
      type(umfpack_solver_t), allocatable :: fallback   !! created at the first fallback
      logical :: use_fallback = .false.                 !! for the rest of the current increment
   contains
      procedure :: name
      procedure :: factorize
      procedure :: solve
      procedure :: release
      procedure :: begin_increment
      procedure :: expect_unsymmetric
      procedure :: description
      procedure :: add_totals
   end type auto_solver_t

contains

   function name(solver) result(keyword)
      class(auto_solver_t), intent(in) :: solver
      character(len=:), allocatable :: keyword
      keyword = solver%primary%name()
   end function name

   subroutine factorize(solver, matrix, error)
      class(auto_solver_t), intent(inout) :: solver
      class(system_matrix_t), intent(in), target :: matrix
      type(error_t), allocatable, intent(out) :: error
      if (.not. solver%use_fallback) then
         call solver%primary%factorize(matrix, error)
         call mirror_primary(solver)
         if (.not. allocated(error)) return
         if (solver%primary%failure /= solver_not_positive_definite) return
         deallocate (error)
         solver%use_fallback = .true.
         if (.not. allocated(solver%fallback)) allocate (solver%fallback)
      end if
      call solver%fallback%factorize(matrix, error)
      solver%failed_equation = solver%fallback%failed_equation
      solver%failure = solver%fallback%failure
   end subroutine factorize

   subroutine solve(solver, matrix, rhs, x, error)
      class(auto_solver_t), intent(inout) :: solver
      class(system_matrix_t), intent(in), target :: matrix
      real(dp), intent(in), target :: rhs(:)
      real(dp), intent(out), target :: x(:)
      type(error_t), allocatable, intent(out) :: error
      if (solver%use_fallback) then
         call solver%fallback%solve(matrix, rhs, x, error)
      else
         call solver%primary%solve(matrix, rhs, x, error)
         call mirror_primary(solver)
      end if
   end subroutine solve

   subroutine release(solver)
      class(auto_solver_t), intent(inout) :: solver
      call solver%primary%release()
      if (allocated(solver%fallback)) call solver%fallback%release()
      call mirror_primary(solver)
   end subroutine release

   subroutine begin_increment(solver)
      class(auto_solver_t), intent(inout) :: solver
      solver%use_fallback = .false.
   end subroutine begin_increment

   !> UMFPACK for the rest of the increment.
   subroutine expect_unsymmetric(solver)
      class(auto_solver_t), intent(inout) :: solver
      solver%use_fallback = .true.
      if (.not. allocated(solver%fallback)) allocate (solver%fallback)
   end subroutine expect_unsymmetric

   !> 'CHOLMOD', or 'CHOLMOD (UMFPACK in N factorizations where the matrix was not positive
   !> definite or unsymmetric)' once UMFPACK was needed.
   function description(solver) result(text)
      class(auto_solver_t), intent(in) :: solver
      character(len=:), allocatable :: text
      text = solver%primary%name()
      if (allocated(solver%fallback)) text = text//' (UMFPACK in '// &
                                             to_string(solver%fallback%n_factorizations)// &
                                             ' factorizations where the matrix was not positive definite or unsymmetric)'
   end function description

   subroutine add_totals(solver, analyse, factorize, solve, factorizations)
      class(auto_solver_t), intent(in) :: solver
      real(dp), intent(inout) :: analyse, factorize, solve
      integer, intent(inout) :: factorizations
      call solver%primary%add_totals(analyse, factorize, solve, factorizations)
      if (allocated(solver%fallback)) call solver%fallback%add_totals(analyse, factorize, solve, factorizations)
   end subroutine add_totals

   !> The statistics and state fields of the type are those of CHOLMOD.
   subroutine mirror_primary(solver)
      class(auto_solver_t), intent(inout) :: solver
      associate (p => solver%primary)
         solver%analyse_seconds = p%analyse_seconds
         solver%factorize_seconds = p%factorize_seconds
         solver%solve_seconds = p%solve_seconds
         solver%last_analyse_seconds = p%last_analyse_seconds
         solver%last_factorize_seconds = p%last_factorize_seconds
         solver%last_solve_seconds = p%last_solve_seconds
         solver%n_analyses = p%n_analyses
         solver%n_factorizations = p%n_factorizations
         solver%n_solves = p%n_solves
         solver%failed_equation = p%failed_equation
         solver%failure = p%failure
         solver%peak_memory_bytes = p%peak_memory_bytes
         solver%factor_entries = p%factor_entries
         solver%analysed_pattern_id = p%analysed_pattern_id
         solver%factorized_pattern_id = p%factorized_pattern_id
      end associate
   end subroutine mirror_primary
end module frix_auto_solver
