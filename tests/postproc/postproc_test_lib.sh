#!/bin/bash
# Shared setup of the post-processing tests (tests/postproc/test_*.sh); sourced, not run.
# Provides: $PYTHON, $POSTPROC (the scripts' folder), $WORK (a temp dir removed on exit),
# run_bar_deck (runs frix on a 4-element bar into $WORK/out), check_png, expect_user_error,
# pass/fail counters and finish (prints "N passed, N failed" and sets the exit status).
set -u
if [ $# -ne 1 ] || [ ! -x "$1" ]; then
    echo "usage: $0 <path of the frix executable>" >&2
    exit 2
fi
FRIX=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
PYTHON=/usr/bin/python3
export PYTHONDONTWRITEBYTECODE=1   # keep postproc/ free of __pycache__
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
POSTPROC=$(cd "$HERE/../../postproc" && pwd)
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
PASSED=0
FAILED=0

pass() { PASSED=$((PASSED + 1)); echo "PASS: $*"; }
fail() { FAILED=$((FAILED + 1)); echo "FAIL: $*"; }

finish() {
    echo "$PASSED passed, $FAILED failed"
    [ "$FAILED" -eq 0 ]
    exit $?
}

# A 4 x 1 x 1 bar of HEX8 (E = 2000, nu = 0), fixed at x = 0, pulled at x = 4 by a pressure
# -3 (tension 3) following curve 1 (load factor = time), 2 increments (t = 0.5, 1).
# Exact solution (uniaxial stress, nu = 0; HEX8 reproduces a linear field exactly):
#   u_x(x) = t * 3 * x / 2000, sigma_xx = 3 t, reaction at each x = 0 node = -3 t / 4.
# NODE_OFFSET 100: user node ids 101..120 (x fastest: id = 101 + i + 5 (j + 2 k)), which
# differ from the internal numbers 1..20, so the id mapping through the listing is tested.
run_bar_deck() {
    cat > "$WORK/bar.dck" <<'DECK'
 bar4: 4 x 1 x 1 bar of four HEX8, fixed at x = 0, pulled at x = 4 by a pressure -3
 (tension 3), E = 2000, nu = 0: u_x(x) = lambda 3 x / 2000, lambda = load factor = time.
---------------------------------------------------------PROBLEM TYP
PROBLEMTYP   Structure
--------------------------------------------------------------STATIC
KINTYP       Geo_Lin
MAXITER      20
TOLRESID     1.0e-10
TOLDISP      1.0e-10
MAXCUT       4
SOLVER       Auto
NEWTONRAPHSO Load_Control
---------------------------------------------------------LOAD CURVES
CURVE 1 POINTS 0.0 0.0  1.0 1.0
-----------------------------------------------------------MATERIALS
MAT 1 MAT_Struct_LinearElastic YOUNG 2000.0 NUE 0.0 DENS 0.0
----------------------------------------------------------MESH BLOCK
BLOCK bar ORIGIN 0 0 0 SIZE 4 1 1 DIVISIONS 4 1 1 NODE_OFFSET 100 ELEMENT_OFFSET 50
--------------------------------------------------STRUCTURE ELEMENTS
SET bar SOLID HEX8 MAT 1
------------------------------------------------DIRICHLET CONDITIONS
SET bar_xmin DOF 1 1 1 VAL 0.0 0.0 0.0
--------------------------------------------------NEUMANN CONDITIONS
SURF bar_xmax PRESSURE -3.0 CURVE 1
---------------------------------------------------------------STEPS
STEP 1 NUMSTEP 2 CONTROL Load
-------------------------------------------------------------RESULTS
VTK Yes  LISTING Yes  EVERY 1
HISTORY NODE 105 DOF 1 KIND U
HISTORY NODE 101 DOF 1 KIND R
-----------------------------------------------------------------END
DECK
    if ! "$FRIX" "$WORK/bar.dck" --out "$WORK/out" --quiet > "$WORK/frix.log" 2>&1; then
        cat "$WORK/frix.log"
        fail "frix run of the bar deck"
        finish
    fi
    if [ ! -f "$WORK/out/bar.pvd" ] || [ ! -f "$WORK/out/bar_history.csv" ] \
            || [ ! -f "$WORK/out/bar_listing.txt" ]; then
        ls -l "$WORK/out"
        fail "frix output files bar.pvd, bar_history.csv, bar_listing.txt"
        finish
    fi
}

# check_table CSV WHAT PYTHON_CHECK: reads a script's --table CSV output into columns `c`
# (numpy float arrays by column name) and runs the Python check on them: passes if it raises nothing.
check_table() {
    local message
    if message=$("$PYTHON" - "$1" "$3" <<'PY' 2>&1
import csv, sys
import numpy as np
with open(sys.argv[1]) as stream:
    rows = list(csv.DictReader(stream))
c = {key: np.array([float(row[key]) for row in rows]) for key in rows[0]}
exec(sys.argv[2])
print("ok")
PY
    ); then pass "$2"; else fail "$2: $message"; fi
}

# check_png FILE WHAT: a PNG signature, an IHDR with width and height >= 200 px, at least
# 5 kB, and more than 20 distinct colours (a plot, not a blank canvas).
check_png() {
    local message
    if message=$("$PYTHON" - "$1" <<'PY' 2>&1
import struct, sys
import numpy as np
path = sys.argv[1]
with open(path, "rb") as stream:
    head = stream.read(33)
assert head[:8] == b"\x89PNG\r\n\x1a\n", "no PNG signature"
assert head[12:16] == b"IHDR", "no IHDR chunk"
width, height = struct.unpack(">II", head[16:24])
assert width >= 200 and height >= 200, f"image only {width} x {height} px"
import os
assert os.path.getsize(path) >= 5000, f"only {os.path.getsize(path)} bytes"
import matplotlib
matplotlib.use("Agg")
import matplotlib.image
pixels = matplotlib.image.imread(path)
colours = len(np.unique(pixels.reshape(-1, pixels.shape[-1]), axis=0))
assert colours > 20, f"only {colours} distinct colours"
print(f"{width} x {height} px, {colours} colours")
PY
    ); then
        pass "$2: PNG $message"
    else
        fail "$2: PNG check: $message"
    fi
}

# expect_user_error WHAT EXPECTED_TEXT COMMAND...: exit status 2, exactly one line on stderr
# containing EXPECTED_TEXT, no Python traceback.
expect_user_error() {
    local what=$1 expected=$2
    shift 2
    "$@" > "$WORK/stdout.txt" 2> "$WORK/stderr.txt"
    local status=$?
    local lines
    lines=$(wc -l < "$WORK/stderr.txt")
    if [ $status -ne 2 ]; then
        fail "$what: exit status $status, expected 2 ($(head -c 300 "$WORK/stderr.txt"))"
    elif grep -q "Traceback" "$WORK/stderr.txt"; then
        fail "$what: Python traceback on stderr"
    elif [ "$lines" -ne 1 ]; then
        fail "$what: $lines lines on stderr, expected one: $(cat "$WORK/stderr.txt")"
    elif ! grep -qF -- "$expected" "$WORK/stderr.txt"; then
        fail "$what: message '$(cat "$WORK/stderr.txt")' lacks '$expected'"
    else
        pass "$what: exit 2, '$(cat "$WORK/stderr.txt")'"
    fi
}
