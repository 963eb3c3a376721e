#!/bin/bash
# S4b-TL regression (inputs/s4_block/s4b_block_tl.dck): run frix with progress lines and check
# Newton's rate and the contact forces with s4_tl_analyse.py (docs/verification/s4.md, S4b-TL).
# Usage: s4_tl_run.sh FRIX DECK
# Prints PASS/FAIL lines and "N passed, N failed"; exit 0 only if all pass.
set -u
frix=$1; deck=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
base=$(basename "$deck" .dck)
if ! "$frix" "$deck" --out "$work/out" > "$work/run.log" 2>&1; then
    tail -n 20 "$work/run.log"
    echo "FAIL: frix did not finish $deck"
    echo "0 passed, 1 failed"
    exit 1
fi
/usr/bin/python3 "$here/s4_tl_analyse.py" check "$work/run.log" "$work/out/$base"
