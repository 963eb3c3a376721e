#!/usr/bin/env python3
"""Check a buried-pipe run (inputs/pipe_soil, docs/verification/pipe_soil.md) against the
design formulas' band and statics.

    check_pipe_soil.py OUT BASE PLATEAU_TOLERANCE     (OUT/BASE_history.csv: the run's history)

The deck BASE names its soil, direction and mesh (generate_pipe_soil_decks.DECKS). Checks:
- the run reached its last increment (t = 2), or with a path-controlled pull (decks with
  `free`) the pipe its displacement;
- a plateau: the force per metre of pipe, P = k r_d / t (k = 2 for the half model, d the
  direction of the pull, r_d the reference node's reaction or the applied force F (t - 1)),
  changed by less than PLATEAU_TOLERANCE (relative) over the last quarter of the pull;
- the plateau inside the band of the design formulas: 0.7 x the lowest to 1.3 x the highest
  (generate_pipe_soil_decks.design_band);
- statics in every increment: the pipe's reaction equals the resultant of the contact forces
  on the soil (to 1e-6 of the plateau), and the vertical reactions (bottom, pipe) carry the
  soil's weight (to 1e-6 of it).
Prints the numbers; exit status 0 when every check holds.
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "inputs" / "pipe_soil"))
import generate_pipe_soil_decks as g  # noqa: E402


def main():
    out, base, tolerance = sys.argv[1], sys.argv[2], float(sys.argv[3])
    soil, direction, displacement, _, overrides, mesh = g.DECKS[base]
    half = direction == "uplift"
    free = overrides.get("free", False)
    dof, factor = (3, 2.0) if half else (1, 1.0)
    history = g.pull_history(out, base)
    rows = [h[0] for h in history]
    times = [float(r["time"]) for r in rows]
    moved, pull, force = ([h[k] for h in history] for k in (1, 2, 3))
    plateau = force[-1]
    failures = []
    if not free and abs(times[-1] - 2.0) > 1e-12:
        failures.append("the run stopped at t = %g" % times[-1])
    if free and moved[-1] < displacement:
        failures.append("the pipe stopped at u = %g m" % moved[-1])
    quarter = [p for u, p in zip(moved, force) if u >= moved[-1] - 0.25 * displacement]
    change = (max(quarter) - min(quarter)) / abs(plateau)
    low, high = g.design_band(soil, direction)
    contact = max(abs(q - float(r["c%d_pair1" % dof])) for q, r in zip(pull, rows))
    weight = g.soil_weight(mesh, half)
    lift = pull if free else [float(r["r3_n%d" % g.REF_NODE]) for r in rows]
    vertical = max(abs(float(r["r3_sum_bottom"]) + q - weight) for q, r in zip(lift, rows))
    print("plateau P = %.2f kN/m after %.0f mm; change over the last quarter %.2f %% (tolerance %.1f %%)"
          % (plateau, 1000 * moved[-1], 100 * change, 100 * tolerance))
    peak = max(force, key=abs)
    print("peak %.2f kN/m after %.0f mm" % (peak, 1000 * moved[force.index(peak)]))
    for name, (value, text) in g.design_resistances(soil, direction).items():
        print("  %-22s %7.2f kN/m (%s): P / design = %.3f" % (name, value, text, plateau / value))
    print("band %.2f ... %.2f kN/m; statics: pipe vs contact %.1e, vertical %.1e of the weight"
          % (low, high, contact / abs(plateau) * factor / g.THICKNESS, vertical / weight))
    if change > tolerance:
        failures.append("no plateau: the force changed by %.2f %% over the last quarter" % (100 * change))
    if not low <= plateau <= high:
        failures.append("plateau %.2f kN/m outside the design band %.2f ... %.2f" % (plateau, low, high))
    if contact * factor / g.THICKNESS > 1e-6 * abs(plateau):
        failures.append("pipe reaction and contact resultant differ by %.2e kN" % contact)
    if vertical > 1e-6 * weight:
        failures.append("the vertical reactions miss the soil's weight by %.2e kN" % vertical)
    for failure in failures:
        print("FAIL:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
