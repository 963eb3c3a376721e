!> What the registries of the contact laws (frix_friction_law_registry,
!> frix_normal_contact_law_registry) share: the part of a table entry that names a law and
!> describes its properties, the union of the properties of a table as a deck reads them, and
!> the lookup of a deck keyword with the message for an unknown one.
module frix_contact_law_table
   use frix_error, only: error_t, fatal_error
   use frix_property_list, only: property_spec_t, joined, keyword_index
   implicit none
   private

   public :: law_entry_t, property_specs_interface, table_property_specs, find_law

   abstract interface
      !> The properties a law takes.
      function property_specs_interface() result(specs)
         import :: property_spec_t
         type(property_spec_t), allocatable :: specs(:)
      end function property_specs_interface
   end interface

   !> A registry entry: the law's deck keyword and its properties; each registry extends it
   !> with the law's constructor.
   type :: law_entry_t
      character(len=16) :: keyword = ''
      procedure(property_specs_interface), pointer, nopass :: properties => null()
   end type law_entry_t

contains

   !> Every property some law of `table` takes (each name once, in table order).
   function table_property_specs(table) result(specs)
      class(law_entry_t), intent(in) :: table(:)
      type(property_spec_t), allocatable :: specs(:), law_specs(:)
      integer :: i, j
      allocate (specs(0))
      do i = 1, size(table)
         law_specs = table(i)%properties()
         do j = 1, size(law_specs)
            if (.not. any(specs%name == law_specs(j)%name)) specs = [specs, law_specs(j)]
         end do
      end do
   end function table_property_specs

   !> The index of `keyword` (any case) in `table`; 0 and the error
   !> `unknown <kind> "<keyword>"; valid <kinds>: <keywords>` if it has none.
   subroutine find_law(table, keyword, kind, kinds, i, error)
      class(law_entry_t), intent(in) :: table(:)
      character(len=*), intent(in) :: keyword
      character(len=*), intent(in) :: kind    !! e.g. 'friction law'
      character(len=*), intent(in) :: kinds   !! its plural in the message, e.g. 'laws'
      integer, intent(out) :: i
      type(error_t), allocatable, intent(out) :: error
      i = keyword_index(table%keyword, keyword)
      if (i == 0) call fatal_error(error, 'unknown '//kind//' "'//trim(adjustl(keyword))//'"; valid '//kinds//': '// &
                                   joined(table%keyword))
   end subroutine find_law
end module frix_contact_law_table
