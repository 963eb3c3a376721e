#!/usr/bin/python3
"""Checks the neutral files written by pos3d_writer_check (tests/pos3d/pos3d_writer_check.f90)
with the independent reader postproc/pos3d_reader.py.

    /usr/bin/python3 tests/pos3d/check_synthetic.py DIRECTORY

Reference values are the closed formulas of pos3d_writer_check.f90, re-evaluated here from the
coordinates (mesh formula repeated here too). Tolerances: values are written with 17
significant digits, so data copied through the file must agree to 1e-15 relative; the von
Mises check compares with an independent computation (exact nodal extrapolation of a linear
field) and allows 1e-12 relative for rounding in the extrapolation and averaging.

Convention verified for ELEMENT.BRICK8 (stated precisely): with natural coordinates
(r, s, t) right-handed, Tecgraf node k at TECGRAF_BRICK8_SIGNS[k] (nodes 1-4 on t = +1 in the
order (-1,-1), (1,-1), (1,1), (-1,1), i.e. counter-clockwise seen from t > 0; node k+4 at the
same (r, s) on t = -1), every brick's volume, integral of det(dx/d(r,s,t)), must be > 0 and
det J > 0 at each Gauss point; reading the same node lists in VTK order (nodes 1-4 on t = -1)
must give exactly the negative volume (the mirror image), which shows the check can fail.
Gauss point k must sit beside Tecgraf node k: the stress written for it must equal the
formula at TECGRAF_BRICK8_SIGNS[k] / sqrt(3) mapped with the Tecgraf node list.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
from pos3d_reader import (Pos3dError, brick_volumes, gauss_point_positions,  # noqa: E402
                          read_pos3d, _trilinear_jacobians, TECGRAF_BRICK8_SIGNS, VTK_HEXAHEDRON_SIGNS)

NX, NY, NZ = 3, 2, 2
from check_tools import check, close, summary  # noqa: E402


def node_number(i, j, k):
    return 1 + i + (NX + 1) * (j + (NY + 1) * k)


def expected_coords():
    coords = np.empty(((NX + 1) * (NY + 1) * (NZ + 1), 3))
    for k in range(NZ + 1):
        for j in range(NY + 1):
            for i in range(NX + 1):
                n = node_number(i, j, k)
                coords[n - 1] = [i + 0.08 * np.sin(1.3 * n), j + 0.06 * np.cos(0.7 * n),
                                 0.5 * k + 0.04 * np.sin(2.1 * n)]
    return coords


def expected_bricks_tecgraf():
    """Top face (z index k+1) counter-clockwise seen from +z, then the bottom face."""
    bricks = []
    for k in range(NZ):
        for j in range(NY):
            for i in range(NX):
                top = [node_number(i, j, k + 1), node_number(i + 1, j, k + 1),
                       node_number(i + 1, j + 1, k + 1), node_number(i, j + 1, k + 1)]
                bottom = [node_number(i, j, k), node_number(i + 1, j, k),
                          node_number(i + 1, j + 1, k), node_number(i, j + 1, k)]
                bricks.append(top + bottom)
    return np.array(bricks)


def displacement(x, f):
    return f * 1e-3 * np.column_stack([x[:, 0] + 2 * x[:, 1], x[:, 1] * x[:, 2] - x[:, 0],
                                       3 * x[:, 2] + x[:, 0] * x[:, 1]])


def stress(x, f):
    """(..., 6) frix Voigt stress at positions x (..., 3)."""
    return np.stack([f * (100 * c + (c + 1) * x[..., 0] - 2 * c * x[..., 1] + 3 * x[..., 2])
                     for c in range(1, 7)], axis=-1)


def von_mises(s):
    return np.sqrt(0.5 * ((s[..., 0] - s[..., 1]) ** 2 + (s[..., 1] - s[..., 2]) ** 2 + (s[..., 2] - s[..., 0]) ** 2)
                   + 3 * (s[..., 3] ** 2 + s[..., 4] ** 2 + s[..., 5] ** 2))


def check_model(model, name, materials):
    coords = expected_coords()
    check(len(model.coords) == len(coords), f"{name}: {len(coords)} nodes")
    close(model.coords, coords, 1e-15, f"{name}: node coordinates")
    check(np.array_equal(model.bricks, expected_bricks_tecgraf()), f"{name}: brick node lists in Tecgraf order")
    check(np.all(model.brick_integration_order == 2), f"{name}: integration order 2")
    close(model.materials, materials, 1e-15, f"{name}: materials")
    centroid_x = model.coords[model.bricks - 1][:, :, 0].mean(axis=1)
    expected_material = np.where(centroid_x < 1.5, 1, 2) if len(materials) == 2 else np.ones(len(model.bricks))
    check(np.array_equal(model.brick_material, expected_material), f"{name}: brick materials")

    volumes = brick_volumes(model, "tecgraf")
    check(bool(np.all(volumes > 0)), f"{name}: every brick has positive volume read in Tecgraf order")
    close(volumes.sum(), 6.0, 0.01, f"{name}: total volume ~ 3 x 2 x 1 (nodes moved by < 0.08)")
    points = VTK_HEXAHEDRON_SIGNS / np.sqrt(3.0)
    dets = _trilinear_jacobians(model.coords, model.bricks, TECGRAF_BRICK8_SIGNS, points)
    check(bool(np.all(dets > 0)), f"{name}: det J > 0 at every Gauss point (Tecgraf order)")
    naive = brick_volumes(model, "vtk")
    close(naive, -volumes, 1e-13, f"{name}: the same lists read in VTK order give the negative volume")


def check_step(model, step, factor, name):
    check(step.factor == factor, f"{name}: factor {factor}")
    u = step.displacement
    close(u[:, :3], displacement(expected_coords(), factor), 1e-15, f"{name}: displacements")
    check(bool(np.all(u[:, 3:] == 0)), f"{name}: rotations 0")
    check(step.nodal_scalar_names == ["VON_MISES", "CONTACT_PRESSURE", "CONTACT_SHEAR"], f"{name}: nodal scalar names")
    x = expected_coords()
    close(step.nodal("CONTACT_PRESSURE"), factor * (x[:, 0] + x[:, 1]), 1e-15, f"{name}: CONTACT_PRESSURE")
    close(step.nodal("CONTACT_SHEAR"), factor * x[:, 2] ** 2, 1e-15, f"{name}: CONTACT_SHEAR")
    # the stress is linear in x, hence trilinear in (r, s, t): extrapolated nodal stress is exact
    close(step.nodal("VON_MISES"), von_mises(stress(x, factor)), 1e-12, f"{name}: VON_MISES at the nodes")
    check(step.gauss_scalar_names == ["STRESS_XX", "STRESS_YY", "STRESS_ZZ", "STRESS_XY", "STRESS_XZ", "STRESS_YZ"],
          f"{name}: Gauss scalar names")
    check(step.gauss_scalars.shape == (len(model.bricks), 8, 6), f"{name}: 8 points x 6 stresses per brick")
    expected = stress(gauss_point_positions(model), factor)
    close(step.gauss_scalars, expected, 1e-13, f"{name}: Gauss stresses, point k beside Tecgraf node k")
    # the same data read as if the points were in VTK order would not match (shows the check bites)
    swapped = step.gauss_scalars[:, [4, 5, 6, 7, 0, 1, 2, 3], :]
    check(not np.allclose(swapped, expected, rtol=1e-6, atol=0), f"{name}: point order matters for the check")


def main(directory):
    try:
        synthetic = read_pos3d(os.path.join(directory, "synthetic.pos"))
        crashed = read_pos3d(os.path.join(directory, "crashed.pos"))
    except Pos3dError as exc:
        print(f"FAILED: {exc}")
        print("0 passed, 1 failed")
        return 1
    materials = np.array([[1000.0, 0.3], [2000.0, 0.25]])
    check(synthetic.title == "synthetic 3x2x2 block, frix\"s pos3d check", "title, quote replaced")
    check_model(synthetic, "synthetic.pos", materials)
    check(len(synthetic.steps) == 2 and synthetic.case_step_labels == ["step1", "step2"], "synthetic.pos: 2 steps listed")
    check_step(synthetic, synthetic.steps[0], 0.5, "synthetic.pos step 1")
    check_step(synthetic, synthetic.steps[1], 1.0, "synthetic.pos step 2")
    check(not os.path.exists(os.path.join(directory, "synthetic.pos.steps.tmp")), "close removed the body file")
    check(not os.path.exists(os.path.join(directory, "synthetic.pos.tmp")), "no temporary file left")

    check_model(crashed, "crashed.pos", np.array([[1.0, 0.0]]))
    check(len(crashed.steps) == 1, "crashed.pos (never closed): complete file with its 1 step")
    check_step(crashed, crashed.steps[0], 0.5, "crashed.pos step 1")

    bad = read_pos3d(os.path.join(directory, "bad.pos"))
    check(len(bad.steps) == 0 and not bad.result_labels, "bad.pos: failed steps left a model-only file")
    return summary()


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print("usage: check_synthetic.py DIRECTORY", file=sys.stderr)
        sys.exit(2)
    sys.exit(main(sys.argv[1]))
