!> The analysis state from the HDF5 file of an earlier run (docs/hdf5-layout.md, "Restart"):
!> the committed displacements (with the RESET_DISPLACEMENT reference, if any), EAS parameters
!> and material history of one converged increment, and the committed slip history of every
!> contact pass (`contact/pass<p>_history`) with the multipliers and penalty factors of
!> augmented passes (`contact/pass<p>_multiplier`, `_penalty_scale`, `_multiplier_rate` with
!> PREDICT, `_tangential_multiplier` with augmented friction).
!> The increment control (`control/`: the next increment's size, the driven displacement per
!> increment of a CONTROL Path step, the last increment's displacement rate) makes the
!> continuation exact after cut-backs, under path control and with EXTRAPOLATION Linear; a
!> file without it (written before frix kept it) restarts with the step's nominal increments.
!> What is read here is what frix_results_collection puts into every increment's results.
module frix_state_restart
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_model, only: model_t
   use frix_analysis_state, only: analysis_state_t, commit_solution
   use frix_hdf5_results, only: read_restart, read_increment_array
   use frix_contact_assembly, only: get_contact_history, set_contact_history, restart_mortar_rows
   use frix_normal_contact_law, only: augmentation_t
   implicit none
   private

   public :: read_state_restart

contains

   !> `state` committed at converged increment (step, increment) of the file at `path`, whose
   !> pseudo time is returned in `time`, with the increment control stored with it
   !> (`increment_size` and `path_increment` zero when the file has none).
   subroutine read_state_restart(model, path, step, increment, state, time, increment_size, path_increment, error)
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: path
      integer, intent(in) :: step, increment
      type(analysis_state_t), intent(inout) :: state
      real(dp), intent(out) :: time
      real(dp), intent(out) :: increment_size   !! the next increment's size [pseudo time]
      real(dp), intent(out) :: path_increment   !! CONTROL Path: driven displacement per increment
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: values(:, :)
      type(augmentation_t) :: settings
      integer :: p
      time = 0.0_dp
      call read_restart(path, step, increment, time, state%u, state%alpha, state%history, error, model%mesh, &
                        state%reference_u)
      if (allocated(error)) return
      state%time = time
      call commit_solution(state)
      call read_increment_control(model, path, step, increment, state, increment_size, path_increment, error)
      if (allocated(error)) return
      if (.not. state%has_contact) return
      do p = 1, size(state%contact%passes)
         call get_contact_history(state%contact, p, values)   ! for the shape
         call read_pass_array('history', values)
         if (allocated(error)) return
         call set_contact_history(state%contact, p, values)
         associate (pass => state%contact%passes(p), parameters => model%contact_pairs(state%contact%passes(p)%pair))
            if (parameters%tied) cycle
            settings = parameters%parameters%normal%augmentation()
            if (.not. settings%augmented) cycle
            values = reshape(pass%multiplier, [1, size(pass%multiplier)])
            call read_pass_array('multiplier', values)
            if (allocated(error)) return
            pass%multiplier = values(1, :)
            pass%committed_multiplier = values(1, :)
            values = reshape([pass%normal_scale, pass%tangential_scale], [1, 2])
            call read_pass_array('penalty_scale', values)
            if (allocated(error)) return
            pass%normal_scale = values(1, 1)
            pass%committed_normal_scale = values(1, 1)
            pass%tangential_scale = values(1, 2)
            pass%committed_tangential_scale = values(1, 2)
            if (parameters%parameters%predict) then
               values = spread(pass%multiplier_rate, 1, 4)   ! for the shape (4, n)
               call read_pass_array('multiplier_rate', values)
               if (allocated(error)) return
               pass%multiplier_rate = values(1, :)
               pass%tangential_multiplier_rate = values(2:4, :)
            end if
            if (.not. parameters%parameters%tangential_augmented) cycle
            values = pass%tangential_multiplier
            call read_pass_array('tangential_multiplier', values)
            if (allocated(error)) return
            pass%tangential_multiplier = values
            pass%committed_tangential_multiplier = values
         end associate
      end do
      call restart_mortar_rows(model, state%contact, state%u)
   contains
      !> `contact/pass<p>_<name>` of the increment into `values` (sized by the caller); an
      !> error names the pass.
      subroutine read_pass_array(name, values)
         character(len=*), intent(in) :: name
         real(dp), intent(inout) :: values(:, :)
         call read_increment_array(path, step, increment, 'contact/pass'//to_string(p)//'_'//name, values, error)
         if (allocated(error)) error%message = 'contact pass '//to_string(p)//': '//error%message
      end subroutine read_pass_array
   end subroutine read_state_restart

   !> The `control` group of the increment (see the module head); all zero (no rate) when the
   !> file has none.
   subroutine read_increment_control(model, path, step, increment, state, increment_size, path_increment, error)
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: path
      integer, intent(in) :: step, increment
      type(analysis_state_t), intent(inout) :: state
      real(dp), intent(out) :: increment_size, path_increment
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: scalar(1, 1)
      real(dp), allocatable :: rate(:, :)
      logical :: found
      increment_size = 0.0_dp
      path_increment = 0.0_dp
      call read_increment_array(path, step, increment, 'control/increment_size', scalar, error, found)
      if (allocated(error) .or. .not. found) return
      increment_size = scalar(1, 1)
      call read_control('path_increment', scalar)
      if (allocated(error)) return
      path_increment = scalar(1, 1)
      call read_control('rate_start', scalar)
      if (allocated(error)) return
      allocate (rate(3, model%mesh%n_nodes))
      call read_control('displacement_rate', rate)
      if (allocated(error)) return
      state%rate_start = scalar(1, 1)
      state%rate = reshape(rate, [size(state%rate)])
   contains
      subroutine read_control(name, values)
         character(len=*), intent(in) :: name
         real(dp), intent(inout) :: values(:, :)
         call read_increment_array(path, step, increment, 'control/'//name, values, error)
         if (allocated(error)) error%message = 'increment control: '//error%message
      end subroutine read_control
   end subroutine read_increment_control
end module frix_state_restart
