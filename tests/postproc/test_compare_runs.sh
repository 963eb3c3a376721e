#!/bin/bash
# Test of postproc/compare_runs.py: two real frix runs of a tiny contact deck that differ only
# in the load (closed-form difference), a synthetic run B with a hand-made displacement
# difference, and the error cases.
# Usage: test_compare_runs.sh <path of the frix executable>; exit 0 if all checks pass.
source "$(dirname "$0")/postproc_test_lib.sh"
CR=("$PYTHON" "$POSTPROC/compare_runs.py")

# A 2 x 1 x 1 block of two HEX8 (E = 2000, nu = 0, user node ids 101..112, x fastest) on the
# rigid plane z = 0 (contact pair 1, slave surface blk_zmin, frictionless, EPSN 1000),
# u_x = 0 at x = 0, u_y = 0 at y = 0, pressed by a pressure P on its top (load factor t,
# increments t = 0.5, 1). Uniaxial compression t P, nu = 0: every slave node penetrates the
# plane by t P / EPSN (the penalty force of each node, EPSN x penetration x its tributary
# area, balances t P x the same area), so u_z(z) = -t P (1/EPSN + z/E), u_x = u_y = 0.
# Runs A (P = 1) and B (P = 3): d = u_B - u_A, in mm (--scale 1000):
#   slave nodes (z = 0):  dz = -1000 t 2/1000 = -2 t          (-2 at t = 1, -1 at t = 0.5)
#   top nodes   (z = 1):  dz = -1000 t 2 (1/1000 + 1/2000) = -3 t
write_deck() {   # write_deck FILE PRESSURE DIVISIONS_X
    cat > "$1" <<DECK
 block2: 2 x 1 x 1 block of HEX8 on a rigid plane z = 0 (frictionless penalty contact,
 EPSN 1000), pressed by a pressure on its top, E = 2000, nu = 0.
---------------------------------------------------------PROBLEM TYP
PROBLEMTYP   Structure
--------------------------------------------------------------STATIC
KINTYP       Geo_Lin
MAXITER      20
TOLRESID     1.0e-10
TOLDISP      1.0e-10
NEWTONRAPHSO Load_Control
---------------------------------------------------------LOAD CURVES
CURVE 1 POINTS 0.0 0.0  1.0 1.0
-----------------------------------------------------------MATERIALS
MAT 1 MAT_Struct_LinearElastic YOUNG 2000.0 NUE 0.0 DENS 0.0
----------------------------------------------------------MESH BLOCK
BLOCK blk ORIGIN 0 0 0 SIZE 2 1 1 DIVISIONS $3 1 1 NODE_OFFSET 100
--------------------------------------------------STRUCTURE ELEMENTS
SET blk SOLID HEX8 MAT 1
------------------------------------------------DIRICHLET CONDITIONS
SET blk_xmin DOF 1 0 0 VAL 0.0 0.0 0.0
SET blk_ymin DOF 0 1 0 VAL 0.0 0.0 0.0
--------------------------------------------------NEUMANN CONDITIONS
SURF blk_zmax PRESSURE $2 CURVE 1
--------------------------------------------------CONTACT CONDITIONS
PAIR 1 SLAVE blk_zmin MASTER RIGID_PLANE POINT 0 0 0 NORMAL 0 0 1 EPSN 1000.0
---------------------------------------------------------------STEPS
STEP 1 NUMSTEP 2 CONTROL Load
-------------------------------------------------------------RESULTS
HDF5 Yes
-----------------------------------------------------------------END
DECK
}
for run in "a 1.0 2" "b 3.0 2" "m 1.0 3"; do
    set -- $run
    write_deck "$WORK/$1.dck" "$2" "$3"
    if ! "$FRIX" "$WORK/$1.dck" --out "$WORK/$1" --quiet > "$WORK/frix.log" 2>&1 \
            || [ ! -f "$WORK/$1/$1.h5" ] || [ ! -f "$WORK/$1/$1_contact.csv" ]; then
        cat "$WORK/frix.log"
        fail "frix run $1 (P = $2, $3 elements)"
        finish
    fi
done
A=$WORK/a/a.h5
B=$WORK/b/b.h5


# 1. Real runs, contact pair 1 at the last common time t = 1: the 6 slave nodes 101..106
#    (z = 0), sorted by x (then id), dz = -2 mm, dx = dy = 0 (round-off: 1e-12 mm).
if "${CR[@]}" "$A" "$B" --pair 1 --scale 1000 --unit mm --table "$WORK/pair.csv" \
        --plot "$WORK/pair.png" --axis x > "$WORK/log.txt" 2>&1 \
        && grep -q "^at step 1 incr 2 (t = 1); 6 nodes of contact pair 1 (pass 1); scale 1000 (mm)" \
            "$WORK/log.txt" \
        && grep -q "^dz  *-2.000000e+00 " "$WORK/log.txt" \
        && grep -q "^dmag  *2.000000e+00 " "$WORK/log.txt"; then
    pass "pair 1, t = 1: summary dz = -2 mm"
    check_table "$WORK/pair.csv" "pair 1, t = 1: table dz = -2, ua_z = -1, ub_z = -3 (mm)" '
