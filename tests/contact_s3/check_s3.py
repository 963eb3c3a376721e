#!/usr/bin/python3
"""Checks of one S3 run (elastic punch on a foundation, docs/verification/s3.md).

usage: check_s3.py OUTDIR BASE CENTRE_NODE MU [--reference FILE] [--summary]
                   [--stop-between LOW HIGH]

Reads <OUTDIR>/<BASE>_history.csv, _contact.csv and the last .vtu of <BASE>.pvd and checks
  1. the run reached t = 1 (the whole load);
  2. global equilibrium in z: sum of the bottom reactions R_z = t x 800 x (x-y projected area
     of the deformed punch top), t the load factor of the last increment (1 at the full load).
     The z component of a follower pressure p on a face is p times the face's projected area (the integral of n da is the vector area), and 2x2 Gauss
     integrates the bilinear face exactly; the symmetry planes carry no z reaction. Tolerance
     1e-6 relative: the residual tolerance (TOLRESID 1e-8 of the force scale) with margin;
  3. with --reference: the punch-top centre displacement u_z at t = 1 against the stored frix
     value for the same deck (1e-6 relative: regression, a change of the solution beyond the
     Newton tolerance), and against the stored mu = 0.5 value (the mu-independence of the
     displacement) within the tolerance stored in the file (reasoning in s3.md).
--summary prints the per-increment centre displacement and the interface force sums.
--stop-between LOW HIGH replaces 1.: the run stopped before the full load and its last
converged increment has LOW <= t <= HIGH; 2. holds there.
"""
import csv
import glob
import os
import sys
import xml.etree.ElementTree as element_tree

import numpy as np
import meshio

PRESSURE = 800.0          # punch-top follower pressure (benchmarks.md S3)
FULL_LOAD_TIME = 1.0


def fail(message):
    print("check_s3.py: FAIL: " + message)
    sys.exit(1)


def read_history(path, centre):
    with open(path) as handle:
        rows = list(csv.DictReader(handle))
    column = "u3_n%d" % centre
    if not rows or column not in rows[0]:
        fail("%s: no column %s" % (path, column))
    return [(float(r["time"]), float(r[column])) for r in rows]


def last_vtu(outdir, base):
    tree = element_tree.parse(os.path.join(outdir, base + ".pvd"))
    files = [d.get("file") for d in tree.iter("DataSet")]
    if not files:
        fail("no increment in %s.pvd" % base)
    return meshio.read(os.path.join(outdir, files[-1]))


def contact_rows(path):
    with open(path) as handle:
        rows = list(csv.DictReader(handle))
    last_time = max(float(r["time"]) for r in rows)
    return [r for r in rows if abs(float(r["time"]) - last_time) < 1e-12], last_time


