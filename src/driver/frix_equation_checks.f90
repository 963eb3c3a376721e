!> Checks and labels of global equations for the Newton iterations' messages: the
!> finite-value guard (docs/solver.md, "Non-finite values") and where a factorization broke
!> down, each naming the node and direction of the equation concerned.
module frix_equation_checks
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_finite_check, only: first_non_finite
   use frix_model, only: model_t
   use frix_system_matrix, only: system_matrix_t
   use frix_process_group, only: agree_on_message
   implicit none
   private

   public :: check_finite, check_finite_tangent, describe_singularity, equation_label

contains

   !> The finite-value guard (docs/solver.md): `failure` names the first equation where
   !> `values` (per global equation) holds NaN or an infinity, and the quantity; unchanged when
   !> every value is finite.
   subroutine check_finite(model, values, quantity, failure)
      type(model_t), intent(in) :: model
      real(dp), intent(in) :: values(:)
      character(len=*), intent(in) :: quantity
      character(len=:), allocatable, intent(inout) :: failure
      integer :: equation
      equation = first_non_finite(values)
      if (equation == 0) return
      failure = 'the '//quantity//' is not finite ('//to_string(values(equation))//') at '// &
                equation_label(model, equation)
   end subroutine check_finite

   !> check_finite for the tangent matrix: names the column (equation) of the first
   !> non-finite entry. In a parallel run each process checks its share of the matrix and the
   !> failure of the lowest process that has one becomes every process's.
   subroutine check_finite_tangent(model, matrix, failure)
      type(model_t), intent(in) :: model
      class(system_matrix_t), intent(in) :: matrix
      character(len=:), allocatable, intent(inout) :: failure
      integer :: column
      real(dp) :: value
      call matrix%first_non_finite_column(column, value)
      if (column /= 0) failure = 'the tangent stiffness is not finite ('//to_string(value)//') in the column of '// &
                                 equation_label(model, column)
      call agree_on_message(failure)
   end subroutine check_finite_tangent

   !> Name the node and direction where the factorization broke down.
   subroutine describe_singularity(model, equation, error)
      type(model_t), intent(in) :: model
      integer, intent(in) :: equation   !! where the factorization failed, 0: unknown
      type(error_t), allocatable, intent(inout) :: error
      if (equation <= 0) return
      error%message = error%message//new_line('a')// &
                      model%deck_path//': the stiffness matrix is singular at '// &
                      equation_label(model, equation)// &
                      ': is that part of the model held against rigid-body motion, or is the load '// &
                      'beyond what it can carry (a limit load, a collapse mechanism)?'
   end subroutine describe_singularity

   !> 'node <user id>, direction x|y|z' of global equation `equation` (node-major, 3 per node).
   function equation_label(model, equation) result(text)
      type(model_t), intent(in) :: model
      integer, intent(in) :: equation
      character(len=:), allocatable :: text
      character(len=1), parameter :: direction(3) = ['x', 'y', 'z']
      text = 'node '//to_string(model%mesh%node_ids((equation - 1)/3 + 1))//', direction '// &
             direction(mod(equation - 1, 3) + 1)
   end function equation_label

end module frix_equation_checks
