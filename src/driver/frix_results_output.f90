!> The result files of a run, written after every converged increment (so a run that stops
!> keeps everything converged): the fixed-column listing `<base>_listing.txt`, the ParaView
!> series `<base>.pvd` + `<base>_<step>_<increment>.vtu`, and the CSV history
!> `<base>_history.csv` of the RESULTS HISTORY columns, and on request the POS3D neutral file
!> `<base>.pos` and the HDF5 results/restart file `<base>.h5`. See docs/output.md.
module frix_results_output
   use frix_kinds, only: dp
   use frix_version_info, only: frix_version
   use frix_error, only: error_t, fatal_error
   use frix_model, only: model_t, history_request_t
   use frix_increment_results, only: increment_results_t, contact_pass_results_t, named_field_t
   use frix_field_recovery, only: nodal_extrapolated, cell_average
   use frix_listing_writer, only: listing_t
   use frix_vtk_writer, only: vtk_series_t
   use frix_history_writer, only: history_t, history_label, set_history_label, contact_history_label
   use frix_pos3d_writer, only: pos3d_writer_t
   use frix_hdf5_results, only: hdf5_results_t
   use frix_text_output, only: text_file_t
   use frix_strings, only: to_string, to_lower, to_upper
   use frix_contact_assembly, only: contact_table_labels
   use frix_process_group, only: is_root_process
   implicit none
   private

   public :: results_output_t

   type :: results_output_t
      integer :: n_increments = 0        !! converged increments so far
      type(listing_t) :: listing
      type(vtk_series_t) :: vtk
      type(history_t) :: history
      type(pos3d_writer_t) :: pos3d
      type(hdf5_results_t) :: hdf5
      logical :: hdf5_open = .false.
      logical :: pos3d_open = .false.
      type(text_file_t) :: contact_csv    !! <base>_contact.csv
      !> this process writes the files: process 0 alone in a parallel run (frix_process_group),
      !> the others collect the same results and write nothing
      logical :: writes = .true.
   contains
      procedure :: open => output_open
      procedure :: write_increment => output_write_increment
      procedure :: write_note => output_write_note
      procedure :: close => output_close
   end type results_output_t

