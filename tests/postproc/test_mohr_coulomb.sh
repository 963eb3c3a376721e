#!/bin/bash
# Test of postproc/mohr_coulomb.py: a synthetic .vtu with hand-computed stress states (written
# here with meshio) and a real frix run (the 4-element bar of postproc_test_lib.sh).
# Usage: test_mohr_coulomb.sh <path of the frix executable>; exit 0 if all checks pass.
source "$(dirname "$0")/postproc_test_lib.sh"
run_bar_deck
OUT=$WORK/out
MC=("$PYTHON" "$POSTPROC/mohr_coulomb.py")

# 1. Synthetic result: 10 unit-cube HEX8 cells, cell stresses in VTK order XX YY ZZ XY YZ XZ,
#    tension positive. Hand values with c = 0.020, phi = 30 deg (sin = 1/2, cos = sqrt(3)/2,
#    c cos(phi) = 0.01 sqrt(3) = 0.017320508075688773), f = (s1 - s3)/2 + (s1 + s3)/4 - c cos:
#    id  block state                                       s1, s2, s3          f
#    1   1  uniaxial compression XX = -0.1                 0, 0, -0.1          +0.007679491924311227
#    2   1  uniaxial compression ZZ = -0.05                0, 0, -0.05         -0.004820508075688773
#    3   1  uniaxial compression YY = -q_u, q_u = 2 c cos/(1 - sin) = 0.04 sqrt(3): on the envelope, f = 0
#    4   1  hydrostatic -1                                 -1, -1, -1          -0.5173205080756888
#    5   1  hydrostatic tension 0.05 (> apex c cot = 0.0346) 0.05 x 3          +0.007679491924311227
#    6   2  pure shear XY = 0.03                           0.03, 0, -0.03      +0.012679491924311227
#    7   2  pure shear YZ = 0.015                          0.015, 0, -0.015    -0.002320508075688773
#    8   2  R diag(0.01, -0.05, -0.2) R^T                  0.01, -0.05, -0.2   +0.04017949192431123
#    9   2  R diag(-0.1, -0.15, -0.2) R^T                  -0.1, -0.15, -0.2   -0.042320508075688773
#    10  2  pure shear XZ = 0.02                           0.02, 0, -0.02      +0.002679491924311227
#    R: rotation by 60 deg about (1, 2, 3)/sqrt(14) (all six components non-zero, so a mix-up
#    of the XY/YZ/XZ order changes the eigenvalues). At or beyond failure: ids 1 3 5 6 8 10.
"$PYTHON" - "$WORK" <<'PY' || { fail "writing the synthetic vtu"; finish; }
import sys
import numpy as np
import meshio
folder = sys.argv[1]
cube = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                 [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], dtype=float)
points = np.vstack([cube + [2.0 * cell, 0, 0] for cell in range(10)])
cells = np.arange(80).reshape(10, 8)
axis = np.array([1.0, 2.0, 3.0]) / np.sqrt(14.0)
angle = np.radians(60.0)
cross = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
rotation = np.eye(3) + np.sin(angle) * cross + (1 - np.cos(angle)) * cross @ cross  # Rodrigues
def vtk(tensor):
    return [tensor[0, 0], tensor[1, 1], tensor[2, 2], tensor[0, 1], tensor[1, 2], tensor[0, 2]]
q_u = 0.04 * np.sqrt(3.0)
stress = np.array([
    [-0.1, 0, 0, 0, 0, 0], [0, 0, -0.05, 0, 0, 0], [0, -q_u, 0, 0, 0, 0], [-1, -1, -1, 0, 0, 0],
    [0.05, 0.05, 0.05, 0, 0, 0], [0, 0, 0, 0.03, 0, 0], [0, 0, 0, 0, 0.015, 0],
    vtk(rotation @ np.diag([0.01, -0.05, -0.2]) @ rotation.T),
    vtk(rotation @ np.diag([-0.1, -0.15, -0.2]) @ rotation.T), [0, 0, 0, 0, 0, 0.02]])
assert np.all(np.abs(stress[7]) > 1e-2), "rotated state should mix all components"
swapped = stress[7][[0, 1, 2, 3, 5, 4]]          # YZ <-> XZ mixed up: other eigenvalues
tensor = np.array([[swapped[0], swapped[3], swapped[5]], [swapped[3], swapped[1], swapped[4]],
                   [swapped[5], swapped[4], swapped[2]]])
assert abs(np.linalg.eigvalsh(tensor)[0] + 0.2) > 1e-3, "order mix-up would go unnoticed"
cell_data = {"stress": [stress], "element_id": [np.arange(1, 11, dtype=np.int32)],
             "block": [np.array([1] * 5 + [2] * 5, dtype=np.int32)]}
