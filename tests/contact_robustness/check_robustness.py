#!/usr/bin/python3
"""Checks of one run of a contact robustness deck (tests/contact_robustness, docs/testing.md
"Robustness decks"). Usage:

  check_robustness.py RUN_BASE LOG --time T --increments K --max-iterations N
      [--max-cutbacks C] [--applied FX FY FZ] [--support FIRST LAST]
      [--normal-force N] [--uniform-pressure P] [--friction STEP MU SIGN]
      [--friction-tolerance F] [--tolerance E]

RUN_BASE is the frix output prefix (DIR/name): <base>_listing.txt is read (every converged
increment: its time, Newton iterations, reactions and contact block). LOG is frix's terminal
output (its progress lines), where every cut-back is a line starting with `cut-back:`.

Bounds of the run:
- --time T: the last converged increment is at t = T (the run reached the end of its steps);
- --increments K: exactly K converged increments (the deck's NUMSTEPs: no cut-back), unless
  --max-cutbacks C allows C cut-backs (default 0), then at least K;
- --max-iterations N: no increment took more than N Newton iterations.

Physics, at the last increment (and with --friction at the end of the named step):
- --applied FX FY FZ: the total external load; the sum of all reactions (SUM OF REACTIONS)
  must balance it, |R + F| <= E |F| (E = --tolerance, default 1e-6); with a zero load (a
  slab pressed by a prescribed displacement) |R| <= E x the support's normal force;
- --support FIRST LAST: the nodes FIRST..LAST (user ids) are the supported bottom of the
  master block; their reactions give the normal force N = sum R_z and the friction force
  T = sum R_x transmitted through the interface;
- --normal-force N: sum R_z over the support = N to E (relative);
- --uniform-pressure P: every slave node is in contact and carries p = P to E (relative);
- --friction STEP MU SIGN: at the last increment of step STEP every slave node in contact
  slips (status 2) with |t| = MU p to E (Coulomb's law, the traction being tangential to the
  normal used), and T = SIGN x MU x N to --friction-tolerance (relative, default 1e-3): the
  Coulomb force of the sliding slab, the support's reaction opposing the drag (SIGN = -1 for
  a drag towards +x). T is not MU x N exactly: the master faces turn under load (normals
  up to 5e-5 off z in reversal.dck), so the pressures have an x part and the tractions a z part
  (measured 1.1e-4 in reversal.dck, 1.7e-5 in slide_edges.dck; n_x / mu, 1.5e-3, in
  slide_off_end_mu01.dck, whose faces near the free edge turn by 1.6e-4).
Prints PASS:/FAIL: lines and "N passed, N failed"; exit 0 if all pass.
"""
import argparse
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
import frix_results as fr  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from check_tally import check, summary  # noqa: E402


def support_forces(increment, first, last):
    """(sum R_x, sum R_y, sum R_z) over the reactions of nodes first..last."""
    _, _, keys, values = increment.blocks["REACTIONS (constrained DOFs only)"]
    rows = [i for i, key in enumerate(keys) if first <= key <= last]
    return values[rows].sum(axis=0)


