!> History of selected nodal DOFs: a CSV file `<base>_history.csv` with a header
!> `step,increment,time,<label>...` and one row per converged increment.
!> A request is a (user node id, DOF) pair; DOF codes 1..3 = displacement UX, UY, UZ and
!> 4..6 = reaction RX, RY, RZ (force the supports exert on the body, zero at a free DOF).
!> Column label: 'u' or 'r', the direction 1..3, '_n', the user node id: `u3_n31` is the
!> z displacement of node 31, `r1_n5` the x reaction of node 5.
!> Numbers: integers as i0, reals as es24.16e3 without padding (exact binary64 round trip).
!> Open with any CSV reader, e.g. `numpy.genfromtxt(path, delimiter=',', names=True)`.
module frix_history_writer
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error, append_error
   use frix_strings, only: to_string, to_upper
   use frix_mesh, only: mesh_t
   use frix_text_output, only: text_file_t
   implicit none
   private

   public :: history_t, history_dof_code, history_label
   public :: history_ux, history_uy, history_uz, history_rx, history_ry, history_rz

   integer, parameter :: history_ux = 1, history_uy = 2, history_uz = 3  !! displacement components
   integer, parameter :: history_rx = 4, history_ry = 5, history_rz = 6  !! reaction components
   character(len=2), parameter :: dof_names(6) = ['UX', 'UY', 'UZ', 'RX', 'RY', 'RZ']

   type :: history_t
      private
      type(text_file_t) :: file
      integer, allocatable :: nodes(:)   !! internal node number of each column
      integer, allocatable :: dofs(:)    !! DOF code 1..6 of each column
   contains
      procedure :: open => history_open
      procedure :: append => history_append
      procedure :: close => history_close
      procedure :: is_open => history_is_open
   end type history_t

contains

   !> DOF code 1..6 of 'UX', 'UY', 'UZ', 'RX', 'RY', 'RZ' (any case); 0 if none of these.
   pure integer function history_dof_code(name) result(code)
      character(len=*), intent(in) :: name
      integer :: i
      code = 0
      do i = 1, size(dof_names)
         if (to_upper(trim(adjustl(name))) == dof_names(i)) code = i
      end do
   end function history_dof_code

   !> Column label of a request, e.g. `u3_n31` for (node 31, UZ), `r1_n5` for (node 5, RX).
   pure function history_label(node_id, dof) result(label)
      integer, intent(in) :: node_id   !! user node id
      integer, intent(in) :: dof       !! 1..6
      character(len=:), allocatable :: label
      character(len=1), parameter :: kind_letter(2) = ['u', 'r']
      label = kind_letter((dof - 1)/3 + 1)//to_string(mod(dof - 1, 3) + 1)//'_n'//to_string(node_id)
   end function history_label

   !> Create (replace) `<base>_history.csv` for the requests (node_ids(i), dofs(i)) and write
   !> its header. Unknown node ids and DOF codes outside 1..6 are all reported in one error.
   subroutine history_open(self, base, mesh, node_ids, dofs, error)
      class(history_t), intent(inout) :: self
      character(len=*), intent(in) :: base
      type(mesh_t), intent(in) :: mesh
      integer, intent(in) :: node_ids(:)   !! user node ids
      integer, intent(in) :: dofs(:)       !! DOF codes, same size as node_ids
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: header, path
      integer :: i, found(1)
      if (size(dofs) /= size(node_ids)) then
         call fatal_error(error, 'history: '//to_string(size(node_ids))//' nodes but '//to_string(size(dofs))//' DOFs')
         return
      end if
      if (allocated(self%nodes)) deallocate (self%nodes)
      allocate (self%nodes(size(node_ids)))
      self%dofs = dofs
      do i = 1, size(node_ids)
         found = findloc(mesh%node_ids, node_ids(i))
         self%nodes(i) = found(1)
         if (found(1) == 0) call append_error(error, 'history: node '//to_string(node_ids(i))//' is not in the mesh')
         if (dofs(i) < 1 .or. dofs(i) > 6) call append_error(error, 'history: DOF code '//to_string(dofs(i))// &
                                                             ' of node '//to_string(node_ids(i))//' is not 1..6 (UX..RZ)')
      end do
      if (allocated(error)) return
      header = 'step,increment,time'
      do i = 1, size(node_ids)
         header = header//','//history_label(node_ids(i), dofs(i))
      end do
      path = base//'_history.csv'
      call self%file%open(path, 'history file "'//path//'"', error)
      if (allocated(error)) return
      call self%file%put(header)
      call self%file%flush(error)
   end subroutine history_open

   !> Append the row of one converged increment and flush it to disk.
   subroutine history_append(self, step, increment, time, displacement, reaction, error)
      class(history_t), intent(inout) :: self
      integer, intent(in) :: step, increment
      real(dp), intent(in) :: time                 !! load factor / pseudo time
      real(dp), intent(in) :: displacement(:, :)   !! (3, n_nodes)
      real(dp), intent(in) :: reaction(:, :)       !! (3, n_nodes)
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: row
      real(dp) :: value
      integer :: i
      if (.not. self%file%is_open()) then
         call fatal_error(error, 'history written before it was opened')
         return
      end if
      row = to_string(step)//','//to_string(increment)//','//real_text(time)
      do i = 1, size(self%nodes)
         if (self%dofs(i) <= 3) then
            value = displacement(self%dofs(i), self%nodes(i))
         else
            value = reaction(self%dofs(i) - 3, self%nodes(i))
         end if
         row = row//','//real_text(value)
      end do
      call self%file%put(row)
      call self%file%flush(error)
   end subroutine history_append

   pure logical function history_is_open(self)
      class(history_t), intent(in) :: self
      history_is_open = self%file%is_open()
   end function history_is_open

   subroutine history_close(self, error)
      class(history_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      call self%file%close(error)
   end subroutine history_close

   pure function real_text(value) result(text)
      real(dp), intent(in) :: value
      character(len=:), allocatable :: text
      character(len=24) :: buffer
      write (buffer, '(es24.16e3)') value
      text = trim(adjustl(buffer))
   end function real_text
end module frix_history_writer
