#!/bin/bash
# Test of postproc/plot_history.py and of frix_results.read_history / read_listing on a real
# frix run (the 4-element bar of postproc_test_lib.sh).
# Usage: test_plot_history.sh <path of the frix executable>; exit 0 if all checks pass.
source "$(dirname "$0")/postproc_test_lib.sh"
run_bar_deck
OUT=$WORK/out

# 1. The history values read by frix_results against the exact solution and the listing.
#    Exact: u_x(x = 4) = t * 3 * 4 / 2000 = 6e-3 t; the reaction at node 101 (one of the 4
#    nodes of the face x = 0, each carrying a quarter of the total 3 t) = -0.75 t. Tolerance
#    1e-12 relative: the solve is exact up to round-off (a few ulp of the assembled sums).
#    The listing prints 10 significant digits: it must agree to 5e-10 relative.
if message=$("$PYTHON" - "$POSTPROC" "$OUT" <<'PY' 2>&1
import sys
sys.path.insert(0, sys.argv[1])
import numpy as np
import frix_results
out = sys.argv[2]
history = frix_results.read_history(f"{out}/bar_history.csv")
assert history.columns == ["step", "increment", "time", "u1_n105", "r1_n101"], history.columns
time = history.column("time")
assert np.array_equal(time, [0.5, 1.0]), time
assert np.allclose(history.column("u1_n105"), 6e-3 * time, rtol=1e-12, atol=0), \
    history.column("u1_n105")
assert np.allclose(history.column("r1_n101"), -0.75 * time, rtol=1e-12, atol=0), \
    history.column("r1_n101")
listing = frix_results.read_listing(f"{out}/bar_listing.txt")
assert [(i.step, i.increment) for i in listing] == [(1, 1), (1, 2)]
for row, increment in enumerate(listing):
    assert increment.time == time[row]
    _, labels, keys, values = increment.blocks["NODAL DISPLACEMENTS"]
    assert labels == ["UX", "UY", "UZ"] and keys == list(range(101, 121)), (labels, keys)
    ux = values[keys.index(105), 0]
    assert abs(ux - history.column("u1_n105")[row]) <= 5e-10 * abs(ux), ux
    _, labels, keys, values = increment.blocks["REACTIONS (constrained DOFs only)"]
    rx = values[keys.index(101), 0]
    assert abs(rx - history.column("r1_n101")[row]) <= 5e-10 * abs(rx), rx
    _, labels, keys, values = increment.blocks["SUM OF REACTIONS"]
    assert keys == ["TOTAL"] and abs(values[0, 0] + 3.0 * time[row]) <= 5e-10 * 3.0 * time[row]
print("history and listing agree with u = 6e-3 t, r = -0.75 t")
PY
); then pass "read_history/read_listing: $message"; else fail "read_history/read_listing: $message"; fi

# 2. Figures: default (all DOF columns against time), displacement on x with time and the
#    reaction on y, two files with labels.
cp "$OUT/bar_history.csv" "$WORK/copy_history.csv"
if "$PYTHON" "$POSTPROC/plot_history.py" "$OUT/bar_history.csv" -o "$WORK/default.png" \
        > "$WORK/log.txt" 2>&1; then
    check_png "$WORK/default.png" "plot_history default columns"
else
    fail "plot_history default columns: $(cat "$WORK/log.txt")"
fi
if "$PYTHON" "$POSTPROC/plot_history.py" "$OUT/bar_history.csv" "$WORK/copy_history.csv" \
        --x u1_n105 --y time,-r1_n101 --labels "run a,run b" \
        --title "bar: load-displacement" -o "$WORK/curve.png" > "$WORK/log.txt" 2>&1; then
    check_png "$WORK/curve.png" "plot_history --x u1_n105 --y time,-r1_n101, two files"
else
    fail "plot_history --x/--y: $(cat "$WORK/log.txt")"
