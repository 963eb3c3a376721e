!> The initial (in-situ) stress of every law (material_t%initial_stress_response): the stress at
!> zero strain is sigma0 under both kinematics, and in the elastic range the law adds sigma0 to
!> its response without changing the tangent; the plastic laws yield from sigma0: a geostatic
!> state sheared at constant normal stresses reaches the Mohr-Coulomb and Drucker-Prager limits
!> of that state (closed forms), von Mises yields where sigma0 + D eps reaches SIGY.
module test_initial_stress
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_testing, only: unittest_t, new_unittest, check, check_close
   use frix_material, only: material_t
   use frix_material_registry, only: create_material, material_keywords
   use frix_drucker_prager, only: cone_parameters, match_outer
   use frix_frictional_plasticity, only: state_region, region_surface
   use test_material_checks, only: material_response, check_matrix_close, check_tangent_by_differences
   use test_soil_paths, only: make_soil, mixed_control, n_state
   implicit none
   private

   public :: collect_initial_stress

   !> A geostatic state, K0 = 0.6: sigma_v = -100 (z), sigma_h = -60, and a small shear.
   real(dp), parameter :: geostatic(6) = [-60.0_dp, -60.0_dp, -100.0_dp, 0.0_dp, 5.0_dp, 0.0_dp]
   real(dp), parameter :: pi = 3.14159265358979323846264338327950_dp

