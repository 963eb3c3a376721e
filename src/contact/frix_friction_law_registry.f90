!> The friction law registry: turns a deck keyword and its (name, value) property pairs into
!> a friction law object (keywords and property names match case-insensitively).
!>   COULOMB       Coulomb friction, property MU (required, >= 0; MU = 0 is frictionless)
!>   FRICTIONLESS  no tangential traction and no tangential stiffness; no properties
module frix_friction_law_registry
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error, append_error
   use frix_strings, only: to_string, to_upper
   use frix_friction_law, only: friction_law_t
   use frix_coulomb_friction, only: new_coulomb_friction
   implicit none
   private

   public :: create_friction_law

contains

   !> Create the friction law of deck keyword `keyword`. Every mistake (unknown law, unknown or
   !> repeated property, missing or out-of-range value) is reported, one per line of
   !> `error%message`; `law` is then not allocated.
   subroutine create_friction_law(keyword, property_names, property_values, law, error)
      character(len=*), intent(in) :: keyword            !! COULOMB or FRICTIONLESS (any case)
      character(len=*), intent(in) :: property_names(:)  !! e.g. MU
      real(dp), intent(in) :: property_values(:)         !! value of each name, same order
      class(friction_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: name, law_name
      real(dp) :: coefficient
      logical :: has_coefficient
      integer :: i, j

      law_name = to_upper(trim(adjustl(keyword)))
      if (law_name /= 'COULOMB' .and. law_name /= 'FRICTIONLESS') then
         call fatal_error(error, 'unknown friction law "'//trim(adjustl(keyword))// &
                          '"; valid laws: COULOMB, FRICTIONLESS')
         return
      end if
      if (size(property_names) /= size(property_values)) then
         call fatal_error(error, law_name//': '//to_string(size(property_names))// &
                          ' property names but '//to_string(size(property_values))//' values')
         return
      end if

      has_coefficient = .false.
      coefficient = 0.0_dp
      do i = 1, size(property_names)
         name = to_upper(trim(adjustl(property_names(i))))
         do j = 1, i - 1
            if (to_upper(trim(adjustl(property_names(j)))) == name) then
               call append_error(error, law_name//': property '//name//' given twice')
               exit
            end if
         end do
         if (law_name == 'COULOMB' .and. name == 'MU') then
            has_coefficient = .true.
            coefficient = property_values(i)
         else if (law_name == 'COULOMB') then
            call append_error(error, law_name//': unknown property "'//name//'" (valid: MU)')
         else
            call append_error(error, law_name//': takes no property, got "'//name//'"')
         end if
      end do
      if (law_name == 'COULOMB') then
         if (.not. has_coefficient) then
            call append_error(error, law_name//': missing property MU')
         else if (.not. (coefficient >= 0.0_dp .and. coefficient < huge(1.0_dp))) then
            call append_error(error, law_name//': MU must be >= 0, got '//to_string(coefficient))
         end if
      end if
      if (allocated(error)) return

      allocate (law, source=new_coulomb_friction(coefficient))
   end subroutine create_friction_law
end module frix_friction_law_registry
