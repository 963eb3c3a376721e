#!/usr/bin/env python3
"""Check a strip-footing run (inputs/strip_footing, docs/verification/strip_footing.md) against
Prandtl's limit pressure and statics.

    check_footing.py OUT BASE PHI_DEGREES TOLERANCE     (OUT/BASE_history.csv: the run's history)

- the run reached its last increment (t = 1);
- collapse: the footing pressure q = -r3_sum_footing / (b t) changed by less than 0.5 % over
  the last quarter of the settlement (a plateau, not a still rising curve);
- |q / (c N_c) - 1| <= TOLERANCE with Prandtl's N_c (generate_footing_decks.bearing_factor);
- equilibrium: r3_sum_footing + r3_sum_bottom = 0 to 1e-6 of the footing force (the bottom
  is the only support in z, the soil weightless).
Prints the numbers; exit status 0 when every check holds.
"""
import csv
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "inputs" / "strip_footing"))
from generate_footing_decks import B_HALF, THICKNESS, COHESION, bearing_factor  # noqa: E402


def main():
    out, base, phi, tolerance = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
    path = pathlib.Path(out) / f"{base}_history.csv"
    with open(path) as f:
        rows = list(csv.DictReader(f))
    times = [float(r["time"]) for r in rows]
    pressures = [-float(r["r3_sum_footing"]) / (B_HALF * THICKNESS) for r in rows]
    bottom = [float(r["r3_sum_bottom"]) for r in rows]
    expected = COHESION * bearing_factor(phi)
    failures = []
    if abs(times[-1] - 1.0) > 1e-12:
        failures.append("the run stopped at t = %g" % times[-1])
    quarter = [q for t, q in zip(times, pressures) if t >= times[-1] - 0.25]
    rise = (max(quarter) - min(quarter)) / pressures[-1]
    error = pressures[-1] / expected - 1.0
    balance = max(abs(f + b) for f, b in zip((-q * B_HALF * THICKNESS for q in pressures), bottom)) / \
        (pressures[-1] * B_HALF * THICKNESS)
    print("q_u = %.3f kPa, Prandtl c N_c = %.3f kPa (N_c = %.3f): %+.2f %% (tolerance %.1f %%)"
          % (pressures[-1], expected, expected / COHESION, 100 * error, 100 * tolerance))
    print("change over the last quarter of the settlement: %.3f %%; equilibrium: %.1e" % (100 * rise, balance))
    if rise > 0.005:
        failures.append("no plateau: the pressure changed by %.2f %% over the last quarter" % (100 * rise))
    if abs(error) > tolerance:
        failures.append("limit pressure off Prandtl's by %+.2f %%" % (100 * error))
    if balance > 1e-6:
        failures.append("footing and bottom reactions do not balance (%.1e)" % balance)
    for failure in failures:
        print("FAIL:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
