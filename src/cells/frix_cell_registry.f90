!> The reference cells frix knows, as a table: looked up by name, by VTK code or by gmsh code.
!> Adding a cell type is one file (a `reference_cell_t` extension) and one line here.
module frix_cell_registry
   use frix_reference_cell, only: reference_cell_t
   use frix_hex8_cell, only: new_hex8_cell
   use frix_quad4_cell, only: new_quad4_cell
   use frix_tet4_cell, only: new_tet4_cell
   use frix_tri3_cell, only: new_tri3_cell
   use frix_tet10_cell, only: new_tet10_cell
   use frix_tri6_cell, only: new_tri6_cell
   use frix_line2_cell, only: new_line2_cell
   implicit none
   private

   public :: cell_table, find_cell, find_in_table, cell_names, max_cell_nodes, hex8_cell_index

   !> The line of HEX8 in cell_table(): a mesh built without cell types is HEX8 (frix_mesh).
   integer, parameter :: hex8_cell_index = 1

   !> One entry of the table (an allocatable component holds the concrete cell).
   type, public :: cell_entry_t
      class(reference_cell_t), allocatable :: cell
   end type cell_entry_t

contains

   !> Every known cell, one line each.
   function cell_table() result(table)
      type(cell_entry_t), allocatable :: table(:)
      allocate (table(7))
      allocate (table(1)%cell, source=new_hex8_cell())
      allocate (table(2)%cell, source=new_quad4_cell())
      allocate (table(3)%cell, source=new_tet4_cell())
      allocate (table(4)%cell, source=new_tri3_cell())
      allocate (table(5)%cell, source=new_tet10_cell())
      allocate (table(6)%cell, source=new_tri6_cell())
      allocate (table(7)%cell, source=new_line2_cell())   ! the edge of QUAD4 and TRI3
   end function cell_table

   !> The cell with `name` (upper case), VTK code `vtk_type` or gmsh code `gmsh_type`, whichever
   !> is given; `found` false when none matches (then `cell` is not allocated).
   subroutine find_cell(cell, found, name, vtk_type, gmsh_type)
      class(reference_cell_t), allocatable, intent(out) :: cell
      logical, intent(out) :: found
      character(len=*), intent(in), optional :: name
      integer, intent(in), optional :: vtk_type, gmsh_type
      type(cell_entry_t), allocatable :: table(:)
      integer :: k
      table = cell_table()
      found = .false.
      do k = 1, size(table)
         if (present(name)) found = table(k)%cell%name == name
         if (present(vtk_type)) found = table(k)%cell%vtk_type == vtk_type
         if (present(gmsh_type)) found = table(k)%cell%gmsh_type == gmsh_type
         if (found) then
            call move_alloc(table(k)%cell, cell)
            return
         end if
      end do
   end subroutine find_cell

   !> The line of the cell called `name` in `table` (a cell_table()), 0 if none.
   pure integer function find_in_table(table, name) result(index_found)
      type(cell_entry_t), intent(in) :: table(:)
      character(len=*), intent(in) :: name
      integer :: k
      index_found = 0
      do k = 1, size(table)
         if (table(k)%cell%name == name) index_found = k
      end do
   end function find_in_table

   !> The most nodes of any known cell.
   integer function max_cell_nodes()
      type(cell_entry_t), allocatable :: table(:)
      integer :: k
      table = cell_table()
      max_cell_nodes = 0
      do k = 1, size(table)
         max_cell_nodes = max(max_cell_nodes, table(k)%cell%n_nodes)
      end do
   end function max_cell_nodes

   !> The names of the known cells, blank-separated (for messages).
   function cell_names() result(names)
      character(len=:), allocatable :: names
      type(cell_entry_t), allocatable :: table(:)
      integer :: k
      table = cell_table()
      names = table(1)%cell%name
      do k = 2, size(table)
         names = names//' '//table(k)%cell%name
      end do
   end function cell_names

end module frix_cell_registry
