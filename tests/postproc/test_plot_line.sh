#!/bin/bash
# Test of postproc/plot_line.py on a real frix run (the 4-element bar of postproc_test_lib.sh):
# the sampled u_x along the bar must be the exact u_x(x) = t * 3 x / 2000 (uniaxial tension
# 3 t, E = 2000, nu = 0, fixed at x = 0; HEX8 reproduces this linear field exactly, so only
# round-off remains: tolerance 1e-12 x the largest |u|).
# Usage: test_plot_line.sh <path of the frix executable>; exit 0 if all checks pass.
source "$(dirname "$0")/postproc_test_lib.sh"
run_bar_deck
OUT=$WORK/out
LINE=("$PYTHON" "$POSTPROC/plot_line.py")

# check_csv FILE WHAT EXPECTED_ROWS PYTHON_CHECK: reads the --csv output as a dict of columns
# (`c`) and runs the check (assert statements) on it.
check_csv() {
    local message
    if message=$("$PYTHON" - "$1" "$3" "$4" <<'PY' 2>&1
import csv, sys
import numpy as np
with open(sys.argv[1]) as stream:
    rows = list(csv.DictReader(stream))
assert len(rows) == int(sys.argv[2]), f"{len(rows)} rows, expected {sys.argv[2]}"
c = {key: np.array([float(row[key]) if row[key] != "" else np.nan for row in rows])
     for key in rows[0]}
exact = c["time"] * 3.0 * c["x"] / 2000.0        # u_x = t p x / E, p = 3, E = 2000
tolerance = 1e-12 * 6e-3                         # 1e-12 x the largest |u| (x = 4, t = 1)
exec(sys.argv[3])
print("ok")
PY
    ); then pass "$2"; else fail "$2: $message"; fi
}

# 1. --line along the edge y = z = 0, every increment, analytic expression, CSV.
if "${LINE[@]}" "$OUT/bar.pvd" --line 0,0,0,4,0,0 --field displacement:x --increments all \
        --analytic "t * 3 * x / 2000" --csv "$WORK/line.csv" -o "$WORK/line.png" \
        > "$WORK/log.txt" 2>&1; then
    check_png "$WORK/line.png" "plot_line --line, all increments, analytic"
    check_csv "$WORK/line.csv" "CSV of --line: 5 nodes x 2 increments, ids 101..105, u = t 3 x / 2000" 10 '
assert np.array_equal(c["time"], [0.5] * 5 + [1.0] * 5), c["time"]
assert np.array_equal(c["node_id"], list(range(101, 106)) * 2), c["node_id"]
assert np.array_equal(c["x"], [0, 1, 2, 3, 4] * 2) and not np.any(c["y"]) and not np.any(c["z"])
assert np.array_equal(c["position"], c["x"])
assert np.max(np.abs(c["value"] - exact)) <= tolerance, np.max(np.abs(c["value"] - exact))
assert np.max(np.abs(c["analytic"] - exact)) <= 1e-15, "analytic column"
'
else
    fail "plot_line --line: $(cat "$WORK/log.txt")"
fi

# 2. A reversed line on the edge y = z = 1: position = 4 - x, sorted by position; ids 116..120.
if "${LINE[@]}" "$OUT/bar.pvd" --line 4,1,1,0,1,1 --increments 1:2 --csv "$WORK/reverse.csv" \
        -o "$WORK/reverse.png" > "$WORK/log.txt" 2>&1; then
    check_csv "$WORK/reverse.csv" "CSV of a reversed --line: position = 4 - x, ids 120..116" 5 '
assert np.array_equal(c["position"], [0, 1, 2, 3, 4]) and np.array_equal(c["x"], [4, 3, 2, 1, 0])
assert np.array_equal(c["node_id"], [120, 119, 118, 117, 116]), c["node_id"]
assert np.all(c["time"] == 1.0) and np.max(np.abs(c["value"] - exact)) <= tolerance
'
else
    fail "plot_line reversed --line: $(cat "$WORK/log.txt")"
fi

# 3. Node set file of user ids (mapped through the listing): the face x = 4 and node 103.
printf '# face x = 4 and the middle node\n105, 110\n115 120\n103\n' > "$WORK/ids.txt"
if "${LINE[@]}" "$OUT/bar.pvd" --node-set "$WORK/ids.txt" --increments 1 \
        --csv "$WORK/set.csv" -o "$WORK/set.png" > "$WORK/log.txt" 2>&1; then
    check_csv "$WORK/set.csv" "CSV of --node-set (user ids): first increment, sorted along x" 5 '
assert np.array_equal(c["node_id"], [103, 105, 110, 115, 120]), c["node_id"]
assert np.array_equal(c["x"], [2, 4, 4, 4, 4]) and np.all(c["time"] == 0.5)
assert np.max(np.abs(c["value"] - exact)) <= tolerance
'
else
    fail "plot_line --node-set: $(cat "$WORK/log.txt")"
