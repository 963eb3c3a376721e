!> Field recovery and von Mises: reference values from closed formulas (stated per test).
module test_field_recovery
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_testing, only: unittest_t, new_unittest, check, check_close, check_message_contains
   use frix_field_recovery, only: cell_average, nodal_average, nodal_extrapolated, von_mises, &
                                  von_mises_field
   use frix_hex8_cell, only: hex8_corner
   implicit none
   private

   public :: collect_field_recovery

   !> Round-off only: a few operations on O(1) numbers.
   real(dp), parameter :: tight = 1.0e-13_dp
   !> Two hexahedra sharing the face of nodes 2, 5, 8, 11 (see test_io_fixtures).
   integer, parameter :: connectivity(8, 2) = reshape([1, 2, 5, 4, 7, 8, 11, 10, &
                                                       2, 3, 6, 5, 8, 9, 12, 11], [8, 2])
   integer, parameter :: shared_nodes(4) = [2, 5, 8, 11]

contains

   subroutine collect_field_recovery(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('constant field is recovered exactly', test_constant_field), &
               new_unittest('trilinear field is extrapolated exactly', test_trilinear_extrapolation), &
               new_unittest('shared nodes average the elements', test_shared_node_average), &
               new_unittest('extrapolation needs 8 points', test_extrapolation_needs_8_points), &
               new_unittest('von Mises of uniaxial stress is |s|', test_von_mises_uniaxial), &
               new_unittest('von Mises of pure shear is sqrt(3)|t|', test_von_mises_shear), &
               new_unittest('von Mises of hydrostatic stress is 0', test_von_mises_hydrostatic)]
   end subroutine collect_field_recovery

   !> A field equal to c at every point must give c in every cell and at every node
   !> (the extrapolation weights N_g(sqrt(3) s_a) sum to 1: partition of unity).
   subroutine test_constant_field(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: c(6) = [1.5_dp, -2.0_dp, 3.25_dp, 0.5_dp, -0.75_dp, 4.0_dp]
      real(dp) :: gp(6, 8, 2), cell(6, 2), nodal(6, 12)
      integer :: i, j
      do j = 1, 2
         do i = 1, 8
            gp(:, i, j) = c
         end do
      end do
      call cell_average(gp, cell)
      call check(error, maxval(abs(cell - spread(c, 2, 2))) <= tight*maxval(abs(c)), 'cell average of a constant')
      if (allocated(error)) return
      call nodal_average(connectivity, gp, nodal)
      call check(error, maxval(abs(nodal - spread(c, 2, 12))) <= tight*maxval(abs(c)), 'nodal average of a constant')
      if (allocated(error)) return
      call nodal_extrapolated(connectivity, gp, nodal, error)
      if (allocated(error)) return
      call check(error, maxval(abs(nodal - spread(c, 2, 12))) <= tight*maxval(abs(c)), &
                 'extrapolation of a constant, worst '//to_string(maxval(abs(nodal - spread(c, 2, 12)))))
   end subroutine test_constant_field

   !> f(xi, eta, zeta) = 1 + 2 xi + 3 eta + 4 zeta + 5 xi eta zeta sampled at the Gauss points
   !> (signs of node g)/sqrt(3) must come back as f at the corners (signs of node a): the
   !> field lies in the trilinear space, which the extrapolation reproduces exactly.
   subroutine test_trilinear_extrapolation(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: gp(1, 8, 1), nodal(1, 8), expected
      integer :: g, a
      do g = 1, 8
         gp(1, g, 1) = field(real(hex8_corner(:, g), dp)/sqrt(3.0_dp))
      end do
      call nodal_extrapolated(reshape([(a, a=1, 8)], [8, 1]), gp, nodal, error)
      if (allocated(error)) return
      do a = 1, 8
         expected = field(real(hex8_corner(:, a), dp))
         call check_close(error, nodal(1, a), expected, tight, tight*15.0_dp, 'corner '//to_string(a))
         if (allocated(error)) return
      end do
   contains
      pure real(dp) function field(xi)
         real(dp), intent(in) :: xi(3)
         field = 1.0_dp + 2.0_dp*xi(1) + 3.0_dp*xi(2) + 4.0_dp*xi(3) + 5.0_dp*xi(1)*xi(2)*xi(3)
      end function field
   end subroutine test_trilinear_extrapolation

   !> Element 1 constant 1, element 2 constant 3: the shared face gets (1 + 3)/2 = 2, the
   !> other nodes their element's value, with both recoveries.
   subroutine test_shared_node_average(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: gp(1, 8, 2), nodal(1, 12), expected(12)
      integer :: pass
      gp(1, :, 1) = 1.0_dp
      gp(1, :, 2) = 3.0_dp
      expected = 0.0_dp
      expected(connectivity(:, 1)) = 1.0_dp
      expected(connectivity(:, 2)) = 3.0_dp
      expected(shared_nodes) = 2.0_dp
      do pass = 1, 2
         if (pass == 1) then
            call nodal_average(connectivity, gp, nodal)
         else
            call nodal_extrapolated(connectivity, gp, nodal, error)
            if (allocated(error)) return
         end if
         call check(error, maxval(abs(nodal(1, :) - expected)) <= tight, &
                    'pass '//to_string(pass)//': worst deviation '//to_string(maxval(abs(nodal(1, :) - expected))))
         if (allocated(error)) return
      end do
   end subroutine test_shared_node_average

   subroutine test_extrapolation_needs_8_points(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: recovery_error
      real(dp) :: gp(6, 1, 2), nodal(6, 12)
      gp = 1.0_dp
      call nodal_extrapolated(connectivity, gp, nodal, recovery_error)
      call check_message_contains(error, recovery_error, 'needs 8 integration points')
   end subroutine test_extrapolation_needs_8_points

   !> sigma_xx = s only: J2 = s^2/3, so sqrt(3 J2) = |s| (also along y and z, and for s < 0).
   subroutine test_von_mises_uniaxial(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: stress(6)
      integer :: i
      do i = 1, 3
         stress = 0.0_dp
         stress(i) = -250.0_dp
         call check_close(error, von_mises(stress), 250.0_dp, tight, message='uniaxial along '//to_string(i))
         if (allocated(error)) return
      end do
   end subroutine test_von_mises_uniaxial

   !> One tensor shear t only: J2 = t^2, so sqrt(3 J2) = sqrt(3)|t|, for each of xy, xz, yz.
   subroutine test_von_mises_shear(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: stress(6, 3), equivalent(3)
      integer :: i
      stress = 0.0_dp
      do i = 1, 3
         stress(3 + i, i) = 40.0_dp*i
      end do
      equivalent = von_mises_field(stress)
      do i = 1, 3
         call check_close(error, equivalent(i), sqrt(3.0_dp)*40.0_dp*i, tight, message='shear component '//to_string(3 + i))
         if (allocated(error)) return
      end do
   end subroutine test_von_mises_shear

   !> p on the diagonal has no deviator: von Mises 0 (up to round-off of p = 1e3).
   subroutine test_von_mises_hydrostatic(error)
      type(error_t), allocatable, intent(out) :: error
      call check_close(error, von_mises([1.0e3_dp, 1.0e3_dp, 1.0e3_dp, 0.0_dp, 0.0_dp, 0.0_dp]), 0.0_dp, &
                       0.0_dp, 1.0e3_dp*tight, 'hydrostatic')
   end subroutine test_von_mises_hydrostatic
end module test_field_recovery
