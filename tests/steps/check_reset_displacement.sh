#!/usr/bin/env bash
# RESET_DISPLACEMENT against the closed forms of reset_displacement_column.dck (see its header):
# the reported displacement of every increment in the history CSV, the HDF5 file (all nodes),
# the VTK files and the POS3D file is the total less the total at the start of the last
# RESET_DISPLACEMENT step; the HDF5 and VTK files also hold the total (and the HDF5 file the
# reference) after a reset, and not before; the reactions (mechanics) are those of the total
# loads; the listing notes each reference.
#   check_reset_displacement.sh FRIX DECK
set -eu
frix=$1; deck=$2
name=$(basename "$deck" .dck)
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
"$frix" "$deck" --out "$out" --quiet
/usr/bin/python3 - "$out" "$name" <<'PY'
import sys, glob, re
import numpy as np, h5py, meshio
out, name = sys.argv[1], sys.argv[2]
# the deck's data: H = 10, E = 1000, rho = 2, g = 9.81, p = 5 on a 1 x 1 top
H, E, rho, g, p = 10.0, 1000.0, 2.0, 9.81, 5.0
def f2(t):            # CURVE 2: 0 up to t = 1, then 1 per unit of t
    return max(t - 1.0, 0.0)
def total(z, t):      # u_z(z, t) = u_g(z) min(t, 1) + u_p(z) f_2(t), 1D closed forms
    return -rho * g * (H * z - z**2 / 2) / E * min(t, 1.0) - p * z / E * f2(t)
def reference_time(step):   # RESET_DISPLACEMENT on steps 2 and 4; step s starts at t = s - 1
    return {1: None, 2: 1.0, 3: 1.0, 4: 3.0}[step]
def reported(z, t, step):
    r = reference_time(step)
    return total(z, t) - (0.0 if r is None else total(z, r))
fail = 0
def check(label, error, tol=1e-12):   # error relative to the largest total, 1.131
    global fail
    ok = error <= tol
    fail |= not ok
    print(f"{'ok  ' if ok else 'FAIL'} {label}: max error {error:.1e} (tol {tol:.0e})")
scale = abs(total(H, 4.0))

# history CSV: node 44 at the top (z = 10), node 24 at z = 5
d = np.atleast_1d(np.genfromtxt(f"{out}/{name}_history.csv", delimiter=',', names=True))
check("history: 9 rows (2 + 3 + 2 + 2 increments)", abs(len(d) - 9))
for column, z in (("u3_n44", 10.0), ("u3_n24", 5.0)):
    err = max(abs(row[column] - reported(z, row["time"], int(row["step"]))) for row in d)
    check(f"history {column} (z = {z}) = reported closed form", err / scale)
print("history at the end of each step, top:",
      [(int(r["step"]), round(float(r[  "u3_n44"]), 12)) for r in d if abs(r["time"] - round(r["time"])) < 1e-12])

# HDF5: every increment, every node
h5 = h5py.File(f"{out}/{name}.h5", "r")
z = h5["mesh/coordinates"][:, 2]
increments = [h5["increments"][k] for k in sorted(h5["increments"])]
hdf5_disp = {}
for gr in increments:
    step, inc, t = int(gr.attrs["step"]), int(gr.attrs["increment"]), float(gr.attrs["time"])
    u = gr["displacement"][...]
    hdf5_disp[(step, inc)] = u
    expected = np.array([reported(zz, t, step) for zz in z])
    err = max(np.abs(u[:, 2] - expected).max(), np.abs(u[:, :2]).max()) / scale
    has_ref = "reference_displacement" in gr
    extra = ""
    if has_ref:
        tot, ref = gr["total_displacement"][...], gr["reference_displacement"][...]
        err = max(err, np.abs(tot[:, 2] - [total(zz, t) for zz in z]).max() / scale,
                  np.abs(ref[:, 2] - [total(zz, reference_time(step)) for zz in z]).max() / scale)
        # the reported displacement is computed once, as total - reference
        if not np.array_equal(u, tot - ref):
            print(f"FAIL {step}.{inc}: displacement != total_displacement - reference_displacement"); fail = 1
    if has_ref != (reference_time(step) is not None) or ("total_displacement" in gr) != has_ref:
        print(f"FAIL {step}.{inc}: total/reference datasets present: {list(gr)}"); fail = 1
    # the mechanics use the total state: the base reactions carry the whole weight and pressure
    reaction = gr["reaction"][:, 2].sum()
    load = rho * g * H * min(t, 1.0) + p * f2(t)
    err = max(err, abs(reaction - load) / load)
    check(f"HDF5 step {step} increment {inc} t = {t:.4f}: displacement{', total, reference' if has_ref else ''}, "
          f"base reaction {reaction:.6f}", err)

