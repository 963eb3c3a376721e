#!/bin/bash
# S2 end-plate T-stub (docs/verification/s2.md): run one deck and check it with
# check_s2.py (its options follow the deck).
# usage: run_s2.sh FRIX DECK [check_s2.py options]
set -u
frix=$1; deck=$2; shift 2
here=$(cd "$(dirname "$0")" && pwd)
base=$(basename "$deck" .dck)
out=$(mktemp -d "${TMPDIR:-/tmp}/s2_${base}_XXXXXX")
trap 'rm -rf "$out"' EXIT
start=$(date +%s)
"$frix" "$deck" --out "$out" > "$out/run.log" 2>&1
status=$?
echo "run_s2.sh: $base: frix exit status $status, $(( $(date +%s) - start )) s"
grep -E "converged in|cut-back|newton_iterations" "$out/run.log" | cut -c1-160
if [ $status -ne 0 ]; then
   echo "run_s2.sh: FAIL: $base did not run to its end"
   tail -5 "$out/run.log"
   exit 1
fi
/usr/bin/python3 "$here/check_s2.py" "$out" "$base" "$@"
