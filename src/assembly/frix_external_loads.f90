!> External forces at pseudo time t and the prescribed displacements.
!> A pressure on an element face is integrated by the element's formulation (element_t%face_pressure:
!> the face of a solid, the edge of a plane element with its thickness or 2 pi r).
!> Sign convention: the residual is r = fext - fint; a follower pressure's load stiffness
!> K_load = d fext / d u enters the Newton matrix as K = d fint/du - K_load.
module frix_external_loads
   use frix_kinds, only: dp
   use frix_model, only: model_t, curve_factor
   use frix_system_matrix, only: system_matrix_t
   implicit none
   private

   public :: assemble_external, prescribed_displacements, has_follower_loads

contains

   !> fext(t) at displacements u. With `matrix` present, the follower-load stiffness is
   !> subtracted from it (the matrix must already hold d fint / d u). With `step_window`
   !> = (t_start, t_end) of a path-following step, every load's curve factor is replaced by
   !> its straight line through the step's ends, extended beyond them: the load is the value
   !> at the start plus (t - t_start) / (t_end - t_start) times the step's load change (the
   !> load factor of path following scales that change; curves shape nothing inside the step).
   subroutine assemble_external(model, time, u, fext, matrix, step_window)
      type(model_t), intent(in) :: model
      real(dp), intent(in) :: time
      real(dp), intent(in) :: u(:)
      real(dp), intent(out) :: fext(:)
      class(system_matrix_t), intent(inout), optional :: matrix
      real(dp), intent(in), optional :: step_window(2)
      integer :: i, k, a, node, e, face, equation, face_cell
      real(dp) :: factor
      real(dp), allocatable :: element_coords(:, :), weights(:), coords(:, :), displacement(:, :), force(:), &
                               stiffness(:, :)
      integer, allocatable :: face_nodes(:)

      fext = 0.0_dp
      if (allocated(model%nodal_forces)) then
         do i = 1, size(model%nodal_forces)
            associate (load => model%nodal_forces(i))
               factor = load%value*load_factor(load%curve)
               do k = 1, size(load%nodes)
                  equation = 3*(load%nodes(k) - 1) + load%component
                  fext(equation) = fext(equation) + factor
               end do
            end associate
         end do
      end if

      if (allocated(model%pressures)) then
         do i = 1, size(model%pressures)
            associate (load => model%pressures(i), &
                       surface => model%mesh%surfaces(model%pressures(i)%surface))
               factor = load%value*load_factor(load%curve)
               if (factor == 0.0_dp) cycle
               do k = 1, size(surface%elements)
                  e = surface%elements(k)
                  face = surface%faces(k)
                  face_nodes = model%mesh%face_nodes(e, face)
                  face_cell = model%mesh%face_cell_of(e)
                  call face_arrays(size(face_nodes))
                  do a = 1, size(face_nodes)
                     node = face_nodes(a)
                     coords(:, a) = model%mesh%coords(:, node)
                     displacement(:, a) = u(3*node - 2:3*node)
                  end do
                  associate (element => model%blocks(model%mesh%element_block(e))%element%formulation)
                     call element%face_pressure(model%mesh%cells(face_cell)%cell, coords, displacement, factor, load%follower, &
                                                force, stiffness)
                  end associate
                  do a = 1, size(face_nodes)
                     node = face_nodes(a)
                     fext(3*node - 2:3*node) = fext(3*node - 2:3*node) + force(3*a - 2:3*a)
                  end do
                  if (load%follower .and. present(matrix)) then
                     call matrix%add_element(face_nodes, -stiffness)
                  end if
               end do
            end associate
         end do
      end if

      if (allocated(model%body_forces)) then
         do i = 1, size(model%body_forces)
            associate (load => model%body_forces(i))
               factor = load_factor(load%curve)
               if (factor == 0.0_dp) cycle
               do k = 1, size(load%elements)
                  e = load%elements(k)
                  associate (block => model%blocks(model%mesh%element_block(e)))
                     associate (element => block%element%formulation, &
                                density => model%materials(block%material)%law%density)
                        element_coords = model%mesh%coords(:, model%mesh%element_nodes(e))
                        if (allocated(weights)) deallocate (weights)
                        allocate (weights(model%mesh%node_count(e)))
                        call element%volume_weights(element_coords, weights)
                        do a = 1, model%mesh%node_count(e)
                           node = model%mesh%connectivity(a, e)
                           fext(3*node - 2:3*node) = fext(3*node - 2:3*node) + &
                                                     density*factor*weights(a)*load%gravity
                        end do
                     end associate
                  end associate
               end do
            end associate
         end do
      end if
   contains
      !> coords, displacement, force and stiffness sized for a face of n nodes.
      subroutine face_arrays(n)
         integer, intent(in) :: n
         if (allocated(coords)) then
            if (size(coords, 2) == n) return
            deallocate (coords, displacement, force, stiffness)
         end if
         allocate (coords(3, n), displacement(3, n), force(3*n), stiffness(3*n, 3*n))
      end subroutine face_arrays

      !> The factor of `curve` at `time` (see above for `step_window`).
      real(dp) function load_factor(curve)
         integer, intent(in) :: curve
         real(dp) :: at_start
         if (.not. present(step_window)) then
            load_factor = curve_factor(model, curve, time)
            return
         end if
         at_start = curve_factor(model, curve, step_window(1))
         load_factor = at_start + (time - step_window(1))/(step_window(2) - step_window(1))* &
                       (curve_factor(model, curve, step_window(2)) - at_start)
      end function load_factor
   end subroutine assemble_external

   !> Constrained equations and their prescribed values at time t. Nodes that belong to no
   !> element have no stiffness: they are held fixed, except the reference and rotation nodes
   !> of kinematic couplings (frix_kinematic_coupling), which receive the coupled nodes' stiffness.
   !> The nodes of plane strain and axisymmetric elements (cells of dimension 2) move in the
   !> x-y plane: their z displacement is held at 0.
   subroutine prescribed_displacements(model, time, fixed, values)
      type(model_t), intent(in) :: model
      real(dp), intent(in) :: time
      logical, intent(out) :: fixed(:)
      real(dp), intent(out) :: values(:)
      logical, allocatable :: in_element(:)
      integer :: i, k, equation, node, e
      fixed = .false.
      values = 0.0_dp
      if (allocated(model%dirichlet)) then
         do i = 1, size(model%dirichlet)
            associate (condition => model%dirichlet(i))
               do k = 1, size(condition%nodes)
                  equation = 3*(condition%nodes(k) - 1) + condition%component
                  fixed(equation) = .true.
                  values(equation) = condition%value*curve_factor(model, condition%curve, time)
               end do
            end associate
         end do
      end if
      allocate (in_element(model%mesh%n_nodes), source=.false.)
      in_element(pack(model%mesh%connectivity, model%mesh%connectivity > 0)) = .true.
      if (allocated(model%couplings)) then
         in_element(model%couplings%reference_node) = .true.
         in_element(model%couplings%rotation_node) = .true.
      end if
      do node = 1, model%mesh%n_nodes
         if (.not. in_element(node)) fixed(3*node - 2:3*node) = .true.
      end do
      do e = 1, model%mesh%n_elements
         if (model%mesh%cell_dimension(e) /= 2) cycle
         do k = 1, model%mesh%node_count(e)
            node = model%mesh%connectivity(k, e)
            fixed(3*node) = .true.
            values(3*node) = 0.0_dp
         end do
      end do
   end subroutine prescribed_displacements

   pure logical function has_follower_loads(model)
      type(model_t), intent(in) :: model
      has_follower_loads = .false.
      if (allocated(model%pressures)) has_follower_loads = any(model%pressures%follower)
   end function has_follower_loads
end module frix_external_loads
