!> What `frix --check` found in a valid deck (docs/deck-format.md, "Checking a deck"): the
!> mesh's sizes, each element block with its formulation and material, the named node sets,
!> element sets and surfaces with their sizes, the contact pairs and kinematic couplings, the
!> loads and the steps, so that a user sees at once whether gmsh's physical groups, the deck's
!> sets and the pairs are what was meant.
module frix_model_summary
   use frix_strings, only: to_string
   use frix_element, only: kinematics_name
   use frix_model, only: model_t
   implicit none
   private

   public :: model_summary

contains

   !> The summary's lines, each indented by two blanks, ending with a new line.
   function model_summary(model) result(text)
      type(model_t), intent(in) :: model
      character(len=:), allocatable :: text
      character(len=*), parameter :: nl = new_line('a')
      integer :: k, n_increments
      text = '  mesh: '//to_string(model%mesh%n_nodes)//' nodes, '//to_string(model%mesh%n_elements)// &
             ' elements, '//to_string(3*model%mesh%n_nodes)//' equations'//nl
      do k = 1, size(model%blocks)
         text = text//block_line(model, k)//nl
      end do
      text = text//named_sizes(model)
      do k = 1, size(model%contact_pairs)
         text = text//pair_line(model, k)//nl
      end do
      if (allocated(model%couplings)) then
         do k = 1, size(model%couplings)
            associate (coupling => model%couplings(k))
               text = text//'  coupling '//to_string(coupling%id)//': '//to_string(size(coupling%nodes))// &
                      ' nodes to reference node '//to_string(model%mesh%node_ids(coupling%reference_node))// &
                      ', rotation node '//to_string(model%mesh%node_ids(coupling%rotation_node))//nl
            end associate
         end do
      end if
      text = text//'  loads: '//to_string(size(model%dirichlet))//' prescribed-displacement lines, '// &
             to_string(size(model%nodal_forces))//' nodal-force lines, '//to_string(size(model%pressures))// &
             ' pressures, '//to_string(size(model%body_forces))//' body forces, '// &
             to_string(size(model%curves))//' load curves'//nl
      if (allocated(model%initial_stress_source)) &
         text = text//'  initial stress: '//to_string(size(model%initial_stresses))//' lines, on '// &
                to_string(count(model%initial_stress_source > 0))//' elements'//nl
      n_increments = sum(model%steps%n_increments)
      text = text//'  steps: '//to_string(size(model%steps))//', '//to_string(n_increments)// &
             ' nominal increments in all'//nl
   end function model_summary

   !> "  block k: <n> elements <formulation> (<kinematics>) on <cell> cells, material <id> <law>"
   !> (the cell of the block's elements: a block has one formulation, and a formulation one cell).
   function block_line(model, k) result(line)
      type(model_t), intent(in) :: model
      integer, intent(in) :: k
      character(len=:), allocatable :: line
      character(len=:), allocatable :: cell
      integer :: first
      first = findloc(model%mesh%element_block, k, dim=1)
      cell = 'no'
      if (first > 0) cell = model%mesh%cell_name(first)
      associate (block => model%blocks(k))
         line = '  block '//to_string(k)//': '//to_string(count(model%mesh%element_block == k))//' elements '// &
                block%element%formulation%name//' ('//kinematics_name(block%element%formulation%kinematics)// &
                ') on '//cell//' cells, material '//to_string(model%material_ids(block%material))//' '// &
                model%materials(block%material)%law%name
      end associate
   end function block_line

   !> The named node sets, element sets and surfaces, one line each kind: "name (size)".
   function named_sizes(model) result(text)
      type(model_t), intent(in) :: model
      character(len=:), allocatable :: text
      integer :: k
      text = ''
      associate (mesh => model%mesh)
         if (allocated(mesh%node_sets)) then
            do k = 1, size(mesh%node_sets)
               call add_entry('  node sets (nodes):', k, mesh%node_sets(k)%name, size(mesh%node_sets(k)%nodes))
            end do
            call end_line(size(mesh%node_sets))
         end if
         if (allocated(mesh%element_sets)) then
            do k = 1, size(mesh%element_sets)
               call add_entry('  element sets (elements):', k, mesh%element_sets(k)%name, &
                              size(mesh%element_sets(k)%elements))
            end do
            call end_line(size(mesh%element_sets))
         end if
         if (allocated(mesh%surfaces)) then
            do k = 1, size(mesh%surfaces)
               call add_entry('  surfaces (faces):', k, mesh%surfaces(k)%name, size(mesh%surfaces(k)%faces))
            end do
            call end_line(size(mesh%surfaces))
         end if
      end associate
   contains
      !> " name (size)", after the line's head for the first entry (k = 1).
      subroutine add_entry(head, k, name, n)
         character(len=*), intent(in) :: head, name
         integer, intent(in) :: k, n
         if (k == 1) text = text//head
         text = text//' '//name//' ('//to_string(n)//')'
      end subroutine add_entry
      subroutine end_line(n)
         integer, intent(in) :: n
         if (n > 0) text = text//new_line('a')
      end subroutine end_line
   end function named_sizes

   !> "  contact pair <id>: slave <surface>, master <surface | rigid plane>, <kind>".
   function pair_line(model, k) result(line)
      type(model_t), intent(in) :: model
      integer, intent(in) :: k
      character(len=:), allocatable :: line, master, kind
      associate (pair => model%contact_pairs(k))
         if (pair%master_surface == 0) then
            master = 'a rigid plane'
         else
            master = model%mesh%surfaces(pair%master_surface)%name
         end if
         if (pair%tied) then
            kind = 'tied'
         else if (pair%mortar) then
            kind = 'mortar'
         else
            kind = 'node-to-segment, '//to_string(pair%passes)//' pass'//trim(merge('es', '  ', pair%passes > 1))
         end if
         line = '  contact pair '//to_string(pair%id)//': slave '//model%mesh%surfaces(pair%slave_surface)%name// &
                ', master '//master//', '//kind
      end associate
   end function pair_line
end module frix_model_summary
