!> The results of a committed increment, gathered once from the analysis state, the Newton
!> loop's report and the contact system into an increment_results_t for the writers
!> (frix_results_output). The stresses and strains come from one more element pass at the
!> converged displacements, when the increment's fields are written (RESULTS EVERY, the last
!> of a step). Every field is checked before any file receives it: the finite-value guard of
!> the output (docs/solver.md, "Non-finite values").
module frix_results_collection
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string, to_lower
   use frix_finite_check, only: first_non_finite
   use frix_field_recovery, only: cell_average, nodal_extrapolated, von_mises_field
   use frix_model, only: model_t, history_request_t
   use frix_analysis_state, only: analysis_state_t, reported_displacement
   use frix_newton_solver, only: newton_context_t
   use frix_newton_report, only: newton_report_t
   use frix_assembler, only: assemble_internal
   use frix_material, only: history_name_length
   use frix_increment_results, only: increment_results_t, named_field_t, contact_pass_results_t
   use frix_normal_contact_law, only: augmentation_t
   use frix_contact_parameters, only: contact_parameters_t
   use frix_contact_assembly, only: contact_nodal_fields, contact_pass_table, contact_table_labels, contact_resultant, &
                                    get_contact_history
   implicit none
   private

   public :: collect_results

contains

   !> `results` of converged increment `increment` of step `step` (committed in `state`).
   subroutine collect_results(model, step, increment, state, context, report, results, error)
      type(model_t), intent(in) :: model
      integer, intent(in) :: step, increment
      type(analysis_state_t), intent(inout) :: state   !! (the element pass updates its iterate)
      type(newton_context_t), intent(in) :: context
      type(newton_report_t), intent(in) :: report
      type(increment_results_t), intent(out) :: results
      type(error_t), allocatable, intent(out) :: error
      integer :: n_nodes
      logical :: last_of_step

      n_nodes = model%mesh%n_nodes
      results%step = step
      results%increment = increment
      results%time = state%time
      results%iterations = report%iterations
      results%iteration_log = transpose(reshape([report%residual_norms(0:report%iterations), &
                                                 report%relative_norms(0:report%iterations), &
                                                 report%energy_norms(0:report%iterations)], &
                                                [report%iterations + 1, 3]))
      results%displacement = reported_displacement(state)
      results%total_displacement = reshape(state%committed_u, [3, n_nodes])
      if (allocated(state%reference_u)) results%reference_displacement = reshape(state%reference_u, [3, n_nodes])
      results%reaction = reshape(context%reactions, [3, n_nodes])
      results%constrained = reshape(context%fixed, [3, n_nodes])
      call check_nodal_finite(model, results, 'displacement', state%u, error)
      if (.not. allocated(error)) call check_nodal_finite(model, results, 'reaction', context%reactions, error)
      if (allocated(error)) return
      results%yielding_points = yielding_points(model, state)
      results%has_contact = state%has_contact
      if (state%has_contact) then
         call collect_contact(model, state, results, error)
         if (allocated(error)) return
      end if
      call collect_history_values(model, state, results)

      last_of_step = abs(state%time - real(step, dp)) < 1.0e-12_dp
      results%full = mod(increment, max(1, model%results%every)) == 0 .or. last_of_step
      results%has_fields = results%full .and. (model%results%vtk .or. model%results%pos3d .or. model%results%hdf5)
      if (results%has_fields) call collect_fields(model, state, results, error)
   end subroutine collect_results

   !> The value of each RESULTS HISTORY request (docs/output.md): a node's displacement or
   !> reaction component, their sum (reactions) or mean (displacements) over a node set, or a
   !> contact pair's resultant (contact_resultant).
   subroutine collect_history_values(model, state, results)
      type(model_t), intent(in) :: model
      type(analysis_state_t), intent(in) :: state
      type(increment_results_t), intent(inout) :: results
      integer :: r
      if (.not. allocated(model%results%history)) then
         allocate (results%history_values(0))
         return
      end if
      allocate (results%history_values(size(model%results%history)))
      do r = 1, size(model%results%history)
         associate (request => model%results%history(r))
            select case (request%kind)
            case ('C')
               results%history_values(r) = 0.0_dp
               if (state%has_contact) results%history_values(r) = &
                  contact_resultant(state%contact, request%pair, request%component)
            case ('R')
               results%history_values(r) = nodal_value(request, results%reaction)
            case default
               results%history_values(r) = nodal_value(request, results%displacement)
            end select
         end associate
      end do
   end subroutine collect_history_values

   !> Component `request%component` of a nodal field (3, n_nodes) at the request's node, or
   !> summed or averaged over its set's nodes.
   pure real(dp) function nodal_value(request, field) result(value)
      type(history_request_t), intent(in) :: request
      real(dp), intent(in) :: field(:, :)
      select case (request%reduction)
      case ('SUM')
         value = sum(field(request%component, request%nodes))
      case ('MEAN')
         value = sum(field(request%component, request%nodes))/size(request%nodes)
      case default
         value = field(request%component, request%node)
      end select
   end function nodal_value

   !> Stresses and strains at the integration points (one element pass), the materials'
   !> named history variables, and the committed state for restarts.
   subroutine collect_fields(model, state, results, error)
      type(model_t), intent(in) :: model
      type(analysis_state_t), intent(inout) :: state
      type(increment_results_t), intent(inout) :: results
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: fint(:)
      integer :: k, n_points
      ! the most integration points of any element (8 for HEX8); an element with fewer fills
      ! the first ones, the rest stay 0
      n_points = 0
      do k = 1, size(model%blocks)
         n_points = max(n_points, model%blocks(k)%element%formulation%n_points())
      end do
      allocate (results%stress(6, n_points, model%mesh%n_elements), results%strain(6, n_points, model%mesh%n_elements), &
                source=0.0_dp)
      allocate (fint(3*model%mesh%n_nodes))
      call assemble_internal(model, state, fint, error, gp_stress=results%stress, gp_strain=results%strain)
      if (allocated(error)) return
      call check_element_finite(model, results, 'stress', results%stress, error)
      if (.not. allocated(error)) call check_element_finite(model, results, 'strain', results%strain, error)
      if (.not. allocated(error)) call check_recovered_finite(model, results, 'stress', results%stress, error)
      if (.not. allocated(error)) call check_recovered_finite(model, results, 'strain', results%strain, error)
      if (allocated(error)) return
      results%alpha = state%committed_alpha
      results%history = state%committed_history
      results%displacement_rate = reshape(state%rate, [3, model%mesh%n_nodes])
      results%rate_start = state%rate_start
      call collect_history_fields(model, state, results)
   end subroutine collect_fields

   !> The number of integration points with history variable YIELDED = 1 in the committed
   !> state; -1 if no material names a variable YIELDED.
   integer function yielding_points(model, state)
      type(model_t), intent(in) :: model
      type(analysis_state_t), intent(in) :: state
      character(len=history_name_length), allocatable :: names(:)
      integer :: entry(size(model%materials)), m, k, e
      entry = 0
      do m = 1, size(model%materials)
         call model%materials(m)%law%history_names(names)
         do k = 1, size(names)
            if (names(k) == 'YIELDED') entry(m) = k
         end do
      end do
      yielding_points = -1
      if (all(entry == 0)) return
      yielding_points = 0
      do e = 1, model%mesh%n_elements
         k = entry(model%blocks(model%mesh%element_block(e))%material)
         if (k > 0) yielding_points = yielding_points + count(state%committed_history(k, :, e) > 0.5_dp)
      end do
   end function yielding_points

   !> One named field per distinct name of the materials' history_names: entry k of the
   !> committed state of every element whose material names it so, zero elsewhere.
   subroutine collect_history_fields(model, state, results)
      type(model_t), intent(in) :: model
      type(analysis_state_t), intent(in) :: state
      type(increment_results_t), intent(inout) :: results
      character(len=history_name_length), allocatable :: names(:), all_names(:)
      integer, allocatable :: entry(:, :)   !! (field, material): the state entry named so, 0 if none
      integer :: m, k, f, e
      allocate (all_names(0))
      do m = 1, size(model%materials)
         call model%materials(m)%law%history_names(names)
         do k = 1, size(names)
            if (.not. any(all_names == names(k))) call append_name(all_names, names(k))
         end do
      end do
      allocate (entry(size(all_names), size(model%materials)), source=0)
      do m = 1, size(model%materials)
         call model%materials(m)%law%history_names(names)
         do k = 1, size(names)
            entry(findloc(all_names, names(k), dim=1), m) = k
         end do
      end do
      allocate (results%point_fields(size(all_names)))
      do f = 1, size(all_names)
         results%point_fields(f)%name = trim(all_names(f))
         allocate (results%point_fields(f)%values(size(state%committed_history, 2), model%mesh%n_elements), &
                   source=0.0_dp)
         do e = 1, model%mesh%n_elements
            k = entry(f, model%blocks(model%mesh%element_block(e))%material)
            if (k > 0) results%point_fields(f)%values(:, e) = state%committed_history(k, :, e)
         end do
      end do
   end subroutine collect_history_fields

   !> `name` appended to `list` (an explicit copy: gfortran 12 at -O0 with -fcheck=all misreads
   !> the length of a growing character array constructor, [list, name], and stops the run).
   pure subroutine append_name(list, name)
      character(len=history_name_length), allocatable, intent(inout) :: list(:)
      character(len=history_name_length), intent(in) :: name
      character(len=history_name_length), allocatable :: longer(:)
      allocate (longer(size(list) + 1))
      longer(:size(list)) = list
      longer(size(list) + 1) = name
      call move_alloc(longer, list)
   end subroutine append_name

   !> The contact tables of every pass, the slip histories and the per-node contact fields.
   !> Whether contact pair `pair` has an augmented normal law (its multipliers are results).
   logical function augmented_pass(model, pair) result(augmented)
      type(model_t), intent(in) :: model
      integer, intent(in) :: pair
      type(augmentation_t) :: settings
      augmented = .false.
      if (model%contact_pairs(pair)%tied) return
      settings = model%contact_pairs(pair)%parameters%normal%augmentation()
      augmented = settings%augmented
   end function augmented_pass

   !> [eps_N, eps_T, automatic eps_N (1/0), automatic eps_T (1/0)] of a contact pair (the
   !> HDF5 dataset contact/pass<p>_penalty, docs/hdf5-layout.md).
   subroutine pair_penalties(parameters, penalty)
      type(contact_parameters_t), intent(in) :: parameters
      real(dp), allocatable, intent(out) :: penalty(:)
      penalty = [parameters%normal%penalty(), parameters%tangential_penalty, &
                 merge(1.0_dp, 0.0_dp, parameters%normal%automatic_penalty), &
                 merge(1.0_dp, 0.0_dp, parameters%automatic_tangential_penalty)]
   end subroutine pair_penalties

   subroutine collect_contact(model, state, results, error)
      type(model_t), intent(in) :: model
      type(analysis_state_t), intent(in) :: state
      type(increment_results_t), intent(inout) :: results
      type(error_t), allocatable, intent(out) :: error
      integer :: p, pair
      allocate (results%contact(size(state%contact%passes)))
      do p = 1, size(state%contact%passes)
         associate (table => results%contact(p))
            call contact_pass_table(state%contact, p, pair, table%nodes, table%values)
            table%pair_id = model%contact_pairs(pair)%id
            call get_contact_history(state%contact, p, table%history)
            if (.not. model%contact_pairs(pair)%tied) call pair_penalties(model%contact_pairs(pair)%parameters, &
                                                                       table%penalty)
            if (augmented_pass(model, pair)) table%multiplier = state%contact%passes(p)%committed_multiplier
            if (augmented_pass(model, pair)) then
               table%penalty_scale = [state%contact%passes(p)%committed_normal_scale, &
                                      state%contact%passes(p)%committed_tangential_scale]
               if (model%contact_pairs(pair)%parameters%tangential_augmented) &
                  table%tangential_multiplier = state%contact%passes(p)%committed_tangential_multiplier
               if (model%contact_pairs(pair)%parameters%predict) then
                  allocate (table%multiplier_rate(4, size(state%contact%passes(p)%multiplier_rate)))
                  table%multiplier_rate(1, :) = state%contact%passes(p)%multiplier_rate
                  table%multiplier_rate(2:4, :) = state%contact%passes(p)%tangential_multiplier_rate
               end if
            end if
            call check_contact_finite(model, results, table, error)
            if (allocated(error)) return
         end associate
      end do
      call contact_nodal_fields(state%contact, model%mesh%n_nodes, results%contact_pressure, &
                                results%contact_traction, results%contact_gap, results%contact_status, &
                                results%contact_slip, results%contact_normal)
   end subroutine collect_contact

   !> An error naming the node and direction of the first non-finite entry of a nodal field
   !> (3 values per node), so that no result file receives NaN or an infinity.
   subroutine check_nodal_finite(model, results, quantity, values, error)
      type(model_t), intent(in) :: model
      type(increment_results_t), intent(in) :: results
      character(len=*), intent(in) :: quantity
      real(dp), intent(in) :: values(:)
      type(error_t), allocatable, intent(out) :: error
      character(len=1), parameter :: direction(3) = ['x', 'y', 'z']
      integer :: k
      k = first_non_finite(values)
      if (k == 0) return
      call fatal_error(error, not_written(results)//'the '//quantity//' at node '// &
                       to_string(model%mesh%node_ids((k - 1)/3 + 1))//', direction '// &
                       direction(mod(k - 1, 3) + 1)//' is not finite ('//to_string(values(k))//')')
   end subroutine check_nodal_finite

   !> check_nodal_finite for an integration-point field (6 components per point).
   subroutine check_element_finite(model, results, quantity, values, error)
      type(model_t), intent(in) :: model
      type(increment_results_t), intent(in) :: results
      character(len=*), intent(in) :: quantity
      real(dp), intent(in) :: values(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      integer :: location(3)
      if (all(ieee_is_finite(values))) return
      location = findloc(ieee_is_finite(values), .false.)
      call fatal_error(error, not_written(results)//'the '//quantity//' of element '// &
                       to_string(model%mesh%element_ids(location(3)))//' is not finite')
   end subroutine check_element_finite

   !> check_element_finite for what the writers derive from an integration-point field
   !> (frix_field_recovery): the element means, the values extrapolated to the nodes and, for
   !> the stress, the von Mises stress of both, which can overflow where the points' values do
   !> not (E = 1e200 at 1 % strain: stresses of 1e198, their squares beyond the range of reals).
   subroutine check_recovered_finite(model, results, quantity, gp, error)
      type(model_t), intent(in) :: model
      type(increment_results_t), intent(in) :: results
      character(len=*), intent(in) :: quantity   !! 'stress' or 'strain'
      real(dp), intent(in) :: gp(:, :, :)        !! (6, n_points, n_elements)
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: cell(:, :), nodal(:, :)
      allocate (cell(6, model%mesh%n_elements), nodal(6, model%mesh%n_nodes))
      call cell_average(gp, cell, model%mesh%cell_indices())
      call check_columns(model, results, 'element', quantity//' (element mean)', cell, error)
      if (allocated(error)) return
      call nodal_extrapolated(model%mesh%connectivity, gp, nodal, error, model%mesh%cell_indices())
      if (allocated(error)) return
      call check_columns(model, results, 'node', quantity//' (extrapolated to the nodes)', nodal, error)
      if (allocated(error) .or. quantity /= 'stress') return
      call check_columns(model, results, 'element', 'von Mises stress (element mean)', &
                         reshape(von_mises_field(cell), [1, size(cell, 2)]), error)
      if (allocated(error)) return
      call check_columns(model, results, 'node', 'von Mises stress (extrapolated to the nodes)', &
                         reshape(von_mises_field(nodal), [1, size(nodal, 2)]), error)
   end subroutine check_recovered_finite

   !> An error naming the element or node (`what`) of the first column of `values` with a
   !> non-finite entry.
   subroutine check_columns(model, results, what, quantity, values, error)
      type(model_t), intent(in) :: model
      type(increment_results_t), intent(in) :: results
      character(len=*), intent(in) :: what, quantity
      real(dp), intent(in) :: values(:, :)
      type(error_t), allocatable, intent(out) :: error
      integer :: location(2), id
      if (all(ieee_is_finite(values))) return
      location = findloc(ieee_is_finite(values), .false.)
      if (what == 'node') then
         id = model%mesh%node_ids(location(2))
      else
         id = model%mesh%element_ids(location(2))
      end if
      call fatal_error(error, not_written(results)//'the '//quantity//' at '//what//' '//to_string(id)// &
                       ' is not finite ('//to_string(values(location(1), location(2)))//')')
   end subroutine check_columns

   !> check_nodal_finite for the contact table of one pass (gap, pressure, traction, slip).
   subroutine check_contact_finite(model, results, table, error)
      type(model_t), intent(in) :: model
      type(increment_results_t), intent(in) :: results
      type(contact_pass_results_t), intent(in) :: table
      type(error_t), allocatable, intent(out) :: error
      integer :: location(2)
      if (all(ieee_is_finite(table%values))) return
      location = findloc(ieee_is_finite(table%values), .false.)
      call fatal_error(error, not_written(results)//'the contact '// &
                       to_lower(trim(contact_table_labels(location(1))))//' at slave node '// &
                       to_string(model%mesh%node_ids(table%nodes(location(2))))//' of pair '// &
                       to_string(table%pair_id)//' is not finite')
   end subroutine check_contact_finite

   !> Start of the output guard's messages.
   function not_written(results) result(text)
      type(increment_results_t), intent(in) :: results
      character(len=:), allocatable :: text
      text = 'frix: step '//to_string(results%step)//' increment '//to_string(results%increment)// &
             ' is not written: '
   end function not_written
end module frix_results_collection
