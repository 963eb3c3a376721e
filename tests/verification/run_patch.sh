#!/bin/bash
# run_patch.sh FRIX DECK [--tol T]
# V1 patch test: run frix on DECK (inputs/verification/v1_patch/*.dck) in a scratch folder and
# check the last converged increment's VTK file against the exact homogeneous solution with
# check_patch.py (displacements of all nodes, cell stresses and strains, default 1e-10 relative).
set -u
[ $# -ge 2 ] || { echo "usage: run_patch.sh FRIX DECK [--tol T]" >&2; exit 2; }
frix=$1; deck=$2; shift 2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
name=$(basename "$deck" .dck)
if ! "$frix" "$deck" --out "$work" --quiet > "$work/run.log" 2>&1; then
    echo "run_patch.sh: frix failed on $deck:"; cat "$work/run.log"; exit 1
fi
vtu=$(ls "$work"/"$name"_*.vtu 2> /dev/null | sort | tail -n 1)
[ -n "$vtu" ] || { echo "run_patch.sh: no .vtu written for $deck"; exit 1; }
grep -h "ITERATIONS" "$work/${name}_listing.txt" | sed 's/^/listing: /'
/usr/bin/python3 "$here/check_patch.py" "$deck" "$vtu" "$@"
