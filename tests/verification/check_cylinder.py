#!/usr/bin/python3
"""check_cylinder.py: run a pressurised-tube deck (V4 thick cylinder, S6(a) pipe) and check it.

    check_cylinder.py run FRIX DECK [--curve T,F,T,F,...] [--allow-stop]
                      [--value COLUMN TIME FACTOR EXPECTED REL_TOL LABEL]...
                      [--limit EXPECTED REL_TOL LABEL] [--peak EXPECTED REL_TOL LABEL]
                      [--front TIME EXPECTED ABS_TOL LABEL]...
    check_cylinder.py reference [--inner A] [--outer B] [--young E] [--poisson NU]
                      [--sigy S] [--pressure P ...]

`run` runs frix on DECK in a scratch folder (`--out`), prints the run time, increments and
Newton iterations, then makes the checks; exit status 0 when all pass, 1 otherwise.
  --curve T,F,...  the deck's load curve of the pressure (CURVE ... POINTS), so that the
                   load p = F(t) is known at every time t of the history (default p = t).
  --allow-stop     the run may end with exit status 1 at a limit load: then frix's message must
                   say that an increment failed "at the smallest increment allowed" (the
                   load-controlled run stopped at the limit, docs/solver.md "Cut-back").
  --value          FACTOR x history column COLUMN in the row of time TIME (a number, or `last`)
                   against EXPECTED, relative tolerance.
  --limit          the load F(t) of the last converged increment (a load-controlled run that
                   stopped at the limit) against EXPECTED, relative tolerance.
  --peak           the largest load F(t) over the history (a path-controlled run past the limit).
  --front          the plastic front radius c at time TIME from the HDF5 results file
                   (`increments/*/fields/eqps`): the radius of each integration point (point g
                   beside node g at the parent coordinates +-1/sqrt(3), mapped by the element's
                   shape functions, r = sqrt(x^2 + y^2)); c is the midpoint between the
                   outermost point with EQPS > 0 and the innermost point with EQPS = 0 beyond
                   it, +- half their distance. Absolute tolerance ABS_TOL (a length).
`reference` prints the closed forms used by the checks: Lame's plane strain displacements, the
first yield pressure (von Mises, sigma_z = nu (sigma_r + sigma_theta)), the limit pressure
(2/sqrt 3) sigma_y ln(b/a) and the plastic front radius of Hill's solution
p = k (2 ln(c/a) + 1 - c^2/b^2), k = sigma_y/sqrt 3 (docs/verification/v4_thick_cylinder.md).
"""
import csv
import math
import os
import re
import subprocess
import sys
import tempfile
import time


# ---------------------------------------------------------------------------- closed forms
def lame_ur(p, a, b, young, nu, r):
    """Radial displacement of a tube under internal pressure p, plane strain (eps_z = 0):
    u_r = (1 + nu)/E ((1 - 2 nu) A r + B/r), A = p a^2/(b^2 - a^2), B = p a^2 b^2/(b^2 - a^2)
    (Lame; Timoshenko & Goodier, Theory of Elasticity, 3rd ed. 1970, ch. 4)."""
    big_a = p * a * a / (b * b - a * a)
    big_b = p * a * a * b * b / (b * b - a * a)
    return (1.0 + nu) / young * ((1.0 - 2.0 * nu) * big_a * r + big_b / r)


def first_yield(a, b, nu, sigy):
    """p at which sigma_vm(a) = sigma_y in plane strain: sigma_vm^2 = 3 (B/r^2)^2 + (1 - 2 nu)^2 A^2
    is largest at r = a, so p_y = sigma_y (b^2 - a^2)/sqrt(3 b^4 + (1 - 2 nu)^2 a^4)."""
    return sigy * (b * b - a * a) / math.sqrt(3.0 * b ** 4 + (1.0 - 2.0 * nu) ** 2 * a ** 4)


def limit_pressure(a, b, sigy):
    """(2/sqrt 3) sigma_y ln(b/a): plane strain, von Mises (Hill 1950, ch. V)."""
    return 2.0 / math.sqrt(3.0) * sigy * math.log(b / a)


def hill_pressure(c, a, b, sigy):
    """p = k (2 ln(c/a) + 1 - c^2/b^2), k = sigma_y/sqrt 3 (Hill 1950, ch. V)."""
    return sigy / math.sqrt(3.0) * (2.0 * math.log(c / a) + 1.0 - c * c / (b * b))


def hill_front(p, a, b, sigy):
    """The front radius c in [a, b] of hill_pressure(c) = p (bisection; p between the
    first yield k (1 - a^2/b^2) and the limit)."""
    low, high = a, b
    for _ in range(200):
        middle = 0.5 * (low + high)
        if hill_pressure(middle, a, b, sigy) < p:
            low = middle
        else:
            high = middle
    return 0.5 * (low + high)


