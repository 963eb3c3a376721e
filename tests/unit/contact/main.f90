!> Unit tests of the contact library (frix_contact).
program test_contact
   use frix_testing, only: run_suites, new_testsuite
   use test_dual_number, only: collect_dual_number
   use test_face_projection, only: collect_face_projection
   use test_friction_law_registry, only: collect_friction_law_registry
   use test_normal_contact_law, only: collect_normal_contact_law
   use test_augmented_normal_law, only: collect_augmented_normal_law
   use test_contact_tangent, only: collect_contact_tangent
   use test_contact_physics, only: collect_contact_physics
   use test_contact_patches, only: collect_contact_patches
   use test_contact_search, only: collect_contact_search
   use test_smoothed_normals, only: collect_smoothed_normals
   use test_mortar_contact, only: collect_mortar_contact
   use test_face_grid, only: collect_face_grid
   use test_plane_faces, only: collect_plane_faces
   implicit none
   call run_suites([new_testsuite('dual_number', collect_dual_number), &
                    new_testsuite('face_projection', collect_face_projection), &
                    new_testsuite('friction_law_registry', collect_friction_law_registry), &
                    new_testsuite('normal_contact_law', collect_normal_contact_law), &
                    new_testsuite('augmented_normal_law', collect_augmented_normal_law), &
                    new_testsuite('contact_tangent', collect_contact_tangent), &
                    new_testsuite('contact_physics', collect_contact_physics), &
                    new_testsuite('contact_patches', collect_contact_patches), &
                    new_testsuite('contact_search', collect_contact_search), &
                    new_testsuite('smoothed_normals', collect_smoothed_normals), &
                    new_testsuite('mortar_contact', collect_mortar_contact), &
                    new_testsuite('face_grid', collect_face_grid), &
                    new_testsuite('plane_faces', collect_plane_faces)])
end program test_contact
