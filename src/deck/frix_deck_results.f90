!> The RESULTS section of a deck: which result files are written, how often, and the CSV
!> history columns (docs/deck-format.md, docs/output.md).
module frix_deck_results
   use frix_strings, only: to_upper
   use frix_model, only: model_t, history_request_t
   use frix_deck_tokens, only: deck_line_t
   use frix_deck_context, only: deck_reader_t, read_keyword_pairs, keyword_pair_t, require, read_node_dof, s_results
   implicit none
   private

   public :: read_results

contains

   subroutine read_results(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      if (.not. allocated(model%results%history)) allocate (model%results%history(0))
      call read_keyword_pairs(reader, model, s_results, read_results_pair)
   end subroutine read_results

   !> `VTK|LISTING|POS3D|HDF5 Yes|No`, `EVERY <n>`, `HISTORY ...`.
   subroutine read_results_pair(reader, model, pair)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(keyword_pair_t), intent(inout) :: pair
      type(history_request_t) :: request
      integer :: value
      associate (line => pair%line, position => pair%position, ok => pair%ok)
         select case (pair%keyword)
         case ('VTK')
            call reader%take_yes_no(line, position, 'VTK', model%results%vtk, ok)
         case ('LISTING')
            call reader%take_yes_no(line, position, 'LISTING', model%results%listing, ok)
         case ('POS3D')
            call reader%take_yes_no(line, position, 'POS3D', model%results%pos3d, ok)
         case ('HDF5')
            call reader%take_yes_no(line, position, 'HDF5', model%results%hdf5, ok)
         case ('EVERY')
            call reader%take_integer(line, position, 'EVERY', value, ok)
            call require(reader, ok, value >= 1, line, position - 1, 'EVERY must be at least 1')
            if (ok) model%results%every = value
         case ('HISTORY')
            call read_history(reader, model, line, position, request, ok)
            if (ok) model%results%history = [model%results%history, request]
         case default
            pair%known = .false.
         end select
      end associate
   end subroutine read_results_pair

   !> `HISTORY NODE <id> | SET <one-node set> DOF <1-3> [KIND U|R]` (after HISTORY).
   subroutine read_history(reader, model, line, position, request, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      type(history_request_t), intent(out) :: request
      logical, intent(inout) :: ok
      character(len=:), allocatable :: word
      call read_node_dof(reader, model, line, position, request%node, request%component, ok)
      if (.not. ok) return
      if (position <= line%n_tokens()) then
         if (line%keyword(position) == 'KIND') then
            position = position + 1
            call reader%take_word(line, position, 'KIND value', word, ok)
            if (.not. ok) return
            select case (to_upper(word))
            case ('U', 'R')
               request%kind = to_upper(word)
            case default
               call reader%report(line, position - 1, 'unknown KIND (expected U or R)')
               ok = .false.
            end select
         end if
      end if
   end subroutine read_history

end module frix_deck_results
