!> Global assembly of internal forces and tangent stiffness: one loop over the elements,
!> dispatching once per element to its block's formulation and scattering into the
!> node-blocked sparse matrix.
module frix_assembler
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_model, only: model_t
   use frix_analysis_state, only: analysis_state_t
   use frix_system_matrix, only: system_matrix_t
   use frix_process_group, only: n_processes, owns_element, sum_over_processes, gather_owned_elements, &
                                 agree_on_error
   implicit none
   private

   public :: assemble_internal, internal_tangent_symmetric

contains

   !> fint(u) of the whole mesh at state%u, and if `matrix` is present the tangent
   !> d fint / d u (the matrix is zeroed first). Updates state%alpha (EAS parameters solved
   !> at this u) and state%history (material history at this u, from the committed one).
   !> With `gp_stress`/`gp_strain` present, the Cauchy stress and the strain at every
   !> integration point are returned too, (6, n_points, n_elements).
   !> In a parallel run (frix_process_group) each process evaluates its own elements: fint,
   !> gp_stress and gp_strain are summed over the processes (every process gets the whole
   !> vector), the matrix holds this process's elements only, state%alpha and state%history
   !> are updated for its own elements (commit_solution gathers them); an element that fails
   !> on one process fails the assembly on all.
   subroutine assemble_internal(model, state, fint, error, matrix, gp_stress, gp_strain)
      type(model_t), intent(in) :: model
      type(analysis_state_t), intent(inout) :: state
      real(dp), intent(out) :: fint(:)
      type(error_t), allocatable, intent(out) :: error
      class(system_matrix_t), intent(inout), optional :: matrix
      real(dp), intent(out), optional :: gp_stress(:, :, :)
      real(dp), intent(out), optional :: gp_strain(:, :, :)

      ! sized by the mesh's largest element (rows of its connectivity)
      real(dp), allocatable :: coords(:, :), displacement(:, :), element_force(:), element_tangent(:, :)
      !> the element's initial stress (frix_initial_stress); unallocated: none, and the element
      !> sees an absent optional argument (Fortran 2008, 12.5.2.12)
      real(dp), allocatable :: initial(:, :)
      integer :: e, a, node, n_nodes, n_enhanced, n_state, n_points, block, max_nodes
      type(error_t), allocatable :: element_error

      max_nodes = size(model%mesh%connectivity, 1)
      allocate (coords(3, max_nodes), displacement(3, max_nodes), element_force(3*max_nodes))
      if (present(matrix)) allocate (element_tangent(3*max_nodes, 3*max_nodes))
      fint = 0.0_dp
      if (present(matrix)) call matrix%zero()
      do e = 1, model%mesh%n_elements
         if (.not. owns_element(e)) cycle   ! (another process's, in a parallel run)
         block = model%mesh%element_block(e)
         associate (element => model%blocks(block)%element%formulation, &
                    material => model%materials(model%blocks(block)%material)%law, &
                    nodes => model%mesh%connectivity(:, e))
            n_nodes = element%n_nodes()
            n_enhanced = element%n_enhanced()
            n_points = element%n_points()
            n_state = material%n_state()
            do a = 1, n_nodes
               node = nodes(a)
               coords(:, a) = model%mesh%coords(:, node)
               displacement(:, a) = state%u(3*node - 2:3*node)
            end do
            call element_initial_stress(model, e, n_points, initial)
            if (present(matrix)) then
               call element%evaluate(material, coords(:, :n_nodes), displacement(:, :n_nodes), &
                                     state%alpha(:n_enhanced, e), &
                                     state%committed_history(:n_state, :n_points, e), &
                                     state%history(:n_state, :n_points, e), &
                                     element_force(:3*n_nodes), &
                                     tangent=element_tangent(:3*n_nodes, :3*n_nodes), &
                                     error=element_error, initial_stress=initial)
            else if (present(gp_stress) .and. present(gp_strain)) then
               call element%evaluate(material, coords(:, :n_nodes), displacement(:, :n_nodes), &
                                     state%alpha(:n_enhanced, e), &
                                     state%committed_history(:n_state, :n_points, e), &
                                     state%history(:n_state, :n_points, e), &
                                     element_force(:3*n_nodes), &
                                     stress=gp_stress(:, :n_points, e), &
                                     strain=gp_strain(:, :n_points, e), error=element_error, &
                                     initial_stress=initial)
            else
               call element%evaluate(material, coords(:, :n_nodes), displacement(:, :n_nodes), &
                                     state%alpha(:n_enhanced, e), &
                                     state%committed_history(:n_state, :n_points, e), &
                                     state%history(:n_state, :n_points, e), &
                                     element_force(:3*n_nodes), error=element_error, initial_stress=initial)
            end if
            if (allocated(element_error)) then
               call fatal_error(error, 'element '//to_string(model%mesh%element_ids(e))//': '// &
                                element_error%message)
               exit
            end if
            do a = 1, n_nodes
               node = nodes(a)
               fint(3*node - 2:3*node) = fint(3*node - 2:3*node) + element_force(3*a - 2:3*a)
            end do
            if (present(matrix)) then
               call matrix%add_element(nodes(:n_nodes), element_tangent(:3*n_nodes, :3*n_nodes))
            end if
         end associate
      end do
      if (n_processes() > 1) then
         ! the processes' shares summed; a failure of one process is every one's
         call agree_on_error(error)
         if (allocated(error)) return
         call sum_over_processes(fint)
         if (present(gp_stress)) call gather_owned_elements(gp_stress)
         if (present(gp_strain)) call gather_owned_elements(gp_strain)
      end if
   end subroutine assemble_internal

   !> `initial` = the initial stress of element e's points (6, n_points), or unallocated when
   !> it has none.
   subroutine element_initial_stress(model, e, n_points, initial)
      type(model_t), intent(in) :: model
      integer, intent(in) :: e, n_points
      real(dp), allocatable, intent(inout) :: initial(:, :)
      logical :: prestressed
      prestressed = .false.
      if (allocated(model%initial_stress_source)) prestressed = model%initial_stress_source(e) > 0
      if (prestressed) then
         initial = model%point_initial_stress(:, :n_points, e)
      else if (allocated(initial)) then
         deallocate (initial)
      end if
   end subroutine element_initial_stress

   !> Whether d fint / du is symmetric: every material in use says its tangent is (the
   !> elements then mirror their upper blocks, frix_hex8). Loads (follower pressure) and
   !> contact add their own unsymmetric parts; the Newton loop combines the three.
   logical function internal_tangent_symmetric(model)
      type(model_t), intent(in) :: model
      integer :: b
      internal_tangent_symmetric = .true.
      do b = 1, size(model%blocks)
         if (.not. model%materials(model%blocks(b)%material)%law%symmetric_tangent()) &
            internal_tangent_symmetric = .false.
      end do
   end function internal_tangent_symmetric
end module frix_assembler
