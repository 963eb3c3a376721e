!> HDF5 results file of a run: its writer, and its readers for restarts. One file holds the
!> mesh once and one group per converged increment; layout (h5py shapes, i.e. the Fortran
!> shapes reversed), see docs/hdf5-layout.md:
!>   /                      attributes frix_version, deck_path, title, layout_version
!>   /mesh/coordinates      (n_nodes, 3) reference coordinates
!>   /mesh/node_ids, /mesh/element_ids, /mesh/element_block     user ids, block index
!>   /mesh/connectivity     (n_elements, rows) 1-based internal node numbers, the cell's order
!>                          (frix_mesh), 0 past the nodes of a smaller cell (TET4: 4); rows:
!>                          the most nodes of the mesh's cells, at least 8 (TET10: 10)
!>   /mesh/cell_types       (n_elements) VTK cell type codes, only in a mesh with other cells than HEX8
!>   /mesh/node_sets/<name>, /mesh/element_sets/<name>          1-based internal numbers
!>   /mesh/surfaces/<name>/elements, .../faces                  element number, local face 1..6
!>   /increments/<NNNNNN>/  running number 000001, 000002, ... in the order written;
!>       attributes step, increment, time, complete (= 1, written last)
!>       displacement, reaction (n_nodes, 3); stress, strain (n_elements, n_points, 6) Cauchy
!>       (displacement: the reported one; after a RESET_DISPLACEMENT step also
!>       total_displacement and reference_displacement (n_nodes, 3), the restart's state)
!>       stress / strain with engineering shears, frix Voigt order xx yy zz xy xz yz;
!>       alpha (n_elements, max_eas); history (n_elements, n_points, n_state);
!>       optional group contact/ with the caller's named arrays.
!> The file is flushed (H5Fflush, global scope) and closed after the header and after every
!> increment, and reopened for the next one: a run that stops keeps the converged increments,
!> and other processes can open the file (read-only) between increments; while one holds it
!> open the writer waits for it (frix_hdf5_file's open_for_writing). A group without the
!> `complete` attribute (a run stopped while writing it) is ignored by the readers.
!>
!> Restart: `read_restart` returns time, displacements, EAS parameters and material history of
!> one increment after checking them against the current model's array shapes. A restarted run
!> writes a new results file (it does not append to the old one).
!>
!> This module writes the file (`hdf5_results_t`); the readers `read_restart`, `list_increments`
!> and `read_increment_array` are frix_hdf5_restart's, made available here too; creating,
!> opening, flushing and closing the file are frix_hdf5_file's.
module frix_hdf5_results
   use, intrinsic :: iso_c_binding, only: c_long_long
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_mesh, only: mesh_t
   use frix_hdf5_support, only: hdf5_location_t, create_group, open_group, close_group, close_group_after, &
                                write_dataset, write_attribute
   use frix_hdf5_file, only: hdf5_layout_version, increment_group_name, create_file, open_for_writing, flush_file, &
                             close_file, check_room
   use frix_hdf5_restart, only: read_restart, list_increments, read_increment_array
   implicit none
   private

   public :: hdf5_results_t, read_restart, list_increments, read_increment_array
   public :: hdf5_layout_version

   !> A caller-given array written into the `contact` group of the next increment.
   type :: named_array_t
      character(len=:), allocatable :: name
      real(dp), allocatable :: reals(:, :)        !! real data, Fortran shape (n_components, n)
      integer, allocatable :: integers(:, :)      !! or integer data
      logical :: rank_one = .false.               !! written as a 1-D dataset (n)
   end type named_array_t

   !> An HDF5 results file being written. Usage: `create`; per converged increment optionally
   !> `add_contact_array` (any number), then `write_increment`; at the end `close`.
   type :: hdf5_results_t
      private
      type(hdf5_location_t) :: file
      integer :: n_nodes = 0
      integer :: n_elements = 0
      integer :: n_increments = 0                 !! increment groups written so far
      logical :: created = .false.                !! the file exists with its header (closed between writes)
      type(named_array_t), allocatable :: contact(:)
      type(named_array_t), allocatable :: fields(:)   !! named integration-point fields
      type(named_array_t), allocatable :: control(:)  !! the increment control, for restarts
      type(named_array_t), allocatable :: history_columns(:)   !! the history's values, one each
   contains
      procedure :: create => results_create
      procedure :: write_increment => results_write_increment
      procedure :: close => results_close
      procedure :: n_written => results_n_written
      procedure :: add_point_field
      procedure :: add_control_array
      procedure :: add_history_value
      procedure, private :: add_contact_real_1, add_contact_real_2, add_contact_integer_1
      generic :: add_contact_array => add_contact_real_1, add_contact_real_2, add_contact_integer_1
   end type hdf5_results_t

contains

   !> Create (or truncate) the file `path`, write the root attributes and the mesh group.
   subroutine results_create(self, path, mesh, title, deck_path, version, error)
      class(hdf5_results_t), intent(inout) :: self
      character(len=*), intent(in) :: path
      type(mesh_t), intent(in) :: mesh
      character(len=*), intent(in) :: title       !! the deck's title (header comment lines)
      character(len=*), intent(in) :: deck_path   !! the deck as given on the command line
      character(len=*), intent(in) :: version     !! frix version, e.g. '0.1.0'
      type(error_t), allocatable, intent(out) :: error

      if (self%created) then
         call fatal_error(error, 'HDF5: results file "'//self%file%file_path//'" is already open, cannot create "'// &
                          path//'"')
         return
      end if
      if (.not. (allocated(mesh%coords) .and. allocated(mesh%node_ids) .and. allocated(mesh%connectivity) &
                 .and. allocated(mesh%element_ids) .and. allocated(mesh%element_block))) then
         call fatal_error(error, 'HDF5 output: the mesh lacks coordinates, node ids, connectivity, element ids or blocks')
         return
      end if
      call create_file(path, self%file, error)
      if (allocated(error)) return
      self%n_nodes = mesh%n_nodes
      self%n_elements = mesh%n_elements
      self%n_increments = 0
      if (allocated(self%contact)) deallocate (self%contact)
      if (allocated(self%fields)) deallocate (self%fields)
      if (allocated(self%control)) deallocate (self%control)
      if (allocated(self%history_columns)) deallocate (self%history_columns)
      allocate (self%contact(0), self%fields(0), self%control(0), self%history_columns(0))

      call write_header(self%file, mesh, title, deck_path, version, error)
      if (.not. allocated(error)) call flush_file(self%file, error)
      call close_file(self%file, error)   ! keeps the first error
      self%created = .not. allocated(error)
   end subroutine results_create

   subroutine write_header(file, mesh, title, deck_path, version, error)
      type(hdf5_location_t), intent(in) :: file
      type(mesh_t), intent(in) :: mesh
      character(len=*), intent(in) :: title, deck_path, version
      type(error_t), allocatable, intent(out) :: error
      type(hdf5_location_t) :: group

      call write_attribute(file, 'frix_version', version, error)
      if (allocated(error)) return
      call write_attribute(file, 'deck_path', deck_path, error)
      if (allocated(error)) return
      call write_attribute(file, 'title', title, error)
      if (allocated(error)) return
      call write_attribute(file, 'layout_version', hdf5_layout_version, error)
      if (allocated(error)) return

      call create_group(file, 'mesh', group, error)
      if (allocated(error)) return
      call write_mesh(group, mesh, error)
      call close_group_after(group, error)
      if (allocated(error)) return
      call create_group(file, 'increments', group, error)
      if (allocated(error)) return
      call close_group(group, error)
   end subroutine write_header

   !> The datasets of /mesh and its set groups.
   subroutine write_mesh(group, mesh, error)
      type(hdf5_location_t), intent(in) :: group
      type(mesh_t), intent(in) :: mesh
      type(error_t), allocatable, intent(out) :: error
      integer :: e

      call write_dataset(group, 'coordinates', mesh%coords, error)
      if (allocated(error)) return
      call write_dataset(group, 'node_ids', mesh%node_ids, error)
      if (allocated(error)) return
      call write_dataset(group, 'connectivity', mesh%connectivity, error)
      if (allocated(error)) return
      call write_dataset(group, 'element_ids', mesh%element_ids, error)
      if (allocated(error)) return
      call write_dataset(group, 'element_block', mesh%element_block, error)
      if (allocated(error)) return
      if (.not. mesh%has_only_hex8()) then
         ! a mesh of other cells than HEX8 (a mesh of HEX8 only has no such dataset)
         call write_dataset(group, 'cell_types', [(mesh%cells(mesh%cell_of(e))%cell%vtk_type, e=1, mesh%n_elements)], &
                            error)
         if (allocated(error)) return
      end if
      call write_sets(group, mesh, error)
   end subroutine write_mesh

   !> The groups node_sets, element_sets and surfaces of /mesh, one entry per set.
   subroutine write_sets(group, mesh, error)
      type(hdf5_location_t), intent(in) :: group
      type(mesh_t), intent(in) :: mesh
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: group_names(3) = [character(len=12) :: 'node_sets', 'element_sets', 'surfaces']
      type(hdf5_location_t) :: sets
      integer :: kind, i
      do kind = 1, 3
         call create_group(group, trim(group_names(kind)), sets, error)
         if (allocated(error)) return
         do i = 1, set_count(mesh, kind)
            call write_set(sets, mesh, kind, i, error)
            if (allocated(error)) exit
         end do
         call close_group_after(sets, error)
         if (allocated(error)) return
      end do
   end subroutine write_sets

   !> Number of sets of a kind (1: node sets, 2: element sets, 3: surfaces) of the mesh.
   pure integer function set_count(mesh, kind)
      type(mesh_t), intent(in) :: mesh
      integer, intent(in) :: kind
      set_count = 0
      select case (kind)
      case (1)
         if (allocated(mesh%node_sets)) set_count = size(mesh%node_sets)
      case (2)
         if (allocated(mesh%element_sets)) set_count = size(mesh%element_sets)
      case default
         if (allocated(mesh%surfaces)) set_count = size(mesh%surfaces)
      end select
   end function set_count

   !> Set `i` of a kind (as in `set_count`) below `sets`: a dataset of its node or element
   !> numbers, or for a surface a group with the datasets elements and faces.
   subroutine write_set(sets, mesh, kind, i, error)
      type(hdf5_location_t), intent(in) :: sets
      type(mesh_t), intent(in) :: mesh
      integer, intent(in) :: kind, i
      type(error_t), allocatable, intent(out) :: error
      type(hdf5_location_t) :: surface
      select case (kind)
      case (1)
         call check_object_name(mesh%node_sets(i)%name, 'node set', error)
         if (.not. allocated(error)) call write_dataset(sets, mesh%node_sets(i)%name, mesh%node_sets(i)%nodes, error)
      case (2)
         call check_object_name(mesh%element_sets(i)%name, 'element set', error)
         if (.not. allocated(error)) &
            call write_dataset(sets, mesh%element_sets(i)%name, mesh%element_sets(i)%elements, error)
      case default
         call check_object_name(mesh%surfaces(i)%name, 'surface', error)
         if (allocated(error)) return
         call create_group(sets, mesh%surfaces(i)%name, surface, error)
         if (allocated(error)) return
         call write_dataset(surface, 'elements', mesh%surfaces(i)%elements, error)
         if (.not. allocated(error)) call write_dataset(surface, 'faces', mesh%surfaces(i)%faces, error)
         call close_group_after(surface, error)
      end select
   end subroutine write_set

   !> A set or array name must be usable as an HDF5 link name: not empty, not '.', no '/'.
   subroutine check_object_name(name, what, error)
      character(len=*), intent(in) :: name, what
      type(error_t), allocatable, intent(out) :: error
      if (len(name) == 0 .or. name == '.' .or. index(name, '/') > 0) &
         call fatal_error(error, 'HDF5 output: '//what//' name "'//name//'" cannot be an HDF5 name '// &
                          '(empty, "." or containing "/")')
   end subroutine check_object_name

   !> Number of increments written to the open file.
   pure integer function results_n_written(self)
      class(hdf5_results_t), intent(in) :: self
      results_n_written = self%n_increments
   end function results_n_written

   !> Add a real per-entity array values(n) (e.g. per slave node gap) to the `contact` group
   !> of the next increment; h5py shape (n).
   subroutine add_contact_real_1(self, name, values)
      class(hdf5_results_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: values(:)
      call append_reals(self%contact, name, reshape(values, [1, size(values)]), .true.)
   end subroutine add_contact_real_1

   !> Add a real array values(n_components, n) (e.g. per slave node traction (3, n)) to the
   !> `contact` group of the next increment; h5py shape (n, n_components).
   subroutine add_contact_real_2(self, name, values)
      class(hdf5_results_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: values(:, :)
      call append_reals(self%contact, name, values, .false.)
   end subroutine add_contact_real_2

   !> Add an integer array values(n) (e.g. slave node numbers, stick/slip status) to the
   !> `contact` group of the next increment; h5py shape (n).
   subroutine add_contact_integer_1(self, name, values)
      class(hdf5_results_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      integer, intent(in) :: values(:)
      type(named_array_t) :: item
      item%name = name
      item%integers = reshape(values, [1, size(values)])
      item%rank_one = .true.
      call append_item(self%contact, item)
   end subroutine add_contact_integer_1

   !> Add a named scalar per integration point, values(n_points, n_elements) (a material's
   !> history variable such as an equivalent plastic strain), to the `fields` group of the next
   !> increment; h5py shape (n_elements, n_points).
   subroutine add_point_field(self, name, values)
      class(hdf5_results_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: values(:, :)
      call append_reals(self%fields, name, values, .false.)
   end subroutine add_point_field

   !> Add a real array values(n_components, n) of the increment control (a restart's increment
   !> size, displacement rate) to the `control` group of the next increment; h5py shape
   !> (n, n_components), or (n) for one component.
   subroutine add_control_array(self, name, values)
      class(hdf5_results_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: values(:, :)
      call append_reals(self%control, name, values, size(values, 1) == 1)
   end subroutine add_control_array

   !> Add the value of a history column (RESULTS HISTORY, named by its CSV label) to the
   !> `history_columns` group of the next increment; h5py shape (1).
   subroutine add_history_value(self, name, value)
      class(hdf5_results_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: value
      call append_reals(self%history_columns, name, reshape([value], [1, 1]), .true.)
   end subroutine add_history_value

   !> A real array values(n_components, n) named `name` at the end of `items` (written as a
   !> 1-D dataset when `rank_one`).
   subroutine append_reals(items, name, values, rank_one)
      type(named_array_t), allocatable, intent(inout) :: items(:)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: values(:, :)
      logical, intent(in) :: rank_one
      type(named_array_t) :: item
      item%name = name
      item%reals = values
      item%rank_one = rank_one
      call append_item(items, item)
   end subroutine append_reals

   !> items = [items, item], moving item's arrays (an array constructor of this type would
   !> leak their copies with gfortran 12).
   subroutine append_item(items, item)
      type(named_array_t), allocatable, intent(inout) :: items(:)
      type(named_array_t), intent(inout) :: item
      type(named_array_t), allocatable :: grown(:)
      integer :: i, n
      if (.not. allocated(items)) allocate (items(0))
      n = size(items)
      allocate (grown(n + 1))
      do i = 1, n
         call move_alloc(items(i)%name, grown(i)%name)
         if (allocated(items(i)%reals)) call move_alloc(items(i)%reals, grown(i)%reals)
         if (allocated(items(i)%integers)) call move_alloc(items(i)%integers, grown(i)%integers)
         grown(i)%rank_one = items(i)%rank_one
      end do
      call move_alloc(item%name, grown(n + 1)%name)
      if (allocated(item%reals)) call move_alloc(item%reals, grown(n + 1)%reals)
      if (allocated(item%integers)) call move_alloc(item%integers, grown(n + 1)%integers)
      grown(n + 1)%rank_one = item%rank_one
      call move_alloc(grown, items)
   end subroutine append_item

   !> Write one converged increment as group /increments/<NNNNNN> and flush the file. The
   !> contact arrays added since the previous increment are written with it and then dropped.
   subroutine results_write_increment(self, step, increment, time, displacement, reaction, stress, strain, &
                                      alpha, history, error, total, reference)
      class(hdf5_results_t), intent(inout) :: self
      integer, intent(in) :: step, increment      !! step number and increment number within the step
      real(dp), intent(in) :: time                !! pseudo time (load factor) of the increment
      real(dp), intent(in) :: displacement(:, :)  !! (3, n_nodes) reported displacements
      real(dp), intent(in) :: reaction(:, :)      !! (3, n_nodes) reactions, zero at free DOFs
      real(dp), intent(in) :: stress(:, :, :)     !! (6, n_points, n_elements) Cauchy, frix Voigt
      real(dp), intent(in) :: strain(:, :, :)     !! (6, n_points, n_elements) engineering shears
      real(dp), intent(in) :: alpha(:, :)         !! (max EAS parameters, n_elements)
      real(dp), intent(in) :: history(:, :, :)    !! (n_state, n_points, n_elements)
      type(error_t), allocatable, intent(out) :: error
      !> (3, n_nodes) after a RESET_DISPLACEMENT step: the total displacements and their
      !> reference (displacement = total - reference), both or neither
      real(dp), intent(in), optional :: total(:, :), reference(:, :)
      type(hdf5_location_t) :: increments, group

      if (.not. self%created) then
         call fatal_error(error, 'HDF5 output: increment written before the results file was created')
         return
      end if
      call check_increment_shapes(self, displacement, reaction, stress, strain, alpha, history, error)
      if (allocated(error)) return
      if (present(total) .neqv. present(reference)) then
         call fatal_error(error, 'HDF5 output: the total displacements and their reference go together')
         return
      end if
      if (present(total)) then
         if (any(shape(total) /= shape(displacement)) .or. any(shape(reference) /= shape(displacement))) then
            call fatal_error(error, 'HDF5 output: the total displacements and their reference must be (3, '// &
                             to_string(self%n_nodes)//')')
            return
         end if
      end if

      call check_room(self%file, increment_bytes(self, displacement, stress, alpha, history, present(total)), &
                      'increment '//to_string(self%n_increments + 1), error)
      if (allocated(error)) return
      call open_for_writing(self%file%file_path, self%file, error)
      if (allocated(error)) return
      call open_group(self%file, 'increments', increments, error)
      if (allocated(error)) then
         call close_file(self%file, error)
         return
      end if
      call create_group(increments, increment_group_name(self%n_increments + 1), group, error)
      if (.not. allocated(error)) then
         call write_increment_group(self, group, step, increment, time, displacement, reaction, stress, strain, &
                                    alpha, history, error, total, reference)
         call close_group_after(group, error)
      end if
      call close_group_after(increments, error)
      if (.not. allocated(error)) then
         self%n_increments = self%n_increments + 1
         deallocate (self%contact, self%fields, self%control, self%history_columns)
         allocate (self%contact(0), self%fields(0), self%control(0), self%history_columns(0))
         call flush_file(self%file, error)
      end if
      call close_file(self%file, error)   ! keeps the first error
   end subroutine results_write_increment

   !> Bytes an increment adds to the file: its arrays and 64 KiB for HDF5's object headers,
   !> heaps and B-tree nodes (about 1 KiB per dataset).
   pure function increment_bytes(self, displacement, stress, alpha, history, with_total) result(bytes)
      type(hdf5_results_t), intent(in) :: self
      real(dp), intent(in) :: displacement(:, :), stress(:, :, :), alpha(:, :), history(:, :, :)
      logical, intent(in) :: with_total   !! total and reference displacements written too
      integer(c_long_long) :: bytes
      integer(c_long_long), parameter :: metadata = 65536
      integer :: i
      bytes = 8_c_long_long*(merge(4, 2, with_total)*size(displacement, kind=c_long_long) + &
                             2*size(stress, kind=c_long_long) + size(alpha, kind=c_long_long) + &
                             size(history, kind=c_long_long)) + metadata
      do i = 1, size(self%contact)
         bytes = bytes + item_bytes(self%contact(i))
      end do
      do i = 1, size(self%fields)
         bytes = bytes + item_bytes(self%fields(i))
      end do
      do i = 1, size(self%control)
         bytes = bytes + item_bytes(self%control(i))
      end do
      do i = 1, size(self%history_columns)
         bytes = bytes + item_bytes(self%history_columns(i))
      end do
   end function increment_bytes

   pure integer(c_long_long) function item_bytes(item)
      type(named_array_t), intent(in) :: item
      item_bytes = 0
      if (allocated(item%reals)) item_bytes = 8*size(item%reals, kind=c_long_long)
      if (allocated(item%integers)) item_bytes = 4*size(item%integers, kind=c_long_long)
   end function item_bytes

   subroutine check_increment_shapes(self, displacement, reaction, stress, strain, alpha, history, error)
      type(hdf5_results_t), intent(in) :: self
      real(dp), intent(in) :: displacement(:, :), reaction(:, :), stress(:, :, :), strain(:, :, :)
      real(dp), intent(in) :: alpha(:, :), history(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      if (any(shape(displacement) /= [3, self%n_nodes]) .or. any(shape(reaction) /= [3, self%n_nodes])) then
         call fatal_error(error, 'HDF5 output: displacement and reaction must be (3, '//to_string(self%n_nodes)//')')
      else if (size(stress, 1) /= 6 .or. size(stress, 3) /= self%n_elements .or. any(shape(strain) /= shape(stress))) then
         call fatal_error(error, 'HDF5 output: stress and strain must be (6, n_points, '//to_string(self%n_elements)//')')
      else if (size(alpha, 2) /= self%n_elements .or. size(history, 3) /= self%n_elements) then
         call fatal_error(error, 'HDF5 output: alpha and history must have '//to_string(self%n_elements)// &
                          ' elements in their last dimension')
      end if
      if (allocated(error)) return
      do i = 1, size(self%contact)
         call check_object_name(self%contact(i)%name, 'contact array', error)
         if (allocated(error)) return
      end do
      do i = 1, size(self%history_columns)
         call check_object_name(self%history_columns(i)%name, 'history column', error)
         if (allocated(error)) return
      end do
      do i = 1, size(self%fields)
         call check_object_name(self%fields(i)%name, 'field', error)
         if (allocated(error)) return
         if (size(self%fields(i)%reals, 2) /= self%n_elements) then
            call fatal_error(error, 'HDF5 output: field "'//self%fields(i)%name//'" must have '// &
                             to_string(self%n_elements)//' elements in its last dimension')
            return
         end if
      end do
   end subroutine check_increment_shapes

   subroutine write_increment_group(self, group, step, increment, time, displacement, reaction, stress, strain, &
                                    alpha, history, error, total, reference)
      type(hdf5_results_t), intent(in) :: self
      type(hdf5_location_t), intent(in) :: group
      integer, intent(in) :: step, increment
      real(dp), intent(in) :: time
      real(dp), intent(in) :: displacement(:, :), reaction(:, :), stress(:, :, :), strain(:, :, :)
      real(dp), intent(in) :: alpha(:, :), history(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      real(dp), intent(in), optional :: total(:, :), reference(:, :)

      call write_attribute(group, 'step', step, error)
      if (allocated(error)) return
      call write_attribute(group, 'increment', increment, error)
      if (allocated(error)) return
      call write_attribute(group, 'time', time, error)
      if (allocated(error)) return
      call write_dataset(group, 'displacement', displacement, error)
      if (allocated(error)) return
      if (present(total) .and. present(reference)) then
         call write_dataset(group, 'total_displacement', total, error)
         if (.not. allocated(error)) call write_dataset(group, 'reference_displacement', reference, error)
         if (allocated(error)) return
      end if
      call write_dataset(group, 'reaction', reaction, error)
      if (allocated(error)) return
      call write_dataset(group, 'stress', stress, error)
      if (allocated(error)) return
      call write_dataset(group, 'strain', strain, error)
      if (allocated(error)) return
      call write_dataset(group, 'alpha', alpha, error)
      if (allocated(error)) return
      call write_dataset(group, 'history', history, error)
      if (allocated(error)) return

      call write_named_arrays(group, 'contact', self%contact, error)
      if (allocated(error)) return
      call write_named_arrays(group, 'fields', self%fields, error)
      if (allocated(error)) return
      call write_named_arrays(group, 'control', self%control, error)
      if (allocated(error)) return
      call write_named_arrays(group, 'history_columns', self%history_columns, error)
      if (allocated(error)) return
      ! written last: readers ignore a group without it (a run stopped while writing it)
      call write_attribute(group, 'complete', 1, error)
   end subroutine write_increment_group

   !> The group `name` of an increment holding `items` (none: no group).
   subroutine write_named_arrays(increment, name, items, error)
      type(hdf5_location_t), intent(in) :: increment
      character(len=*), intent(in) :: name
      type(named_array_t), intent(in) :: items(:)
      type(error_t), allocatable, intent(out) :: error
      type(hdf5_location_t) :: group
      integer :: i
      if (size(items) == 0) return
      call create_group(increment, name, group, error)
      if (allocated(error)) return
      do i = 1, size(items)
         associate (item => items(i))
            if (allocated(item%reals)) then
               if (item%rank_one) then
                  call write_dataset(group, item%name, item%reals(1, :), error)
               else
                  call write_dataset(group, item%name, item%reals, error)
               end if
            else
               call write_dataset(group, item%name, item%integers(1, :), error)
            end if
         end associate
         if (allocated(error)) exit
      end do
      call close_group_after(group, error)
   end subroutine write_named_arrays

   !> Close the file if it is open (it is closed between increments) and end the writing.
   subroutine results_close(self, error)
      class(hdf5_results_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      call close_file(self%file, error)
      self%created = .false.
   end subroutine results_close
end module frix_hdf5_results