fi
#    --curve: time becomes the load factor f(time) of a deck's load curve (piecewise linear,
#    constant beyond its ends); the bar's times 0.5 and 1 give f = 5 and 10 on 0 0 1 10 2 10.
if message=$("$PYTHON" - "$POSTPROC" "$OUT" <<'PY' 2>&1
import sys
sys.path.insert(0, sys.argv[1])
import numpy as np
import frix_results
import plot_history
history = frix_results.read_history(f"{sys.argv[2]}/bar_history.csv")
curve = plot_history.parse_curve("0,0,1,10,2,10")
assert np.array_equal(plot_history.signed_column(history, "time", curve), [5.0, 10.0])
assert np.array_equal(plot_history.signed_column(history, "-time", curve), [-5.0, -10.0])
assert np.array_equal(plot_history.signed_column(history, "time"), [0.5, 1.0])
assert np.array_equal(plot_history.parse_curve("0 0 0.25 1")[1], [0.0, 1.0])
print("time -> f(time): 0.5 -> 5, 1 -> 10")
PY
); then pass "plot_history --curve values: $message"; else fail "plot_history --curve values: $message"; fi
if "$PYTHON" "$POSTPROC/plot_history.py" "$OUT/bar_history.csv" --x u1_n105 --y time \
        --curve 0,0,1,10,2,10 -o "$WORK/curve_factor.png" > "$WORK/log.txt" 2>&1; then
    check_png "$WORK/curve_factor.png" "plot_history --curve"
else
    fail "plot_history --curve: $(cat "$WORK/log.txt")"
fi
if "$PYTHON" "$POSTPROC/plot_history.py" --help | grep -q -- "--labels"; then
    pass "plot_history --help"
else
    fail "plot_history --help"
fi

# 3. User mistakes: one line, exit 2, no traceback.
printf 'step,increment,time,u1_n1\n1,1,0.5\n' > "$WORK/short_history.csv"
printf 'step,increment,time,u1_n1\n1,1,0.5,abc\n' > "$WORK/text_history.csv"
: > "$WORK/empty_history.csv"
expect_user_error "missing file" "not found: $WORK/missing.csv" \
    "$PYTHON" "$POSTPROC/plot_history.py" "$WORK/missing.csv" -o "$WORK/x.png"
expect_user_error "missing column" "no column 'u3_n7'" \
    "$PYTHON" "$POSTPROC/plot_history.py" "$OUT/bar_history.csv" --y u3_n7 -o "$WORK/x.png"
expect_user_error "missing x column" "no column 'u9_n1'" \
    "$PYTHON" "$POSTPROC/plot_history.py" "$OUT/bar_history.csv" --x u9_n1 -o "$WORK/x.png"
expect_user_error "short row" "line 2: 3 fields, header has 4" \
    "$PYTHON" "$POSTPROC/plot_history.py" "$WORK/short_history.csv" -o "$WORK/x.png"
expect_user_error "text in a number field" "line 2: not a number" \
    "$PYTHON" "$POSTPROC/plot_history.py" "$WORK/text_history.csv" -o "$WORK/x.png"
expect_user_error "empty file" "empty file" \
    "$PYTHON" "$POSTPROC/plot_history.py" "$WORK/empty_history.csv" -o "$WORK/x.png"
expect_user_error "label count" "--labels has 1 labels for 2 CSV files" \
    "$PYTHON" "$POSTPROC/plot_history.py" "$OUT/bar_history.csv" "$WORK/copy_history.csv" \
    --labels one -o "$WORK/x.png"
expect_user_error "unwritable output" "cannot write $WORK/no/such/dir/x.png" \
    "$PYTHON" "$POSTPROC/plot_history.py" "$OUT/bar_history.csv" -o "$WORK/no/such/dir/x.png"
expect_user_error "odd curve" "--curve needs pairs T,F (at least two)" \
    "$PYTHON" "$POSTPROC/plot_history.py" "$OUT/bar_history.csv" --curve 0,0,1 -o "$WORK/x.png"
expect_user_error "curve times" "--curve: the times must increase strictly" \
    "$PYTHON" "$POSTPROC/plot_history.py" "$OUT/bar_history.csv" --curve 0,0,0,1 -o "$WORK/x.png"
expect_user_error "curve text" "--curve: not a number" \
    "$PYTHON" "$POSTPROC/plot_history.py" "$OUT/bar_history.csv" --curve 0,0,a,1 -o "$WORK/x.png"
[ ! -e "$WORK/x.png" ] && pass "no figure written on errors" || fail "a figure was written despite errors"
finish
