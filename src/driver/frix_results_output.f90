!> The result files of a run, written after every converged increment (so a run that stops
!> keeps everything converged): the fixed-column listing `<base>_listing.txt`, the ParaView
!> series `<base>.pvd` + `<base>_<step>_<increment>.vtu`, and the CSV history
!> `<base>_history.csv` of the requested node DOFs, and on request the POS3D neutral file
!> `<base>.pos` and the HDF5 results/restart file `<base>.h5`. See docs/output.md.
module frix_results_output
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_model, only: model_t
   use frix_analysis_state, only: analysis_state_t
   use frix_newton_solver, only: newton_context_t, newton_report_t
   use frix_assembler, only: assemble_internal
   use frix_listing_writer, only: listing_t
   use frix_vtk_writer, only: vtk_series_t
   use frix_history_writer, only: history_t
   use frix_pos3d_writer, only: pos3d_writer_t
   use frix_hdf5_results, only: hdf5_results_t
   use frix_strings, only: to_string, to_lower
   use frix_finite_check, only: first_non_finite
   use frix_contact_assembly, only: contact_nodal_fields, contact_pass_table, contact_table_labels, &
                                    get_contact_history
   implicit none
   private

   public :: results_output_t, frix_version

   character(len=*), parameter :: frix_version = '0.1.0'

   type :: results_output_t
      integer :: n_increments = 0        !! converged increments so far
      type(listing_t) :: listing
      type(vtk_series_t) :: vtk
      type(history_t) :: history
      type(pos3d_writer_t) :: pos3d
      type(hdf5_results_t) :: hdf5
      logical :: hdf5_open = .false.
      logical :: has_history = .false.
      logical :: pos3d_open = .false.
      integer :: contact_unit = -1        !! <base>_contact.csv
   contains
      procedure :: open => output_open
      procedure :: write_increment => output_write_increment
      procedure :: close => output_close
   end type results_output_t

