!> HEX8-EAS where the perfectly plastic material tangent makes K_aa = sum_g G^T C G dV
!> singular (frix_hex8, solve_enhanced_system; docs/elements.md, "Singular K_aa"): every point
!> beyond the apex of the Mohr-Coulomb cone, where C = 0. Without the regularised solve every
!> EAS variant stops with "singular enhanced-strain stiffness K_aa".
module test_hex8_degenerate
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_testing, only: unittest_t, new_unittest, check
   use frix_material, only: material_t
   use frix_element, only: kinematics_linear
   use frix_hex8, only: hex8_t, new_hex8
   use frix_material_registry, only: create_material
   use test_element_fixtures, only: distorted_coords, sample_displacement, element_size
   implicit none
   private

   public :: collect_hex8_degenerate

   integer, parameter :: variants(4) = [3, 9, 21, 30]
   integer, parameter :: n_history = 10, region = 3   !! Mohr-Coulomb history; REGION's entry

contains

   subroutine collect_hex8_degenerate(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('every point beyond the apex: stress c cot(phi) 1, zero tangent, every variant', &
                            test_apex)]
   end subroutine collect_hex8_degenerate

   !> MAT_3DMohrCoulomb with E = 1e5, nu = 0.3, perfectly plastic (a subroutine, not a function:
   !> a polymorphic function result leaks under gfortran 12).
   subroutine mohr_coulomb(cohesion, phi, psi, material)
      real(dp), intent(in) :: cohesion, phi, psi
      class(material_t), allocatable, intent(out) :: material
      type(error_t), allocatable :: law_error
      call create_material('MAT_3DMohrCoulomb', [character(len=8) :: 'YOUNG', 'NUE', 'COHESION', 'PHI', 'PSI'], &
                           [1.0e5_dp, 0.3_dp, cohesion, phi, psi], material, law_error)
      if (allocated(law_error)) error stop 'test_hex8_degenerate: invalid soil'
   end subroutine mohr_coulomb

   !> The distorted element stretched by 5 % in every direction plus an irregular pattern
   !> (c = 1, phi = 30 degrees, psi = 30 and 10 degrees): the trial mean stress (about 1.2e4)
   !> lies far beyond the apex c cot(phi) = 1.732, so every point returns to it (REGION 3),
   !> where the perfectly plastic tangent is zero: K_aa = 0. The stress at every point is
   !> c cot(phi) 1 to 1e-12 relative and the condensed tangent is zero (below 1e-12 E size).
   subroutine test_apex(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      type(hex8_t) :: element
      real(dp) :: coords(3, 8), u(3, 8), fint(24), tangent(24, 24), stress(6, 8), expected(6)
      real(dp) :: state_old(n_history, 8), state_new(n_history, 8), alpha(30), apex
      integer :: k, v
      real(dp), parameter :: psi(2) = [30.0_dp, 10.0_dp]
      coords = distorted_coords()
      u = 0.05_dp*coords + sample_displacement(0.002_dp*element_size)
      apex = 1.0_dp/tan(30.0_dp*acos(-1.0_dp)/180.0_dp)
      expected = apex*[1.0_dp, 1.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]
      state_old = 0.0_dp
      do k = 1, 2
         call mohr_coulomb(1.0_dp, 30.0_dp, psi(k), material)
         do v = 1, size(variants)
            element = new_hex8(variants(v), kinematics_linear)
            alpha = 0.0_dp
            call element%evaluate(material, coords, u, alpha, state_old, state_new, fint, tangent=tangent, &
                                  stress=stress, error=error)
            if (allocated(error)) return
            call check(error, all(nint(state_new(region, :)) == 3), element%name//': not every point at the apex')
            if (allocated(error)) return
            call check(error, maxval(abs(stress - spread(expected, 2, 8))) <= 1.0e-12_dp*apex, element%name// &
                       ': stress off the apex by '//to_string(maxval(abs(stress - spread(expected, 2, 8)))))
            if (allocated(error)) return
            call check(error, maxval(abs(tangent)) <= 1.0e-12_dp*1.0e5_dp*element_size, element%name// &
                       ': tangent not zero, max|K| '//to_string(maxval(abs(tangent))))
            if (allocated(error)) return
         end do
      end do
   end subroutine test_apex
end module test_hex8_degenerate
