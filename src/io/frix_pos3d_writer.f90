!> POS3D output: Tecgraf's (PUC-Rio) "neutral file", read by POS3D and MView; see docs/pos3d.md
!> (section "The format"; no public specification exists: the block
!> layout is the one independent public writers and readers agree on).
!>
!> One file per run holds the model (%HEADER, %NODE, %NODE.COORD, %MATERIAL,
!> %MATERIAL.ISOTROPIC, %ELEMENT, %ELEMENT.BRICK8) and one result step per converged increment
!> passed to `add_step` (%RESULT, %RESULT.CASE with the step list, then per step
!> %RESULT.CASE.STEP, .FACTOR, .NODAL.DISPLACEMENT, .NODAL.SCALAR(.DATA),
!> .ELEMENT.GAUSS.SCALAR(.DATA)), and %END.
!>
!> Crash safety: the step list sits before the steps, so the file is rewritten completely after
!> every step: the step blocks are appended to a body file `<path>.steps.tmp`; the model, the
!> step list, a copy of the body and %END are written to `<path>.tmp`, which is then renamed to
!> `<path>` (POSIX rename(2): atomic, so `<path>` is always a complete file of the steps written
!> so far). Each rewrite costs the size of the file, i.e. O(n_steps^2) step blocks in total.
!> `close` deletes the body file.
!>
!> Numbering: nodes and elements are numbered 1..n in frix's internal order (the format's ids
!> are 1-based and many readers need them consecutive); user ids are not written.
!>
!> BRICK8 node order (Tecgraf): nodes 1-4 on the face t = +1, counter-clockwise in (r, s)
!> seen from t > 0; nodes 5-8 on t = -1, node k+4 below node k. From frix/VTK order
!> (nodes 1-4 on zeta = -1, node a+4 above node a): Tecgraf node k = VTK node
!> `pos3d_brick8_from_vtk(k)` = (5, 6, 7, 8, 1, 2, 3, 4).
!> Gauss points: frix's point g sits beside VTK node g (at s_g / sqrt(3)); the file lists the
!> 8 points in the Tecgraf node order too: file point k = frix point pos3d_brick8_from_vtk(k),
!> i.e. file point k sits beside Tecgraf node k.
!>
!> Displacements: six values per node (u, v, w, then rotations 0). Nodal scalars: VON_MISES
!> always (von Mises of the stress extrapolated to the nodes and averaged over the elements,
!> `frix_field_recovery`, as in the VTK output), then the caller's fields. Gauss scalars: the
!> 6 stress components STRESS_XX YY ZZ XY XZ YZ (frix Voigt order, tensor shears).
!> Reals as es24.16e3 (17 significant digits: binary64 round-trips exactly). Units: the deck's.
module frix_pos3d_writer
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_mesh, only: mesh_t
   use frix_field_recovery, only: nodal_extrapolated, von_mises_field
   use frix_finite_check, only: first_non_finite
   use frix_text_output, only: real_edit, text_file_t
   use frix_hex8_cell, only: hex8_pos3d_name
   implicit none
   private

   public :: pos3d_writer_t, pos3d_brick8_from_vtk

   !> Tecgraf BRICK8 local node k (and Gauss point k) = frix/VTK local node (point) of this index.
   integer, parameter :: pos3d_brick8_from_vtk(8) = [5, 6, 7, 8, 1, 2, 3, 4]
   integer, parameter :: integration_order = 2              !! 2x2x2 Gauss, in the element records
   character(len=*), parameter :: stress_names = &
                                  "'STRESS_XX' 'STRESS_YY' 'STRESS_ZZ' 'STRESS_XY' 'STRESS_XZ' 'STRESS_YZ'"

   !> A neutral file being written. Usage: `open` (writes the model at once: a bad folder is
   !> reported there), `add_step` per converged increment (the file is complete after each),
   !> `close` (removes the temporary body file).
   type :: pos3d_writer_t
      private
      character(len=:), allocatable :: path            !! the neutral file
      character(len=:), allocatable :: title           !! one line, no single quote
      real(dp), allocatable :: coords(:, :)            !! (3, n_nodes) reference coordinates
      integer, allocatable :: connectivity(:, :)       !! (8, n_elements) frix/VTK order
      integer, allocatable :: element_material(:)      !! (n_elements) index into materials
      real(dp), allocatable :: materials(:, :)         !! (2, n_materials): Young's modulus E, Poisson's ratio nu
      real(dp), allocatable :: factors(:)              !! load factor of each step written
      logical :: is_open = .false.
   contains
      procedure :: open => writer_open
      procedure :: add_step
      procedure :: close => writer_close
      procedure :: n_steps
   end type pos3d_writer_t

