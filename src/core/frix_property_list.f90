!> (name, value) pairs read from a deck - the properties of a material law, a friction law, the
!> options of an element formulation - and the helpers with which each constructor takes its
!> own: names match case-insensitively, and every mistake (unknown or repeated name, missing
!> value) is appended to one error, one line each, prefixed by the list's owner (the keyword of
!> the law), so that all of them are reported at once.
!> A property_spec_t describes one property a registry entry takes (name, whether whole, lower
!> and upper bound and the deck's message for a value beyond them, default), so that a deck
!> reader can read any registered law's or element's properties without naming them and report
!> a value out of range at its token.
module frix_property_list
   use frix_kinds, only: dp, i8
   use frix_error, only: error_t, append_error, fatal_error
   use frix_strings, only: to_string, to_upper
   implicit none
   private

   public :: property_list_t, new_property_list, joined, property_spec_t, keyword_index, spec_names

   integer, parameter :: name_length = 32

   !> One property a law or element takes, as a deck reader reads it.
   type :: property_spec_t
      character(len=name_length) :: name = ''   !! upper case, e.g. MU, EAS
      character(len=64) :: what = ''            !! the value in messages, e.g. 'an EAS parameter count'
      logical :: whole = .false.                !! an integer value
      logical :: bounded = .false.              !! value >= minimum (> minimum if strict) required
      real(dp) :: minimum = 0.0_dp
      logical :: strict = .false.
      logical :: bounded_above = .false.        !! value <= maximum required
      real(dp) :: maximum = 0.0_dp
      character(len=64) :: bound_message = ''   !! reported when the bound does not hold
      logical :: has_default = .false.          !! value used by restricted_to when not given
      real(dp) :: default = 0.0_dp
   contains
      procedure :: admits
   end type property_spec_t

   type :: property_list_t
      character(len=64) :: owner = ''                        !! prefix of every message
      character(len=name_length), allocatable :: names(:)  !! upper case, in deck order
      real(dp), allocatable :: values(:)
   contains
      procedure :: add
      procedure :: set
      procedure :: restricted_to
      procedure :: count => property_count
      procedure :: check_names
      procedure :: take_real
      procedure :: take_integer
      procedure :: same_as
   end type property_list_t

contains

   !> The list of `names` (any case) with `values`; an error if their sizes differ.
   subroutine new_property_list(owner, names, values, list, error)
      character(len=*), intent(in) :: owner
      character(len=*), intent(in) :: names(:)
      real(dp), intent(in) :: values(:)
      type(property_list_t), intent(out) :: list
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      list%owner = owner
      allocate (list%names(0), list%values(0))
      if (size(names) /= size(values)) then
         call fatal_error(error, trim(owner)//': '//to_string(size(names))//' property names but '// &
                          to_string(size(values))//' values')
         return
      end if
      do i = 1, size(names)
         call list%add(names(i), values(i))
      end do
   end subroutine new_property_list

   subroutine add(self, name, value)
      class(property_list_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: value
      if (.not. allocated(self%names)) allocate (self%names(0), self%values(0))
      self%names = [character(len=name_length) :: self%names, to_upper(trim(adjustl(name)))]
      self%values = [self%values, value]
   end subroutine add

   !> `name` set to `value`: the last value given wins (as on a deck line).
   subroutine set(self, name, value)
      class(property_list_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: value
      integer :: i
      do i = 1, self%count()
         if (self%names(i) /= to_upper(trim(adjustl(name)))) cycle
         self%values(i) = value
         return
      end do
      call self%add(name, value)
   end subroutine set

   !> The properties of `specs` only, in their order: the value given, else the spec's
   !> default; a property neither given nor defaulted is left out (its constructor reports it).
   function restricted_to(self, specs) result(list)
      class(property_list_t), intent(in) :: self
      type(property_spec_t), intent(in) :: specs(:)
      type(property_list_t) :: list
      integer :: i, j
      list%owner = self%owner
      allocate (list%names(0), list%values(0))
      do i = 1, size(specs)
         ! the last value given wins (a loop: gfortran 12's findloc with back= reads before
         ! a character array)
         do j = self%count(), 1, -1
            if (self%names(j) == specs(i)%name) exit
         end do
         if (j > 0) then
            call list%add(specs(i)%name, self%values(j))
         else if (specs(i)%has_default) then
            call list%add(specs(i)%name, specs(i)%default)
         end if
      end do
   end function restricted_to

   !> Whether `value` satisfies the spec's bounds.
   pure logical function admits(self, value)
      class(property_spec_t), intent(in) :: self
      real(dp), intent(in) :: value
      admits = .true.
      if (self%bounded_above) admits = value <= self%maximum
      if (.not. self%bounded) return
      if (self%strict) then
         admits = admits .and. value > self%minimum
      else
         admits = admits .and. value >= self%minimum
      end if
   end function admits

   !> The names of `specs`.
   pure function spec_names(specs) result(names)
      type(property_spec_t), intent(in) :: specs(:)
      character(len=name_length) :: names(size(specs))
      names = specs%name
   end function spec_names

   !> Index of `keyword` (any case, surrounding blanks ignored) in `keywords` (compared
   !> case-insensitively), 0 if absent: the lookup of every registry.
   pure integer function keyword_index(keywords, keyword)
      character(len=*), intent(in) :: keywords(:), keyword
      integer :: i
      keyword_index = 0
      do i = 1, size(keywords)
         if (to_upper(trim(adjustl(keywords(i)))) == to_upper(trim(adjustl(keyword)))) then
            keyword_index = i
            return
         end if
      end do
   end function keyword_index

   pure integer function property_count(self)
      class(property_list_t), intent(in) :: self
      property_count = 0
      if (allocated(self%names)) property_count = size(self%names)
   end function property_count

   !> Report every name given twice and every name not in `valid` (upper case).
   !> `listed`, if given, is what the message prints as the valid names (a law with numbered
   !> properties says "EPSPk, SIGYk (k = 1..50)" rather than a hundred names).
   subroutine check_names(self, valid, error, listed)
      class(property_list_t), intent(in) :: self
      character(len=*), intent(in) :: valid(:)
      type(error_t), allocatable, intent(inout) :: error
      character(len=*), intent(in), optional :: listed
      character(len=:), allocatable :: name, valid_text
      integer :: i
      if (present(listed)) then
         valid_text = listed
      else
         valid_text = joined(valid)
      end if
      do i = 1, self%count()
         name = trim(self%names(i))
         if (any(self%names(1:i - 1) == name)) &
            call append_error(error, trim(self%owner)//': property '//name//' given twice')
         if (size(valid) == 0) then
            call append_error(error, trim(self%owner)//': takes no property, got "'//name//'"')
         else if (.not. any(valid == name)) then
            call append_error(error, trim(self%owner)//': unknown property "'//name//'" (valid: '// &
                              valid_text//')')
         end if
      end do
   end subroutine check_names

   !> The value of `name` (the last one given) and whether it was given; without `default`
   !> the property is required and its absence reported.
   subroutine take_real(self, name, value, found, error, default)
      class(property_list_t), intent(in) :: self
      character(len=*), intent(in) :: name
      real(dp), intent(out) :: value
      logical, intent(out) :: found
      type(error_t), allocatable, intent(inout) :: error
      real(dp), intent(in), optional :: default
      integer :: i
      character(len=:), allocatable :: wanted
      wanted = to_upper(trim(adjustl(name)))
      value = 0.0_dp
      if (present(default)) value = default
      found = .false.
      do i = 1, self%count()
         if (self%names(i) /= wanted) cycle
         value = self%values(i)
         found = .true.
      end do
      if (.not. found .and. .not. present(default)) &
         call append_error(error, trim(self%owner)//': missing property '//name)
   end subroutine take_real

   !> As take_real, for a whole number.
   subroutine take_integer(self, name, value, found, error, default)
      class(property_list_t), intent(in) :: self
      character(len=*), intent(in) :: name
      integer, intent(out) :: value
      logical, intent(out) :: found
      type(error_t), allocatable, intent(inout) :: error
      integer, intent(in), optional :: default
      real(dp) :: real_value
      value = 0
      if (present(default)) value = default
      if (present(default)) then
         call self%take_real(name, real_value, found, error, real(default, dp))
      else
         call self%take_real(name, real_value, found, error)
      end if
      if (.not. found) return
      if (abs(real_value) < real(huge(1), dp) .and. real_value == aint(real_value)) then
         value = int(real_value)
      else if (real_value == aint(real_value)) then
         call append_error(error, trim(self%owner)//': '//name//' must be a whole number within +-'// &
                           to_string(huge(1))//', got '//number_text(real_value))
      else
         call append_error(error, trim(self%owner)//': '//name//' must be a whole number, got '//number_text(real_value))
      end if
   end subroutine take_integer

   !> A property value for messages: a whole number below 1e18 in full (2147483648), else as
   !> to_string.
   pure function number_text(value) result(text)
      real(dp), intent(in) :: value
      character(len=:), allocatable :: text
      if (abs(value) < 1.0e18_dp .and. value == aint(value)) then
         text = to_string(int(value, i8))
      else
         text = to_string(value)
      end if
   end function number_text

   !> Whether both lists give the same value to the same names (in any order).
   pure logical function same_as(self, other)
      class(property_list_t), intent(in) :: self
      type(property_list_t), intent(in) :: other
      integer :: i, j
      same_as = self%count() == other%count()
      do i = 1, self%count()
         if (.not. same_as) return
         same_as = .false.
         do j = 1, other%count()
            if (other%names(j) == self%names(i) .and. other%values(j) == self%values(i)) same_as = .true.
         end do
      end do
   end function same_as

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
end module frix_property_list
