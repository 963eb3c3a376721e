#!/bin/bash
# run_totals.sh FRIX DECK LABEL=EXPRESSION[@TOL]...: run DECK in a scratch folder and check its
# history columns (CSV, listing TOTALS, HDF5) against the closed forms with check_totals.py.
set -u
[ $# -ge 3 ] || { echo "usage: run_totals.sh FRIX DECK LABEL=EXPRESSION[@TOL]..." >&2; exit 2; }
frix=$1; deck=$2; shift 2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
name=$(basename "$deck" .dck)
if ! "$frix" "$deck" --out "$work" > "$work/run.log" 2>&1; then
    echo "FAIL: frix failed on $deck:"; tail -n 10 "$work/run.log"; exit 1
fi
/usr/bin/python3 "$here/check_totals.py" "$work/$name" "$@"
