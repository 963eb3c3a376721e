#!/usr/bin/python3
"""Checks of one run of overhang.dck (a slave block overhanging its master's free edge;
docs/contact.md "Edges and corners") or of soft_overhang.dck (the same with E = 1e3, EPSN 1e6,
10 increments). Usage: check_overhang.py RUN_BASE [--window W] [--tolerance T]
[--increments K --max-iterations N]
RUN_BASE is the frix output prefix (DIR/overhang): <base>_contact.csv and <base>.pvd are read
(last increment), with --increments also <base>_listing.txt. --window: how far (current x) a
slave column may lie from its reference x (default 0.01; the soft slab moves up to 0.012);
--tolerance: of the equilibrium checks (default 1e-8); --increments K --max-iterations N: the
run took exactly K increments (no cut-back), each in at most N Newton iterations. Prints
PASS:/FAIL: lines and "N passed, N failed"; exit 0 if all pass.

The deck: master = the top face of the lower block [0,2] x [0,1] x [0,1] (faces 0.5 x 0.5), free
edge x = 2; slave = the bottom face of the upper block [1.28,2.28] x [0,1] x [1,1.5], nodes
every 0.125 in x (9 columns) and 1/3 in y (4 rows); pressure P = 100 on the upper block's top.
The search's extension zone beyond the free edge is 0.1 x the master face's length across it
(frix_contact_search's extension_zone): 0.1 x 0.5 = 0.05. So:
- the 7 x 4 slave nodes at x <= 2.03 (over the master, and the column 0.03 beyond the edge,
  inside the zone) are pressed: status != 0, p > 0;
- the 2 x 4 nodes at x = 2.155 and 2.28 (0.155 and 0.28 beyond) are open: status 0, p = 0
  (before the free-edge rule the column x = 2.155 was pressed against the master plane's
  extension, p = 114-141; x = 2.28 lies outside the search band's boxes);
- equilibrium: sum p_i n_z,i A_i over the slave nodes (A_i the bilinear tributary areas of the
  reference grid; n_z the vertical component of the normal used: frictionless, the traction is
  p n) and the z reaction of the support z = 0 both equal P x 1 x 1 = 100, to 1e-6 relative
  (the deck's Newton tolerance is 1e-8 on the residual).
"""
import argparse
import csv
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
import frix_results as fr  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from check_tally import check, summary  # noqa: E402

LOAD = 100.0                      # P x the upper block's 1 x 1 top
X0, DX, NX = 1.28, 0.125, 8       # slave grid in x (reference)
NY = 3                            # slave grid: 1/3 in y
EDGE, ZONE = 2.0, 0.1 * 0.5       # the master's free edge and extension zone


def tributary_area(x, y):
    """Bilinear tributary area of the slave node nearest (x, y) on the reference grid."""
    i = int(round((x - X0) / DX))
    j = int(round(y * NY))
    wx = DX * (0.5 if i in (0, NX) else 1.0)
    wy = (0.5 if j in (0, NY) else 1.0) / NY
    return wx * wy


def check_iterations(base, increments, max_iterations):
    """The listing's increments: exactly `increments`, each in at most max_iterations."""
    with open(base + "_listing.txt", encoding="utf-8") as stream:
        counts = [int(m.group(1)) for m in re.finditer(r"^STEP .* ITERATIONS +(\d+)", stream.read(), re.M)]
    check(len(counts) == increments, f"{increments} increments (no cut-back): {len(counts)}")
    check(counts and max(counts) <= max_iterations,
          f"Newton iterations per increment <= {max_iterations}: {counts}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("base")
    parser.add_argument("--window", type=float, default=0.01)
    parser.add_argument("--tolerance", type=float, default=1e-8)
    parser.add_argument("--increments", type=int)
    parser.add_argument("--max-iterations", type=int)
    args = parser.parse_args()
    base, window, tolerance = args.base, args.window, args.tolerance
    if args.increments is not None:
        check_iterations(base, args.increments, args.max_iterations)
    with open(base + "_contact.csv", newline="", encoding="utf-8") as stream:
        rows = list(csv.DictReader(stream))
    last = max((int(r["step"]), int(r["increment"])) for r in rows)
    rows = [r for r in rows if (int(r["step"]), int(r["increment"])) == last]
    x = np.array([float(r["x"]) for r in rows])
    y = np.array([float(r["y"]) for r in rows])
    pressure = np.array([float(r["pressure"]) for r in rows])
    status = np.array([int(r["status"]) for r in rows])
    normal_z = np.array([float(r["normal_z"]) for r in rows])
    # current x within `window` of the reference: the columns are 0.125 apart
    over = x < EDGE - window
    zone = np.abs(x - (EDGE + 0.03)) < window
    beyond = x > EDGE + ZONE + window
    check(len(rows) == 36 and over.sum() == 24 and zone.sum() == 4 and beyond.sum() == 8,
          f"36 slave nodes: 24 over the master, 4 at 0.03 beyond its edge, 8 farther: "
          f"{len(rows)}, {over.sum()}, {zone.sum()}, {beyond.sum()}")
    check(np.all(status[over] != 0) and np.all(pressure[over] > 0),
          f"over the master: pressed, p = {pressure[over].min():.3f} .. {pressure[over].max():.3f}")
    check(np.all(status[zone] != 0) and np.all(pressure[zone] > 0),
          f"0.03 beyond the free edge (inside the zone 0.05): pressed, p = "
          f"{np.round(pressure[zone], 3).tolist()}")
    check(np.all(status[beyond] == 0) and np.all(pressure[beyond] == 0.0),
          f"0.155 and 0.28 beyond the free edge: open, statuses {status[beyond].tolist()}, "
          f"p = {np.round(pressure[beyond], 3).tolist()}")
    total = sum(p * nz * tributary_area(xi, yi) for p, nz, xi, yi in zip(pressure, normal_z, x, y))
    # overhang.dck: equilibrium holds to the deck's TOLRESID 1e-8 (measured 3e-11 and 0)
    check(abs(total / LOAD - 1.0) <= tolerance, f"sum p n_z A = {total:.9f} = {LOAD} ({tolerance:g})")
    series = fr.ResultSeries(base + ".pvd")
    mesh = series.mesh(series.select("last")[0])
    support = mesh.points[:, 2] < 1e-9
    reaction = mesh.point_data["reaction"][support, 2].sum()
    check(abs(reaction / LOAD - 1.0) <= tolerance, f"reaction at z = 0: {reaction:.9f} = {LOAD} ({tolerance:g})")
    return summary()


if __name__ == "__main__":
    sys.exit(main())
