#!/bin/bash
# run_v6.sh FRIX DECK [--check KEY=LO:HI]... [--listing-reference]
# V6 Hertz: run frix on DECK (inputs/v6_hertz, or the plane model tests/plane/hertz_plane*.dck
# with --listing-reference) in a scratch folder, then v6_hertz_check.py on the last increment
# with the deck's data P = 400, R = 1, E = 1e5, nu = 0.3.
set -u
[ $# -ge 2 ] || { echo "usage: run_v6.sh FRIX DECK [--check KEY=LO:HI]... [--listing-reference]" >&2; exit 2; }
frix=$1; deck=$2; shift 2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/run_common.sh"
run_in_scratch run_v6.sh "$frix" "$deck"
grep -E '^  converged|linear solver' "$work/run.log"
args=()
while [ $# -gt 0 ]; do
    case "$1" in
        --check) args+=(--check "$2"); shift 2 ;;
        --listing-reference) args+=(--listing-reference); shift ;;
        *) echo "run_v6.sh: unknown argument $1" >&2; exit 2 ;;
    esac
done
/usr/bin/python3 "$here/v6_hertz_check.py" "$work/$name" --load 400 --radius 1 --young 1e5 --poisson 0.3 "${args[@]}"
