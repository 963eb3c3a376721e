!> The data lines of the .inp keywords frix reads (Abaqus Keywords Reference; CalculiX
!> User's Manual, "Input deck format"), each read into `inp_data_t` (frix_inp_context):
!> - *NODE: `id, x, y, z`;
!> - *ELEMENT (an 8-node hexahedron): `id, n1, ..., n8`, continued on the next line after a
!>   trailing comma;
!> - *NSET, *ELSET: ids or names of sets of the same kind, any number per line; with GENERATE
!>   `first, last[, increment]`;
!> - *SURFACE, TYPE=ELEMENT: `element or element set, S1..S6`.
!> An id must be defined before a line names it. The scanner separates tokens by commas and
!> blanks; every message starts with `file:line:`, most with the column and a caret.
module frix_inp_data_lines
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string, to_upper
   use frix_text_scanner, only: text_scanner_t
   use frix_gmsh_context, only: push, shorten
   use frix_inp_context, only: inp_data_t, node_kind, element_kind, find_set, add_node, add_element
   use frix_cell_registry, only: cell_entry_t, cell_table
   implicit none
   private

   public :: read_node_line, read_element_line, read_set_line, read_generate_line, read_surface_line
   public :: where_defined

contains

   !> `id, x, y, z` (or `id, x, y`: z = 0) of *NODE; the node joins the keyword's NSET if it has one.
   subroutine read_node_line(scanner, data, file, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(inp_data_t), intent(inout) :: data
      integer, intent(in) :: file
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: xyz(3)
      integer :: id, k, existing
      call read_id(scanner, 'node', id, error)
      if (allocated(error)) return
      xyz = 0
      do k = 1, 3
         ! z may be left out (a plane mesh's node: `id, x, y`, z = 0)
         if (k == 3 .and. scanner%at_end_of_line()) exit
         call scanner%read_real(xyz(k), error)
         if (allocated(error)) return
      end do
      call scanner%expect_end_of_line(error)
      if (allocated(error)) return
      call data%node_map%insert(id, data%node_ids%count + 1, existing)
      if (existing /= 0) then
         call scanner%fail(error, 'duplicate node id '//to_string(id)//' (first defined at '// &
                           where_defined(data, data%node_files%items(existing), data%node_lines%items(existing))//')')
         return
      end if
      call add_node(data, id, xyz, file, scanner%line_number)
      if (data%target_set > 0) call push(data%sets(data%target_set)%members, data%node_ids%count)
   end subroutine read_node_line

   !> `id, n1, ..., nk` of *ELEMENT (k the nodes of the keyword's cell), or the rest of an
   !> element whose line ended with a comma. A complete element joins the keyword's ELSET if it
   !> has one.
   subroutine read_element_line(scanner, data, file, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(inp_data_t), intent(inout) :: data
      integer, intent(in) :: file
      type(error_t), allocatable, intent(out) :: error
      integer :: node_id, node, existing
      character(len=:), allocatable :: line
      if (.not. data%pending) then
         call read_id(scanner, 'element', data%pending_id, error)
         if (allocated(error)) return
         data%pending = .true.
         data%pending_count = 0
         data%pending_nodes = spread(0, 1, data%element_node_count)
         data%pending_file = file
         data%pending_line = scanner%line_number
      end if
      do while (.not. scanner%at_end_of_line() .and. data%pending_count < data%element_node_count)
         call read_id(scanner, 'node', node_id, error)
         if (allocated(error)) return
         node = data%node_map%lookup(node_id)
         if (node == 0) then
            call scanner%fail_at_token(error, 'element '//to_string(data%pending_id)//' names node '// &
                                       to_string(node_id)//', which is not defined (before this line)')
            return
         end if
         data%pending_count = data%pending_count + 1
         data%pending_nodes(data%pending_count) = node
      end do
      if (data%pending_count < data%element_node_count) then
         line = trim(scanner%line())
         if (len(line) > 0) then
            if (line(len(line):len(line)) == ',') return   ! continued on the next line
         end if
         call scanner%fail(error, 'element '//to_string(data%pending_id)//' has '//to_string(data%pending_count)// &
                           ' nodes, a '//data%element_cell_name//' needs '//to_string(data%element_node_count))
         return
      end if
      call scanner%expect_end_of_line(error)
      if (allocated(error)) then
         error%message = error%message//' (a '//data%element_cell_name//' has '// &
                         to_string(data%element_node_count)//' nodes)'
         return
      end if
      call data%element_map%insert(data%pending_id, data%element_ids%count + 1, existing)
      if (existing /= 0) then
         call scanner%fail(error, 'duplicate element id '//to_string(data%pending_id)//' (first defined at '// &
                           where_defined(data, data%element_files%items(existing), &
                                         data%element_lines%items(existing))//')')
         return
      end if
      call add_element(data, data%pending_id, data%pending_nodes, data%pending_file, data%pending_line)
      data%pending = .false.
      if (data%target_set > 0) call push(data%sets(data%target_set)%members, data%element_ids%count)
   end subroutine read_element_line

   !> A data line of *NSET or *ELSET: ids, or names of sets of the same kind, into the
   !> keyword's set.
   subroutine read_set_line(scanner, data, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(inp_data_t), intent(inout) :: data
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: token
      integer :: kind, id, member, other, k
      logical :: found
      kind = data%sets(data%target_set)%kind
      do while (.not. scanner%at_end_of_line())
         token = scanner%peek_token()
         if (verify(token, '+-0123456789') == 0) then
            call read_id(scanner, kind_name(kind), id, error)
            if (allocated(error)) return
            call existing_member(scanner, data, kind, id, member, error)
            if (allocated(error)) return
            call push(data%sets(data%target_set)%members, member)
         else
            call scanner%next_token(token, found)
            other = find_set(data, kind, token)
            if (other == 0) then
               call scanner%fail_at_token(error, 'unknown '//kind_name(kind)//' set "'//shorten(token)//'"')
               return
            end if
            do k = 1, data%sets(other)%members%count
               call push(data%sets(data%target_set)%members, data%sets(other)%members%items(k))
            end do
         end if
      end do
   end subroutine read_set_line

   !> A data line of *NSET or *ELSET with GENERATE: `first, last[, increment]`, every id of
   !> first, first + increment, ..., last defined.
   subroutine read_generate_line(scanner, data, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(inp_data_t), intent(inout) :: data
      type(error_t), allocatable, intent(out) :: error
      integer :: kind, first, last, increment, id, member
      kind = data%sets(data%target_set)%kind
      call read_id(scanner, kind_name(kind), first, error)
      if (.not. allocated(error)) call read_id(scanner, kind_name(kind), last, error)
      if (allocated(error)) return
      increment = 1
      if (.not. scanner%at_end_of_line()) then
         call read_id(scanner, 'increment', increment, error)
         if (allocated(error)) return
      end if
      call scanner%expect_end_of_line(error)
      if (allocated(error)) return
      if (last < first) then
         call scanner%fail(error, 'GENERATE: the last id '//to_string(last)//' is below the first '//to_string(first))
         return
      end if
      do id = first, last, increment
         call existing_member(scanner, data, kind, id, member, error)
         if (allocated(error)) return
         call push(data%sets(data%target_set)%members, member)
      end do
   end subroutine read_generate_line

   !> `element or element set, S1..S6` of *SURFACE, TYPE=ELEMENT: the faces join the surface.
   !> CalculiX's face k of a C3D8 (User's Manual, *DLOAD: 1: 1-2-3-4, 2: 5-8-7-6, 3: 1-5-6-2,
   !> 4: 2-6-7-3, 5: 3-7-8-4, 6: 4-8-5-1) has the nodes of frix's local face k (frix_hex8_cell),
   !> and so does face k of a C3D4 (1: 1-2-3, 2: 1-4-2, 3: 2-4-3, 4: 3-4-1; frix_tet4_cell).
   !> Face k of a plane element (*DLOAD: quadrilaterals 1: 1-2, 2: 2-3, 3: 3-4, 4: 4-1;
   !> triangles 1: 1-2, 2: 2-3, 3: 3-1) is its edge k, frix's local edge k (frix_quad4_cell,
   !> frix_tri3_cell: the same node pairs).
   subroutine read_surface_line(scanner, data, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(inp_data_t), intent(inout) :: data
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: token, label
      integer, allocatable :: elements(:), faces_of_cell(:)
      integer :: id, element, set, face, k
      logical :: found
      token = scanner%peek_token()
      if (verify(token, '+-0123456789') == 0) then
         call read_id(scanner, 'element', id, error)
         if (allocated(error)) return
         call existing_member(scanner, data, element_kind, id, element, error)
         if (allocated(error)) return
         elements = [element]
      else
         call scanner%next_token(token, found)
         set = find_set(data, element_kind, token)
         if (set == 0) then
            call scanner%fail_at_token(error, 'unknown element set "'//shorten(token)//'" in a *SURFACE')
            return
         end if
         allocate (elements(data%sets(set)%members%count))
         if (size(elements) > 0) elements = data%sets(set)%members%items(1:size(elements))
      end if
      call scanner%next_token(label, found)
      if (.not. found) then
         call scanner%fail(error, 'expected a face label S1 to S6 after the element or element set')
         return
      end if
      face = index('S1S2S3S4S5S6', to_upper(label))
      if (len(label) /= 2 .or. modulo(face, 2) /= 1) then
         call scanner%fail_at_token(error, 'expected a face label S1 to S6 (faces of an 8-node hexahedron), got "'// &
                                    shorten(label)//'"')
         return
      end if
      face = (face + 1)/2
      faces_of_cell = face_counts()
      do k = 1, size(elements)
         if (face > faces_of_cell(data%element_cells%items(elements(k)))) then
            call scanner%fail_at_token(error, 'element '//to_string(data%element_ids%items(elements(k)))// &
                                       ' has no face '//to_upper(label)//' (it has '// &
                                       to_string(faces_of_cell(data%element_cells%items(elements(k))))//')')
            return
         end if
      end do
      call scanner%expect_end_of_line(error)
      if (allocated(error)) return
      associate (surface => data%surfaces(data%target_surface))
         do k = 1, size(elements)
            call push(surface%elements, elements(k))
            call push(surface%faces, face)
         end do
      end associate
   end subroutine read_surface_line

   !> "file:line" of a definition.
   function where_defined(data, file, line) result(text)
      type(inp_data_t), intent(in) :: data
      integer, intent(in) :: file, line
      character(len=:), allocatable :: text
      text = data%files(file)%text//':'//to_string(line)
   end function where_defined

   ! ---- private ---------------------------------------------------------------------------

   !> A positive id.
   subroutine read_id(scanner, what, id, error)
      type(text_scanner_t), intent(inout) :: scanner
      character(len=*), intent(in) :: what
      integer, intent(out) :: id
      type(error_t), allocatable, intent(out) :: error
      call scanner%read_integer(id, error)
      if (allocated(error)) return
      if (id <= 0) call scanner%fail_at_token(error, 'expected a positive '//what//' id, got '//to_string(id))
   end subroutine read_id

   !> Internal number of node or element `id`, which must be defined.
   subroutine existing_member(scanner, data, kind, id, member, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(inp_data_t), intent(in) :: data
      integer, intent(in) :: kind, id
      integer, intent(out) :: member
      type(error_t), allocatable, intent(out) :: error
      if (kind == node_kind) then
         member = data%node_map%lookup(id)
      else
         member = data%element_map%lookup(id)
      end if
      if (member == 0) call scanner%fail_at_token(error, kind_name(kind)//' '//to_string(id)// &
                                                  ' is not defined (before this line)')
   end subroutine existing_member

   pure function kind_name(kind) result(name)
      integer, intent(in) :: kind
      character(len=:), allocatable :: name
      if (kind == node_kind) then
         name = 'node'
      else
         name = 'element'
      end if
   end function kind_name
   !> The faces of each cell of the cell table.
   function face_counts() result(counts)
      integer, allocatable :: counts(:)
      type(cell_entry_t), allocatable :: table(:)
      integer :: k
      table = cell_table()
      counts = [(table(k)%cell%n_faces(), k=1, size(table))]
   end function face_counts
end module frix_inp_data_lines
