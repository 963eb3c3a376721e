"""Check the TET4 patch test: check_patch.py H5

Every boundary node of patch.inp moved by u = A x (GRADIENT below, make_patch.py writes the
conditions), the interior node free. A linear element reproduces a linear field exactly, so
(patch test, Zienkiewicz & Taylor, vol. 1, 10.3) every node's displacement is A x and every
element's stress the constant sigma = lambda tr(eps) I + 2 mu eps, eps = sym(A), with
E = 210000, nu = 0.3 of patch.dck: to 1e-10 relative to |sigma|. The VTK file beside the
HDF5 file (whose /mesh/cell_types are VTK_TETRA, 10) must hold the 48 cells as VTK tetrahedra with the HDF5 file's nodes, and the stress
at every node and cell (VTK order XX YY ZZ XY YZ XZ) the same constant. Exit 0 if all hold.
"""
import pathlib
import sys

import numpy as np

GRADIENT = np.array([[1e-3, 2e-4, -3e-4], [5e-4, -2e-3, 1e-4], [-4e-4, 3e-4, 1.5e-3]])
YOUNG, POISSON = 210000.0, 0.3


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
        stress = last["stress"][()][:, 0, :]   # (n_elements, point 1, 6): a TET4's one point
        connectivity = f["/mesh/connectivity"][()]
        cell_types = f["/mesh/cell_types"][()]
    u_error = np.abs(u - x @ GRADIENT.T).max() / np.abs(x @ GRADIENT.T).max()
    s_error = np.abs(stress - exact_stress()).max() / np.abs(exact_stress()).max()
    print(f"{stress.shape[0]} elements; displacement error {u_error:.2e}, stress error {s_error:.2e} (relative)")
    if not np.all(cell_types == 10):
        print(f"/mesh/cell_types: {sorted(set(cell_types.tolist()))}, expected VTK_TETRA (10) only")
        return 1
    vtk_error = vtk_stress_error(pathlib.Path(sys.argv[1]), connectivity)
    print(f"VTK: tetrahedra with the HDF5 nodes, stress error {vtk_error:.2e} (relative)")
    return 0 if u_error <= 1e-10 and s_error <= 1e-10 and vtk_error <= 1e-10 else 1


def vtk_stress_error(h5_path, connectivity):
    """Largest relative deviation of the VTK node and cell stresses from the exact one (inf if
    the cells are not the HDF5 file's tetrahedra: 1-based nodes in the first 4 columns, 0 after)."""
    import meshio
    mesh = meshio.read(sorted(h5_path.parent.glob(h5_path.stem + "_*.vtu"))[-1])
    tetra = mesh.cells_dict.get("tetra")
    if list(mesh.cells_dict) != ["tetra"] or not np.array_equal(tetra + 1, connectivity[:, :4]) \
            or np.any(connectivity[:, 4:] != 0):
        return np.inf
    s = exact_stress()
    vtk_order = np.array([s[0], s[1], s[2], s[3], s[5], s[4]])
    deviation = max(np.abs(mesh.point_data["stress"] - vtk_order).max(),
                    np.abs(mesh.cell_data["stress"][0] - vtk_order).max())
    return deviation / np.abs(vtk_order).max()


if __name__ == "__main__":
    sys.exit(main())