contains

   !> Start the neutral file `path` (e.g. 'results/s1.pos') for `mesh` and write the model.
   !> Without `materials`, one dummy isotropic material (E = 1, nu = 0) is written for all
   !> elements; with it, `element_material` (required then) gives each element's column.
   subroutine writer_open(self, path, title, mesh, error, materials, element_material)
      class(pos3d_writer_t), intent(inout) :: self
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: title           !! free text for %HEADER (quotes and line breaks replaced)
      type(mesh_t), intent(in) :: mesh
      type(error_t), allocatable, intent(out) :: error
      real(dp), intent(in), optional :: materials(:, :)     !! (2, n_materials): E, nu
      integer, intent(in), optional :: element_material(:)  !! (n_elements) column of `materials`
      type(text_file_t) :: file

      self%is_open = .false.
      if (.not. (allocated(mesh%coords) .and. allocated(mesh%connectivity))) then
         call fatal_error(error, 'POS3D output: the mesh lacks coordinates or connectivity')
         return
      end if
      if (.not. mesh%has_only_hex8()) then
         call fatal_error(error, 'POS3D output: frix writes BRICK8 (HEX8) elements only, the mesh has others '// &
                          '(write VTK or HDF5 instead)')
         return
      end if
      if (size(mesh%coords, 1) /= 3 .or. size(mesh%coords, 2) /= mesh%n_nodes .or. &
          size(mesh%connectivity, 1) /= 8 .or. size(mesh%connectivity, 2) /= mesh%n_elements) then
         call fatal_error(error, 'POS3D output: mesh arrays do not match n_nodes = '//to_string(mesh%n_nodes)// &
                          ', n_elements = '//to_string(mesh%n_elements)//' with 8 nodes per element')
         return
      end if
      if (present(materials)) then
         if (.not. present(element_material)) then
            call fatal_error(error, 'POS3D output: materials given without the element material indices')
            return
         end if
         if (size(materials, 1) /= 2 .or. size(materials, 2) < 1) then
            call fatal_error(error, 'POS3D output: materials must be (2, n_materials >= 1): E, nu')
            return
         end if
         if (size(element_material) /= mesh%n_elements) then
            call fatal_error(error, 'POS3D output: element_material has '//to_string(size(element_material))// &
                             ' entries, the mesh '//to_string(mesh%n_elements)//' elements')
            return
         end if
         if (any(element_material < 1 .or. element_material > size(materials, 2))) then
            call fatal_error(error, 'POS3D output: element material index outside 1..'//to_string(size(materials, 2)))
            return
         end if
         if (first_non_finite(reshape(materials, [size(materials)])) > 0) then
            call fatal_error(error, 'POS3D output: the material block''s E or nu of material number '// &
                             to_string((first_non_finite(reshape(materials, [size(materials)])) + 1)/2)// &
                             ' (in deck order) is not finite (beyond the range of real numbers)')
            return
         end if
         self%materials = materials
         self%element_material = element_material
      else
         self%materials = reshape([1.0_dp, 0.0_dp], [2, 1])
         self%element_material = spread(1, 1, mesh%n_elements)
      end if

      self%path = path
      self%title = trim(one_line(title))
      self%coords = mesh%coords
      self%connectivity = mesh%connectivity
      self%factors = [real(dp) ::]

      call file%open(body_path(self), 'POS3D body file "'//body_path(self)//'"', error)
      if (allocated(error)) return
      call file%close(error)
      if (allocated(error)) return
      self%is_open = .true.
      call rewrite(self, error)
   end subroutine writer_open

   !> Number of steps written so far.
   pure integer function n_steps(self)
      class(pos3d_writer_t), intent(in) :: self
      n_steps = 0
      if (allocated(self%factors)) n_steps = size(self%factors)
   end function n_steps

   !> Append one result step (a converged increment) and rewrite the file.
   subroutine add_step(self, time, displacement, gp_stress, nodal_scalar_names, nodal_scalars, error)
      class(pos3d_writer_t), intent(inout) :: self
      real(dp), intent(in) :: time                         !! load factor / pseudo time, written as the step FACTOR
      real(dp), intent(in) :: displacement(:, :)           !! (3, n_nodes)
      real(dp), intent(in) :: gp_stress(:, :, :)           !! (6, 8, n_elements) Cauchy stress, frix Voigt, frix point order
      character(len=*), intent(in) :: nodal_scalar_names(:)  !! names of the caller's nodal scalars (no quotes, not blank)
      real(dp), intent(in) :: nodal_scalars(:, :)          !! (size(nodal_scalar_names), n_nodes)
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: node_stress(:, :), node_von_mises(:)
      character(len=:), allocatable :: line_format
      character(len=:), allocatable :: line
      type(text_file_t) :: file
      integer :: n_nodes, n_elements, node, element, k, step, n_names

      if (.not. self%is_open) then
         call fatal_error(error, 'POS3D output: step added before open or after close')
         return
      end if
      n_nodes = size(self%coords, 2)
      n_elements = size(self%connectivity, 2)
      n_names = size(nodal_scalar_names)
      if (any(shape(displacement) /= [3, n_nodes])) then
         call fatal_error(error, 'POS3D output: displacement must be (3, '//to_string(n_nodes)//')')
      else if (any(shape(gp_stress) /= [6, 8, n_elements])) then
         call fatal_error(error, 'POS3D output: gp_stress must be (6, 8, '//to_string(n_elements)//')')
      else if (any(shape(nodal_scalars) /= [n_names, n_nodes]) .and. .not. (n_names == 0 .and. size(nodal_scalars) == 0)) then
         call fatal_error(error, 'POS3D output: nodal_scalars must be ('//to_string(n_names)//', '//to_string(n_nodes)//')')
      end if
      if (allocated(error)) return
      do k = 1, n_names
         if (len_trim(nodal_scalar_names(k)) == 0 .or. index(nodal_scalar_names(k), "'") > 0) then
            call fatal_error(error, 'POS3D output: nodal scalar name '//to_string(k)//' is blank or contains a quote')
            return
         end if
      end do

      allocate (node_stress(6, n_nodes))
      call nodal_extrapolated(self%connectivity, gp_stress, node_stress, error)
      if (allocated(error)) return
      node_von_mises = von_mises_field(node_stress)

      step = size(self%factors) + 1
      call file%open(body_path(self), 'POS3D body file "'//body_path(self)//'"', error, append=.true.)
      if (allocated(error)) return
      call file%put('%RESULT.CASE.STEP')
      call file%put(to_string(step))
      call file%put('%RESULT.CASE.STEP.FACTOR')
      call put_real_row(file, [time])
      call file%put('%RESULT.CASE.STEP.NODAL.DISPLACEMENT')
      call file%put(to_string(n_nodes)//" 'displacement'")
      do node = 1, n_nodes
         call put_real_row(file, [displacement(:, node), 0.0_dp, 0.0_dp, 0.0_dp], node)
      end do
      call file%put('%RESULT.CASE.STEP.NODAL.SCALAR')
      call file%put(to_string(n_names + 1))
      call file%put(quoted_names(nodal_scalar_names))
      call file%put('%RESULT.CASE.STEP.NODAL.SCALAR.DATA')
      call file%put(to_string(n_nodes))
      line_format = '(i0,'//to_string(n_names + 1)//'(1x,'//real_edit//'))'
      allocate (character(len=12 + 25*(n_names + 1)) :: line)
      do node = 1, n_nodes
         if (file%failed()) exit
         if (n_names > 0) then
            write (line, line_format) node, node_von_mises(node), nodal_scalars(:, node)
         else
            write (line, line_format) node, node_von_mises(node)
         end if
         call file%put(trim(line))
      end do
      call file%put('%RESULT.CASE.STEP.ELEMENT.GAUSS.SCALAR')
      call file%put('6')
      call file%put(stress_names)
      call file%put('%RESULT.CASE.STEP.ELEMENT.GAUSS.SCALAR.DATA')
      call file%put(to_string(n_elements))
      do element = 1, n_elements
         call file%put(to_string(element))
         call file%put('8')
         do k = 1, 8
            call put_real_row(file, gp_stress(:, pos3d_brick8_from_vtk(k), element))
         end do
      end do
      call file%close(error)
      if (allocated(error)) return
      self%factors = [self%factors, time]
      call rewrite(self, error)
   end subroutine add_step

   !> Finish: the file is already complete; remove the body file.
   subroutine writer_close(self, error)
      class(pos3d_writer_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      integer :: unit, stat
      if (.not. self%is_open) return
      self%is_open = .false.
      open (newunit=unit, file=body_path(self), status='old', iostat=stat)
      if (stat == 0) close (unit, status='delete', iostat=stat)
      if (stat /= 0) call fatal_error(error, 'cannot delete POS3D body file "'//body_path(self)//'"')
   end subroutine writer_close

   !> Write model, step list, body and %END as a replacement of `<path>` (written to
   !> `<path>.tmp`, renamed to `<path>` when complete).
   subroutine rewrite(self, error)
      type(pos3d_writer_t), intent(in) :: self
      type(error_t), allocatable, intent(out) :: error
      character(len=11*12) :: line
      type(text_file_t) :: file
      type(error_t), allocatable :: ignored
      integer :: node, element, material, step, n_nodes, n_elements

      n_nodes = size(self%coords, 2)
      n_elements = size(self%connectivity, 2)
      call file%open(self%path, 'POS3D file "'//self%path//'"', error, replacement=.true.)
      if (allocated(error)) return
      call file%put('%HEADER')
      call file%put("'"//self%title//"'")
      call file%put('%NODE')
      call file%put(to_string(n_nodes))
      call file%put('%NODE.COORD')
      call file%put(to_string(n_nodes))
      do node = 1, n_nodes
         call put_real_row(file, self%coords(:, node), node)
      end do
      call file%put('%MATERIAL')
      call file%put(to_string(size(self%materials, 2)))
      call file%put('%MATERIAL.ISOTROPIC')
      call file%put(to_string(size(self%materials, 2)))
      do material = 1, size(self%materials, 2)
         call put_real_row(file, self%materials(:, material), material)
      end do
      call file%put('%ELEMENT')
      call file%put(to_string(n_elements))
      call file%put('%ELEMENT.'//hex8_pos3d_name)
      call file%put(to_string(n_elements))
      do element = 1, n_elements
         if (file%failed()) exit
         write (line, '(i0,1x,i0,1x,i0,8(1x,i0))') element, self%element_material(element), &
            integration_order, self%connectivity(pos3d_brick8_from_vtk, element)
         call file%put(trim(line))
      end do
      if (size(self%factors) > 0) then
         call file%put('%RESULT')
         call file%put('1')
         call file%put("1 'frix'")
         call file%put('%RESULT.CASE')
         call file%put('1 '//to_string(size(self%factors)))
         do step = 1, size(self%factors)
            call file%put(to_string(step)//" 'step"//to_string(step)//"'")
         end do
         if (.not. file%failed()) call copy_body(self, file, error)
      end if
      call file%put('%END')
      if (allocated(error)) then
         call file%close(ignored, discard=.true.)
         return
      end if
      call file%close(error)
   end subroutine rewrite

   !> Copy the body file line by line into `file`.
   subroutine copy_body(self, file, error)
      type(pos3d_writer_t), intent(in) :: self
      type(text_file_t), intent(inout) :: file
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: line
      character(len=256) :: message
      integer :: body, read_stat
      open (newunit=body, file=body_path(self), status='old', action='read', iostat=read_stat, iomsg=message)
      if (read_stat /= 0) then
         call fatal_error(error, 'cannot read POS3D body file "'//body_path(self)//'": '//trim(message))
         return
      end if
      do
         call read_line(body, line, read_stat)
         if (read_stat /= 0) exit
         call file%put(line)
         if (file%failed()) exit
      end do
      close (body)
      if (.not. is_iostat_end(read_stat) .and. read_stat /= 0) then
         call fatal_error(error, 'cannot read POS3D body file "'//body_path(self)//'" (iostat '//to_string(read_stat)//')')
      end if
   end subroutine copy_body

   !> One whole line of any length (non-advancing reads in chunks).
   subroutine read_line(unit, line, stat)
      integer, intent(in) :: unit
      character(len=:), allocatable, intent(out) :: line
      integer, intent(out) :: stat
      character(len=512) :: chunk
      integer :: n_read
      line = ''
      do
         read (unit, '(a)', advance='no', iostat=stat, size=n_read) chunk
         line = line//chunk(:n_read)
         if (stat /= 0) exit
      end do
      if (is_iostat_eor(stat)) stat = 0
   end subroutine read_line

   pure function body_path(self) result(path)
      type(pos3d_writer_t), intent(in) :: self
      character(len=:), allocatable :: path
      path = self%path//'.steps.tmp'
   end function body_path

   !> 'VON_MISES' followed by the caller's names, each in single quotes.
   pure function quoted_names(names) result(text)
      character(len=*), intent(in) :: names(:)
      character(len=:), allocatable :: text
      integer :: k
      text = "'VON_MISES'"
      do k = 1, size(names)
         text = text//" '"//trim(adjustl(names(k)))//"'"
      end do
   end function quoted_names

   !> `text` with single quotes turned into double quotes and line breaks into blanks.
   pure function one_line(text) result(line)
      character(len=*), intent(in) :: text
      character(len=len(text)) :: line
      integer :: i
      line = text
      do i = 1, len(line)
         if (line(i:i) == "'") line(i:i) = '"'
         if (line(i:i) == new_line('a') .or. line(i:i) == achar(13)) line(i:i) = ' '
      end do
   end function one_line

   !> A row of reals, preceded by the id `id` when present.
   subroutine put_real_row(file, values, id)
      type(text_file_t), intent(inout) :: file
      real(dp), intent(in) :: values(:)
      integer, intent(in), optional :: id
      character(len=12 + 25*size(values)) :: line
      if (file%failed()) return
      if (present(id)) then
         write (line, '(i0,'//to_string(size(values))//'(1x,'//real_edit//'))') id, values
      else
         write (line, '('//to_string(size(values))//'(1x,'//real_edit//'))') values
      end if
      call file%put(trim(line))
   end subroutine put_real_row
end module frix_pos3d_writer