contains

   subroutine output_open(self, model, base, error)
      class(results_output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: base   !! path prefix of every result file
      type(error_t), allocatable, intent(out) :: error
      integer :: slash, status
      self%writes = is_root_process()
      if (.not. self%writes) return
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
         call write_penalty_notes(self, model, error)
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
            call self%history%open(base, history_labels(model), error)
            if (allocated(error)) return
         end if
      end if
   end subroutine output_open

   !> The column label of each RESULTS HISTORY request (frix_history_writer): `u3_n31`,
   !> `r3_sum_<set>`, `u1_mean_<set>`, `c1_pair<id>`, `cn_pair<id>`.
   function history_labels(model) result(labels)
      type(model_t), intent(in) :: model
      character(len=:), allocatable :: labels(:)
      integer :: k, width
      width = 1
      do k = 1, size(model%results%history)
         width = max(width, len(history_column_label(model, model%results%history(k))))
      end do
      allocate (character(len=width) :: labels(size(model%results%history)))
      do k = 1, size(model%results%history)
         labels(k) = history_column_label(model, model%results%history(k))
      end do
   end function history_labels

   function history_column_label(model, request) result(label)
      type(model_t), intent(in) :: model
      type(history_request_t), intent(in) :: request
      character(len=:), allocatable :: label
      integer :: dof
      dof = request%component + merge(3, 0, request%kind == 'R')
      select case (request%kind)
      case ('C')
         label = contact_history_label(model%contact_pairs(request%pair)%id, request%component)
      case default
         if (request%reduction == '') then
            label = history_label(model%mesh%node_ids(request%node), dof)
         else
            label = set_history_label(request%set_name, dof, to_lower(trim(request%reduction)))
         end if
      end select
   end function history_column_label

   !> The listing's header: one comment line per contact pair with an automatic penalty
   !> (`# contact pair <id>: EPSN ...`, its penalty_note); none for pairs whose deck gives
   !> every penalty, whose listings stay as they were.
   subroutine write_penalty_notes(self, model, error)
      class(results_output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      integer :: k
      if (.not. allocated(model%contact_pairs)) return
      do k = 1, size(model%contact_pairs)
         associate (pair => model%contact_pairs(k))
            if (.not. allocated(pair%penalty_note)) cycle
            call self%listing%write_comment('contact pair '//to_string(pair%id)//': '//pair%penalty_note, error)
            if (allocated(error)) return
         end associate
      end do
   end subroutine write_penalty_notes

   !> Write the results of one converged increment: a row of the CSV files for every
   !> increment, the listing, VTK, POS3D and HDF5 files for those written in full.
   subroutine output_write_increment(self, model, results, error)
      class(results_output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(increment_results_t), intent(in) :: results
      type(error_t), allocatable, intent(out) :: error
      self%n_increments = self%n_increments + 1
      if (.not. self%writes) return
      if (self%history%is_open()) then
         call self%history%append(results%step, results%increment, results%time, results%history_values, error)
         if (allocated(error)) return
      end if
      if (results%has_contact) then
         call write_contact_csv(self, model, results, error)
         if (allocated(error)) return
      end if
      if (.not. results%full) return
      if (self%listing%is_open()) then
         call write_listing(self, model, results, error)
         if (allocated(error)) return
      end if
      if (model%results%vtk) then
         call write_vtk(self, model, results, error)
         if (allocated(error)) return
      end if
      if (self%hdf5_open) then
         call write_hdf5(self, model, results, error)
         if (allocated(error)) return
      end if
      if (model%results%pos3d) call write_pos3d(self, model, results, error)
   end subroutine output_write_increment

   subroutine write_listing(self, model, results, error)
      class(results_output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(increment_results_t), intent(in) :: results
      type(error_t), allocatable, intent(out) :: error
      integer :: p
      call self%listing%write_increment_header(results%step, results%increment, results%time, results%iterations, &
                                               error)
      if (allocated(error)) return
      if (results%yielding_points >= 0) then
         call self%listing%write_count('YIELDING POINTS', results%yielding_points, error)
         if (allocated(error)) return
      end if
      call self%listing%write_iteration_log([character(len=17) :: 'RESIDUAL_NORM', 'RELATIVE_NORM', 'ENERGY_NORM'], &
                                            results%iteration_log, error)
      if (allocated(error)) return
      call self%listing%write_displacements(model%mesh, results%displacement, error)
      if (allocated(error)) return
      call self%listing%write_reactions(model%mesh, results%reaction, results%constrained, error)
      if (allocated(error)) return
      call write_listing_totals(self, model, results, error)
      if (allocated(error) .or. .not. results%has_contact) return
      ! one block per contact pass: `CONTACT PAIR <id> PASS <p>`, a row per slave node
      do p = 1, size(results%contact)
         associate (table => results%contact(p))
            call self%listing%write_table('CONTACT PAIR '//to_string(table%pair_id)//' PASS '//to_string(p), &
                                          'NODE', contact_table_labels, model%mesh%node_ids(table%nodes), &
                                          table%values, error)
            if (.not. allocated(error) .and. allocated(table%multiplier)) &
               call write_multipliers(self, model, table, p, error)
         end associate
         if (allocated(error)) return
      end do
   end subroutine write_listing

   !> The listing's `TOTALS` block: the history columns that are totals (SUM and MEAN over a
   !> set, contact resultants); none without such columns, whose listings stay as they were.
   subroutine write_listing_totals(self, model, results, error)
      class(results_output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(increment_results_t), intent(in) :: results
      type(error_t), allocatable, intent(out) :: error
      logical, allocatable :: total(:)
      character(len=:), allocatable :: labels(:)
      if (.not. allocated(model%results%history)) return
      total = model%results%history%reduction /= '' .or. model%results%history%kind == 'C'
      if (.not. any(total)) return
      labels = history_labels(model)
      call self%listing%write_totals(labels, results%history_values, total, error)
   end subroutine write_listing_totals

   !> An augmented pass's committed multipliers: `CONTACT MULTIPLIERS PAIR <id> PASS <p>`, a row
   !> per slave node: LAMBDA (normal, force/area) and, with augmented friction, LAMBDA_T_X Y Z.
   subroutine write_multipliers(self, model, table, p, error)
      class(results_output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(contact_pass_results_t), intent(in) :: table
      integer, intent(in) :: p
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: labels(4) = [character(len=10) :: 'LAMBDA', 'LAMBDA_T_X', 'LAMBDA_T_Y', &
                                                                  'LAMBDA_T_Z']
      real(dp), allocatable :: values(:, :)
      integer :: n
      n = 1
      if (allocated(table%tangential_multiplier)) n = 4
      allocate (values(n, size(table%multiplier)))
      values(1, :) = table%multiplier
      if (n == 4) values(2:4, :) = table%tangential_multiplier
      call self%listing%write_table('CONTACT MULTIPLIERS PAIR '//to_string(table%pair_id)//' PASS '//to_string(p), &
                                    'NODE', labels(:n), model%mesh%node_ids(table%nodes), values, error)
   end subroutine write_multipliers

   !> The .vtu of the increment: displacement, reaction, stress, strain, the contact fields and
   !> the materials' named history variables (extrapolated to the nodes, averaged per cell).
   subroutine write_vtk(self, model, results, error)
      class(results_output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(increment_results_t), intent(in) :: results
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: nodal(:, :), cell(:, :)
      integer :: n_nodes, f
      n_nodes = model%mesh%n_nodes
      ! with a RESET_DISPLACEMENT reference, `displacement` is the reported one: the total too,
      ! for warping by the deformed shape
      if (allocated(results%reference_displacement)) &
         call self%vtk%add_point_field('total_displacement', results%total_displacement)
      if (results%has_contact) then
         call self%vtk%add_point_field('contact_pressure', reshape(results%contact_pressure, [1, n_nodes]))
         call self%vtk%add_point_field('contact_traction', results%contact_traction)
         call self%vtk%add_point_field('contact_gap', reshape(results%contact_gap, [1, n_nodes]))
         call self%vtk%add_point_field('contact_status', reshape(results%contact_status, [1, n_nodes]))
         call self%vtk%add_point_field('contact_slip', reshape(results%contact_slip, [1, n_nodes]))
      end if
      do f = 1, size(results%point_fields)
         call recovered_field(model, results%point_fields(f), nodal, cell, error)
         if (allocated(error)) return
         call self%vtk%add_point_field(to_lower(results%point_fields(f)%name), nodal)
         call self%vtk%add_cell_field(to_lower(results%point_fields(f)%name), cell)
      end do
      call self%vtk%write_increment(model%mesh, results%step, results%increment, results%time, &
                                    results%displacement, results%reaction, results%stress, results%strain, error)
   end subroutine write_vtk

   !> A named integration-point field extrapolated to the nodes, nodal(1, n_nodes), and
   !> averaged per element, cell(1, n_elements) (frix_field_recovery, as the stresses).
   subroutine recovered_field(model, field, nodal, cell, error)
      type(model_t), intent(in) :: model
      type(named_field_t), intent(in) :: field
      real(dp), allocatable, intent(out) :: nodal(:, :), cell(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: gp(:, :, :)
      gp = reshape(field%values, [1, size(field%values, 1), size(field%values, 2)])
      allocate (nodal(1, model%mesh%n_nodes), cell(1, model%mesh%n_elements))
      call nodal_extrapolated(model%mesh%connectivity, gp, nodal, error, model%mesh%cell_indices())
      if (allocated(error)) return
      call cell_average(gp, cell, model%mesh%cell_indices())
   end subroutine recovered_field

   subroutine write_hdf5(self, model, results, error)
      class(results_output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(increment_results_t), intent(in) :: results
      type(error_t), allocatable, intent(out) :: error
      integer :: p, f
      if (results%has_contact) then
         call self%hdf5%add_contact_array('pressure', results%contact_pressure)
         call self%hdf5%add_contact_array('traction', results%contact_traction)
         call self%hdf5%add_contact_array('gap', results%contact_gap)
         call self%hdf5%add_contact_array('status', results%contact_status)
         call self%hdf5%add_contact_array('slip', results%contact_slip)
         call self%hdf5%add_contact_array('normal', results%contact_normal)
         do p = 1, size(results%contact)
            call self%hdf5%add_contact_array('pass'//to_string(p)//'_history', results%contact(p)%history)
            if (allocated(results%contact(p)%multiplier)) &
               call self%hdf5%add_contact_array('pass'//to_string(p)//'_multiplier', results%contact(p)%multiplier)
            if (allocated(results%contact(p)%tangential_multiplier)) &
               call self%hdf5%add_contact_array('pass'//to_string(p)//'_tangential_multiplier', &
                                                results%contact(p)%tangential_multiplier)
            if (allocated(results%contact(p)%multiplier_rate)) &
               call self%hdf5%add_contact_array('pass'//to_string(p)//'_multiplier_rate', &
                                                results%contact(p)%multiplier_rate)
            if (allocated(results%contact(p)%penalty)) &
               call self%hdf5%add_contact_array('pass'//to_string(p)//'_penalty', results%contact(p)%penalty)
            if (allocated(results%contact(p)%penalty_scale)) &
               call self%hdf5%add_contact_array('pass'//to_string(p)//'_penalty_scale', &
                                                results%contact(p)%penalty_scale)
         end do
      end if
      call self%hdf5%add_control_array('increment_size', reshape([results%increment_size], [1, 1]))
      call self%hdf5%add_control_array('path_increment', reshape([results%path_increment], [1, 1]))
      call self%hdf5%add_control_array('rate_start', reshape([results%rate_start], [1, 1]))
      if (allocated(results%displacement_rate)) &
         call self%hdf5%add_control_array('displacement_rate', results%displacement_rate)
      do f = 1, size(results%point_fields)
         call self%hdf5%add_point_field(to_lower(results%point_fields(f)%name), results%point_fields(f)%values)
      end do
      if (allocated(model%results%history)) then
         do f = 1, size(model%results%history)
            call self%hdf5%add_history_value(history_column_label(model, model%results%history(f)), &
                                             results%history_values(f))
         end do
      end if
      if (allocated(results%reference_displacement)) then
         call self%hdf5%write_increment(results%step, results%increment, results%time, results%displacement, &
                                        results%reaction, results%stress, results%strain, results%alpha, &
                                        results%history, error, results%total_displacement, &
                                        results%reference_displacement)
      else
         call self%hdf5%write_increment(results%step, results%increment, results%time, results%displacement, &
                                        results%reaction, results%stress, results%strain, results%alpha, &
                                        results%history, error)
      end if
   end subroutine write_hdf5

   !> A POS3D result step: displacements, Gauss stresses, and as nodal scalars the contact
   !> pressure and shear and the materials' named history variables.
   subroutine write_pos3d(self, model, results, error)
      class(results_output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(increment_results_t), intent(in) :: results
      type(error_t), allocatable, intent(out) :: error
      character(len=16), allocatable :: names(:)
      real(dp), allocatable :: scalars(:, :), nodal(:, :), cell(:, :), grown(:, :)
      integer :: n_nodes, f
      n_nodes = model%mesh%n_nodes
      allocate (names(0), scalars(0, n_nodes))
      if (results%has_contact) then
         names = [character(len=16) :: 'CONTACT_PRESSURE', 'CONTACT_SHEAR']
         scalars = transpose(reshape([results%contact_pressure, norm2(results%contact_traction, dim=1)], [n_nodes, 2]))
      end if
      do f = 1, size(results%point_fields)
         call recovered_field(model, results%point_fields(f), nodal, cell, error)
         if (allocated(error)) return
         names = [character(len=16) :: names, to_upper(results%point_fields(f)%name)]
         allocate (grown(size(names), n_nodes))
         grown(:size(names) - 1, :) = scalars
         grown(size(names), :) = nodal(1, :)
         call move_alloc(grown, scalars)
      end do
      call self%pos3d%add_step(results%time, results%displacement, results%stress, names, scalars, error)
   end subroutine write_pos3d

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
         ! E = mu (3 lambda + 2 mu)/(lambda + mu), written so that no intermediate exceeds E
         elastic(1, m) = mu*(3.0_dp - mu/(lambda + mu))
         elastic(2, m) = lambda/(2.0_dp*(lambda + mu))
      end do
      call self%pos3d%open(base//'.pos', model%title, model%mesh, error, elastic, &
                           model%blocks(model%mesh%element_block)%material)
      self%pos3d_open = .true.   ! also after a failure: the close removes the body file
   end subroutine open_pos3d

   !> `<base>_contact.csv`: one row per slave node and converged increment.
   subroutine open_contact_csv(self, base, error)
      class(results_output_t), intent(inout) :: self
      character(len=*), intent(in) :: base
      type(error_t), allocatable, intent(out) :: error
      call self%contact_csv%open(base//'_contact.csv', 'contact CSV file "'//base//'_contact.csv"', error)
      if (allocated(error)) return
      call self%contact_csv%put('step,increment,time,pair,pass,node,x,y,z,gap,pressure,'// &
                                'traction_x,traction_y,traction_z,slip,status,normal_x,normal_y,normal_z')
      call self%contact_csv%flush(error)   ! a run killed before its first increment leaves the header
   end subroutine open_contact_csv

   !> One contact CSV row: step, increment, time, pair, pass, node, x y z, gap, pressure,
   !> traction x y z, slip, status, normal x y z (the header of open_contact_csv).
   subroutine write_contact_csv(self, model, results, error)
      class(results_output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(increment_results_t), intent(in) :: results
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: contact_row_format = &
                                     '(i0,",",i0,",",es24.16e3,",",i0,",",i0,",",i0,9(",",es24.16e3),",",i0,'// &
                                     '3(",",es24.16e3))'
      character(len=512) :: row
      integer :: p, i, node
      do p = 1, size(results%contact)
         associate (table => results%contact(p))
            do i = 1, size(table%nodes)
               node = table%nodes(i)
               write (row, contact_row_format) results%step, results%increment, results%time, table%pair_id, p, &
                  model%mesh%node_ids(node), model%mesh%coords(:, node) + results%total_displacement(:, node), &
                  table%values(1:6, i), nint(table%values(7, i)), table%values(8:10, i)
               call self%contact_csv%put(trim(row))
            end do
         end associate
      end do
      call self%contact_csv%flush(error)
   end subroutine write_contact_csv

   !> A note in the listing (a `#` comment line between increments), e.g. where the reported
   !> displacements are measured from; nothing without a listing.
   subroutine output_write_note(self, text, error)
      class(results_output_t), intent(inout) :: self
      character(len=*), intent(in) :: text
      type(error_t), allocatable, intent(out) :: error
      if (self%listing%is_open()) call self%listing%write_comment(text, error)
   end subroutine output_write_note

   !> Close every file that is open, also after a failure (`error` allocated on entry, which it
   !> keeps); otherwise `error` is the first failure of a close.
   subroutine output_close(self, error)
      class(results_output_t), intent(inout) :: self
      type(error_t), allocatable, intent(inout) :: error
      type(error_t), allocatable :: close_error
      call self%listing%close(close_error)
      call keep_first(close_error, error)
      call self%history%close(close_error)
      call keep_first(close_error, error)
      call self%contact_csv%close(close_error)
      call keep_first(close_error, error)
      if (self%pos3d_open) call self%pos3d%close(close_error)
      self%pos3d_open = .false.
      call keep_first(close_error, error)
      if (self%hdf5_open) call self%hdf5%close(close_error)
      self%hdf5_open = .false.
      call keep_first(close_error, error)
   end subroutine output_close

   !> `error` = `new` unless `error` already holds an earlier failure; `new` is deallocated.
   subroutine keep_first(new, error)
      type(error_t), allocatable, intent(inout) :: new, error
      if (.not. allocated(error) .and. allocated(new)) call move_alloc(new, error)
      if (allocated(new)) deallocate (new)
   end subroutine keep_first
end module frix_results_output