def contact_block(increment):
    """The (first) CONTACT PAIR block of an increment: (labels, keys, values)."""
    for title, (_, labels, keys, values) in increment.blocks.items():
        if title.startswith("CONTACT PAIR"):
            return labels, keys, values
    return None


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("base")
    parser.add_argument("log")
    parser.add_argument("--time", type=float, required=True)
    parser.add_argument("--increments", type=int, required=True)
    parser.add_argument("--max-iterations", type=int, required=True)
    parser.add_argument("--max-cutbacks", type=int, default=0)
    parser.add_argument("--applied", type=float, nargs=3)
    parser.add_argument("--support", type=int, nargs=2)
    parser.add_argument("--normal-force", type=float)
    parser.add_argument("--uniform-pressure", type=float)
    parser.add_argument("--friction", nargs=3, action="append", default=[])
    parser.add_argument("--friction-tolerance", type=float, default=1e-3)
    parser.add_argument("--tolerance", type=float, default=1e-6)
    args = parser.parse_args()
    tol = args.tolerance

    increments = fr.read_listing(args.base + "_listing.txt")
    with open(args.log, encoding="utf-8", errors="replace") as stream:
        cutbacks = sum(1 for line in stream if line.lstrip().startswith("cut-back:"))
    counts = [inc.iterations for inc in increments]
    if not increments:
        check(False, f"reaches t = {args.time:g}: no converged increment")
        return summary()
    last = increments[-1]
    check(abs(last.time - args.time) <= 1e-9 * max(1.0, args.time),
          f"reaches t = {args.time:g}: last converged t = {last.time:.10g}")
    check(cutbacks <= args.max_cutbacks, f"cut-backs <= {args.max_cutbacks}: {cutbacks}")
    if args.max_cutbacks == 0:
        check(len(counts) == args.increments, f"{args.increments} increments: {len(counts)}")
    else:
        check(len(counts) >= args.increments, f"at least {args.increments} increments: {len(counts)}")
    check(counts and max(counts) <= args.max_iterations,
          f"Newton iterations per increment <= {args.max_iterations}: max {max(counts)}, "
          f"total {sum(counts)}, {counts}")

    normal = None
    if args.support:
        rx, ry, rz = support_forces(last, *args.support)
        normal = rz
        print(f"support: R = ({rx:.9g}, {ry:.9g}, {rz:.9g})")
    if args.applied:
        applied = np.array(args.applied)
        total = last.blocks["SUM OF REACTIONS"][3][0]
        scale = np.linalg.norm(applied)
        if scale == 0.0:
            scale = abs(normal) if normal else 1.0
        error = np.linalg.norm(total + applied) / scale
        check(error <= tol, f"sum of reactions {np.round(total, 9).tolist()} balances the load "
              f"{applied.tolist()}: error {error:.2e} ({tol:g})")
    if args.normal_force is not None:
        error = abs(normal / args.normal_force - 1.0)
        check(error <= tol, f"support normal force {normal:.9g} = {args.normal_force:g}: "
              f"error {error:.2e} ({tol:g})")
    if args.uniform_pressure is not None:
        labels, keys, values = contact_block(last)
        pressure = values[:, labels.index("PRESSURE")]
        status = values[:, labels.index("STATUS")]
        error = np.max(np.abs(pressure / args.uniform_pressure - 1.0))
        check(np.all(status != 0) and error <= tol,
              f"every slave node in contact with p = {args.uniform_pressure:g}: p = "
              f"{pressure.min():.9g} .. {pressure.max():.9g}, error {error:.2e} ({tol:g})")
    for step, mu, sign in args.friction:
        step, mu, sign = int(step), float(mu), float(sign)
        end = [inc for inc in increments if inc.step == step]
        if not end or abs(end[-1].time - step) > 1e-9 * step:
            check(False, f"step {step} reaches its end t = {step}")
            continue
        labels, keys, values = contact_block(end[-1])
        pressure = values[:, labels.index("PRESSURE")]
        status = values[:, labels.index("STATUS")]
        shear = np.linalg.norm(values[:, [labels.index(f"TRACTION_{c}") for c in "XYZ"]], axis=1)
        pressed = pressure > 0.0
        error = np.max(np.abs(shear[pressed] / (mu * pressure[pressed]) - 1.0))
        check(np.all(status[pressed] == 2) and error <= tol,
              f"end of step {step}: the {pressed.sum()} nodes in contact slip with |t| = "
              f"{mu:g} p: statuses {sorted(set(status[pressed].astype(int).tolist()))}, "
              f"error {error:.2e} ({tol:g})")
        rx, ry, rz = support_forces(end[-1], *args.support)
        expected = sign * mu * rz
        error = abs(rx / expected - 1.0)
        check(error <= args.friction_tolerance,
              f"end of step {step} (t = {end[-1].time:g}): friction force {rx:.9g} = "
              f"{sign:+g} x {mu:g} x N = {expected:.9g}, error {error:.2e} "
              f"({args.friction_tolerance:g}); R_y = {ry:.3g}")
    return summary()


if __name__ == "__main__":
    sys.exit(main())