contains

   subroutine collect_initial_stress(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('every law: sigma = sigma0 at zero strain, sigma0 + response, same tangent', test_every_law), &
               new_unittest('Mohr-Coulomb: a geostatic state sheared to its limit', test_mohr_coulomb_shear), &
               new_unittest('Drucker-Prager: a geostatic state sheared to its limit', test_drucker_prager_shear), &
               new_unittest('von Mises: yields where sigma0 + D eps reaches SIGY', test_von_mises), &
               new_unittest('every law: zero strain from sigma0 leaves the history unchanged', test_history_at_rest)]
   end subroutine collect_initial_stress

   !> The law `keyword` with properties that keep the states below elastic.
   subroutine make_law(keyword, material)
      character(len=*), intent(in) :: keyword
      class(material_t), allocatable, intent(out) :: material
      type(error_t), allocatable :: error
      select case (trim(keyword))
      case ('MAT_Struct_NeoHookeAbaqus')
         call create_material(keyword, [character(len=4) :: 'C10', 'D1'], [3000.0_dp, 1.0e-4_dp], material, error)
      case ('MAT_3DMisesPlastic')
         call create_material(keyword, [character(len=5) :: 'YOUNG', 'NUE', 'SIGY'], [20000.0_dp, 0.3_dp, 1000.0_dp], &
                              material, error)
      case ('MAT_3DMohrCoulomb', 'MAT_3DDruckerPrager')
         call create_material(keyword, [character(len=8) :: 'YOUNG', 'NUE', 'COHESION', 'PHI', 'PSI'], &
                              [20000.0_dp, 0.3_dp, 10.0_dp, 30.0_dp, 10.0_dp], material, error)
      case default
         call create_material(keyword, [character(len=5) :: 'YOUNG', 'NUE'], [20000.0_dp, 0.3_dp], material, error)
      end select
      if (allocated(error)) error stop 'test_initial_stress: invalid law'
   end subroutine make_law

   subroutine test_every_law(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp), parameter :: strain(6) = [1.0e-4_dp, -2.0e-4_dp, 0.5e-4_dp, 1.0e-4_dp, 0.0_dp, -0.5e-4_dp]
      real(dp) :: stress(6), tangent(6, 6), plain(6), plain_tangent(6, 6)
      integer :: k, f
      logical :: finite
      associate (keywords => material_keywords())
         do k = 1, size(keywords)
            call make_law(keywords(k), material)
            do f = 1, 2
               finite = f == 2
               call material_response(error, material, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], stress, tangent, &
                                      finite, initial_stress=geostatic)
               if (allocated(error)) return
               call check_matrix_close(error, reshape(stress, [6, 1]), reshape(geostatic, [6, 1]), 1.0e-12_dp, &
                                       trim(keywords(k))//': sigma0 at zero strain, finite '//merge('T', 'F', finite))
               if (allocated(error)) return
               call material_response(error, material, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], plain, &
                                      plain_tangent, finite)
               if (allocated(error)) return
               if (finite .and. material%n_state() > 0) then
                  ! a plastic law maps T = sigma0 + D E_log: its tangent has the term T : d2 E_log / dE dE
                  call check_tangent_by_differences(error, material, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], &
                                                    1.0e-6_dp, trim(keywords(k))//': finite strain tangent from sigma0', &
                                                    finite, initial_stress=geostatic)
                  if (allocated(error)) return
                  cycle
               end if
               ! an elastic law adds sigma0 at any strain; a plastic one in the elastic range at small strain
               call material_response(error, material, strain, stress, tangent, finite, initial_stress=geostatic)
               if (allocated(error)) return
               call material_response(error, material, strain, plain, plain_tangent, finite)
               if (allocated(error)) return
               call check_matrix_close(error, tangent, plain_tangent, 1.0e-12_dp, trim(keywords(k))//': tangent')
               if (allocated(error)) return
               call check_matrix_close(error, reshape(stress - geostatic, [6, 1]), reshape(plain, [6, 1]), 1.0e-12_dp, &
                                       trim(keywords(k))//': sigma0 + response')
               if (allocated(error)) return
            end do
         end do
      end associate
   end subroutine test_every_law

   !> From sigma0 = (sigma_h, sigma_h, sigma_v) (no shear), gamma_xz increased at these normal
   !> stresses: in the x-z plane the Mohr circle has centre C = (sigma_h + sigma_v)/2 and radius
   !> sqrt(((sigma_h - sigma_v)/2)^2 + tau^2); sigma_yy = sigma_h stays the intermediate stress,
   !> and f = 0 gives radius = c cos(phi) - C sin(phi), so
   !>   tau = sqrt((c cos(phi) - C sin(phi))^2 - ((sigma_h - sigma_v)/2)^2) = 44.361
   !> (c = 10, phi = 30 degrees). No strain before the shear: the state is sigma0 from the start.
   subroutine test_mohr_coulomb_shear(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp) :: expected
      call make_soil(material, 'MAT_3DMohrCoulomb', 10.0_dp, 30.0_dp, 10.0_dp, 0.0_dp)
      expected = sqrt((10.0_dp*cos(pi/6.0_dp) + 80.0_dp*sin(pi/6.0_dp))**2 - 20.0_dp**2)
      call shear_to_limit(error, material, expected, 'Mohr-Coulomb')
   end subroutine test_mohr_coulomb_shear

   !> As above with the outer cone: sqrt(J2) = sqrt((sigma_h - sigma_v)^2 / 3 + tau^2), so
   !>   tau = sqrt((xi c - eta p)^2 - (sigma_h - sigma_v)^2 / 3),  p = (2 sigma_h + sigma_v)/3.
   subroutine test_drucker_prager_shear(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp) :: eta, xi
      call make_soil(material, 'MAT_3DDruckerPrager', 10.0_dp, 30.0_dp, 10.0_dp, 0.0_dp)
      call cone_parameters(match_outer, pi/6.0_dp, eta, xi)
      call shear_to_limit(error, material, sqrt((10.0_dp*xi + eta*220.0_dp/3.0_dp)**2 - 1600.0_dp/3.0_dp), &
                          'Drucker-Prager')
   end subroutine test_drucker_prager_shear

   subroutine shear_to_limit(error, material, expected, label)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), intent(in) :: material
      real(dp), intent(in) :: expected
      character(len=*), intent(in) :: label
      real(dp), parameter :: initial(6) = [-60.0_dp, -60.0_dp, -100.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]
      real(dp) :: strain(6), state(n_state), stress(6)
      integer :: step
      strain = 0.0_dp
      state = 0.0_dp
      do step = 1, 30
         strain(5) = strain(5) + 1.0e-3_dp
         call mixed_control(error, material, strain, [1, 2, 3], initial(1:3), state, stress, initial)
         if (allocated(error)) return
      end do
      call check_close(error, stress(5), expected, 1.0e-10_dp, message=label//': tau_xz at the limit')
      if (allocated(error)) return
      call check(error, nint(state(state_region)) == region_surface, label//': on the plane (cone)')
      if (allocated(error)) return
      call check_tangent_by_differences(error, material, strain + [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0e-4_dp, 0.0_dp], &
                                        1.0e-6_dp, label//': tangent from sigma0', .false., state, initial)
   end subroutine shear_to_limit

   !> A point at rest in its initial state: zero strain from sigma0 keeps the history of a law
   !> with one (here EQPS = 0.01, the rest 0) as it is (the initial stress is no plastic flow),
   !> under both kinematics.
   subroutine test_history_at_rest(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp), allocatable :: old(:), new(:)
      real(dp) :: stress(6), tangent(6, 6)
      integer :: k, f, j
      associate (keywords => material_keywords())
         do k = 1, size(keywords)
            call make_law(keywords(k), material)
            if (material%n_state() == 0) cycle
            old = [(0.0_dp, j=1, material%n_state())]
            old(1) = 0.01_dp   ! EQPS of von Mises and of the soil laws
            allocate (new(material%n_state()))
            do f = 1, 2
               new = -1.0_dp
               call material_response(error, material, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], stress, &
                                      tangent, f == 2, old, new, geostatic)
               if (allocated(error)) return
               call check(error, all(new == old), trim(keywords(k))//': history changed at rest, finite '// &
                          merge('T', 'F', f == 2))
               if (allocated(error)) return
            end do
            deallocate (new)
         end do
      end associate
   end subroutine test_history_at_rest

   !> sigma0 = 300 e_x x e_x, strain eps (1, -nu, -nu): sigma_xx = 300 + E eps reaches SIGY = 420
   !> at eps = 120 / E: elastic just below, plastic just above.
   subroutine test_von_mises(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      real(dp), parameter :: initial(6) = [300.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]
      real(dp) :: stress(6), tangent(6, 6), old(14), new(14), factor
      integer :: k
      type(error_t), allocatable :: law_error
      call create_material('MAT_3DMisesPlastic', [character(len=5) :: 'YOUNG', 'NUE', 'SIGY'], &
                           [210000.0_dp, 0.3_dp, 420.0_dp], material, law_error)
      if (allocated(law_error)) error stop 'test_initial_stress: invalid steel'
      old = 0.0_dp
      do k = 1, 2
         factor = merge(0.99_dp, 1.01_dp, k == 1)*120.0_dp/210000.0_dp
         call material_response(error, material, factor*[1.0_dp, -0.3_dp, -0.3_dp, 0.0_dp, 0.0_dp, 0.0_dp], stress, &
                                tangent, .false., old, new, initial)
         if (allocated(error)) return
         call check(error, nint(new(2)) == k - 1, 'YIELDED = '//to_string(k - 1)//' at '//to_string(factor)// &
                    ' x 120 / E, sigma_xx = '//to_string(stress(1)))
         if (allocated(error)) return
      end do
   end subroutine test_von_mises
end module test_initial_stress
