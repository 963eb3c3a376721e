!> Unit tests of the element library (frix_elements).
program test_elements
   use frix_testing, only: run_suites, new_testsuite
   use test_hex8, only: collect_hex8
   use test_hex8_thin, only: collect_hex8_thin
   use test_element_registry, only: collect_element_registry
   use test_surface_load, only: collect_surface_load
   use test_tet4, only: collect_tet4
   use test_tet10, only: collect_tet10
   use test_element_initial_stress, only: collect_element_initial_stress
   use test_hex8_degenerate, only: collect_hex8_degenerate
   use test_plane_solid, only: collect_plane_solid
   implicit none
   call run_suites([new_testsuite('hex8', collect_hex8), &
                    new_testsuite('hex8_thin', collect_hex8_thin), &
                    new_testsuite('element_registry', collect_element_registry), &
                    new_testsuite('surface_load', collect_surface_load), &
                    new_testsuite('tet4', collect_tet4), &
                    new_testsuite('tet10', collect_tet10), &
                    new_testsuite('initial_stress', collect_element_initial_stress), &
                    new_testsuite('hex8_degenerate', collect_hex8_degenerate), &
                    new_testsuite('plane_solid', collect_plane_solid)])
end program test_elements
