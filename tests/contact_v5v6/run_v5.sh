#!/bin/bash
# run_v5.sh FRIX DECK UPPER_DIVISIONS [--check KEY=LO:HI]... [--max-iterations N] [--pressure P]
# V5 contact patch test: run frix on DECK (inputs/v5_contact_patch) in a scratch folder, then
# v5_patch_check.py on the last increment (quantities and checks: see that script's header);
# with --max-iterations, also fails when the run took more than N Newton iterations (frix's
# `stat newton_iterations`); --pressure: the deck's top pressure (default the checker's, 100).
set -u
[ $# -ge 3 ] || { echo "usage: run_v5.sh FRIX DECK UPPER_DIVISIONS [--check KEY=LO:HI]... [--max-iterations N] [--pressure P]" >&2; exit 2; }
frix=$1; deck=$2; upper=$3; shift 3
here=$(cd "$(dirname "$0")" && pwd)
args=()
max_iterations=
while [ $# -gt 0 ]; do
    case "$1" in
        --check) [ $# -ge 2 ] || { echo "run_v5.sh: --check needs KEY=LO:HI" >&2; exit 2; }
                 args+=(--check "$2"); shift 2 ;;
        --pressure) [ $# -ge 2 ] || { echo "run_v5.sh: --pressure needs a value" >&2; exit 2; }
                    args+=(--pressure "$2"); shift 2 ;;
        --max-iterations) [[ $# -ge 2 && $2 =~ ^[1-9][0-9]*$ ]] || \
                              { echo "run_v5.sh: --max-iterations needs a positive integer" >&2; exit 2; }
                          max_iterations=$2; shift 2 ;;
        *) echo "run_v5.sh: unknown argument $1" >&2; exit 2 ;;
    esac
done
source "$here/run_common.sh"
run_in_scratch run_v5.sh "$frix" "$deck"
grep -c '^  step' "$work/run.log" | awk '{ print "residual evaluations (ITER 0, 1, ...):", $1 }'
if [ -n "$max_iterations" ]; then
    iterations=$(awk '$2 == "stat" && $3 == "newton_iterations" { print $4 }' "$work/run.log")
    echo "Newton iterations: ${iterations:-none} (at most $max_iterations)"
    [ -n "$iterations" ] && [ "$iterations" -le "$max_iterations" ] || { echo "run_v5.sh: FAIL: Newton iterations"; exit 1; }
fi
/usr/bin/python3 "$here/v5_patch_check.py" "$work/$name" --upper "$upper" "${args[@]}"
