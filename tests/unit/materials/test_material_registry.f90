!> The material registry: each law is created from its deck keyword and properties, and every
!> documented mistake is reported with a message naming the keyword or property.
module test_material_registry
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close, check_message_contains
   use frix_material, only: material_t
   use frix_linear_elastic, only: linear_elastic_t
   use frix_saint_venant_kirchhoff, only: saint_venant_kirchhoff_t
   use frix_neo_hookean, only: neo_hookean_t
   use frix_von_mises_plastic, only: von_mises_plastic_t
   use frix_abaqus_neo_hooke, only: abaqus_neo_hooke_t
   use frix_material_registry, only: create_material, material_keywords, keyword_length
   implicit none
   private

   public :: collect_material_registry

   character(len=8), parameter :: standard_names(3) = [character(len=8) :: 'YOUNG', 'NUE', 'DENS']
   real(dp), parameter :: standard_values(3) = [1000.0_dp, 0.3_dp, 20.0_dp]

contains

   subroutine collect_material_registry(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('creates St. Venant-Kirchhoff', test_create_saint_venant_kirchhoff), &
               new_unittest('creates linear elastic', test_create_linear_elastic), &
               new_unittest('creates neo-Hookean, keyword and names in any case', test_create_neo_hookean), &
               new_unittest('creates the Abaqus neo-Hookean from C10, D1, DENS', test_create_abaqus_neo_hooke), &
               new_unittest('MAT_Struct_NeoHookeAbaqus: properties checked', test_abaqus_neo_hooke_mistakes), &
               new_unittest('every listed keyword creates its law', test_keywords_round_trip), &
               new_unittest('DENS defaults to 0', test_default_density), &
               new_unittest('unknown law lists the valid ones', test_unknown_law), &
               new_unittest('MAT_3DMisesPlastic: properties checked', test_plasticity), &
               new_unittest('MAT_3DMisesPlastic: SIGINF, DELTA and 12 table points accepted', test_plasticity_names), &
               new_unittest('MAT_3DMohrCoulomb, MAT_3DDruckerPrager: properties checked', test_frictional), &
               new_unittest('missing YOUNG', test_missing_young), &
               new_unittest('missing NUE', test_missing_poisson), &
               new_unittest('unknown property', test_unknown_property), &
               new_unittest('repeated property', test_repeated_property), &
               new_unittest('YOUNG <= 0', test_bad_young), &
               new_unittest('NUE outside (-1, 0.5)', test_bad_poisson), &
               new_unittest('DENS < 0', test_bad_density), &
               new_unittest('names and values of different lengths', test_length_mismatch), &
               new_unittest('all mistakes reported at once', test_several_mistakes)]
   end subroutine collect_material_registry

   subroutine test_create_saint_venant_kirchhoff(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      call create_material('MAT_Struct_StVenantKirchhoff', standard_names, standard_values, material, error)
      if (allocated(error)) return
      call check(error, material%name == 'MAT_Struct_StVenantKirchhoff', 'name')
      if (allocated(error)) return
      call check_close(error, material%density, 20.0_dp, 0.0_dp, message='density')
      if (allocated(error)) return
      select type (material)
      type is (saint_venant_kirchhoff_t)
         call check_close(error, material%young, 1000.0_dp, 0.0_dp, message='young')
         if (allocated(error)) return
         call check_close(error, material%poisson, 0.3_dp, 0.0_dp, message='poisson')
      class default
         call check(error, .false., 'wrong dynamic type')
      end select
   end subroutine test_create_saint_venant_kirchhoff

   subroutine test_create_linear_elastic(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      call create_material('MAT_Struct_LinearElastic', standard_names, standard_values, material, error)
      if (allocated(error)) return
      select type (material)
      type is (linear_elastic_t)
         call check_close(error, material%young, 1000.0_dp, 0.0_dp, message='young')
      class default
         call check(error, .false., 'wrong dynamic type')
      end select
   end subroutine test_create_linear_elastic

   subroutine test_create_neo_hookean(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      call create_material('  mat_struct_NEOHOOKE', [character(len=5) :: 'nue', 'Young'], [0.25_dp, 500.0_dp], &
                           material, error)
      if (allocated(error)) return
      call check(error, material%name == 'MAT_Struct_NeoHooke', 'name in documented spelling')
      if (allocated(error)) return
      select type (material)
      type is (neo_hookean_t)
         call check_close(error, material%young, 500.0_dp, 0.0_dp, message='young')
         if (allocated(error)) return
         call check_close(error, material%poisson, 0.25_dp, 0.0_dp, message='poisson')
      class default
         call check(error, .false., 'wrong dynamic type')
      end select
   end subroutine test_create_neo_hookean

   subroutine test_create_abaqus_neo_hooke(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      call create_material('mat_struct_neohookeabaqus', [character(len=4) :: 'c10', 'D1', 'DENS'], &
                           [80.0_dp, 1.0e-3_dp, 2.0_dp], material, error)
      if (allocated(error)) return
      call check(error, material%name == 'MAT_Struct_NeoHookeAbaqus', 'name in documented spelling')
      if (allocated(error)) return
      call check_close(error, material%density, 2.0_dp, 0.0_dp, message='density')
      if (allocated(error)) return
      select type (material)
      type is (abaqus_neo_hooke_t)
         call check_close(error, material%c10, 80.0_dp, 0.0_dp, message='C10')
         if (allocated(error)) return
         call check_close(error, material%d1, 1.0e-3_dp, 0.0_dp, message='D1')
         if (allocated(error)) return
         call check_close(error, material%shear_modulus, 160.0_dp, 1.0e-15_dp, message='mu0 = 2 C10')
         if (allocated(error)) return
         call check_close(error, material%bulk_modulus, 2000.0_dp, 1.0e-15_dp, message='K0 = 2 / D1')
      class default
         call check(error, .false., 'wrong dynamic type')
      end select
      if (allocated(error)) return
      call create_material('MAT_Struct_NeoHookeAbaqus', [character(len=4) :: 'C10', 'D1'], [80.0_dp, 1.0e-3_dp], &
                           material, error)
      if (allocated(error)) return
      call check_close(error, material%density, 0.0_dp, 0.0_dp, message='DENS defaults to 0')
   end subroutine test_create_abaqus_neo_hooke

   subroutine test_abaqus_neo_hooke_mistakes(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: law = 'MAT_Struct_NeoHookeAbaqus'
      call check_failure(error, law, [character(len=4) :: 'C10', 'D1'], [80.0_dp, 0.0_dp], &
                         law//': D1 must be > 0, got 0 (D1 = 0, the incompressible law,')
      if (allocated(error)) return
      call check_failure(error, law, [character(len=4) :: 'C10', 'D1'], [80.0_dp, -1.0_dp], &
                         law//': D1 must be > 0, got -1')
      if (allocated(error)) return
      call check_failure(error, law, [character(len=4) :: 'C10', 'D1'], [0.0_dp, 1.0e-3_dp], &
                         law//': C10 must be > 0, got 0')
      if (allocated(error)) return
      call check_failure(error, law, [character(len=4) :: 'C10', 'D1', 'DENS'], [80.0_dp, 1.0e-3_dp, -1.0_dp], &
                         law//': DENS must be >= 0, got -1')
      if (allocated(error)) return
      call check_failure(error, law, [character(len=4) :: 'C10'], [80.0_dp], law//': missing property D1')
      if (allocated(error)) return
      call check_failure(error, law, [character(len=4) :: 'D1'], [1.0e-3_dp], law//': missing property C10')
      if (allocated(error)) return
      call check_failure(error, law, [character(len=5) :: 'YOUNG', 'NUE'], [1000.0_dp, 0.3_dp], &
                         law//': unknown property "YOUNG" (valid: C10, D1, DENS)')
   end subroutine test_abaqus_neo_hooke_mistakes

   subroutine test_keywords_round_trip(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      integer :: i
      associate (keywords => material_keywords())
         call check(error, size(keywords) == 7 .and. len(keywords) == keyword_length, 'seven laws')
         if (allocated(error)) return
         do i = 1, size(keywords)
            if (keywords(i) == 'MAT_3DMisesPlastic') then
               call create_material(keywords(i), [standard_names, 'SIGY    '], [standard_values, 1.0_dp], material, error)
            else if (keywords(i) == 'MAT_3DMohrCoulomb' .or. keywords(i) == 'MAT_3DDruckerPrager') then
               call create_material(keywords(i), [standard_names, 'COHESION', 'PHI     ', 'PSI     '], &
                                    [standard_values, 10.0_dp, 30.0_dp, 0.0_dp], material, error)
            else if (keywords(i) == 'MAT_Struct_NeoHookeAbaqus') then
               call create_material(keywords(i), [character(len=4) :: 'C10', 'D1', 'DENS'], [80.0_dp, 1.0e-3_dp, 20.0_dp], &
                                    material, error)
            else
               call create_material(keywords(i), standard_names, standard_values, material, error)
            end if
            if (allocated(error)) return
            call check(error, material%name == trim(keywords(i)), 'name of '//trim(keywords(i)))
            if (allocated(error)) return
         end do
      end associate
   end subroutine test_keywords_round_trip

   subroutine test_default_density(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      call create_material('MAT_Struct_StVenantKirchhoff', standard_names(1:2), standard_values(1:2), &
                           material, error)
      if (allocated(error)) return
      call check_close(error, material%density, 0.0_dp, 0.0_dp, message='density')
   end subroutine test_default_density

   !> Creates `keyword` from the given properties and checks that it fails with `fragment`
   !> and leaves no material.
   subroutine check_failure(error, keyword, names, values, fragment)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: keyword, names(:), fragment
      real(dp), intent(in) :: values(:)
      class(material_t), allocatable :: material
      type(error_t), allocatable :: registry_error
      call create_material(keyword, names, values, material, registry_error)
      call check_message_contains(error, registry_error, fragment)
      if (allocated(error)) return
      call check(error, .not. allocated(material), 'no material on error')
   end subroutine check_failure

   subroutine test_unknown_law(error)
      type(error_t), allocatable, intent(out) :: error
      call check_failure(error, 'MAT_Struct_Foo', standard_names, standard_values, &
                         'unknown material law "MAT_Struct_Foo"')
      if (allocated(error)) return
      call check_failure(error, 'MAT_Struct_Foo', standard_names, standard_values, &
                         'valid laws: MAT_Struct_LinearElastic, MAT_Struct_StVenantKirchhoff, MAT_Struct_NeoHooke, '// &
                         'MAT_Struct_NeoHookeAbaqus, MAT_3DMisesPlastic, MAT_3DMohrCoulomb, MAT_3DDruckerPrager')
   end subroutine test_unknown_law

   subroutine test_plasticity(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      type(error_t), allocatable :: law_error
      call create_material('MAT_3DMisesPlastic', [character(len=5) :: 'YOUNG', 'NUE', 'SIGY', 'HARD', 'KINH'], &
                           [1000.0_dp, 0.3_dp, 1.0_dp, 10.0_dp, 5.0_dp], material, law_error)
      call check(error, .not. allocated(law_error), 'valid linear hardening accepted')
      if (allocated(error)) return
      call check(error, material%n_state() == 14, 'n_state')
      if (allocated(error)) return
      call check_failure(error, 'MAT_3DMisesPlastic', [character(len=5) :: 'YOUNG', 'NUE', 'HARD'], &
                         [1000.0_dp, 0.3_dp, 0.0_dp], 'MAT_3DMisesPlastic: missing property SIGY')
      if (allocated(error)) return
      call check_failure(error, 'MAT_3DMisesPlastic', [character(len=5) :: 'YOUNG', 'NUE', 'SIGY', 'EPSP2', 'SIGY2'], &
                         [1000.0_dp, 0.3_dp, 1.0_dp, 0.1_dp, 2.0_dp], 'the hardening table has a gap before point 2')
      if (allocated(error)) return
      call check_failure(error, 'MAT_3DMisesPlastic', [character(len=5) :: 'YOUNG', 'NUE', 'SIGY', 'HARD', 'EPSP1', &
                         'SIGY1'], [1000.0_dp, 0.3_dp, 1.0_dp, 1.0_dp, 0.1_dp, 2.0_dp], 'excludes HARD, SIGINF and DELTA')
      if (allocated(error)) return
      call check_failure(error, 'MAT_3DMisesPlastic', [character(len=6) :: 'YOUNG', 'NUE', 'SIGY', 'SIGINF'], &
                         [1000.0_dp, 0.3_dp, 1.0_dp, 2.0_dp], 'SIGINF and DELTA go together')
      if (allocated(error)) return
      call create_material('MAT_3DMisesPlastic', [character(len=5) :: 'YOUNG', 'NUE', 'SIGY', 'ETAN'], &
                           [1000.0_dp, 0.3_dp, 1.0_dp, 100.0_dp], material, law_error)
      call check(error, .not. allocated(law_error), 'ETAN accepted')
      if (allocated(error)) return
      select type (material)
      type is (von_mises_plastic_t)
         ! 1/E_t = 1/E + 1/H: H = 1000 * 100 / 900
         call check_close(error, material%hardening%modulus, 1000.0_dp*100.0_dp/900.0_dp, 1.0e-14_dp, &
                          message='HARD from ETAN')
      class default
         call check(error, .false., 'wrong dynamic type')
      end select
      if (allocated(error)) return
      call check_failure(error, 'MAT_3DMisesPlastic', [character(len=5) :: 'YOUNG', 'NUE', 'SIGY', 'ETAN', 'HARD'], &
                         [1000.0_dp, 0.3_dp, 1.0_dp, 100.0_dp, 1.0_dp], 'ETAN excludes HARD')
      if (allocated(error)) return
      call check_failure(error, 'MAT_3DMisesPlastic', [character(len=5) :: 'YOUNG', 'NUE', 'SIGY', 'ETAN'], &
                         [1000.0_dp, 0.3_dp, 1.0_dp, 1000.0_dp], 'ETAN must lie in [0, YOUNG)')
      if (allocated(error)) return
      call check_failure(error, 'MAT_3DMisesPlastic', [character(len=5) :: 'YOUNG', 'NUE', 'SIGY', 'KINH'], &
                         [1000.0_dp, 0.3_dp, 1.0_dp, -1.0_dp], 'KINH must be >= 0')
      if (allocated(error)) return
      call check_failure(error, 'MAT_3DMisesPlastic', [character(len=5) :: 'YOUNG', 'NUE', 'SIGY', 'FOO'], &
                         [1000.0_dp, 0.3_dp, 1.0_dp, 1.0_dp], 'FOO')
   end subroutine test_plasticity

   !> Names longer than YOUNG reach the law whole (gfortran 12 once cut them to 5 characters:
   !> SIGINF to SIGIN, EPSP10 to EPSP1, and rejected them as unknown).
   subroutine test_plasticity_names(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      type(error_t), allocatable :: law_error
      character(len=6) :: names(27)
      real(dp) :: values(27)
      integer :: k
      call create_material('MAT_3DMisesPlastic', [character(len=6) :: 'YOUNG', 'NUE', 'SIGY', 'HARD', 'SIGINF', 'DELTA'], &
                           [1000.0_dp, 0.3_dp, 1.0_dp, 10.0_dp, 2.0_dp, 20.0_dp], material, law_error)
      if (allocated(law_error)) then
         call check(error, .false., 'saturation hardening rejected: '//law_error%message)
         return
      end if
      names(1:3) = [character(len=6) :: 'YOUNG', 'NUE', 'SIGY']
      values(1:3) = [1000.0_dp, 0.3_dp, 1.0_dp]
      do k = 1, 12
         write (names(2*k + 2), '(a, i0)') 'EPSP', k
         write (names(2*k + 3), '(a, i0)') 'SIGY', k
         values(2*k + 2) = 0.01_dp*k
         values(2*k + 3) = 1.0_dp + 0.1_dp*k
      end do
      call create_material('MAT_3DMisesPlastic', names, values, material, law_error)
      if (allocated(law_error)) then
         call check(error, .false., 'table of 12 points rejected: '//law_error%message)
         return
      end if
      call check_failure(error, 'MAT_3DMisesPlastic', [character(len=5) :: 'YOUNG', 'NUE', 'SIGY', 'FOO'], &
                         [1000.0_dp, 0.3_dp, 1.0_dp, 1.0_dp], 'unknown property "FOO" (valid: YOUNG, NUE, DENS, '// &
                         'SIGY, HARD, ETAN, SIGINF, DELTA, EPSPk and SIGYk (k = 1..50), KINH)')
   end subroutine test_plasticity_names

   !> The frictional laws: valid properties accepted (history size, symmetric tangent only for
   !> PSI = PHI), every documented mistake reported.
   subroutine test_frictional(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=8), parameter :: names(5) = [character(len=8) :: 'YOUNG', 'NUE', 'COHESION', 'PHI', 'PSI']
      class(material_t), allocatable :: material
      character(len=32) :: law
      integer :: k
      do k = 1, 2
         law = merge('MAT_3DMohrCoulomb  ', 'MAT_3DDruckerPrager', k == 1)
         call create_material(law, names, [1000.0_dp, 0.3_dp, 10.0_dp, 30.0_dp, 30.0_dp], material, error)
         if (allocated(error)) return
         call check(error, material%n_state() == 10 .and. material%symmetric_tangent(), trim(law)//': associated')
         if (allocated(error)) return
         call create_material(law, [names, 'HARD    '], [1000.0_dp, 0.3_dp, 10.0_dp, 30.0_dp, 5.0_dp, -50.0_dp], &
                              material, error)
         if (allocated(error)) return
         call check(error, .not. material%symmetric_tangent(), trim(law)//': non-associated is unsymmetric')
         if (allocated(error)) return
         call check_failure(error, law, names(1:4), [1000.0_dp, 0.3_dp, 10.0_dp, 30.0_dp], 'missing property PSI')
         if (allocated(error)) return
         call check_failure(error, law, names, [1000.0_dp, 0.3_dp, -1.0_dp, 30.0_dp, 0.0_dp], &
                            'COHESION must be >= 0, got -1')
         if (allocated(error)) return
         call check_failure(error, law, names, [1000.0_dp, 0.3_dp, 10.0_dp, 90.0_dp, 0.0_dp], &
                            'PHI must lie in [0, 90) degrees, got 90')
         if (allocated(error)) return
         call check_failure(error, law, names, [1000.0_dp, 0.3_dp, 10.0_dp, 30.0_dp, 31.0_dp], &
                            'PSI must lie in [0, PHI] degrees, got 31')
         if (allocated(error)) return
         call check_failure(error, law, names, [1000.0_dp, 0.3_dp, 0.0_dp, 0.0_dp, 0.0_dp], &
                            'COHESION and PHI are both zero')
         if (allocated(error)) return
      end do
      call check_failure(error, 'MAT_3DMohrCoulomb', [names, 'MATCH   '], [1000.0_dp, 0.3_dp, 10.0_dp, 30.0_dp, 0.0_dp, 1.0_dp], &
                         'unknown property "MATCH" (valid: YOUNG, NUE, DENS, COHESION, PHI, PSI, HARD, TENSION)')
      if (allocated(error)) return
      call check_failure(error, 'MAT_3DMohrCoulomb', [names, 'TENSION '], [1000.0_dp, 0.3_dp, 10.0_dp, 30.0_dp, 0.0_dp, &
                         17.4_dp], 'TENSION must lie in [0, COHESION cot(PHI)) = [0, 17.3205')
      if (allocated(error)) return
      call check_failure(error, 'MAT_3DMohrCoulomb', [names, 'TENSION '], [1000.0_dp, 0.3_dp, 10.0_dp, 0.0_dp, 0.0_dp, &
                         -1.0_dp], 'TENSION must lie in [0, COHESION cot(PHI)) = [0, infinity), got -1')
      if (allocated(error)) return
      call check_failure(error, 'MAT_3DDruckerPrager', [names, 'TENSION '], [1000.0_dp, 0.3_dp, 10.0_dp, 30.0_dp, &
                         0.0_dp, 5.0_dp], 'unknown property "TENSION"')
      if (allocated(error)) return
      call check_failure(error, 'MAT_3DDruckerPrager', [names, 'MATCH   '], &
                         [1000.0_dp, 0.3_dp, 10.0_dp, 30.0_dp, 0.0_dp, 4.0_dp], &
                         'MATCH must be 1 (outer cone), 2 (inner cone) or 3 (plane strain), got 4')
   end subroutine test_frictional

   subroutine test_missing_young(error)
      type(error_t), allocatable, intent(out) :: error
      call check_failure(error, 'MAT_Struct_NeoHooke', standard_names(2:3), standard_values(2:3), &
                         'MAT_Struct_NeoHooke: missing property YOUNG')
   end subroutine test_missing_young

   subroutine test_missing_poisson(error)
      type(error_t), allocatable, intent(out) :: error
      call check_failure(error, 'MAT_Struct_LinearElastic', standard_names([1, 3]), standard_values([1, 3]), &
                         'MAT_Struct_LinearElastic: missing property NUE')
   end subroutine test_missing_poisson

   subroutine test_unknown_property(error)
      type(error_t), allocatable, intent(out) :: error
      call check_failure(error, 'MAT_Struct_StVenantKirchhoff', [character(len=5) :: 'YOUNG', 'NUE', 'SIGY'], &
                         [1000.0_dp, 0.3_dp, 1.0_dp], &
                         'MAT_Struct_StVenantKirchhoff: unknown property "SIGY" (valid: YOUNG, NUE, DENS)')
   end subroutine test_unknown_property

   subroutine test_repeated_property(error)
      type(error_t), allocatable, intent(out) :: error
      call check_failure(error, 'MAT_Struct_StVenantKirchhoff', [character(len=5) :: 'YOUNG', 'NUE', 'young'], &
                         [1000.0_dp, 0.3_dp, 2000.0_dp], 'property YOUNG given twice')
   end subroutine test_repeated_property

   subroutine test_bad_young(error)
      type(error_t), allocatable, intent(out) :: error
      call check_failure(error, 'MAT_Struct_StVenantKirchhoff', standard_names, [0.0_dp, 0.3_dp, 0.0_dp], &
                         'MAT_Struct_StVenantKirchhoff: YOUNG must be > 0, got 0')
      if (allocated(error)) return
      call check_failure(error, 'MAT_Struct_StVenantKirchhoff', standard_names, [-5.0_dp, 0.3_dp, 0.0_dp], &
                         'YOUNG must be > 0, got -5')
   end subroutine test_bad_young

   subroutine test_bad_poisson(error)
      type(error_t), allocatable, intent(out) :: error
      call check_failure(error, 'MAT_Struct_NeoHooke', standard_names, [1000.0_dp, 0.5_dp, 0.0_dp], &
                         'MAT_Struct_NeoHooke: NUE must lie in (-1, 0.5), got 0.5')
      if (allocated(error)) return
      call check_failure(error, 'MAT_Struct_NeoHooke', standard_names, [1000.0_dp, -1.0_dp, 0.0_dp], &
                         'NUE must lie in (-1, 0.5), got -1')
   end subroutine test_bad_poisson

   subroutine test_bad_density(error)
      type(error_t), allocatable, intent(out) :: error
      call check_failure(error, 'MAT_Struct_LinearElastic', standard_names, [1000.0_dp, 0.3_dp, -1.0_dp], &
                         'MAT_Struct_LinearElastic: DENS must be >= 0, got -1')
   end subroutine test_bad_density

   subroutine test_length_mismatch(error)
      type(error_t), allocatable, intent(out) :: error
      call check_failure(error, 'MAT_Struct_LinearElastic', standard_names, standard_values(1:2), &
                         '3 property names but 2 values')
   end subroutine test_length_mismatch

   subroutine test_several_mistakes(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=5), parameter :: names(2) = [character(len=5) :: 'NUE', 'FOO']
      real(dp), parameter :: values(2) = [0.7_dp, 1.0_dp]
      call check_failure(error, 'MAT_Struct_LinearElastic', names, values, 'unknown property "FOO"')
      if (allocated(error)) return
      call check_failure(error, 'MAT_Struct_LinearElastic', names, values, 'missing property YOUNG')
      if (allocated(error)) return
      call check_failure(error, 'MAT_Struct_LinearElastic', names, values, 'NUE must lie in (-1, 0.5), got 0.7')
   end subroutine test_several_mistakes
end module test_material_registry
