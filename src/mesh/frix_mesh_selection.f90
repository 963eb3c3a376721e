!> Selections of mesh entities by geometry: the nodes inside a box and the boundary faces whose
!> nodes lie in a box (NODE SETS and SURFACES of a deck, docs/deck-format.md).
module frix_mesh_selection
   use frix_kinds, only: dp
   use frix_mesh, only: mesh_t, surface_t
   use frix_sorted_order, only: sorted_order
   implicit none
   private

   public :: nodes_in_box, boundary_faces_in_box, sorted_unique, sort_nodes

contains

   !> Internal numbers of the nodes inside `box` widened by `tolerance`.
   pure function nodes_in_box(mesh, box, tolerance) result(nodes)
      type(mesh_t), intent(in) :: mesh
      real(dp), intent(in) :: box(6), tolerance
      integer, allocatable :: nodes(:)
      logical, allocatable :: inside(:)
      integer :: n
      allocate (inside(mesh%n_nodes))
      do n = 1, mesh%n_nodes
         inside(n) = in_box(mesh%coords(:, n), box, tolerance)
      end do
      nodes = pack([(n, n=1, mesh%n_nodes)], inside)
   end function nodes_in_box

   pure logical function in_box(x, box, tolerance)
      real(dp), intent(in) :: x(3), box(6), tolerance
      in_box = all(x >= box(1:3) - tolerance) .and. all(x <= box(4:6) + tolerance)
   end function in_box

   pure function sorted_unique(values) result(unique)
      integer, intent(in) :: values(:)
      integer, allocatable :: unique(:)
      integer, allocatable :: order(:)
      integer :: k, n
      allocate (order(size(values)), unique(size(values)))
      order(:) = sorted_order(reshape(values, [1, size(values)]))
      n = 0
      do k = 1, size(order)
         if (n > 0) then
            if (unique(n) == values(order(k))) cycle
         end if
         n = n + 1
         unique(n) = values(order(k))
      end do
      unique = unique(1:n)
   end function sorted_unique

   !> `SURF <name> BOX xmin ymin zmin xmax ymax zmax` or `SURF <name> FACES e f e f ...`.
   !> Faces that belong to exactly one element and whose nodes all lie in the box. Candidate
   !> faces (nodes in the box) are sorted by their sorted node numbers; a face shared by two
   !> elements has both copies among the candidates, so it appears twice and is dropped.
   subroutine boundary_faces_in_box(mesh, box, tolerance, surface)
      type(mesh_t), intent(in) :: mesh
      real(dp), intent(in) :: box(6), tolerance
      type(surface_t), intent(out) :: surface
      logical, allocatable :: inside(:)
      integer, allocatable :: keys(:, :), elements(:), faces(:), order(:), face(:)
      integer :: e, f, n, k, count
      allocate (inside(mesh%n_nodes))
      do k = 1, mesh%n_nodes
         inside(k) = in_box(mesh%coords(:, k), box, tolerance)
      end do
      n = 0
      do e = 1, mesh%n_elements
         do f = 1, mesh%face_count(e)
            if (all(inside(mesh%face_nodes(e, f)))) n = n + 1
         end do
      end do
      allocate (keys(4, n), elements(n), faces(n))
      n = 0
      do e = 1, mesh%n_elements
         do f = 1, mesh%face_count(e)
            face = mesh%face_nodes(e, f)
            if (all(inside(face))) then
               n = n + 1
               keys(:, n) = 0   ! a triangle's key: its 3 nodes sorted, then 0
               keys(1:size(face), n) = sort_nodes(face)
               elements(n) = e
               faces(n) = f
            end if
         end do
      end do
      order = sorted_order(keys)
      allocate (surface%elements(n), surface%faces(n))
      count = 0
      k = 1
      do while (k <= n)
         if (k < n) then
            if (all(keys(:, order(k)) == keys(:, order(k + 1)))) then
               k = k + 2  ! an interior face (shared by two elements)
               cycle
            end if
         end if
         count = count + 1
         surface%elements(count) = elements(order(k))
         surface%faces(count) = faces(order(k))
         k = k + 1
      end do
      surface%elements = surface%elements(1:count)
      surface%faces = surface%faces(1:count)
   end subroutine boundary_faces_in_box

   !> A few integers (a face's nodes) in ascending order (insertion sort).
   pure function sort_nodes(values) result(sorted)
      integer, intent(in) :: values(:)
      integer :: sorted(size(values))
      integer :: i, j, swap
      sorted = values
      do i = 2, size(values)
         j = i
         do while (j > 1)
            if (sorted(j - 1) <= sorted(j)) exit
            swap = sorted(j)
            sorted(j) = sorted(j - 1)
            sorted(j - 1) = swap
            j = j - 1
         end do
      end do
   end function sort_nodes

end module frix_mesh_selection
