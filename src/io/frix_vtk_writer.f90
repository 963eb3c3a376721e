!> ParaView output: one VTK XML UnstructuredGrid file (`.vtu`, ASCII) per converged increment
!> and a ParaView collection (`.pvd`) listing them with their pseudo time.
!>
!> Files: `<base>_<step>_<increment>.vtu` (step and increment zero-padded to 4 digits, more if
!> needed) and `<base>.pvd`. The `.pvd` is rewritten after every increment so that a run that
!> stops early still leaves a valid collection of the increments written so far; it names the
!> `.vtu` files relative to its own folder. Format reference: "VTK File Formats", VTK User's
!> Guide (Kitware), section "XML File Formats"; ParaView reads `.pvd` as a time series.
!>
!> Each `.vtu` holds the reference coordinates as Points, HEX8 cells (the cell's VTK code, 12,
!> frix_mesh node order = VTK order, 0-based connectivity) and
!>   PointData: displacement (3), reaction (3), stress (6), strain (6), von_mises (1),
!>              then the extra point fields added since the last increment;
!>   CellData:  stress (6), strain (6), von_mises (1), element_id (user ids), block,
!>              then the extra cell fields;
!>   FieldData: TimeValue, step, increment.
!> Tensors are written in VTK's symmetric-tensor order XX, YY, ZZ, XY, YZ, XZ (frix Voigt order
!> is xx yy zz xy xz yz: components 5 and 6 are swapped), with tensor shears: the strain's
!> engineering shears (gamma = 2 eps) are halved so that ParaView's eigenvalue/"von Mises"
!> filters see the true tensor. Nodal tensors come from `frix_field_recovery`
!> (`nodal_extrapolated` when the arrays hold every point of each element's cell,
!> `nodal_average` otherwise); cell tensors are the
!> point means; von_mises is computed from those recovered stresses.
!> Numbers are written as es24.16e3 (17 significant digits: binary64 round-trips exactly).
module frix_vtk_writer
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string, zero_padded
   use frix_mesh, only: mesh_t
   use frix_hex8_cell, only: hex8_vtk_type
   use frix_cell_registry, only: cell_entry_t, cell_table
   use frix_field_recovery, only: cell_average, nodal_average, nodal_extrapolated, von_mises_field
   use frix_text_output, only: real_edit, text_file_t
   implicit none
   private

   public :: vtk_series_t


   !> A named field: values(n_components, n_nodes or n_elements).
   type :: named_field_t
      character(len=:), allocatable :: name
      real(dp), allocatable :: values(:, :)
   end type named_field_t

   !> One written increment, as listed in the `.pvd`.
   type :: dataset_entry_t
      character(len=:), allocatable :: file_name   !! relative to the folder of the .pvd
      real(dp) :: time = 0.0_dp
   end type dataset_entry_t

   !> A series of `.vtu` files and their `.pvd` collection. Usage: `call series%open(base,
   !> error)`; per converged increment, optionally `add_point_field`/`add_cell_field`, then
   !> `write_increment`. Extra fields are written with the next increment and then dropped.
   type :: vtk_series_t
      private
      character(len=:), allocatable :: base               !! path prefix of every file
      type(dataset_entry_t), allocatable :: datasets(:)
      type(named_field_t), allocatable :: point_fields(:)
      type(named_field_t), allocatable :: cell_fields(:)
   contains
      procedure :: open => series_open
      procedure :: add_point_field
      procedure :: add_cell_field
      procedure :: write_increment
      procedure :: n_written
   end type vtk_series_t

