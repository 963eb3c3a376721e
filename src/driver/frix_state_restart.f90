!> The analysis state from the HDF5 file of an earlier run (docs/hdf5-layout.md, "Restart"):
!> the committed displacements (with the RESET_DISPLACEMENT reference, if any), EAS parameters
!> and material history of one converged increment, and the committed slip history of every
!> contact pass (`contact/pass<p>_history`) with the multipliers and penalty factors of
!> augmented passes (`contact/pass<p>_multiplier`, `contact/pass<p>_penalty_scale`).
!> What is read here is what frix_results_collection puts into every increment's results.
module frix_state_restart
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_model, only: model_t
   use frix_analysis_state, only: analysis_state_t, commit_solution
   use frix_hdf5_results, only: read_restart, read_increment_array
   use frix_contact_assembly, only: get_contact_history, set_contact_history
   use frix_normal_contact_law, only: augmentation_t
   implicit none
   private

   public :: read_state_restart

contains

   !> `state` committed at converged increment (step, increment) of the file at `path`, whose
   !> pseudo time is returned in `time`.
   subroutine read_state_restart(model, path, step, increment, state, time, error)
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: path
      integer, intent(in) :: step, increment
      type(analysis_state_t), intent(inout) :: state
      real(dp), intent(out) :: time
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
      if (.not. state%has_contact) return
      do p = 1, size(state%contact%passes)
         call get_contact_history(state%contact, p, values)   ! for the shape
         call read_increment_array(path, step, increment, 'contact/pass'//to_string(p)//'_history', values, error)
         if (allocated(error)) then
            error%message = 'contact pass '//to_string(p)//': '//error%message
            return
         end if
         call set_contact_history(state%contact, p, values)
         associate (pass => state%contact%passes(p))
            if (model%contact_pairs(pass%pair)%tied) cycle
            settings = model%contact_pairs(pass%pair)%parameters%normal%augmentation()
            if (.not. settings%augmented) cycle
            values = reshape(pass%multiplier, [1, size(pass%multiplier)])
            call read_increment_array(path, step, increment, 'contact/pass'//to_string(p)//'_multiplier', values, &
                                      error)
            if (allocated(error)) then
               error%message = 'contact pass '//to_string(p)//': '//error%message
               return
            end if
            pass%multiplier = values(1, :)
            pass%committed_multiplier = values(1, :)
            values = reshape([pass%normal_scale, pass%tangential_scale], [1, 2])
            call read_increment_array(path, step, increment, 'contact/pass'//to_string(p)//'_penalty_scale', values, &
                                      error)
            if (allocated(error)) then
               error%message = 'contact pass '//to_string(p)//': '//error%message
               return
            end if
            pass%normal_scale = values(1, 1)
            pass%committed_normal_scale = values(1, 1)
            pass%tangential_scale = values(1, 2)
            pass%committed_tangential_scale = values(1, 2)
            if (model%contact_pairs(pass%pair)%parameters%predict) then
               values = spread(pass%multiplier_rate, 1, 4)   ! for the shape (4, n)
               call read_increment_array(path, step, increment, 'contact/pass'//to_string(p)//'_multiplier_rate', &
                                         values, error)
               if (allocated(error)) then
                  error%message = 'contact pass '//to_string(p)//': '//error%message
                  return
               end if
               pass%multiplier_rate = values(1, :)
               pass%tangential_multiplier_rate = values(2:4, :)
            end if
            if (.not. model%contact_pairs(pass%pair)%parameters%tangential_augmented) cycle
            values = pass%tangential_multiplier
            call read_increment_array(path, step, increment, 'contact/pass'//to_string(p)//'_tangential_multiplier', &
                                      values, error)
            if (allocated(error)) then
               error%message = 'contact pass '//to_string(p)//': '//error%message
               return
            end if
            pass%tangential_multiplier = values
            pass%committed_tangential_multiplier = values
         end associate
      end do
   end subroutine read_state_restart
end module frix_state_restart
