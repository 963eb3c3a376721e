#!/usr/bin/env bash
# Restart with frictional contact: DECK (restart_s1.dck, restart_s1_augmented.dck) run through,
# then restarted from increment 2.3 (2 slipping nodes, stick elsewhere). The slip anchors and accumulated slip come back from
# the HDF5 file's contact group, so the restarted run must end at the uninterrupted one's state
# to 1e-10 relative: displacements, contact tractions and accumulated slip (without the slip
# history the restarted run would start from reference anchors with zero slip and differ; with
# METHOD Augmented also the multipliers, contact/pass1_multiplier and, with TMETHOD Augmented,
# contact/pass1_tangential_multiplier, and the grown penalty factors, contact/pass1_penalty_scale:
# 100 on eps_N and eps_T from step 2 on in restart_s1_augmented.dck).
# An optional third argument TOLERANCE replaces 1e-10 (tests/contact_mortar/mortar.cmake).
set -eu
frix=$1; deck=$2; tolerance=${3:-1e-10}
name=$(basename "$deck" .dck)
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
"$frix" "$deck" --out "$out/full" --quiet
"$frix" "$deck" --out "$out/restarted" --quiet --restart "$out/full/$name.h5" --from 2.3
/usr/bin/python3 - "$out" "$name" "$tolerance" <<'PY'
import sys, h5py, numpy as np
out, name, tolerance = sys.argv[1], sys.argv[2], float(sys.argv[3])
def last(path):
    with h5py.File(path, 'r') as f:
        g = f['increments'][sorted(f['increments'])[-1]]
        keys = ['displacement', 'contact/traction', 'contact/slip', 'contact/pressure']
        keys += [k for k in ('contact/pass1_multiplier', 'contact/pass1_tangential_multiplier',
                             'contact/pass1_penalty_scale', 'contact/pass1_multiplier_rate') if k in g]
        return {k: g[k][...] for k in keys}
ref, got = last(f"{out}/full/{name}.h5"), last(f"{out}/restarted/{name}.h5")
fail = 0
for k in ref:
    scale = np.max(np.abs(ref[k]))
    err = np.max(np.abs(got[k] - ref[k])) / scale
    ok = err <= tolerance and scale > 0
    fail |= not ok
    print(f"{'ok  ' if ok else 'FAIL'} {k}: max difference {err:.1e} of max |{k}| = {scale:.3e}")
sys.exit(fail)
PY
