#!/bin/bash
# S3 elastic punch on a foundation (docs/verification/s3.md): run one deck and check it.
# usage: run_s3.sh FRIX DECK CENTRE_NODE MU [--reference FILE]
#        run_s3.sh FRIX DECK CENTRE_NODE MU --stop-between LOW HIGH [--expect-log TEXT]
#        run_s3.sh FRIX DECK --path-limit LIMIT
# Load control: exit 0 if the run reaches the full load, is in equilibrium and (with
# --reference) matches the stored frix value and the mu = 0.5 displacement within the stored
# tolerance (check_s3.py).
# --stop-between LOW HIGH (a run expected to stop before the full load): exit 0 if frix stops in order (exit status 1, "at the smallest increment
# allowed"), its last converged increment has LOW <= t <= HIGH and is in equilibrium, and (with
# --expect-log) its output contains TEXT.
# --path-limit LIMIT (a CONTROL Path deck past a limit point): exit 0 if the run ends at its
# target displacement and passes the limit point near LIMIT (check_s3_path.py).
set -u
frix=$1; deck=$2; shift 2
here=$(cd "$(dirname "$0")" && pwd)
base=$(basename "$deck" .dck)
out=$(mktemp -d "${TMPDIR:-/tmp}/s3_${base}_XXXXXX")
trap 'rm -rf "$out"' EXIT
start=$(date +%s)
"$frix" "$deck" --out "$out" > "$out/run.log" 2>&1
status=$?
echo "run_s3.sh: $base: frix exit status $status, $(( $(date +%s) - start )) s"
grep -E "converged in|cut-back" "$out/run.log" | cut -c1-160
[ $status -ne 0 ] && grep -E "^frix: step|failed" "$out/run.log" | cut -c1-400
if [ $# -ge 5 ] && [ "$3" = "--stop-between" ]; then
   if [ $status -ne 1 ] || ! grep -q "at the smallest increment allowed" "$out/run.log" || \
      grep -qE "Fortran runtime error|Backtrace" "$out/run.log"; then
      echo "run_s3.sh: FAIL: $base did not stop in order at the smallest increment (exit status $status)"
      exit 1
   fi
   if [ $# -ge 7 ] && [ "$6" = "--expect-log" ] && ! grep -qF -- "$7" "$out/run.log"; then
      echo "run_s3.sh: FAIL: the output of $base lacks \"$7\""
      exit 1
   fi
   /usr/bin/python3 "$here/check_s3.py" "$out" "$base" "$1" "$2" --summary --stop-between "$4" "$5"
   exit $?
fi
if [ $status -ne 0 ]; then
   echo "run_s3.sh: FAIL: $base did not run to its end"
   exit 1
fi
if [ "$1" = "--path-limit" ]; then
   if ! grep -q 'reached its target' "$out/run.log"; then
      echo "run_s3.sh: FAIL: $base did not reach its target displacement"
      exit 1
   fi
   /usr/bin/python3 "$here/check_s3_path.py" "$out/${base}_history.csv" "$2"
   exit $?
fi
centre=$1; mu=$2; shift 2
/usr/bin/python3 "$here/check_s3.py" "$out" "$base" "$centre" "$mu" --summary "$@"
