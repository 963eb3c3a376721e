# P2 reproducer of the first-increment friction defect (docs/performance-p2.md). Not included
# anywhere yet: the lead may include(bench/p2/p2_tests.cmake) from tests/CMakeLists.txt once
# frix initialises the slip anchors of initially touching slave nodes (it fails until then).
# FRIX_BIN: the frix executable, as in the other contact tests.
add_test(NAME p2_first_increment_friction
         COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_first_increment_friction.sh ${FRIX_BIN}
                 ${CMAKE_CURRENT_BINARY_DIR}/p2_first_increment_friction)
set_tests_properties(p2_first_increment_friction PROPERTIES LABELS "regression;contact")
