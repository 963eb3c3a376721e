!> The listing: a fixed-column text file of each converged increment, for comparing a run with
!> an older one number by number (`tests/compare.sh`, Debian's numdiff). Format documented in
!> docs/listing-format.md; in short:
!>   - lines starting with '#' are comments (run header, anything that may differ between
!>     two equal runs such as dates or paths); compare.sh ignores them;
!>   - a block starts with a title line whose first character is not a blank, e.g.
!>     `STEP ...`, `ITERATION LOG`, `NODAL DISPLACEMENTS`; every other line starts with a blank;
!>   - a table has a title line, a column header line (key column right-aligned in 10
!>     characters, value columns right-aligned in 18) and rows `(i10, n(es18.9e3))`.
!> Node columns hold user node ids (`mesh%node_ids`). New block kinds (contact status,
!> forces) are written with `write_table` and need no change to compare.sh.
module frix_listing_writer
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string, padded
   use frix_mesh, only: mesh_t
   use frix_text_output, only: text_file_t
   implicit none
   private

   public :: listing_t, listing_label_length

   integer, parameter :: listing_label_length = 17   !! longest column label that fits a value column
   character(len=*), parameter :: key_format = '(i10)'
   character(len=*), parameter :: value_format = '(es18.9e3)'

   !> An open listing file. Every `write_*` flushes (and reports a failed write), so a crashed
   !> run keeps what it wrote.
   type :: listing_t
      private
      type(text_file_t) :: file
   contains
      procedure :: open => listing_open
      procedure :: close => listing_close
      procedure :: is_open
      procedure :: write_comment
      procedure :: write_increment_header
      procedure :: write_iteration_log
      procedure :: write_count
      procedure :: write_displacements
      procedure :: write_reactions
      procedure :: write_table
      procedure :: write_totals
   end type listing_t

contains

   !> Create (replace) the listing at `path` and write the run header as '#' comment lines.
   subroutine listing_open(self, path, deck_name, version, error)
      class(listing_t), intent(inout) :: self
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: deck_name   !! deck file as given on the command line
      character(len=*), intent(in) :: version     !! frix version, e.g. '0.1.0'
      type(error_t), allocatable, intent(out) :: error
      call self%file%open(path, 'listing "'//path//'"', error)
      if (allocated(error)) return
      call self%write_comment('frix listing, format: docs/listing-format.md', error)
      if (allocated(error)) return
      call self%write_comment('frix version '//version, error)
      if (allocated(error)) return
      call self%write_comment('deck '//deck_name, error)
   end subroutine listing_open

   pure logical function is_open(self)
      class(listing_t), intent(in) :: self
      is_open = self%file%is_open()
   end function is_open

   subroutine listing_close(self, error)
      class(listing_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      call self%file%close(error)
   end subroutine listing_close

   !> A comment line '# text' (ignored by compare.sh): dates, paths, timings go here.
   subroutine write_comment(self, text, error)
      class(listing_t), intent(inout) :: self
      character(len=*), intent(in) :: text
      type(error_t), allocatable, intent(out) :: error
      call write_lines(self, ['# '//text], error)
   end subroutine write_comment

   !> Block title of a converged increment:
   !> `STEP <i6>  INCREMENT <i6>  TIME <es18.9e3>  ITERATIONS <i6>`.
   subroutine write_increment_header(self, step, increment, time, iterations, error)
      class(listing_t), intent(inout) :: self
      integer, intent(in) :: step, increment
      real(dp), intent(in) :: time         !! load factor / pseudo time at the end of the increment
      integer, intent(in) :: iterations    !! Newton iterations to convergence
      type(error_t), allocatable, intent(out) :: error
      character(len=80) :: line
      integer :: stat
      write (line, '(a,es18.9e3,a)', iostat=stat) 'STEP'//padded(to_string(step), 6)//'  INCREMENT'// &
         padded(to_string(increment), 6)//'  TIME', time, '  ITERATIONS'//padded(to_string(iterations), 6)
      call write_lines(self, [line], error)
   end subroutine write_increment_header

   !> A one-line block `<title> <i10>`, e.g. `YIELDING POINTS         12`.
   subroutine write_count(self, title, count, error)
      class(listing_t), intent(inout) :: self
      character(len=*), intent(in) :: title
      integer, intent(in) :: count
      type(error_t), allocatable, intent(out) :: error
      character(len=80) :: line
      write (line, '(a,i10)') title, count
      call write_lines(self, [line], error)
   end subroutine write_count

   !> `ITERATION LOG` table: one row per Newton iteration (key ITER = 1, 2, ...), one column
   !> per norm named in `labels` (e.g. RESIDUAL_NORM, ENERGY_NORM), values(n_labels, n_iterations).
   subroutine write_iteration_log(self, labels, values, error)
      class(listing_t), intent(inout) :: self
      character(len=*), intent(in) :: labels(:)
      real(dp), intent(in) :: values(:, :)
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      call self%write_table('ITERATION LOG', 'ITER', labels, [(i, i=0, size(values, 2) - 1)], values, error)
   end subroutine write_iteration_log

   !> `NODAL DISPLACEMENTS` table: NODE (user id), UX, UY, UZ for every node.
   subroutine write_displacements(self, mesh, displacement, error)
      class(listing_t), intent(inout) :: self
      type(mesh_t), intent(in) :: mesh
      real(dp), intent(in) :: displacement(:, :)   !! (3, n_nodes)
      type(error_t), allocatable, intent(out) :: error
      call self%write_table('NODAL DISPLACEMENTS', 'NODE', [character(len=2) :: 'UX', 'UY', 'UZ'], &
                            mesh%node_ids, displacement, error)
   end subroutine write_displacements

   !> `REACTIONS` table (NODE, RX, RY, RZ) for the nodes with at least one constrained DOF,
   !> then `SUM OF REACTIONS` over all nodes (row key `TOTAL`). Reactions are the forces the
   !> supports exert on the body (fint - fext at constrained DOFs), in force units.
   subroutine write_reactions(self, mesh, reaction, constrained, error)
      class(listing_t), intent(inout) :: self
      type(mesh_t), intent(in) :: mesh
      real(dp), intent(in) :: reaction(:, :)     !! (3, n_nodes), zero at free DOFs
      logical, intent(in) :: constrained(:, :)   !! (3, n_nodes) true at prescribed DOFs
      type(error_t), allocatable, intent(out) :: error
      character(len=2), parameter :: labels(3) = ['RX', 'RY', 'RZ']
      integer, allocatable :: nodes(:)
      character(len=10) :: total
      integer :: node
      nodes = pack([(node, node=1, mesh%n_nodes)], any(constrained, dim=1))
      call self%write_table('REACTIONS (constrained DOFs only)', 'NODE', labels, mesh%node_ids(nodes), &
                            reaction(:, nodes), error)
      if (allocated(error)) return
      write (total, '(a10)') 'TOTAL'
      call write_lines(self, [character(len=10 + 18*size(labels)) :: 'SUM OF REACTIONS', header_line('', labels), &
                              total//values_text(sum(reaction, dim=2))], error)
   end subroutine write_reactions

   !> `TOTALS` block: one row per written total of the history (a sum of reactions or mean of
   !> displacements over a node set, a contact pair's resultant), its label right-aligned in 27
   !> characters after a blank (longer labels widen the row), then its value `es18.9e3`.
   subroutine write_totals(self, labels, values, written, error)
      class(listing_t), intent(inout) :: self
      character(len=*), intent(in) :: labels(:)
      real(dp), intent(in) :: values(:)   !! one per label
      logical, intent(in) :: written(:)   !! per label: whether it is a total, written here
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: lines(:)
      integer :: k, n, width
      width = 1 + 27 + 18
      do k = 1, size(labels)
         width = max(width, 1 + len_trim(labels(k)) + 18)
      end do
      allocate (character(len=width) :: lines(count(written) + 1))
      lines(1) = 'TOTALS'
      n = 1
      do k = 1, size(labels)
         if (.not. written(k)) cycle
         n = n + 1
         lines(n) = ' '//padded(trim(labels(k)), 27)//values_text(values(k:k))
      end do
      call write_lines(self, lines, error)
   end subroutine write_totals

   !> A generic block: title line, header line (`key_label`, `labels`), and one row per key:
   !> `(i10, n(es18.9e3))` with values(n_labels, n_keys). Labels longer than
   !> `listing_label_length` are cut.
   subroutine write_table(self, title, key_label, labels, keys, values, error)
      class(listing_t), intent(inout) :: self
      character(len=*), intent(in) :: title       !! block title, must not start with a blank or '#'
      character(len=*), intent(in) :: key_label   !! e.g. NODE, ITER, ELEMENT
      character(len=*), intent(in) :: labels(:)
      integer, intent(in) :: keys(:)
      real(dp), intent(in) :: values(:, :)
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: lines(:)
      character(len=10) :: key_text
      integer :: i, width
      if (len(title) == 0 .or. title(1:min(1, len(title))) == ' ' .or. title(1:min(1, len(title))) == '#') then
         call fatal_error(error, 'listing block title "'//title//'" must start with a non-blank character other than #')
         return
      end if
      if (size(values, 1) /= size(labels) .or. size(values, 2) /= size(keys)) then
         call fatal_error(error, 'listing block "'//title//'": values are ('//to_string(size(values, 1))//', '// &
                          to_string(size(values, 2))//'), expected ('//to_string(size(labels))//', '// &
                          to_string(size(keys))//')')
         return
      end if
      width = max(len(title), 10 + 18*size(labels))
      allocate (character(len=width) :: lines(size(keys) + 2))
      lines(1) = title
      lines(2) = header_line(key_label, labels)
      do i = 1, size(keys)
         write (key_text, key_format) keys(i)
         lines(i + 2) = key_text//values_text(values(:, i))
      end do
      call write_lines(self, lines, error)
   end subroutine write_table

   !> Key label right-aligned in 10 characters, each label right-aligned in 18.
   pure function header_line(key_label, labels) result(line)
      character(len=*), intent(in) :: key_label
      character(len=*), intent(in) :: labels(:)
      character(len=:), allocatable :: line
      integer :: i
      line = right_aligned(key_label, 10)
      do i = 1, size(labels)
         line = line//right_aligned(labels(i), 18)
      end do
   end function header_line

   pure function right_aligned(text, width) result(field)
      character(len=*), intent(in) :: text
      integer, intent(in) :: width
      character(len=width) :: field
      character(len=:), allocatable :: cut
      cut = trim(adjustl(text))
      cut = cut(1:min(len(cut), width - 1))   ! keep one blank as separator
      field = repeat(' ', width - len(cut))//cut
   end function right_aligned

   !> Values as consecutive `es18.9e3` fields; -0 is printed as 0 so that equal runs print
   !> equal text.
   function values_text(values) result(text)
      real(dp), intent(in) :: values(:)
      character(len=18*size(values)) :: text
      integer :: i
      do i = 1, size(values)
         write (text(18*i - 17:18*i), value_format) merge(0.0_dp, values(i), values(i) == 0.0_dp)
      end do
   end function values_text

   !> Write lines (trailing blanks cut) and flush.
   subroutine write_lines(self, lines, error)
      type(listing_t), intent(inout) :: self
      character(len=*), intent(in) :: lines(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      if (.not. self%file%is_open()) then
         call fatal_error(error, 'listing written before it was opened')
         return
      end if
      do i = 1, size(lines)
         call self%file%put(trim(lines(i)))
      end do
      call self%file%flush(error)
   end subroutine write_lines
end module frix_listing_writer
