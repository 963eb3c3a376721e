!> INITIAL STRESS (docs/deck-format.md): the in-situ stress of element sets, one line each,
!>   SET <element set>|ALL GEOSTATIC DATUM z0 GAMMA gamma K0 k0 [SURCHARGE q] [AXIS x|y|z]
!>   SET <element set>|ALL STRESS sxx syy szz sxy sxz syz
!> read into model%initial_stresses; once the model is valid, evaluate_initial_stresses has
!> frix_initial_stress evaluate them at the integration points and reports, at each line, an
!> element given two initial stresses, a point above its datum or a stress outside the
!> material's elastic domain.
module frix_deck_initial_stress
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_model, only: model_t, initial_stress_t
   use frix_deck_tokens, only: deck_line_t
   use frix_deck_context, only: deck_reader_t, require, resume_position, after_keyword, s_initial_stress
   use frix_initial_stress, only: apply_initial_stress
   implicit none
   private

   public :: read_initial_stresses, evaluate_initial_stresses

   character(len=*), parameter :: geostatic_keywords(5) = [character(len=9) :: 'DATUM', 'GAMMA', 'K0', 'SURCHARGE', 'AXIS']

contains

   subroutine read_initial_stresses(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(initial_stress_t) :: definition
      integer :: i, position, choice
      logical :: ok
      allocate (model%initial_stresses(0))
      i = 0
      do while (reader%next_line(s_initial_stress, i, position, ok))
         associate (line => reader%lines(i))
            definition = initial_stress_t(line=i)
            call reader%take_element_target(model, line, position, definition%elements, ok)
            call reader%take_choice(line, position, 'GEOSTATIC or STRESS', [character(len=9) :: 'GEOSTATIC', 'STRESS'], &
                                    'expected GEOSTATIC or STRESS', choice, ok)
            if (ok .and. choice == 1) then
               definition%geostatic = .true.
               call read_geostatic(reader, line, position, definition, ok)
            else if (ok) then
               call reader%take_reals(line, position, 'a stress component', definition%stress, ok)
               call reader%expect_end(line, position, ok)
            end if
            if (ok) call append(model%initial_stresses, definition)
         end associate
      end do
   end subroutine read_initial_stresses

   !> list <- [list, item], without an array constructor of a type with allocatable components.
   subroutine append(list, item)
      type(initial_stress_t), allocatable, intent(inout) :: list(:)
      type(initial_stress_t), intent(in) :: item
      type(initial_stress_t), allocatable :: longer(:)
      integer :: k
      allocate (longer(size(list) + 1))
      do k = 1, size(list)
         longer(k) = list(k)
      end do
      longer(size(longer)) = item
      call move_alloc(longer, list)
   end subroutine append

   !> The keyword/value pairs after GEOSTATIC, every mistake reported; DATUM, GAMMA and K0
   !> required.
   subroutine read_geostatic(reader, line, position, definition, line_ok)
      type(deck_reader_t), intent(inout) :: reader
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      type(initial_stress_t), intent(inout) :: definition
      logical, intent(inout) :: line_ok
      logical :: given(size(geostatic_keywords)), ok
      integer :: start, k, axis
      given = .false.
      do while (position <= line%n_tokens())
         start = position
         ok = .true.
         k = geostatic_index(line%keyword(position))
         if (k == 0) then
            call reader%report(line, position, 'unknown keyword (expected DATUM, GAMMA, K0, SURCHARGE or AXIS)')
            ok = .false.
         else if (given(k)) then
            call reader%report(line, position, trim(geostatic_keywords(k))//' given twice on this line')
            ok = .false.
         end if
         position = position + 1
         select case (k)
         case (1)
            call reader%take_real(line, position, 'DATUM', definition%datum, ok)
         case (2)
            call reader%take_real(line, position, 'GAMMA', definition%unit_weight, ok)
            call require(reader, ok, definition%unit_weight >= 0.0_dp, line, position - 1, 'GAMMA must be >= 0')
         case (3)
            call reader%take_real(line, position, 'K0', definition%k0, ok)
            call require(reader, ok, definition%k0 >= 0.0_dp, line, position - 1, 'K0 must be >= 0')
         case (4)
            call reader%take_real(line, position, 'SURCHARGE', definition%surcharge, ok)
            call require(reader, ok, definition%surcharge >= 0.0_dp, line, position - 1, &
                         'SURCHARGE must be >= 0 (the vertical stress at the datum, compression positive)')
         case (5)
            call reader%take_choice(line, position, 'AXIS', [character(len=1) :: 'X', 'Y', 'Z'], &
                                    'expected AXIS x, y or z', axis, ok)
            if (ok) definition%axis = axis
         end select
         if (k > 0) given(k) = given(k) .or. ok
         call after_keyword(line, start, geostatic_keywords, position, ok, line_ok)
      end do
      do k = 1, 3
         if (line_ok .and. .not. given(k)) then
            call reader%report(line, line%n_tokens() + 1, 'missing '//trim(geostatic_keywords(k)))
            line_ok = .false.
         end if
      end do
   end subroutine read_geostatic

   !> The index of `word` (upper case) in geostatic_keywords, 0 if none.
   pure integer function geostatic_index(word) result(k)
      character(len=*), intent(in) :: word
      do k = 1, size(geostatic_keywords)
         if (geostatic_keywords(k) == word) return
      end do
      k = 0
   end function geostatic_index

   !> In a valid model: each definition evaluated at its points (frix_initial_stress), its
   !> mistakes reported at its line.
   subroutine evaluate_initial_stresses(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(error_t), allocatable :: error
      integer :: k
      do k = 1, size(model%initial_stresses)
         call apply_initial_stress(model, k, error)
         if (allocated(error)) call reader%report(reader%lines(model%initial_stresses(k)%line), 1, error%message)
      end do
   end subroutine evaluate_initial_stresses
end module frix_deck_initial_stress
