#!/bin/bash
# Test of postproc/render_mesh.py on a real frix run (the 4-element bar of
# postproc_test_lib.sh) and of its boundary-face extraction on synthetic HEX8 meshes.
# Usage: test_render_mesh.sh <path of the frix executable>; exit 0 if all checks pass.
source "$(dirname "$0")/postproc_test_lib.sh"
run_bar_deck
OUT=$WORK/out
RENDER=("$PYTHON" "$POSTPROC/render_mesh.py")

# 1. Boundary faces (frix_results.boundary_faces, which render_mesh draws): an n x m x k block
#    of hexahedra has 2 (nm + mk + nk) of them, the same block with each cube split into six
#    tetrahedra (Kuhn's split along the main diagonal) twice as many triangles, each listed
#    once, with the outward orientation (the face normal from the node order points away
#    from its element's centroid), and on the block's surface. Checked for 1x1x1 (6 / 12),
#    4x1x1 (18 / 36) and 3x2x2 (32 / 64).
if message=$("$PYTHON" - "$POSTPROC" <<'PY' 2>&1
import itertools
import sys
sys.path.insert(0, sys.argv[1])
import numpy as np
import frix_results as fr

HEX, TET = fr.CELL_TYPES["hexahedron"], fr.CELL_TYPES["tetra"]

def block(nx, ny, nz, tets):
    node = lambda i, j, k: i + (nx + 1) * (j + (ny + 1) * k)
    points = np.array([[i, j, k] for k in range(nz + 1) for j in range(ny + 1)
                       for i in range(nx + 1)], dtype=float)
    cells = []
    for k, j, i in itertools.product(range(nz), range(ny), range(nx)):
        corners = [node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                   node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                   node(i, j + 1, k + 1)]
        if not tets(i, j, k):
            cells.append((HEX, np.array(corners)))
            continue
        for path in itertools.permutations(range(3)):   # Kuhn: 0 -> ... -> (1, 1, 1)
            step, chain = np.zeros(3, dtype=int), [node(i, j, k)]
            for axis in path:
                step[axis] = 1
                chain.append(node(i + step[0], j + step[1], k + step[2]))
            tet = np.array(chain)
            a, b, c, d = points[tet]
            if np.dot(np.cross(b - a, c - a), d - a) < 0:
                tet[[1, 2]] = tet[[2, 1]]
            cells.append((TET, tet))
    return points, cells

for n in [(1, 1, 1), (4, 1, 1), (3, 2, 2)]:
    squares = 2 * (n[0] * n[1] + n[1] * n[2] + n[0] * n[2])
    for name, tets, expected in [("HEX8", lambda i, j, k: False, squares),
                                 ("TET4", lambda i, j, k: True, 2 * squares)]:
        points, cells = block(*n, tets)
        faces, owners = fr.boundary_faces(cells)
        assert len(faces) == expected, (name, n, len(faces), expected)
        assert len({tuple(sorted(face)) for face in faces}) == expected, "a face listed twice"
        for face, owner in zip(faces, owners):
            corners = points[face]
            normal = np.cross(corners[1] - corners[0], corners[-1] - corners[0])
            outward = corners.mean(axis=0) - points[cells[owner][1]].mean(axis=0)
            assert np.dot(normal, outward) > 0, (name, n, "inward face")
            on_surface = np.any((np.abs(corners) < 1e-12) | (np.abs(corners - np.array(n)) < 1e-12),
                                axis=0)
            assert on_surface.any(), (name, n, "interior face drawn")
print("HEX8 6, 18, 32; TET4 12, 36, 64 outward boundary faces")
PY
); then pass "boundary_faces: $message"; else fail "boundary_faces: $message"; fi

# 2. Figures: point field, cell field of an earlier increment, auto scale + reference shape.
if "${RENDER[@]}" "$OUT/bar.pvd" --field von_mises -o "$WORK/vm.png" > "$WORK/log.txt" 2>&1 \
        && grep -q "18 boundary faces, scale 1)" "$WORK/log.txt"; then
    check_png "$WORK/vm.png" "render_mesh von_mises (18 boundary faces)"
