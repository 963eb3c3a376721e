!> What `frix --check` found in a valid deck (docs/deck-format.md, "Checking a deck"): the
!> mesh's sizes, each element block with its formulation and material, the named node sets,
!> element sets and surfaces with their sizes, the contact pairs, the loads and the steps, so
!> that a user sees at once whether gmsh's physical groups, the deck's sets and the pairs are
!> what was meant.
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
      text = text//'  loads: '//to_string(size(model%dirichlet))//' prescribed-displacement lines, '// &
             to_string(size(model%nodal_forces))//' nodal-force lines, '//to_string(size(model%pressures))// &
             ' pressures, '//to_string(size(model%body_forces))//' body forces, '// &
             to_string(size(model%curves))//' load curves'//nl
      n_increments = sum(model%steps%n_increments)
      text = text//'  steps: '//to_string(size(model%steps))//', '//to_string(n_increments)// &
             ' nominal increments in all'//nl
   end function model_summary

   !> "  block k: <n> elements <formulation> (<kinematics>), material <id> <law>".
   function block_line(model, k) result(line)
      type(model_t), intent(in) :: model
      integer, intent(in) :: k
      character(len=:), allocatable :: line
      associate (block => model%blocks(k))
         line = '  block '//to_string(k)//': '//to_string(count(model%mesh%element_block == k))//' elements '// &
                block%element%formulation%name//' ('//kinematics_name(block%element%formulation%kinematics)// &
                '), material '//to_string(model%material_ids(block%material))//' '// &
                model%materials(block%material)%law%name
      end associate
   end function block_line

   !> The named node sets, element sets and surfaces, one line each kind: "name (size)".
   function named_sizes(model) result(text)
      type(model_t), intent(in) :: model
      character(len=:), allocatable :: text, list
      integer :: k
      text = ''
      if (allocated(model%mesh%node_sets)) then
         list = ''
         do k = 1, size(model%mesh%node_sets)
            list = list//' '//model%mesh%node_sets(k)%name//' ('//to_string(size(model%mesh%node_sets(k)%nodes))//')'
         end do
         if (size(model%mesh%node_sets) > 0) text = text//'  node sets (nodes):'//list//new_line('a')
      end if
      if (allocated(model%mesh%element_sets)) then
         list = ''
         do k = 1, size(model%mesh%element_sets)
            list = list//' '//model%mesh%element_sets(k)%name//' ('// &
                   to_string(size(model%mesh%element_sets(k)%elements))//')'
         end do
         if (size(model%mesh%element_sets) > 0) text = text//'  element sets (elements):'//list//new_line('a')
      end if
      if (allocated(model%mesh%surfaces)) then
         list = ''
         do k = 1, size(model%mesh%surfaces)
            list = list//' '//model%mesh%surfaces(k)%name//' ('//to_string(size(model%mesh%surfaces(k)%faces))//')'
         end do
         if (size(model%mesh%surfaces) > 0) text = text//'  surfaces (faces):'//list//new_line('a')
      end if
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