assert np.array_equal(c["node_id"], [101, 104, 102, 105, 103, 106]), c["node_id"]
assert np.array_equal(c["position"], c["x"]) and np.array_equal(c["x"], [0, 0, 1, 1, 2, 2])
assert np.all(c["z"] == 0.0)
for name, value in (("dz", -2.0), ("dmag", 2.0), ("ua_z", -1.0), ("ub_z", -3.0)):
    worst = np.max(np.abs(c[name] - value))
    assert worst <= 1e-12, f"{name} off by {worst:.2e}"
for name in ("dx", "dy", "ua_x", "ua_y", "ub_x", "ub_y"):
    assert np.max(np.abs(c[name])) <= 1e-12, (name, c[name])
'
    check_png "$WORK/pair.png" "pair 1 plot"
else
    fail "pair 1, t = 1: $(cat "$WORK/log.txt")"
fi
# t = 0.5 chosen three ways: --time, --increment 1:1, --increment first: dz = -1 mm
for choice in "--time 0.5" "--increment 1:1" "--increment first"; do
    if "${CR[@]}" "$A" "$B" --pair 1 --scale 1000 $choice > "$WORK/log.txt" 2>&1 \
            && grep -q "^at step 1 incr 1 (t = 0.5)" "$WORK/log.txt" \
            && grep -q "^dz  *-1.000000e+00 " "$WORK/log.txt"; then
        pass "$choice: t = 0.5, dz = -1 mm"
    else
        fail "$choice: $(cat "$WORK/log.txt")"
    fi
done
# the same slave nodes as the surface blk_zmin; the top node set: dz = -3 mm at t = 1
if "${CR[@]}" "$A" "$B" --surface blk_zmin --scale 1000 --table "$WORK/surface.csv" \
        > "$WORK/log.txt" 2>&1; then
    check_table "$WORK/surface.csv" "--surface blk_zmin: nodes 101..106, dz = -2 mm" '
assert sorted(c["node_id"]) == list(range(101, 107)), c["node_id"]
assert np.max(np.abs(c["dz"] + 2.0)) <= 1e-12, c["dz"]
'
else
    fail "--surface blk_zmin: $(cat "$WORK/log.txt")"
fi
if "${CR[@]}" "$A" "$B" --node-set blk_zmax --scale 1000 --table "$WORK/top.csv" \
        > "$WORK/log.txt" 2>&1; then
    check_table "$WORK/top.csv" "--node-set blk_zmax: nodes 107..112, dz = -3 mm" '
assert sorted(c["node_id"]) == list(range(107, 113)), c["node_id"]
assert np.all(c["z"] == 1.0)
assert np.max(np.abs(c["dz"] + 3.0)) <= 1e-12, c["dz"]
'
else
    fail "--node-set blk_zmax: $(cat "$WORK/log.txt")"
fi

# 2. Synthetic run B': a copy of A whose displacements (every increment) get
#    D = 1e-3 (x, -2 y, 0.5 (x + 1)) added. At the slave nodes (z = 0), in mm:
#    dx = x, dy = -2 y, dz = 0.5 (x + 1), |d| = sqrt(x^2 + 4 y^2 + 0.25 (x + 1)^2).
#    Largest (nodes sorted by x, then id; the first of equal magnitudes):
#    dx = 2 at node 103 (2, 0, 0); dy = -2 at node 104 (0, 1, 0); dz = 1.5 at node 103;
#    |d| = sqrt(4 + 4 + 2.25) = 3.2015621187164243 at node 106 (2, 1, 0).
"$PYTHON" - "$A" "$WORK" <<'PY' || fail "writing the synthetic HDF5 files"
import shutil, sys
import h5py
import numpy as np
source, folder = sys.argv[1], sys.argv[2]
def copy(name, change):
    shutil.copyfile(source, f"{folder}/{name}.h5")
    with h5py.File(f"{folder}/{name}.h5", "r+") as stream:
        change(stream)
def add_field(stream):
    x = stream["mesh/coordinates"][()]
    extra = 1e-3 * np.column_stack([x[:, 0], -2 * x[:, 1], 0.5 * (x[:, 0] + 1)])
    for group in stream["increments"].values():
        group["displacement"][...] = group["displacement"][()] + extra
def shift_times(stream):            # no time in common with A: 0.75, 1.25
    for group in stream["increments"].values():
        group.attrs["time"] = group.attrs["time"] + 0.25
def move_node(stream):              # node 1 moved by 1e-3: not the same mesh
    x = stream["mesh/coordinates"][()]
    x[0, 0] += 1e-3
    stream["mesh/coordinates"][...] = x
def shrink_set(stream):             # node set blk_zmax without its first node
    nodes = stream["mesh/node_sets/blk_zmax"][()]
    del stream["mesh/node_sets/blk_zmax"]
    stream["mesh/node_sets/blk_zmax"] = nodes[1:]
