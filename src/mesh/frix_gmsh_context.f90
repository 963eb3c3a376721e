!> The state of one gmsh .msh reading shared by the section readers (frix_gmsh_header,
!> frix_gmsh_nodes, frix_gmsh_elements) and by frix_gmsh_to_mesh: the file's content before
!> it becomes a mesh_t (`raw_mesh_t`), and the scanner helpers for what every section has
!> (counts, ids, physical tags, dimensions, its data lines and its `$End` line). Each helper
!> reports its own mistake through the scanner, so every message starts with `file:line:`
!> (gmsh reference manual, "MSH file format", for the meaning of the numbers).
module frix_gmsh_context
   use frix_kinds, only: dp, i8
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string, scientific
   use frix_text_scanner, only: text_scanner_t
   use frix_id_map, only: id_map_t
   use frix_hex8_cell, only: hex8_gmsh_type
   use frix_quad4_cell, only: quad4_gmsh_type
   use frix_tet4_cell, only: tet4_gmsh_type
   use frix_tri3_cell, only: tri3_gmsh_type
   use frix_tet10_cell, only: tet10_gmsh_type
   use frix_tri6_cell, only: tri6_gmsh_type
   implicit none
   private

   public :: gmsh_quadrangle, gmsh_hexahedron, gmsh_triangle, gmsh_tetrahedron, is_volume_cell, is_surface_cell
   public :: gmsh_line, is_element_cell, is_boundary_cell, first_off_plane, off_plane_message
   public :: integer_list_t, push, reserve, name_t, raw_mesh_t
   public :: claim_section, skip_section, next_data_line, expect_section_end
   public :: read_count, read_count_line, check_room
   public :: read_blocks_header, read_block_start, read_block_count, check_blocks_total
   public :: read_positive_id, read_physical_tag, read_dimension, shorten

   !> The gmsh element types frix reads: the reference cells' codes (frix_hex8_cell,
   !> frix_quad4_cell, frix_tet4_cell, frix_tri3_cell, frix_tet10_cell, frix_tri6_cell).
   integer, parameter :: gmsh_quadrangle = quad4_gmsh_type, gmsh_hexahedron = hex8_gmsh_type
   integer, parameter :: gmsh_triangle = tri3_gmsh_type, gmsh_tetrahedron = tet4_gmsh_type
   integer, parameter :: gmsh_tetrahedron10 = tet10_gmsh_type, gmsh_triangle6 = tri6_gmsh_type
   !> The 2-node line (gmsh type 1), the edge of a plane cell: matched to an element edge, not a
   !> cell of the mesh.
   integer, parameter :: gmsh_line = 1

   !> A growable list of default integers.
   type :: integer_list_t
      integer :: count = 0
      integer, allocatable :: items(:)
   end type integer_list_t

   type :: name_t
      character(len=:), allocatable :: text
   end type name_t

   !> The file's content before it becomes a mesh_t.
   type :: raw_mesh_t
      integer :: version = 0                     !! 2 (format 2.2) or 4 (format 4.1)
      ! nodes
      integer :: n_nodes = 0
      integer, allocatable :: node_ids(:), node_lines(:)   !! line of the node's id
      integer, allocatable :: coordinate_lines(:)          !! line of its coordinates (4.1: not the id's)
      real(dp), allocatable :: coords(:, :)
      ! element records kept: volume cells, quadrilaterals and triangles, and elements of physical groups
      type(integer_list_t) :: record_ids, record_types, record_lines
      type(integer_list_t) :: record_node_first   !! record r: nodes(first(r):first(r+1)-1)
      type(integer_list_t) :: record_nodes        !! user node ids
      type(integer_list_t) :: record_group_first  !! record r: groups(first(r):first(r+1)-1)
      type(integer_list_t) :: record_groups       !! indices into the group table
      ! physical groups met in elements or entities
      type(integer_list_t) :: group_dims, group_tags
      ! $PhysicalNames
      type(integer_list_t) :: name_dims, name_tags, name_lines
      type(name_t), allocatable :: names(:)
      ! 4.1 $Entities: physical tags of entity (dim, tag), by dim 0..3
      type(id_map_t) :: entity_map(0:3)
      type(integer_list_t) :: entity_physical_first(0:3), entity_physicals(0:3)
      ! line of each section that may appear only once (0: not met)
      integer :: mesh_format_line = 0, physical_names_line = 0, entities_line = 0
      integer :: nodes_line = 0, elements_line = 0
   end type raw_mesh_t

contains

   !> Whether gmsh element type `element_type` is a volume cell frix reads (HEX8, TET4, TET10).
   pure logical function is_volume_cell(element_type)
      integer, intent(in) :: element_type
      is_volume_cell = element_type == gmsh_hexahedron .or. element_type == gmsh_tetrahedron .or. &
                       element_type == gmsh_tetrahedron10
   end function is_volume_cell

   !> Whether gmsh element type `element_type` is a face cell of a volume cell frix reads
   !> (QUAD4, TRI3, TRI6).
   pure logical function is_surface_cell(element_type)
      integer, intent(in) :: element_type
      is_surface_cell = element_type == gmsh_quadrangle .or. element_type == gmsh_triangle .or. &
                        element_type == gmsh_triangle6
   end function is_surface_cell

   !> Whether gmsh element type `element_type` gives an element of a mesh of dimension `dim`:
   !> a volume cell (3), or a 4-node quadrilateral or 3-node triangle (2: a plane mesh, QUAD4
   !> and TRI3 cells, the cells of the plane strain and axisymmetric elements).
   pure logical function is_element_cell(element_type, dim)
      integer, intent(in) :: element_type, dim
      select case (dim)
      case (3)
         is_element_cell = is_volume_cell(element_type)
      case (2)
         is_element_cell = element_type == gmsh_quadrangle .or. element_type == gmsh_triangle
      case default
         is_element_cell = .false.
      end select
   end function is_element_cell

   !> Whether gmsh element type `element_type` is a boundary cell of a mesh of dimension `dim`
   !> (one dimension lower, matched to the elements' faces): a face cell of a volume cell (3),
   !> or a 2-node line, the edge of a plane cell (2).
   pure logical function is_boundary_cell(element_type, dim)
      integer, intent(in) :: element_type, dim
      select case (dim)
      case (3)
         is_boundary_cell = is_surface_cell(element_type)
      case (2)
         is_boundary_cell = element_type == gmsh_line
      case default
         is_boundary_cell = .false.
      end select
   end function is_boundary_cell

   !> The first of the nodes (`coords`, 3 x n) of a plane mesh that is not in the x-y plane,
   !> 0 if none: |z| above plane_z_tolerance times the largest |x|, |y| of the nodes.
   pure integer function first_off_plane(coords) result(first)
      real(dp), intent(in) :: coords(:, :)
      ! round-off (mesh generators write coordinates with 16 significant digits), not a third dimension
      real(dp), parameter :: plane_z_tolerance = 1.0e-12_dp
      real(dp) :: extent
      integer :: i
      first = 0
      if (size(coords, 2) == 0) return
      extent = maxval(abs(coords(1:2, :)))
      do i = 1, size(coords, 2)
         if (abs(coords(3, i)) > plane_z_tolerance*extent) then
            first = i
            return
         end if
      end do
   end function first_off_plane

   !> The message for node `id` of a plane mesh at height `z` (first_off_plane).
   pure function off_plane_message(id, z) result(message)
      integer, intent(in) :: id
      real(dp), intent(in) :: z
      character(len=:), allocatable :: message
      message = 'node '//to_string(id)//' has z = '//scientific(z, 6)//': the mesh has plane elements (no volume '// &
                'elements), whose nodes lie in the x-y plane (z = 0)'
   end function off_plane_message

   ! ---- sections ---------------------------------------------------------------------------

   !> Error if a section that may appear once was met before, on line `first_line` (0: not
   !> met); else the current line becomes its `first_line`.
   subroutine claim_section(scanner, section, first_line, error)
      type(text_scanner_t), intent(inout) :: scanner
      character(len=*), intent(in) :: section
      integer, intent(inout) :: first_line
      type(error_t), allocatable, intent(out) :: error
      if (first_line /= 0) then
         call scanner%fail(error, 'a second '//section//' section (the first is on line '//to_string(first_line)//')')
         return
      end if
      first_line = scanner%line_number
   end subroutine claim_section

   !> Skip a section we do not use, up to its `$End...` line.
   subroutine skip_section(scanner, section, error)
      type(text_scanner_t), intent(inout) :: scanner
      character(len=*), intent(in) :: section
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: token
      logical :: found
      do while (scanner%next_line())
         call scanner%next_token(token, found)
         if (token == '$End'//section(2:)) return
      end do
      call fail_without_end(scanner, section, error)
   end subroutine skip_section

   !> Advance to the next line of `section`: error at the end of the file, or if a `$` line
   !> comes first (the section holds fewer entries than its counts declare).
   subroutine next_data_line(scanner, section, error)
      type(text_scanner_t), intent(inout) :: scanner
      character(len=*), intent(in) :: section
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: token
      if (.not. scanner%next_line()) then
         call scanner%fail(error, 'truncated file: end of file inside section '//section)
         return
      end if
      token = scanner%peek_token()
      if (len(token) > 0) then
         if (token(1:1) == '$') call scanner%fail(error, 'bad counts: "'//shorten(token)//'" inside section '// &
                                                  section//', which holds fewer entries than declared')
      end if
   end subroutine next_data_line

   !> The next line must be `$End<name>`.
   subroutine expect_section_end(scanner, section, error)
      type(text_scanner_t), intent(inout) :: scanner
      character(len=*), intent(in) :: section
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: token
      logical :: found
      if (.not. scanner%next_line()) then
         call fail_without_end(scanner, section, error)
         return
      end if
      call scanner%next_token(token, found)
      if (token /= '$End'//section(2:)) then
         call scanner%fail(error, 'bad counts: expected $End'//section(2:)//', got "'//shorten(token)// &
                           '" (more entries than declared?)')
      end if
   end subroutine expect_section_end

   !> The end of the file came before the `$End` line of `section`.
   subroutine fail_without_end(scanner, section, error)
      type(text_scanner_t), intent(in) :: scanner
      character(len=*), intent(in) :: section
      type(error_t), allocatable, intent(out) :: error
      call scanner%fail(error, 'truncated file: end of file inside section '//section// &
                        ' (no $End'//section(2:)//')')
   end subroutine fail_without_end

   ! ---- counts -----------------------------------------------------------------------------

   !> A non-negative count token.
   subroutine read_count(scanner, section, count, error)
      type(text_scanner_t), intent(inout) :: scanner
      character(len=*), intent(in) :: section
      integer, intent(out) :: count
      type(error_t), allocatable, intent(out) :: error
      call scanner%read_integer(count, error)
      if (allocated(error)) return
      if (count < 0) call scanner%fail(error, 'bad counts: negative count "'//to_string(count)//'" in '//section)
   end subroutine read_count

   !> A line holding only a count, which must not exceed the lines left in the file.
   subroutine read_count_line(scanner, section, count, error)
      type(text_scanner_t), intent(inout) :: scanner
      character(len=*), intent(in) :: section
      integer, intent(out) :: count
      type(error_t), allocatable, intent(out) :: error
      call next_data_line(scanner, section, error)
      if (allocated(error)) return
      call read_count(scanner, section, count, error)
      if (allocated(error)) return
      call scanner%expect_end_of_line(error)
      if (allocated(error)) return
      call check_room(scanner, section, int(count, i8), 'entries', error)
   end subroutine read_count_line

   !> Error if `section` declares more `what` (one a line at least) than lines left in the file.
   subroutine check_room(scanner, section, count, what, error)
      type(text_scanner_t), intent(in) :: scanner
      character(len=*), intent(in) :: section
      integer(i8), intent(in) :: count
      character(len=*), intent(in) :: what     !! e.g. 'entries', 'nodes'
      type(error_t), allocatable, intent(out) :: error
      if (count > scanner%remaining_lines()) then
         call scanner%fail(error, section//' declares '//to_string(count)//' '//what//' but only '// &
                           to_string(scanner%remaining_lines())//' lines follow (truncated file or bad count)')
      end if
   end subroutine check_room

   ! ---- blocks of 4.1 $Nodes and $Elements -------------------------------------------------

   !> The header line of a 4.1 block section: `nblocks count mintag maxtag` (the tags are not
   !> read); `count` items, one a line at least, must fit in the file.
   subroutine read_blocks_header(scanner, section, what, n_blocks, count, header_line, error)
      type(text_scanner_t), intent(inout) :: scanner
      character(len=*), intent(in) :: section
      character(len=*), intent(in) :: what     !! 'node' or 'element'
      integer, intent(out) :: n_blocks, count, header_line
      type(error_t), allocatable, intent(out) :: error
      call next_data_line(scanner, section, error)
      if (allocated(error)) return
      header_line = scanner%line_number
      call read_count(scanner, section, n_blocks, error)
      if (allocated(error)) return
      call read_count(scanner, section, count, error)
      if (allocated(error)) return
      call check_room(scanner, section, int(count, i8), what//'s', error)
   end subroutine read_blocks_header

   !> The first three numbers of a block's line: `dim tag kind` (kind: parametric flag of a
   !> node block, element type of an element block).
   subroutine read_block_start(scanner, section, dim, tag, kind, error)
      type(text_scanner_t), intent(inout) :: scanner
      character(len=*), intent(in) :: section
      integer, intent(out) :: dim, tag, kind
      type(error_t), allocatable, intent(out) :: error
      call next_data_line(scanner, section, error)
      if (allocated(error)) return
      call read_dimension(scanner, dim, error)
      if (allocated(error)) return
      call scanner%read_integer(tag, error)
      if (allocated(error)) return
      call scanner%read_integer(kind, error)
   end subroutine read_block_start

   !> The number of items of a block, at most what the header (`count` on `header_line`)
   !> leaves after the `held` items of the blocks before.
   subroutine read_block_count(scanner, section, what, count, held, header_line, block_count, error)
      type(text_scanner_t), intent(inout) :: scanner
      character(len=*), intent(in) :: section
      character(len=*), intent(in) :: what     !! 'node' or 'element'
      integer, intent(in) :: count, held, header_line
      integer, intent(out) :: block_count
      type(error_t), allocatable, intent(out) :: error
      call read_count(scanner, section, block_count, error)
      if (allocated(error)) return
      if (block_count > count - held) then
         call scanner%fail(error, 'bad counts: the '//what//' blocks hold more than the '//to_string(count)// &
                           ' '//what//'s declared on line '//to_string(header_line))
      end if
   end subroutine read_block_count

   !> Error, at the header line, if the blocks hold fewer items (`total`) than it declares.
   subroutine check_blocks_total(scanner, section, what, count, total, header_line, error)
      type(text_scanner_t), intent(in) :: scanner
      character(len=*), intent(in) :: section
      character(len=*), intent(in) :: what     !! 'node' or 'element'
      integer, intent(in) :: count, total, header_line
      type(error_t), allocatable, intent(out) :: error
      if (total /= count) then
         call fatal_error(error, scanner%file_name//':'//to_string(header_line)//': bad counts: '//section// &
                          ' declares '//to_string(count)//' '//what//'s, its blocks hold '//to_string(total))
      end if
   end subroutine check_blocks_total

   ! ---- numbers ----------------------------------------------------------------------------

   subroutine read_positive_id(scanner, what, id, error)
      type(text_scanner_t), intent(inout) :: scanner
      character(len=*), intent(in) :: what
      integer, intent(out) :: id
      type(error_t), allocatable, intent(out) :: error
      call scanner%read_integer(id, error)
      if (allocated(error)) return
      if (id <= 0) call scanner%fail(error, 'expected a positive '//what//' id, got "'//to_string(id)//'"')
   end subroutine read_positive_id

   !> A physical tag: positive, gmsh numbers physical groups from 1; with `zero_for_none`, 0
   !> too (the first tag of a 2.2 element in no physical group).
   subroutine read_physical_tag(scanner, zero_for_none, tag, error)
      type(text_scanner_t), intent(inout) :: scanner
      logical, intent(in) :: zero_for_none
      integer, intent(out) :: tag
      type(error_t), allocatable, intent(out) :: error
      call scanner%read_integer(tag, error)
      if (allocated(error)) return
      if (tag < 0 .or. (tag == 0 .and. .not. zero_for_none)) then
         call scanner%fail(error, 'expected a positive physical tag, got "'//to_string(tag)//'"')
      end if
   end subroutine read_physical_tag

   subroutine read_dimension(scanner, dim, error)
      type(text_scanner_t), intent(inout) :: scanner
      integer, intent(out) :: dim
      type(error_t), allocatable, intent(out) :: error
      call scanner%read_integer(dim, error)
      if (allocated(error)) return
      if (dim < 0 .or. dim > 3) call scanner%fail(error, 'expected a dimension 0..3, got "'//to_string(dim)//'"')
   end subroutine read_dimension

   !> A token cut to 40 characters for messages (binary files give long garbage tokens).
   pure function shorten(token) result(short)
      character(len=*), intent(in) :: token
      character(len=:), allocatable :: short
      if (len(token) > 40) then
         short = token(1:40)//'...'
      else
         short = token
      end if
   end function shorten

   ! ---- integer_list_t ---------------------------------------------------------------------

   subroutine push(list, value)
      type(integer_list_t), intent(inout) :: list
      integer, intent(in) :: value
      if (.not. allocated(list%items)) then
         allocate (list%items(16))
      else if (list%count == size(list%items)) then
         call reserve(list, 2*list%count)
      end if
      list%count = list%count + 1
      list%items(list%count) = value
   end subroutine push

   subroutine reserve(list, capacity)
      type(integer_list_t), intent(inout) :: list
      integer, intent(in) :: capacity
      integer, allocatable :: larger(:)
      if (allocated(list%items)) then
         if (size(list%items) >= capacity) return
         allocate (larger(capacity))
         larger(1:list%count) = list%items(1:list%count)
         call move_alloc(larger, list%items)
      else
         allocate (list%items(max(capacity, 16)))
      end if
   end subroutine reserve
end module frix_gmsh_context
