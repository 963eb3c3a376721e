#!/bin/bash
# S3 elastic punch on a foundation (docs/verification/s3.md): run one deck and check it.
# usage: run_s3.sh FRIX DECK CENTRE_NODE MU [--reference FILE]
# Exit 0 if the run reaches the full load, is in equilibrium and (with --reference) matches
# the stored frix value and the mu = 0.5 displacement within the stored tolerance.
set -u
frix=$1; deck=$2; centre=$3; mu=$4; shift 4
here=$(cd "$(dirname "$0")" && pwd)
base=$(basename "$deck" .dck)
out=$(mktemp -d "${TMPDIR:-/tmp}/s3_${base}_XXXXXX")
trap 'rm -rf "$out"' EXIT
start=$(date +%s)
"$frix" "$deck" --out "$out" > "$out/run.log" 2>&1
status=$?
echo "run_s3.sh: $base: frix exit status $status, $(( $(date +%s) - start )) s"
grep -E "converged in|cut-back" "$out/run.log" | cut -c1-160
if [ $status -ne 0 ]; then
   grep -E "^frix: step|failed" "$out/run.log" | cut -c1-400
   echo "run_s3.sh: FAIL: $base did not converge to the full load"
   exit 1
fi
/usr/bin/python3 "$here/check_s3.py" "$out" "$base" "$centre" "$mu" --summary "$@"
