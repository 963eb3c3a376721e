#!/bin/bash
# check_example.sh FRIX EXAMPLE_SCRIPT: runs scripts/example_s1.sh with FRIX into a scratch
# folder and checks that it prints where the results and the plot are, and that the PNG, the
# theory CSV and the comparison table exist (the numbers are checked by run_s1.sh).
set -u
frix=$1; script=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0; failed=0
pass() { echo "PASS: $1"; passed=$((passed + 1)); }
fail() { echo "FAIL: $1"; failed=$((failed + 1)); }
if FRIX=$frix bash "$script" --out "$work/out" > "$work/log" 2>&1; then pass "example_s1.sh runs"
else fail "example_s1.sh failed: $(tail -n 5 "$work/log")"; fi
grep -q "^plot: *$work/out/s1_interface_ux.png" "$work/log" && pass "prints the plot's path" || fail "no plot line"
grep -q "^results: *$work/out/s1_rigid_plane.pvd" "$work/log" && pass "prints the results' path" || fail "no results line"
/usr/bin/python3 - "$work/out/s1_interface_ux.png" <<'PY' && pass "PNG written (>= 200 x 200 px, < 200 kB)" || fail "PNG"
import sys
data = open(sys.argv[1], "rb").read()
width, height = int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")
sys.exit(0 if data[:8] == b"\x89PNG\r\n\x1a\n" and width >= 200 and height >= 200 and len(data) < 200e3 else 1)
PY
[ "$(wc -l < "$work/out/s1_theory.csv")" -eq 202 ] && pass "theory CSV: header + 201 rows" || fail "theory CSV"
[ "$(grep -c '^ *[0-9]' "$work/out/s1_comparison.txt")" -eq 6 ] && pass "table: 6 load levels" || fail "table"
bash "$script" --bad > /dev/null 2>&1; [ $? -eq 2 ] && pass "unknown argument: status 2" || fail "unknown argument status"
echo "$passed passed, $failed failed"
[ $failed -eq 0 ]
