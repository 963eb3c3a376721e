!> The normal contact law registry: a table of (deck keyword, constructor, property specs)
!> entries that turns the METHOD of a contact pair and its (name, value) property pairs into a
!> normal contact law object (keywords and property names match case-insensitively). Each
!> law's file parses and validates its own properties (the keyword lookup and the union of the
!> properties are frix_contact_law_table's):
!>   PENALTY   p_N = eps_N max(0, -g), property EPSN (> 0; without it eps_N is derived by the
!>             deck reader, docs/contact.md "Choosing the penalties"); the default of a pair
!>             without METHOD
!>   AUGMENTED p_N = max(0, lambda + eps_N (-g)) with Uzawa augmentations of lambda, properties
!>             EPSN, PENTOL, MAXAUG (frix_augmented_normal_law)
module frix_normal_contact_law_registry
   use frix_error, only: error_t
   use frix_property_list, only: property_list_t, property_spec_t
   use frix_contact_law_table, only: law_entry_t, table_property_specs, find_law
   use frix_normal_contact_law, only: normal_contact_law_t
   use frix_penalty_normal_law, only: penalty_from_properties, penalty_properties
   use frix_augmented_normal_law, only: augmented_from_properties, augmented_properties
   implicit none
   private

   public :: create_normal_contact_law, normal_property_specs, default_normal_method

   abstract interface
      subroutine normal_constructor(properties, law, error)
         import :: property_list_t, normal_contact_law_t, error_t
         type(property_list_t), intent(in) :: properties
         class(normal_contact_law_t), allocatable, intent(out) :: law
         type(error_t), allocatable, intent(out) :: error
      end subroutine normal_constructor
   end interface

   !> keyword, properties (law_entry_t) and constructor
   type, extends(law_entry_t) :: normal_entry_t
      procedure(normal_constructor), pointer, nopass :: create => null()
   end type normal_entry_t

contains

   !> The registered laws, one line per law; the first is the default.
   function normal_table() result(table)
      type(normal_entry_t), allocatable :: table(:)
      table = [normal_entry_t('PENALTY', penalty_properties, penalty_from_properties), &
               normal_entry_t('AUGMENTED', augmented_properties, augmented_from_properties)]
   end function normal_table

   !> The METHOD of a contact pair that names none.
   function default_normal_method() result(keyword)
      character(len=:), allocatable :: keyword
      type(normal_entry_t), allocatable :: table(:)
      table = normal_table()
      keyword = trim(table(1)%keyword)
   end function default_normal_method

   !> Every property some law takes (each name once), as a deck reads them.
   function normal_property_specs() result(specs)
      type(property_spec_t), allocatable :: specs(:)
      specs = table_property_specs(normal_table())
   end function normal_property_specs

   !> Create the normal contact law of deck keyword `keyword` (a contact pair's METHOD) from
   !> the normal-law properties the pair gives. Every mistake (unknown method, a property the
   !> law does not take, a repeated, missing or out-of-range value) is reported, one per line of
   !> `error%message`; `law` is then not allocated.
   subroutine create_normal_contact_law(keyword, properties, law, error)
      character(len=*), intent(in) :: keyword           !! PENALTY (any case)
      type(property_list_t), intent(in) :: properties   !! e.g. EPSN
      class(normal_contact_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      type(normal_entry_t), allocatable :: table(:)
      type(property_list_t) :: named
      integer :: i
      table = normal_table()
      call find_law(table, keyword, 'normal contact method', 'methods', i, error)
      if (i == 0) return
      named = properties
      named%owner = table(i)%keyword
      call table(i)%create(named, law, error)
   end subroutine create_normal_contact_law
end module frix_normal_contact_law_registry