meshio.write(f"{folder}/synthetic.vtu", meshio.Mesh(points, [("hexahedron", cells)],
             cell_data=cell_data), file_format="vtu")
cell_data["stress"] = [-stress]                  # the same states, compression positive
meshio.write(f"{folder}/compression_positive.vtu", meshio.Mesh(points, [("hexahedron", cells)],
             cell_data=cell_data), file_format="vtu")
meshio.write(f"{folder}/no_stress.vtu", meshio.Mesh(points, [("hexahedron", cells)]),
             file_format="vtu")
PY

# hand values of the table above (s: s1 s2 s3, f), also used by the --vtk checks;
# eigvalsh round-off: 1e-14 absolute (stresses <= 1)
HAND_VALUES='
root3 = np.sqrt(3.0)
s = np.array([[0, 0, -0.1], [0, 0, -0.05], [0, 0, -0.04 * root3], [-1, -1, -1], [0.05] * 3,
              [0.03, 0, -0.03], [0.015, 0, -0.015], [0.01, -0.05, -0.2], [-0.1, -0.15, -0.2],
              [0.02, 0, -0.02]])
f = np.array([0.007679491924311227, -0.004820508075688773, 0.0, -0.5173205080756888,
              0.007679491924311227, 0.012679491924311227, -0.002320508075688773,
              0.04017949192431123, -0.042320508075688773, 0.002679491924311227])
'
HAND=$HAND_VALUES'
assert np.array_equal(c["element_id"], range(1, 11)), c["element_id"]
assert np.array_equal(c["block"], [1] * 5 + [2] * 5)
worst = np.max(np.abs(np.column_stack([c["s1"], c["s2"], c["s3"]]) - s))
assert worst <= 1e-14, f"principal stresses off by {worst:.2e}"
worst = np.max(np.abs(c["f"] - f))
assert worst <= 1e-14, f"f off by {worst:.2e}"
assert np.array_equal(c["failed"], [1, 0, 1, 0, 1, 1, 0, 1, 0, 1]), c["failed"]
'
if "${MC[@]}" "$WORK/synthetic.vtu" --c 0.020 --phi 30 --table "$WORK/mc.csv" \
        > "$WORK/log.txt" 2>&1 && grep -q "^6 of 10 elements at or beyond failure" "$WORK/log.txt"; then
    pass "synthetic: 6 of 10 elements at or beyond failure"
    check_table "$WORK/mc.csv" "synthetic: table s1 s2 s3 f failed = hand values" "$HAND"
else
    fail "synthetic count: $(cat "$WORK/log.txt")"
fi
if "${MC[@]}" "$WORK/compression_positive.vtu" --c 0.020 --phi 30 --compression-positive \
        --table "$WORK/mc_cp.csv" > "$WORK/log.txt" 2>&1 \
        && grep -q "^6 of 10 elements" "$WORK/log.txt"; then
    check_table "$WORK/mc_cp.csv" "--compression-positive on negated stresses: same table" "$HAND"
else
    fail "--compression-positive: $(cat "$WORK/log.txt")"
fi
if "${MC[@]}" "$WORK/synthetic.vtu" --c 0.020 --phi 30 --block 1 > "$WORK/log.txt" 2>&1 \
        && grep -q "^3 of 5 elements" "$WORK/log.txt"; then
    pass "--block 1: 3 of 5 (ids 1 3 5)"
else
    fail "--block 1: $(cat "$WORK/log.txt")"
fi
# check_vtk VTU WHAT PYTHON_CHECK: reads a --vtk output back with meshio: `m` the mesh,
# `cell` its cell data (first block), `point` its point data; the hand values s, f defined.
check_vtk() {
    local message
    if message=$("$PYTHON" - "$1" "$HAND_VALUES$3" <<'PY' 2>&1
import sys
import numpy as np
import meshio
m = meshio.read(sys.argv[1])
assert list(m.cells_dict) == ["hexahedron"], list(m.cells_dict)
cell = {key: np.asarray(value[0]) for key, value in m.cell_data.items()}
point = {key: np.asarray(value) for key, value in m.point_data.items()}
exec(sys.argv[2])
print("ok")
PY
    ); then pass "$2"; else fail "$2: $message"; fi
}
# --vtk with --block 2: the 5 cells 6..10 only (their 40 points, unit cubes at x = 2 (id - 1)),
# fields = the hand values of the table above
if "${MC[@]}" "$WORK/synthetic.vtu" --c 0.020 --phi 30 --block 2 --vtk "$WORK/block2.vtu" \
        > "$WORK/log.txt" 2>&1 && grep -q "^wrote $WORK/block2.vtu (5 cells)" "$WORK/log.txt"; then
    check_vtk "$WORK/block2.vtu" "--vtk --block 2: 5 cells, s1 s2 s3 f failed = hand values" '
