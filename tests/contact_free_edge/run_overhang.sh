#!/bin/bash
# run_overhang.sh FRIX DECK [CHECK_OPTIONS...]: run overhang.dck or soft_overhang.dck (a slave
# block overhanging its master's free edge) in a scratch folder and check it (check_overhang.py,
# which gets CHECK_OPTIONS). Exit 0 when every check passes.
set -u
[ $# -ge 2 ] || { echo "usage: run_overhang.sh FRIX DECK [CHECK_OPTIONS...]" >&2; exit 2; }
frix=$1; deck=$2; shift 2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
name=$(basename "$deck" .dck)
if ! "$frix" "$deck" --out "$work" --quiet > "$work/run.log" 2>&1; then
    echo "FAIL: frix failed on $deck:"; tail -n 20 "$work/run.log"; echo "0 passed, 1 failed"; exit 1
fi
/usr/bin/python3 "$here/check_overhang.py" "$work/$name" "$@"
