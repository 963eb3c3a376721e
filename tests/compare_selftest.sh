#!/bin/bash
# Self-test of tests/compare.sh: builds small listings in a temporary folder and asserts the
# exit status (0 equal within tolerance, 1 different, 2 usage error) of each case.
# Usage: compare_selftest.sh   (finds compare.sh next to itself). Exit 0 if every case passes.
set -u
compare=$(cd "$(dirname "$0")" && pwd)/compare.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# listing UX_102 RX_101 TEXT DATE: a two-increment listing in the documented format where
# UX of node 102, RX of node 101 and the title of the reaction block can be varied.
listing() {
    cat << LISTING
# frix listing, format: docs/listing-format.md
# written $4
STEP     1  INCREMENT     1  TIME  1.000000000E+000  ITERATIONS     2
ITERATION LOG
      ITER     RESIDUAL_NORM
         1  1.000000000E+003
         2  3.000000000E-011
NODAL DISPLACEMENTS
      NODE                UX                UY                UZ
       101  0.000000000E+000  0.000000000E+000  0.000000000E+000
       102  $1  0.000000000E+000 -2.000000000E-003
$3
      NODE                RX                RY                RZ
       101  $2  0.000000000E+000  5.000000000E+001
SUM OF REACTIONS
                          RX                RY                RZ
     TOTAL -1.000000000E+002  0.000000000E+000  5.000000000E+001
LISTING
}

# expect STATUS NAME ARGS...: run compare.sh ARGS and check its exit status.
expect() {
    local expected=$1 name=$2
    shift 2
    "$compare" "$@" > "$work/out.txt" 2>&1
    local actual=$?
    if [ "$actual" -eq "$expected" ]; then
        echo "  ok    $name (exit $actual)"
    else
        echo "  FAIL  $name: exit $actual, expected $expected"
        sed 's/^/        /' "$work/out.txt"
        failures=$((failures + 1))
    fi
}

reactions="REACTIONS (constrained DOFs only)"
listing " 1.000000000E-003" "-1.000000000E+002" "$reactions" "2024-01-01" > "$work/old.lst"
# Equal within tolerance: UX changed by 1e-9 relative, RX by 5e-8 relative; another date.
listing " 1.000000001E-003" "-1.000000050E+002" "$reactions" "2025-06-30" > "$work/close.lst"
# One value differs by 1e-3 relative.
listing " 1.001000000E-003" "-1.000000000E+002" "$reactions" "2024-01-01" > "$work/value.lst"
# Round-off noise 3e-15 where OLD has 0, in a block whose largest value is 2e-3: passes with
# the scaled absolute tolerance (1e-9 x 2e-3 = 2e-12), fails with --abs 0.
sed 's/^       101  0.000000000E+000  0.000000000E+000  0.000000000E+000$/       101  3.000000000E-015 -1.000000000E-016  0.000000000E+000/' \
    "$work/old.lst" > "$work/noise.lst"
# Text difference in a block title.
listing " 1.000000000E-003" "-1.000000000E+002" "REACTIONS (all DOFs)" "2024-01-01" > "$work/text.lst"
# A block missing (the sum of reactions).
head -n 15 "$work/old.lst" > "$work/short.lst"
# Iteration count differs (an integer field).
sed 's/ITERATIONS     2/ITERATIONS     3/' "$work/old.lst" > "$work/iterations.lst"

expect 0 "identical files" "$work/old.lst" "$work/old.lst"
expect 0 "equal within tolerance, comment lines differ" "$work/old.lst" "$work/close.lst"
expect 1 "one value differs" "$work/old.lst" "$work/value.lst"
grep -q 'NODAL DISPLACEMENTS' "$work/out.txt" && grep -q 'OLD line 11, field 2' "$work/out.txt" || {
    echo "  FAIL  the report names the block and the line"; failures=$((failures + 1)); }
expect 0 "value difference accepted with --rel 1e-2" "$work/old.lst" "$work/value.lst" --rel 1e-2
expect 0 "near-zero noise in a block of large values" "$work/old.lst" "$work/noise.lst"
expect 1 "near-zero noise fails without the block-scaled tolerance" "$work/old.lst" "$work/noise.lst" --abs 0
expect 1 "text difference" "$work/old.lst" "$work/text.lst"
expect 1 "missing block" "$work/old.lst" "$work/short.lst"
expect 1 "different iteration count" "$work/old.lst" "$work/iterations.lst"
expect 2 "missing file" "$work/old.lst" "$work/does_not_exist.lst"
expect 2 "one argument only" "$work/old.lst"
expect 2 "bad tolerance" "$work/old.lst" "$work/old.lst" --rel abc
expect 2 "unknown option" "$work/old.lst" "$work/old.lst" --relative 1e-3

if [ $failures -eq 0 ]; then
    echo "compare selftest: all cases passed"
    exit 0
fi
echo "compare selftest: $failures failed"
exit 1
