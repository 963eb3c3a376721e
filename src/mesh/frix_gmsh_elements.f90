!> The `$Elements` section of a gmsh .msh file, formats 2.2 and 4.1 (gmsh reference manual,
!> "MSH file format", including its table of element types): the elements kept as records
!> (every volume cell, 4-node quadrilateral and 3-node triangle, and every element of a physical
!> group) with their node ids, their
!> line (for messages) and their physical groups. A 2.2 element names its physical group in
!> its first tag; a 4.1 element has those of its entity (`$Entities`). Other elements are
!> skipped. The group table (`group_dims`, `group_tags`) is filled as groups are met.
module frix_gmsh_elements
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_text_scanner, only: text_scanner_t
   use frix_gmsh_context, only: is_element_cell, raw_mesh_t, push, reserve, next_data_line, &
                                expect_section_end, read_count, read_count_line, read_blocks_header, &
                                read_block_start, read_block_count, check_blocks_total, read_positive_id, &
                                read_physical_tag
   implicit none
   private

   public :: read_elements_v2, read_elements_v4

contains

   !> 2.2 `$Elements`: count, then lines `id type ntags tags... nodes...`; the first tag is
   !> the physical group (0: none).
   subroutine read_elements_v2(scanner, raw, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(raw_mesh_t), intent(inout) :: raw
      type(error_t), allocatable, intent(out) :: error
      integer :: count, i, id, element_type, physical, n_nodes, dim, group
      call read_count_line(scanner, '$Elements', count, error)
      if (allocated(error)) return
      call reserve_records(raw, count)
      do i = 1, count
         call next_data_line(scanner, '$Elements', error)
         if (allocated(error)) return
         call read_element_start_v2(scanner, id, element_type, physical, error)
         if (allocated(error)) return
         if (physical == 0 .and. .not. is_mesh_cell(element_type)) cycle
         call gmsh_type_info(element_type, n_nodes, dim)
         group = 0
         if (physical /= 0) then
            if (dim < 0) then
               call scanner%fail(error, 'element '//to_string(id)//' of physical group '//to_string(physical)// &
                                 ' has type '//to_string(element_type)//', unknown to this reader')
               return
            end if
            call find_or_add_group(raw, dim, physical, group)
         end if
         call add_record(scanner, raw, id, element_type, n_nodes, [group], error)
         if (allocated(error)) return
      end do
      call expect_section_end(scanner, '$Elements', error)
   end subroutine read_elements_v2

   !> `id type ntags tags...` of a 2.2 element line; `physical` is the first tag (0 if none).
   subroutine read_element_start_v2(scanner, id, element_type, physical, error)
      type(text_scanner_t), intent(inout) :: scanner
      integer, intent(out) :: id, element_type, physical
      type(error_t), allocatable, intent(out) :: error
      integer :: n_tags, j, tag
      physical = 0
      call read_positive_id(scanner, 'element', id, error)
      if (allocated(error)) return
      call scanner%read_integer(element_type, error)
      if (allocated(error)) return
      call read_count(scanner, '$Elements', n_tags, error)
      if (allocated(error)) return
      do j = 1, n_tags
         if (j == 1) then
            call read_physical_tag(scanner, .true., physical, error)
         else
            call scanner%read_integer(tag, error)
         end if
         if (allocated(error)) return
      end do
   end subroutine read_element_start_v2

   !> 4.1 `$Elements`: `nblocks nelements mintag maxtag`; per block `dim entity type n`, then
   !> n lines `id nodes...`. The physical groups are those of the entity (from `$Entities`).
   subroutine read_elements_v4(scanner, raw, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(raw_mesh_t), intent(inout) :: raw
      type(error_t), allocatable, intent(out) :: error
      integer :: n_blocks, count, block, dim, tag, element_type, block_count, total, header_line
      integer, allocatable :: groups(:)
      call read_blocks_header(scanner, '$Elements', 'element', n_blocks, count, header_line, error)
      if (allocated(error)) return
      call reserve_records(raw, count)
      total = 0
      do block = 1, n_blocks
         call read_block_start(scanner, '$Elements', dim, tag, element_type, error)
         if (allocated(error)) return
         call read_block_count(scanner, '$Elements', 'element', count, total, header_line, block_count, error)
         if (allocated(error)) return
         total = total + block_count
         call entity_groups(scanner, raw, dim, tag, groups, error)
         if (allocated(error)) return
         call read_element_block(scanner, raw, dim, element_type, block_count, groups, error)
         if (allocated(error)) return
      end do
      call check_blocks_total(scanner, '$Elements', 'element', count, total, header_line, error)
      if (allocated(error)) return
      call expect_section_end(scanner, '$Elements', error)
   end subroutine read_elements_v4

   !> The group indices of the physical groups of entity (dim, tag) (none without `$Entities`).
   subroutine entity_groups(scanner, raw, dim, tag, groups, error)
      type(text_scanner_t), intent(in) :: scanner
      type(raw_mesh_t), intent(inout) :: raw
      integer, intent(in) :: dim, tag
      integer, allocatable, intent(out) :: groups(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: entity, first, last, j, physical
      if (raw%entities_line == 0) then
         allocate (groups(0))
         return
      end if
      entity = raw%entity_map(dim)%lookup(tag)
      if (entity == 0) then
         call scanner%fail(error, 'entity '//to_string(tag)//' of dimension '//to_string(dim)// &
                           ' is not defined in $Entities')
         return
      end if
      first = raw%entity_physical_first(dim)%items(entity)
      last = raw%entity_physical_first(dim)%items(entity + 1) - 1
      allocate (groups(last - first + 1))
      do j = first, last
         physical = raw%entity_physicals(dim)%items(j)
         call find_or_add_group(raw, dim, physical, groups(j - first + 1))
      end do
   end subroutine entity_groups

   !> The `block_count` element lines of a 4.1 block of dimension `dim`: kept if they are
   !> cells of a mesh (is_mesh_cell) or the block's entity has physical `groups`.
   subroutine read_element_block(scanner, raw, dim, element_type, block_count, groups, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(raw_mesh_t), intent(inout) :: raw
      integer, intent(in) :: dim, element_type, block_count
      integer, intent(in) :: groups(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: i, id, n_nodes, type_dim
      call gmsh_type_info(element_type, n_nodes, type_dim)
      if (type_dim >= 0 .and. type_dim /= dim) then
         call scanner%fail(error, 'element type '//to_string(element_type)//' has dimension '// &
                           to_string(type_dim)//', the block says '//to_string(dim))
         return
      end if
      do i = 1, block_count
         call next_data_line(scanner, '$Elements', error)
         if (allocated(error)) return
         if (size(groups) == 0 .and. .not. is_mesh_cell(element_type)) cycle
         call read_positive_id(scanner, 'element', id, error)
         if (allocated(error)) return
         call add_record(scanner, raw, id, element_type, n_nodes, groups, error)
         if (allocated(error)) return
      end do
   end subroutine read_element_block

   !> Index `g` of physical group (dim, tag) in the group table, added if new.
   subroutine find_or_add_group(raw, dim, tag, g)
      type(raw_mesh_t), intent(inout) :: raw
      integer, intent(in) :: dim, tag
      integer, intent(out) :: g
      do g = raw%group_dims%count, 1, -1
         if (raw%group_dims%items(g) == dim .and. raw%group_tags%items(g) == tag) return
      end do
      call push(raw%group_dims, dim)
      call push(raw%group_tags, tag)
      g = raw%group_dims%count
   end subroutine find_or_add_group

   !> Read the rest of an element line (its nodes: `n_nodes` of them, or all remaining
   !> tokens if the type is unknown) and keep it as a record with its groups.
   subroutine add_record(scanner, raw, id, element_type, n_nodes, groups, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(raw_mesh_t), intent(inout) :: raw
      integer, intent(in) :: id, element_type, n_nodes
      integer, intent(in) :: groups(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: k
      call read_record_nodes(scanner, raw, id, element_type, n_nodes, error)
      if (allocated(error)) return
      call push(raw%record_ids, id)
      call push(raw%record_types, element_type)
      call push(raw%record_lines, scanner%line_number)
      call push(raw%record_node_first, raw%record_nodes%count + 1)
      do k = 1, size(groups)
         if (groups(k) /= 0) call push(raw%record_groups, groups(k))
      end do
      call push(raw%record_group_first, raw%record_groups%count + 1)
   end subroutine add_record

   !> The node ids ending an element line, appended to `raw%record_nodes`.
   subroutine read_record_nodes(scanner, raw, id, element_type, n_nodes, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(raw_mesh_t), intent(inout) :: raw
      integer, intent(in) :: id, element_type, n_nodes
      type(error_t), allocatable, intent(out) :: error
      integer :: k, node
      if (n_nodes > 0) then
         do k = 1, n_nodes
            call scanner%read_integer(node, error)
            if (allocated(error)) then
               if (scanner%at_end_of_line()) error%message = error%message//' (element '//to_string(id)// &
                                                             ' of type '//to_string(element_type)//' needs '// &
                                                             to_string(n_nodes)//' nodes)'
               return
            end if
            call push(raw%record_nodes, node)
         end do
         call scanner%expect_end_of_line(error)
      else
         do while (.not. scanner%at_end_of_line())
            call scanner%read_integer(node, error)
            if (allocated(error)) return
            call push(raw%record_nodes, node)
         end do
      end if
   end subroutine read_record_nodes

   !> Whether an element of type `element_type` is kept without a physical group: a cell of
   !> a volume or of a plane mesh (gmsh writes every element when there is no physical group).
   pure logical function is_mesh_cell(element_type)
      integer, intent(in) :: element_type
      is_mesh_cell = is_element_cell(element_type, 3) .or. is_element_cell(element_type, 2)
   end function is_mesh_cell

   subroutine reserve_records(raw, count)
      type(raw_mesh_t), intent(inout) :: raw
      integer, intent(in) :: count
      call reserve(raw%record_ids, count)
      call reserve(raw%record_types, count)
      call reserve(raw%record_lines, count)
      call reserve(raw%record_node_first, count + 1)
      call reserve(raw%record_group_first, count + 1)
      call reserve(raw%record_nodes, 8*count)
   end subroutine reserve_records

   !> Number of nodes and dimension of a gmsh element type (gmsh manual, "MSH file format",
   !> element types); n_nodes = 0 and dim = -1 for a type not listed.
   pure subroutine gmsh_type_info(element_type, n_nodes, dim)
      integer, intent(in) :: element_type
      integer, intent(out) :: n_nodes, dim
      integer, parameter :: nodes_of_type(31) = [2, 3, 4, 4, 8, 6, 5, 3, 6, 9, 10, 27, 18, 14, 1, 8, 20, 15, 13, &
                                                 9, 10, 12, 15, 15, 21, 4, 5, 6, 20, 35, 56]
      integer, parameter :: dim_of_type(31) = [1, 2, 2, 3, 3, 3, 3, 1, 2, 2, 3, 3, 3, 3, 0, 2, 3, 3, 3, &
                                               2, 2, 2, 2, 2, 2, 1, 1, 1, 3, 3, 3]
      select case (element_type)
      case (1:31)
         n_nodes = nodes_of_type(element_type)
         dim = dim_of_type(element_type)
      case (92)
         n_nodes = 64
         dim = 3
      case (93)
         n_nodes = 125
         dim = 3
      case default
         n_nodes = 0
         dim = -1
      end select
   end subroutine gmsh_type_info
end module frix_gmsh_elements
