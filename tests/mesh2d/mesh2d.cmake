# Plane meshes read from files (tests/mesh2d/README.md): the plane strain cantilever of
# tests/plane/beam_plane.dck with a pressure on its top edges, on an Abaqus/CalculiX mesh
# (beam.inp, MESH BLOCK's numbering, the top edges a *SURFACE of S3 faces: node 105's
# displacements those of the same model by MESH BLOCK, beam_block.dck, to 1e-12: bit for bit measured), and on
# a gmsh mesh (beam.msh, the top edges a physical curve: the mean tip displacements those of
# beam.inp to 1e-11 (measured 1e-13), gmsh placing its nodes to about 1e-12). Equilibrium: the clamp's reaction
# is the tip force 0.01 plus the pressure 0.001 times the top's length 10 and thickness 0.1.
set(mesh2d_dir ${CMAKE_CURRENT_SOURCE_DIR}/mesh2d)
set(mesh2d_pair bash ${CMAKE_CURRENT_SOURCE_DIR}/plane/run_pair.sh ${FRIX_BIN})
add_test(NAME mesh2d_beam_inp
         COMMAND ${mesh2d_pair} ${mesh2d_dir}/beam_inp.dck ${mesh2d_dir}/beam_block.dck 1e-12 u2_n105 u1_n105)
add_test(NAME mesh2d_beam_gmsh
         COMMAND ${mesh2d_pair} ${mesh2d_dir}/beam_gmsh.dck ${mesh2d_dir}/beam_inp.dck 1e-11
                 u2_mean_beam_xmax u1_mean_beam_xmax)
add_test(NAME mesh2d_beam_gmsh_equilibrium
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${mesh2d_dir}/beam_gmsh.dck
                 ${CMAKE_CURRENT_SOURCE_DIR}/plane/check_plane.py history r2_sum_beam_xmin=0.011:1e-9)
set_tests_properties(mesh2d_beam_inp mesh2d_beam_gmsh mesh2d_beam_gmsh_equilibrium
                     PROPERTIES LABELS regression TIMEOUT ${scaled_60})
# Patch test on the gmsh plane mesh of the reader's unit tests (PLANE4 on its quadrilaterals,
# PLANE3 on its triangles): the interior nodes follow the linear field imposed on the boundary,
# u = 1e-3 (x + y/2), v = 1e-3 (y + x/2) at the file's coordinates, to the patch test's 1e-10 (measured 5e-16).
add_test(NAME mesh2d_patch_gmsh
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${mesh2d_dir}/patch_gmsh.dck
                 ${CMAKE_CURRENT_SOURCE_DIR}/plane/check_plane.py history
                 u1_n13=0.001249999999999346:1e-10 u2_n13=0.000999999999998692:1e-10
                 u1_n14=0.0007500000000005637:1e-10 u2_n14=0.0007500000000005637:1e-10
                 u1_n15=0.001749999999999346:1e-10 u2_n15=0.0012499999999986923:1e-10)
set_tests_properties(mesh2d_patch_gmsh PROPERTIES LABELS regression TIMEOUT ${scaled_60})
