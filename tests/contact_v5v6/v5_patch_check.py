#!/usr/bin/python3
"""V5 contact patch test: error of the transmitted contact pressure (docs/verification/v5_v6.md).

usage: v5_patch_check.py RUN_BASE --upper N [--pressure P] [--check KEY=LO:HI ...] [--csv FILE]

RUN_BASE is a frix output prefix (DIR/name): <base>_contact.csv, <base>.pvd and
<base>_listing.txt are read (last increment). The model is the one of
inputs/v5_contact_patch/*.dck: lower block 4 x 4 x 2 on [0,1]^2 x [0,0.5] (node ids 1..75,
x fastest), upper block N x N x 2 on [0,1]^2 x [0.5,1] (ids from 76), uniform pressure P on top.
Exact solution (same material in both blocks): sigma_zz = -P everywhere, contact pressure P.

Quantities (all divided by P):
  pass<k>_min, pass<k>_max  slave-node pressures p_i of pass k as printed by frix (per unit area)
  pass_sum                  sum over passes and slave nodes of p_i A_i / (P * 1): the transmitted
                            load over the applied one (equilibrium: 1); with two passes the
                            mean of the two passes' sums (each pass's pressure is the
                            interface's, docs/contact.md)
  upper_err, lower_err      max |t_a - P| / P over the interface nodes a of each body, with the
                            TRANSMITTED nodal traction t_a = f_a / A_a (two passes: the pressure
                            frix writes, which is that traction): f_a the total contact
                            force on node a (its own slave force p_a A_a, plus N_a(xi_j) p_j A_j
                            of every slave node j of the other pass that lands on a face of a),
                            A_a its tributary area (bilinear face weights of the reference grid)
  upper_szz, lower_szz      max |sigma_zz + P| / P over the elements of each body (cell means)
  upper_soff, lower_soff    max |sigma_ij| / P of the other stress components
  tangential                max |traction_x, traction_y| / P over all slave nodes
  slipping                  number of slave nodes with status 2 (only meaningful with friction)
A --check KEY=LO:HI fails (exit 1) when the value is outside [LO, HI].
"""
import argparse
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/tests/", 1)[0] + "/tests")
from check_tally import check_ranges  # noqa: E402

sys.path.insert(0, __file__.rsplit("/tests/", 1)[0] + "/postproc")
import frix_results as fr  # noqa: E402

LOWER_N = 4
Z_INTERFACE = 0.5


def grid(n, first_id, layer):
    """Node ids (n+1, n+1) [i_x, i_y] of layer `layer` of an n x n x 2 BLOCK, and areas."""
    ids = np.empty((n + 1, n + 1), dtype=int)
    for j in range(n + 1):
        for i in range(n + 1):
            ids[i, j] = first_id + i + (n + 1) * j + (n + 1) ** 2 * layer
    w = np.full(n + 1, 1.0 / n)
    w[0] = w[-1] = 0.5 / n
    return ids, np.outer(w, w)   # tributary area of each node on the unit square


