#!/usr/bin/python3
"""The contact penalties frix used, in the HDF5 results file (docs/hdf5-layout.md, "Contact
state written by frix": contact/pass<p>_penalty and contact/pass<p>_penalty_scale).

usage: check_penalty_h5.py FRIX S4_DECK S4_AUTOPENALTY_DECK

Runs FRIX on copies of the two S4 decks (inputs/s4_block) with `HDF5 Yes` added to their
RESULTS line, the automatic one also with `METHOD Augmented TMETHOD Augmented` on its PAIR line,
and checks in every increment of both files (read with h5py):
  1. hand-tuned deck (EPSN 1e8, EPST 1e4 given): pass1_penalty = [1e8, 1e4, 0, 0] exactly, and
     no pass1_penalty_scale (a penalty pair has no growth);
  2. automatic deck: pass1_penalty = [eps, eps, 1, 1] with eps = 10 M/h of the block's bottom
     faces (docs/contact.md, "Automatic penalties"): M = E (1 - nu) / ((1 + nu)(1 - 2 nu)) with
     E = 1000, nu = 0.3 (the deck's material), h = 0.2 (the deck's element height), to 1e-12
     relative; and eps agrees with the value frix printed (`frix: contact pair 1: EPSN ...`, 5
     digits);
  3. automatic augmented deck: pass1_penalty_scale has 2 values, each a power of 10 between 1
     and PENCAP's default 1e4, non-decreasing over the increments.
Prints PASS:/FAIL: lines and "N passed, N failed"; exit 0 if all pass.
"""
import math
import os
import re
import subprocess
import sys
import tempfile

import h5py

results = {"passed": 0, "failed": 0}


def report(ok, text):
    results["passed" if ok else "failed"] += 1
    print(("PASS: " if ok else "FAIL: ") + text)


def run(frix, deck, work, augmented):
    """Run frix on a copy of deck with HDF5 output; return (h5 path, stdout)."""
    with open(deck) as handle:
        text = handle.read()
    text, n_results = re.subn(r"^(VTK Yes.*)$", r"\1  HDF5 Yes", text, count=1, flags=re.M)
    if augmented:
        text = re.sub(r"^(PAIR 1 .*NORMAL 0 0 1)", r"\1 METHOD Augmented TMETHOD Augmented", text,
                      count=1, flags=re.M)
    if n_results != 1:
        report(False, "%s: no RESULTS line `VTK Yes ...` to add HDF5 Yes to" % deck)
        return None, ""
    base = os.path.splitext(os.path.basename(deck))[0]
    copy = os.path.join(work, base + ".dck")
    with open(copy, "w") as handle:
        handle.write(text)
    out = os.path.join(work, base)
    proc = subprocess.run([frix, copy, "--out", out], capture_output=True, text=True)
    report(proc.returncode == 0, "%s: frix exit status %d" % (base, proc.returncode))
    return os.path.join(out, base + ".h5"), proc.stdout


def increments(path):
    with h5py.File(path, "r") as f:
        for name in sorted(f["increments"]):
            group = f["increments"][name]
            contact = group["contact"]
            scale = contact["pass1_penalty_scale"][()] if "pass1_penalty_scale" in contact else None
            yield name, contact["pass1_penalty"][()], scale


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        sys.exit(2)
    frix, hand_deck, auto_deck = sys.argv[1:4]
    young, nu, height = 1000.0, 0.3, 0.2
    eps = 10.0 * young * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu)) / height
    with tempfile.TemporaryDirectory() as work:
        path, _ = run(frix, hand_deck, work, False)
        if path:
            rows = list(increments(path))
            report(len(rows) == 10, "hand-tuned: %d increments (10 expected)" % len(rows))
            bad = [n for n, penalty, scale in rows if list(penalty) != [1.0e8, 1.0e4, 0.0, 0.0] or scale is not None]
            report(not bad, "hand-tuned: pass1_penalty = [1e8, 1e4, 0, 0], no penalty_scale (bad: %s)" % bad)
        path, stdout = run(frix, auto_deck, work, True)
        if path:
            rows = list(increments(path))
            report(len(rows) == 10, "automatic: %d increments (10 expected)" % len(rows))
            bad = [n for n, penalty, _ in rows
                   if abs(penalty[0] - eps) > 1e-12 * eps or penalty[1] != penalty[0] or list(penalty[2:]) != [1.0, 1.0]]
            report(not bad, "automatic: pass1_penalty = [%.10g, same, 1, 1] in every increment (bad: %s)" % (eps, bad))
            printed = re.search(r"frix: contact pair 1: EPSN (\S+) \(automatic", stdout)
            report(printed is not None and abs(float(printed.group(1)) - rows[0][1][0]) <= 1e-4 * eps,
                   "automatic: the printed EPSN %s equals the file's %.10g" %
                   (printed.group(1) if printed else "(not printed)", rows[0][1][0] if rows else float("nan")))
            scales = [scale for _, _, scale in rows]
            ok = all(s is not None and len(s) == 2 for s in scales)
            if ok:
                ok = all(1.0 <= v <= 1.0e4 and abs(math.log10(v) - round(math.log10(v))) < 1e-12
                         for s in scales for v in s)
                ok = ok and all((b >= a).all() for a, b in zip(scales, scales[1:]))
            report(ok, "augmented: pass1_penalty_scale powers of 10 in [1, 1e4], non-decreasing: %s ... %s" %
                   (scales[0] if scales else None, scales[-1] if scales else None))
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    sys.exit(0 if results["failed"] == 0 else 1)


if __name__ == "__main__":
    main()
