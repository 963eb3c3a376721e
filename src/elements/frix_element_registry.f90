!> The element registry: a table of (shape keyword, constructor) entries. For each shape of an
!> element line it answers how many nodes the shape has and which option keywords it takes,
!> and it turns the keyword, the options (a property list) and the kinematics into an element
!> formulation object; the deck reader names no element type. Each shape's file reads and
!> validates its own options.
!>
!> Shapes (case-insensitive; frix_hex8_options):
!>   HEX8      8-node hexahedron, option EAS 0 (default), 3, 9, 21 or 30
!>   HEXA8-E3  CARAT's name of HEX8 with EAS 3
!>   TET4      4-node tetrahedron, no options (frix_cell_solid)
!>   TET10     10-node tetrahedron, no options (frix_cell_solid)
!>   PLANE4    4-node quadrilateral, plane strain, options THICKNESS (default 1), EAS 0 or 4
!>   PLANE3    3-node triangle, plane strain, option THICKNESS (frix_plane_solid_options)
!>   AXISYM4   4-node quadrilateral, axisymmetric (x = radius, y = axis), option EAS 0 or 4
!>   AXISYM3   3-node triangle, axisymmetric (EAS 0 only)
module frix_element_registry
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_property_list, only: property_list_t, property_spec_t, keyword_index, joined
   use frix_element, only: element_t, kinematics_linear, kinematics_total_lagrangian
   use frix_hex8_options, only: hex8_options, hex8_from_options, hexa8_e3_from_options
   use frix_cell_solid, only: tet4_from_options, tet10_from_options, no_options
   use frix_plane_solid_options, only: plane_strain_options, axisymmetric_options, plane4_from_options, &
                                       plane3_from_options, axisym4_from_options, axisym3_from_options
   implicit none
   private

   public :: element_shape_t, create_element, find_element_shape, element_shape_choices, &
             element_shape_example, max_element_nodes

   integer, parameter :: keyword_length = 16

   abstract interface
      !> A shape's constructor from its options (owner: the shape keyword).
      subroutine element_constructor(options, kinematics, element, error)
         import :: property_list_t, element_t, error_t
         type(property_list_t), intent(in) :: options
         integer, intent(in) :: kinematics
         class(element_t), allocatable, intent(out) :: element
         type(error_t), allocatable, intent(out) :: error
      end subroutine element_constructor

      !> The option keywords a shape takes.
      function option_specs() result(specs)
         import :: property_spec_t
         type(property_spec_t), allocatable :: specs(:)
      end function option_specs
   end interface

   type :: element_entry_t
      character(len=keyword_length) :: keyword   !! upper case, as printed
      character(len=keyword_length) :: family    !! named in node-count messages
      character(len=keyword_length) :: cell      !! the reference cell of its elements (frix_cell_registry)
      integer :: n_nodes
      procedure(element_constructor), pointer, nopass :: create => null()
      procedure(option_specs), pointer, nopass :: options => null()
   end type element_entry_t

   !> What a deck reader needs to know of a shape.
   type :: element_shape_t
      character(len=keyword_length) :: keyword = ''
      character(len=keyword_length) :: family = ''
      character(len=keyword_length) :: cell = ''   !! the cell its elements must have
      integer :: n_nodes = 0
      type(property_spec_t), allocatable :: options(:)
   end type element_shape_t

contains

   !> The registered shapes: one line per shape (keyword, family, cell, node count, constructor,
   !> options).
   function element_table() result(table)
      type(element_entry_t), allocatable :: table(:)
      table = [element_entry_t('HEX8', 'HEX8', 'HEX8', 8, hex8_from_options, hex8_options), &
               element_entry_t('HEXA8-E3', 'HEX8', 'HEX8', 8, hexa8_e3_from_options, hex8_options), &
               element_entry_t('TET4', 'TET4', 'TET4', 4, tet4_from_options, no_options), &
               element_entry_t('TET10', 'TET10', 'TET10', 10, tet10_from_options, no_options), &
               element_entry_t('PLANE4', 'PLANE4', 'QUAD4', 4, plane4_from_options, plane_strain_options), &
               element_entry_t('AXISYM4', 'AXISYM4', 'QUAD4', 4, axisym4_from_options, axisymmetric_options), &
               element_entry_t('PLANE3', 'PLANE3', 'TRI3', 3, plane3_from_options, plane_strain_options), &
               element_entry_t('AXISYM3', 'AXISYM3', 'TRI3', 3, axisym3_from_options, axisymmetric_options)]
   end function element_table

   !> The shape of `keyword` (any case); `found` false if no shape has it.
   subroutine find_element_shape(keyword, shape, found)
      character(len=*), intent(in) :: keyword
      type(element_shape_t), intent(out) :: shape
      logical, intent(out) :: found
      type(element_entry_t), allocatable :: table(:)
      integer :: i
      table = element_table()
      i = keyword_index([table%keyword], keyword)
      found = i > 0
      if (.not. found) return
      shape%keyword = table(i)%keyword
      shape%family = table(i)%family
      shape%cell = table(i)%cell
      shape%n_nodes = table(i)%n_nodes
      shape%options = table(i)%options()
   end subroutine find_element_shape

   !> "HEX8 or HEXA8-E3": the shapes as a deck message lists them.
   function element_shape_choices() result(text)
      character(len=:), allocatable :: text
      type(element_entry_t), allocatable :: table(:)
      integer :: n
      table = element_table()
      n = size(table)
      text = trim(table(n)%keyword)
      if (n > 1) text = joined(table(1:n - 1)%keyword)//' or '//text
   end function element_shape_choices

   !> The first shape, as an example in messages.
   function element_shape_example() result(text)
      character(len=:), allocatable :: text
      type(element_entry_t), allocatable :: table(:)
      table = element_table()
      text = trim(table(1)%keyword)
   end function element_shape_example

   !> The most nodes of any shape.
   integer function max_element_nodes()
      type(element_entry_t), allocatable :: table(:)
      table = element_table()
      max_element_nodes = maxval(table%n_nodes)
   end function max_element_nodes

   !> Element formulation for `shape_keyword` with `options` and `kinematics`
   !> (kinematics_linear or kinematics_total_lagrangian).
   subroutine create_element(shape_keyword, options, kinematics, element, error)
      character(len=*), intent(in) :: shape_keyword   !! e.g. 'HEX8', 'hexa8-e3'
      type(property_list_t), intent(in) :: options    !! e.g. EAS 9
      integer, intent(in) :: kinematics
      class(element_t), allocatable, intent(out) :: element
      type(error_t), allocatable, intent(out) :: error
      type(element_entry_t), allocatable :: table(:)
      type(property_list_t) :: named
      integer :: i
      if (kinematics /= kinematics_linear .and. kinematics /= kinematics_total_lagrangian) then
         call fatal_error(error, 'unknown kinematics code '//to_string(kinematics)// &
                          ' for element shape '//trim(shape_keyword))
         return
      end if
      table = element_table()
      i = keyword_index([table%keyword], shape_keyword)
      if (i == 0) then
         call fatal_error(error, 'unknown element shape "'//trim(shape_keyword)// &
                          '" (valid: '//joined(table%keyword)//')')
         return
      end if
      named = options
      named%owner = table(i)%keyword
      call table(i)%create(named, kinematics, element, error)
   end subroutine create_element
end module frix_element_registry