else
    fail "render_mesh von_mises: $(cat "$WORK/log.txt")"
fi
if "${RENDER[@]}" "$OUT/bar.pvd" --field stress:xx --cell --increment 1:1 --view 30,-120 \
        --title "bar" -o "$WORK/sxx.png" > "$WORK/log.txt" 2>&1; then
    check_png "$WORK/sxx.png" "render_mesh cell stress:xx of increment 1:1"
else
    fail "render_mesh --cell: $(cat "$WORK/log.txt")"
fi
# auto scale: largest |u| (6e-3 at x = 4, t = 1) drawn as 10 % of the diagonal sqrt(18):
# factor = 0.1 sqrt(18) / 6e-3 = 70.71.
if "${RENDER[@]}" "$OUT/bar.pvd" --field displacement:2 --scale auto --undeformed \
        -o "$WORK/uz.png" > "$WORK/log.txt" 2>&1 && grep -q "scale 70.71" "$WORK/log.txt"; then
    check_png "$WORK/uz.png" "render_mesh --scale auto (70.71) --undeformed"
else
    fail "render_mesh --scale auto: $(cat "$WORK/log.txt")"
fi

# --block: the bar is block 1 (its one SET line), so the same 18 faces are drawn.
if "${RENDER[@]}" "$OUT/bar.pvd" --block 1 -o "$WORK/b1.png" > "$WORK/log.txt" 2>&1 \
        && grep -q "18 boundary faces" "$WORK/log.txt"; then
    check_png "$WORK/b1.png" "render_mesh --block 1 (18 boundary faces)"
else
    fail "render_mesh --block 1: $(cat "$WORK/log.txt")"
fi

# --up: the 4 x 1 x 1 bar along x drawn with x vertical is 4 high (with z up: 1, the
# deformed height at scale 1, 1 + 1e-4 or less).
if "${RENDER[@]}" "$OUT/bar.pvd" --up x -o "$WORK/up.png" > "$WORK/log.txt" 2>&1 \
        && grep -q "vertical axis x, drawn height 4" "$WORK/log.txt"; then
    check_png "$WORK/up.png" "render_mesh --up x (the bar's length vertical)"
else
    fail "render_mesh --up x: $(cat "$WORK/log.txt")"
fi

# 3. User mistakes.
expect_user_error "empty --block" "no element in block(s) 2" \
    "${RENDER[@]}" "$OUT/bar.pvd" --block 2 -o "$WORK/x.png"
expect_user_error "bad --block" "--block: 'pipe' is not a comma list of integers" \
    "${RENDER[@]}" "$OUT/bar.pvd" --block pipe -o "$WORK/x.png"
expect_user_error "missing result" "not found: $WORK/none.vtu" \
    "${RENDER[@]}" "$WORK/none.vtu" -o "$WORK/x.png"
expect_user_error "unknown field" "no point field 'pressure'" \
    "${RENDER[@]}" "$OUT/bar.pvd" --field pressure -o "$WORK/x.png"
expect_user_error "unknown cell field" "no cell field 'reaction'" \
    "${RENDER[@]}" "$OUT/bar.pvd" --field reaction --cell -o "$WORK/x.png"
expect_user_error "bad --view" "--view needs 2 comma-separated numbers" \
    "${RENDER[@]}" "$OUT/bar.pvd" --view 30 -o "$WORK/x.png"
expect_user_error "bad --scale" "--scale: 'big' is neither a number nor 'auto'" \
    "${RENDER[@]}" "$OUT/bar.pvd" --scale big -o "$WORK/x.png"
expect_user_error "increment out of range" "increment position 5 out of range 1..2" \
    "${RENDER[@]}" "$OUT/bar.pvd" --increment 5 -o "$WORK/x.png"
expect_user_error "several increments" "exactly one increment" \
    "${RENDER[@]}" "$OUT/bar.pvd" --increment all -o "$WORK/x.png"
expect_user_error "not a result file" "expected a .pvd or .vtu file" \
    "${RENDER[@]}" "$OUT/bar_history.csv" -o "$WORK/x.png"
[ ! -e "$WORK/x.png" ] && pass "no figure written on errors" || fail "a figure was written despite errors"
finish
