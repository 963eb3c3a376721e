#!/usr/bin/env python3
"""Plot the force per metre of pipe against the pipe's displacement of buried-pipe runs with
the design formulas and their band (docs/verification/pipe_soil.md).

    plot_pipe_soil.py OUT.png RUN_DIR [RUN_DIR ...]

Each RUN_DIR is a frix output folder of a deck of this folder, named as the deck
(`<deck>_history.csv` in it). One panel per soil and direction found among the runs.
"""
import csv
import pathlib
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import generate_pipe_soil_decks as g  # noqa: E402


def curve(run):
    """Displacement (mm) and force per metre of pipe (kN/m) of step 2, from 0."""
    soil, direction, displacement, _, _, _ = g.DECKS[run.name]
    dof, factor = (3, 2.0) if direction == "uplift" else (1, 1.0)
    with open(run / f"{run.name}_history.csv") as f:
        rows = [r for r in csv.DictReader(f) if float(r["time"]) >= 1.0]
    u = [1000 * displacement * (float(r["time"]) - 1.0) for r in rows]
    p = [factor * float(r["r%d_n%d" % (dof, g.REF_NODE)]) / g.THICKNESS for r in rows]
    return u, p


def main():
    out, runs = sys.argv[1], [pathlib.Path(p) for p in sys.argv[2:]]
    cases = sorted({g.DECKS[r.name][:2] for r in runs})
    figure, axes = plt.subplots(1, len(cases), figsize=(4.2 * len(cases), 4.0), squeeze=False)
    for axis, case in zip(axes[0], cases):
        for run in runs:
            if g.DECKS[run.name][:2] == case:
                u, p = curve(run)
                axis.plot(u, p, label=run.name.replace("pipe_", ""))
        low, high = g.design_band(*case)
        axis.axhspan(low, high, color="grey", alpha=0.12, label="band (0.7 min, 1.3 max)")
        for k, (name, (value, _)) in enumerate(g.design_resistances(*case).items()):
            axis.axhline(value, color="C%d" % (k + 3), lw=0.8, ls="--", label=name)
        axis.set_title("%s, %s" % case)
        axis.set_xlabel("pipe displacement (mm)")
        axis.set_ylabel("force per metre of pipe (kN/m)")
        axis.set_ylim(0, 1.1 * high)
        axis.grid(alpha=0.3)
        axis.legend(fontsize=7, loc="lower right")
    figure.tight_layout()
    figure.savefig(out, dpi=110)
    print("wrote", out)


if __name__ == "__main__":
    main()
