!> The sections of a gmsh .msh file (formats 2.2 and 4.1; gmsh reference manual, "MSH file
!> format") that describe the others: `$MeshFormat` (the version; ASCII only),
!> `$PhysicalNames` (a name per physical group) and the 4.1 `$Entities` (the physical groups
!> of each geometric entity, from which the elements of a block take theirs).
module frix_gmsh_header
   use frix_kinds, only: i8
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_text_scanner, only: text_scanner_t
   use frix_gmsh_context, only: raw_mesh_t, push, claim_section, next_data_line, expect_section_end, &
                                read_count, read_count_line, check_room, read_physical_tag, read_dimension, &
                                shorten
   implicit none
   private

   public :: read_mesh_format, read_physical_names, read_entities_section

contains

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

   !> 4.1 `$Entities`: numbers of points, curves, surfaces, volumes; then one line per entity
   !> (`read_entity`). Only the physical tags are kept.
   subroutine read_entities(scanner, raw, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(raw_mesh_t), intent(inout) :: raw
      type(error_t), allocatable, intent(out) :: error
      integer :: counts(0:3), dim, i
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
      call check_room(scanner, '$Entities', sum(int(counts, i8)), 'entities', error)
      if (allocated(error)) return
      do dim = 0, 3
         call raw%entity_map(dim)%clear(counts(dim))
         do i = 1, counts(dim)
            call read_entity(scanner, raw, dim, i, error)
            if (allocated(error)) return
         end do
      end do
      call expect_section_end(scanner, '$Entities', error)
   end subroutine read_entities

   !> Entity `i` of dimension `dim`: a point `tag x y z nphys phys...`, others `tag minx miny
   !> minz maxx maxy maxz nphys phys... nbounding bounding...`.
   subroutine read_entity(scanner, raw, dim, i, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(raw_mesh_t), intent(inout) :: raw
      integer, intent(in) :: dim, i
      type(error_t), allocatable, intent(out) :: error
      integer :: j, tag, n_physical, physical, skipped, existing
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
      end if
   end subroutine read_entity
end module frix_gmsh_header
