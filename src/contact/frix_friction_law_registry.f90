!> The friction law registry: a table of (deck keyword, constructor) entries that turns a
!> keyword and its (name, value) property pairs into a friction law object (keywords and
!> property names match case-insensitively). Each law's file parses its own properties, says
!> which properties it takes and when a contact pair without LAW gets it (the keyword lookup
!> and the union of the properties are frix_contact_law_table's):
!>   COULOMB       Coulomb friction, property MU (required, >= 0; MU = 0 is frictionless);
!>                 the default of a pair with MU > 0
!>   FRICTIONLESS  no tangential traction and no tangential stiffness; no properties; the
!>                 default otherwise
module frix_friction_law_registry
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_property_list, only: property_list_t, property_spec_t, new_property_list, keyword_index
   use frix_contact_law_table, only: law_entry_t, table_property_specs, find_law
   use frix_friction_law, only: friction_law_t
   use frix_coulomb_friction, only: coulomb_from_properties, frictionless_from_properties, &
                                    coulomb_properties, frictionless_properties, &
                                    coulomb_by_default, frictionless_by_default
   implicit none
   private

   public :: create_friction_law, create_pair_friction_law, friction_property_specs, default_friction_law

   abstract interface
      subroutine friction_constructor(properties, law, error)
         import :: property_list_t, friction_law_t, error_t
         type(property_list_t), intent(in) :: properties
         class(friction_law_t), allocatable, intent(out) :: law
         type(error_t), allocatable, intent(out) :: error
      end subroutine friction_constructor

      !> Whether a contact pair without LAW, giving `given`, gets this law.
      logical function default_choice(given)
         import :: property_list_t
         type(property_list_t), intent(in) :: given
      end function default_choice
   end interface

   !> keyword, properties (law_entry_t), constructor, default rule
   type, extends(law_entry_t) :: friction_entry_t
      procedure(friction_constructor), pointer, nopass :: create => null()
      procedure(default_choice), pointer, nopass :: by_default => null()
   end type friction_entry_t

   interface create_friction_law
      module procedure create_friction_law_from_list, create_friction_law_from_arrays
   end interface create_friction_law

contains

   !> The registered laws: one line per law; a pair without LAW gets the first whose
   !> by_default holds.
   function friction_table() result(table)
      type(friction_entry_t), allocatable :: table(:)
      table = [friction_entry_t('COULOMB', coulomb_properties, coulomb_from_properties, coulomb_by_default), &
               friction_entry_t('FRICTIONLESS', frictionless_properties, frictionless_from_properties, &
                                frictionless_by_default)]
   end function friction_table

   !> Every property some law takes (each name once), as a deck reads them.
   function friction_property_specs() result(specs)
      type(property_spec_t), allocatable :: specs(:)
      specs = table_property_specs(friction_table())
   end function friction_property_specs

   !> The keyword of the law of a contact pair that names none and gives `given`.
   function default_friction_law(given) result(keyword)
      type(property_list_t), intent(in) :: given
      character(len=:), allocatable :: keyword
      type(friction_entry_t), allocatable :: table(:)
      integer :: i
      table = friction_table()
      keyword = trim(table(size(table))%keyword)
      do i = 1, size(table)
         if (.not. table(i)%by_default(given)) cycle
         keyword = trim(table(i)%keyword)
         return
      end do
   end function default_friction_law

   !> The law `keyword` of a contact pair from the friction properties the pair gives: those the
   !> law takes (with their defaults where not given); the others are ignored.
   subroutine create_pair_friction_law(keyword, given, law, error)
      character(len=*), intent(in) :: keyword
      type(property_list_t), intent(in) :: given
      class(friction_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      type(friction_entry_t), allocatable :: table(:)
      integer :: i
      table = friction_table()
      i = keyword_index(table%keyword, keyword)
      if (i == 0) then
         call create_friction_law_from_list(keyword, given, law, error)
      else
         call create_friction_law_from_list(keyword, given%restricted_to(table(i)%properties()), law, error)
      end if
   end subroutine create_pair_friction_law

   !> Create the friction law of deck keyword `keyword`. Every mistake (unknown law, unknown or
   !> repeated property, missing or out-of-range value) is reported, one per line of
   !> `error%message`; `law` is then not allocated.
   subroutine create_friction_law_from_list(keyword, properties, law, error)
      character(len=*), intent(in) :: keyword            !! COULOMB or FRICTIONLESS (any case)
      type(property_list_t), intent(in) :: properties    !! e.g. MU
      class(friction_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      type(friction_entry_t), allocatable :: table(:)
      type(property_list_t) :: named
      integer :: i
      table = friction_table()
      call find_law(table, keyword, 'friction law', 'laws', i, error)
      if (i == 0) return
      named = properties
      named%owner = table(i)%keyword
      call table(i)%create(named, law, error)
   end subroutine create_friction_law_from_list

   !> create_friction_law with the properties as two arrays of the same size.
   subroutine create_friction_law_from_arrays(keyword, property_names, property_values, law, error)
      character(len=*), intent(in) :: keyword
      character(len=*), intent(in) :: property_names(:)
      real(dp), intent(in) :: property_values(:)
      class(friction_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      type(property_list_t) :: properties
      call new_property_list(trim(adjustl(keyword)), property_names, property_values, properties, error)
      if (.not. allocated(error)) call create_friction_law_from_list(keyword, properties, law, error)
   end subroutine create_friction_law_from_arrays
end module frix_friction_law_registry
