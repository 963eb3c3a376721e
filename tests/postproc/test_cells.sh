#!/bin/bash
# The post-processing scripts on meshes of tetrahedra (the cell table of
# postproc/frix_results.py): frix runs tests/tet4/patch10.dck (48 TET10 filling the unit
# cube, u = A x on the boundary: a constant stress, tests/tet4/check_patch.py) and
# tests/tet4/pressure_tet4.dck (a TET4 beam with the end-face surface xmax), then
# 1. render_mesh.py draws the 48 boundary triangles of the cube (2 x 2 squares per side, each
#    split into 2 by the Kuhn split of make_patch.py: 6 x 8 = 48);
# 2. mohr_coulomb.py on the .pvd (element means) and on the HDF5 file (integration points)
#    writes its --vtk file with the 48 cells as tetra10, whose s1 >= s2 >= s3 are the
#    principal values of the exact stress of check_patch.py (sigma = lambda tr(eps) I +
#    2 mu eps, eps = sym(A), E = 210000, nu = 0.3) to 1e-12 of the largest (check_patch.py);
# 3. H5Results.surface_nodes (compare_runs.py --surface) finds the nodes of the TET4 surface
#    xmax: every node of the mesh at x = 10 and no other.
# Usage: test_cells.sh <path of the frix executable>; exit 0 if all checks pass.
source "$(dirname "$0")/postproc_test_lib.sh"
TET=$(cd "$HERE/../tet4" && pwd)
# the beam's mesh as tests/tet4/run_pressure.py makes it (gmsh, h = 0.5, order 1)
mkdir -p "$WORK/beam"
cp "$TET/pressure_tet4.dck" "$WORK/beam/"
gmsh -3 -setnumber h 0.5 -setnumber order 1 "$TET/beam.geo" -format msh22 \
    -o "$WORK/beam/beam.msh" > "$WORK/gmsh.log" 2>&1 || { cat "$WORK/gmsh.log"; fail "gmsh"; finish; }
for run in "$TET patch10" "$WORK/beam pressure_tet4"; do
    set -- $run
    if ! (cd "$1" && "$FRIX" "$2.dck" --out "$WORK/$2" --quiet) > "$WORK/$2.log" 2>&1; then
        cat "$WORK/$2.log"
        fail "frix run of $2.dck"
        finish
    fi
done

# 1. the boundary of the TET10 cube
if "$PYTHON" "$POSTPROC/render_mesh.py" "$WORK/patch10/patch10.pvd" --field von_mises \
        -o "$WORK/patch10.png" > "$WORK/log.txt" 2>&1 \
        && grep -q "(48 boundary faces," "$WORK/log.txt"; then
    check_png "$WORK/patch10.png" "render_mesh on TET10 (48 boundary triangles)"
else
    fail "render_mesh on TET10: $(cat "$WORK/log.txt")"
fi

# 2. mohr_coulomb.py --vtk with tetra10 cells and the exact principal stresses
for source in patch10.pvd patch10.h5; do
    if "$PYTHON" "$POSTPROC/mohr_coulomb.py" "$WORK/patch10/$source" --c 1000 --phi 30 \
            --vtk "$WORK/mc_$source.vtu" > "$WORK/log.txt" 2>&1 \
       && message=$("$PYTHON" - "$WORK/mc_$source.vtu" "$TET" <<'PY' 2>&1
import sys
sys.path.insert(0, sys.argv[2])
import meshio
import numpy as np
from check_patch import exact_stress
mesh = meshio.vtu.read(sys.argv[1])
assert [block.type for block in mesh.cells] == ["tetra10"], [b.type for b in mesh.cells]
assert len(mesh.cells[0].data) == 48, len(mesh.cells[0].data)
xx, yy, zz, xy, xz, yz = exact_stress()             # frix Voigt order
tensor = np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])
expected = np.sort(np.linalg.eigvalsh(tensor))[::-1]
computed = np.column_stack([mesh.cell_data[name][0] for name in ("s1", "s2", "s3")])
error = np.abs(computed - expected).max() / np.abs(expected).max()
assert error < 1e-12, error   # check_patch.py TOLERANCE (round-off: 3e-15)
print(f"48 tetra10 cells, principal stresses within {error:.1e} of the exact ones")
PY
); then
        pass "mohr_coulomb.py --vtk from $source: $message"
    else
        fail "mohr_coulomb.py --vtk from $source: $(cat "$WORK/log.txt") ${message:-}"
    fi
done

# 3. the nodes of a surface of TET4 faces
if message=$("$PYTHON" - "$POSTPROC" "$WORK/pressure_tet4/pressure_tet4.h5" <<'PY' 2>&1
import sys
sys.path.insert(0, sys.argv[1])
import numpy as np
import frix_results as fr
with fr.H5Results(sys.argv[2]) as results:
    nodes = results.surface_nodes("xmax")
    x = results.mesh_array("coordinates")[:, 0]
end = np.flatnonzero(np.abs(x - 10.0) < 1e-12)
assert nodes.size > 0 and np.array_equal(nodes, end), (nodes, end)
print(f"{nodes.size} nodes, all and only those at x = 10")
PY
); then pass "surface_nodes on TET4 faces: $message"; else fail "surface_nodes on TET4 faces: $message"; fi
finish
