!> A uniform bucket grid of faces' bounding boxes (inflated by a band), shared by the
!> node-to-segment contact search (frix_contact_search: the faces whose box holds a slave node)
!> and the mortar integrals (frix_mortar_segments: the master faces whose box meets a slave
!> face's box). Built in linear time; a query visits the cells the point or box covers.
module frix_face_grid
   use frix_kinds, only: dp
   use frix_sorted_order, only: sorted_order
   implicit none
   private

   public :: face_grid_t, build_face_grid, grid_cell, faces_meeting_box

   integer, parameter :: max_cells = 200              !! most grid cells along an axis

   !> Uniform bucket grid of the faces' inflated bounding boxes: the faces whose box
   !> meets cell c are cell_faces(cell_start(c) + 1 : cell_start(c + 1)); cells are numbered
   !> x fastest.
   type :: face_grid_t
      real(dp), allocatable :: lower(:, :), upper(:, :)  !! (3, n_faces) box corners
      real(dp) :: origin(3) = 0.0_dp
      real(dp) :: cell_size = 0.0_dp
      integer :: n_cells(3) = 1
      integer, allocatable :: cell_start(:), cell_faces(:)
   end type face_grid_t

contains

   !> The bucket grid of faces x_faces (3, 4, n >= 1), boxes inflated by band: cells about the
   !> size of the largest box, at most max_cells along an axis.
   pure subroutine build_face_grid(x_faces, band, grid)
      real(dp), intent(in) :: x_faces(:, :, :), band
      type(face_grid_t), intent(out) :: grid
      integer, allocatable :: counts(:)
      integer :: f, c, n_faces
      n_faces = size(x_faces, 3)
      allocate (grid%lower(3, n_faces), grid%upper(3, n_faces))
      do f = 1, n_faces
         grid%lower(:, f) = minval(x_faces(:, :, f), dim=2) - band
         grid%upper(:, f) = maxval(x_faces(:, :, f), dim=2) + band
      end do
      grid%origin = minval(grid%lower, dim=2)
      grid%cell_size = max(maxval(grid%upper - grid%lower), maxval(maxval(grid%upper, dim=2) - grid%origin)/max_cells, &
                           tiny(1.0_dp))
      grid%n_cells = max(1, min(ceiling((maxval(grid%upper, dim=2) - grid%origin)/grid%cell_size), max_cells))
      ! faces per cell as compressed rows: count, prefix sums, fill
      allocate (counts(product(grid%n_cells)), source=0)
      do f = 1, n_faces
         call visit_cells(grid, f, counts, .false.)
      end do
      allocate (grid%cell_start(product(grid%n_cells) + 1))
      grid%cell_start(1) = 0
      do c = 1, product(grid%n_cells)
         grid%cell_start(c + 1) = grid%cell_start(c) + counts(c)
      end do
      allocate (grid%cell_faces(grid%cell_start(product(grid%n_cells) + 1)))
      counts = grid%cell_start(:product(grid%n_cells))
      do f = 1, n_faces
         call visit_cells(grid, f, counts, .true.)
      end do
   end subroutine build_face_grid

   !> Count face f in every cell its box covers, or (fill) also store it there.
   pure subroutine visit_cells(grid, f, counts, fill)
      type(face_grid_t), intent(inout) :: grid
      integer, intent(in) :: f
      integer, intent(inout) :: counts(:)
      logical, intent(in) :: fill
      integer :: lo(3), hi(3), ix, iy, iz, c
      lo = cell_of(grid, grid%lower(:, f))
      hi = cell_of(grid, grid%upper(:, f))
      do iz = lo(3), hi(3)
         do iy = lo(2), hi(2)
            do ix = lo(1), hi(1)
               c = ix + grid%n_cells(1)*((iy - 1) + grid%n_cells(2)*(iz - 1))
               counts(c) = counts(c) + 1
               if (fill) grid%cell_faces(counts(c)) = f
            end do
         end do
      end do
   end subroutine visit_cells

   !> The cell (x, y, z indices) of a point, clamped to the grid.
   pure function cell_of(grid, point) result(index3)
      type(face_grid_t), intent(in) :: grid
      real(dp), intent(in) :: point(3)
      integer :: index3(3)
      real(dp) :: position(3)
      ! clamped before the conversion, which is undefined for reals beyond the integers
      position = min(real(grid%n_cells, dp), max(1.0_dp, (point - grid%origin)/grid%cell_size + 1.0_dp))
      index3 = int(position)
   end function cell_of

   !> The number of the cell that holds a point, 0 if the point lies outside the grid.
   pure integer function grid_cell(grid, point) result(c)
      type(face_grid_t), intent(in) :: grid
      real(dp), intent(in) :: point(3)
      integer :: cell(3)
      c = 0
      if (.not. (all(point >= grid%origin) .and. all(point <= grid%origin + grid%n_cells*grid%cell_size))) return
      cell = cell_of(grid, point)
      c = cell(1) + grid%n_cells(1)*((cell(2) - 1) + grid%n_cells(2)*(cell(3) - 1))
   end function grid_cell

   !> The faces of `grid` whose box meets the box [lower, upper] (length), each once, in
   !> increasing face number (the order of a loop over all faces): faces(:n_found).
   !> visited (n_faces, kept by the caller between queries, 0 at first) and query (a number
   !> the caller raises by one per query) mark the faces already seen by this query.
   pure subroutine faces_meeting_box(grid, lower, upper, query, visited, faces, n_found)
      type(face_grid_t), intent(in) :: grid
      real(dp), intent(in) :: lower(3), upper(3)
      integer, intent(in) :: query
      integer, intent(inout) :: visited(:)
      integer, allocatable, intent(inout) :: faces(:)
      integer, intent(out) :: n_found
      integer, allocatable :: grown(:)
      integer :: lo(3), hi(3), ix, iy, iz, c, k, f
      n_found = 0
      if (.not. allocated(faces)) allocate (faces(16))
      lo = cell_of(grid, lower)
      hi = cell_of(grid, upper)
      do iz = lo(3), hi(3)
         do iy = lo(2), hi(2)
            do ix = lo(1), hi(1)
               c = ix + grid%n_cells(1)*((iy - 1) + grid%n_cells(2)*(iz - 1))
               do k = grid%cell_start(c) + 1, grid%cell_start(c + 1)
                  f = grid%cell_faces(k)
                  if (visited(f) == query) cycle
                  visited(f) = query
                  if (any(upper < grid%lower(:, f) .or. lower > grid%upper(:, f))) cycle
                  if (n_found == size(faces)) then
                     allocate (grown(2*n_found))
                     grown(:n_found) = faces
                     call move_alloc(grown, faces)
                  end if
                  n_found = n_found + 1
                  faces(n_found) = f
               end do
            end do
         end do
      end do
      faces(:n_found) = faces(sorted_order(reshape(faces(:n_found), [1, n_found])))
   end subroutine faces_meeting_box
end module frix_face_grid
