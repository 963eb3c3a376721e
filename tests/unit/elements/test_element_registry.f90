!> Unit tests of frix_element_registry: shape keywords, EAS counts, the HEXA8-E3 alias and
!> the error messages.
module test_element_registry
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_message_contains
   use frix_element, only: element_t, kinematics_linear, kinematics_total_lagrangian
   use frix_kinds, only: dp
   use frix_property_list, only: property_list_t
   use frix_element_registry, only: create_element, element_shape_t, find_element_shape, element_shape_choices, &
                                    element_shape_example, max_element_nodes
   implicit none
   private

   public :: collect_element_registry

contains

   subroutine collect_element_registry(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [ &
              new_unittest('HEX8 with every EAS count', test_hex8_counts), &
              new_unittest('HEXA8-E3 is HEX8-EAS3', test_hexa8_e3), &
              new_unittest('unknown shape is an error', test_unknown_shape), &
              new_unittest('bad EAS count is an error', test_bad_count), &
              new_unittest('HEXA8-E3 with another EAS count is an error', test_hexa8_e3_conflict), &
              new_unittest('unknown kinematics is an error', test_bad_kinematics), &
              new_unittest('shapes answer node count and options', test_shape_info), &
              new_unittest('unknown option is an error', test_unknown_option) &
              ]
   end subroutine collect_element_registry

   subroutine test_hex8_counts(error)
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: counts(5) = [0, 3, 9, 21, 30]
      character(len=*), parameter :: names(5) = [character(len=10) :: 'HEX8', 'HEX8-EAS3', 'HEX8-EAS9', &
                                                 'HEX8-EAS21', 'HEX8-EAS30']
      class(element_t), allocatable :: element
      integer :: i
      do i = 1, size(counts)
         call create_element('hex8', eas(counts(i)), kinematics_total_lagrangian, element, error)
         if (allocated(error)) return
         call check(error, element%n_enhanced() == counts(i) .and. element%name == trim(names(i)) .and. &
                    element%n_nodes() == 8 .and. element%kinematics == kinematics_total_lagrangian, &
                    'HEX8 with EAS count '//trim(names(i))//' gave '//element%name)
         if (allocated(error)) return
      end do
   end subroutine test_hex8_counts

   subroutine test_hexa8_e3(error)
      type(error_t), allocatable, intent(out) :: error
      class(element_t), allocatable :: element
      call create_element('Hexa8-E3', eas(0), kinematics_linear, element, error)
      if (allocated(error)) return
      call check(error, element%n_enhanced() == 3 .and. element%name == 'HEX8-EAS3', &
                 'Hexa8-E3 gave '//element%name)
      if (allocated(error)) return
      call create_element('HEXA8-E3', eas(3), kinematics_linear, element, error)
      if (allocated(error)) return
      call check(error, element%n_enhanced() == 3, 'HEXA8-E3 with n_eas 3')
   end subroutine test_hexa8_e3

   subroutine test_unknown_shape(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: create_error
      class(element_t), allocatable :: element
      call create_element('WEDGE6', eas(0), kinematics_linear, element, create_error)
      call check_message_contains(error, create_error, 'unknown element shape "WEDGE6"')
      if (allocated(error)) return
      call check_message_contains(error, create_error, 'HEX8, HEXA8-E3')
   end subroutine test_unknown_shape

   subroutine test_bad_count(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: create_error
      class(element_t), allocatable :: element
      call create_element('HEX8', eas(7), kinematics_linear, element, create_error)
      call check_message_contains(error, create_error, 'unsupported number of EAS parameters 7')
      if (allocated(error)) return
      call check_message_contains(error, create_error, '0, 3, 9, 21, 30')
   end subroutine test_bad_count

   subroutine test_hexa8_e3_conflict(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: create_error
      class(element_t), allocatable :: element
      call create_element('HEXA8-E3', eas(9), kinematics_linear, element, create_error)
      call check_message_contains(error, create_error, 'conflicts with the EAS count 9')
   end subroutine test_hexa8_e3_conflict

   subroutine test_bad_kinematics(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: create_error
      class(element_t), allocatable :: element
      call create_element('HEX8', eas(0), 7, element, create_error)
      call check_message_contains(error, create_error, 'unknown kinematics')
   end subroutine test_bad_kinematics

   !> The options `EAS n` (none for n = 0, as a deck line without EAS).
   function eas(n) result(options)
      integer, intent(in) :: n
      type(property_list_t) :: options
      allocate (options%names(0), options%values(0))
      if (n /= 0) call options%add('EAS', real(n, dp))
   end function eas

   subroutine test_shape_info(error)
      type(error_t), allocatable, intent(out) :: error
      type(element_shape_t) :: shape
      logical :: found
      call find_element_shape('hexa8-e3', shape, found)
      call check(error, found .and. shape%n_nodes == 8 .and. shape%family == 'HEX8' .and. &
                 size(shape%options) == 1, 'HEXA8-E3 shape')
      if (allocated(error)) return
      call check(error, shape%options(1)%name == 'EAS' .and. shape%options(1)%whole, 'EAS option')
      if (allocated(error)) return
      call find_element_shape('WEDGE6', shape, found)
      call check(error, .not. found, 'WEDGE6 is no shape')
      if (allocated(error)) return
      call find_element_shape('tet10', shape, found)
      call check(error, found .and. shape%n_nodes == 10 .and. shape%cell == 'TET10' .and. size(shape%options) == 0, &
                 'TET10 shape: 10 nodes on TET10 cells, no options')
      if (allocated(error)) return
      call check(error, element_shape_choices() == 'HEX8, HEXA8-E3, TET4, TET10, PLANE4, AXISYM4, PLANE3 or AXISYM3' &
                 .and. element_shape_example() == 'HEX8' .and. max_element_nodes() == 10, 'choices '//element_shape_choices())
   end subroutine test_shape_info

   subroutine test_unknown_option(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: create_error
      class(element_t), allocatable :: element
      type(property_list_t) :: options
      options = eas(9)
      call options%add('GP', 2.0_dp)
      call create_element('HEX8', options, kinematics_linear, element, create_error)
      call check_message_contains(error, create_error, 'HEX8: unknown property "GP" (valid: EAS)')
   end subroutine test_unknown_option
end module test_element_registry
