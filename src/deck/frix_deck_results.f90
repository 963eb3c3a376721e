!> The RESULTS section of a deck: which result files are written, how often, and the CSV
!> history columns (docs/deck-format.md, docs/output.md).
module frix_deck_results
   use frix_strings, only: to_upper, to_string
   use frix_model, only: model_t, history_request_t
   use frix_deck_tokens, only: deck_line_t
   use frix_deck_context, only: deck_reader_t, read_keyword_pairs, keyword_pair_t, require, read_dof, s_results
   implicit none
   private

   public :: read_results

contains

   subroutine read_results(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      if (.not. allocated(model%results%history)) allocate (model%results%history(0))
      call read_keyword_pairs(reader, model, s_results, [character(len=7) :: 'VTK', 'LISTING', 'POS3D', 'HDF5', 'EVERY', &
                                                                 'HISTORY'], read_results_pair)
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
            if (ok .and. model%results%pos3d) call require_pos3d_cells(reader, model, line, position - 1, ok)
         case ('HDF5')
            call reader%take_yes_no(line, position, 'HDF5', model%results%hdf5, ok)
         case ('EVERY')
            call reader%take_integer(line, position, 'EVERY', value, ok)
            call require(reader, ok, value >= 1, line, position - 1, 'EVERY must be at least 1')
            if (ok) model%results%every = value
         case ('HISTORY')
            call read_history(reader, model, line, position, request, ok)
            if (ok) model%results%history = [model%results%history, request]
         end select
      end associate
   end subroutine read_results_pair

   !> POS3D holds BRICK8 elements only (docs/pos3d.md): an error naming the first element of
   !> another cell.
   subroutine require_pos3d_cells(reader, model, line, column, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      integer, intent(in) :: column
      logical, intent(inout) :: ok
      integer :: element
      if (model%mesh%has_only_hex8()) return
      do element = 1, model%mesh%n_elements
         if (model%mesh%cell_name(element) /= 'HEX8') exit
      end do
      call reader%report(line, column, 'POS3D output holds BRICK8 (HEX8) elements only: element '// &
                         to_string(model%mesh%element_ids(element))//' is a '// &
                         model%mesh%cell_name(element)//' (write VTK or HDF5)')
      ok = .false.
   end subroutine require_pos3d_cells

   !> After HISTORY: `NODE <id> | SET <set> DOF <1-3> [KIND U|R] [SUM|MEAN]` or
   !> `CONTACT <pair id> FORCE DOF <1-3> | NORMAL`. Without SUM or MEAN the set must hold one
   !> node; SUM goes with KIND R, MEAN with KIND U.
   subroutine read_history(reader, model, line, position, request, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      type(history_request_t), intent(out) :: request
      logical, intent(inout) :: ok
      integer, allocatable :: nodes(:)
      integer :: target_position
      if (position <= line%n_tokens()) then
         if (line%keyword(position) == 'CONTACT') then
            call read_contact_history(reader, model, line, position, request, ok)
            return
         end if
      end if
      target_position = position
      call reader%take_node_target(model, line, position, nodes, ok)
      call read_dof(reader, line, position, request%component, ok)
      if (.not. ok) return
      call read_kind(reader, line, position, request, ok)
      if (.not. ok) return
      if (position <= line%n_tokens()) then
         select case (line%keyword(position))
         case ('SUM', 'MEAN')
            request%reduction = line%keyword(position)
            call check_reduction(reader, line, target_position, position, request, ok)
            position = position + 1
         end select
      end if
      if (.not. ok) return
      if (request%reduction /= '') then
         request%nodes = nodes
         request%set_name = line%token(target_position + 1)
      else if (size(nodes) /= 1) then
         call reader%report(line, target_position + 1, 'this node set has '//to_string(size(nodes))// &
                            ' nodes, not one (a total over a set: KIND R SUM or KIND U MEAN)')
         ok = .false.
      else
         request%node = nodes(1)
      end if
   end subroutine read_history

   !> `[KIND U|R]`.
   subroutine read_kind(reader, line, position, request, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      type(history_request_t), intent(inout) :: request
      logical, intent(inout) :: ok
      character(len=:), allocatable :: word
      if (position > line%n_tokens()) return
      if (line%keyword(position) /= 'KIND') return
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
   end subroutine read_kind

   !> SUM or MEAN (token `position`) needs a SET target and its KIND: R for SUM, U for MEAN.
   subroutine check_reduction(reader, line, target_position, position, request, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(deck_line_t), intent(in) :: line
      integer, intent(in) :: target_position, position
      type(history_request_t), intent(in) :: request
      logical, intent(inout) :: ok
      call require(reader, ok, line%keyword(target_position) == 'SET', line, position, &
                   trim(request%reduction)//' needs a node SET (NODE <id> is one node)')
      if (request%reduction == 'SUM') then
         call require(reader, ok, request%kind == 'R', line, position, &
                      'SUM goes with KIND R (the total reaction); for displacements use KIND U MEAN')
      else
         call require(reader, ok, request%kind == 'U', line, position, &
                      'MEAN goes with KIND U (the mean displacement); for reactions use KIND R SUM')
      end if
   end subroutine check_reduction

   !> `CONTACT <pair id> FORCE DOF <1-3> | NORMAL` (after HISTORY): a contact (not tie) pair.
   subroutine read_contact_history(reader, model, line, position, request, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      type(history_request_t), intent(inout) :: request
      logical, intent(inout) :: ok
      integer :: id, k
      position = position + 1
      request%kind = 'C'
      call reader%take_integer(line, position, 'a contact pair id', id, ok)
      if (.not. ok) return
      request%pair = 0
      if (allocated(model%contact_pairs)) then
         do k = 1, size(model%contact_pairs)
            if (model%contact_pairs(k)%id == id) request%pair = k
         end do
      end if
      call require(reader, ok, request%pair > 0, line, position - 1, 'unknown contact pair '//to_string(id))
      if (.not. ok) return
      call require(reader, ok, .not. model%contact_pairs(request%pair)%tied, line, position - 1, &
                   'pair '//to_string(id)//' is a TIE: its forces are not contact forces')
      if (.not. ok) return
      if (position <= line%n_tokens()) then
         if (line%keyword(position) == 'NORMAL') then
            position = position + 1
            request%component = 0
            return
         end if
      end if
      call reader%expect_keyword(line, position, 'FORCE', ok)
      call read_dof(reader, line, position, request%component, ok)
   end subroutine read_contact_history

end module frix_deck_results
