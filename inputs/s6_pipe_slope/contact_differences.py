#!/usr/bin/python3
"""Displacement differences at the contact slave nodes between two S6(b) runs (the seed's
Table 6.2: mu = 0.1 against 0.3 and 0.3 against 0.6), docs/verification/s6.md.

usage: contact_differences.py RUN_A/<base>_contact.csv RUN_B/<base>_contact.csv
           [--time T] [--rows N] [--plot PNG] [--labels A,B]

Both runs must use the same mesh (the same slave node ids and reference positions). The
contact CSV gives each slave node's current position x + u; at the same reference position
the difference of current positions is the difference of displacements, u_B - u_A. Prints a
summary (largest |du| and largest |du_x|, |du_y|, |du_z|) and the N largest rows (node,
reference position from run A's first row, du in mm); --plot draws the largest |du| and
du_y at the crown and invert lines and du_x at the springline against z.
(An S6 helper until the general postproc/compare_runs.py is available.)
"""
import argparse
import csv
import sys

import numpy as np


def positions(path, time):
    rows = list(csv.DictReader(open(path)))
    times = sorted({float(r["time"]) for r in rows})
    t = times[-1] if time is None else time
    first_t = times[0]
    cur, ref = {}, {}
    for r in rows:
        if int(r["pass"]) != 1:
            continue
        xyz = np.array([float(r[k]) for k in ("x", "y", "z")])
        if abs(float(r["time"]) - t) < 1e-9:
            cur[int(r["node"])] = xyz
        if abs(float(r["time"]) - first_t) < 1e-9:
            ref[int(r["node"])] = xyz
    if not cur:
        sys.exit("contact_differences.py: error: %s has no rows at t = %g" % (path, t))
    return t, cur, ref


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--time", type=float, default=None, help="pseudo time (default: the last)")
    ap.add_argument("--rows", type=int, default=10)
    ap.add_argument("--plot", default=None)
    ap.add_argument("--labels", default="A,B")
    args = ap.parse_args()
    ta, a, ref = positions(args.a, args.time)
    tb, b, _ = positions(args.b, args.time)
    nodes = sorted(set(a) & set(b))
    if len(nodes) != len(a) or len(nodes) != len(b):
        sys.exit("contact_differences.py: error: the runs have different slave nodes")
    d = np.array([b[n] - a[n] for n in nodes])
    p = np.array([ref[n] for n in nodes])        # position at the first written increment
    mag = np.linalg.norm(d, axis=1)
    la, lb = args.labels.split(",")
    print("%s (t = %g) -> %s (t = %g): %d slave nodes" % (la, ta, lb, tb, len(nodes)))
    print("largest |du| = %.4f mm; largest |du_x|, |du_y|, |du_z| = %.4f, %.4f, %.4f mm"
          % ((mag.max() * 1e3,) + tuple(np.abs(d).max(axis=0) * 1e3)))
    print("| node | x | y | z | du_x [mm] | du_y [mm] | du_z [mm] | abs du [mm] |")
    print("|---|---|---|---|---|---|---|---|")
    for i in np.argsort(-mag)[:args.rows]:
        print("| %d | %.3f | %.3f | %.2f | %.4f | %.4f | %.4f | %.4f |"
              % ((nodes[i],) + tuple(p[i]) + tuple(d[i] * 1e3) + (mag[i] * 1e3,)))
    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        from matplotlib import pyplot
        r = np.hypot(p[:, 0], p[:, 1])
        crown = (np.abs(p[:, 0]) < 1e-3) & (p[:, 1] > 0.5 * r)
        invert = (np.abs(p[:, 0]) < 1e-3) & (p[:, 1] < -0.5 * r)
        spring = np.abs(p[:, 1]) < 0.01 * r.max()         # the geostatic step moved it
        zs = np.unique(np.round(p[:, 2], 2))                # stations (geostatic shift < 2 mm)
        figure, axes = pyplot.subplots(figsize=(7, 4.2))
        axes.plot(zs, [mag[np.abs(p[:, 2] - z) < 0.01].max() * 1e3 for z in zs], "k-o", ms=3,
                  label="largest |du| at the station")
        for mask, comp, name in ((crown, 1, "du_y crown"), (invert, 1, "du_y invert"),
                                 (spring, 0, "du_x springline")):
            order = np.argsort(p[mask, 2])
            axes.plot(p[mask, 2][order], d[mask, comp][order] * 1e3, "-", marker=".", label=name)
        axes.set_xlabel("z along the pipe [m] (reference position of the slave node)")
        axes.set_ylabel("u(%s) - u(%s) [mm]" % (lb, la))
        axes.set_title("S6(b): displacement differences at the contact nodes, %s vs %s" % (lb, la))
        axes.grid(alpha=0.3)
        axes.legend(fontsize=8)
        figure.tight_layout()
        figure.savefig(args.plot, dpi=90)
        print("wrote", args.plot)
    return 0


if __name__ == "__main__":
    sys.exit(main())
