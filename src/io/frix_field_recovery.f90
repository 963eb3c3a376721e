!> Recovery of integration-point fields (stress, strain) to cells and nodes for output, and the
!> von Mises equivalent stress.
!>
!> Integration-point arrays are `gp(n_components, n_points, n_elements)`, the points in the order
!> of the cell's Gauss rule (frix_hex8_cell: point g beside node g).
!>
!> Nodal values: each element gives a value at each of its nodes, and a node receives the
!> arithmetic mean over the elements that contain it (unweighted; discontinuities between
!> blocks of different materials are smeared). The element's nodal values are
!>   - `nodal_average`: the element's mean over its points, copied to all its nodes;
!>   - `nodal_extrapolated` (HEX8 with 8 points): the field the cell recovers from its Gauss
!>     values, evaluated at the nodes, f_a = sum_g E(a, g) f_g with the cell's extrapolation
!>     matrix E (frix_hex8_cell: the trilinear field through the 8 Gauss values).
module frix_field_recovery
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_hex8_cell, only: hex8_cell_t, new_hex8_cell
   implicit none
   private

   public :: cell_average, nodal_average, nodal_extrapolated, von_mises, von_mises_field

contains

   !> Mean over the integration points of each element (unweighted: exact for the Gauss
   !> rules of undistorted elements, whose weights are equal), (n_components, n_elements).
   pure subroutine cell_average(gp, cell)
      real(dp), intent(in) :: gp(:, :, :)     !! (n_components, n_points, n_elements)
      real(dp), intent(out) :: cell(:, :)     !! (n_components, n_elements)
      integer :: e
      do e = 1, size(gp, 3)
         cell(:, e) = sum(gp(:, :, e), dim=2)/real(size(gp, 2), dp)
      end do
   end subroutine cell_average

   !> Nodal values as the mean, over the elements at each node, of the element's point mean.
   !> Nodes that belong to no element receive 0.
   pure subroutine nodal_average(connectivity, gp, nodal)
      integer, intent(in) :: connectivity(:, :)  !! (nodes per element, n_elements) internal node numbers
      real(dp), intent(in) :: gp(:, :, :)        !! (n_components, n_points, n_elements)
      real(dp), intent(out) :: nodal(:, :)       !! (n_components, n_nodes)
      real(dp), allocatable :: cell(:, :), element_values(:, :, :)  ! heap, not stack: meshes can be large
      integer :: e, a
      allocate (cell(size(gp, 1), size(gp, 3)), element_values(size(gp, 1), size(connectivity, 1), size(gp, 3)))
      call cell_average(gp, cell)
      do e = 1, size(gp, 3)
         do a = 1, size(connectivity, 1)
            element_values(:, a, e) = cell(:, e)
         end do
      end do
      call scatter_mean(connectivity, element_values, nodal)
   end subroutine nodal_average

   !> Nodal values from the 2x2x2 Gauss values by trilinear extrapolation within each element,
   !> then the mean over the elements at each node. Fails unless there are 8 points and 8
   !> nodes per element.
   pure subroutine nodal_extrapolated(connectivity, gp, nodal, error)
      integer, intent(in) :: connectivity(:, :)  !! (8, n_elements) internal node numbers
      real(dp), intent(in) :: gp(:, :, :)        !! (n_components, 8, n_elements)
      real(dp), intent(out) :: nodal(:, :)       !! (n_components, n_nodes)
      type(error_t), allocatable, intent(out) :: error
      type(hex8_cell_t) :: cell
      real(dp), allocatable :: extrapolation(:, :)
      real(dp), allocatable :: element_values(:, :, :)
      integer :: e
      if (size(gp, 2) /= 8 .or. size(connectivity, 1) /= 8) then
         call fatal_error(error, 'nodal_extrapolated needs 8 integration points and 8 nodes per element, got '// &
                          to_string(size(gp, 2))//' points and '//to_string(size(connectivity, 1))//' nodes')
         return
      end if
      cell = new_hex8_cell()
      extrapolation = cell%extrapolation()
      allocate (element_values(size(gp, 1), 8, size(gp, 3)))
      do e = 1, size(gp, 3)
         ! element_values(:, a, e) = sum_g gp(:, g, e) * extrapolation(a, g)
         element_values(:, :, e) = matmul(gp(:, :, e), transpose(extrapolation))
      end do
      call scatter_mean(connectivity, element_values, nodal)
   end subroutine nodal_extrapolated

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
