!> The material registry: turns a deck keyword and its (name, value) property pairs into a
!> material object, so that the deck reader knows no law in particular.
!>
!> Laws and their properties (keywords and property names are matched case-insensitively):
!>   MAT_Struct_LinearElastic      Hooke (frix_linear_elastic)
!>   MAT_Struct_StVenantKirchhoff  St. Venant-Kirchhoff (frix_saint_venant_kirchhoff)
!>   MAT_Struct_NeoHooke           compressible neo-Hookean (frix_neo_hookean)
!> each with YOUNG (required, > 0), NUE (required, -1 < NUE < 0.5), DENS (optional, >= 0,
!> default 0; mass per unit reference volume).
!> MAT_3DMisesPlastic (deck keyword of the CARAT family, properties YOUNG NUE SIGY HARD) is
!> recognised but not implemented yet: it returns an error saying so.
module frix_material_registry
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error, append_error
   use frix_strings, only: to_string, to_upper
   use frix_material, only: material_t
   use frix_linear_elastic, only: new_linear_elastic
   use frix_saint_venant_kirchhoff, only: new_saint_venant_kirchhoff
   use frix_neo_hookean, only: new_neo_hookean
   implicit none
   private

   public :: create_material, material_keywords, keyword_length

   integer, parameter :: keyword_length = 32  !! length of the names returned by material_keywords

   !> Implemented laws, as they are printed (the match is case-insensitive).
   character(len=keyword_length), parameter :: implemented_keywords(3) = [character(len=keyword_length) :: &
      'MAT_Struct_LinearElastic', 'MAT_Struct_StVenantKirchhoff', 'MAT_Struct_NeoHooke']
   !> Laws known from the CARAT family but not implemented yet.
   character(len=*), parameter :: plasticity_keyword = 'MAT_3DMisesPlastic'
   !> Properties accepted by every implemented (elastic) law.
   character(len=8), parameter :: elastic_properties(3) = [character(len=8) :: 'YOUNG', 'NUE', 'DENS']

contains

   !> Names of the implemented material laws, in the spelling of the documentation.
   pure function material_keywords() result(keywords)
      character(len=keyword_length) :: keywords(size(implemented_keywords))
      keywords = implemented_keywords
   end function material_keywords

   !> Create the material of deck keyword `keyword` from its properties. Every mistake found
   !> (unknown or repeated property, missing or out-of-range value) is reported, one per line
   !> of `error%message`, each naming the keyword; `material` is then not allocated.
   subroutine create_material(keyword, property_names, property_values, material, error)
      character(len=*), intent(in) :: keyword            !! e.g. MAT_Struct_StVenantKirchhoff
      character(len=*), intent(in) :: property_names(:)  !! e.g. YOUNG, NUE, DENS (any case)
      real(dp), intent(in) :: property_values(:)         !! value of each name, same order
      class(material_t), allocatable, intent(out) :: material
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: law, name
      real(dp) :: young, poisson, density
      logical :: has_young, has_poisson, has_density
      integer :: i, j

      law = law_spelling(keyword)
      if (to_upper(trim(adjustl(keyword))) == to_upper(plasticity_keyword)) then
         call fatal_error(error, plasticity_keyword//': plasticity is not implemented yet')
         return
      else if (len(law) == 0) then
         call fatal_error(error, 'unknown material law "'//trim(adjustl(keyword))// &
                          '"; valid laws: '//joined(implemented_keywords))
         return
      end if
      if (size(property_names) /= size(property_values)) then
         call fatal_error(error, law//': '//to_string(size(property_names))//' property names but '// &
                          to_string(size(property_values))//' values')
         return
      end if

      has_young = .false.
      has_poisson = .false.
      has_density = .false.
      young = 0.0_dp
      poisson = 0.0_dp
      density = 0.0_dp
      do i = 1, size(property_names)
         name = to_upper(trim(adjustl(property_names(i))))
         do j = 1, i - 1
            if (to_upper(trim(adjustl(property_names(j)))) == name) then
               call append_error(error, law//': property '//name//' given twice')
               exit
            end if
         end do
         select case (name)
         case ('YOUNG')
            has_young = .true.
            young = property_values(i)
         case ('NUE')
            has_poisson = .true.
            poisson = property_values(i)
         case ('DENS')
            has_density = .true.
            density = property_values(i)
         case default
            call append_error(error, law//': unknown property "'//name//'" (valid: '// &
                              joined(elastic_properties)//')')
         end select
      end do

      if (.not. has_young) call append_error(error, law//': missing property YOUNG')
      if (.not. has_poisson) call append_error(error, law//': missing property NUE')
      if (has_young .and. .not. (young > 0.0_dp)) &
         call append_error(error, law//': YOUNG must be > 0, got '//to_string(young))
      if (has_poisson .and. .not. (poisson > -1.0_dp .and. poisson < 0.5_dp)) &
         call append_error(error, law//': NUE must lie in (-1, 0.5), got '//to_string(poisson))
      if (has_density .and. .not. (density >= 0.0_dp)) &
         call append_error(error, law//': DENS must be >= 0, got '//to_string(density))
      if (allocated(error)) return

      select case (law)
      case ('MAT_Struct_LinearElastic')
         allocate (material, source=new_linear_elastic(young, poisson, density))
      case ('MAT_Struct_StVenantKirchhoff')
         allocate (material, source=new_saint_venant_kirchhoff(young, poisson, density))
      case ('MAT_Struct_NeoHooke')
         allocate (material, source=new_neo_hookean(young, poisson, density))
      end select
   end subroutine create_material

   !> The documented spelling of an implemented law matching `keyword` case-insensitively,
   !> or an empty string.
   pure function law_spelling(keyword) result(law)
      character(len=*), intent(in) :: keyword
      character(len=:), allocatable :: law
      integer :: i
      law = ''
      do i = 1, size(implemented_keywords)
         if (to_upper(trim(adjustl(keyword))) == to_upper(trim(implemented_keywords(i)))) then
            law = trim(implemented_keywords(i))
            return
         end if
      end do
   end function law_spelling

   !> Trimmed names separated by ", ".
   pure function joined(names) result(text)
      character(len=*), intent(in) :: names(:)
      character(len=:), allocatable :: text
      integer :: i
      text = ''
      do i = 1, size(names)
         if (i > 1) text = text//', '
         text = text//trim(names(i))
      end do
   end function joined
end module frix_material_registry
