# Regression test for the first-increment friction defect found by P2 (docs/performance-p2.md;
# fixed 2026-11-23: slip anchors start at the reference foot points). Included from
# tests/cases.cmake.
# FRIX_BIN: the frix executable, as in the other contact tests.
add_test(NAME p2_first_increment_friction
         COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/check_first_increment_friction.sh ${FRIX_BIN}
                 ${CMAKE_CURRENT_BINARY_DIR}/p2_first_increment_friction)
set_tests_properties(p2_first_increment_friction PROPERTIES LABELS "regression;contact")
