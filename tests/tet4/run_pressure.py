"""Pressure on tetrahedron faces against statics and the closed form: run_pressure.py FRIX

Meshes beam.geo with gmsh at h = 0.5, order 1 (TET4, TRI3 end faces) and order 2 (TET10,
TRI6 end faces), and runs on it pressure_tet4.dck, pressure_tet10.dck (a dead pressure p = 10,
small strain) and pressure_tet10_follower.dck (a follower pressure p = 50, total Lagrangian,
St. Venant-Kirchhoff). E = 1000, nu = 0, the end x = 0 clamped. Checks, on the last increment
of the HDF5 file and the history CSV:
- statics: the reactions at the clamp sum to (p A, 0, 0), A = 1, to 1e-12 relative: the
  pressure's resultant is p times the face area (the end face's triangles are flat);
- the closed form: with nu = 0 the state is uniaxial and the lateral stretch 1 (S_yy = 0 gives
  E_yy = 0 for St. Venant-Kirchhoff too, so the current end area stays A and the follower load
  stays p A along -x), the displacement u = ((lambda - 1) x, 0, 0), linear in x, which both
  elements hold: lambda = 1 - p/E at small strain, and lambda E (lambda^2 - 1) / 2 = -p (the
  first Piola-Kirchhoff stress lambda S) under total Lagrangian kinematics; every node to
  1e-10 of the end displacement.
Exit 0 if all hold.
"""
import csv
import pathlib
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np
from scipy.optimize import brentq

HERE = pathlib.Path(__file__).resolve().parent
YOUNG = 1000.0
CASES = [("pressure_tet4.dck", 1, 10.0, False), ("pressure_tet10.dck", 2, 10.0, False),
         ("pressure_tet10_follower.dck", 2, 50.0, True)]


def stretch(pressure, total_lagrangian):
    if not total_lagrangian:
        return 1.0 - pressure / YOUNG
    return brentq(lambda s: s * YOUNG * (s * s - 1) / 2 + pressure, 0.5, 1.0)


def run_case(frix, scratch, deck, order, pressure, total_lagrangian):
    work = pathlib.Path(scratch) / deck
    work.mkdir()
    subprocess.run(["gmsh", "-3", "-setnumber", "h", "0.5", "-setnumber", "order", str(order), str(HERE / "beam.geo"),
                    "-format", "msh22", "-o", str(work / "beam.msh")], check=True, stdout=subprocess.DEVNULL)
    shutil.copy(HERE / deck, work / deck)
    out = work / "out"
    subprocess.run([frix, str(work / deck), "--out", str(out), "--quiet"], check=True)
    rows = list(csv.reader(open(next(out.glob("*.csv")))))
    reaction = np.array([float(v) for v in rows[-1][3:6]])
    with h5py.File(next(out.glob("*.h5")), "r") as f:
        x = f["/mesh/coordinates"][()]
        last = f["/increments"][sorted(f["/increments"])[-1]]
        u = last["displacement"][()]
    lam = stretch(pressure, total_lagrangian)
    exact = np.zeros_like(u)
    exact[:, 0] = (lam - 1) * x[:, 0]
    reaction_error = np.abs(reaction - [pressure, 0, 0]).max() / pressure
    u_error = np.abs(u - exact).max() / abs((lam - 1) * 10)
    print(f"{deck}: reaction sum {reaction} (p A = {pressure}), error {reaction_error:.1e}; "
          f"stretch {lam:.6f}, displacement error {u_error:.1e} (relative to the end's)")
    return reaction_error <= 1e-12 and u_error <= 1e-10


def main():
    frix = sys.argv[1]
    with tempfile.TemporaryDirectory() as scratch:
        results = [run_case(frix, scratch, *case) for case in CASES]
    print("all checks hold" if all(results) else "FAILED")
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
