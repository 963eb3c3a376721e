#!/bin/bash
# run_case.sh FRIX DECK [CHECK_OPTIONS...]: run a contact robustness deck in a scratch folder
# (its terminal output kept as the log of Newton iterations and cut-backs) and check it with
# check_robustness.py, which gets CHECK_OPTIONS. A run that stops early is still checked (the
# time it reached, its increments) but fails. Exit 0 when frix succeeds and every check passes.
set -u
[ $# -ge 2 ] || { echo "usage: run_case.sh FRIX DECK [CHECK_OPTIONS...]" >&2; exit 2; }
frix=$1; deck=$2; shift 2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
name=$(basename "$deck" .dck)
"$frix" "$deck" --out "$work" > "$work/run.log" 2>&1
status=$?
if [ $status -ne 0 ]; then
    echo "FAIL: frix failed on $deck (exit status $status):"
    grep -E "^ *cut-back|^frix: step|error" "$work/run.log" | tail -n 10
    [ -s "$work/${name}_listing.txt" ] || { echo "0 passed, 1 failed"; exit 1; }
fi
/usr/bin/python3 "$here/check_robustness.py" "$work/$name" "$work/run.log" "$@"
check=$?
[ $status -eq 0 ] || exit 1
exit $check
