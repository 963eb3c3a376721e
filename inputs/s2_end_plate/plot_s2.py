#!/usr/bin/python3
"""Plots and numbers of docs/verification/s2.md from S2 runs.

usage: plot_s2.py RUNS_DIR OUT_DIR

RUNS_DIR holds one folder per deck, named as the deck (s2_eas9/, s2_eas9_fine/, ...), each with
the run's output (frix DECK --out RUNS_DIR/BASE). Writes into OUT_DIR:
- s2_load_displacement.png: the T-stub's force against the web displacement for the runs
  found (for EAS 9 also against the rise of the flange's face under the web: node set heel,
  the history column after cn_pair1), with the EN 1993-1-8 resistances
  and the seed's ~550 kN at 2 mm;
- s2_bolt_prying.png: the bolt force (per bolt) and the prying force of the T-stub against the
  T-stub's force (coarse and fine EAS 9, and the preloaded deck);
- s2_penalty_study.png: the seed's penalty study (its Table 6.1) on the coarse EAS 9 mesh: the
  force against the web displacement for every penalty pair, the augmented Lagrangian and the
  automatic penalties, with the spread of the force at 2 mm;
and prints per run the force at 0.5, 1 and 2 mm, the plastic resistance (tangent
intersection), the bolt and prying forces at 2 mm and the position of the prying force's
resultant (x of the contact pressure's centroid, the flange's tip at 100 mm, the bolt at 55 mm).
Needs matplotlib (Debian: python3-matplotlib).
"""
import csv
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import tstub_en1993 as en  # noqa: E402

RUNS = [("s2_eas9", "coarse, EAS 9"), ("s2_eas9_fine", "fine, EAS 9"),
        ("s2_eas3", "coarse, EAS 3 (Hexa8-E3)"), ("s2_hex8", "coarse, HEX8"),
        ("s2_eas9_preload", "coarse, EAS 9, preloaded")]
# the penalty study: (deck, label), the penalties as multiples of M / t_f (generate_s2_decks.py)
PENALTY_RUNS = [("s2_eas9", "(1e3, 1e1) the seed's"), ("s2_eas9_n100_t100", "(1e2, 1e2)"),
                ("s2_eas9_n1000_t100", "(1e3, 1e2)"), ("s2_eas9_n10000_t100", "(1e4, 1e2)"),
                ("s2_eas9_n1_t0.01", "(1e0, 1e-2): the seed's / 1e3"),
                ("s2_eas9_n0.1_t0.001", "(1e-1, 1e-3): the seed's / 1e4"),
                ("s2_eas9_augmented", "(1e-1, 1e-3) with METHOD / TMETHOD Augmented"),
                ("s2_eas9_autopenalty", "automatic penalties")]


def penalty_study(runs_dir, out_dir):
    """The force against the web displacement of the penalty decks found in runs_dir, and
    each one's force at 2 mm against the seed's pair's (the spread the seed saw)."""
    fig, (ax, bars) = plt.subplots(1, 2, figsize=(11, 4.5), gridspec_kw={"width_ratios": [1, 1.3]})
    at_2mm, labels = {}, {}
    for base, label in PENALTY_RUNS:
        path = os.path.join(runs_dir, base, base + "_history.csv")
        if not os.path.exists(path):
            continue
        u, force, _, _ = en.tstub_curve(en.read_history(path))
        at_2mm[base], labels[base] = en.value_at(u, force, 2.0), label
        style = "--" if "augmented" in base or "autopenalty" in base else "-"
        ax.plot([0.0] + u, [0.0] + force, style, label=label)
    ax.set_xlabel("web displacement (mm)")
    ax.set_ylabel("T-stub force F (kN)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="lower right")
    if "s2_eas9" in at_2mm:
        names = list(at_2mm)
        reference = at_2mm["s2_eas9"]
        differences = [at_2mm[n] - reference for n in names]
        bars.barh(range(len(names)), differences, color=["C%d" % i for i in range(len(names))])
        bars.set_yticks(range(len(names)))
        bars.set_yticklabels(["%s: %.4f kN" % (labels[n], at_2mm[n]) for n in names], fontsize=7)
        bars.invert_yaxis()
        bars.axvline(0.0, color="k", lw=0.6)
        bars.set_xlabel("F(2 mm) minus the seed's pair's F(2 mm) (kN)")
        bars.grid(alpha=0.3, axis="x")
    fig.suptitle("S2 penalty study (coarse mesh, EAS 9): EPSN, EPST as multiples of M / t_f", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "s2_penalty_study.png"), dpi=110)


