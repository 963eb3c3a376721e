# Plane meshes read from files (tests/mesh2d/README.md): the plane strain cantilever of
# tests/plane/beam_plane.dck on an Abaqus/CalculiX mesh (beam.inp, MESH BLOCK's numbering:
# the same tip displacement of node 105 to round-off) and on a gmsh mesh (beam.msh: the same
# mean tip displacements as beam.inp's to 1e-9, gmsh placing its nodes to about 1e-12).
set(mesh2d_dir ${CMAKE_CURRENT_SOURCE_DIR}/mesh2d)
add_test(NAME mesh2d_beam_inp
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/plane/run_pair.sh ${FRIX_BIN} ${mesh2d_dir}/beam_inp.dck
                 ${CMAKE_CURRENT_SOURCE_DIR}/plane/beam_plane.dck 1e-9 u2_n105 u1_n105)
add_test(NAME mesh2d_beam_gmsh
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/plane/run_pair.sh ${FRIX_BIN} ${mesh2d_dir}/beam_gmsh.dck
                 ${mesh2d_dir}/beam_inp.dck 1e-9 u2_mean_beam_xmax u1_mean_beam_xmax)
set_tests_properties(mesh2d_beam_inp mesh2d_beam_gmsh PROPERTIES LABELS regression TIMEOUT ${scaled_60})
