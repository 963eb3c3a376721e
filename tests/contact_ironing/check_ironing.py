#!/usr/bin/env python3
"""Check an ironing run (docs/verification/ironing.md) against reference force histories.

usage: check_ironing.py OUT BASE REFERENCE [--sliding T0 T1 MU] [--end T]
OUT/BASE_history.csv: the run's history (half model; inputs/ironing/ironing_forces.py doubles
it to the whole die). REFERENCE: lines `t Fx Fz tol_x tol_z` (whole die; `#` comments give
their source): at each t the run's Fx and Fz (interpolated between increments) must lie within
tol of the reference. --sliding T0 T1 MU: over t in [T0, T1] (die sliding) every increment has
Fx / Fz >= MU (Coulomb friction on the die's front, which also carries the pile-up ahead of
it, resists the drag with at least mu times the pressing force) and Fx / Fz <= 2 MU. --end T: the
run must reach t = T (default 2, the end of the sliding)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "inputs", "ironing"))
from ironing_forces import frix_history, interpolate  # noqa: E402


def main():
    args = sys.argv[1:]
    if len(args) < 3:
        sys.exit(__doc__)
    out, base, reference = args[:3]
    rows = frix_history(os.path.join(out, base + "_history.csv"))
    failures = []
    end = float(args[args.index("--end") + 1]) if "--end" in args else 2.0
    if rows[-1][0] < end - 1e-9:
        failures.append("the run ended at t = %g, not %g" % (rows[-1][0], end))
    for line in open(reference):
        line = line.split("#")[0].split()
        if not line:
            continue
        t, fx_ref, fz_ref, tol_x, tol_z = (float(w) for w in line)
        fx, fz = interpolate(rows, t)
        ok = abs(fx - fx_ref) <= tol_x and abs(fz - fz_ref) <= tol_z
        print("t %.3f  Fx %9.5f (ref %9.5f, tol %.3f)  Fz %9.5f (ref %9.5f, tol %.3f)  %s"
              % (t, fx, fx_ref, tol_x, fz, fz_ref, tol_z, "ok" if ok else "FAIL"))
        if not ok:
            failures.append("t = %g: Fx %g, Fz %g against %g, %g" % (t, fx, fz, fx_ref, fz_ref))
    if "--sliding" in args:
        k = args.index("--sliding")
        t0, t1, mu = (float(w) for w in args[k + 1:k + 4])
        ratios = [fx / fz for t, fx, fz in rows if t0 <= t <= t1]
        print("sliding t in [%g, %g]: %d increments, Fx/Fz from %.4f to %.4f (bounds %g, %g)"
              % (t0, t1, len(ratios), min(ratios), max(ratios), mu, 2 * mu))
        if not ratios or min(ratios) < mu or max(ratios) > 2 * mu:
            failures.append("Fx/Fz outside [mu, 2 mu] while sliding")
    for f in failures:
        print("check_ironing.py: FAIL:", f)
    print("check_ironing.py: %s" % ("FAIL" if failures else "PASS"))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
