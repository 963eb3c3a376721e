#!/usr/bin/python3
"""Key quantities of one run of bench/penalty_sweep.sh (docs/verification/penalty.md).

usage: penalty_sweep_extract.py BENCHMARK RUN_BASE LOG
       penalty_sweep_extract.py --header BENCHMARK     (the column names of those fields)

RUN_BASE is the frix output prefix (DIR/deckname), LOG the run's console output (frix's
`stat` lines at its end). Prints one comma-separated line of the fields below; a quantity
that cannot be read (the run stopped early, a missing file) is left empty.

Quantities (the final time of the run; penalty.md defines them per benchmark):
  v5        traction error max(upper_err, lower_err), stress error max(upper_szz, lower_szz)
            (tests/contact_v5v6/v5_patch_check.py RUN_BASE --upper 3)
  s1        free-end interface u_x (node 31) at the last load level
  s3, s3f   punch-top centre u_z (node 1101) at t = 1; s3f also the largest accumulated slip
            of the contact CSV at t = 1
  s4        interface u_x of node 1, top u_z of node 431 at t = 2
  s4b       R_x at the pull u_x = 0.2, the pull at which all 42 interface nodes first slip,
            R_x / (mu N) at the end (tests/contact_s4/s4_analyse.py s4b-csv)
  s5, s5f   dD_v = u_z(crown, node 6) - u_z(invert, node 10), dD_h = 2 u_x(springline, node 8)
            at t = 1 (as tests/contact_s5/check_s5.py); s5f also the largest accumulated slip
and for every run the time reached (t_end, empty without a history), the Newton iterations,
the augmentations and the increments accepted at the augmentation limit (limit_hits).
"""
import csv
import os
import re
import subprocess
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
sys.path.insert(0, os.path.join(ROOT, "postproc"))
import frix_results as fr  # noqa: E402
HEADERS = {
    "v5": ["traction_error", "stress_error"],
    "s1": ["ux_n31"],
    "s3": ["uz_n1101"],
    "s3f": ["uz_n1101", "max_slip"],
    "s4": ["ux_n1", "uz_n431"],
    "s4b": ["Rx_at_0.2", "full_slip_at_ux", "plateau_Rx_muN"],
    "s5": ["dD_v", "dD_h"],
    "s5f": ["dD_v", "dD_h", "max_slip"],
}


def history(base):
    """<base>_history.csv (frix_results.History), None without a readable one."""
    try:
        return fr.read_history(base + "_history.csv")
    except fr.UserError:
        return None


def max_slip(base, time):
    """Largest accumulated slip over the slave nodes of <base>_contact.csv at `time`."""
    try:
        with open(base + "_contact.csv") as stream:
            values = [float(r["slip"]) for r in csv.DictReader(stream)
                      if abs(float(r["time"]) - time) < 1e-9]
    except OSError:
        return None
    return max(values) if values else None


def v5(base):
    out = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "tests/contact_v5v6/v5_patch_check.py"),
                          base, "--upper", "3"], capture_output=True, text=True).stdout
    value = dict(re.findall(r"(\w+)=(\S+)", out))
    if "upper_err" not in value:
        return [None, None]
    return [max(float(value["upper_err"]), float(value["lower_err"])),
            max(float(value["upper_szz"]), float(value["lower_szz"]))]


def s4b(base):
    table = base + "_s4b.csv"
    subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "tests/contact_s4/s4_analyse.py"),
                    "s4b-csv", base, table], capture_output=True, text=True)
    try:
        with open(table) as stream:
            rows = [(float(r["u1_face_x0"]), abs(float(r["r1_sum_face_x0"])), int(r["n_slip"]))
                    for r in csv.DictReader(stream)]
    except OSError:
        return [None, None, None]
    at_02 = [r for u, *r in rows if abs(u - 0.2) < 1e-6]
    full = [u for u, _, n in rows if n == 42]
    return [at_02[0][0] if at_02 else None, full[0] if full else "not reached",
            rows[-1][1] / 360.0 if rows else None]   # mu N = 0.5 x 720 (s4_analyse.py)


def quantities(bench, base):
    table = history(base)
    t = float(table.column("time")[-1]) if table is not None and len(table.data) else None
    if bench == "v5":
        return v5(base), t
    if bench == "s4b":
        return s4b(base), t
    if t is None:
        return [None] * len(HEADERS[bench]), None
    get = lambda column: float(table.column(column)[-1])  # noqa: E731
    if bench == "s1":
        values = [get("u1_n31")]
    elif bench in ("s3", "s3f"):
        values = [get("u3_n1101")]
    elif bench == "s4":
        values = [get("u1_n1"), get("u3_n431")]
    else:
        values = [get("u3_n6") - get("u3_n10"), 2.0 * get("u1_n8")]
    if bench in ("s3f", "s5f"):
        values.append(max_slip(base, t))
    return values, t


def stats(log):
    """frix's `stat newton_iterations` and `stat augmentations` (None where not printed), and
    the number of increments that ended at the augmentation limit (MAXAUG)."""
    found = {}
    limits = 0
    try:
        with open(log, errors="replace") as stream:
            for line in stream:
                limits += line.lstrip().startswith("augmentation limit")
                match = re.match(r"frix: stat (newton_iterations|augmentations)\s+(\S+)", line)
                if match:
                    found[match.group(1)] = match.group(2)
    except OSError:
        pass
    return [found.get("newton_iterations"), found.get("augmentations"), limits]


def text(value):
    if value is None:
        return ""
    return "%.7g" % value if isinstance(value, float) else str(value)


def main(args):
    if len(args) == 2 and args[0] == "--header" and args[1] in HEADERS:
        print(",".join(HEADERS[args[1]] + ["t_end", "newton_iterations", "augmentations", "limit_hits"]))
        return 0
    if len(args) != 3 or args[0] not in HEADERS:
        print(__doc__)
        return 2
    bench, base, log = args
    values, t = quantities(bench, base)
    print(",".join(text(v) for v in values + [t] + stats(log)))
    return 0


if __name__ == "__main__":
    fr.run_main(main, sys.argv[1:])
