!> Reader of gmsh ASCII meshes, formats 2.2 and 4.1 (gmsh reference manual, "MSH file
!> format"; the version is taken from `$MeshFormat`).
!>
!> What becomes of the file's content:
!> - every node, in file order (user ids kept in `node_ids`);
!> - every 8-node hexahedron (gmsh type 5, whose node order is VTK's and frix_mesh's), in file
!>   order (gmsh ids kept in `element_ids`; `element_block` is left 0 for the caller);
!> - every physical group, named from `$PhysicalNames` or, if unnamed, "<dim>:<tag>":
!>   a physical volume gives an element set (its hexahedra) and a node set; a physical surface
!>   gives a surface (each 4-node quadrilateral matched to the hexahedron face with the same
!>   four nodes) and a node set; a physical curve or point gives a node set.
!>   Sets are in ascending (dim, tag) order; their contents are sorted and unique. Two
!>   groups with the same name (even of different dimensions) are an error, since each gives
!>   a node set. A quadrilateral on a face shared by two hexahedra is an error too (a
!>   surface for loads or contact must lie on the boundary).
!>   Without any physical group (gmsh then writes every element) there are no sets.
!> - other elements in no physical group (lines, points, ... that gmsh writes) are skipped.
!> Hexahedra are taken as they are: an inverted one (negative Jacobian, e.g. from a mirrored
!> geometry) is reported by `check_hex8_jacobians`, never silently renumbered here.
!>
!> Rejected: a second $MeshFormat, $PhysicalNames, $Entities, $Nodes or $Elements section;
!> a 4.1 $Entities after $Elements; a physical tag that is not positive (0 is allowed only as
!> a 2.2 element's "no physical group"); a dimension outside 0..3; a (dim, tag) named twice in
!> $PhysicalNames; negative counts, counts beyond the lines left in the file, blocks holding
!> more than their section declares; a section without its $End line; missing, extra or
!> malformed numbers on a line; coordinates that are not finite numbers (NaN, Inf, 1e400);
!> duplicate node ids; elements referencing undefined nodes.
!> Every error names the file, and the line where there is one:
!> `mesh.msh:17: expected a number, got "abc"`.
module frix_gmsh_reader
   use frix_kinds, only: dp, i8
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_text_scanner, only: text_scanner_t, open_text_file
   use frix_id_map, only: id_map_t
   use frix_mesh, only: mesh_t, hex8_face_nodes
   use frix_mesh_checks, only: node_to_elements
   implicit none
   private

   public :: read_gmsh

   integer, parameter :: gmsh_quadrangle = 3, gmsh_hexahedron = 5

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
      integer, allocatable :: node_ids(:), node_lines(:)
      real(dp), allocatable :: coords(:, :)
      ! element records kept: hexahedra, and elements of physical groups
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

   !> Read the gmsh ASCII mesh at `path` (format 2.2 or 4.1) into `mesh`.
   subroutine read_gmsh(path, mesh, error)
      character(len=*), intent(in) :: path
      type(mesh_t), intent(out) :: mesh
      type(error_t), allocatable, intent(out) :: error
      type(text_scanner_t) :: scanner
      type(raw_mesh_t) :: raw
      character(len=:), allocatable :: section
      logical :: found

      call open_text_file(path, scanner, error)
      if (allocated(error)) return
      call push(raw%record_node_first, 1)
      call push(raw%record_group_first, 1)
      call read_mesh_format(scanner, raw, error)
      if (allocated(error)) return
      do while (scanner%next_line())
         if (scanner%is_blank_line()) cycle
         call scanner%next_token(section, found)
         call read_section(scanner, section, raw, error)
         if (allocated(error)) return
      end do
      if (raw%nodes_line == 0) then
         call fatal_error(error, path//': no $Nodes section')
         return
      end if
      if (raw%elements_line == 0) then
         call fatal_error(error, path//': no $Elements section')
         return
      end if
      call build_mesh(scanner%file_name, raw, mesh, error)
   end subroutine read_gmsh

   ! ---- sections ---------------------------------------------------------------------------

   !> Read the section whose first line (the current one) starts with the token `section`.
   !> $MeshFormat, $PhysicalNames, $Entities, $Nodes and $Elements may appear once each;
   !> the sections this reader does not use are skipped.
   subroutine read_section(scanner, section, raw, error)
      type(text_scanner_t), intent(inout) :: scanner
      character(len=*), intent(in) :: section
      type(raw_mesh_t), intent(inout) :: raw
      type(error_t), allocatable, intent(out) :: error
      select case (section)
      case ('$MeshFormat')
         call claim_section(scanner, section, raw%mesh_format_line, error)
      case ('$PhysicalNames')
         call claim_section(scanner, section, raw%physical_names_line, error)
         if (.not. allocated(error)) call read_physical_names(scanner, raw, error)
      case ('$Entities')
         if (raw%version == 4) then
            call read_entities_section(scanner, raw, error)
         else
            call skip_section(scanner, section, error)
         end if
      case ('$Nodes')
         call claim_section(scanner, section, raw%nodes_line, error)
         if (allocated(error)) return
         if (raw%version == 2) then
            call read_nodes_v2(scanner, raw, error)
         else
            call read_nodes_v4(scanner, raw, error)
         end if
      case ('$Elements')
         call claim_section(scanner, section, raw%elements_line, error)
         if (allocated(error)) return
         if (raw%version == 2) then
            call read_elements_v2(scanner, raw, error)
         else
            call read_elements_v4(scanner, raw, error)
         end if
      case default
         if (index(section, '$End') == 1) then
            call scanner%fail(error, '"'//shorten(section)//'" outside its section (more entries than declared?)')
         else if (section(1:1) == '$') then
            call skip_section(scanner, section, error)
         else
            call scanner%fail(error, 'expected a section such as $Nodes, got "'//shorten(section)//'"')
         end if
      end select
   end subroutine read_section

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

   !> 4.1 `$Entities`, once, and before `$Elements`: the physical groups of an element are
   !> those of its entity, looked up when the element block is read.
   subroutine read_entities_section(scanner, raw, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(raw_mesh_t), intent(inout) :: raw
      type(error_t), allocatable, intent(out) :: error
      call claim_section(scanner, '$Entities', raw%entities_line, error)
      if (allocated(error)) return
      if (raw%elements_line /= 0) then
         call scanner%fail(error, '$Entities after $Elements (line '//to_string(raw%elements_line)// &
                           '): the physical groups of the elements come from $Entities, which must come first')
         return
      end if
      call read_entities(scanner, raw, error)
   end subroutine read_entities_section

   !> First section: `$MeshFormat`, version file-type data-size, `$EndMeshFormat`.
   subroutine read_mesh_format(scanner, raw, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(raw_mesh_t), intent(inout) :: raw
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: token
      integer :: file_type
      logical :: found
      do
         if (.not. scanner%next_line()) then
            call fatal_error(error, scanner%file_name//': empty file, expected $MeshFormat')
            return
         end if
         if (.not. scanner%is_blank_line()) exit
      end do
      call scanner%next_token(token, found)
      if (token /= '$MeshFormat') then
         call scanner%fail(error, 'expected $MeshFormat, got "'//shorten(token)// &
                           '" (not a gmsh ASCII mesh file)')
         return
      end if
      raw%mesh_format_line = scanner%line_number
      call next_data_line(scanner, '$MeshFormat', error)
      if (allocated(error)) return
      call scanner%next_token(token, found)
      select case (token)
      case ('2.2')
         raw%version = 2
      case ('4.1')
         raw%version = 4
      case default
         call scanner%fail(error, 'unknown msh format version "'//shorten(token)//'" (supported: 2.2, 4.1)')
         return
      end select
      call scanner%read_integer(file_type, error)
      if (allocated(error)) return
      if (file_type /= 0) then
         call scanner%fail(error, 'binary msh files are not supported (file-type "'//to_string(file_type)// &
                           '"); write ASCII: gmsh -format msh41 without -bin')
         return
      end if
      call expect_section_end(scanner, '$MeshFormat', error)
   end subroutine read_mesh_format

   !> `$PhysicalNames`: count, then lines `dim tag "name"`; one name per (dim, tag).
   subroutine read_physical_names(scanner, raw, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(raw_mesh_t), intent(inout) :: raw
      type(error_t), allocatable, intent(out) :: error
      integer :: count, i, k, dim, tag
      character(len=:), allocatable :: name
      call read_count_line(scanner, '$PhysicalNames', count, error)
      if (allocated(error)) return
      allocate (raw%names(count))
      do i = 1, count
         call next_data_line(scanner, '$PhysicalNames', error)
         if (allocated(error)) return
         call read_dimension(scanner, dim, error)
         if (allocated(error)) return
         call read_physical_tag(scanner, .false., tag, error)
         if (allocated(error)) return
         call scanner%read_string(name, error)
         if (allocated(error)) return
         call scanner%expect_end_of_line(error)
         if (allocated(error)) return
         do k = 1, raw%name_dims%count
            if (raw%name_dims%items(k) == dim .and. raw%name_tags%items(k) == tag) then
               call scanner%fail(error, 'physical group '//to_string(dim)//':'//to_string(tag)// &
                                 ' is named twice (first on line '//to_string(raw%name_lines%items(k))//')')
               return
            end if
         end do
         call push(raw%name_dims, dim)
         call push(raw%name_tags, tag)
         call push(raw%name_lines, scanner%line_number)
         raw%names(i)%text = name
      end do
      call expect_section_end(scanner, '$PhysicalNames', error)
   end subroutine read_physical_names

   !> 4.1 `$Entities`: numbers of points, curves, surfaces, volumes; then one line per entity:
   !> a point `tag x y z nphys phys...`, others `tag minx miny minz maxx maxy maxz nphys
   !> phys... nbounding bounding...`. Only the physical tags are kept.
   subroutine read_entities(scanner, raw, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(raw_mesh_t), intent(inout) :: raw
      type(error_t), allocatable, intent(out) :: error
      integer :: counts(0:3), dim, i, j, tag, n_physical, physical, skipped, existing
      do dim = 0, 3
         call push(raw%entity_physical_first(dim), 1)
      end do
      call next_data_line(scanner, '$Entities', error)
      if (allocated(error)) return
      do dim = 0, 3
         call read_count(scanner, '$Entities', counts(dim), error)
         if (allocated(error)) return
      end do
      call scanner%expect_end_of_line(error)
      if (allocated(error)) return
      if (sum(int(counts, i8)) > scanner%remaining_lines()) then
         call scanner%fail(error, '$Entities declares '//to_string(sum(int(counts, i8)))//' entities but only '// &
                           to_string(scanner%remaining_lines())//' lines follow (truncated file or bad count)')
         return
      end if
      do dim = 0, 3
         call raw%entity_map(dim)%clear(counts(dim))
         do i = 1, counts(dim)
            call next_data_line(scanner, '$Entities', error)
            if (allocated(error)) return
            call scanner%read_integer(tag, error)
            if (allocated(error)) return
            call scanner%skip_tokens(merge(3, 6, dim == 0), skipped)
            call scanner%read_integer(n_physical, error)
            if (allocated(error)) return
            if (n_physical < 0) then
               call scanner%fail(error, 'bad counts: negative number of physical tags')
               return
            end if
            do j = 1, n_physical
               call read_physical_tag(scanner, .false., physical, error)
               if (allocated(error)) return
               call push(raw%entity_physicals(dim), physical)
            end do
            call push(raw%entity_physical_first(dim), raw%entity_physicals(dim)%count + 1)
            call raw%entity_map(dim)%insert(tag, i, existing)
            if (existing /= 0) then
               call scanner%fail(error, 'entity '//to_string(tag)//' of dimension '//to_string(dim)// &
                                 ' is defined twice')
               return
            end if
         end do
      end do
      call expect_section_end(scanner, '$Entities', error)
   end subroutine read_entities

   !> 2.2 `$Nodes`: count, then lines `id x y z`.
   subroutine read_nodes_v2(scanner, raw, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(raw_mesh_t), intent(inout) :: raw
      type(error_t), allocatable, intent(out) :: error
      integer :: count, i
      call read_count_line(scanner, '$Nodes', count, error)
      if (allocated(error)) return
      call allocate_nodes(raw, count)
      do i = 1, count
         call next_data_line(scanner, '$Nodes', error)
         if (allocated(error)) return
         call read_positive_id(scanner, 'node', raw%node_ids(i), error)
         if (allocated(error)) return
         raw%node_lines(i) = scanner%line_number
         call read_coordinates(scanner, raw%coords(:, i), 0, error)
         if (allocated(error)) return
      end do
      raw%n_nodes = count
      call expect_section_end(scanner, '$Nodes', error)
   end subroutine read_nodes_v2

   !> 4.1 `$Nodes`: `nblocks nnodes mintag maxtag`; per block `dim tag parametric n`, then
   !> n lines of node tags and n lines `x y z`, followed by `dim` parametric coordinates
   !> (u; u v; u v w) if `parametric` is 1.
   subroutine read_nodes_v4(scanner, raw, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(raw_mesh_t), intent(inout) :: raw
      type(error_t), allocatable, intent(out) :: error
      integer :: n_blocks, count, block, dim, tag, parametric, block_count, i, header_line
      call next_data_line(scanner, '$Nodes', error)
      if (allocated(error)) return
      header_line = scanner%line_number
      call read_count(scanner, '$Nodes', n_blocks, error)
      if (allocated(error)) return
      call read_count(scanner, '$Nodes', count, error)
      if (allocated(error)) return
      if (count > scanner%remaining_lines()) then
         call scanner%fail(error, '$Nodes declares '//to_string(count)//' nodes but only '// &
                           to_string(scanner%remaining_lines())//' lines follow (truncated file or bad count)')
         return
      end if
      call allocate_nodes(raw, count)
      do block = 1, n_blocks
         call next_data_line(scanner, '$Nodes', error)
         if (allocated(error)) return
         call read_dimension(scanner, dim, error)
         if (allocated(error)) return
         call scanner%read_integer(tag, error)
         if (allocated(error)) return
         call scanner%read_integer(parametric, error)
         if (allocated(error)) return
         if (parametric /= 0 .and. parametric /= 1) then
            call scanner%fail(error, 'expected parametric 0 or 1, got "'//to_string(parametric)//'"')
            return
         end if
         call read_count(scanner, '$Nodes', block_count, error)
         if (allocated(error)) return
         if (block_count > count - raw%n_nodes) then
            call scanner%fail(error, 'bad counts: the node blocks hold more than the '//to_string(count)// &
                              ' nodes declared on line '//to_string(header_line))
            return
         end if
         do i = raw%n_nodes + 1, raw%n_nodes + block_count
            call next_data_line(scanner, '$Nodes', error)
            if (allocated(error)) return
            call read_positive_id(scanner, 'node', raw%node_ids(i), error)
            if (allocated(error)) return
            raw%node_lines(i) = scanner%line_number
            call scanner%expect_end_of_line(error)
            if (allocated(error)) return
         end do
         do i = raw%n_nodes + 1, raw%n_nodes + block_count
            call next_data_line(scanner, '$Nodes', error)
            if (allocated(error)) return
            call read_coordinates(scanner, raw%coords(:, i), parametric*dim, error)
            if (allocated(error)) return
         end do
         raw%n_nodes = raw%n_nodes + block_count
      end do
      if (raw%n_nodes /= count) then
         call fatal_error(error, scanner%file_name//':'//to_string(header_line)//': bad counts: $Nodes declares '// &
                          to_string(count)//' nodes, its blocks hold '//to_string(raw%n_nodes))
         return
      end if
      call expect_section_end(scanner, '$Nodes', error)
   end subroutine read_nodes_v4

   !> 2.2 `$Elements`: count, then lines `id type ntags tags... nodes...`; the first tag is
   !> the physical group (0: none).
   subroutine read_elements_v2(scanner, raw, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(raw_mesh_t), intent(inout) :: raw
      type(error_t), allocatable, intent(out) :: error
      integer :: count, i, id, element_type, n_tags, physical, tag, j, n_nodes, dim, group
      call read_count_line(scanner, '$Elements', count, error)
      if (allocated(error)) return
      call reserve_records(raw, count)
      do i = 1, count
         call next_data_line(scanner, '$Elements', error)
         if (allocated(error)) return
         call read_positive_id(scanner, 'element', id, error)
         if (allocated(error)) return
         call scanner%read_integer(element_type, error)
         if (allocated(error)) return
         call read_count(scanner, '$Elements', n_tags, error)
         if (allocated(error)) return
         physical = 0
         do j = 1, n_tags
            if (j == 1) then
               call read_physical_tag(scanner, .true., physical, error)
            else
               call scanner%read_integer(tag, error)
            end if
            if (allocated(error)) return
         end do
         if (physical == 0 .and. element_type /= gmsh_hexahedron) cycle
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

   !> 4.1 `$Elements`: `nblocks nelements mintag maxtag`; per block `dim entity type n`, then
   !> n lines `id nodes...`. The physical groups are those of the entity (from `$Entities`).
   subroutine read_elements_v4(scanner, raw, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(raw_mesh_t), intent(inout) :: raw
      type(error_t), allocatable, intent(out) :: error
      integer :: n_blocks, count, block, dim, tag, element_type, block_count, i, id, n_nodes, type_dim
      integer :: entity, j, total, header_line, first, last, physical
      integer, allocatable :: groups(:)
      call next_data_line(scanner, '$Elements', error)
      if (allocated(error)) return
      header_line = scanner%line_number
      call read_count(scanner, '$Elements', n_blocks, error)
      if (allocated(error)) return
      call read_count(scanner, '$Elements', count, error)
      if (allocated(error)) return
      if (count > scanner%remaining_lines()) then
         call scanner%fail(error, '$Elements declares '//to_string(count)//' elements but only '// &
                           to_string(scanner%remaining_lines())//' lines follow (truncated file or bad count)')
         return
      end if
      call reserve_records(raw, count)
      total = 0
      do block = 1, n_blocks
         call next_data_line(scanner, '$Elements', error)
         if (allocated(error)) return
         call read_dimension(scanner, dim, error)
         if (allocated(error)) return
         call scanner%read_integer(tag, error)
         if (allocated(error)) return
         call scanner%read_integer(element_type, error)
         if (allocated(error)) return
         call read_count(scanner, '$Elements', block_count, error)
         if (allocated(error)) return
         if (block_count > count - total) then
            call scanner%fail(error, 'bad counts: the element blocks hold more than the '//to_string(count)// &
                              ' elements declared on line '//to_string(header_line))
            return
         end if
         total = total + block_count
         ! physical groups of the entity
         allocate (groups(0))
         if (raw%entities_line /= 0) then
            entity = raw%entity_map(dim)%lookup(tag)
            if (entity == 0) then
               call scanner%fail(error, 'entity '//to_string(tag)//' of dimension '//to_string(dim)// &
                                 ' is not defined in $Entities')
               return
            end if
            first = raw%entity_physical_first(dim)%items(entity)
            last = raw%entity_physical_first(dim)%items(entity + 1) - 1
            deallocate (groups)
            allocate (groups(last - first + 1))
            do j = first, last
               physical = raw%entity_physicals(dim)%items(j)
               call find_or_add_group(raw, dim, physical, groups(j - first + 1))
            end do
         end if
         call gmsh_type_info(element_type, n_nodes, type_dim)
         if (type_dim >= 0 .and. type_dim /= dim) then
            call scanner%fail(error, 'element type '//to_string(element_type)//' has dimension '// &
                              to_string(type_dim)//', the block says '//to_string(dim))
            return
         end if
         do i = 1, block_count
            call next_data_line(scanner, '$Elements', error)
            if (allocated(error)) return
            if (size(groups) == 0 .and. element_type /= gmsh_hexahedron) cycle
            call read_positive_id(scanner, 'element', id, error)
            if (allocated(error)) return
            call add_record(scanner, raw, id, element_type, n_nodes, groups, error)
            if (allocated(error)) return
         end do
         deallocate (groups)
      end do
      if (total /= count) then
         call fatal_error(error, scanner%file_name//':'//to_string(header_line)//': bad counts: $Elements declares '// &
                          to_string(count)//' elements, its blocks hold '//to_string(total))
         return
      end if
      call expect_section_end(scanner, '$Elements', error)
   end subroutine read_elements_v4

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
      call scanner%fail(error, 'truncated file: end of file inside section '//section// &
                        ' (no $End'//section(2:)//')')
   end subroutine skip_section

   ! ---- assembling the mesh ----------------------------------------------------------------

   !> Turn the raw content into `mesh`: node numbering, hexahedra, sets and surfaces.
   subroutine build_mesh(file_name, raw, mesh, error)
      character(len=*), intent(in) :: file_name
      type(raw_mesh_t), intent(inout) :: raw
      type(mesh_t), intent(out) :: mesh
      type(error_t), allocatable, intent(out) :: error
      type(id_map_t) :: node_map, element_map
      integer, allocatable :: record_element(:), group_offsets(:), group_records(:), order(:)
      integer :: n_records, duplicate, r, n_hexahedra, element, existing, a, group, n_groups, dim, k
      integer, allocatable :: nodes(:)

      ! nodes
      call node_map%build(raw%node_ids(1:raw%n_nodes), duplicate)
      if (duplicate /= 0) then
         call fatal_error(error, file_name//':'//to_string(raw%node_lines(duplicate))//': duplicate node id '// &
                          to_string(raw%node_ids(duplicate))//' (first defined on line '// &
                          to_string(raw%node_lines(node_map%lookup(raw%node_ids(duplicate))))//')')
         return
      end if
      mesh%n_nodes = raw%n_nodes
      mesh%node_ids = raw%node_ids(1:raw%n_nodes)
      mesh%coords = raw%coords(:, 1:raw%n_nodes)

      ! hexahedra, in file order; records with the same id must have the same nodes
      n_records = raw%record_ids%count
      n_hexahedra = count(raw%record_types%items(1:n_records) == gmsh_hexahedron)
      allocate (mesh%connectivity(8, n_hexahedra), mesh%element_ids(n_hexahedra), record_element(n_records))
      record_element = 0
      call element_map%clear(n_hexahedra)
      element = 0
      do r = 1, n_records
         if (raw%record_types%items(r) /= gmsh_hexahedron) cycle
         call record_nodes(file_name, raw, r, node_map, nodes, error)
         if (allocated(error)) return
         call element_map%insert(raw%record_ids%items(r), element + 1, existing)
         if (existing /= 0) then
            if (any(mesh%connectivity(:, existing) /= nodes)) then
               call fail_at_record(file_name, raw, r, error, 'duplicate element id '// &
                                   to_string(raw%record_ids%items(r))//' with different nodes')
               return
            end if
            record_element(r) = existing
         else
            element = element + 1
            mesh%connectivity(:, element) = nodes
            mesh%element_ids(element) = raw%record_ids%items(r)
            record_element(r) = element
         end if
      end do
      mesh%n_elements = element
      mesh%connectivity = mesh%connectivity(:, 1:element)
      mesh%element_ids = mesh%element_ids(1:element)
      call merge_copies(mesh, record_element)
      allocate (mesh%element_block(mesh%n_elements), source=0)

      ! records of each group, compressed: group g holds group_records(group_offsets(g):group_offsets(g+1)-1)
      n_groups = raw%group_dims%count
      allocate (group_offsets(n_groups + 1))
      group_offsets = 0
      do a = 1, raw%record_groups%count
         group = raw%record_groups%items(a)
         group_offsets(group + 1) = group_offsets(group + 1) + 1
      end do
      group_offsets(1) = 1
      do a = 1, n_groups
         group_offsets(a + 1) = group_offsets(a + 1) + group_offsets(a)
      end do
      allocate (group_records(group_offsets(n_groups + 1) - 1))
      block
         integer, allocatable :: next(:)
         integer :: g
         next = group_offsets(1:n_groups)
         do r = 1, n_records
            do k = raw%record_group_first%items(r), raw%record_group_first%items(r + 1) - 1
               g = raw%record_groups%items(k)
               group_records(next(g)) = r
               next(g) = next(g) + 1
            end do
         end do
      end block

      ! element types: volumes first, since a wrong volume type (2nd order, tetrahedra)
      ! is the cause of a wrong surface type
      do dim = 3, 2, -1
         do r = 1, n_records
            do k = raw%record_group_first%items(r), raw%record_group_first%items(r + 1) - 1
               if (raw%group_dims%items(raw%record_groups%items(k)) /= dim) cycle
               associate (element_type => raw%record_types%items(r), id => raw%record_ids%items(r))
                  if (dim == 3 .and. element_type /= gmsh_hexahedron) then
                     call fail_at_record(file_name, raw, r, error, 'only 8-node hexahedra are supported: element '// &
                                         to_string(id)//' has type '//to_string(element_type))
                     return
                  end if
                  if (dim == 2 .and. element_type /= gmsh_quadrangle) then
                     call fail_at_record(file_name, raw, r, error, 'only 4-node quadrilaterals are supported on '// &
                                         'surfaces: element '//to_string(id)//' has type '//to_string(element_type))
                     return
                  end if
               end associate
            end do
         end do
      end do

      ! groups in ascending (dim, tag) order
      order = sorted_group_order(raw)
      call build_sets(file_name, raw, order, group_offsets, group_records, record_element, node_map, mesh, error)
   end subroutine build_mesh

   !> Format 2.2 writes a hexahedron once per physical volume holding it, each copy with an id
   !> of its own (gmsh 4.8): keep the first of hexahedra with identical node lists, and point
   !> the records of the others to it. Found through the elements around each first node.
   subroutine merge_copies(mesh, record_element)
      type(mesh_t), intent(inout) :: mesh
      integer, intent(inout) :: record_element(:)
      integer, allocatable :: offsets(:), adjacency(:), new_number(:)
      integer :: element, k, other, n_kept
      call node_to_elements(mesh, offsets, adjacency)
      allocate (new_number(mesh%n_elements))
      n_kept = 0
      do element = 1, mesh%n_elements
         new_number(element) = 0
         do k = offsets(mesh%connectivity(1, element)), offsets(mesh%connectivity(1, element) + 1) - 1
            other = adjacency(k)
            if (other >= element) exit
            if (all(mesh%connectivity(:, other) == mesh%connectivity(:, element))) then
               new_number(element) = new_number(other)
               exit
            end if
         end do
         if (new_number(element) == 0) then
            n_kept = n_kept + 1
            new_number(element) = n_kept
         end if
      end do
      if (n_kept == mesh%n_elements) return
      ! compact (new_number(e) <= e, and kept elements keep their order)
      n_kept = 0
      do element = 1, mesh%n_elements
         if (new_number(element) /= n_kept + 1) cycle   ! a copy of an earlier element
         n_kept = n_kept + 1
         mesh%connectivity(:, n_kept) = mesh%connectivity(:, element)
         mesh%element_ids(n_kept) = mesh%element_ids(element)
      end do
      where (record_element > 0) record_element = new_number(max(record_element, 1))
      mesh%n_elements = n_kept
      mesh%connectivity = mesh%connectivity(:, 1:n_kept)
      mesh%element_ids = mesh%element_ids(1:n_kept)
   end subroutine merge_copies

   !> Node sets, element sets and surfaces of the physical groups, in the given order (element
   !> types already checked: hexahedra in volumes, 4-node quadrilaterals in surfaces).
   subroutine build_sets(file_name, raw, order, group_offsets, group_records, record_element, node_map, mesh, error)
      character(len=*), intent(in) :: file_name
      type(raw_mesh_t), intent(in) :: raw
      integer, intent(in) :: order(:), group_offsets(:), group_records(:), record_element(:)
      type(id_map_t), intent(in) :: node_map
      type(mesh_t), intent(inout) :: mesh
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: node_stamp(:), element_stamp(:), face_stamp(:), nodes(:)
      integer, allocatable :: adjacency_offsets(:), adjacency(:)
      integer :: n_volumes, n_surfaces, i, g, k, r, dim, element, face, n_sets_volume, n_sets_surface, j
      character(len=:), allocatable :: name

      if (size(order) == 0) then
         allocate (mesh%node_sets(0), mesh%element_sets(0), mesh%surfaces(0))
         return
      end if
      n_volumes = count(raw%group_dims%items(order) == 3)
      n_surfaces = count(raw%group_dims%items(order) == 2)
      allocate (mesh%node_sets(size(order)), mesh%element_sets(n_volumes), mesh%surfaces(n_surfaces))
      allocate (node_stamp(mesh%n_nodes), element_stamp(mesh%n_elements), face_stamp(6*mesh%n_elements))
      node_stamp = 0
      element_stamp = 0
      face_stamp = 0
      if (n_surfaces > 0) call node_to_elements(mesh, adjacency_offsets, adjacency)
      n_sets_volume = 0
      n_sets_surface = 0
      do i = 1, size(order)
         g = order(i)
         dim = raw%group_dims%items(g)
         name = group_name(raw, g)
         do j = 1, i - 1
            if (mesh%node_sets(j)%name == name) then
               call fatal_error(error, file_name//': physical groups '//to_string(raw%group_dims%items(order(j)))// &
                                ':'//to_string(raw%group_tags%items(order(j)))//' and '//to_string(dim)//':'// &
                                to_string(raw%group_tags%items(g))//' have the same name "'//name//'"')
               return
            end if
         end do
         do k = group_offsets(g), group_offsets(g + 1) - 1
            r = group_records(k)
            call record_nodes(file_name, raw, r, node_map, nodes, error)
            if (allocated(error)) return
            node_stamp(nodes) = i
            if (dim == 3) element_stamp(record_element(r)) = i
            if (dim == 2) then
               call match_face(mesh, adjacency_offsets, adjacency, nodes, element, face, j)
               if (j == 0) then
                  call fail_at_record(file_name, raw, r, error, 'quadrilateral '//to_string(raw%record_ids%items(r))// &
                                      ' matches no face of a hexahedron')
                  return
               else if (j > 1) then
                  call fail_at_record(file_name, raw, r, error, 'quadrilateral '//to_string(raw%record_ids%items(r))// &
                                      ' lies on a face shared by two hexahedra (an interior face)')
                  return
               end if
               face_stamp(6*(element - 1) + face) = i
            end if
         end do
         mesh%node_sets(i)%name = name
         mesh%node_sets(i)%nodes = pack([(k, k=1, mesh%n_nodes)], node_stamp == i)
         if (dim == 3) then
            n_sets_volume = n_sets_volume + 1
            mesh%element_sets(n_sets_volume)%name = name
            mesh%element_sets(n_sets_volume)%elements = pack([(k, k=1, mesh%n_elements)], element_stamp == i)
         else if (dim == 2) then
            n_sets_surface = n_sets_surface + 1
            mesh%surfaces(n_sets_surface)%name = name
            nodes = pack([(k, k=1, 6*mesh%n_elements)], face_stamp == i)
            mesh%surfaces(n_sets_surface)%elements = (nodes - 1)/6 + 1
            mesh%surfaces(n_sets_surface)%faces = modulo(nodes - 1, 6) + 1
         end if
      end do
   end subroutine build_sets

   !> The hexahedron faces with the nodes of `quad` (any order): `n_matches` of them, the
   !> last one found is (element, face).
   subroutine match_face(mesh, offsets, adjacency, quad, element, face, n_matches)
      type(mesh_t), intent(in) :: mesh
      integer, intent(in) :: offsets(:), adjacency(:), quad(:)
      integer, intent(out) :: element, face, n_matches
      integer :: key(4), candidate(4), k, f, e
      key = sorted4(quad)
      element = 0
      face = 0
      n_matches = 0
      do k = offsets(quad(1)), offsets(quad(1) + 1) - 1
         e = adjacency(k)
         do f = 1, 6
            candidate = sorted4(mesh%connectivity(hex8_face_nodes(:, f), e))
            if (all(candidate == key)) then
               n_matches = n_matches + 1
               element = e
               face = f
            end if
         end do
      end do
   end subroutine match_face

   pure function sorted4(values) result(sorted)
      integer, intent(in) :: values(4)
      integer :: sorted(4)
      sorted = values
      call order_pair(sorted(1), sorted(2))
      call order_pair(sorted(3), sorted(4))
      call order_pair(sorted(1), sorted(3))
      call order_pair(sorted(2), sorted(4))
      call order_pair(sorted(2), sorted(3))
   contains
      pure subroutine order_pair(low, high)
         integer, intent(inout) :: low, high
         integer :: swap
         if (low > high) then
            swap = low
            low = high
            high = swap
         end if
      end subroutine order_pair
   end function sorted4

   !> Internal node numbers of record r; error naming the record's line if one is undefined.
   subroutine record_nodes(file_name, raw, r, node_map, nodes, error)
      character(len=*), intent(in) :: file_name
      type(raw_mesh_t), intent(in) :: raw
      integer, intent(in) :: r
      type(id_map_t), intent(in) :: node_map
      integer, allocatable, intent(inout) :: nodes(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: first, last, k
      first = raw%record_node_first%items(r)
      last = raw%record_node_first%items(r + 1) - 1
      if (allocated(nodes)) then
         if (size(nodes) /= last - first + 1) deallocate (nodes)
      end if
      if (.not. allocated(nodes)) allocate (nodes(last - first + 1))
      do k = first, last
         nodes(k - first + 1) = node_map%lookup(raw%record_nodes%items(k))
         if (nodes(k - first + 1) == 0) then
            call fail_at_record(file_name, raw, r, error, 'element '//to_string(raw%record_ids%items(r))// &
                                ' references node '//to_string(raw%record_nodes%items(k))//', which is not defined')
            return
         end if
      end do
   end subroutine record_nodes

   subroutine fail_at_record(file_name, raw, r, error, message)
      character(len=*), intent(in) :: file_name
      type(raw_mesh_t), intent(in) :: raw
      integer, intent(in) :: r
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: message
      call fatal_error(error, file_name//':'//to_string(raw%record_lines%items(r))//': '//message)
   end subroutine fail_at_record

   !> Group indices sorted by (dim, tag) (insertion sort: a mesh has few physical groups).
   function sorted_group_order(raw) result(order)
      type(raw_mesh_t), intent(in) :: raw
      integer, allocatable :: order(:)
      integer :: n, i, j, current
      n = raw%group_dims%count
      order = [(i, i=1, n)]
      do i = 2, n
         current = order(i)
         j = i - 1
         do while (j >= 1)
            if (.not. comes_after(order(j), current)) exit
            order(j + 1) = order(j)
            j = j - 1
         end do
         order(j + 1) = current
      end do
   contains
      logical function comes_after(first, second)
         integer, intent(in) :: first, second
         associate (dims => raw%group_dims%items, tags => raw%group_tags%items)
            comes_after = dims(first) > dims(second) .or. (dims(first) == dims(second) .and. tags(first) > tags(second))
         end associate
      end function comes_after
   end function sorted_group_order

   !> Name of group g: from $PhysicalNames, else "<dim>:<tag>".
   function group_name(raw, g) result(name)
      type(raw_mesh_t), intent(in) :: raw
      integer, intent(in) :: g
      character(len=:), allocatable :: name
      integer :: k
      do k = 1, raw%name_dims%count
         if (raw%name_dims%items(k) == raw%group_dims%items(g) .and. raw%name_tags%items(k) == raw%group_tags%items(g)) then
            name = raw%names(k)%text
            return
         end if
      end do
      name = to_string(raw%group_dims%items(g))//':'//to_string(raw%group_tags%items(g))
   end function group_name

   ! ---- small parsing helpers --------------------------------------------------------------

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
         if (allocated(error)) return
      else
         do while (.not. scanner%at_end_of_line())
            call scanner%read_integer(node, error)
            if (allocated(error)) return
            call push(raw%record_nodes, node)
         end do
      end if
      call push(raw%record_ids, id)
      call push(raw%record_types, element_type)
      call push(raw%record_lines, scanner%line_number)
      call push(raw%record_node_first, raw%record_nodes%count + 1)
      do k = 1, size(groups)
         if (groups(k) /= 0) call push(raw%record_groups, groups(k))
      end do
      call push(raw%record_group_first, raw%record_groups%count + 1)
   end subroutine add_record

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

   subroutine allocate_nodes(raw, count)
      type(raw_mesh_t), intent(inout) :: raw
      integer, intent(in) :: count
      allocate (raw%node_ids(count), raw%node_lines(count), raw%coords(3, count))
   end subroutine allocate_nodes

   !> x y z of a node line, then `n_parametric` parametric coordinates (not kept), then
   !> nothing else. All must be finite numbers.
   subroutine read_coordinates(scanner, x, n_parametric, error)
      type(text_scanner_t), intent(inout) :: scanner
      real(dp), intent(out) :: x(3)
      integer, intent(in) :: n_parametric
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: parameter_value
      integer :: k
      do k = 1, 3
         call scanner%read_real(x(k), error)
         if (allocated(error)) return
      end do
      do k = 1, n_parametric
         call scanner%read_real(parameter_value, error)
         if (allocated(error)) return
      end do
      call scanner%expect_end_of_line(error)
   end subroutine read_coordinates

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
      if (count > scanner%remaining_lines()) then
         call scanner%fail(error, section//' declares '//to_string(count)//' entries but only '// &
                           to_string(scanner%remaining_lines())//' lines follow (truncated file or bad count)')
      end if
   end subroutine read_count_line

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
         call scanner%fail(error, 'truncated file: end of file inside section '//section// &
                           ' (no $End'//section(2:)//')')
         return
      end if
      call scanner%next_token(token, found)
      if (token /= '$End'//section(2:)) then
         call scanner%fail(error, 'bad counts: expected $End'//section(2:)//', got "'//shorten(token)// &
                           '" (more entries than declared?)')
      end if
   end subroutine expect_section_end

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
end module frix_gmsh_reader
