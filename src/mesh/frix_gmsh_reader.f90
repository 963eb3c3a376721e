!> Reader of gmsh ASCII meshes, formats 2.2 and 4.1 (gmsh reference manual, "MSH file
!> format"; the version is taken from `$MeshFormat`).
!>
!> What becomes of the file's content:
!> - every node, in file order (user ids kept in `node_ids`);
!> - every volume cell (8-node hexahedron, gmsh type 5, whose node order is VTK's and
!>   frix_mesh's; 4- and 10-node tetrahedra), in file order (gmsh ids kept in `element_ids`;
!>   `element_block` is left 0 for the caller); in a file without volume elements (a plane
!>   mesh, every node at z = 0), every 4-node quadrilateral and 3-node triangle instead;
!> - every physical group, named from `$PhysicalNames` or, if unnamed, "<dim>:<tag>":
!>   a physical volume gives an element set (its hexahedra) and a node set; a physical surface
!>   gives a surface (each 4-node quadrilateral matched to the hexahedron face with the same
!>   four nodes) and a node set; a physical curve or point gives a node set.
!>   In a plane mesh, one dimension lower: a physical surface gives an element set, a
!>   physical curve a surface (each 2-node line matched to the element edge with its nodes).
!>   Sets are in ascending (dim, tag) order; their contents are sorted and unique. Two
!>   groups with the same name (even of different dimensions) are an error, since each gives
!>   a node set. A quadrilateral on a face shared by two hexahedra is an error too (a
!>   surface for loads or contact must lie on the boundary).
!>   Without any physical group (gmsh then writes every element) there are no sets.
!> - other elements in no physical group (lines, points, ... that gmsh writes) are skipped.
!> Hexahedra are taken as they are: an inverted one (negative Jacobian, e.g. from a mirrored
!> geometry) is reported by `check_element_jacobians`, never silently renumbered here.
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
!>
!> This module runs the section readers over the file: frix_gmsh_header ($MeshFormat,
!> $PhysicalNames, $Entities), frix_gmsh_nodes, frix_gmsh_elements (their state and helpers
!> in frix_gmsh_context), then frix_gmsh_to_mesh makes the mesh.
module frix_gmsh_reader
   use frix_error, only: error_t, fatal_error
   use frix_text_scanner, only: text_scanner_t, open_text_file
   use frix_mesh, only: mesh_t
   use frix_gmsh_context, only: raw_mesh_t, push, claim_section, skip_section, shorten
   use frix_gmsh_header, only: read_mesh_format, read_physical_names, read_entities_section
   use frix_gmsh_nodes, only: read_nodes_v2, read_nodes_v4
   use frix_gmsh_elements, only: read_elements_v2, read_elements_v4
   use frix_gmsh_to_mesh, only: build_mesh
   implicit none
   private

   public :: read_gmsh

   !> A reader of the body of one section (its first line already read).
   abstract interface
      subroutine section_reader(scanner, raw, error)
         import :: text_scanner_t, raw_mesh_t, error_t
         type(text_scanner_t), intent(inout) :: scanner
         type(raw_mesh_t), intent(inout) :: raw
         type(error_t), allocatable, intent(out) :: error
      end subroutine section_reader
   end interface

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
         if (.not. allocated(error)) call read_by_version(scanner, raw, read_nodes_v2, read_nodes_v4, error)
      case ('$Elements')
         call claim_section(scanner, section, raw%elements_line, error)
         if (.not. allocated(error)) call read_by_version(scanner, raw, read_elements_v2, read_elements_v4, error)
      case default
         call read_other_section(scanner, section, error)
      end select
   end subroutine read_section

   !> Read a section with the reader of the file's format (`raw%version`: 2 or 4).
   subroutine read_by_version(scanner, raw, reader_v2, reader_v4, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(raw_mesh_t), intent(inout) :: raw
      procedure(section_reader) :: reader_v2, reader_v4
      type(error_t), allocatable, intent(out) :: error
      if (raw%version == 2) then
         call reader_v2(scanner, raw, error)
      else
         call reader_v4(scanner, raw, error)
      end if
   end subroutine read_by_version

   !> A section this reader does not use is skipped; a line that starts no section is an error.
   subroutine read_other_section(scanner, section, error)
      type(text_scanner_t), intent(inout) :: scanner
      character(len=*), intent(in) :: section
      type(error_t), allocatable, intent(out) :: error
      if (index(section, '$End') == 1) then
         call scanner%fail(error, '"'//shorten(section)//'" outside its section (more entries than declared?)')
      else if (section(1:1) == '$') then
         call skip_section(scanner, section, error)
      else
         call scanner%fail(error, 'expected a section such as $Nodes, got "'//shorten(section)//'"')
      end if
   end subroutine read_other_section
end module frix_gmsh_reader
