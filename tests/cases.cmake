# Deck-level tests. The frix binary is run on decks; each family has its own label.
set(FRIX_BIN $<TARGET_FILE:frix>)

# Error cases: every tests/errors/*.dck must be rejected with the message given in its
# `// EXPECT:` lines, without a crash.
file(GLOB error_decks CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/errors/*.dck)
foreach(deck ${error_decks})
  get_filename_component(name ${deck} NAME_WE)
  add_test(NAME errors_${name}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/errors/check_error_case.sh ${FRIX_BIN} ${deck})
  set_tests_properties(errors_${name} PROPERTIES LABELS errors)
endforeach()

# Output checks (shell): VTK files read back with meshio; the listing comparison script.
add_test(NAME io_vtk_readback COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/vtk_readback_test.sh $<TARGET_FILE:test_io>)
add_test(NAME compare_selftest COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/compare_selftest.sh)
set_tests_properties(io_vtk_readback compare_selftest PROPERTIES LABELS unit)