contains

   subroutine output_open(self, model, base, error)
      class(results_output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: base   !! path prefix of every result file
      type(error_t), allocatable, intent(out) :: error
      integer :: slash, status, i
      slash = index(base, '/', back=.true.)
      if (slash > 1) then
         call execute_command_line('mkdir -p "'//base(:slash - 1)//'" 2> /dev/null', exitstat=status)
         if (status /= 0) then
            call fatal_error(error, 'frix: cannot create the output directory "'//base(:slash - 1)//'"')
            return
         end if
      end if
      if (model%results%listing) then
         call self%listing%open(base//'_listing.txt', model%deck_path, frix_version, error)
         if (allocated(error)) return
      end if
      if (model%results%vtk) then
         call self%vtk%open(base, error)
         if (allocated(error)) return
      end if
      if (model%results%pos3d) then
         call open_pos3d(self, model, base, error)
         if (allocated(error)) return
      end if
      if (model%results%hdf5) then
         call self%hdf5%create(base//'.h5', model%mesh, model%title, model%deck_path, frix_version, error)
         if (allocated(error)) return
         self%hdf5_open = .true.
      end if
      if (allocated(model%contact_pairs)) then
         if (size(model%contact_pairs) > 0) then
            call open_contact_csv(self, base, error)
            if (allocated(error)) return
         end if
      end if
      if (allocated(model%results%history)) then
         if (size(model%results%history) > 0) then
            associate (requests => model%results%history)
               call self%history%open(base, model%mesh, model%mesh%node_ids(requests%node), &
                                      [(requests(i)%component + merge(3, 0, requests(i)%kind == 'R'), &
                                        i=1, size(requests))], error)
            end associate
            if (allocated(error)) return
            self%has_history = .true.
         end if
      end if
   end subroutine output_open

   !> Write one converged increment. Stresses are recovered by one more element pass at the
   !> converged displacements.
   subroutine output_write_increment(self, model, step, increment, state, context, report, error)
      class(results_output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      integer, intent(in) :: step, increment
      type(analysis_state_t), intent(inout) :: state
      type(newton_context_t), intent(in) :: context
      type(newton_report_t), intent(in) :: report
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: gp_stress(:, :, :), gp_strain(:, :, :), fint(:)
      real(dp), allocatable :: displacement(:, :), reaction(:, :), norms(:, :)
      real(dp), allocatable :: pressure(:), traction(:, :), gap(:), status(:), slip(:), shear(:)
      logical :: last_of_step, wanted
      integer :: n_nodes
      character(len=1), allocatable :: no_names(:)
      real(dp), allocatable :: no_scalars(:, :), history_table(:, :)
      integer :: p

      n_nodes = model%mesh%n_nodes
      displacement = reshape(state%u, [3, n_nodes])
      reaction = reshape(context%reactions, [3, n_nodes])
      last_of_step = abs(state%time - real(step, dp)) < 1.0e-12_dp
      wanted = mod(increment, max(1, model%results%every)) == 0 .or. last_of_step
      ! every field is computed and checked before the first file receives any of them
      call check_nodal_finite(model, step, increment, 'displacement', state%u, error)
      if (.not. allocated(error)) call check_nodal_finite(model, step, increment, 'reaction', context%reactions, error)
      if (.not. allocated(error) .and. context%has_contact) call check_contact_finite(model, step, increment, context, error)
      if (allocated(error)) return
      if (wanted .and. (model%results%vtk .or. model%results%pos3d .or. model%results%hdf5)) then
         allocate (gp_stress(6, 8, model%mesh%n_elements), gp_strain(6, 8, model%mesh%n_elements))
         allocate (fint(3*n_nodes))
         call assemble_internal(model, state, fint, error, gp_stress=gp_stress, gp_strain=gp_strain)
         if (allocated(error)) return
         call check_element_finite(model, step, increment, 'stress', gp_stress, error)
         if (.not. allocated(error)) call check_element_finite(model, step, increment, 'strain', gp_strain, error)
         if (allocated(error)) return
      end if
      self%n_increments = self%n_increments + 1

      if (self%has_history) then
         call self%history%append(step, increment, state%time, displacement, reaction, error)
         if (allocated(error)) return
      end if
      if (context%has_contact) then
         call write_contact_csv(self, model, context, step, increment, state%time, displacement, error)
         if (allocated(error)) return
         call contact_nodal_fields(context%contact, n_nodes, pressure, traction, gap, status, slip)
         shear = norm2(traction, dim=1)
      end if
      if (.not. wanted) return

      if (self%listing%is_open()) then
         call self%listing%write_increment_header(step, increment, state%time, report%iterations, error)
         if (allocated(error)) return
         norms = reshape([report%residual_norms(0:report%iterations), &
                          report%relative_norms(0:report%iterations), &
                          report%energy_norms(0:report%iterations)], [report%iterations + 1, 3])
         call self%listing%write_iteration_log([character(len=17) :: 'RESIDUAL_NORM', 'RELATIVE_NORM', &
                                                'ENERGY_NORM'], transpose(norms), error)
         if (allocated(error)) return
         call self%listing%write_displacements(model%mesh, displacement, error)
         if (allocated(error)) return
         call self%listing%write_reactions(model%mesh, reaction, reshape(context%fixed, [3, n_nodes]), error)
         if (allocated(error)) return
         if (context%has_contact) then
            call write_contact_listing(self, model, context, error)
            if (allocated(error)) return
         end if
      end if

      if (model%results%vtk) then
         if (context%has_contact) then
            call self%vtk%add_point_field('contact_pressure', reshape(pressure, [1, n_nodes]))
            call self%vtk%add_point_field('contact_traction', traction)
            call self%vtk%add_point_field('contact_gap', reshape(gap, [1, n_nodes]))
            call self%vtk%add_point_field('contact_status', reshape(status, [1, n_nodes]))
            call self%vtk%add_point_field('contact_slip', reshape(slip, [1, n_nodes]))
         end if
         call self%vtk%write_increment(model%mesh, step, increment, state%time, displacement, &
                                       reaction, gp_stress, gp_strain, error)
         if (allocated(error)) return
      end if
      if (self%hdf5_open) then
         if (context%has_contact) then
            call self%hdf5%add_contact_array('pressure', pressure)
            call self%hdf5%add_contact_array('traction', traction)
            call self%hdf5%add_contact_array('gap', gap)
            call self%hdf5%add_contact_array('status', status)
            call self%hdf5%add_contact_array('slip', slip)
            do p = 1, size(context%contact%passes)
               call get_contact_history(context%contact, p, history_table)
               call self%hdf5%add_contact_array('pass'//to_string(p)//'_history', history_table)
            end do
         end if
         call self%hdf5%write_increment(step, increment, state%time, displacement, reaction, gp_stress, &
                                        gp_strain, state%committed_alpha, state%committed_history, error)
         if (allocated(error)) return
      end if
      if (model%results%pos3d) then
         if (context%has_contact) then
            call self%pos3d%add_step(state%time, displacement, gp_stress, &
                                     [character(len=16) :: 'CONTACT_PRESSURE', 'CONTACT_SHEAR'], &
                                     transpose(reshape([pressure, shear], [n_nodes, 2])), error)
         else
            allocate (no_names(0), no_scalars(0, n_nodes))
            call self%pos3d%add_step(state%time, displacement, gp_stress, no_names, no_scalars, error)
         end if
         if (allocated(error)) return
      end if
   end subroutine output_write_increment

   !> The finite-value guard of the output (docs/solver.md): an error naming the node and
   !> direction of the first non-finite entry of a nodal field (3 values per node), so that no
   !> result file receives NaN or an infinity.
   subroutine check_nodal_finite(model, step, increment, quantity, values, error)
      type(model_t), intent(in) :: model
      integer, intent(in) :: step, increment
      character(len=*), intent(in) :: quantity
      real(dp), intent(in) :: values(:)
      type(error_t), allocatable, intent(out) :: error
      character(len=1), parameter :: direction(3) = ['x', 'y', 'z']
      integer :: k
      k = first_non_finite(values)
      if (k == 0) return
      call fatal_error(error, not_written(step, increment)//'the '//quantity//' at node '// &
                       to_string(model%mesh%node_ids((k - 1)/3 + 1))//', direction '// &
                       direction(mod(k - 1, 3) + 1)//' is not finite ('//to_string(values(k))//')')
   end subroutine check_nodal_finite

   !> check_nodal_finite for an integration-point field (6 components, 8 points per element).
   subroutine check_element_finite(model, step, increment, quantity, values, error)
      type(model_t), intent(in) :: model
      integer, intent(in) :: step, increment
      character(len=*), intent(in) :: quantity
      real(dp), intent(in) :: values(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      integer :: location(3)
      if (all(ieee_is_finite(values))) return
      location = findloc(ieee_is_finite(values), .false.)
      call fatal_error(error, not_written(step, increment)//'the '//quantity//' of element '// &
                       to_string(model%mesh%element_ids(location(3)))//' is not finite')
   end subroutine check_element_finite

   !> check_nodal_finite for the contact tables of every pass (gap, pressure, traction, slip).
   subroutine check_contact_finite(model, step, increment, context, error)
      type(model_t), intent(in) :: model
      integer, intent(in) :: step, increment
      type(newton_context_t), intent(in) :: context
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: nodes(:)
      real(dp), allocatable :: values(:, :)
      integer :: p, pair, location(2)
      do p = 1, size(context%contact%passes)
         call contact_pass_table(context%contact, p, pair, nodes, values)
         if (all(ieee_is_finite(values))) cycle
         location = findloc(ieee_is_finite(values), .false.)
         call fatal_error(error, not_written(step, increment)//'the contact '// &
                          to_lower(trim(contact_table_labels(location(1))))//' at slave node '// &
                          to_string(model%mesh%node_ids(nodes(location(2))))//' of pair '// &
                          to_string(model%contact_pairs(pair)%id)//' is not finite')
         return
      end do
   end subroutine check_contact_finite

   !> Start of the output guard's messages.
   function not_written(step, increment) result(text)
      integer, intent(in) :: step, increment
      character(len=:), allocatable :: text
      text = 'frix: step '//to_string(step)//' increment '//to_string(increment)// &
             ' is not written: '
   end function not_written

   !> `<base>.pos` with the model; the materials' E and nu are read off their small-strain
   !> elastic tangent (C11 = lambda + 2 mu, C12 = lambda).
   subroutine open_pos3d(self, model, base, error)
      class(results_output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: base
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: elastic(:, :)
      real(dp) :: tangent(6, 6), lambda, mu
      integer :: m
      allocate (elastic(2, size(model%materials)))
      do m = 1, size(model%materials)
         call model%materials(m)%law%elastic_tangent(tangent)
         lambda = tangent(1, 2)
         mu = 0.5_dp*(tangent(1, 1) - tangent(1, 2))
         elastic(1, m) = mu*(3.0_dp*lambda + 2.0_dp*mu)/(lambda + mu)
         elastic(2, m) = lambda/(2.0_dp*(lambda + mu))
      end do
      call self%pos3d%open(base//'.pos', model%title, model%mesh, error, elastic, &
                           model%blocks(model%mesh%element_block)%material)
      if (allocated(error)) return
      self%pos3d_open = .true.
   end subroutine open_pos3d

   !> `<base>_contact.csv`: one row per slave node and converged increment.
   subroutine open_contact_csv(self, base, error)
      class(results_output_t), intent(inout) :: self
      character(len=*), intent(in) :: base
      type(error_t), allocatable, intent(out) :: error
      integer :: stat
      open (newunit=self%contact_unit, file=base//'_contact.csv', status='replace', action='write', &
            iostat=stat)
      if (stat /= 0) then
         self%contact_unit = -1
         call fatal_error(error, 'frix: cannot open '//base//'_contact.csv')
         return
      end if
      write (self%contact_unit, '(a)') 'step,increment,time,pair,pass,node,x,y,z,gap,pressure,'// &
         'traction_x,traction_y,traction_z,slip,status'
      flush (self%contact_unit)   ! a run killed before its first increment leaves the header
   end subroutine open_contact_csv

   subroutine write_contact_csv(self, model, context, step, increment, time, displacement, error)
      class(results_output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(newton_context_t), intent(in) :: context
      integer, intent(in) :: step, increment
      real(dp), intent(in) :: time, displacement(:, :)
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: nodes(:)
      real(dp), allocatable :: values(:, :)
      integer :: p, i, pair, stat
      do p = 1, size(context%contact%passes)
         call contact_pass_table(context%contact, p, pair, nodes, values)
         do i = 1, size(nodes)
            write (self%contact_unit, '(i0,",",i0,",",es24.16e3,",",i0,",",i0,",",i0,9(",",es24.16e3),",",i0)', &
                   iostat=stat) step, increment, time, model%contact_pairs(pair)%id, p, &
               model%mesh%node_ids(nodes(i)), model%mesh%coords(:, nodes(i)) + displacement(:, nodes(i)), &
               values(1:6, i), nint(values(7, i))
            if (stat /= 0) then
               call fatal_error(error, 'frix: cannot write the contact CSV file')
               return
            end if
         end do
      end do
      flush (self%contact_unit)
   end subroutine write_contact_csv

   !> One listing block per contact pass: `CONTACT PAIR <id> PASS <p>`, a row per slave node.
   subroutine write_contact_listing(self, model, context, error)
      class(results_output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(newton_context_t), intent(in) :: context
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: nodes(:)
      real(dp), allocatable :: values(:, :)
      integer :: p, pair
      do p = 1, size(context%contact%passes)
         call contact_pass_table(context%contact, p, pair, nodes, values)
         call self%listing%write_table('CONTACT PAIR '//to_string(model%contact_pairs(pair)%id)//' PASS '// &
                                       to_string(p), 'NODE', contact_table_labels, model%mesh%node_ids(nodes), &
                                       values, error)
         if (allocated(error)) return
      end do
   end subroutine write_contact_listing

   subroutine output_close(self, error)
      class(results_output_t), intent(inout) :: self
      type(error_t), allocatable, intent(inout) :: error
      type(error_t), allocatable :: close_error
      if (self%listing%is_open()) call self%listing%close(close_error)
      if (self%has_history) call self%history%close(close_error)
      if (self%pos3d_open) call self%pos3d%close(close_error)
      if (self%hdf5_open) call self%hdf5%close(close_error)
      if (self%contact_unit /= -1) close (self%contact_unit)
      if (allocated(close_error) .and. .not. allocated(error)) call move_alloc(close_error, error)
   end subroutine output_close
end module frix_results_output
