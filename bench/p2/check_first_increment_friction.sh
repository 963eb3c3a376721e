#!/usr/bin/env bash
# Regression test for a frix defect found by P2 (docs/performance-p2.md; fixed 2026-11-23):
# the tangential (stick) history of slave nodes that touch at t = 0 started only after the
# first converged increment, so the friction of the first increment was lost.
# Deck: first_increment_friction.dck.in (block on the rigid plane, top held in x and y,
# pressure on top, MU 0.9 so every node sticks). In pure stick the problem is linear once the
# contact is closed, so the corner node's traction at t = 1 must not depend on NUMSTEP.
# Reference: the NUMSTEP 8 run itself; tolerance 1e-6 relative (TOLRESID 1e-10 in the deck; a
# linear stick problem has no other source of increment dependence).
# Usage: check_first_increment_friction.sh FRIX [WORKDIR]. Exit 0: consistent; 1: defect.
set -euo pipefail
frix=$1
work=${2:-$(mktemp -d)}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "${work}"
for k in 1 2 4 8; do
   sed "s/@N@/${k}/" "${here}/first_increment_friction.dck.in" > "${work}/fif_${k}.dck"
   "${frix}" "${work}/fif_${k}.dck" --out "${work}/fif_${k}" --quiet > /dev/null
done
/usr/bin/python3 - "${work}" <<'PY'
import csv, sys
work = sys.argv[1]
values = {}
for k in (1, 2, 4, 8):
    rows = [r for r in csv.DictReader(open('%s/fif_%d/fif_%d_contact.csv' % (work, k, k)))
            if r['node'] == '1' and abs(float(r['time']) - 1.0) < 1e-12]
    values[k] = (float(rows[0]['pressure']), float(rows[0]['traction_x']))
    print('NUMSTEP %d: corner node 1 at t = 1: pressure %.6f traction_x %.6f'
          % ((k,) + values[k]))
ref = values[8][1]
bad = [k for k in values if abs(values[k][1] - ref) > 1e-6 * abs(ref)]
if bad:
    print('FAIL: the stick traction at t = 1 depends on the number of increments '
          '(NUMSTEP %s differ from NUMSTEP 8 by more than 1e-6 relative)' % bad)
    sys.exit(1)
print('OK: increment-independent stick traction')
PY
