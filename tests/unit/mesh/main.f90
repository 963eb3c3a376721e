!> Unit tests of the mesh library (frix_mesh): scanner, id map, gmsh reader, mesh checks, block generator,
!> plane meshes of the gmsh and .inp readers.
program test_mesh
   use frix_testing, only: run_suites, new_testsuite
   use test_text_scanner, only: collect_text_scanner
   use test_id_map, only: collect_id_map
   use test_gmsh_reader, only: collect_gmsh_reader, collect_gmsh_errors
   use test_mesh_checks, only: collect_mesh_checks
   use test_block_generator, only: collect_block_generator
   use test_plane_meshes, only: collect_plane_meshes, collect_plane_errors
   implicit none
   call run_suites([new_testsuite('text_scanner', collect_text_scanner), &
                    new_testsuite('id_map', collect_id_map), &
                    new_testsuite('gmsh_reader', collect_gmsh_reader), &
                    new_testsuite('gmsh_errors', collect_gmsh_errors), &
                    new_testsuite('mesh_checks', collect_mesh_checks), &
                    new_testsuite('block_generator', collect_block_generator), &
                    new_testsuite('plane_meshes', collect_plane_meshes), &
                    new_testsuite('plane_mesh_errors', collect_plane_errors)])
end program test_mesh
