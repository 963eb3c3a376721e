!> Unit tests of the material library (frix_materials).
program test_materials
   use frix_testing, only: run_suites, new_testsuite
   use test_linear_elastic, only: collect_linear_elastic
   use test_saint_venant_kirchhoff, only: collect_saint_venant_kirchhoff
   use test_neo_hookean, only: collect_neo_hookean
   use test_abaqus_neo_hooke, only: collect_abaqus_neo_hooke
   use test_material_registry, only: collect_material_registry
   use test_von_mises, only: collect_von_mises
   use test_mohr_coulomb, only: collect_mohr_coulomb
   use test_drucker_prager, only: collect_drucker_prager
   use test_initial_stress, only: collect_initial_stress
   implicit none
   call run_suites([new_testsuite('linear_elastic', collect_linear_elastic), &
                    new_testsuite('saint_venant_kirchhoff', collect_saint_venant_kirchhoff), &
                    new_testsuite('neo_hookean', collect_neo_hookean), &
                    new_testsuite('abaqus_neo_hooke', collect_abaqus_neo_hooke), &
                    new_testsuite('material_registry', collect_material_registry), &
                    new_testsuite('von_mises', collect_von_mises), &
                    new_testsuite('mohr_coulomb', collect_mohr_coulomb), &
                    new_testsuite('drucker_prager', collect_drucker_prager), &
                    new_testsuite('initial_stress', collect_initial_stress)])
end program test_materials
