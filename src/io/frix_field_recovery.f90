!> Recovery of integration-point fields (stress, strain) to cells and nodes for output, and the
!> von Mises equivalent stress.
!>
!> Integration-point arrays are `gp(n_components, n_points, n_elements)`, the points in the order
!> of the element's cell's Gauss rule (frix_hex8_cell: point g beside node g), n_points the
!> most of any element; an element with fewer points (a TET4's one) fills the first ones. The
!> optional `element_cell` gives each element's cell (an index into the cell registry's table,
!> frix_mesh's `element_cell`); without it every element is a HEX8.
!>
!> Nodal values: each element gives a value at each of its nodes, and a node receives the
!> arithmetic mean over the elements that contain it (unweighted; discontinuities between
!> blocks of different materials are smeared). The element's nodal values are
!>   - `nodal_average`: the element's mean over its points, copied to all its nodes;
!>   - `nodal_extrapolated`: the field the cell recovers from its Gauss values, evaluated at
!>     the nodes, f_a = sum_g E(a, g) f_g with the cell's extrapolation matrix E (HEX8: the
!>     trilinear field through the 8 Gauss values; TET4: the one point's value).
module frix_field_recovery
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_cell_registry, only: cell_entry_t, cell_table, hex8_cell_index
   implicit none
   private

   public :: cell_average, nodal_average, nodal_extrapolated, von_mises, von_mises_field

   !> One cell's extrapolation matrix E(a, g).
   type :: extrapolation_t
      real(dp), allocatable :: matrix(:, :)
   end type extrapolation_t

contains

   !> Mean over the integration points of each element (unweighted: exact for the Gauss
   !> rules of undistorted elements, whose weights are equal), (n_components, n_elements).
   subroutine cell_average(gp, cell, element_cell)
      real(dp), intent(in) :: gp(:, :, :)     !! (n_components, n_points, n_elements)
      real(dp), intent(out) :: cell(:, :)     !! (n_components, n_elements)
      integer, intent(in), optional :: element_cell(:)
      integer, allocatable :: points(:)
      integer :: e, n
      ! an absent optional array is not passed on: gfortran's descriptor of it is a null pointer
      ! that the undefined-behaviour sanitizer reports
      if (present(element_cell)) then
         points = point_counts(size(gp, 2), element_cell)
      else
         allocate (points(size(gp, 3)), source=size(gp, 2))
      end if
      do e = 1, size(gp, 3)
         n = points(e)
         cell(:, e) = sum(gp(:, 1:n, e), dim=2)/real(n, dp)
      end do
   end subroutine cell_average

   !> Nodal values as the mean, over the elements at each node, of the element's point mean.
   !> Nodes that belong to no element receive 0.
   subroutine nodal_average(connectivity, gp, nodal, element_cell)
      integer, intent(in) :: connectivity(:, :)  !! (nodes per element, n_elements) internal node numbers, 0: none
      real(dp), intent(in) :: gp(:, :, :)        !! (n_components, n_points, n_elements)
      real(dp), intent(out) :: nodal(:, :)       !! (n_components, n_nodes)
      integer, intent(in), optional :: element_cell(:)
      real(dp), allocatable :: cell(:, :), element_values(:, :, :)  ! heap, not stack: meshes can be large
      integer :: e, a
      allocate (cell(size(gp, 1), size(gp, 3)), element_values(size(gp, 1), size(connectivity, 1), size(gp, 3)))
      if (present(element_cell)) then
         call cell_average(gp, cell, element_cell)
      else
         call cell_average(gp, cell)
      end if
      do e = 1, size(gp, 3)
         do a = 1, size(connectivity, 1)
            element_values(:, a, e) = cell(:, e)
         end do
      end do
      call scatter_mean(connectivity, element_values, nodal)
   end subroutine nodal_average

   !> Nodal values from each element's Gauss values by its cell's extrapolation, then the mean
   !> over the elements at each node. Fails when an element's cell has more points than `gp`
   !> or more nodes than the rows of `connectivity`.
   subroutine nodal_extrapolated(connectivity, gp, nodal, error, element_cell)
      integer, intent(in) :: connectivity(:, :)  !! (nodes per element, n_elements) internal node numbers, 0: none
      real(dp), intent(in) :: gp(:, :, :)        !! (n_components, n_points, n_elements)
      real(dp), intent(out) :: nodal(:, :)       !! (n_components, n_nodes)
      type(error_t), allocatable, intent(out) :: error
      integer, intent(in), optional :: element_cell(:)
      type(cell_entry_t), allocatable :: table(:)
      type(extrapolation_t), allocatable :: matrices(:)
      real(dp), allocatable :: element_values(:, :, :), matrix(:, :)
      integer :: e, k, n_points, n_nodes
      table = cell_table()
      allocate (matrices(size(table)))
      do k = 1, size(table)
         associate (cell => table(k)%cell)   ! (a direct table(k)%cell%extrapolation() crashes gfortran 12)
            matrix = cell%extrapolation()
         end associate
         call move_alloc(matrix, matrices(k)%matrix)
      end do
      allocate (element_values(size(gp, 1), size(connectivity, 1), size(gp, 3)), source=0.0_dp)
      do e = 1, size(gp, 3)
         k = hex8_cell_index   ! without element_cell
         if (present(element_cell)) k = element_cell(e)
         n_nodes = size(matrices(k)%matrix, 1)
         n_points = size(matrices(k)%matrix, 2)
         if (n_points > size(gp, 2) .or. n_nodes > size(connectivity, 1)) then
            call fatal_error(error, 'nodal_extrapolated: a '//table(k)%cell%name//' needs '//to_string(n_points)// &
                             ' integration points and '//to_string(n_nodes)//' nodes per element, got '// &
                             to_string(size(gp, 2))//' points and '//to_string(size(connectivity, 1))//' nodes')
            return
         end if
         ! element_values(:, a, e) = sum_g gp(:, g, e) * extrapolation(a, g)
         element_values(:, 1:n_nodes, e) = matmul(gp(:, 1:n_points, e), transpose(matrices(k)%matrix))
      end do
      call scatter_mean(connectivity, element_values, nodal)
   end subroutine nodal_extrapolated

   !> The integration points of each element: its cell's, at most max_points (gp's).
   function point_counts(max_points, element_cell) result(points)
      integer, intent(in) :: max_points
      integer, intent(in) :: element_cell(:)   !! (n_elements) index into cell_table()
      integer, allocatable :: points(:)
      type(cell_entry_t), allocatable :: table(:)
      integer, allocatable :: cell_points(:)
      integer :: k, e
      table = cell_table()
      allocate (cell_points(size(table)), points(size(element_cell)))
      do k = 1, size(table)
         cell_points(k) = size(table(k)%cell%weights)
      end do
      do e = 1, size(element_cell)
         points(e) = min(cell_points(element_cell(e)), max_points)
      end do
   end function point_counts

   !> nodal(:, n) = mean of element_values(:, a, e) over all (a, e) with connectivity(a, e) = n.
   pure subroutine scatter_mean(connectivity, element_values, nodal)
      integer, intent(in) :: connectivity(:, :)
      real(dp), intent(in) :: element_values(:, :, :)
      real(dp), intent(out) :: nodal(:, :)
      integer, allocatable :: count(:)
      integer :: e, a, node
      allocate (count(size(nodal, 2)))
      nodal = 0.0_dp
      count = 0
      do e = 1, size(connectivity, 2)
         do a = 1, size(connectivity, 1)
            node = connectivity(a, e)
            if (node == 0) cycle   ! past the element's own nodes
            nodal(:, node) = nodal(:, node) + element_values(:, a, e)
            count(node) = count(node) + 1
         end do
      end do
      do node = 1, size(nodal, 2)
         if (count(node) > 0) nodal(:, node) = nodal(:, node)/real(count(node), dp)
      end do
   end subroutine scatter_mean

   !> von Mises equivalent of a stress in frix Voigt order (xx yy zz xy xz yz, tensor shears):
   !> sqrt(1/2((sxx-syy)^2 + (syy-szz)^2 + (szz-sxx)^2) + 3(sxy^2 + sxz^2 + syz^2)),
   !> i.e. sqrt(3 J2); same units as the stress.
   pure function von_mises(stress) result(equivalent)
      real(dp), intent(in) :: stress(6)
      real(dp) :: equivalent
      equivalent = sqrt(0.5_dp*((stress(1) - stress(2))**2 + (stress(2) - stress(3))**2 + (stress(3) - stress(1))**2) &
                        + 3.0_dp*(stress(4)**2 + stress(5)**2 + stress(6)**2))
   end function von_mises

   !> `von_mises` of each column of `stress` (6, n).
   pure function von_mises_field(stress) result(equivalent)
      real(dp), intent(in) :: stress(:, :)
      real(dp) :: equivalent(size(stress, 2))
      integer :: i
      do i = 1, size(stress, 2)
         equivalent(i) = von_mises(stress(:, i))
      end do
   end function von_mises_field
end module frix_field_recovery
