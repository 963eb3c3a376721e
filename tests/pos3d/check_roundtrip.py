#!/usr/bin/python3
"""Compares the POS3D neutral file of a frix run with the VTK files of the same run.

    /usr/bin/python3 tests/pos3d/check_roundtrip.py RUN_BASE      (e.g. out/pos3d_block)

Reads RUN_BASE.pos with postproc/pos3d_reader.py and RUN_BASE.pvd + its .vtu files with meshio
(independent of each other and of frix's Fortran). Reference values: the .vtu arrays, written
with 17 significant digits by frix_vtk_writer, so copied data (coordinates, displacements, load
factors) must agree to 1e-15 relative to the largest value of the array; recovered values
(von Mises, nodal stress extrapolated here from the .pos Gauss values) to 1e-12.
Checks: one .pos step per .vtu dataset with the same factor; coordinates; displacements
(rotations 0); VON_MISES = the .vtu point von_mises; mean of the 8 Gauss stresses of each brick
= the .vtu cell stress (VTK order XX YY ZZ XY YZ XZ); the nodal stress extrapolated from the
.pos Gauss values *assuming point k sits beside Tecgraf node k* (f_a = sum_g N_g(sqrt(3) s_a) f_g,
s = Tecgraf node signs, then the mean over the bricks at each node) = the .vtu point stress;
every brick read in Tecgraf order (nodes 1-4 on t = +1) has positive volume, and the VTK-order
reading of the same lists gives the negative volume.
"""
import os
import sys
import xml.etree.ElementTree as ElementTree

import meshio
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
from pos3d_reader import Pos3dError, brick_volumes, read_pos3d, TECGRAF_BRICK8_SIGNS  # noqa: E402

from check_tools import check, close, summary  # noqa: E402


def nodal_from_gauss(model, gauss, n_nodes):
    """Trilinear extrapolation with the Tecgraf convention, then the mean over bricks."""
    s = TECGRAF_BRICK8_SIGNS
    extrapolation = np.prod(1.0 + np.sqrt(3.0) * s[:, None, :] * s[None, :, :], axis=2) / 8.0  # (node a, point g)
    element_values = np.einsum("ag,egc->eac", extrapolation, gauss)
    total = np.zeros((n_nodes, gauss.shape[2]))
    count = np.zeros(n_nodes)
    np.add.at(total, model.bricks - 1, element_values)
    np.add.at(count, model.bricks - 1, 1.0)
    return total / np.maximum(count, 1.0)[:, None]


def main(base):
    try:
        model = read_pos3d(base + ".pos")
    except Pos3dError as exc:
        print(f"FAILED: {exc}")
        print("0 passed, 1 failed")
        return 1
    folder = os.path.dirname(base + ".pvd")
    datasets = ElementTree.parse(base + ".pvd").getroot().findall(".//DataSet")
    check(len(model.steps) == len(datasets), f"{len(datasets)} .vtu datasets, {len(model.steps)} .pos steps")
    volumes = brick_volumes(model, "tecgraf")
    check(bool(np.all(volumes > 0)), "every brick has positive volume read in Tecgraf order")
    close(brick_volumes(model, "vtk"), -volumes, 1e-13, "VTK-order reading gives the negative volume")
    vtk_order = [0, 1, 2, 3, 5, 4]   # frix Voigt (xx yy zz xy xz yz) -> VTK (XX YY ZZ XY YZ XZ)
    for step, dataset in zip(model.steps, datasets):
        mesh = meshio.read(os.path.join(folder, dataset.get("file")))
        name = f"step {step.id} ({dataset.get('file')})"
        if step.id == 1:
            close(model.coords, mesh.points, 1e-15, "node coordinates")
            check(len(model.bricks) == len(mesh.cells_dict["hexahedron"]), "number of bricks")
        close(step.factor, float(dataset.get("timestep")), 1e-15, f"{name}: factor = pvd time")
        close(step.displacement[:, :3], mesh.point_data["displacement"], 1e-15, f"{name}: displacements")
        check(bool(np.all(step.displacement[:, 3:] == 0)), f"{name}: rotations 0")
        close(step.nodal("VON_MISES"), mesh.point_data["von_mises"].ravel(), 1e-12, f"{name}: VON_MISES")
        gauss = step.gauss_scalars
        check(gauss.shape == (len(model.bricks), 8, 6), f"{name}: 8 points x 6 stresses")
        close(gauss.mean(axis=1)[:, vtk_order], mesh.cell_data["stress"][0], 1e-13, f"{name}: brick mean stress")
        nodal = nodal_from_gauss(model, gauss, len(model.coords))
        close(nodal[:, vtk_order], mesh.point_data["stress"], 1e-12,
              f"{name}: nodal stress extrapolated with point k beside Tecgraf node k")
    return summary()


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print("usage: check_roundtrip.py RUN_BASE", file=sys.stderr)
        sys.exit(2)
    sys.exit(main(sys.argv[1]))
