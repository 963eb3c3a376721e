#!/usr/bin/env bash
# restart_test.sh FRIX DECK [FROM...]: run DECK through, then restart it from converged
# increments FROM (default 1.2, inside step 1, and 1.3, the end of step 1) of the stored HDF5
# file. Each restarted run must end at the same final state as the uninterrupted one, bit for
# bit (displacements, EAS parameters, reactions, and the material history when the model has
# one), with the same step/increment numbering and iteration counts. A state stored at increment k is what an
# interrupted run leaves behind, so restarting from it stands for an interrupted run.
set -eu
frix=$1; deck=$2; shift 2
froms=${*:-1.2 1.3}
name=$(basename "$deck" .dck)
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
"$frix" "$deck" --out "$out/full" --quiet
for from in $froms; do
  "$frix" "$deck" --out "$out/from_$from" --quiet --restart "$out/full/$name.h5" --from "$from"
done
# A clash with the file being read is refused, not overwritten.
if "$frix" "$deck" --out "$out/full" --quiet --restart "$out/full/$name.h5" --from 1.2 2> "$out/clash.err"; then
  echo "FAIL: restarting into the restart file's own folder was accepted"; exit 1
fi
grep -q "would be overwritten" "$out/clash.err" || { echo "FAIL: clash message"; cat "$out/clash.err"; exit 1; }
/usr/bin/python3 - "$out" "$name" $froms <<'PY'
import sys, h5py, numpy as np
out, name, froms = sys.argv[1], sys.argv[2], sys.argv[3:]
def last(path):
    with h5py.File(path, 'r') as f:
        names = sorted(f['increments'])
        g = f['increments'][names[-1]]
        return (int(g.attrs['step']), int(g.attrs['increment']), float(g.attrs['time']),
                {k: g[k][...] for k in ('displacement', 'alpha', 'reaction', 'history') if g[k].size > 0})
ref = last(f"{out}/full/{name}.h5")
fail = 0
for src in froms:
    got = last(f"{out}/from_{src}/{name}.h5")
    if got[:3] != ref[:3]:
        print(f"FAIL from {src}: last increment {got[:3]} != {ref[:3]}"); fail = 1
    for k in ref[3]:
        scale = np.max(np.abs(ref[3][k]))
        # an all-zero field (the EAS parameters of a homogeneous sample) compares absolutely
        err = np.max(np.abs(got[3][k] - ref[3][k])) / (scale if scale > 0 else 1.0)
        print(f"restart from {src}: {k} max difference {err:.1e} of max |{k}| = {scale:.3e}")
        if not err == 0.0:
            print(f"FAIL from {src}: {k}"); fail = 1
# The restarted runs must also have iterated exactly like the uninterrupted one in every
# increment they share (a run restarted from a wrong state converges to nearly the same end,
# when the material is elastic, but needs other iteration counts on the way).
import re
def iterations(path):
    pat = re.compile(r"^STEP\s+(\d+)\s+INCREMENT\s+(\d+)\s+TIME\s+\S+\s+ITERATIONS\s+(\d+)")
    return {(int(m[1]), int(m[2])): int(m[3]) for m in map(pat.match, open(path)) if m}
full_its = iterations(f"{out}/full/{name}_listing.txt")
for src in froms:
    its = iterations(f"{out}/from_{src}/{name}_listing.txt")
    shared = {k: full_its[k] for k in its}
    print(f"restart from {src}: increments {sorted(its)}; iterations {list(its.values())}, uninterrupted {list(shared.values())}")
    if its != shared or not its:
        print(f"FAIL from {src}: iteration counts differ"); fail = 1
tip = ref[3]['displacement'][:, 2].min()
print(f"uninterrupted: step {ref[0]} increment {ref[1]} t = {ref[2]}, tip deflection {tip:.6f}")
sys.exit(fail)
PY
