#!/usr/bin/python3
"""Check one S2 run (column flange T-stub on a rigid end plate, docs/verification/s2.md).

usage: check_s2.py OUTDIR BASE [--reference FILE] [--stiffness]

Checks, each printing PASS/FAIL, on <BASE>_history.csv (the quarter of the T-stub with one
bolt; every history value is of the model, forces in kN, displacements in m):
- the run reached the web displacement u = 2 mm (last row);
- statics at every increment: the force on the web equals the bolt force minus the prying
  force, r3_sum_web_top + r3_sum_bolt_end + c3_pair1 = 0 (the only other supports are
  symmetry planes without a z component), to 1e-6 of r3_sum_web_top (Newton tolerance 1e-8);
- the contact force is normal to the end plate: c3_pair1 = cn_pair1 to 1e-9 (friction acts in
  the plane z = 0);
- the plastic resistance of the T-stub (4 x the model's force; the intersection of the
  elastic tangent, first increment, and the plastic tangent, least squares over u >= 1 mm)
  between the EN 1993-1-8 Table 6.2 resistances of the modelled T-stub: above mode 1
  (Method 1, conservative by design) and below mode 2 with the model's bolts (yield force
  1.0e6 kPa x 245 mm^2 each), whichever mechanism the FE takes;
- with --stiffness: the initial stiffness (first increment) within 20 % of the beam estimate
  of inputs/s2_end_plate/tstub_en1993.py (flange clamped at EN's hinge line m = 36.1 mm, bolts
  as springs E A_s / L_b, tip on the plate) in series with the web's stretch E t_w L / 85 mm
  (docs/verification/s2.md, "Elastic stiffness": the estimate itself moves by 12 % between
  the clamp at the hinge line and at the fillet's toe, and the bolt head bonded over the
  washer's area stiffens the flange);
- with --reference: the history columns at the times t listed in FILE for BASE (frix
  regression values) to 1e-6 of the largest value of the row.
"""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "inputs", "s2_end_plate"))
import generate_s2_decks as geo  # noqa: E402
import tstub_en1993 as en  # noqa: E402

STIFFNESS_TOLERANCE = 0.20
failures = []


def check(ok, text):
    print(("PASS: " if ok else "FAIL: ") + text)
    if not ok:
        failures.append(text)


def web_stiffness():
    """E t_w L / h of the web (both halves, the T-stub's length), from the flange's top to the
    prescribed plane, kN/mm."""
    return en.E * geo.T_W * en.L_EFF / (geo.Z_TOP - geo.T_F) / 1000


def check_statics(h):
    worst = max(abs(w + b + c) / abs(w) for w, b, c in
                zip(h["r3_sum_web_top"], h["r3_sum_bolt_end"], h["c3_pair1"]))
    check(worst <= 1e-6, "web force = bolt force - prying force at every increment "
          "(largest error %.2e of the web force, limit 1e-6)" % worst)
    worst = max(abs(c - n) / max(abs(n), 1e-30) for c, n in zip(h["c3_pair1"], h["cn_pair1"]))
    check(worst <= 1e-9, "contact resultant normal to the plate (|c3 - cn| / cn = %.2e, "
          "limit 1e-9)" % worst)


def check_closed_forms(h, stiffness):
    u, force, _, _ = en.tstub_curve(h)
    f_p, u_p, k_el, k_pl = en.plastic_resistance(u, force)
    modes = en.resistances()
    low, high = modes["mode1_method1"], modes["mode2_model_bolts"]
    check(low <= f_p <= high, "plastic resistance %.1f kN (at %.3f mm; tangents %.0f and %.1f "
          "kN/mm) between EN mode 1 Method 1 %.1f kN and mode 2 with the model's bolts %.1f kN"
          % (f_p, u_p, k_el, k_pl, low, high))
    if stiffness:
        estimate = 1 / (1 / en.beam_stiffness() + 1 / web_stiffness())
        error = k_el / estimate - 1
        check(abs(error) <= STIFFNESS_TOLERANCE, "initial stiffness %.1f kN/mm against the beam "
              "estimate with the web in series %.1f kN/mm: %+.1f %% (limit %.0f %%)" % (
                  k_el, estimate, 100 * error, 100 * STIFFNESS_TOLERANCE))


def check_reference(h, base, path):
    names = list(h)
    found = False
    for line in open(path):
        fields = line.split()
        if not fields or line.startswith("#") or fields[0] != base:
            continue
        found = True
        time = float(fields[1])
        rows = [i for i, t in enumerate(h["time"]) if abs(t - time) <= 1e-9]
        check(len(rows) == 1, "t = %g written once" % time)
        if len(rows) != 1:
            continue
        stored = [float(v) for v in fields[2:]]
        now = [h[n][rows[0]] for n in names[3:]]
        scale = max(abs(v) for v in stored)
        worst = max(abs(a - b) for a, b in zip(now, stored)) / scale
        check(len(stored) == len(now) and worst <= 1e-6, "t = %g: history against the "
              "regression values (largest difference %.2e of the row's largest value)"
              % (time, worst))
    check(found, "regression values for %s in %s" % (base, path))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir")
    ap.add_argument("base")
    ap.add_argument("--reference")
    ap.add_argument("--stiffness", action="store_true")
    args = ap.parse_args()
    h = en.read_history(os.path.join(args.outdir, args.base + "_history.csv"))
    reached = h["u3_mean_web_top"][-1]
    check(abs(reached - geo.U_END) <= 1e-12, "reached the web displacement %.6g m (%g m)"
          % (reached, geo.U_END))
    check_statics(h)
    check_closed_forms(h, args.stiffness)
    if args.reference:
        check_reference(h, args.base, args.reference)
    print("check_s2.py: %s: %d failure(s)" % (args.base, len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