def quad_projected_area(xy):
    """Area of the x-y projection of a quadrilateral given by 4 corners in order (shoelace)."""
    x, y = xy[:, 0], xy[:, 1]
    return 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def main():
    args = sys.argv[1:]
    if len(args) < 4:
        print(__doc__)
        sys.exit(2)
    outdir, base, centre, mu = args[0], args[1], int(args[2]), float(args[3])
    reference = None
    if "--reference" in args:
        reference = args[args.index("--reference") + 1]
    history = read_history(os.path.join(outdir, base + "_history.csv"), centre)

    # 1. the whole load, or the expected stop
    if "--stop-between" in args:
        at = args.index("--stop-between")
        low, high = float(args[at + 1]), float(args[at + 2])
        if not low <= history[-1][0] <= high:
            fail("the last converged increment is at t = %.6g, expected %g <= t <= %g" %
                 (history[-1][0], low, high))
    elif abs(history[-1][0] - FULL_LOAD_TIME) > 1e-9:
        fail("the run stopped at t = %.6g, not at t = 1" % history[-1][0])
    u_centre = history[-1][1]

    # 2. equilibrium in z
    mesh = last_vtu(outdir, base)
    points = mesh.points
    u = mesh.point_data["displacement"]
    reaction = mesh.point_data["reaction"]
    z_top = points[:, 2].max()
    top = np.where(np.abs(points[:, 2] - z_top) < 1e-9)[0]
    cells = mesh.cells_dict["hexahedron"]
    applied = 0.0
    top_set = set(top.tolist())
    for cell in cells:
        face = cell[4:8]                       # HEX8 face 2 (zeta = +1): nodes 5 6 7 8
        if all(int(n) in top_set for n in face):
            applied += history[-1][0] * PRESSURE * quad_projected_area((points[face] + u[face])[:, :2])
    bottom_reaction = reaction[:, 2].sum()
    if applied <= 0.0 or abs(bottom_reaction - applied) > 1e-6 * applied:
        fail("equilibrium: sum R_z = %.10g, applied t x 800 x projected top area = %.10g" %
             (bottom_reaction, applied))

    # interface forces at the last increment (reported): tributary areas of the regular punch bottom grid
    rows, _ = contact_rows(os.path.join(outdir, base + "_contact.csv"))
    # Tributary areas of the slave nodes: the punch bottom is a regular n x n grid of
    # spacing h = 5/(n - 1) whose node ids run x fastest, then y (MESH BLOCK); a node's
    # weight is h^2 (interior), h^2/2 (edge), h^2/4 (corner), as face_area_weights gives
    # for rectangles. n^2 = the number of slave nodes.
    normal_force = 0.0
    tangential_force = np.zeros(3)
    n_side = int(round(len(rows) ** 0.5))
    if n_side * n_side != len(rows):
        fail("%d slave nodes is not a square grid" % len(rows))
    h = 5.0 / (n_side - 1)
    ids = sorted(int(r["node"]) for r in rows)
    first = ids[0]
    for r in rows:
        k = int(r["node"]) - first
        ix, iy = k % n_side, k // n_side
        weight = (0.5 if ix in (0, n_side - 1) else 1.0) * (0.5 if iy in (0, n_side - 1) else 1.0)
        area = weight * h * h
        normal_force += area * float(r["pressure"])
        tangential_force += area * np.array([float(r["traction_x"]), float(r["traction_y"]),
                                             float(r["traction_z"])])

    if "--summary" in args:
        print("mu %.3g  centre u_z per increment:" % mu)
        for time, value in history:
            print("  t = %.6f  u_z = %.10f" % (time, value))
        print("  applied F_z = %.6f  sum R_z = %.6f  sum A p_N = %.6f  sum A t = %s" %
              (applied, bottom_reaction, normal_force, np.array2string(tangential_force, precision=4)))
        n_stick = sum(1 for r in rows if r["status"] == "1")
        n_slip = sum(1 for r in rows if r["status"] == "2")
        print("  slave nodes: %d stick, %d slip, %d open" % (n_stick, n_slip, len(rows) - n_stick - n_slip))

    # 3. stored references
    if reference:
        table = {}
        mu_tolerance = None
        with open(reference) as handle:
            for line in handle:
                line = line.split("#")[0].strip()
                if not line:
                    continue
                key, value = line.split()[:2]
                if key == "mu_tolerance":
                    mu_tolerance = float(value)
                else:
                    table[float(key)] = float(value)
        if 0.5 not in table or mu_tolerance is None:
            fail("reference file %s lacks mu 0.5 or mu_tolerance" % reference)
        if mu in table:
            own = table[mu]
            if abs(u_centre - own) > 1e-6 * abs(own):
                fail("centre u_z = %.10f, stored frix value %.10f (1e-6 relative)" % (u_centre, own))
        else:
            print("check_s3.py: note: no stored value for mu = %g (store %.16g once reviewed)" % (mu, u_centre))
        if abs(u_centre - table[0.5]) > mu_tolerance * abs(table[0.5]):
            fail("centre u_z = %.10f differs from the mu = 0.5 value %.10f by more than %g relative" %
                 (u_centre, table[0.5], mu_tolerance))
    print("check_s3.py: OK: %s: t = %.6f reached, centre u_z = %.8f, R_z = %.6f = applied %.6f" %
          (base, history[-1][0], u_centre, bottom_reaction, applied))


if __name__ == "__main__":
    main()
