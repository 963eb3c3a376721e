"""Check a tetrahedron patch test: check_patch.py H5

TET4 (patch.dck) or TET10 (patch10.dck): every boundary node of the mesh moved by u = A x
(GRADIENT below, make_patch.py writes the conditions), the other nodes free. The element's
shape functions contain the linear fields (TET10's too, with straight edges and mid-edge
nodes at the middle), so (patch test, Zienkiewicz & Taylor, vol. 1, 10.3) every node's
displacement is A x and the stress at every integration point the constant
sigma = lambda tr(eps) I + 2 mu eps, eps = sym(A), with E = 210000, nu = 0.3 of the decks: to
1e-12 relative to |sigma|. The HDF5 file's /mesh/cell_types are all VTK_TETRA (10) or all
VTK_QUADRATIC_TETRA (24); the VTK file beside it must hold the 48 cells as VTK tetrahedra of
that kind with the HDF5 file's nodes, and the stress at every node and cell (VTK order XX YY
ZZ XY YZ XZ) the same constant. Exit 0 if all hold.
"""
import pathlib
import sys

import numpy as np

GRADIENT = np.array([[1e-3, 2e-4, -3e-4], [5e-4, -2e-3, 1e-4], [-4e-4, 3e-4, 1.5e-3]])
YOUNG, POISSON = 210000.0, 0.3
TOLERANCE = 1e-12
# VTK cell type: (nodes, integration points of the frix cell, meshio's name)
CELLS = {10: (4, 1, "tetra"), 24: (10, 4, "tetra10")}


def exact_stress():
    eps = 0.5 * (GRADIENT + GRADIENT.T)
    lam = YOUNG * POISSON / ((1 + POISSON) * (1 - 2 * POISSON))
    mu = YOUNG / (2 * (1 + POISSON))
    s = lam * np.trace(eps) * np.eye(3) + 2 * mu * eps
    return np.array([s[0, 0], s[1, 1], s[2, 2], s[0, 1], s[0, 2], s[1, 2]])   # frix Voigt


def main():
    import h5py
    with h5py.File(sys.argv[1], "r") as f:
        x = f["/mesh/coordinates"][()]
        last = f["/increments"][sorted(f["/increments"])[-1]]
        u = last["displacement"][()]
        stress = last["stress"][()]   # (n_elements, points, 6)
        connectivity = f["/mesh/connectivity"][()]
        cell_types = f["/mesh/cell_types"][()]
    if len(set(cell_types.tolist())) != 1 or cell_types[0] not in CELLS:
        print(f"/mesh/cell_types: {sorted(set(cell_types.tolist()))}, expected VTK_TETRA (10) or 24 only")
        return 1
    n_nodes, n_points, name = CELLS[cell_types[0]]
    stress = stress[:, :n_points, :]
    u_error = np.abs(u - x @ GRADIENT.T).max() / np.abs(x @ GRADIENT.T).max()
    s_error = np.abs(stress - exact_stress()).max() / np.abs(exact_stress()).max()
    print(f"{stress.shape[0]} {name} elements, {n_points} point(s) each; displacement error {u_error:.2e}, "
          f"stress error {s_error:.2e} (relative)")
    vtk_error = vtk_stress_error(pathlib.Path(sys.argv[1]), connectivity, n_nodes, name)
    print(f"VTK: {name} cells with the HDF5 nodes, stress error {vtk_error:.2e} (relative)")
    return 0 if max(u_error, s_error, vtk_error) <= TOLERANCE else 1


def vtk_stress_error(h5_path, connectivity, n_nodes, name):
    """Largest relative deviation of the VTK node and cell stresses from the exact one (inf if
    the cells are not the HDF5 file's: 1-based nodes in the first n_nodes columns, 0 after)."""
    import meshio
    mesh = meshio.read(sorted(h5_path.parent.glob(h5_path.stem + "_*.vtu"))[-1])
    cells = mesh.cells_dict.get(name)
    if list(mesh.cells_dict) != [name] or not np.array_equal(cells + 1, connectivity[:, :n_nodes]) \
            or np.any(connectivity[:, n_nodes:] != 0):
        return np.inf
    s = exact_stress()
    vtk_order = np.array([s[0], s[1], s[2], s[3], s[5], s[4]])
    deviation = max(np.abs(mesh.point_data["stress"] - vtk_order).max(),
                    np.abs(mesh.cell_data["stress"][0] - vtk_order).max())
    return deviation / np.abs(vtk_order).max()


if __name__ == "__main__":
    sys.exit(main())