assert np.array_equal(cell["element_id"], range(6, 11)), cell["element_id"]
assert np.array_equal(cell["block"], [2] * 5) and np.array_equal(cell["failed"], [1, 0, 1, 0, 1])
worst = np.max(np.abs(np.column_stack([cell["s1"], cell["s2"], cell["s3"]]) - s[5:]))
assert worst <= 1e-14, f"principal stresses off by {worst:.2e}"
assert np.max(np.abs(cell["f"] - f[5:])) <= 1e-14, cell["f"]
assert m.points.shape == (40, 3), m.points.shape
corners = m.points[m.cells_dict["hexahedron"]]           # (5, 8, 3)
for k, element in enumerate(range(6, 11)):
    assert np.allclose(corners[k].min(axis=0), [2.0 * (element - 1), 0, 0], atol=0)
    assert np.allclose(np.ptp(corners[k], axis=0), 1.0, atol=0)
assert "displacement" not in point                       # the synthetic file has none
'
else
    fail "--vtk --block 2: $(cat "$WORK/log.txt")"
fi
# phi = 0 is Tresca, f = (s1 - s3)/2 - c: failed where the max shear >= 0.02: ids 1 (0.05),
# 2 (0.025), 3 (0.0346), 6 (0.03), 8 (0.105), 9 (0.05), 10 (0.02, on the envelope) -> 7.
if "${MC[@]}" "$WORK/synthetic.vtu" --c 0.020 --phi 0 > "$WORK/log.txt" 2>&1 \
        && grep -q "^7 of 10 elements" "$WORK/log.txt"; then
    pass "phi = 0 (Tresca): 7 of 10"
else
    fail "phi = 0: $(cat "$WORK/log.txt")"
fi
if "${MC[@]}" "$WORK/synthetic.vtu" --c 0.020 --phi 30 --exit-code > "$WORK/log.txt" 2>&1; then
    fail "--exit-code with failed elements returned 0"
else
    [ $? -eq 1 ] && pass "--exit-code: 1 with failed elements" || fail "--exit-code: $(cat "$WORK/log.txt")"
fi

# 1b. Integration-point stresses from an HDF5 results file (docs/hdf5-layout.md), written here
#    with h5py: 5 elements (ids 11..15, block 1) x 2 points holding the states of the table
#    above (Voigt order xx yy zz xy xz yz in the file): element 11: states 1, 2 (fails);
#    12: 2, 4 (safe); 13: 3, 7 (fails: 3 on the envelope); 14: 9, 4 (safe); 15: 8, 10 (fails).
#    -> 3 of 5 elements, 4 of 10 points. Group 000002 lacks the `complete` attribute (a run
#    stopped while writing it) and must be ignored, so "last" is 000001 (step 1, incr 2).
if "$PYTHON" - "$WORK" <<'PY'
import sys
import h5py, meshio
import numpy as np
folder = sys.argv[1]
vtk = np.asarray(meshio.read(f"{folder}/synthetic.vtu").cell_data["stress"][0])
voigt = vtk[:, [0, 1, 2, 3, 5, 4]]
pairs = [(1, 2), (2, 4), (3, 7), (9, 4), (8, 10)]
cube = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                 [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], dtype=float)
with h5py.File(f"{folder}/gauss.h5", "w") as stream:
    # 5 separate unit cubes at x = 2 k (for --vtk), displacement u = (node number, 0, -1)
    stream["mesh/coordinates"] = np.vstack([cube + [2.0 * k, 0, 0] for k in range(5)])
    stream["mesh/connectivity"] = np.arange(1, 41, dtype=np.int32).reshape(5, 8)
    stream["mesh/element_ids"] = np.arange(11, 16, dtype=np.int32)
    stream["mesh/element_block"] = np.ones(5, dtype=np.int32)
    stream["mesh/element_sets/odd"] = np.array([1, 3, 5], dtype=np.int32)
    group = stream.create_group("increments/000001")
    group.attrs.update(step=1, increment=2, time=1.0, complete=1)
    group["stress"] = np.array([[voigt[a - 1], voigt[b - 1]] for a, b in pairs])
    group["displacement"] = np.column_stack([np.arange(1.0, 41.0), np.zeros(40), -np.ones(40)])
    group = stream.create_group("increments/000002")
    group.attrs.update(step=1, increment=3, time=1.5)
    group["stress"] = np.full((5, 2, 6), 1.0)
