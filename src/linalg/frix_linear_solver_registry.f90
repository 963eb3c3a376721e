!> The linear solver registry: a table of (deck keyword, constructor) entries. The deck's
!> SOLVER keyword (Auto, Cholmod, Umfpack, Petsc) becomes a solver object; the Newton loop then only
!> calls linear_solver_t's procedures.
!>
!> For a Newton system (`symmetric` given: whether its tangent is expected symmetric):
!>   AUTO     CHOLMOD guarded by UMFPACK (frix_auto_solver) if symmetric, else UMFPACK
!>   CHOLMOD  CHOLMOD guarded by UMFPACK (frix_auto_solver)
!>   UMFPACK  UMFPACK
!> Without `symmetric`, CHOLMOD and UMFPACK are the bare library solvers, and AUTO the guarded
!> CHOLMOD.
module frix_linear_solver_registry
   use frix_error, only: error_t, fatal_error
   use frix_property_list, only: keyword_index, joined
   use frix_linear_solver, only: linear_solver_t
   use frix_cholmod_solver, only: cholmod_solver_t
   use frix_umfpack_solver, only: umfpack_solver_t
   use frix_auto_solver, only: auto_solver_t
   use frix_petsc_solver, only: petsc_solver_t, petsc_available, finish_petsc
   implicit none
   private

   public :: create_linear_solver, is_linear_solver_keyword, linear_solver_choices, linear_solver_unavailable, &
             finish_linear_solvers

   !> The deck's choices, as its messages name them (the deck's spelling of the table below).
   character(len=*), parameter :: linear_solver_choices = 'Auto, Cholmod, Umfpack or Petsc'

   abstract interface
      !> A solver for a Newton system (`newton`) whose tangent is expected `symmetric`.
      subroutine solver_constructor(newton, symmetric, solver)
         import :: linear_solver_t
         logical, intent(in) :: newton, symmetric
         class(linear_solver_t), allocatable, intent(out) :: solver
      end subroutine solver_constructor
   end interface

   type :: solver_entry_t
      character(len=16) :: keyword   !! as long as the deck's SOLVER value (model controls)
      procedure(solver_constructor), pointer, nopass :: create => null()
   end type solver_entry_t

contains

   !> The registered solvers: one line per solver.
   function solver_table() result(table)
      type(solver_entry_t), allocatable :: table(:)
      table = [solver_entry_t('AUTO', new_auto), solver_entry_t('CHOLMOD', new_cholmod), &
               solver_entry_t('UMFPACK', new_umfpack), solver_entry_t('PETSC', new_petsc)]
   end function solver_table

   !> Whether `keyword` (any case) names a registered solver.
   logical function is_linear_solver_keyword(keyword)
      character(len=*), intent(in) :: keyword
      type(solver_entry_t), allocatable :: table(:)
      table = solver_table()
      is_linear_solver_keyword = keyword_index(table%keyword, keyword) > 0
   end function is_linear_solver_keyword

   !> Allocate the solver named by `keyword` (case-insensitive, surrounding blanks ignored);
   !> `symmetric` given: for a Newton system (see the module head).
   !> Why a known solver cannot run in this build ('' when it can): PETSc not linked.
   function linear_solver_unavailable(keyword) result(reason)
      character(len=*), intent(in) :: keyword
      character(len=:), allocatable :: reason
      reason = ''
      if (keyword_index(['PETSC'], keyword) > 0 .and. .not. petsc_available) &
         reason = 'this frix was built without PETSc (scripts/setup.sh --petsc builds one with it)'
   end function linear_solver_unavailable

   !> What a solver library needs at the end of a run (PetscFinalize when PETSc was started).
   subroutine finish_linear_solvers()
      call finish_petsc()
   end subroutine finish_linear_solvers

   subroutine create_linear_solver(keyword, solver, error, symmetric)
      character(len=*), intent(in) :: keyword
      class(linear_solver_t), allocatable, intent(out) :: solver
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: symmetric
      type(solver_entry_t), allocatable :: table(:)
      integer :: i
      table = solver_table()
      i = keyword_index(table%keyword, keyword)
      if (i > 0 .and. present(symmetric)) then
         call table(i)%create(.true., symmetric, solver)
      else if (i > 0) then
         call table(i)%create(.false., .true., solver)
      else
         call fatal_error(error, 'unknown linear solver "'//trim(adjustl(keyword))//'"; valid: '// &
                          joined(table%keyword))
      end if
   end subroutine create_linear_solver

   subroutine new_auto(newton, symmetric, solver)
      logical, intent(in) :: newton, symmetric
      class(linear_solver_t), allocatable, intent(out) :: solver
      if (symmetric) then
         allocate (auto_solver_t :: solver)
      else
         allocate (umfpack_solver_t :: solver)
      end if
   end subroutine new_auto

   subroutine new_cholmod(newton, symmetric, solver)
      logical, intent(in) :: newton, symmetric
      class(linear_solver_t), allocatable, intent(out) :: solver
      if (newton) then
         allocate (auto_solver_t :: solver)
      else
         allocate (cholmod_solver_t :: solver)
      end if
   end subroutine new_cholmod

   subroutine new_umfpack(newton, symmetric, solver)
      logical, intent(in) :: newton, symmetric
      class(linear_solver_t), allocatable, intent(out) :: solver
      allocate (umfpack_solver_t :: solver)
   end subroutine new_umfpack

   subroutine new_petsc(newton, symmetric, solver)
      logical, intent(in) :: newton, symmetric
      class(linear_solver_t), allocatable, intent(out) :: solver
      allocate (petsc_solver_t :: solver)
   end subroutine new_petsc
end module frix_linear_solver_registry
