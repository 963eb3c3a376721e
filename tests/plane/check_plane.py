"""Checks of the plane strain and axisymmetric decks (tests/plane), on a run's results
(tests/harness/run_deck_check.sh runs the deck and calls it with OUT BASE):

  check_plane.py OUT BASE patch --gradient G11 G12 G21 G22 --young E --poisson NU [--axisymmetric]
      Patch test: every node's in-plane displacement is G x (x, y) and u_z = 0; every
      integration point's strain is the constant eps = sym(G) with eps_33 = 0 (plane strain) or
      eps_33 = G11 (axisymmetric: the hoop strain u_r / r of u_r = G11 r, which needs G12 = 0),
      and its stress the linear elastic one of that strain; all to 1e-10 relative. Cells of
      the HDF5 file: VTK_QUAD (9).
  check_plane.py OUT BASE history COLUMN[@TIME]=REFERENCE:TOLERANCE ...
      The history CSV's row at pseudo time TIME (default: the last row): each column within
      the relative tolerance of its reference (the reference's source is given where the test
      is registered).
  check_plane.py OUT BASE s1
      S1 in plane strain (s1_plane.dck): at every load level of step 2 (p = 300 (t - 1)) the
      free end's u_x (u1_n31) within the 6 % of benchmark S1 of Hird & Russell's solution
      (postproc/s1_analytical.py) and below it (the 1D theory ignores the shear lag over H).

  check_plane.py OUT BASE contact_patch --pressure P --poisson NU --tolerance T [--axisymmetric]
      Contact patch test (contact_patch_plane.dck, contact_patch_axisym.dck): at the last
      increment every integration point's stress is the uniaxial sigma_yy = -P, sigma_zz = -NU P
      (plane strain; 0, the hoop stress, with --axisymmetric), the other components 0, and
      every slave node of the contact CSV (both passes) has pressure P and no tangential
      traction; each within T of P.

OUT is the run's output folder, BASE the deck's name (files OUT/BASE.h5, OUT/BASE_history.csv).
Exit 0 if every check holds.
"""
import argparse
import csv
import pathlib
import sys

import numpy as np

TOLERANCE = 1e-10
VTK_QUAD, QUAD4_POINTS = 9, 4


def elastic_stress(eps, young, poisson):
    """Voigt 11 22 33 12 13 23 stress (tensor shears) of the strain eps (engineering shears)."""
    lam = young * poisson / ((1 + poisson) * (1 - 2 * poisson))
    mu = young / (2 * (1 + poisson))
    normal = lam * eps[:3].sum() + 2 * mu * eps[:3]
    return np.concatenate([normal, mu * eps[3:]])


def check_patch(args):
    import h5py
    g = np.array(args.gradient).reshape(2, 2)
    if args.axisymmetric and g[0, 1] != 0.0:
        print("--axisymmetric needs G12 = 0 (u_r = G11 r)")
        return 1
    with h5py.File(pathlib.Path(args.out) / f"{args.base}.h5", "r") as f:
        x = f["/mesh/coordinates"][()]
        cells = f["/mesh/cell_types"][()]
        last = f["/increments"][sorted(f["/increments"], key=int)[-1]]
        u = last["displacement"][()]
        stress = last["stress"][()][:, :QUAD4_POINTS, :]
        strain = last["strain"][()][:, :QUAD4_POINTS, :] if "strain" in last else None
    if set(cells.tolist()) != {VTK_QUAD}:
        print(f"/mesh/cell_types {sorted(set(cells.tolist()))}: expected VTK_QUAD (9) only")
        return 1
    exact_u = np.zeros_like(u)
    exact_u[:, :2] = x[:, :2] @ g.T
    eps = np.array([g[0, 0], g[1, 1], g[0, 0] if args.axisymmetric else 0.0, g[0, 1] + g[1, 0], 0.0, 0.0])
    sigma = elastic_stress(eps, args.young, args.poisson)
    u_error = np.abs(u - exact_u).max() / np.abs(exact_u).max()
    s_error = np.abs(stress - sigma).max() / np.abs(sigma).max()
    errors = [u_error, s_error]
    text = f"{len(cells)} QUAD4 cells: displacement error {u_error:.2e}, stress error {s_error:.2e}"
    if strain is not None:
        e_error = np.abs(strain - eps).max() / np.abs(eps).max()
        errors.append(e_error)
        text += f", strain error {e_error:.2e}"
    print(text + f" (relative; exact sigma = {np.array2string(sigma, precision=6)})")
    return 0 if max(errors) <= TOLERANCE else 1