# ---------------------------------------------------------------------------- run and read
def fail_usage(message):
    print(f"check_cylinder.py: {message}", file=sys.stderr)
    sys.exit(2)


class Curve:
    """Piecewise-linear p = F(t), constant beyond the ends (identity without points)."""

    def __init__(self, text):
        self.points = None
        if text:
            values = [float(v) for v in text.replace(",", " ").split()]
            if len(values) < 4 or len(values) % 2:
                fail_usage(f"--curve needs pairs T,F (at least two): {text}")
            self.points = list(zip(values[0::2], values[1::2]))

    def __call__(self, t):
        if self.points is None:
            return t
        pts = self.points
        if t <= pts[0][0]:
            return pts[0][1]
        for (t0, f0), (t1, f1) in zip(pts, pts[1:]):
            if t <= t1:
                return f0 + (f1 - f0) * (t - t0) / (t1 - t0)
        return pts[-1][1]


def read_history(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        print(f"FAIL no converged increment in {path}")
        sys.exit(1)
    return rows


def history_row(rows, when):
    if when == "last":
        return rows[-1]
    t = float(when)
    for row in rows:
        if abs(float(row["time"]) - t) <= 1e-9 * max(1.0, abs(t)):
            return row
    print(f"FAIL no history row at time {when} (times: "
          f"{', '.join(row['time'] for row in rows[:5])} ...)")
    sys.exit(1)


def report(ok, label, text):
    print(f"{'ok  ' if ok else 'FAIL'} {label}: {text}")
    return ok


def relative_check(label, value, expected, tol):
    error = (value - expected) / abs(expected)
    return report(abs(error) <= tol, label,
                  f"{value:.6g}, expected {expected:.6g}, relative error {error:+.3e} "
                  f"(tolerance {tol:.1e})")


def gauss_point_radii(coordinates, connectivity):
    """(n_elements, 8) radii sqrt(x^2 + y^2) of the 2x2x2 points, point g beside node g."""
    import numpy as np
    corners = np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
                        [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]], dtype=float)
    points = corners / math.sqrt(3.0)
    shape = np.prod(1.0 + points[:, None, :] * corners[None, :, :], axis=2) / 8.0  # (g, a)
    xyz = coordinates[connectivity - 1]                    # (e, a, 3)
    at_points = np.einsum("ga,ead->egd", shape, xyz)       # (e, g, 3)
    return np.hypot(at_points[..., 0], at_points[..., 1])


def plastic_front(h5_path, when):
    """(c, half width, n plastic points, n points) at time `when` from the HDF5 file."""
    import h5py
    import numpy as np
    with h5py.File(h5_path, "r") as f:
        radii = gauss_point_radii(f["/mesh/coordinates"][()], f["/mesh/connectivity"][()])
        group = None
        for g in f["increments"].values():
            if g.attrs.get("complete", 0) == 1 and abs(float(g.attrs["time"]) - when) <= 1e-9 * max(1.0, when):
                group = g
        if group is None:
            return None
        eqps = group["fields/eqps"][()]                    # (e, points)
    plastic = eqps > 0.0
    if not plastic.any():
        return radii.min(), 0.0, 0, eqps.size
    outer_plastic = radii[plastic].max()
    beyond = radii[(~plastic) & (radii > outer_plastic)]
    inner_elastic = beyond.min() if beyond.size else radii.max()
    elastic_inside = int(np.count_nonzero((~plastic) & (radii < outer_plastic)))
    if elastic_inside:
        print(f"note: {elastic_inside} elastic points lie inside the outermost plastic point")
    return (0.5 * (outer_plastic + inner_elastic), 0.5 * (inner_elastic - outer_plastic),
            int(plastic.sum()), eqps.size)


