!> The `$Nodes` section of a gmsh .msh file, formats 2.2 and 4.1 (gmsh reference manual, "MSH
!> file format"): every node in file order, with its id, the lines of its id and of its
!> coordinates (for messages) and its coordinates, which must be finite numbers. Parametric
!> coordinates of 4.1 are read and dropped.
module frix_gmsh_nodes
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_text_scanner, only: text_scanner_t
   use frix_gmsh_context, only: raw_mesh_t, next_data_line, expect_section_end, read_count_line, &
                                read_blocks_header, read_block_start, read_block_count, check_blocks_total, &
                                read_positive_id
   implicit none
   private

   public :: read_nodes_v2, read_nodes_v4

contains

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
         call read_node_id(scanner, raw, i, error)
         if (allocated(error)) return
         raw%coordinate_lines(i) = scanner%line_number
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
      integer :: n_blocks, count, block, dim, tag, parametric, block_count, header_line
      call read_blocks_header(scanner, '$Nodes', 'node', n_blocks, count, header_line, error)
      if (allocated(error)) return
      call allocate_nodes(raw, count)
      do block = 1, n_blocks
         call read_block_start(scanner, '$Nodes', dim, tag, parametric, error)
         if (allocated(error)) return
         if (parametric /= 0 .and. parametric /= 1) then
            call scanner%fail(error, 'expected parametric 0 or 1, got "'//to_string(parametric)//'"')
            return
         end if
         call read_block_count(scanner, '$Nodes', 'node', count, raw%n_nodes, header_line, block_count, error)
         if (allocated(error)) return
         call read_node_block(scanner, raw, block_count, parametric*dim, error)
         if (allocated(error)) return
      end do
      call check_blocks_total(scanner, '$Nodes', 'node', count, raw%n_nodes, header_line, error)
      if (allocated(error)) return
      call expect_section_end(scanner, '$Nodes', error)
   end subroutine read_nodes_v4

   !> The lines of a 4.1 node block after its header: `block_count` lines with a node id, then
   !> as many with coordinates, each followed by `n_parametric` parametric coordinates.
   subroutine read_node_block(scanner, raw, block_count, n_parametric, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(raw_mesh_t), intent(inout) :: raw
      integer, intent(in) :: block_count, n_parametric
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      do i = raw%n_nodes + 1, raw%n_nodes + block_count
         call read_node_id(scanner, raw, i, error)
         if (allocated(error)) return
         call scanner%expect_end_of_line(error)
         if (allocated(error)) return
      end do
      do i = raw%n_nodes + 1, raw%n_nodes + block_count
         call next_data_line(scanner, '$Nodes', error)
         if (allocated(error)) return
         raw%coordinate_lines(i) = scanner%line_number
         call read_coordinates(scanner, raw%coords(:, i), n_parametric, error)
         if (allocated(error)) return
      end do
      raw%n_nodes = raw%n_nodes + block_count
   end subroutine read_node_block

   !> The next line of `$Nodes` starts with the id of node `i`, which is kept with the line.
   subroutine read_node_id(scanner, raw, i, error)
      type(text_scanner_t), intent(inout) :: scanner
      type(raw_mesh_t), intent(inout) :: raw
      integer, intent(in) :: i
      type(error_t), allocatable, intent(out) :: error
      call next_data_line(scanner, '$Nodes', error)
      if (allocated(error)) return
      call read_positive_id(scanner, 'node', raw%node_ids(i), error)
      if (allocated(error)) return
      raw%node_lines(i) = scanner%line_number
   end subroutine read_node_id

   subroutine allocate_nodes(raw, count)
      type(raw_mesh_t), intent(inout) :: raw
      integer, intent(in) :: count
      allocate (raw%node_ids(count), raw%node_lines(count), raw%coordinate_lines(count))
      allocate (raw%coords(3, count))
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
end module frix_gmsh_nodes
