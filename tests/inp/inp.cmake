# The Abaqus/CalculiX .inp mesh reader (tests/inp/README.md): a cantilever meshed by CalculiX
# GraphiX against CalculiX and MESH BLOCK, one hexahedron's six faces against CalculiX, and
# the reader's features against a closed form.
set(inp_run bash ${CMAKE_CURRENT_SOURCE_DIR}/inp/run_inp_case.sh ${FRIX_BIN})
add_test(NAME inp_cantilever COMMAND ${inp_run} check_cantilever.py cantilever_inp.dck cantilever_block.dck
         -- cantilever_ccx.dat)
add_test(NAME inp_faces COMMAND ${inp_run} check_faces.py faces.dck -- faces_ccx.dat)
add_test(NAME inp_features COMMAND ${inp_run} check_features.py features.dck)
set_tests_properties(inp_cantilever inp_faces inp_features PROPERTIES LABELS regression TIMEOUT ${scaled_60})
