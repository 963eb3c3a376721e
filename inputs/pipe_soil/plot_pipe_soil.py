#!/usr/bin/env python3
"""Plot the force per metre of pipe against the pipe's displacement of buried-pipe runs with
the design formulas and their band (docs/verification/pipe_soil.md).

    plot_pipe_soil.py OUT.png RUN_DIR [RUN_DIR ...]
    plot_pipe_soil.py --mechanism OUT.png RUN_DIR [RUN_DIR ...]

Each RUN_DIR is a frix output folder of a deck of this folder, named as the deck
(`<deck>_history.csv` in it). One panel per soil and direction found among the runs. With
--mechanism: one panel per run, the equivalent plastic strain (element means) of the last
.vtu of step 2 on the cross-section near the pipe (the plastic zone at the plateau).
"""
import pathlib
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
import numpy as np  # noqa: E402

import generate_pipe_soil_decks as g  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "postproc"))
import frix_results  # noqa: E402


def curve(run):
    """Displacement (mm) and force per metre of pipe (kN/m) of step 2, from 0."""
    history = g.pull_history(run, run.name, first=1.0)
    return [1000 * h[1] for h in history], [h[3] for h in history]


def mechanism(out, runs, eqps_max=0.05):
    """Equivalent plastic strain at the end of each run, soil elements of the face y = 0."""
    columns = min(3, len(runs))
    rows = (len(runs) + columns - 1) // columns
    figure, axes = plt.subplots(rows, columns, figsize=(4.6 * columns, 2.6 * rows), squeeze=False)
    for axis in axes.flat[len(runs):]:
        axis.set_visible(False)
    for axis, run in zip(axes.flat, runs):
        last = sorted(run.glob(f"{run.name}_0002_*.vtu"))[-1]
        mesh = frix_results.read_vtu(str(last))
        cells = mesh.cells[0].data
        block = np.ravel(mesh.cell_data["block"][0])
        eqps = np.ravel(mesh.cell_data["eqps"][0])
        soil = cells[block == 1]
        # nodes 1, 2, 6, 5 of a hexahedron built by the generator lie on y = 0
        faces = mesh.points[soil[:, [0, 1, 5, 4]]][:, :, [0, 2]]
        collection = PolyCollection(faces, array=eqps[block == 1], cmap="viridis", edgecolors="none")
        collection.set_clim(0, eqps_max)
        axis.add_collection(collection)
        axis.add_patch(plt.Circle((0, -g.CENTRE_DEPTH), g.RADIUS, color="0.6"))
        half = g.DECKS[run.name][1] == "uplift"
        axis.set_xlim(-1.5 if half else -1.5, 3.0)
        axis.set_ylim(-2.0, 0)
        axis.set_aspect("equal")
        axis.set_title(run.name.replace("pipe_", ""), fontsize=9)
        axis.set_xlabel("x (m)", fontsize=8)
        axis.set_ylabel("z (m)", fontsize=8)
        axis.tick_params(labelsize=7)
    figure.colorbar(collection, ax=axes.ravel().tolist(), shrink=0.8, label="equivalent plastic strain")
    figure.savefig(out, dpi=110)
    print("wrote", out)


def main():
    if sys.argv[1] == "--mechanism":
        mechanism(sys.argv[2], [pathlib.Path(p) for p in sys.argv[3:]])
        return
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
        entries = len(axis.get_legend_handles_labels()[1])
        axis.legend(fontsize=6 if entries > 6 else 7, loc="lower right", ncol=2 if entries > 6 else 1)
    figure.tight_layout()
    figure.savefig(out, dpi=110)
    print("wrote", out)


if __name__ == "__main__":
    main()
