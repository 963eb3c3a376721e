!> History of selected quantities: a CSV file `<base>_history.csv` with a header
!> `step,increment,time,<label>...` and one row per converged increment (docs/output.md).
!> A column is a nodal DOF, a total over a node set or a contact pair's resultant; the
!> caller computes the values, this module names the columns and writes the rows.
!> Column labels: 'u' (displacement) or 'r' (reaction, the force the supports exert on the
!> body), the direction 1..3, then
!>   `_n<id>` one node: `u3_n31` the z displacement of node 31, `r1_n5` the x reaction of node 5;
!>   `_sum_<set>` the sum over a node set (reactions): `r3_sum_base_zmin`;
!>   `_mean_<set>` the mean over a node set (displacements): `u3_mean_top`;
!> and for a contact pair `c<d>_pair<id>` (component d of the resultant of the contact
!> forces on its slave surface) and `cn_pair<id>` (the sum of their normal parts).
!> Numbers: integers as i0, reals as es24.16e3 without padding (exact binary64 round trip).
!> Open with any CSV reader, e.g. `numpy.genfromtxt(path, delimiter=',', names=True)`.
module frix_history_writer
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string, to_upper
   use frix_text_output, only: text_file_t
   implicit none
   private

   public :: history_t, history_dof_code, history_label, set_history_label, contact_history_label
   public :: history_ux, history_uy, history_uz, history_rx, history_ry, history_rz

   integer, parameter :: history_ux = 1, history_uy = 2, history_uz = 3  !! displacement components
   integer, parameter :: history_rx = 4, history_ry = 5, history_rz = 6  !! reaction components
   character(len=2), parameter :: dof_names(6) = ['UX', 'UY', 'UZ', 'RX', 'RY', 'RZ']
   character(len=1), parameter :: kind_letter(2) = ['u', 'r']

   type :: history_t
      private
      type(text_file_t) :: file
      integer :: n_columns = 0
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

   !> Column label of one node's DOF, e.g. `u3_n31` for (node 31, UZ), `r1_n5` for (node 5, RX).
   pure function history_label(node_id, dof) result(label)
      integer, intent(in) :: node_id   !! user node id
      integer, intent(in) :: dof       !! 1..6
      character(len=:), allocatable :: label
      label = dof_prefix(dof)//'_n'//to_string(node_id)
   end function history_label

   !> Column label of a total over a node set: `r3_sum_<set>`, `u1_mean_<set>`.
   pure function set_history_label(set_name, dof, reduction) result(label)
      character(len=*), intent(in) :: set_name
      integer, intent(in) :: dof             !! 1..6
      character(len=*), intent(in) :: reduction   !! 'sum' or 'mean'
      character(len=:), allocatable :: label
      label = dof_prefix(dof)//'_'//reduction//'_'//set_name
   end function set_history_label

   !> Column label of a contact pair's resultant: `c<component>_pair<id>`, or `cn_pair<id>`
   !> for the normal force (component 0).
   pure function contact_history_label(pair_id, component) result(label)
      integer, intent(in) :: pair_id, component
      character(len=:), allocatable :: label
      if (component == 0) then
         label = 'cn_pair'//to_string(pair_id)
      else
         label = 'c'//to_string(component)//'_pair'//to_string(pair_id)
      end if
   end function contact_history_label

   !> 'u' or 'r' and the direction of DOF code 1..6: `u3`, `r1`.
   pure function dof_prefix(dof) result(prefix)
      integer, intent(in) :: dof
      character(len=:), allocatable :: prefix
      prefix = kind_letter((dof - 1)/3 + 1)//to_string(mod(dof - 1, 3) + 1)
   end function dof_prefix

   !> Create (replace) `<base>_history.csv` with the columns `labels` and write its header.
   subroutine history_open(self, base, labels, error)
      class(history_t), intent(inout) :: self
      character(len=*), intent(in) :: base
      character(len=*), intent(in) :: labels(:)
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: header, path
      integer :: i
      header = 'step,increment,time'
      do i = 1, size(labels)
         header = header//','//trim(labels(i))
      end do
      self%n_columns = size(labels)
      path = base//'_history.csv'
      call self%file%open(path, 'history file "'//path//'"', error)
      if (allocated(error)) return
      call self%file%put(header)
      call self%file%flush(error)
   end subroutine history_open

   !> Append the row of one converged increment, one value per column, and flush it to disk.
   subroutine history_append(self, step, increment, time, values, error)
      class(history_t), intent(inout) :: self
      integer, intent(in) :: step, increment
      real(dp), intent(in) :: time        !! load factor / pseudo time
      real(dp), intent(in) :: values(:)   !! one per column
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: row
      integer :: i
      if (.not. self%file%is_open()) then
         call fatal_error(error, 'history written before it was opened')
         return
      end if
      if (size(values) /= self%n_columns) then
         call fatal_error(error, 'history: '//to_string(size(values))//' values for '//to_string(self%n_columns)// &
                          ' columns')
         return
      end if
      row = to_string(step)//','//to_string(increment)//','//real_text(time)
      do i = 1, size(values)
         row = row//','//real_text(values(i))
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
