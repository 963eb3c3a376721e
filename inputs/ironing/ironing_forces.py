#!/usr/bin/env python3
"""Reaction-force histories of the ironing decks (docs/verification/ironing.md).

Reads frix history CSVs (columns time, r1_sum_die_top, r3_sum_die_top) and CalculiX .dat files
(*NODE PRINT, NSET=DIE_TOP, TOTALS=ONLY), both of the half model, and returns the forces on
the whole die: Fz = -2 r3 (the pressing force, > 0) and Fx = 2 r1 (the drag force, > 0 when
the die is pulled along +x against friction), against the load time t (0..1 pressing, 1..2
sliding). Used by plot_ironing.py and tests/contact_ironing/check_ironing.py.
Python standard library only."""
import csv


def frix_history(path):
    """[(t, Fx, Fz)] of a frix history CSV."""
    rows = []
    with open(path) as f:
        for row in csv.DictReader(f):
            rows.append((float(row["time"]), 2.0 * float(row["r1_sum_die_top"]),
                         -2.0 * float(row["r3_sum_die_top"])))
    return rows


def ccx_history(path):
    """[(t, Fx, Fz)] of a CalculiX .dat file; t is CalculiX's total time (steps of length 1)."""
    rows, t = [], None
    with open(path) as f:
        for line in f:
            words = line.split()
            if line.strip().startswith("total force") and "time" in words:
                t = float(words[-1])
            elif t is not None and len(words) == 3:
                fx, _, fz = (float(w) for w in words)
                rows.append((t, 2.0 * fx, -2.0 * fz))
                t = None
    return rows


def interpolate(rows, t):
    """(Fx, Fz) at time t, linear between the rows (t within their range)."""
    for (t0, x0, z0), (t1, x1, z1) in zip(rows, rows[1:]):
        if t0 <= t <= t1:
            w = 0.0 if t1 == t0 else (t - t0) / (t1 - t0)
            return x0 + w * (x1 - x0), z0 + w * (z1 - z0)
    raise ValueError("t = %g outside %g..%g" % (t, rows[0][0], rows[-1][0]))
