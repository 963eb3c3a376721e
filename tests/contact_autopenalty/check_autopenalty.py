#!/usr/bin/python3
"""A benchmark deck run with automatic contact penalties (no EPSN/EPST; docs/contact.md,
"Choosing the penalties"; docs/verification/penalty.md, "Automatic penalty").

usage: check_autopenalty.py FRIX DECK --end-time T [--stored COLUMN VALUE]...
                            [--near COLUMN VALUE RELTOL]...

Runs FRIX on DECK in a scratch folder and checks
  1. frix ran to its end (exit status 0, the last row of <base>_history.csv at time T);
  2. frix printed the automatic penalty of pair 1 (`frix: contact pair 1: EPSN ... (automatic`)
     and the listing's header holds it (`# contact pair 1: EPSN`);
  3. --stored COLUMN VALUE: the history column's last value equals VALUE, the stored result of
     this deck, to 1e-6 relative (a regression anchor: a change beyond the Newton tolerance);
  4. --near COLUMN VALUE RELTOL: the history column's last value lies within RELTOL (relative)
     of VALUE, the result of the hand-tuned deck; the difference is printed in percent.
Prints PASS:/FAIL: lines and "N passed, N failed"; exit 0 if all pass.
"""
import csv
import os
import subprocess
import sys
import tempfile

results = {"passed": 0, "failed": 0}


def report(ok, text):
    results["passed" if ok else "failed"] += 1
    print(("PASS: " if ok else "FAIL: ") + text)


def parse(args):
    if len(args) < 4 or "--end-time" not in args:
        print(__doc__)
        sys.exit(2)
    frix, deck = args[0], args[1]
    end_time, stored, near = None, [], []
    i = 2
    while i < len(args):
        if args[i] == "--end-time":
            end_time = float(args[i + 1])
            i += 2
        elif args[i] == "--stored":
            stored.append((args[i + 1], float(args[i + 2])))
            i += 3
        elif args[i] == "--near":
            near.append((args[i + 1], float(args[i + 2]), float(args[i + 3])))
            i += 4
        else:
            print("check_autopenalty.py: unknown argument " + args[i])
            sys.exit(2)
    return frix, deck, end_time, stored, near


def main():
    frix, deck, end_time, stored, near = parse(sys.argv[1:])
    base = os.path.splitext(os.path.basename(deck))[0]
    with tempfile.TemporaryDirectory() as work:
        run = subprocess.run([frix, deck, "--out", work], capture_output=True, text=True)
        if run.returncode != 0:
            print(run.stdout[-3000:] + run.stderr[-3000:])
            report(False, "frix exit status %d on %s" % (run.returncode, deck))
            print("%d passed, %d failed" % (results["passed"], results["failed"]))
            return 1
        lines = [line for line in run.stdout.splitlines() if line.startswith("frix: contact pair 1: ")]
        report(len(lines) == 1 and "(automatic" in lines[0], "stdout: %s" % (lines[0] if lines else "no pair line"))
        with open(os.path.join(work, base + "_listing.txt")) as handle:
            header = [line for line in handle if line.startswith("# contact pair 1: EPSN")]
        report(len(header) == 1, "listing header: %s" % (header[0].strip() if header else "no pair line"))
        with open(os.path.join(work, base + "_history.csv")) as handle:
            rows = list(csv.DictReader(handle))
    last = rows[-1]
    report(abs(float(last["time"]) - end_time) <= 1e-12 * max(1.0, end_time),
           "last increment at t = %s (end %g)" % (last["time"], end_time))
    for column, value in stored:
        actual = float(last[column])
        report(abs(actual - value) <= 1e-6 * abs(value),
               "%s = %.10g, stored %.10g (1e-6 relative)" % (column, actual, value))
    for column, value, tolerance in near:
        actual = float(last[column])
        difference = (actual - value) / abs(value)
        report(abs(difference) <= tolerance,
               "%s = %.10g against hand-tuned %.10g: %+.2f %% (bound %.2f %%)"
               % (column, actual, value, 100 * difference, 100 * tolerance))
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    return 0 if results["failed"] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
