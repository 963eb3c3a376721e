!> The material registry: a table of (deck keyword, constructor) entries that turns a keyword
!> and its (name, value) properties into a material object, so that the deck reader knows no
!> law in particular. Each law's file parses and validates its own properties.
!>
!> Laws (keywords and property names are matched case-insensitively):
!>   MAT_Struct_LinearElastic      Hooke (frix_linear_elastic)
!>   MAT_Struct_StVenantKirchhoff  St. Venant-Kirchhoff (frix_saint_venant_kirchhoff)
!>   MAT_Struct_NeoHooke           compressible neo-Hookean (frix_neo_hookean)
!> each with YOUNG (required, > 0), NUE (required, -1 < NUE < 0.5), DENS (optional, >= 0,
!> default 0; mass per unit reference volume).
!>   MAT_Struct_NeoHookeAbaqus     neo-Hookean of Abaqus and CalculiX (frix_abaqus_neo_hooke):
!>                                 C10 (> 0), D1 (> 0), DENS
!>   MAT_3DMisesPlastic            von Mises plasticity (frix_von_mises_plastic): also SIGY,
!>                                 HARD, SIGINF, DELTA, EPSPk/SIGYk, KINH (docs/materials.md)
!>   MAT_3DMohrCoulomb             Mohr-Coulomb plasticity (frix_mohr_coulomb): YOUNG, NUE,
!>                                 COHESION, PHI, PSI, TENSION, HARD, DENS
!>   MAT_3DDruckerPrager           Drucker-Prager plasticity (frix_drucker_prager): the same but
!>                                 TENSION, and MATCH (1 outer cone, 2 inner cone, 3 plane strain)
module frix_material_registry
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_upper
   use frix_property_list, only: property_list_t, new_property_list, joined, keyword_index
   use frix_material, only: material_t
   use frix_linear_elastic, only: linear_elastic_from_properties
   use frix_saint_venant_kirchhoff, only: saint_venant_kirchhoff_from_properties
   use frix_neo_hookean, only: neo_hookean_from_properties
   use frix_abaqus_neo_hooke, only: abaqus_neo_hooke_from_properties
   use frix_von_mises_plastic, only: von_mises_from_properties
   use frix_mohr_coulomb, only: mohr_coulomb_from_properties
   use frix_drucker_prager, only: drucker_prager_from_properties
   implicit none
   private

   public :: create_material, material_keywords, keyword_length

   integer, parameter :: keyword_length = 32  !! length of the names returned by material_keywords

   abstract interface
      !> A law's constructor from its deck properties (owner: the law's keyword).
      subroutine material_constructor(properties, material, error)
         import :: property_list_t, material_t, error_t
         type(property_list_t), intent(in) :: properties
         class(material_t), allocatable, intent(out) :: material
         type(error_t), allocatable, intent(out) :: error
      end subroutine material_constructor
   end interface

   type :: material_entry_t
      character(len=keyword_length) :: keyword   !! as printed; matched case-insensitively
      procedure(material_constructor), pointer, nopass :: create => null()
   end type material_entry_t

   interface create_material
      module procedure create_material_from_list, create_material_from_arrays
   end interface create_material

contains

   !> The registered laws: one line per law.
   function material_table() result(table)
      type(material_entry_t), allocatable :: table(:)
      table = [material_entry_t('MAT_Struct_LinearElastic', linear_elastic_from_properties), &
               material_entry_t('MAT_Struct_StVenantKirchhoff', saint_venant_kirchhoff_from_properties), &
               material_entry_t('MAT_Struct_NeoHooke', neo_hookean_from_properties), &
               material_entry_t('MAT_Struct_NeoHookeAbaqus', abaqus_neo_hooke_from_properties), &
               material_entry_t('MAT_3DMisesPlastic', von_mises_from_properties), &
               material_entry_t('MAT_3DMohrCoulomb', mohr_coulomb_from_properties), &
               material_entry_t('MAT_3DDruckerPrager', drucker_prager_from_properties)]
   end function material_table

   !> Names of the implemented material laws, in the spelling of the documentation.
   function material_keywords() result(keywords)
      character(len=keyword_length), allocatable :: keywords(:)
      type(material_entry_t), allocatable :: table(:)
      table = material_table()
      keywords = table%keyword
   end function material_keywords

   !> Create the material of deck keyword `keyword` from its properties. Every mistake found
   !> (unknown or repeated property, missing or out-of-range value) is reported, one per line
   !> of `error%message`, each naming the keyword; `material` is then not allocated.
   subroutine create_material_from_list(keyword, properties, material, error)
      character(len=*), intent(in) :: keyword            !! e.g. MAT_Struct_StVenantKirchhoff
      type(property_list_t), intent(in) :: properties    !! e.g. YOUNG, NUE, DENS
      class(material_t), allocatable, intent(out) :: material
      type(error_t), allocatable, intent(out) :: error
      type(material_entry_t), allocatable :: table(:)
      type(property_list_t) :: named
      integer :: i
      table = material_table()
      i = keyword_index([table%keyword], keyword)
      if (i > 0) then
         named = properties
         named%owner = trim(table(i)%keyword)
         call table(i)%create(named, material, error)
      else
         call fatal_error(error, 'unknown material law "'//trim(adjustl(keyword))// &
                          '"; valid laws: '//joined([table%keyword]))
      end if
   end subroutine create_material_from_list

   !> create_material with the properties as two arrays of the same size.
   subroutine create_material_from_arrays(keyword, property_names, property_values, material, error)
      character(len=*), intent(in) :: keyword
      character(len=*), intent(in) :: property_names(:)  !! any case
      real(dp), intent(in) :: property_values(:)         !! value of each name, same order
      class(material_t), allocatable, intent(out) :: material
      type(error_t), allocatable, intent(out) :: error
      type(property_list_t) :: properties
      call new_property_list(trim(adjustl(keyword)), property_names, property_values, properties, error)
      if (.not. allocated(error)) call create_material_from_list(keyword, properties, material, error)
   end subroutine create_material_from_arrays
end module frix_material_registry