def run(argv):
    if len(argv) < 2:
        fail_usage("usage: check_cylinder.py run FRIX DECK [options] (see --help)")
    frix, deck = argv[0], argv[1]
    options = argv[2:]
    checks, curve_text, allow_stop = [], None, False
    arity = {"--value": 6, "--limit": 3, "--peak": 3, "--front": 4}
    i = 0
    while i < len(options):
        option = options[i]
        if option == "--curve" and i + 1 < len(options):
            curve_text, i = options[i + 1], i + 2
        elif option == "--allow-stop":
            allow_stop, i = True, i + 1
        elif option in arity and i + arity[option] < len(options):
            checks.append((option, options[i + 1:i + 1 + arity[option]]))
            i += 1 + arity[option]
        else:
            fail_usage(f"unknown or incomplete option {option} (see --help)")
    curve = Curve(curve_text)
    name = os.path.splitext(os.path.basename(deck))[0]
    with tempfile.TemporaryDirectory() as work:
        start = time.time()
        result = subprocess.run([frix, deck, "--out", work, "--quiet"], capture_output=True, text=True)
        elapsed = time.time() - start
        message = result.stdout + result.stderr
        print(f"run time {elapsed:.2f} s")
        stopped = False
        if result.returncode == 1 and allow_stop and "at the smallest increment allowed" in message:
            stopped = True
            match = re.search(r"failed.*", message, re.S)
            print("frix stopped at the limit: " + " ".join(match.group(0).split())[:400])
        elif result.returncode != 0:
            print(f"FAIL frix exit status {result.returncode} on {deck}:")
            print("\n".join(message.splitlines()[-20:]))
            return 1
        listing = os.path.join(work, f"{name}_listing.txt")
        increments = iterations = 0
        with open(listing) as f:
            for line in f:
                if line.startswith("STEP"):
                    increments += 1
                    iterations += int(line.split()[-1])
        print(f"{name}: {increments} increments, {iterations} Newton iterations")
        rows = read_history(os.path.join(work, f"{name}_history.csv"))
        ok = True
        for option, args in checks:
            if option == "--value":
                column, when, factor, expected, tol, label = args
                row = history_row(rows, when)
                if column not in row:
                    fail_usage(f"no column {column} in the history (columns: {', '.join(row)})")
                ok &= relative_check(f"{label} (t = {float(row['time']):.6g})",
                                     float(factor) * float(row[column]), float(expected), float(tol))
            elif option == "--limit":
                expected, tol, label = args
                t_last = float(rows[-1]["time"])
                if not stopped:
                    ok &= report(False, label, "the run did not stop at a limit load "
                                 f"(it reached t = {t_last:.6g})")
                    continue
                ok &= relative_check(f"{label} (last converged t = {t_last:.8g})", curve(t_last),
                                     float(expected), float(tol))
            elif option == "--peak":
                expected, tol, label = args
                loads = [(curve(float(row["time"])), float(row["time"])) for row in rows]
                peak, t_peak = max(loads)
                ok &= relative_check(f"{label} (at t = {t_peak:.8g})", peak, float(expected), float(tol))
            elif option == "--front":
                when, expected, tol, label = args
                front = plastic_front(os.path.join(work, f"{name}.h5"), float(when))
                if front is None:
                    ok &= report(False, label, f"no HDF5 increment at t = {when}")
                    continue
                c, half, n_plastic, n_points = front
                error = c - float(expected)
                ok &= report(abs(error) <= float(tol), f"{label} (t = {float(when):g}, p = {curve(float(when)):.6g})",
                             f"c = {c:.4f} +- {half:.4f} ({n_plastic} of {n_points} points plastic), "
                             f"expected {float(expected):.4f}, error {error:+.4f} (tolerance {float(tol):g})")
        return 0 if ok else 1


def reference(argv):
    import argparse
    parser = argparse.ArgumentParser(prog="check_cylinder.py reference")
    parser.add_argument("--inner", type=float, default=1.0)
    parser.add_argument("--outer", type=float, default=2.0)
    parser.add_argument("--young", type=float, default=210000.0)
    parser.add_argument("--poisson", type=float, default=0.3)
    parser.add_argument("--sigy", type=float, default=240.0)
    parser.add_argument("--pressure", type=float, nargs="*", default=[100.0, 150.0, 180.0])
    args = parser.parse_args(argv)
    a, b = args.inner, args.outer
    print(f"a = {a:g}, b = {b:g}, E = {args.young:g}, nu = {args.poisson:g}, sigma_y = {args.sigy:g}")
    py = first_yield(a, b, args.poisson, args.sigy)
    pl = limit_pressure(a, b, args.sigy)
    print(f"first yield (von Mises, plane strain, at r = a): p_y = {py:.6f}")
    print(f"first yield with sigma_z = (sigma_r + sigma_theta)/2: k (1 - a^2/b^2) = "
          f"{hill_pressure(a, a, b, args.sigy):.6f}")
    print(f"limit pressure (2/sqrt 3) sigma_y ln(b/a) = {pl:.6f}")
    for p in args.pressure:
        line = (f"p = {p:g}: Lame u_r(a) = {lame_ur(p, a, b, args.young, args.poisson, a):.9e}, "
                f"u_r(b) = {lame_ur(p, a, b, args.young, args.poisson, b):.9e}")
        if py < p < pl:
            line += f"; Hill front c = {hill_front(p, a, b, args.sigy):.6f}"
        print(line)
    return 0


def main():
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(sys.argv) >= 2 else 2
    if sys.argv[1] == "run":
        return run(sys.argv[2:])
    if sys.argv[1] == "reference":
        return reference(sys.argv[2:])
    fail_usage(f"unknown command {sys.argv[1]} (run, reference)")


if __name__ == "__main__":
    sys.exit(main())
