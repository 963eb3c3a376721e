#!/bin/bash
# Run one deck in a scratch folder and check its results with a Python checker:
#   run_deck_check.sh FRIX DECK CHECKER [checker options]
# runs `FRIX DECK --out OUT`, prints the run's exit status, time, cut-backs and Newton
# iterations, fails if the run did not reach its end, then runs
# `python3 CHECKER OUT BASE [checker options]` (BASE: the deck's name without .dck; the result
# files are OUT/BASE_*). Used by the benchmark families (tests/contact_s2, contact_s6, footing).
set -u
frix=$1; deck=$2; checker=$3; shift 3
base=$(basename "$deck" .dck)
out=$(mktemp -d "${TMPDIR:-/tmp}/${base}_XXXXXX")
trap 'rm -rf "$out"' EXIT
start=$(date +%s)
"$frix" "$deck" --out "$out" > "$out/run.log" 2>&1
status=$?
echo "run_deck_check.sh: $base: frix exit status $status, $(( $(date +%s) - start )) s," \
     "$(grep -c 'cut-back' "$out/run.log") cut-backs"
grep -E "converged in|newton_iterations" "$out/run.log" | cut -c1-160
if [ $status -ne 0 ]; then
   echo "run_deck_check.sh: FAIL: $base did not run to its end"
   tail -5 "$out/run.log"
   exit 1
fi
/usr/bin/python3 "$checker" "$out" "$base" "$@"
