#!/usr/bin/env bash
# Restart with frictional contact: restart_s1.dck run through, then restarted from increment
# 2.3 (2 slipping nodes, stick elsewhere). The slip anchors and accumulated slip come back from
# the HDF5 file's contact group, so the restarted run must end at the uninterrupted one's state
# to 1e-10 relative: displacements, contact tractions and accumulated slip (without the slip
# history the restarted run would start from reference anchors with zero slip and differ).
set -eu
frix=$1; deck=$2
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
"$frix" "$deck" --out "$out/full" --quiet
"$frix" "$deck" --out "$out/restarted" --quiet --restart "$out/full/restart_s1.h5" --from 2.3
/usr/bin/python3 - "$out" <<'PY'
import sys, h5py, numpy as np
out = sys.argv[1]
def last(path):
    with h5py.File(path, 'r') as f:
        g = f['increments'][sorted(f['increments'])[-1]]
        return {k: g[k][...] for k in ('displacement', 'contact/traction', 'contact/slip', 'contact/pressure')}
ref, got = last(f"{out}/full/restart_s1.h5"), last(f"{out}/restarted/restart_s1.h5")
fail = 0
for k in ref:
    scale = np.max(np.abs(ref[k]))
    err = np.max(np.abs(got[k] - ref[k])) / scale
    ok = err <= 1e-10 and scale > 0
    fail |= not ok
    print(f"{'ok  ' if ok else 'FAIL'} {k}: max difference {err:.1e} of max |{k}| = {scale:.3e}")
sys.exit(fail)
PY
