#!/usr/bin/python3
"""Checks of one S5 run (buried pipe, docs/verification/s5.md).

usage: check_s5.py OUTDIR BASE [--reference FILE]
                   [--closed-form full|none --tolerance REL [--pressure P]]
                   [--shear-ratio LOW HIGH [--smoothed]] [--summary]

Reads <OUTDIR>/<BASE>_history.csv (columns u3_n6 crown, u3_n10 invert, u1_n8 springline) and
checks
  1. the run reached t = 1;
  2. with --reference: crown u_z, invert u_z, springline u_x at t = 1 against the stored frix
     regression values of the line BASE in FILE (relative 1e-6 of the largest of them: the
     Newton tolerances TOLRESID = TOLDISP = 1e-8 with margin);
  3. with --closed-form: the vertical and horizontal diameter changes dD_v = u_z(crown) -
     u_z(invert), dD_h = 2 u_x(springline) against the thin ring in an infinite elastic medium
     (postproc/buried_pipe_closed_form.py, full or no slip, K0 = nu/(1 - nu), far-field
     vertical stress P, default 100) within REL;
  4. with --shear-ratio LOW HIGH: the largest |tau| / largest p_r of the contact profile
     (postproc/s5_contact_profile.py, from <BASE>.h5) over the slave nodes off the symmetry
     plane lies in [LOW, HIGH] (the spurious shear of a frictionless interface); and the
     same profile from a copy of the file with the model turned so that the pipe runs along
     z and its crown points along y (x' = -x, y' = z, z' = y; read with --along z --up y and
     the axis at (x, z) = (0, -2), the section at z' = 0) equals it to 1e-12 of its largest
     value (the script's frame for pipes in other directions).
"""
import csv
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "postproc"))


def fail(message):
    print("check_s5.py: FAIL: " + message)
    sys.exit(1)


def turned_copy(source, target):
    """A copy of the HDF5 results file `source` with every position and vector turned by
    x' = -x, y' = z, z' = y (a rotation: the S5 pipe then runs along z, its crown along y)."""
    import shutil
    import h5py
    import numpy as np
    turn = np.array([[-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]])
    shutil.copyfile(source, target)
    with h5py.File(target, "r+") as f:
        vectors = [f["mesh/coordinates"]]
        for group in f["increments"].values():
            vectors += [group["displacement"], group["contact/traction"]]
            if "normal" in group["contact"]:
                vectors.append(group["contact/normal"])
        for dataset in vectors:
            dataset[...] = dataset[...] @ turn.T
    return target


def read_reference(path, base):
    with open(path) as handle:
        for line in handle:
            fields = line.split("#")[0].split()
            if fields and fields[0] == base:
                return [float(v) for v in fields[1:4]]
    fail("%s has no line for %s" % (path, base))


def main():
    args = sys.argv[1:]
    if len(args) < 2 or args[0] in ("-h", "--help"):
        print(__doc__)
        sys.exit(0 if args and args[0] in ("-h", "--help") else 2)
    outdir, base = args[0], args[1]
    with open(os.path.join(outdir, base + "_history.csv")) as handle:
        rows = list(csv.DictReader(handle))
    if not rows:
        fail("no converged increment")
    last = rows[-1]
    t = float(last["time"])
    crown, invert, spring = (float(last[c]) for c in ("u3_n6", "u3_n10", "u1_n8"))
    dv, dh = crown - invert, 2.0 * spring
    print("check_s5.py: %s: t = %.6f crown u_z %.9e invert u_z %.9e springline u_x %.9e "
          "dD_v %.9e dD_h %.9e" % (base, t, crown, invert, spring, dv, dh))
    if abs(t - 1.0) > 1e-12:
        fail("the run stopped at t = %g" % t)
    status = 0
    if "--reference" in args:
        ref = read_reference(args[args.index("--reference") + 1], base)
        scale = max(abs(v) for v in ref)
        for name, value, stored in zip(("crown u_z", "invert u_z", "springline u_x"),
                                       (crown, invert, spring), ref):
            error = abs(value - stored) / scale
            print("  %-15s %.9e stored %.9e  rel. error %.2e (tol 1e-6)" % (name, value, stored, error))
            if error > 1e-6:
                print("check_s5.py: FAIL: %s differs from the stored frix value" % name)
                status = 1
    if "--closed-form" in args:
        from buried_pipe_closed_form import ring_in_medium
        slip = args[args.index("--closed-form") + 1]
        tol = float(args[args.index("--tolerance") + 1])
        nu = 0.33
        pressure = float(args[args.index("--pressure") + 1]) if "--pressure" in args else 100.0
        cdh, cdv, _, _ = ring_in_medium(pressure, nu / (1 - nu), 2.7e3, nu, 2.1e8, 0.3, 0.002, 0.501, slip)
        for name, value, ref in (("dD_v", dv, cdv), ("dD_h", dh, cdh)):
            error = (value - ref) / abs(ref)
            print("  %-5s frix %.6e closed form (%s slip) %.6e  error %+.2f %% (tol %.1f %%)"
                  % (name, value, slip, ref, 100 * error, 100 * tol))
            if abs(error) > tol:
                print("check_s5.py: FAIL: %s off the closed form" % name)
                status = 1
    if "--shear-ratio" in args:
        from s5_contact_profile import profile
        i = args.index("--shear-ratio")
        low, high = float(args[i + 1]), float(args[i + 2])
        table = profile(os.path.join(outdir, base + ".h5"), "pipe_outer", "cavity", 0.0, -2.0,
                        False, None, "--smoothed" in args)
        turned = turned_copy(os.path.join(outdir, base + ".h5"), os.path.join(outdir, base + "_turned.h5"))
        table_turned = profile(turned, "pipe_outer", "cavity", 0.0, -2.0, False, None, "--smoothed" in args,
                               along="z", up="y", section=0.0)
        difference = abs(table_turned - table).max() / abs(table).max()
        print("  profile of the turned model (pipe along z, crown along y): largest difference %.2e"
              % difference)
        if table_turned.shape != table.shape or difference > 1e-12:
            print("check_s5.py: FAIL: the profile depends on the model's orientation")
            status = 1
        inner = table[(table[:, 1] > 1e-6) & (table[:, 1] < 180 - 1e-6)]
        ratio = abs(inner[:, 5]).max() / abs(inner[:, 4]).max()
        print("  spurious shear: max |tau| / max p_r = %.4f off the symmetry plane (band [%g, %g])"
              % (ratio, low, high))
        if not low <= ratio <= high:
            print("check_s5.py: FAIL: shear ratio outside its band")
            status = 1
    sys.exit(status)


if __name__ == "__main__":
    main()