def prying_centroid(path):
    """x (mm) of the pressure centroid of the last increment, each node weighted by its
    pressure and its tributary area on the flange's structured face grid."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    end = (rows[-1]["step"], rows[-1]["increment"])
    last = [r for r in rows if (r["step"], r["increment"]) == end]
    xs = sorted({round(float(r["x"]), 9) for r in last})
    ys = sorted({round(float(r["y"]), 9) for r in last})

    def width(values, v):
        i = values.index(v)
        lo = values[max(i - 1, 0)]
        hi = values[min(i + 1, len(values) - 1)]
        return (hi - lo) / 2
    total = moment = 0.0
    for r in last:
        x, y = round(float(r["x"]), 9), round(float(r["y"]), 9)
        force = float(r["pressure"]) * width(xs, x) * width(ys, y)
        total += force
        moment += force * x
    return 1000 * moment / total if total > 0 else float("nan")


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    runs_dir, out_dir = sys.argv[1:]
    modes = en.resistances()
    fig, ax = plt.subplots(figsize=(7, 5))
    fig2, ax2 = plt.subplots(figsize=(7, 5))
    for base, label in RUNS:
        path = os.path.join(runs_dir, base, base + "_history.csv")
        if not os.path.exists(path) or len(open(path).read().splitlines()) < 3:
            continue
        u, force, bolt, prying = en.tstub_curve(en.read_history(path))
        f_p, u_p, k_el, k_pl = en.plastic_resistance(u, force)
        x_q = prying_centroid(os.path.join(runs_dir, base, base + "_contact.csv"))
        print("%-20s F(0.5) %6.1f F(1) %6.1f F(2) %6.1f kN | F_p %6.1f kN at %.3f mm, k_el %5.0f, "
              "k_pl %5.1f kN/mm | 2 mm: bolt %6.1f kN, prying %6.1f kN at x = %.1f mm" % (
                  base, en.value_at(u, force, 0.5), en.value_at(u, force, 1.0),
                  en.value_at(u, force, 2.0), f_p, u_p, k_el, k_pl, en.value_at(u, bolt, 2.0),
                  en.value_at(u, prying, 2.0), x_q))
        line, = ax.plot([0.0] + u, [0.0] + force, label=label)
        if base in ("s2_eas9", "s2_eas9_fine"):
            history = en.read_history(path)
            names = list(history)
            heel = [1000 * v for v in history[names[names.index("cn_pair1") + 1]]]
            ax.plot([0.0] + heel, [0.0] + force, "--", color=line.get_color(), lw=0.9,
                    label=label + ": against the flange's rise under the web (heel)")
            ax.plot([0, u_p, 2.0], [0, f_p, f_p + k_pl * (2.0 - u_p)], ":", color=line.get_color(),
                    lw=0.8)
            ax.plot([u_p], [f_p], "o", color=line.get_color(), ms=4)
        if base in ("s2_eas9", "s2_eas9_fine", "s2_eas9_preload"):
            ax2.plot(force, bolt, "-", color=line.get_color(),
                     label="bolt force per bolt, " + label)
            ax2.plot(force, prying, "--", color=line.get_color(),
                     label="prying force of the T-stub, " + label)
    for name, text in (("mode1_method1", "EN mode 1, Method 1"),
                       ("mode1_method2", "EN mode 1, Method 2"), ("mode2", "EN mode 2")):
        ax.axhline(modes[name], color="grey", lw=0.7, ls="--")
        ax.text(0.05, modes[name] + 5, "%s %.0f kN" % (text, modes[name]), fontsize=8, color="grey")
    ax.plot([2.0], [550.0], "k*", ms=10, label="seed (CARAT), about 550 kN at 2 mm")
    ax.set_xlabel("displacement (mm): of the web's top (solid), of the heel (dashed)")
    ax.set_ylabel("T-stub force F (kN)")
    ax.set_xlim(0, 2.05)
    ax.set_ylim(0, 700)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    ax.set_title("S2: column flange T-stub (HEB 200, M20 10.9) on a rigid end plate", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "s2_load_displacement.png"), dpi=110)
    top = max(ax2.get_xlim()[1], 600)
    ax2.plot([0, top], [0, top / en.N_BOLTS], "k:", lw=0.8, label="F / 4 (no prying)")
    ax2.axhline(en.F_Y_BOLT * en.geo.A_S / 1000, color="grey", ls="--", lw=0.7)
    ax2.text(10, 250, "bolt yields: 1000 MPa x 245 mm^2 = 245 kN", fontsize=8, color="grey")
    ax2.set_xlabel("T-stub force F (kN)")
    ax2.set_ylabel("force (kN)")
    ax2.grid(alpha=0.3)
    ax2.legend(fontsize=7, loc="upper left")
    fig2.tight_layout()
    fig2.savefig(os.path.join(out_dir, "s2_bolt_prying.png"), dpi=110)
    penalty_study(runs_dir, out_dir)
    return 0


if __name__ == "__main__":
    sys.exit(main())
