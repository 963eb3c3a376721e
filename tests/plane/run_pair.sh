#!/bin/bash
# run_pair.sh FRIX DECK REFERENCE_DECK TOLERANCE COLUMN...: runs both decks, then checks that each
# COLUMN of the last row of DECK's history CSV equals the same column of REFERENCE_DECK's to the
# relative TOLERANCE (of the largest of the compared values' magnitudes). COLUMN=OTHER compares
# DECK's COLUMN with REFERENCE_DECK's OTHER (a plane model's u_y against a slab's u_z). Used for a plane model
# against the same model built of solids (tests/plane/plane.cmake).
set -u
frix=$1; deck=$2; reference=$3; tolerance=$4; shift 4
out=$(mktemp -d "${TMPDIR:-/tmp}/plane_pair_XXXXXX")
trap 'rm -rf "$out"' EXIT
for d in "$deck" "$reference"; do
   if ! "$frix" "$d" --out "$out" --quiet > "$out/$(basename "$d" .dck).log" 2>&1; then
      echo "run_pair.sh: FAIL: frix $d"; tail -5 "$out/$(basename "$d" .dck).log"; exit 1
   fi
done
/usr/bin/python3 - "$out/$(basename "$deck" .dck)_history.csv" "$out/$(basename "$reference" .dck)_history.csv" \
   "$tolerance" "$@" <<'PY'
import csv, sys
def last(path):
    with open(path) as f:
        return list(csv.DictReader(r for r in f if not r.startswith("#")))[-1]
mine, theirs, tolerance = last(sys.argv[1]), last(sys.argv[2]), float(sys.argv[3])
columns = [(c.split("=") + [c])[:2] for c in sys.argv[4:]]
scale = max(abs(float(theirs[r])) for _, r in columns)
worst = 0.0
for c, r in columns:
    a, b = float(mine[c]), float(theirs[r])
    worst = max(worst, abs(a - b) / scale)
    print(f"{c}: {a:.15e} against {r} {b:.15e}, difference {abs(a - b) / scale:.1e} of the largest")
sys.exit(0 if worst <= tolerance else 1)
PY
