#!/usr/bin/python3
"""Checks of one run of overhang.dck (a slave block overhanging its master's free edge;
docs/contact.md "Edges and corners"). Usage: check_overhang.py RUN_BASE
RUN_BASE is the frix output prefix (DIR/overhang): <base>_contact.csv and <base>.pvd are read
(last increment). Prints PASS:/FAIL: lines and "N passed, N failed"; exit 0 if all pass.

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
import csv
import os
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


def main():
    base = sys.argv[1]
    with open(base + "_contact.csv", newline="", encoding="utf-8") as stream:
        rows = list(csv.DictReader(stream))
    last = max((int(r["step"]), int(r["increment"])) for r in rows)
    rows = [r for r in rows if (int(r["step"]), int(r["increment"])) == last]
    x = np.array([float(r["x"]) for r in rows])
    y = np.array([float(r["y"]) for r in rows])
    pressure = np.array([float(r["pressure"]) for r in rows])
    status = np.array([int(r["status"]) for r in rows])
    normal_z = np.array([float(r["normal_z"]) for r in rows])
    # current x within 1e-3 of the reference (|u| ~ 1e-4): the columns are 0.125 apart
    over = x < EDGE - 0.01
    zone = np.abs(x - (EDGE + 0.03)) < 0.01
    beyond = x > EDGE + ZONE + 0.01
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
    # equilibrium holds to the deck's TOLRESID 1e-8 (measured 3e-11 and 0)
    check(abs(total / LOAD - 1.0) <= 1e-8, f"sum p n_z A = {total:.9f} = {LOAD} (1e-8)")
    series = fr.ResultSeries(base + ".pvd")
    mesh = series.mesh(series.select("last")[0])
    support = mesh.points[:, 2] < 1e-9
    reaction = mesh.point_data["reaction"][support, 2].sum()
    check(abs(reaction / LOAD - 1.0) <= 1e-8, f"reaction at z = 0: {reaction:.9f} = {LOAD} (1e-8)")
    return summary()


if __name__ == "__main__":
    sys.exit(main())
