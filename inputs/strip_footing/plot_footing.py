#!/usr/bin/env python3
"""Plot the footing pressure against the settlement of strip-footing runs with Prandtl's limit
(docs/verification/strip_footing.md).

    plot_footing.py OUT.png RUN_DIR [RUN_DIR ...]

Each RUN_DIR is a frix output folder of a deck of this folder (its `<deck>_history.csv`); the
friction angle is read from the deck's name (footing_phi<phi>_...).
"""
import csv
import pathlib
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from generate_footing_decks import B_HALF, THICKNESS, COHESION, LOADING, bearing_factor  # noqa: E402


def main():
    out, runs = sys.argv[1], [pathlib.Path(p) for p in sys.argv[2:]]
    figure, axes = plt.subplots(figsize=(7, 4.5))
    drawn = set()
    for run in runs:
        name = run.name
        phi = int(re.match(r"footing_phi(\d+)_", name).group(1))
        settlement = LOADING[phi][0]
        with open(run / f"{name}_history.csv") as f:
            rows = list(csv.DictReader(f))
        u = [0.0] + [1000 * settlement * float(r["time"]) for r in rows]
        q = [0.0] + [-float(r["r3_sum_footing"]) / (B_HALF * THICKNESS) / COHESION for r in rows]
        style = "-" if name.endswith("_fine") else "--"
        axes.plot(u, q, style, label=name.replace("footing_", ""))
        if phi not in drawn:
            drawn.add(phi)
            axes.axhline(bearing_factor(phi), color="grey", lw=0.8)
            axes.text(14, bearing_factor(phi) - 0.4, "Prandtl N_c = %.3f (phi = %d)" % (bearing_factor(phi), phi),
                      va="top", ha="left", fontsize=8, color="grey")
    axes.set_xlabel("settlement of the footing (mm)")
    axes.set_ylabel("footing pressure / cohesion, q / c")
    axes.set_title("Strip footing on weightless c-phi soil: q / c against Prandtl's N_c")
    axes.legend(fontsize=8, loc="center right")
    axes.grid(alpha=0.3)
    figure.tight_layout()
    figure.savefig(out, dpi=120)
    print("wrote", out)


if __name__ == "__main__":
    main()
