!> Reader of the mesh of an Abaqus/CalculiX .inp file (Abaqus Keywords Reference; CalculiX
!> User's Manual, "Input deck format"; docs/deck-format.md, MESH FILE).
!>
!> What becomes of the file's content:
!> - *NODE (optional NSET=): every node, in file order (ids kept in `node_ids`);
!> - *ELEMENT, TYPE=C3D8 | C3D8R | C3D8I (8-node hexahedra, HEX8 cells), TYPE=C3D4 (4-node
!>   tetrahedra, TET4 cells) or TYPE=C3D10 (10-node tetrahedra, TET10 cells), optional ELSET=:
!>   the elements in file order (ids kept; the node orders of C3D8, C3D4 and C3D10 are those of
!>   frix's HEX8, TET4 and TET10 cells: C3D10's mid-edge nodes 5-10 on the edges 1-2, 2-3,
!>   3-1, 1-4, 2-4, 3-4, Abaqus Analysis User's Guide, "Three-dimensional solid element
!>   library", and CalculiX User's Manual, "C3D10"); in a plane mesh (x-y plane),
!>   TYPE=CPE4 | CPE4R | CPE4I | CAX4 | CAX4R | CAX4I (4-node quadrilaterals, QUAD4 cells) or
!>   TYPE=CPE3 | CAX3 (3-node triangles, TRI3 cells), whose nodes are counter-clockwise as
!>   frix's QUAD4 and TRI3 (CalculiX User's Manual, sections on the plane strain and
!>   axisymmetric elements: the node numbering of the S4 and S3 shells; and *DLOAD's faces of
!>   plane elements, 1-2, 2-3, 3-4, 4-1). The type only gives the
!>   cell: the formulation (integration, EAS; plane strain or axisymmetric) is the one of the
!>   deck's STRUCTURE ELEMENTS property. Plane stress types (CPS...) and other TYPEs are errors
!>   naming them, and so is a file with both solid and plane types;
!> - *NSET, NSET= and *ELSET, ELSET= (optional GENERATE): node sets and element sets, sorted
!>   and unique; a set defined again gets the new members too (as in Abaqus);
!> - *SURFACE, NAME= (TYPE=ELEMENT, the default): a surface of element faces S1..S6 of a
!>   hexahedron (S1..S4 of a tetrahedron), which are frix's local faces 1..6 (1..4); of a
!>   plane element, its edges S1..S4 of a quadrilateral (S1..S3 of a triangle), frix's local
!>   edges 1..4 (1..3);
!> - *INCLUDE, INPUT=: the lines of that file (path relative to the including file), read
!>   in place: data lines there continue the keyword before the *INCLUDE;
!> - *HEADING and every other keyword (materials, *STEP, *BOUNDARY, loads, ...), with its
!>   data lines: ignored. Lines starting with `**` are comments.
!> Keywords, parameter names and set names are case-insensitive; a set keeps the spelling of
!> its first definition, the name the deck uses. An id must be defined before a line names it.
!> Every error names the file and line (most also the column):
!> `pipe.inp:17:9: element 4 names node 99, which is not defined (before this line)`.
module frix_inp_reader
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string, to_upper
   use frix_text_scanner, only: text_scanner_t, open_text_file
   use frix_mesh, only: mesh_t, cell_index, connectivity_rows
   use frix_cell_registry, only: cell_entry_t, cell_table
   use frix_mesh_selection, only: sorted_unique
   use frix_gmsh_context, only: shorten, first_off_plane, off_plane_message
   use frix_inp_keyword, only: inp_keyword_t, read_keyword_line
   use frix_inp_context, only: inp_data_t, node_kind, element_kind, set_index, new_surface, add_file, &
                               mode_skip, mode_node, mode_element, mode_set, mode_set_generate, mode_surface
   use frix_inp_data_lines, only: read_node_line, read_element_line, read_set_line, read_generate_line, &
                                  read_surface_line, where_defined
   implicit none
   private

   public :: read_inp

   !> The most nested *INCLUDEs (guards against a file including itself).
   integer, parameter :: max_include_depth = 10

contains

   !> Read the mesh of the .inp file at `path` into `mesh`.
   subroutine read_inp(path, mesh, error)
      character(len=*), intent(in) :: path
      type(mesh_t), intent(out) :: mesh
      type(error_t), allocatable, intent(out) :: error
      type(inp_data_t) :: data
      call read_file(path, data, 0, error)
      if (allocated(error)) return
      call check_no_pending(data, error)
      if (allocated(error)) return
      call check_plane_nodes(data, error)
      if (allocated(error)) return
      call build_mesh(data, mesh)
   end subroutine read_inp

   !> The nodes of a mesh of plane elements lie in the x-y plane (first_off_plane): error
   !> naming the line of the first that does not.
   subroutine check_plane_nodes(data, error)
      type(inp_data_t), intent(in) :: data
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      if (data%cell_dimension /= 2 .or. data%node_ids%count == 0) return
      i = first_off_plane(data%coords(:, 1:data%node_ids%count))
      if (i /= 0) call fatal_error(error, where_defined(data, data%node_files%items(i), data%node_lines%items(i))// &
                                   ': '//off_plane_message(data%node_ids%items(i), data%coords(3, i)))
   end subroutine check_plane_nodes

   !> Read the lines of one file (the main one, depth 0, or an *INCLUDE).
   recursive subroutine read_file(path, data, depth, error)
      character(len=*), intent(in) :: path
      type(inp_data_t), intent(inout) :: data
      integer, intent(in) :: depth
      type(error_t), allocatable, intent(out) :: error
      type(text_scanner_t) :: scanner
      character(len=:), allocatable :: line
      integer :: file, start
      call open_text_file(path, scanner, error)
      if (allocated(error)) return
      scanner%commas_separate = .true.
      call add_file(data, path, file)
      do while (scanner%next_line())
         line = scanner%line()
         start = verify(line, ' '//achar(9))
         if (start == 0) cycle
         if (index(line(start:), '**') == 1) cycle
         if (line(start:start) == '*') then
            call check_no_pending(data, error)
            if (allocated(error)) return
            call start_keyword(scanner, path, data, depth, error)
         else
            call read_data_line(scanner, data, file, error)
         end if
         if (allocated(error)) return
      end do
   end subroutine read_file

   !> A data line of the current keyword.
   subroutine read_data_line(scanner, data, file, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(inp_data_t), intent(inout) :: data
      integer, intent(in) :: file
      type(error_t), allocatable, intent(out) :: error
      select case (data%mode)
      case (mode_node)
         call read_node_line(scanner, data, file, error)
      case (mode_element)
         call read_element_line(scanner, data, file, error)
      case (mode_set)
         call read_set_line(scanner, data, error)
      case (mode_set_generate)
         call read_generate_line(scanner, data, error)
      case (mode_surface)
         call read_surface_line(scanner, data, error)
      end select
   end subroutine read_data_line

   !> The keyword line (the current one): sets what its data lines are, or reads an *INCLUDE.
   recursive subroutine start_keyword(scanner, path, data, depth, error)
      type(text_scanner_t), intent(inout) :: scanner
      character(len=*), intent(in) :: path
      type(inp_data_t), intent(inout) :: data
      integer, intent(in) :: depth
      type(error_t), allocatable, intent(out) :: error
      type(inp_keyword_t) :: keyword
      call read_keyword_line(scanner, keyword, error)
      if (allocated(error)) return
      if (keyword%name /= 'INCLUDE') then
         data%mode = mode_skip
         data%target_set = 0
      end if
      select case (keyword%name)
      case ('NODE')
         call keyword%check_parameters(scanner, 'NSET=', error)
         if (allocated(error)) return
         data%mode = mode_node
         if (keyword%has('NSET')) data%target_set = set_index(data, node_kind, keyword%value_of('NSET'))
      case ('ELEMENT')
         call start_element(scanner, keyword, data, error)
      case ('NSET')
         call start_set(scanner, keyword, data, node_kind, error)
      case ('ELSET')
         call start_set(scanner, keyword, data, element_kind, error)
      case ('SURFACE')
         call start_surface(scanner, keyword, data, error)
      case ('INCLUDE')
         call read_include(scanner, keyword, path, data, depth, error)
      end select
   end subroutine start_keyword

   !> *ELEMENT, TYPE=..., ELSET=...: 8-node hexahedra, 4- or 10-node tetrahedra.
   subroutine start_element(scanner, keyword, data, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(inp_keyword_t), intent(in) :: keyword
      type(inp_data_t), intent(inout) :: data
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: element_type
      call keyword%check_parameters(scanner, 'TYPE= ELSET=', error)
      if (allocated(error)) return
      element_type = to_upper(keyword%value_of('TYPE'))
      scanner%token_column = keyword%column_of('TYPE')
      if (.not. keyword%has('TYPE')) then
         call scanner%fail(error, '*ELEMENT without TYPE=')
         return
      end if
      select case (element_type)
      case ('C3D8', 'C3D8R', 'C3D8I')
         data%element_cell_name = 'HEX8'
         data%element_node_count = 8
      case ('C3D4')
         data%element_cell_name = 'TET4'
         data%element_node_count = 4
      case ('C3D10')
         data%element_cell_name = 'TET10'
         data%element_node_count = 10
      case ('CPE4', 'CPE4R', 'CPE4I', 'CAX4', 'CAX4R', 'CAX4I')
         data%element_cell_name = 'QUAD4'
         data%element_node_count = 4
      case ('CPE3', 'CAX3')
         data%element_cell_name = 'TRI3'
         data%element_node_count = 3
      case default
         call fail_element_type(scanner, keyword%value_of('TYPE'), error)
         return
      end select
      data%element_cell = cell_index(data%element_cell_name)
      call check_dimension(scanner, keyword%value_of('TYPE'), data, error)
      if (allocated(error)) return
      data%mode = mode_element
      if (keyword%has('ELSET')) data%target_set = set_index(data, element_kind, keyword%value_of('ELSET'))
   end subroutine start_element

   !> Error at the TYPE= token: element type `element_type` is not read (plane stress: not
   !> offered by frix).
   subroutine fail_element_type(scanner, element_type, error)
      type(text_scanner_t), intent(inout) :: scanner
      character(len=*), intent(in) :: element_type
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: plane_types = 'plane strain (CPE3, CPE4, CPE4R, CPE4I) and axisymmetric '// &
                                                   '(CAX3, CAX4, CAX4R, CAX4I) elements'
      if (index(to_upper(element_type), 'CPS') == 1) then
         call scanner%fail_at_token(error, 'element type '//shorten(element_type)//' is a plane stress element, '// &
                                    'which frix does not offer: its plane elements are '//plane_types)
      else
         call scanner%fail_at_token(error, 'element type '//shorten(element_type)// &
                                    ' is not supported: frix reads 8-node hexahedra (C3D8, C3D8R, C3D8I),'// &
                                    ' 4-node tetrahedra (C3D4) and 10-node tetrahedra (C3D10), and '// &
                                    plane_types)
      end if
   end subroutine fail_element_type

   !> The cells of a mesh have one dimension: error at the TYPE= token of an *ELEMENT whose
   !> cell (`data%element_cell`) has another dimension than the cells before it.
   subroutine check_dimension(scanner, element_type, data, error)
      type(text_scanner_t), intent(inout) :: scanner
      character(len=*), intent(in) :: element_type
      type(inp_data_t), intent(inout) :: data
      type(error_t), allocatable, intent(out) :: error
      type(cell_entry_t), allocatable :: table(:)
      integer :: dim
      table = cell_table()
      dim = table(data%element_cell)%cell%dimension
      if (data%cell_dimension == 0) then
         data%cell_dimension = dim
         data%dimension_type = element_type
         data%dimension_where = scanner%location()
      else if (dim /= data%cell_dimension) then
         call scanner%fail_at_token(error, 'element type '//shorten(element_type)//' is '//dimension_word(dim)// &
                                    ', but the elements of TYPE='//shorten(data%dimension_type)//' ('// &
                                    data%dimension_where//') are '//dimension_word(data%cell_dimension)// &
                                    ': a mesh has either solid or plane elements, not both')
      end if
   end subroutine check_dimension

   !> 'solid (3D)' or 'plane (2D)', for messages.
   pure function dimension_word(dim) result(word)
      integer, intent(in) :: dim
      character(len=:), allocatable :: word
      if (dim == 3) then
         word = 'solid (3D)'
      else
         word = 'plane (2D)'
      end if
   end function dimension_word

   !> *NSET, NSET=name or *ELSET, ELSET=name, optionally GENERATE.
   subroutine start_set(scanner, keyword, data, kind, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(inp_keyword_t), intent(in) :: keyword
      type(inp_data_t), intent(inout) :: data
      integer, intent(in) :: kind
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: name
      name = keyword%name
      call keyword%check_parameters(scanner, name//'= GENERATE INTERNAL UNSORTED', error)
      if (allocated(error)) return
      if (.not. keyword%has(name)) then
         call scanner%fail(error, '*'//name//' without '//name//'=')
         return
      end if
      data%target_set = set_index(data, kind, keyword%value_of(name))
      data%mode = mode_set
      if (keyword%has('GENERATE')) data%mode = mode_set_generate
   end subroutine start_set

   !> *SURFACE, NAME=name[, TYPE=ELEMENT]: a new surface of element faces.
   subroutine start_surface(scanner, keyword, data, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(inp_keyword_t), intent(in) :: keyword
      type(inp_data_t), intent(inout) :: data
      type(error_t), allocatable, intent(out) :: error
      integer :: k
      call keyword%check_parameters(scanner, 'NAME= TYPE= INTERNAL', error)
      if (allocated(error)) return
      if (.not. keyword%has('NAME')) then
         call scanner%fail(error, '*SURFACE without NAME=')
         return
      end if
      if (keyword%has('TYPE') .and. to_upper(keyword%value_of('TYPE')) /= 'ELEMENT') then
         scanner%token_column = keyword%column_of('TYPE')
         call scanner%fail_at_token(error, '*SURFACE, TYPE='//shorten(keyword%value_of('TYPE'))// &
                                    ' is not supported: only TYPE=ELEMENT (element faces S1..S6)')
         return
      end if
      do k = 1, data%n_surfaces
         if (to_upper(data%surfaces(k)%name) == to_upper(keyword%value_of('NAME'))) then
            scanner%token_column = keyword%column_of('NAME')
            call scanner%fail_at_token(error, 'surface "'//shorten(keyword%value_of('NAME'))//'" defined twice')
            return
         end if
      end do
      data%target_surface = new_surface(data, keyword%value_of('NAME'))
      data%mode = mode_surface
   end subroutine start_surface

   !> *INCLUDE, INPUT=file: read that file here (relative to the including file's folder).
   recursive subroutine read_include(scanner, keyword, path, data, depth, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(inp_keyword_t), intent(in) :: keyword
      character(len=*), intent(in) :: path
      type(inp_data_t), intent(inout) :: data
      integer, intent(in) :: depth
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: input
      type(error_t), allocatable :: inner
      call keyword%check_parameters(scanner, 'INPUT=', error)
      if (allocated(error)) return
      if (.not. keyword%has('INPUT')) then
         call scanner%fail(error, '*INCLUDE without INPUT=')
         return
      end if
      if (depth >= max_include_depth) then
         call scanner%fail(error, '*INCLUDE nested more than '//to_string(max_include_depth)//' deep')
         return
      end if
      input = keyword%value_of('INPUT')
      if (input(1:1) /= '/') input = folder_of(path)//input
      ! data%mode: the keyword before the *INCLUDE goes on in the included file
      call read_file(input, data, depth + 1, inner)
      if (allocated(inner)) then
         scanner%token_column = keyword%column_of('INPUT')
         call fatal_error(error, scanner%location()//': in the file included here: '//inner%message)
      end if
   end subroutine read_include

   !> Error if an element's line ended with a comma and no line completed it.
   subroutine check_no_pending(data, error)
      type(inp_data_t), intent(inout) :: data
      type(error_t), allocatable, intent(out) :: error
      if (.not. data%pending) return
      call fatal_error(error, where_defined(data, data%pending_file, data%pending_line)//': element '// &
                       to_string(data%pending_id)//' has '//to_string(data%pending_count)// &
                       ' nodes, a '//data%element_cell_name//' needs '//to_string(data%element_node_count)// &
                       ' (its line ends with a comma, but no data line follows)')
   end subroutine check_no_pending

   !> The mesh of what was read.
   subroutine build_mesh(data, mesh)
      type(inp_data_t), intent(in) :: data
      type(mesh_t), intent(out) :: mesh
      integer :: n_node_sets, n_element_sets, k, i_node, i_element, e, first, n
      integer, allocatable :: keys(:)
      mesh%n_nodes = data%node_ids%count
      mesh%n_elements = data%element_ids%count
      allocate (mesh%coords(3, mesh%n_nodes), mesh%node_ids(mesh%n_nodes))
      call mesh%set_cells(data%element_cells%items(1:mesh%n_elements))
      allocate (mesh%connectivity(connectivity_rows(mesh%element_cell), mesh%n_elements), source=0)
      allocate (mesh%element_ids(mesh%n_elements))
      if (mesh%n_nodes > 0) then
         mesh%coords = data%coords(:, 1:mesh%n_nodes)
         mesh%node_ids = data%node_ids%items(1:mesh%n_nodes)
      end if
      first = 1
      do e = 1, mesh%n_elements
         n = mesh%node_count(e)
         mesh%connectivity(1:n, e) = data%connectivity%items(first:first + n - 1)
         first = first + n
      end do
      if (mesh%n_elements > 0) mesh%element_ids = data%element_ids%items(1:mesh%n_elements)
      allocate (mesh%element_block(mesh%n_elements), source=0)
      n_node_sets = 0
      do k = 1, data%n_sets
         if (data%sets(k)%kind == node_kind) n_node_sets = n_node_sets + 1
      end do
      n_element_sets = data%n_sets - n_node_sets
      allocate (mesh%node_sets(n_node_sets), mesh%element_sets(n_element_sets), mesh%surfaces(data%n_surfaces))
      i_node = 0
      i_element = 0
      do k = 1, data%n_sets
         associate (set => data%sets(k))
            if (set%kind == node_kind) then
               i_node = i_node + 1
               mesh%node_sets(i_node)%name = set%name
               mesh%node_sets(i_node)%nodes = members(set%members%items, set%members%count)
            else
               i_element = i_element + 1
               mesh%element_sets(i_element)%name = set%name
               mesh%element_sets(i_element)%elements = members(set%members%items, set%members%count)
            end if
         end associate
      end do
      do k = 1, data%n_surfaces
         associate (surface => data%surfaces(k), n => data%surfaces(k)%faces%count)
            mesh%surfaces(k)%name = surface%name
            if (n > 0) then
               keys = sorted_unique(6*(surface%elements%items(1:n) - 1) + surface%faces%items(1:n) - 1)
            else
               allocate (keys(0))
            end if
            mesh%surfaces(k)%elements = keys/6 + 1
            mesh%surfaces(k)%faces = modulo(keys, 6) + 1
            deallocate (keys)
         end associate
      end do
   end subroutine build_mesh

   !> The sorted, unique members of a set (`count` of `items`, which may be unallocated).
   function members(items, count) result(unique)
      integer, allocatable, intent(in) :: items(:)
      integer, intent(in) :: count
      integer, allocatable :: unique(:)
      if (count == 0) then
         allocate (unique(0))
      else
         unique = sorted_unique(items(1:count))
      end if
   end function members

   !> The folder of `path`, with its trailing slash ('' for a bare file name).
   pure function folder_of(path) result(folder)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: folder
      folder = path(1:index(path, '/', back=.true.))
   end function folder_of
end module frix_inp_reader