PY
then
    if "${MC[@]}" "$WORK/gauss.h5" --c 0.020 --phi 30 --table "$WORK/gauss.csv" \
            > "$WORK/log.txt" 2>&1 && grep -q "^3 of 5 elements at or beyond" "$WORK/log.txt" \
            && grep -q "^4 of 10 integration points" "$WORK/log.txt" \
            && grep -q "step 1 incr 2" "$WORK/log.txt"; then
        check_table "$WORK/gauss.csv" "HDF5 points: 3 of 5 elements, 4 of 10 points, table" '
assert np.array_equal(c["element_id"], np.repeat(range(11, 16), 2))
assert np.array_equal(c["point"], [1, 2] * 5)
assert np.array_equal(c["failed"], [1, 0, 0, 0, 1, 0, 0, 0, 1, 1]), c["failed"]
assert abs(c["f"][9] - 0.002679491924311227) <= 1e-14 and abs(c["s3"][8] + 0.2) <= 1e-14
'
    else
        fail "HDF5 points: $(cat "$WORK/log.txt")"
    fi
    # --vtk from the points: each element's point of largest f (11: state 1, 12: 2, 13: 3,
    # 14: 9, 15: 8), failed if any point fails, failed_points = 1 0 1 0 2
    if "${MC[@]}" "$WORK/gauss.h5" --c 0.020 --phi 30 --vtk "$WORK/gauss.vtu" \
            > "$WORK/log.txt" 2>&1 && grep -q "(5 cells)" "$WORK/log.txt"; then
        check_vtk "$WORK/gauss.vtu" "HDF5 --vtk: worst point per element, failed, failed_points" '
worst_state = np.array([1, 2, 3, 9, 8]) - 1
assert np.array_equal(cell["element_id"], range(11, 16)), cell["element_id"]
assert np.max(np.abs(cell["f"] - f[worst_state])) <= 1e-14, cell["f"]
assert np.max(np.abs(np.column_stack([cell["s1"], cell["s2"], cell["s3"]]) - s[worst_state])) <= 1e-14
assert np.array_equal(cell["failed"], [1, 0, 1, 0, 1]), cell["failed"]
assert np.array_equal(cell["failed_points"], [1, 0, 1, 0, 2]), cell["failed_points"]
assert m.points.shape == (40, 3)
assert np.array_equal(point["displacement"][:, 0], np.arange(1.0, 41.0))
assert np.all(point["displacement"][:, 2] == -1.0)
'
    else
        fail "HDF5 --vtk: $(cat "$WORK/log.txt")"
    fi
    # --element-set odd = internal elements 1 3 5 (ids 11 13 15): all three fail; their 24
    # points, renumbered, carry their own displacements
    if "${MC[@]}" "$WORK/gauss.h5" --c 0.020 --phi 30 --element-set odd --vtk "$WORK/odd.vtu" \
            > "$WORK/log.txt" 2>&1 && grep -q "^3 of 3 elements at or beyond" "$WORK/log.txt" \
            && grep -q "^4 of 6 integration points" "$WORK/log.txt"; then
        check_vtk "$WORK/odd.vtu" "--element-set odd: elements 11 13 15, 3 of 3" '
assert np.array_equal(cell["element_id"], [11, 13, 15]), cell["element_id"]
assert m.points.shape == (24, 3)
nodes = np.concatenate([np.arange(1, 9), np.arange(17, 25), np.arange(33, 41)])
assert np.array_equal(point["displacement"][:, 0], nodes), point["displacement"][:, 0]
assert np.allclose(m.points[:, 0].reshape(3, 8).min(axis=1), [0, 4, 8], atol=0)
'
    else
        fail "--element-set odd: $(cat "$WORK/log.txt")"
    fi
    expect_user_error "unknown element set" "no element set 'soil' (element sets: odd)" \
        "${MC[@]}" "$WORK/gauss.h5" --c 0.02 --phi 30 --element-set soil
    expect_user_error "HDF5 incomplete increment" "no increment 1:3 (available: 1:2)" \
        "${MC[@]}" "$WORK/gauss.h5" --c 0.02 --phi 30 --increment 1:3
else
    fail "writing the synthetic HDF5 file"
fi
cp "$OUT/bar.pvd" "$WORK/not_hdf5.h5"
expect_user_error "not an HDF5 file" "cannot read $WORK/not_hdf5.h5 as a frix HDF5 results file" \
    "${MC[@]}" "$WORK/not_hdf5.h5" --c 0.02 --phi 30

