!> The element registry: turns the shape keyword of a deck's element line (and the EAS count
!> and kinematics given with it) into an element formulation object.
!>
!> Shapes (case-insensitive):
!>   HEX8      8-node hexahedron; n_eas from the caller: 0 (plain), 3, 9, 21 or 30.
!>   HEXA8-E3  the seed's name of "a hybrid-mixed EAS element Hexa8-E3": HEX8 with EAS3. An
!>             n_eas of 0 (not given) or 3 is accepted; any other value is a conflict.
module frix_element_registry
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string, to_upper
   use frix_element, only: element_t, kinematics_linear, kinematics_total_lagrangian
   use frix_eas_modes, only: eas_mode_counts, is_valid_eas_count
   use frix_hex8, only: new_hex8
   implicit none
   private

   public :: create_element, element_shape_names

   !> Shape keywords understood by `create_element`, as listed in error messages.
   character(len=*), parameter :: element_shape_names = 'HEX8, HEXA8-E3'

contains

   !> Element formulation for `shape_keyword` with `n_eas` enhanced parameters and
   !> `kinematics` (kinematics_linear or kinematics_total_lagrangian).
   subroutine create_element(shape_keyword, n_eas, kinematics, element, error)
      character(len=*), intent(in) :: shape_keyword  !! e.g. 'HEX8', 'hexa8-e3'
      integer, intent(in) :: n_eas                   !! enhanced parameters requested (0 = none given)
      integer, intent(in) :: kinematics              !! kinematics_linear or kinematics_total_lagrangian
      class(element_t), allocatable, intent(out) :: element
      type(error_t), allocatable, intent(out) :: error
      integer :: n_used

      if (kinematics /= kinematics_linear .and. kinematics /= kinematics_total_lagrangian) then
         call fatal_error(error, 'unknown kinematics code '//to_string(kinematics)// &
                          ' for element shape '//trim(shape_keyword))
         return
      end if

      select case (to_upper(trim(adjustl(shape_keyword))))
      case ('HEX8')
         if (.not. is_valid_eas_count(n_eas)) then
            call fatal_error(error, 'element shape HEX8: unsupported number of EAS parameters '// &
                             to_string(n_eas)//' (valid: '//valid_counts()//')')
            return
         end if
         n_used = n_eas
      case ('HEXA8-E3')
         if (n_eas /= 0 .and. n_eas /= 3) then
            call fatal_error(error, 'element shape HEXA8-E3 is HEX8 with 3 EAS parameters; '// &
                             'it conflicts with the EAS count '//to_string(n_eas)//' given')
            return
         end if
         n_used = 3
      case default
         call fatal_error(error, 'unknown element shape "'//trim(shape_keyword)// &
                          '" (valid: '//element_shape_names//')')
         return
      end select
      allocate (element, source=new_hex8(n_used, kinematics))
   end subroutine create_element

   !> "0, 3, 9, 21, 30"
   pure function valid_counts() result(text)
      character(len=:), allocatable :: text
      integer :: i
      text = to_string(eas_mode_counts(1))
      do i = 2, size(eas_mode_counts)
         text = text//', '//to_string(eas_mode_counts(i))
      end do
   end function valid_counts
end module frix_element_registry