# VTK: the displacement written with 17 digits, the total beside it after a reset
for path in sorted(glob.glob(f"{out}/{name}_*_*.vtu")):
    step, inc = map(int, re.search(r"_(\d+)_(\d+)\.vtu$", path).groups())
    m = meshio.read(path)
    u = m.point_data["displacement"]
    err = np.abs(u - hdf5_disp[(step, inc)]).max() / scale
    gr = [x for x in increments if int(x.attrs["step"]) == step and int(x.attrs["increment"]) == inc][0]
    if "total_displacement" in gr:
        if "total_displacement" not in m.point_data:
            print(f"FAIL {path}: no total_displacement"); fail = 1
        else:
            err = max(err, np.abs(m.point_data["total_displacement"] - gr["total_displacement"][...]).max() / scale)
    elif "total_displacement" in m.point_data:
        print(f"FAIL {path}: total_displacement without a reference"); fail = 1
    check(f"VTK step {step} increment {inc}: displacement (and total) = HDF5", err)

# POS3D: one result step per increment, in order
text = open(f"{out}/{name}.pos").read().split("\n")
steps = [i for i, line in enumerate(text) if line.strip() == "%RESULT.CASE.STEP.NODAL.DISPLACEMENT"]
check("POS3D: as many result steps as increments", abs(len(steps) - len(increments)))
for i, gr in zip(steps, increments):
    n = int(text[i + 1].split()[0])
    u = np.array([[float(v) for v in text[i + 2 + k].split()[1:4]] for k in range(n)])
    key = (int(gr.attrs["step"]), int(gr.attrs["increment"]))
    check(f"POS3D step {key[0]} increment {key[1]}: displacement = HDF5", np.abs(u - hdf5_disp[key]).max() / scale,
          1e-9)

# the listing: the NODAL DISPLACEMENTS block of every increment (10 significant digits)
blocks, current, key = {}, None, None
for line in open(f"{out}/{name}_listing.txt"):
    if line.startswith("STEP"):
        key = (int(line.split()[1]), int(line.split()[3]))
    elif line.startswith("NODAL DISPLACEMENTS"):
        current = blocks.setdefault(key, {})
    elif not line.startswith(" "):
        current = None
    elif current is not None and line.split()[0].isdigit():
        current[int(line.split()[0])] = [float(v) for v in line.split()[1:4]]
check("listing: a displacement block per increment", abs(len(blocks) - len(increments)))
ids = h5["mesh/node_ids"][...]
for key, rows in sorted(blocks.items()):
    u = np.array([rows[i] for i in ids])
    check(f"listing step {key[0]} increment {key[1]}: displacement = HDF5", np.abs(u - hdf5_disp[key]).max() / scale,
          1e-9)

# the listing notes each reference
notes = [line.strip() for line in open(f"{out}/{name}_listing.txt") if "RESET_DISPLACEMENT" in line]
print("listing:", notes)
if notes != ["# step 2: displacements reported from t = 1.0000000000E+00 (RESET_DISPLACEMENT)",
             "# step 4: displacements reported from t = 3.0000000000E+00 (RESET_DISPLACEMENT)"]:
    print("FAIL: listing notes"); fail = 1
sys.exit(fail)
PY
