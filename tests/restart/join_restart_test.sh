#!/usr/bin/env bash
# postproc/join_restart.py (docs/output.md, "Restarted runs: one series"): restart_s1.dck with
# VTK output run through, then restarted from increment 2.3; the first run's files up to 2.3
# joined with the restart's must be the uninterrupted run's series: the same (step,
# increment, time) rows of the history and contact CSV with their values to 1e-10 relative
# (the restart test's bound, restart_contact_test.sh), the same increments in the .pvd with
# .vtu files that exist, and HDF5 increment groups with the same (step, increment) in order and
# the last group's displacement to 1e-10.
set -eu
frix=$1; deck=$2; postproc=$3
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
sed 's/^VTK No /VTK Yes/' "$deck" > "$out/series.dck"
grep -q '^VTK Yes' "$out/series.dck" || { echo "FAIL: the deck's RESULTS line was not switched to VTK Yes"; exit 1; }
"$frix" "$out/series.dck" --out "$out/full" --quiet
"$frix" "$out/series.dck" --out "$out/restarted" --quiet --restart "$out/full/series.h5" --from 2.3
/usr/bin/python3 "$postproc/join_restart.py" "$out/full/series" "$out/restarted/series" "$out/joined/series"
/usr/bin/python3 - "$out" <<'PY'
import csv, os, sys, h5py, numpy as np
import xml.etree.ElementTree as ElementTree
out = sys.argv[1]
fail = 0
def check(ok, text):
    global fail
    fail |= not ok
    print(("ok   " if ok else "FAIL ") + text)
def rows(path):
    with open(path) as handle:
        table = list(csv.reader(handle))
    return table[0], np.array([[float(v) for v in row] for row in table[1:]])
for name in ("history", "contact"):
    head_full, full = rows(f"{out}/full/series_{name}.csv")
    head_joined, joined = rows(f"{out}/joined/series_{name}.csv")
    same_rows = head_full == head_joined and full.shape == joined.shape and \
        np.array_equal(full[:, :3], joined[:, :3])
    error = np.abs(full - joined).max() / np.abs(full).max() if same_rows else np.inf
    check(same_rows and error <= 1e-10,
          f"{name} CSV: {len(joined)} rows as the uninterrupted run's, values to {error:.1e}")
def data_sets(path):
    root = ElementTree.parse(path).getroot()
    return [(float(d.get("timestep")), os.path.basename(d.get("file")),
             os.path.isfile(os.path.join(os.path.dirname(path), d.get("file"))))
            for d in root.findall("./Collection/DataSet")]
full, joined = data_sets(f"{out}/full/series.pvd"), data_sets(f"{out}/joined/series.pvd")
check([d[:2] for d in full] == [d[:2] for d in joined] and all(d[2] for d in joined),
      f".pvd: {len(joined)} data sets, the uninterrupted run's increments, every .vtu found")
def groups(path):
    with h5py.File(path, "r") as f:
        keys = [(int(g.attrs["step"]), int(g.attrs["increment"])) for _, g in sorted(f["increments"].items())]
        last = f["increments"][sorted(f["increments"])[-1]]["displacement"][...]
    return keys, last
(keys_full, u_full), (keys_joined, u_joined) = groups(f"{out}/full/series.h5"), groups(f"{out}/joined/series.h5")
error = np.abs(u_full - u_joined).max() / np.abs(u_full).max()
check(keys_full == keys_joined and error <= 1e-10,
      f"HDF5: {len(keys_joined)} increment groups in the uninterrupted run's order, last displacement to {error:.1e}")
sys.exit(fail)
PY
