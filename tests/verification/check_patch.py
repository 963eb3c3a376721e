#!/usr/bin/python3
"""Check a V1 patch-test run against its exact homogeneous solution.

usage: check_patch.py DECK VTU [--tol 1e-10]

DECK carries `// VERIFY key values` lines (written by
inputs/verification/v1_patch/generate_patch_decks.py):
  case displacement: u = A X prescribed on the outer nodes; the exact solution is u = A X at
      every node (a homogeneous deformation solves the equilibrium equations without body
      force for any homogeneous material, small strain or finite).
  case uniaxial: rollers on x = 0, y = 0, z = 0, traction t on x = 1 (small strain):
      u = (t x, -nu t y, -nu t z)/E, sigma = diag(t, 0, 0).
Expected stresses and strains are computed here independently of frix:
  linear:   eps = sym(A),  sigma = lambda tr(eps) I + 2 mu eps           (Hooke)
  svk:      E = (F^T F - I)/2,  S = lambda tr(E) I + 2 mu E             (St. Venant-Kirchhoff)
  neohooke: S = mu (I - C^-1) + lambda ln J C^-1                        (docs/materials; Bonet & Wood 6.4.3)
  total Lagrangian output: Cauchy sigma = F S F^T / J, strain = Green-Lagrange E.
Compared: the displacement of every node (in particular the 8 free inner nodes) and every
element's cell stress and strain (VTK cell data, 17 significant digits), each as
max |computed - exact| / max |exact| of that field, which must be <= tol.
Prints one line per quantity and exits 1 on failure.
"""
import sys
import numpy as np
import meshio


def read_verify(deck):
    values = {}
    with open(deck) as f:
        for line in f:
            line = line.strip()
            if line.startswith("// VERIFY "):
                words = line.split()[2:]
                values[words[0]] = words[1:]
    return values


def to_vtk_order(t):
    """3x3 symmetric tensor -> VTK's XX YY ZZ XY YZ XZ."""
    return np.array([t[0, 0], t[1, 1], t[2, 2], t[0, 1], t[1, 2], t[0, 2]])


def main(argv):
    if len(argv) < 3:
        print(__doc__)
        return 2
    deck, vtu = argv[1], argv[2]
    tol = float(argv[argv.index("--tol") + 1]) if "--tol" in argv else 1e-10
    v = read_verify(deck)
    young, nue = float(v["young"][0]), float(v["nue"][0])
    lam = young * nue / ((1 + nue) * (1 - 2 * nue))
    mu = young / (2 * (1 + nue))
    kin, law, case = v["kinematics"][0], v["law"][0], v["case"][0]
    eye = np.eye(3)

    mesh = meshio.read(vtu)
    X = mesh.points
    if case == "displacement":
        A = np.array([float(a) for a in v["A"]]).reshape(3, 3)
    else:
        t = float(v["traction"][0])
        A = np.diag([t / young, -nue * t / young, -nue * t / young])
    u_exact = X @ A.T
    if kin == "Geo_Lin":
        strain = 0.5 * (A + A.T)
        if case == "uniaxial":
            stress = np.diag([t, 0.0, 0.0])
        else:
            stress = lam * np.trace(strain) * eye + 2 * mu * strain
    else:
        F = eye + A
        C = F.T @ F
        J = np.linalg.det(F)
        strain = 0.5 * (C - eye)
        if law == "svk":
            S = lam * np.trace(strain) * eye + 2 * mu * strain
        elif law == "neohooke":
            Cinv = np.linalg.inv(C)
            S = mu * (eye - Cinv) + lam * np.log(J) * Cinv
        else:
            print(f"check_patch: law {law} not supported with {kin}")
            return 2
        stress = F @ S @ F.T / J

    failures = 0

    def report(name, computed, exact):
        nonlocal failures
        scale = np.max(np.abs(exact))
        err = np.max(np.abs(computed - exact)) / scale
        ok = err <= tol
        failures += 0 if ok else 1
        print(f"{'ok  ' if ok else 'FAIL'} {name:32s} max rel error {err:.3e} (tol {tol:.0e}, scale {scale:.6g})")

    u = mesh.point_data["displacement"]
    report(f"displacement, all {len(X)} nodes", u, u_exact)
    inner = np.all((X > 1e-9) & (X < 1 - 1e-9), axis=1)
    if np.any(inner):
        report(f"displacement, {int(inner.sum())} inner nodes", u[inner], u_exact[inner])
    cell_stress = mesh.cell_data["stress"][0]
    cell_strain = mesh.cell_data["strain"][0]
    n_cells = len(cell_stress)
    report(f"cell stress, {n_cells} elements", cell_stress, np.tile(to_vtk_order(stress), (n_cells, 1)))
    report(f"cell strain, {n_cells} elements", cell_strain, np.tile(to_vtk_order(strain), (n_cells, 1)))
    report("nodal (recovered) stress", mesh.point_data["stress"], np.tile(to_vtk_order(stress), (len(X), 1)))
    print(f"check_patch: {'passed' if failures == 0 else 'FAILED'} ({failures} failures)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