contains

   !> Start a series whose files begin with `base` (e.g. 'results/s1'); writes an empty `.pvd`
   !> so that a missing or read-only folder is reported at once.
   subroutine series_open(self, base, error)
      class(vtk_series_t), intent(inout) :: self
      character(len=*), intent(in) :: base
      type(error_t), allocatable, intent(out) :: error
      self%base = base
      allocate (self%datasets(0), self%point_fields(0), self%cell_fields(0))
      call write_collection(self, error)
   end subroutine series_open

   !> Number of increments written so far.
   pure integer function n_written(self)
      class(vtk_series_t), intent(in) :: self
      n_written = 0
      if (allocated(self%datasets)) n_written = size(self%datasets)
   end function n_written

   !> Add a nodal field (values(n_components, n_nodes), 1 = scalar, 3 = vector) to the next
   !> increment. The size is checked against the mesh in `write_increment`.
   subroutine add_point_field(self, name, values)
      class(vtk_series_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: values(:, :)
      call append_field(self%point_fields, name, values)
   end subroutine add_point_field

   !> Add an element field (values(n_components, n_elements)) to the next increment.
   subroutine add_cell_field(self, name, values)
      class(vtk_series_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: values(:, :)
      call append_field(self%cell_fields, name, values)
   end subroutine add_cell_field

   !> `fields` with (name, values) appended. The entries move into a longer array (move_alloc)
   !> instead of `fields = [fields, named_field_t(name, values)]`: gfortran 12 leaks the
   !> allocatable components of a structure constructor inside an array constructor.
   subroutine append_field(fields, name, values)
      type(named_field_t), allocatable, intent(inout) :: fields(:)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: values(:, :)
      type(named_field_t), allocatable :: grown(:)
      integer :: i, n
      n = 0
      if (allocated(fields)) n = size(fields)
      allocate (grown(n + 1))
      do i = 1, n
         call move_alloc(fields(i)%name, grown(i)%name)
         call move_alloc(fields(i)%values, grown(i)%values)
      end do
      grown(n + 1)%name = name
      grown(n + 1)%values = values
      call move_alloc(grown, fields)
   end subroutine append_field

   !> `datasets` with (file_name, time) appended (moved, as in append_field).
   subroutine append_dataset(datasets, file_name, time)
      type(dataset_entry_t), allocatable, intent(inout) :: datasets(:)
      character(len=*), intent(in) :: file_name
      real(dp), intent(in) :: time
      type(dataset_entry_t), allocatable :: grown(:)
      integer :: i, n
      n = 0
      if (allocated(datasets)) n = size(datasets)
      allocate (grown(n + 1))
      do i = 1, n
         call move_alloc(datasets(i)%file_name, grown(i)%file_name)
         grown(i)%time = datasets(i)%time
      end do
      grown(n + 1)%file_name = file_name
      grown(n + 1)%time = time
      call move_alloc(grown, datasets)
   end subroutine append_dataset

   !> Write `<base>_<step>_<increment>.vtu` for one converged increment and rewrite the `.pvd`.
   subroutine write_increment(self, mesh, step, increment, time, displacement, reaction, stress, strain, error)
      class(vtk_series_t), intent(inout) :: self
      type(mesh_t), intent(in) :: mesh
      integer, intent(in) :: step, increment
      real(dp), intent(in) :: time                  !! load factor / pseudo time of the increment
      real(dp), intent(in) :: displacement(:, :)    !! (3, n_nodes)
      real(dp), intent(in) :: reaction(:, :)        !! (3, n_nodes), zero at free DOFs
      real(dp), intent(in) :: stress(:, :, :)       !! (6, n_points, n_elements) Cauchy stress, frix Voigt
      real(dp), intent(in) :: strain(:, :, :)       !! (6, n_points, n_elements) frix Voigt, engineering shears
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: node_stress(:, :), node_strain(:, :), cell_stress(:, :), cell_strain(:, :)
      character(len=:), allocatable :: file_name, path
      type(text_file_t) :: file
      integer :: i

      call check_sizes(self, mesh, displacement, reaction, stress, strain, error)
      if (allocated(error)) return
      allocate (node_stress(6, mesh%n_nodes), node_strain(6, mesh%n_nodes))
      allocate (cell_stress(6, mesh%n_elements), cell_strain(6, mesh%n_elements))
      call recover(mesh, stress, node_stress, cell_stress, error)
      if (allocated(error)) return
      call recover(mesh, strain, node_strain, cell_strain, error)
      if (allocated(error)) return

      file_name = base_name(self%base)//'_'//zero_padded(step, 4)//'_'//zero_padded(increment, 4)//'.vtu'
      path = self%base//'_'//zero_padded(step, 4)//'_'//zero_padded(increment, 4)//'.vtu'
      call file%open(path, 'VTK file "'//path//'"', error, replacement=.true.)   ! no partial .vtu
      if (allocated(error)) return
      call file%put('<?xml version="1.0"?>')
      call file%put('<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian" header_type="UInt64">')
      call file%put('<UnstructuredGrid>')
      call file%put('<FieldData>')
      call put_reals(file, 'TimeValue', reshape([time], [1, 1]), field_data=.true.)
      call put_integers(file, 'step', 'Int32', [step], field_data=.true.)
      call put_integers(file, 'increment', 'Int32', [increment], field_data=.true.)
      call file%put('</FieldData>')
      call file%put('<Piece NumberOfPoints="'//to_string(mesh%n_nodes)//'" NumberOfCells="'// &
               to_string(mesh%n_elements)//'">')

      call file%put('<PointData Vectors="displacement" Tensors="stress" Scalars="von_mises">')
      call put_reals(file, 'displacement', displacement)
      call put_reals(file, 'reaction', reaction)
      call put_reals(file, 'stress', vtk_tensor_order(node_stress, 1.0_dp))
      call put_reals(file, 'strain', vtk_tensor_order(node_strain, 0.5_dp))
      call put_reals(file, 'von_mises', reshape(von_mises_field(node_stress), [1, mesh%n_nodes]))
      do i = 1, size(self%point_fields)
         call put_reals(file, self%point_fields(i)%name, self%point_fields(i)%values)
      end do
      call file%put('</PointData>')

      call file%put('<CellData Tensors="stress" Scalars="von_mises">')
      call put_reals(file, 'stress', vtk_tensor_order(cell_stress, 1.0_dp))
      call put_reals(file, 'strain', vtk_tensor_order(cell_strain, 0.5_dp))
      call put_reals(file, 'von_mises', reshape(von_mises_field(cell_stress), [1, mesh%n_elements]))
      call put_integers(file, 'element_id', 'Int32', mesh%element_ids)
      call put_integers(file, 'block', 'Int32', mesh%element_block)
      do i = 1, size(self%cell_fields)
         call put_reals(file, self%cell_fields(i)%name, self%cell_fields(i)%values)
      end do
      call file%put('</CellData>')

      call file%put('<Points>')
      call put_reals(file, 'coordinates', mesh%coords)
      call file%put('</Points>')
      call file%put('<Cells>')
      if (mesh%has_only_hex8()) then
         call put_integers(file, 'connectivity', 'Int64', reshape(mesh%connectivity - 1, [8*mesh%n_elements]), per_line=8)
         call put_integers(file, 'offsets', 'Int64', [(8*i, i=1, mesh%n_elements)])
         call put_integers(file, 'types', 'UInt8', [(hex8_vtk_type, i=1, mesh%n_elements)])
      else
         ! each element its own cell's nodes and VTK code
         call put_integers(file, 'connectivity', 'Int64', [(mesh%element_nodes(i) - 1, i=1, mesh%n_elements)], per_line=8)
         call put_integers(file, 'offsets', 'Int64', cumulative([(mesh%node_count(i), i=1, mesh%n_elements)]))
         call put_integers(file, 'types', 'UInt8', [(mesh%cells(mesh%cell_of(i))%cell%vtk_type, i=1, mesh%n_elements)])
      end if
      call file%put('</Cells>')
      call file%put('</Piece>')
      call file%put('</UnstructuredGrid>')
      call file%put('</VTKFile>')
      call file%close(error)
      if (allocated(error)) return

      call append_dataset(self%datasets, file_name, time)
      deallocate (self%point_fields, self%cell_fields)
      allocate (self%point_fields(0), self%cell_fields(0))
      call write_collection(self, error)
   end subroutine write_increment

   subroutine check_sizes(self, mesh, displacement, reaction, stress, strain, error)
      type(vtk_series_t), intent(in) :: self
      type(mesh_t), intent(in) :: mesh
      real(dp), intent(in) :: displacement(:, :), reaction(:, :), stress(:, :, :), strain(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      if (.not. allocated(self%base)) then
         call fatal_error(error, 'VTK series written before it was opened')
      else if (any(shape(displacement) /= [3, mesh%n_nodes]) .or. any(shape(reaction) /= [3, mesh%n_nodes])) then
         call fatal_error(error, 'VTK output: displacement and reaction must be (3, '//to_string(mesh%n_nodes)//')')
      else if (.not. (allocated(mesh%element_ids) .and. allocated(mesh%element_block) .and. allocated(mesh%coords) &
                      .and. allocated(mesh%connectivity))) then
         call fatal_error(error, 'VTK output: the mesh lacks coordinates, connectivity, element ids or blocks')
      else if (size(stress, 1) /= 6 .or. size(stress, 3) /= mesh%n_elements .or. any(shape(strain) /= shape(stress))) then
         call fatal_error(error, 'VTK output: stress and strain must be (6, n_points, '//to_string(mesh%n_elements)//')')
      end if
      if (allocated(error)) return
      do i = 1, size(self%point_fields)
         if (size(self%point_fields(i)%values, 2) /= mesh%n_nodes) then
            call fatal_error(error, 'VTK output: point field "'//self%point_fields(i)%name//'" has '// &
                             to_string(size(self%point_fields(i)%values, 2))//' values, the mesh '// &
                             to_string(mesh%n_nodes)//' nodes')
            return
         end if
      end do
      do i = 1, size(self%cell_fields)
         if (size(self%cell_fields(i)%values, 2) /= mesh%n_elements) then
            call fatal_error(error, 'VTK output: cell field "'//self%cell_fields(i)%name//'" has '// &
                             to_string(size(self%cell_fields(i)%values, 2))//' values, the mesh '// &
                             to_string(mesh%n_elements)//' elements')
            return
         end if
      end do
   end subroutine check_sizes

   !> Nodal (extrapolated when `gp` has the points of every element's cell, else the element
   !> means) and cell values of a point field.
   subroutine recover(mesh, gp, nodal, cell, error)
      type(mesh_t), intent(in) :: mesh
      real(dp), intent(in) :: gp(:, :, :)
      real(dp), intent(out) :: nodal(:, :), cell(:, :)
      type(error_t), allocatable, intent(out) :: error
      call cell_average(gp, cell, mesh%cell_indices())
      if (size(gp, 2) >= most_points(mesh)) then
         call nodal_extrapolated(mesh%connectivity, gp, nodal, error, mesh%cell_indices())
      else
         call nodal_average(mesh%connectivity, gp, nodal, mesh%cell_indices())
      end if
   end subroutine recover

   !> The most integration points of the cells of the mesh's elements.
   integer function most_points(mesh)
      type(mesh_t), intent(in) :: mesh
      type(cell_entry_t), allocatable :: table(:)
      integer, allocatable :: cells(:)
      integer :: k
      table = cell_table()
      cells = mesh%cell_indices()
      most_points = 0
      do k = 1, size(table)
         if (any(cells == k)) most_points = max(most_points, table(k)%cell%n_points())
      end do
   end function most_points

   !> The running sums of `counts`.
   pure function cumulative(counts) result(sums)
      integer, intent(in) :: counts(:)
      integer :: sums(size(counts))
      integer :: i
      if (size(counts) == 0) return
      sums(1) = counts(1)
      do i = 2, size(counts)
         sums(i) = sums(i - 1) + counts(i)
      end do
   end function cumulative

   !> frix Voigt (xx yy zz xy xz yz) to VTK symmetric tensor order (XX YY ZZ XY YZ XZ), the
   !> shears multiplied by `shear_factor` (1 for stress, 1/2 for engineering strains).
   pure function vtk_tensor_order(voigt, shear_factor) result(tensor)
      real(dp), intent(in) :: voigt(:, :)
      real(dp), intent(in) :: shear_factor
      real(dp) :: tensor(6, size(voigt, 2))
      tensor(1:3, :) = voigt(1:3, :)
      tensor(4, :) = shear_factor*voigt(4, :)
      tensor(5, :) = shear_factor*voigt(6, :)
      tensor(6, :) = shear_factor*voigt(5, :)
   end function vtk_tensor_order

   !> Rewrite `<base>.pvd` listing every dataset written so far (as a replacement: a failed
   !> write leaves the previous collection).
   subroutine write_collection(self, error)
      type(vtk_series_t), intent(in) :: self
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: path
      character(len=24) :: time_text
      type(text_file_t) :: file
      integer :: i
      path = self%base//'.pvd'
      call file%open(path, 'ParaView collection "'//path//'"', error, replacement=.true.)
      if (allocated(error)) return
      call file%put('<?xml version="1.0"?>')
      call file%put('<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">')
      call file%put('<Collection>')
      do i = 1, size(self%datasets)
         write (time_text, '('//real_edit//')') self%datasets(i)%time
         call file%put('<DataSet timestep="'//trim(adjustl(time_text))//'" group="" part="0" file="'// &
                  self%datasets(i)%file_name//'"/>')
      end do
      call file%put('</Collection>')
      call file%put('</VTKFile>')
      call file%close(error)
   end subroutine write_collection

   !> A Float64 DataArray, one tuple (column of `values`) per line.
   subroutine put_reals(file, name, values, field_data)
      type(text_file_t), intent(inout) :: file
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: values(:, :)          !! (n_components, n_tuples)
      logical, intent(in), optional :: field_data   !! FieldData arrays carry NumberOfTuples
      character(len=:), allocatable :: line_format
      character(len=25*size(values, 1)) :: line
      integer :: i
      line_format = '('//to_string(size(values, 1))//'(1x,'//real_edit//'))'
      if (is_true(field_data)) then
         call file%put('<DataArray type="Float64" Name="'//name//'" NumberOfTuples="'// &
                  to_string(size(values, 2))//'" format="ascii">')
      else
         call file%put('<DataArray type="Float64" Name="'//name//'" NumberOfComponents="'// &
                  to_string(size(values, 1))//'" format="ascii">')
      end if
      do i = 1, size(values, 2)
         if (file%failed()) return
         write (line, line_format) values(:, i)
         call file%put(line)
      end do
      call file%put('</DataArray>')
   end subroutine put_reals

   !> An integer DataArray of VTK type `vtk_type` (Int32, Int64, UInt8), `per_line` values per line.
   subroutine put_integers(file, name, vtk_type, values, per_line, field_data)
      type(text_file_t), intent(inout) :: file
      character(len=*), intent(in) :: name, vtk_type
      integer, intent(in) :: values(:)
      integer, intent(in), optional :: per_line
      logical, intent(in), optional :: field_data
      character(len=:), allocatable :: line
      integer :: first, last, chunk
      chunk = 10
      if (present(per_line)) chunk = per_line
      allocate (character(len=12*chunk) :: line)
      if (is_true(field_data)) then
         call file%put('<DataArray type="'//vtk_type//'" Name="'//name//'" NumberOfTuples="'// &
                  to_string(size(values))//'" format="ascii">')
      else
         call file%put('<DataArray type="'//vtk_type//'" Name="'//name//'" format="ascii">')
      end if
      do first = 1, size(values), chunk
         if (file%failed()) return
         last = min(first + chunk - 1, size(values))
         write (line, '(*(1x,i0))') values(first:last)
         call file%put(trim(line))
      end do
      call file%put('</DataArray>')
   end subroutine put_integers

   !> An optional flag, false when absent.
   pure logical function is_true(flag)
      logical, intent(in), optional :: flag
      is_true = .false.
      if (present(flag)) is_true = flag
   end function is_true

   !> The part of `path` after its last '/'.
   pure function base_name(path) result(name)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: name
      name = path(index(path, '/', back=.true.) + 1:)
   end function base_name
end module frix_vtk_writer
