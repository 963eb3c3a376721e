#!/bin/bash
# run_case.sh FRIX DECK [--reference LISTING] [--check COLUMN FACTOR EXPECTED REL_TOL LABEL]...
#             [--script PYTHON_SCRIPT "ARGUMENTS"]...
#
# Run frix on DECK in a scratch folder, then
#   --reference LISTING : compare the run's listing with a stored one (tests/compare.sh, default
#                         tolerances: 1e-6 relative or 1e-9 x block max). The stored listings
#                         were made by frix itself: they guard against unintended change, they
#                         do not prove correctness.
#   --check ...         : check_value.py on the run's history CSV (last row).
#   --script S "ARGS"   : /usr/bin/python3 S WORK/NAME ARGS (ARGS split at blanks; WORK/NAME is
#                         the run's base path, e.g. WORK/NAME_listing.txt), for checks that
#                         need more than one history column (inputs/verification/necking_bar).
# Exit 0 when every check passes.
set -u
[ $# -ge 2 ] || { echo "usage: run_case.sh FRIX DECK [--reference LISTING] [--check COL FACTOR EXPECTED TOL LABEL]... [--script SCRIPT ARGS]..." >&2; exit 2; }
frix=$1; deck=$2; shift 2
here=$(cd "$(dirname "$0")" && pwd)
compare=$here/../compare.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
name=$(basename "$deck" .dck)
start=$(date +%s.%N)
if ! "$frix" "$deck" --out "$work" --quiet > "$work/run.log" 2>&1; then
    echo "run_case.sh: frix failed on $deck:"; tail -n 20 "$work/run.log"; exit 1
fi
awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "run time %.2f s\n", e - s }'
iterations=$(awk '/^STEP/ { n++; s += $NF } END { printf "%d increments, %d Newton iterations", n, s }' "$work/${name}_listing.txt")
echo "$name: $iterations"
status=0
while [ $# -gt 0 ]; do
    case "$1" in
        --reference)
            bash "$compare" "$2" "$work/${name}_listing.txt" || status=1
            shift 2 ;;
        --check)
            /usr/bin/python3 "$here/check_value.py" "$work/${name}_history.csv" "$2" "$3" "$4" "$5" "$6" || status=1
            shift 6 ;;
        --script)
            # shellcheck disable=SC2086  # ARGS is split at blanks on purpose
            /usr/bin/python3 "$2" "$work/$name" $3 || status=1
            shift 3 ;;
        *) echo "run_case.sh: unknown argument $1" >&2; exit 2 ;;
    esac
done
exit $status