def bilinear_inverse(xf, point):
    """Face coordinates (xi, eta) of `point` (x, y) in the quadrilateral xf (4, 2)."""
    s = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]], dtype=float)
    xi = np.zeros(2)
    for _ in range(30):
        n = 0.25 * (1 + s[:, 0] * xi[0]) * (1 + s[:, 1] * xi[1])
        dn = np.stack([0.25 * s[:, 0] * (1 + s[:, 1] * xi[1]), 0.25 * s[:, 1] * (1 + s[:, 0] * xi[0])], axis=1)
        r = n @ xf - point
        jac = xf.T @ dn
        step = np.linalg.solve(jac, r)
        xi -= step
        if np.max(np.abs(step)) < 1e-14:
            break
    n = 0.25 * (1 + s[:, 0] * xi[0]) * (1 + s[:, 1] * xi[1])
    return xi, n


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("base")
    parser.add_argument("--upper", type=int, required=True, help="divisions of the upper block")
    parser.add_argument("--pressure", type=float, default=100.0)
    parser.add_argument("--check", action="append", default=[])
    parser.add_argument("--label", default=None)
    args = parser.parse_args(argv)
    p_applied = args.pressure

    data = np.genfromtxt(args.base + "_contact.csv", delimiter=",", names=True)
    data = data[(data["step"] == data["step"][-1]) & (data["increment"] == data["increment"][-1])]
    series = fr.ResultSeries(args.base + ".pvd")
    entry = series.select("last")[0]
    mesh = series.mesh(entry)
    ids = fr.node_ids(series, mesh)
    index_of = {int(n): k for k, n in enumerate(ids)}
    current = mesh.points + mesh.point_data["displacement"]

    lower_first = 1
    upper_first = (LOWER_N + 1) ** 2 * 3 + 1
    bodies = {
        "lower": (LOWER_N,) + grid(LOWER_N, lower_first, 2),
        "upper": (args.upper,) + grid(args.upper, upper_first, 0),
    }
    body_of = {}
    for name, (n, gids, _) in bodies.items():
        for node in gids.ravel():
            body_of[int(node)] = name
    force = {name: np.zeros(gids.shape) for name, (n, gids, _) in bodies.items()}
    where = {name: {int(gids[i, j]): (i, j) for i in range(n + 1) for j in range(n + 1)}
             for name, (n, gids, _) in bodies.items()}

    values = {}
    passes = sorted(set(int(k) for k in data["pass"]))
    total = 0.0
    two_pass = len(passes) == 2
    for k in passes:
        rows = data[data["pass"] == k]
        values[f"pass{k}_min"] = rows["pressure"].min() / p_applied
        values[f"pass{k}_max"] = rows["pressure"].max() / p_applied
        if two_pass:
            # frix writes the interface pressure of each slave node (both passes' forces on
            # it): it is the transmitted traction t_a itself, and each pass's integrates to
            # the load
            for row in rows:
                slave = body_of[int(row["node"])]
                n_s, _, area_s = bodies[slave]
                i, j = where[slave][int(row["node"])]
                force[slave][i, j] = row["pressure"] * area_s[i, j]
                total += 0.5 * row["pressure"] * area_s[i, j]
            continue
        for row in rows:
            node = int(row["node"])
            slave = body_of[node]
            master = "upper" if slave == "lower" else "lower"
            n_s, _, area_s = bodies[slave]
            i, j = where[slave][node]
            f = row["pressure"] * area_s[i, j]
            total += f
            force[slave][i, j] += f
            # the reaction on the master face that contains the slave node (current x, y)
            n_m, gids_m, _ = bodies[master]
            point = np.array([row["x"], row["y"]])
            # the master face containing the point; beyond the master's edge (the two bodies
            # expand differently at the free edges) the nearest face, clamped as frix does
            best, best_excess = None, np.inf
            for fi in range(n_m):
                for fj in range(n_m):
                    corner = [gids_m[fi, fj], gids_m[fi + 1, fj], gids_m[fi + 1, fj + 1], gids_m[fi, fj + 1]]
                    xf = np.array([current[index_of[int(c)], :2] for c in corner])
                    xi, shape = bilinear_inverse(xf, point)
                    excess = np.max(np.abs(xi)) - 1
                    if excess < best_excess:
                        xi = np.clip(xi, -1, 1)
                        shape = 0.25 * (1 + np.array([-1, 1, 1, -1]) * xi[0]) * (1 + np.array([-1, -1, 1, 1]) * xi[1])
                        best, best_excess = (fi, fj, shape), excess
            if best_excess > 1e-2:
                raise fr.UserError(f"slave node {node}: no master face under ({point[0]}, {point[1]})")
            fi, fj, shape = best
            for (di, dj), weight in zip([(0, 0), (1, 0), (1, 1), (0, 1)], shape):
                force[master][fi + di, fj + dj] += weight * f
    values["pass_sum"] = total / p_applied
    for name, (n, gids, area) in bodies.items():
        traction = force[name] / area
        values[f"{name}_err"] = np.max(np.abs(traction - p_applied)) / p_applied

    stress = fr.cell_array(mesh, "stress")       # XX YY ZZ XY YZ XZ
    block = fr.cell_array(mesh, "block")
    hexes = fr.hexahedra(mesh)
    centre_z = mesh.points[hexes].mean(axis=1)[:, 2]
    for name, in_body in (("lower", centre_z < Z_INTERFACE), ("upper", centre_z > Z_INTERFACE)):
        s = stress[in_body]
        values[f"{name}_szz"] = np.max(np.abs(s[:, 2] + p_applied)) / p_applied
        values[f"{name}_soff"] = np.max(np.abs(s[:, [0, 1, 3, 4, 5]])) / p_applied
    del block
    values["tangential"] = np.max(np.hypot(data["traction_x"], data["traction_y"])) / p_applied
    values["slipping"] = float(np.sum(data["status"] == 2))

    label = args.label or args.base.rsplit("/", 1)[-1]
    print(f"{label}: " + "  ".join(f"{k}={v:.10g}" if k == "pass_sum" else f"{k}={v:.4g}" for k, v in values.items()))
    return check_ranges(values, args.check)


if __name__ == "__main__":
    sys.exit(fr.run_main(main))
