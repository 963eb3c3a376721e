#!/bin/bash
# S5 buried pipe (docs/verification/s5.md): run one deck and check it with check_s5.py.
# usage: run_s5.sh FRIX DECK [check_s5.py options] [--pos3d]
# --pos3d also reads the POS3D file back with postproc/pos3d_reader.py (--summary) and checks
# that it holds the contact results (CONTACT_PRESSURE, CONTACT_SHEAR).
# --expect-fail TEXT: the run must stop (exit status 1) with TEXT in its output (a reproducer
# of a frix limitation; the test turns red when frix solves the deck).
set -u
frix=$1; deck=$2; shift 2
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
base=$(basename "$deck" .dck)
out=$(mktemp -d "${TMPDIR:-/tmp}/s5_${base}_XXXXXX")
trap 'rm -rf "$out"' EXIT
start=$(date +%s)
"$frix" "$deck" --out "$out" > "$out/run.log" 2>&1
status=$?
echo "run_s5.sh: $base: frix exit status $status, $(( $(date +%s) - start )) s"
grep -E "converged in|cut-back" "$out/run.log" | cut -c1-160
if [ "${1:-}" = "--expect-fail" ]; then
   if [ $status -eq 1 ] && grep -qF -- "$2" "$out/run.log" && \
      ! grep -qE "Fortran runtime error|Backtrace" "$out/run.log"; then
      echo "run_s5.sh: $base stopped as expected (\"$2\")"
      exit 0
   fi
   echo "run_s5.sh: FAIL: $base did not stop with \"$2\" (exit status $status)"
   exit 1
fi
if [ $status -ne 0 ]; then
   echo "run_s5.sh: FAIL: $base did not run to its end"
   tail -5 "$out/run.log"
   exit 1
fi
pos3d=0; args=()
for a in "$@"; do
   if [ "$a" = "--pos3d" ]; then pos3d=1; else args+=("$a"); fi
done
/usr/bin/python3 "$here/check_s5.py" "$out" "$base" "${args[@]}" || exit 1
if [ $pos3d -eq 1 ]; then
   /usr/bin/python3 "$root/postproc/pos3d_reader.py" --summary "$out/$base.pos" > "$out/pos.txt" 2>&1
   rc=$?
   head -40 "$out/pos.txt"
   [ $rc -ne 0 ] && { echo "run_s5.sh: FAIL: pos3d_reader.py exit status $rc"; exit 1; }
   for field in CONTACT_PRESSURE CONTACT_SHEAR; do
      grep -q "$field" "$out/pos.txt" || grep -q "$field" "$out/$base.pos" || \
         { echo "run_s5.sh: FAIL: no $field in $base.pos"; exit 1; }
   done
fi
exit 0