# 2. frix run: uniaxial tension 3 t. At t = 1: s1 = 3, s2 = s3 = 0 (round-off ~1e-16), so
#    f = 1.5 + 0.75 - 0.01 sqrt(3) = 2.232679491924311 in all 4 elements (ids 51..54).
#    At t = 0.5 with c = 10: f = 0.75 + 0.375 - 5 sqrt(3) < 0 everywhere.
if "${MC[@]}" "$OUT/bar.pvd" --c 0.020 --phi 30 --table "$WORK/bar.csv" > "$WORK/log.txt" 2>&1 \
        && grep -q "^4 of 4 elements" "$WORK/log.txt"; then
    check_table "$WORK/bar.csv" "frix bar, last increment: 4 of 4, f = 2.2326794919" '
assert np.array_equal(c["element_id"], [51, 52, 53, 54]), c["element_id"]
assert np.allclose(c["s1"], 3.0, rtol=1e-12, atol=0), c["s1"]
assert np.max(np.abs(c["s3"])) <= 1e-12 and np.max(np.abs(c["s2"])) <= 1e-12
assert np.allclose(c["f"], 2.232679491924311, rtol=1e-12, atol=0), c["f"]
'
else
    fail "frix bar: $(cat "$WORK/log.txt")"
fi
if "${MC[@]}" "$OUT/bar.pvd" --increment 1 --c 10 --phi 30 > "$WORK/log.txt" 2>&1 \
        && grep -q "^0 of 4 elements" "$WORK/log.txt"; then
    pass "frix bar, first increment, c = 10: 0 of 4"
else
    fail "frix bar, c = 10: $(cat "$WORK/log.txt")"
fi
if "${MC[@]}" "$OUT/bar.pvd" --point --c 0.020 --phi 30 --vtk "$WORK/bar_nodes.vtu" \
        > "$WORK/log.txt" 2>&1 && grep -q "^20 of 20 nodes" "$WORK/log.txt"; then
    pass "frix bar, --point: 20 of 20 nodes"
    # nodal fields on the whole mesh, user ids 101..120, u_x = 3 x / 2000 at t = 1
    check_vtk "$WORK/bar_nodes.vtu" "frix bar --point --vtk: s1 = 3, f = 2.2327 at 20 nodes" '
assert m.points.shape == (20, 3) and len(m.cells_dict["hexahedron"]) == 4
assert sorted(point["node_id"]) == list(range(101, 121)), point["node_id"]
assert np.allclose(point["s1"], 3.0, rtol=1e-12, atol=0), point["s1"]
assert np.allclose(point["f"], 2.232679491924311, rtol=1e-12, atol=0)
assert np.all(point["failed"] == 1)
assert np.allclose(point["displacement"][:, 0], 3 * m.points[:, 0] / 2000, rtol=0, atol=1e-15)
'
else
    fail "frix bar --point: $(cat "$WORK/log.txt")"
fi

# 3. User mistakes.
expect_user_error "missing file" "not found: $WORK/none.pvd" \
    "${MC[@]}" "$WORK/none.pvd" --c 0.02 --phi 30
expect_user_error "phi out of range" "--phi must be in [0, 90) degrees" \
    "${MC[@]}" "$WORK/synthetic.vtu" --c 0.02 --phi 90
expect_user_error "negative cohesion" "--c must be a finite cohesion >= 0" \
    "${MC[@]}" "$WORK/synthetic.vtu" --c -1 --phi 30
expect_user_error "missing --c" "required: --c" \
    "${MC[@]}" "$WORK/synthetic.vtu" --phi 30
expect_user_error "no stress field" "no cell field 'stress'" \
    "${MC[@]}" "$WORK/no_stress.vtu" --c 0.02 --phi 30
expect_user_error "unknown block" "no element in block(s) 3 (blocks present: 1, 2)" \
    "${MC[@]}" "$WORK/synthetic.vtu" --c 0.02 --phi 30 --block 3
expect_user_error "element set of a .vtu" "--element-set needs an HDF5 results file" \
    "${MC[@]}" "$WORK/synthetic.vtu" --c 0.02 --phi 30 --element-set soil
expect_user_error "unwritable vtk" "cannot write $WORK/no/dir/mc.vtu" \
    "${MC[@]}" "$WORK/synthetic.vtu" --c 0.02 --phi 30 --vtk "$WORK/no/dir/mc.vtu"
expect_user_error "unwritable table" "cannot write $WORK/no/dir/t.csv" \
    "${MC[@]}" "$WORK/synthetic.vtu" --c 0.02 --phi 30 --table "$WORK/no/dir/t.csv"
finish
