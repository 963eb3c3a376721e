#!/bin/bash
# S4 / S4b regression: run frix on a deck and check the results with s4_analyse.py.
# Usage: run_check.sh FRIX DECK MODE [--augmented]   (MODE: s4 = statuses and creep, s4b = plateau
# mu N; --augmented: the creep of augmented friction, s4_analyse.py)
# Prints the analysis table, PASS/FAIL lines and "N passed, N failed"; exit 0 only if all pass.
set -u
frix=$1; deck=$2; mode=$3
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
base=$(basename "$deck" .dck)
if ! "$frix" "$deck" --out "$work/out" --quiet > "$work/run.log" 2>&1; then
    cat "$work/run.log"
    echo "FAIL: frix did not finish $deck"
    echo "0 passed, 1 failed"
    exit 1
fi
/usr/bin/python3 "$here/s4_analyse.py" "$mode" "$work/out/$base" --check "${@:4}"
