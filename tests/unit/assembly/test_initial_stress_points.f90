!> The initial stress of a definition at a point (frix_initial_stress, initial_stress_at):
!> the geostatic closed form sigma_v = -(q + gamma (z0 - z)), sigma_h = K0 sigma_v along the
!> default axis z and along AXIS y, and an explicit stress given back as it is.
module test_initial_stress_points
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check
   use frix_model, only: initial_stress_t
   use frix_initial_stress, only: initial_stress_at
   implicit none
   private

   public :: collect_initial_stress_points

contains

   subroutine collect_initial_stress_points(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('geostatic stress at points: axis z, axis y, surcharge; explicit stress', test_at_points)]
   end subroutine collect_initial_stress_points

   !> DATUM 4 GAMMA 18 K0 0.5 SURCHARGE 36 at z = 1: sigma_v = -(36 + 18 x 3) = -90,
   !> sigma_h = -45; with AXIS y the same at y = 1 whatever z; STRESS as given.
   subroutine test_at_points(error)
      type(error_t), allocatable, intent(out) :: error
      type(initial_stress_t) :: definition
      real(dp), parameter :: explicit(6) = [-1.0_dp, -2.0_dp, -3.0_dp, 0.5_dp, 0.25_dp, -0.125_dp]
      definition = initial_stress_t(geostatic=.true., datum=4.0_dp, unit_weight=18.0_dp, k0=0.5_dp, surcharge=36.0_dp)
      call check(error, all(initial_stress_at(definition, [7.0_dp, -3.0_dp, 1.0_dp]) == &
                            [-45.0_dp, -45.0_dp, -90.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]), 'geostatic, axis z')
      if (allocated(error)) return
      definition%axis = 2
      call check(error, all(initial_stress_at(definition, [7.0_dp, 1.0_dp, 100.0_dp]) == &
                            [-45.0_dp, -90.0_dp, -45.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]), 'geostatic, axis y')
      if (allocated(error)) return
      definition = initial_stress_t(stress=explicit)
      call check(error, all(initial_stress_at(definition, [1.0_dp, 2.0_dp, 3.0_dp]) == explicit), 'explicit stress')
   end subroutine test_at_points
end module test_initial_stress_points