def second_increment_later(stream): # increment 1:1 at t = 0.6 (A: 0.5)
    stream["increments/000001"].attrs["time"] = 0.6
copy("field", add_field)
copy("shifted", shift_times)
copy("moved", move_node)
copy("shrunk", shrink_set)
copy("later", second_increment_later)
PY
ACSV=$WORK/a/a_contact.csv
if "${CR[@]}" "$A" "$WORK/field.h5" --pair 1 --contact-csv "$ACSV,$ACSV" --scale 1000 \
        --table "$WORK/field.csv" --plot "$WORK/field.png" --axis x > "$WORK/log.txt" 2>&1 \
        && grep -q "^dx  *2.000000e+00  *103 " "$WORK/log.txt" \
        && grep -q "^dy  *-2.000000e+00  *104 " "$WORK/log.txt" \
        && grep -q "^dz  *1.500000e+00  *103 " "$WORK/log.txt" \
        && grep -q "^dmag  *3.201562e+00  *106 " "$WORK/log.txt"; then
    pass "synthetic difference: largest dx, dy, dz, |d| with their nodes"
    check_table "$WORK/field.csv" "synthetic difference: table = hand values (1e-12 mm)" '
x, y = c["x"], c["y"]
expected = {"dx": x, "dy": -2 * y, "dz": 0.5 * (x + 1),
            "dmag": np.sqrt(x**2 + 4 * y**2 + 0.25 * (x + 1)**2)}
for name, value in expected.items():
    worst = np.max(np.abs(c[name] - value))
    assert worst <= 1e-12, f"{name} off by {worst:.2e}"
assert abs(c["dmag"].max() - 3.2015621187164243) <= 1e-12
'
    check_png "$WORK/field.png" "synthetic difference plot"
else
    fail "synthetic difference: $(cat "$WORK/log.txt")"
fi

# 3. User mistakes and runs that cannot be compared.
grep -v "^1,1,.*,1,1,101," "$ACSV" > "$WORK/fewer_contact.csv"
expect_user_error "different meshes" "are not runs of the same mesh: 12 vs 16 nodes, 2 vs 3 elements" \
    "${CR[@]}" "$A" "$WORK/m/m.h5" --pair 1
expect_user_error "moved node" "the node coordinates differ by up to 1.000e-03" \
    "${CR[@]}" "$A" "$WORK/moved.h5" --node-set blk
expect_user_error "different node sets" "node set blk_zmax has different nodes" \
    "${CR[@]}" "$A" "$WORK/shrunk.h5" --node-set blk_zmax
expect_user_error "different slave nodes" "contact pair 1 has different slave nodes in the two runs (6 and 5 nodes)" \
    "${CR[@]}" "$A" "$B" --pair 1 --contact-csv "$ACSV,$WORK/fewer_contact.csv"
expect_user_error "missing run" "HDF5 file not found: $WORK/none.h5" \
    "${CR[@]}" "$A" "$WORK/none.h5" --pair 1
expect_user_error "missing contact CSV" "contact CSV file not found: $WORK/field_contact.csv" \
    "${CR[@]}" "$A" "$WORK/field.h5" --pair 1
expect_user_error "not an HDF5 file" "cannot read $WORK/a.dck as a frix HDF5 results file" \
    "${CR[@]}" "$A" "$WORK/a.dck" --pair 1
expect_user_error "no common time" "have no increment at a common time (times of A: 0.5, 1; of B: 0.75, 1.25)" \
    "${CR[@]}" "$A" "$WORK/shifted.h5" --node-set blk
expect_user_error "STEP:INCREMENT at different times" "increment 1:1 is at t = 0.5" \
    "${CR[@]}" "$A" "$WORK/later.h5" --node-set blk --increment 1:1
expect_user_error "time not in both" "time 0.7 is not in both runs" \
    "${CR[@]}" "$A" "$B" --pair 1 --time 0.7
expect_user_error "unknown increment" "no increment 1:5 (available: 1:1, 1:2)" \
    "${CR[@]}" "$A" "$B" --pair 1 --increment 1:5
expect_user_error "unknown pair" "no contact pair 2 (pairs: 1)" \
    "${CR[@]}" "$A" "$B" --pair 2
expect_user_error "unknown node set" "no node set 'nope'" \
    "${CR[@]}" "$A" "$B" --node-set nope
expect_user_error "unknown surface" "no surface 'nope'" \
    "${CR[@]}" "$A" "$B" --surface nope
expect_user_error "no selection" "one of the arguments --pair --surface --node-set is required" \
    "${CR[@]}" "$A" "$B"
expect_user_error "zero scale" "--scale must be a finite non-zero number" \
    "${CR[@]}" "$A" "$B" --pair 1 --scale 0
expect_user_error "unwritable table" "cannot write $WORK/no/dir/t.csv" \
    "${CR[@]}" "$A" "$B" --pair 1 --table "$WORK/no/dir/t.csv"
finish
