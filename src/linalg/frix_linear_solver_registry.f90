!> Turns a deck keyword into a linear solver object. The default-by-symmetry choice
!> (CHOLMOD for symmetric positive definite tangents, UMFPACK otherwise) is the caller's.
module frix_linear_solver_registry
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_upper
   use frix_linear_solver, only: linear_solver_t
   use frix_cholmod_solver, only: cholmod_solver_t
   use frix_umfpack_solver, only: umfpack_solver_t
   implicit none
   private

   public :: create_linear_solver, linear_solver_keywords

   !> The valid keywords, for messages and deck documentation.
   character(len=*), parameter :: linear_solver_keywords = 'CHOLMOD, UMFPACK'

contains

   !> Allocate the solver named by `keyword` (case-insensitive, surrounding blanks ignored).
   subroutine create_linear_solver(keyword, solver, error)
      character(len=*), intent(in) :: keyword
      class(linear_solver_t), allocatable, intent(out) :: solver
      type(error_t), allocatable, intent(out) :: error
      select case (to_upper(trim(adjustl(keyword))))
      case ('CHOLMOD')
         allocate (cholmod_solver_t :: solver)
      case ('UMFPACK')
         allocate (umfpack_solver_t :: solver)
      case default
         call fatal_error(error, 'unknown linear solver "'//trim(adjustl(keyword))//'"; valid: '// &
                          linear_solver_keywords)
      end select
   end subroutine create_linear_solver
end module frix_linear_solver_registry
