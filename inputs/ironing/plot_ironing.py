#!/usr/bin/env python3
"""Plot the ironing reaction forces (whole die: Fx drag, Fz pressing) against the load time.

usage: plot_ironing.py OUT.png LABEL=FILE [LABEL=FILE ...]   (split at the last "=")
FILE is a frix history CSV (<base>_history.csv) or a CalculiX .dat file (name ending in .dat).
Writes OUT.png and prints, per curve, the forces at t = 1 (end of pressing) and the mean of
the sliding phase t in [1.5, 2]. Uses /usr/bin/python3 with matplotlib."""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ironing_forces import ccx_history, frix_history, interpolate  # noqa: E402


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    fig, (ax_z, ax_x) = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
    for arg in sys.argv[2:]:
        label, path = arg.rsplit("=", 1)
        rows = ccx_history(path) if path.endswith(".dat") else frix_history(path)
        t = [r[0] for r in rows]
        style = "--" if path.endswith(".dat") else "-"
        ax_x.plot(t, [r[1] for r in rows], style, label=label)
        ax_z.plot(t, [r[2] for r in rows], style, label=label)
        sliding = [r for r in rows if r[0] >= 1.5]
        fx1, fz1 = interpolate(rows, 1.0) if rows[-1][0] >= 1.0 else (float("nan"),) * 2
        if sliding:
            mx = sum(r[1] for r in sliding) / len(sliding)
            mz = sum(r[2] for r in sliding) / len(sliding)
        else:
            mx = mz = float("nan")
        print("%-24s t_end %.4f  Fz(1) %.5f  Fx(1) %.5f  sliding mean Fz %.5f Fx %.5f Fx/Fz %.4f"
              % (label, t[-1], fz1, fx1, mz, mx, mx / mz if mz else float("nan")))
    ax_z.set_ylabel("Fz (pressing force on the die)")
    ax_x.set_ylabel("Fx (drag force on the die)")
    ax_x.set_xlabel("load time t (0-1: pressed 1.4; 1-2: dragged 4.0)")
    for ax in (ax_x, ax_z):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Ironing: reaction forces on the die (whole model)")
    fig.tight_layout()
    fig.savefig(sys.argv[1], dpi=110)


if __name__ == "__main__":
    main()
