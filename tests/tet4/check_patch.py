"""Check the TET4 patch test: check_patch.py H5

Every boundary node of patch.inp moved by u = A x (GRADIENT below, make_patch.py writes the
conditions), the interior node free. A linear element reproduces a linear field exactly, so
(patch test, Zienkiewicz & Taylor, vol. 1, 10.3) every node's displacement is A x and every
element's stress the constant sigma = lambda tr(eps) I + 2 mu eps, eps = sym(A), with
E = 210000, nu = 0.3 of patch.dck: to 1e-10 relative to |sigma|. Exit 0 if all hold.
"""
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
    u_error = np.abs(u - x @ GRADIENT.T).max() / np.abs(x @ GRADIENT.T).max()
    s_error = np.abs(stress - exact_stress()).max() / np.abs(exact_stress()).max()
    print(f"{stress.shape[0]} elements; displacement error {u_error:.2e}, stress error {s_error:.2e} (relative)")
    return 0 if u_error <= 1e-10 and s_error <= 1e-10 else 1


if __name__ == "__main__":
    sys.exit(main())