def check_contact_patch(args):
    import h5py
    p = args.pressure
    with h5py.File(pathlib.Path(args.out) / f"{args.base}.h5", "r") as f:
        last = f["/increments"][sorted(f["/increments"], key=int)[-1]]
        stress = last["stress"][()][:, :QUAD4_POINTS, :]
    exact = np.array([0.0, -p, 0.0 if args.axisymmetric else -args.poisson * p, 0.0, 0.0, 0.0])
    s_error = np.abs(stress - exact).max() / p
    with open(pathlib.Path(args.out) / f"{args.base}_contact.csv") as f:
        rows = list(csv.DictReader(row for row in f if not row.startswith("#")))
    last_time = rows[-1]["time"]
    rows = [r for r in rows if r["time"] == last_time]
    pressure = np.array([float(r["pressure"]) for r in rows])
    traction = np.array([[float(r[f"traction_{c}"]) for c in "xyz"] for r in rows])
    p_error = np.abs(pressure - p).max() / p
    t_error = np.abs(traction).max() / p
    passes = sorted({r["pass"] for r in rows})
    print(f"{stress.shape[0]} cells: stress error {s_error:.2e}; {len(rows)} slave nodes of passes "
          f"{' '.join(passes)}: pressure error {p_error:.2e}, tangential traction {t_error:.2e} "
          f"(relative to p = {p:g}; tolerance {args.tolerance:.1e})")
    ok = max(s_error, p_error, t_error) <= args.tolerance and len(passes) == 2
    return 0 if ok else 1


def check_history(args):
    with open(pathlib.Path(args.out) / f"{args.base}_history.csv") as f:
        rows = list(csv.DictReader(row for row in f if not row.startswith("#")))
    failed = 0
    for item in args.checks:
        column, rest = item.split("=")
        reference, tolerance = (float(v) for v in rest.split(":"))
        row = rows[-1]
        if "@" in column:
            column, time = column.split("@")
            matching = [r for r in rows if abs(float(r["time"]) - float(time)) <= 1e-9 * max(1.0, abs(float(time)))]
            if not matching:
                print(f"no history row at time {time}")
                return 1
            row = matching[-1]
        value = float(row[column])
        error = (value - reference) / abs(reference)
        ok = abs(error) <= tolerance
        failed += not ok
        print(f"{column} at t = {float(row['time']):g}: {value:.7e}, reference {reference:.7e}: {error:+.2e} relative "
              f"(tolerance {tolerance:.1e}) {'ok' if ok else 'FAIL'}")
    return 1 if failed else 0


def check_s1(args):
    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "postproc"))
    import s1_analytical
    theory = s1_analytical.Theory()
    with open(pathlib.Path(args.out) / f"{args.base}_history.csv") as f:
        rows = [r for r in csv.DictReader(row for row in f if not row.startswith("#")) if r["step"] == "2"]
    failed = 0
    for row in rows:
        load = 300.0 * (float(row["time"]) - 1.0)
        exact = -float(theory.displacement(load, theory.length))
        value = float(row["u1_n31"])
        error = (value - exact) / abs(exact)
        ok = abs(error) <= 0.06 and abs(value) <= abs(exact)
        failed += not ok
        print(f"p = {load:6.1f}: free end u_x {value:.6e}, Hird & Russell {exact:.6e}, {100 * error:+.2f} % "
              f"{'ok' if ok else 'FAIL'}")
    return 1 if failed or len(rows) != 6 else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("base")
    sub = parser.add_subparsers(dest="what", required=True)
    patch = sub.add_parser("patch")
    history = sub.add_parser("history")
    patch.add_argument("--gradient", type=float, nargs=4, required=True)
    patch.add_argument("--young", type=float, required=True)
    patch.add_argument("--poisson", type=float, required=True)
    patch.add_argument("--axisymmetric", action="store_true")
    history.add_argument("checks", nargs="+", metavar="COLUMN[@TIME]=REFERENCE:TOLERANCE")
    sub.add_parser("s1")
    contact_patch = sub.add_parser("contact_patch")
    contact_patch.add_argument("--pressure", type=float, required=True)
    contact_patch.add_argument("--poisson", type=float, required=True)
    contact_patch.add_argument("--tolerance", type=float, required=True)
    contact_patch.add_argument("--axisymmetric", action="store_true")
    args = parser.parse_args()
    return {"patch": check_patch, "history": check_history, "s1": check_s1,
            "contact_patch": check_contact_patch}[args.what](args)


if __name__ == "__main__":
    sys.exit(main())
