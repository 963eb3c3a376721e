!> The deck constructors of the HEX8 family (frix_hex8), as the element registry calls them:
!> shape keyword, options from a property list (option EAS, the number of enhanced strain
!> parameters) and the kinematics of the element line. Kept apart from frix_hex8 so that the
!> formulation file holds the mechanics only.
!>   HEX8      EAS 0 (plain, default), 3, 9, 21 or 30
!>   HEXA8-E3  CARAT's name of "a hybrid-mixed EAS element Hexa8-E3": HEX8 with EAS 3;
!>             EAS not given or 3 is accepted, any other count is a conflict
module frix_hex8_options
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_property_list, only: property_list_t, property_spec_t, spec_names
   use frix_element, only: element_t
   use frix_eas_modes, only: eas_mode_counts, is_valid_eas_count
   use frix_hex8, only: new_hex8
   implicit none
   private

   public :: hex8_options, hex8_from_options, hexa8_e3_from_options

contains

   !> The options of both shapes: EAS, a whole number.
   function hex8_options() result(specs)
      type(property_spec_t), allocatable :: specs(:)
      allocate (specs(1))
      specs(1)%name = 'EAS'
      specs(1)%what = 'an EAS parameter count'
      specs(1)%whole = .true.
   end function hex8_options

   !> HEX8 with the EAS count of `options` (default 0).
   subroutine hex8_from_options(options, kinematics, element, error)
      type(property_list_t), intent(in) :: options
      integer, intent(in) :: kinematics   !! kinematics_linear or kinematics_total_lagrangian
      class(element_t), allocatable, intent(out) :: element
      type(error_t), allocatable, intent(out) :: error
      integer :: n_eas
      call eas_count(options, n_eas, error)
      if (allocated(error)) return
      if (.not. is_valid_eas_count(n_eas)) then
         call fatal_error(error, 'element shape HEX8: unsupported number of EAS parameters '// &
                          to_string(n_eas)//' (valid: '//valid_counts()//')')
         return
      end if
      allocate (element, source=new_hex8(n_eas, kinematics))
   end subroutine hex8_from_options

   !> HEXA8-E3: HEX8 with EAS 3.
   subroutine hexa8_e3_from_options(options, kinematics, element, error)
      type(property_list_t), intent(in) :: options
      integer, intent(in) :: kinematics
      class(element_t), allocatable, intent(out) :: element
      type(error_t), allocatable, intent(out) :: error
      integer :: n_eas
      call eas_count(options, n_eas, error)
      if (allocated(error)) return
      if (n_eas /= 0 .and. n_eas /= 3) then
         call fatal_error(error, 'element shape HEXA8-E3 is HEX8 with 3 EAS parameters; '// &
                          'it conflicts with the EAS count '//to_string(n_eas)//' given')
         return
      end if
      allocate (element, source=new_hex8(3, kinematics))
   end subroutine hexa8_e3_from_options

   !> The EAS option (0 when not given); unknown options are reported.
   subroutine eas_count(options, n_eas, error)
      type(property_list_t), intent(in) :: options
      integer, intent(out) :: n_eas
      type(error_t), allocatable, intent(inout) :: error
      logical :: found
      call options%check_names(spec_names(hex8_options()), error)
      call options%take_integer('EAS', n_eas, found, error, default=0)
   end subroutine eas_count

   !> "0, 3, 9, 21, 30"
   pure function valid_counts() result(text)
      character(len=:), allocatable :: text
      integer :: i
      text = to_string(eas_mode_counts(1))
      do i = 2, size(eas_mode_counts)
         text = text//', '//to_string(eas_mode_counts(i))
      end do
   end function valid_counts
end module frix_hex8_options
