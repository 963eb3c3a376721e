#!/bin/bash
# Strip footing (docs/verification/strip_footing.md): run one deck of inputs/strip_footing and
# check its history with check_footing.py.
# usage: run_footing.sh FRIX DECK PHI_DEGREES TOLERANCE
set -u
frix=$1; deck=$2; phi=$3; tolerance=$4
here=$(cd "$(dirname "$0")" && pwd)
base=$(basename "$deck" .dck)
out=$(mktemp -d "${TMPDIR:-/tmp}/footing_${base}_XXXXXX")
trap 'rm -rf "$out"' EXIT
start=$(date +%s)
"$frix" "$deck" --out "$out" > "$out/run.log" 2>&1
status=$?
echo "run_footing.sh: $base: frix exit status $status, $(( $(date +%s) - start )) s," \
     "$(grep -c 'cut-back' "$out/run.log") cut-backs"
grep -E "newton_iterations" "$out/run.log" | cut -c1-120
if [ $status -ne 0 ]; then
   echo "run_footing.sh: FAIL: $base did not run to its end"
   tail -5 "$out/run.log"
   exit 1
fi
/usr/bin/python3 "$here/check_footing.py" "$out/${base}_history.csv" "$phi" "$tolerance"
