# Fuzzing of the deck and gmsh readers and of the analysis behind them (tests/fuzz/README.md):
# mutated copies of small decks and meshes are run through frix, which must not crash, hang,
# reject a deck without naming the line, or finish with NaN / Inf in its results.
# Included from tests/cases.cmake (FRIX_BIN = $<TARGET_FILE:frix>).
# Python with h5py (Debian's /usr/bin/python3, scripts/setup.sh) so that .h5 results are checked.
math(EXPR scaled_600 "600 * ${FRIX_TIMEOUT_SCALE}")
if(EXISTS /usr/bin/python3)
  set(FRIX_FUZZ_PYTHON /usr/bin/python3)
else()
  find_program(FRIX_FUZZ_PYTHON NAMES python3 REQUIRED)
endif()
set(frix_fuzz ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_decks.py)

# Write failures are injected by tests/io/fail_writes.c (target frix_fail_writes, tests/cases.cmake).
set(frix_fail_writes_library $<TARGET_FILE:frix_fail_writes>)

# Default run: 560 mutants and 50 fault runs of seed 1 (about 25 s on 2 cores).
add_test(NAME fuzz_decks
         COMMAND ${FRIX_FUZZ_PYTHON} ${frix_fuzz} --frix ${FRIX_BIN} --seed 1 --count 560 --jobs 2
                 --faults 50 --fail-writes ${frix_fail_writes_library}
                 --failures-dir ${CMAKE_CURRENT_BINARY_DIR}/fuzz_failures)
set_tests_properties(fuzz_decks PROPERTIES LABELS "regression;fuzz" PROCESSORS 2 TIMEOUT ${scaled_600})

# Large run: 5000 other mutants and 500 fault runs (seed 2); label slow, left out of
# `ctest -LE slow`.
add_test(NAME fuzz_decks_large
         COMMAND ${FRIX_FUZZ_PYTHON} ${frix_fuzz} --frix ${FRIX_BIN} --seed 2 --count 5000 --jobs 2
                 --faults 500 --fail-writes ${frix_fail_writes_library}
                 --failures-dir ${CMAKE_CURRENT_BINARY_DIR}/fuzz_failures_large)
set_tests_properties(fuzz_decks_large PROPERTIES LABELS "fuzz;slow" PROCESSORS 2 TIMEOUT 3600)
