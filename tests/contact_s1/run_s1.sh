#!/bin/bash
# run_s1.sh FRIX DECK VARIANT: run an S1 deck in a scratch folder and check it against Hird &
# Russell's solution (check_s1.py, VARIANT rigid | base | base_refined | fixed | refined).
# Exit 0 when every check passes.
set -u
[ $# -eq 3 ] || { echo "usage: run_s1.sh FRIX DECK VARIANT" >&2; exit 2; }
frix=$1; deck=$2; variant=$3
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
name=$(basename "$deck" .dck)
start=$(date +%s.%N)
if ! "$frix" "$deck" --out "$work" --quiet > "$work/run.log" 2>&1; then
    echo "FAIL: frix failed on $deck:"; tail -n 20 "$work/run.log"; echo "0 passed, 1 failed"; exit 1
fi
awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "run time %.2f s\n", e - s }'
awk '/^STEP/ { n++; s += $NF } END { printf "%d increments, %d Newton iterations\n", n, s }' \
    "$work/${name}_listing.txt"
/usr/bin/python3 "$here/check_s1.py" "$work/$name.pvd" "$variant"
