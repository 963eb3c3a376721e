#!/usr/bin/env bash
# Restarts across RESET_DISPLACEMENT steps (reset_displacement_column.dck: resets on steps 2
# and 4) must be bit-identical to the uninterrupted run: every dataset of every increment the
# runs share (displacement, total_displacement, reference_displacement, reaction, stress, ...)
# and every history CSV row. Restarted from 1.2 (the end of step 1: the restarted run takes the
# reference itself), 2.1 (inside a reset step: the reference comes from the file), 2.3 (the end
# of the reset step: the next step keeps the file's reference) and 3.2 (the end of step 3: step
# 4 replaces the file's reference).
#   check_reset_restart.sh FRIX DECK
set -eu
frix=$1; deck=$2
froms="1.2 2.1 2.3 3.2"
name=$(basename "$deck" .dck)
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
"$frix" "$deck" --out "$out/full" --quiet
for from in $froms; do
  "$frix" "$deck" --out "$out/from_$from" --quiet --restart "$out/full/$name.h5" --from "$from"
done
/usr/bin/python3 - "$out" "$name" $froms <<'PY'
import sys, h5py, numpy as np
out, name, froms = sys.argv[1], sys.argv[2], sys.argv[3:]
def increments(path):
    with h5py.File(path, "r") as f:
        def datasets(g):   # every dataset of the increment, its subgroups' included
            found = {}
            g.visititems(lambda k, v: found.__setitem__(k, v[...]) if isinstance(v, h5py.Dataset) else None)
            return found
        return {(int(g.attrs["step"]), int(g.attrs["increment"])): datasets(g)
                for g in f["increments"].values()}
def history(path):
    rows = open(path).read().splitlines()
    return rows[0], {tuple(map(int, r.split(",")[:2])): r for r in rows[1:]}
full = increments(f"{out}/full/{name}.h5")
full_header, full_rows = history(f"{out}/full/{name}_history.csv")
fail = 0
for src in froms:
    got = increments(f"{out}/from_{src}/{name}.h5")
    step, inc = map(int, src.split("."))
    expected_keys = sorted(k for k in full if k > (step, inc))
    if sorted(got) != expected_keys:
        print(f"FAIL from {src}: increments {sorted(got)}, expected {expected_keys}"); fail = 1
    differing = [f"{k}/{ds}" for k in got for ds in set(got[k]) | set(full[k])
                 if ds not in got[k] or ds not in full[k] or not np.array_equal(got[k][ds], full[k][ds])]
    header, rows = history(f"{out}/from_{src}/{name}_history.csv")
    differing += [f"history row {k}" for k in rows if rows[k] != full_rows.get(k)]
    if header != full_header or sorted(rows) != expected_keys:
        differing.append("history rows")
    datasets = sorted({n for k in got for n in got[k]})
    print(f"restart from {src}: {len(got)} increments, datasets {datasets}: "
          f"{'bit-identical' if not differing else 'DIFFERENT: ' + ', '.join(differing[:6])}")
    fail |= bool(differing)
sys.exit(fail)
PY
