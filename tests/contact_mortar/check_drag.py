#!/usr/bin/python3
"""Mortar contact with Coulomb friction, a block pressed and dragged (tests/contact_mortar/drag.dck,
first_touch.dck).

usage: check_drag.py RUN_BASE --mu MU [--check KEY=LO:HI ...]

Reads <base>_contact.csv. The slave surface is the upper block's bottom, a 3 x 3 grid of faces
on the unit square, so a slave node's tributary area is w(x) w(y) with w = 1/6 on the square's
edges (x or y = 0 or 1) and 1/3 inside (nodes classified by their position, rounded to
thirds). Per increment: F_n = sum p_i A_i, F_t = sum t_x,i A_i, F_y = sum t_y,i A_i (the
written pressure and traction are forces per reference tributary area, docs/contact.md).
Coulomb: |F_t| < mu F_n while nodes stick; F_t = mu F_n once every node slips, and then every
slipping node has |t_i| = mu p_i.

Quantities (printed; --check KEY=LO:HI fails when outside):
  press_ratio      |F_t| / F_n at the end of step 1 (pressing only)
  stick_increments increments of step 2 in which every node sticks
  stick_max_ratio  max |F_t| / (mu F_n) over the increments of step 2 with a sticking node
  slip_increments  increments of step 2 in which every node slips
  slip_ratio_err   max | |F_t| / (mu F_n) - 1 | over those increments
  node_slip_err    max | |t_i| - mu p_i | / p_i over every slipping node of every increment
  lateral          max |F_y| / F_n over all increments
  touch_ratio      |F_t| / (mu F_n) in the first increment with F_n > 0 after one with every
                   node open (F_n = 0; such increments are skipped otherwise); nan if none
"""
import argparse
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/tests/", 1)[0] + "/tests")
from check_tally import check_ranges  # noqa: E402


def area(x, y):
    w = lambda c: 1.0 / 6.0 if round(3 * c) in (0, 3) else 1.0 / 3.0   # noqa: E731
    return w(x) * w(y)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("base")
    parser.add_argument("--mu", type=float, required=True)
    parser.add_argument("--check", action="append", default=[])
    args = parser.parse_args(argv)
    mu = args.mu
    data = np.genfromtxt(args.base + "_contact.csv", delimiter=",", names=True)
    first = data[(data["step"] == 1) & (data["increment"] == data["increment"][0])]
    areas = {int(n): area(x, y) for n, x, y in zip(first["node"], first["x"], first["y"])}
    values = {"stick_increments": 0.0, "stick_max_ratio": 0.0, "slip_increments": 0.0, "slip_ratio_err": 0.0,
              "node_slip_err": 0.0, "lateral": 0.0, "along_drag": -float("inf"), "touch_ratio": float("nan")}
    was_open = False
    for step, increment in sorted(set(zip(data["step"].astype(int), data["increment"].astype(int)))):
        rows = data[(data["step"] == step) & (data["increment"] == increment)]
        a = np.array([areas[int(n)] for n in rows["node"]])
        f_n = np.sum(rows["pressure"] * a)
        f_t = np.sum(rows["traction_x"] * a)
        if f_n == 0.0:
            print(f"step {step} increment {increment:3d}: every node open")
            was_open = True
            continue
        if was_open and np.isnan(values["touch_ratio"]):
            values["touch_ratio"] = abs(f_t) / (mu * f_n)
        values["lateral"] = max(values["lateral"], abs(np.sum(rows["traction_y"] * a)) / f_n)
        slipping = rows["status"] == 2
        sticking = rows["status"] == 1
        magnitude = np.sqrt(rows["traction_x"] ** 2 + rows["traction_y"] ** 2 + rows["traction_z"] ** 2)
        if slipping.any():
            error = np.abs(magnitude[slipping] - mu * rows["pressure"][slipping]) / rows["pressure"][slipping]
            values["node_slip_err"] = max(values["node_slip_err"], np.max(error))
        print(f"step {step} increment {increment:3d}: F_n = {f_n:.10g}, F_t = {f_t:.10g}, "
              f"|F_t|/(mu F_n) = {abs(f_t) / (mu * f_n):.12f}, sticking {int(sticking.sum())}, "
              f"slipping {int(slipping.sum())}")
        if step == 1:
            values["press_ratio"] = abs(f_t) / f_n
            continue
        # the friction traction on the slave opposes its drag towards +x: F_t / (mu F_n) <= 0
        values["along_drag"] = max(values["along_drag"], f_t / (mu * f_n))
        if sticking.any():
            values["stick_max_ratio"] = max(values["stick_max_ratio"], abs(f_t) / (mu * f_n))
        if sticking.all():
            values["stick_increments"] += 1
        if slipping.all():
            values["slip_increments"] += 1
            values["slip_ratio_err"] = max(values["slip_ratio_err"], abs(abs(f_t) / (mu * f_n) - 1.0))
    print("  ".join(f"{k}={v:.5g}" for k, v in values.items()))
    return check_ranges(values, args.check)


if __name__ == "__main__":
    sys.exit(main())