fi
printf '1 2 3 4 5\n' > "$WORK/internal.txt"
if "${LINE[@]}" "$OUT/bar_0001_0002.vtu" --node-set "$WORK/internal.txt" --node-numbering internal \
        --listing "$OUT/bar_listing.txt" --csv "$WORK/internal.csv" -o "$WORK/internal.png" \
        > "$WORK/log.txt" 2>&1; then
    check_csv "$WORK/internal.csv" "CSV of --node-set internal numbers 1..5 = ids 101..105 (one .vtu)" 5 '
assert np.array_equal(c["node_id"], range(101, 106)) and np.array_equal(c["point"], range(1, 6))
assert np.max(np.abs(c["value"] - exact)) <= tolerance
'
else
    fail "plot_line --node-numbering internal: $(cat "$WORK/log.txt")"
fi

# 4. Analytical curves from a CSV (with header) and --merge of coincident positions.
printf 'x,t=0.5,t=1\n0,0,0\n4,3e-3,6e-3\n' > "$WORK/analytic.csv"
if "${LINE[@]}" "$OUT/bar.pvd" --node-set "$WORK/ids.txt" --merge --increments all \
        --analytic-csv "$WORK/analytic.csv" -o "$WORK/merged.png" > "$WORK/log.txt" 2>&1; then
    check_png "$WORK/merged.png" "plot_line --analytic-csv --merge"
else
    fail "plot_line --analytic-csv: $(cat "$WORK/log.txt")"
fi

# 5. User mistakes: one line, exit 2, no traceback.
expect_user_error "missing result" "not found: $WORK/none.pvd" \
    "${LINE[@]}" "$WORK/none.pvd" --line 0,0,0,4,0,0 -o "$WORK/x.png"
expect_user_error "malformed --line" "--line needs 6 comma-separated numbers" \
    "${LINE[@]}" "$OUT/bar.pvd" --line 0,0,4,0,0 -o "$WORK/x.png"
expect_user_error "line without nodes" "no node within" \
    "${LINE[@]}" "$OUT/bar.pvd" --line 0,0.5,0,4,0.5,0 -o "$WORK/x.png"
expect_user_error "unknown field" "no point field 'displacment'" \
    "${LINE[@]}" "$OUT/bar.pvd" --line 0,0,0,4,0,0 --field displacment:0 -o "$WORK/x.png"
expect_user_error "component out of range" "has 3 components (0..2), not 3" \
    "${LINE[@]}" "$OUT/bar.pvd" --line 0,0,0,4,0,0 --field displacement:3 -o "$WORK/x.png"
expect_user_error "tensor without component" "choose one as stress:INDEX" \
    "${LINE[@]}" "$OUT/bar.pvd" --line 0,0,0,4,0,0 --field stress -o "$WORK/x.png"
expect_user_error "expression with a builtin" "unknown name '__import__'" \
    "${LINE[@]}" "$OUT/bar.pvd" --line 0,0,0,4,0,0 --analytic "__import__('os')" -o "$WORK/x.png"
expect_user_error "expression with a dunder attribute" "only np.<function> attributes" \
    "${LINE[@]}" "$OUT/bar.pvd" --line 0,0,0,4,0,0 --analytic "x.__class__" -o "$WORK/x.png"
expect_user_error "expression syntax" "bad expression" \
    "${LINE[@]}" "$OUT/bar.pvd" --line 0,0,0,4,0,0 --analytic "3 x" -o "$WORK/x.png"
expect_user_error "unknown node id" "node id(s) not in the mesh: [7]" \
    "${LINE[@]}" "$OUT/bar.pvd" --node-set <(echo "101 7") -o "$WORK/x.png"
expect_user_error "unknown increment" "no increment 3:1 (available: 1:1, 1:2)" \
    "${LINE[@]}" "$OUT/bar.pvd" --line 0,0,0,4,0,0 --increments 3:1 -o "$WORK/x.png"
expect_user_error "no selection" "give --line" \
    "${LINE[@]}" "$OUT/bar.pvd" -o "$WORK/x.png"
mkdir -p "$WORK/broken"
cp "$OUT/bar.pvd" "$WORK/broken/bar.pvd"
expect_user_error "pvd entry without its vtu" "vtu file not found: $WORK/broken/bar_0001_0002.vtu" \
    "${LINE[@]}" "$WORK/broken/bar.pvd" --line 0,0,0,4,0,0 -o "$WORK/x.png"
head -c 400 "$OUT/bar_0001_0002.vtu" > "$WORK/broken/truncated.vtu"
expect_user_error "truncated vtu" "cannot read $WORK/broken/truncated.vtu" \
    "${LINE[@]}" "$WORK/broken/truncated.vtu" --line 0,0,0,4,0,0 -o "$WORK/x.png"
echo '<VTKFile><Collection>' > "$WORK/broken/bad.pvd"
expect_user_error "malformed pvd" "not a readable .pvd" \
    "${LINE[@]}" "$WORK/broken/bad.pvd" --line 0,0,0,4,0,0 -o "$WORK/x.png"
[ ! -e "$WORK/x.png" ] && pass "no figure written on errors" || fail "a figure was written despite errors"
finish
