#!/usr/bin/env python3
"""compare_csv_columns.py OLD NEW [--rel R] [--abs A]

Compare two frix CSV files (history or contact table, docs/output.md) column by column:
the same header and rows, text fields equal, and every number within R of itself or within
A of its column's largest magnitude in OLD (the round-off around zero of two solvers). The
columns of one vector share that scale: pressure with traction_x, _y, _z (a frictionless
traction is round-off of the pressure), normal_x, _y, _z, and the lengths x, y, z with gap
and slip (differences of positions: their round-off is that of the positions); and the
tolerance is at least 1e-12 (a column that is round-off around zero throughout, as
compare.sh's --floor). Lines starting with '#' are left out. Prints the largest relative difference found; exit
status 0 equal within tolerance, 1 different.
"""
import argparse
import sys


def rows(path):
    with open(path) as f:
        return [line.rstrip("\n").split(",") for line in f if line.strip() and not line.startswith("#")]


GROUPS = ({"pressure", "traction_x", "traction_y", "traction_z"}, {"normal_x", "normal_y", "normal_z"},
          {"x", "y", "z", "gap", "slip"})
FLOOR = 1e-12


def shared_scales(header, scale):
    """Each column's scale raised to the largest of its group's (GROUPS)."""
    names = [name.strip() for name in header]
    for group in GROUPS:
        members = [k for k, name in enumerate(names) if name in group and k < len(scale)]
        largest = max((scale[k] for k in members), default=0.0)
        for k in members:
            scale[k] = largest
    return scale


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("--rel", type=float, default=1e-8)
    parser.add_argument("--abs", type=float, default=1e-9)
    args = parser.parse_args()
    old, new = rows(args.old), rows(args.new)
    if len(old) != len(new):
        print(f"{args.new}: {len(new)} rows, {args.old}: {len(old)}")
        return 1
    width = max((len(r) for r in old), default=0)
    scale = [0.0] * width
    for r in old:
        for k, field in enumerate(r):
            value = number(field)
            if value is not None:
                scale[k] = max(scale[k], abs(value))
    scale = shared_scales(old[0], scale)
    tolerance = [max(args.abs * value, FLOOR) for value in scale]
    worst = 0.0
    for i, (a, b) in enumerate(zip(old, new), start=1):
        if len(a) != len(b):
            print(f"row {i}: {len(b)} fields, expected {len(a)}")
            return 1
        for k, (x, y) in enumerate(zip(a, b)):
            u, v = number(x), number(y)
            if u is None or v is None:
                if x.strip() != y.strip():
                    print(f"row {i} column {k + 1}: '{y.strip()}', expected '{x.strip()}'")
                    return 1
                continue
            difference = abs(u - v)
            if abs(u) > tolerance[k]:
                worst = max(worst, difference / abs(u))
            if difference > args.rel * abs(u) and difference > tolerance[k]:
                print(f"row {i} column {k + 1} ({old[0][k].strip() if k < len(old[0]) else '?'}): "
                      f"{v!r}, expected {u!r}")
                return 1
    print(f"{args.new}: {len(old)} rows equal, largest relative difference {worst:.2e} "
          f"(of the values above {args.abs} of their column's largest)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
