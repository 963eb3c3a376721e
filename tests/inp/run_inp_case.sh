#!/bin/bash
# run_inp_case.sh FRIX CHECKER DECK... [-- EXTRA...]: runs frix on each deck of tests/inp in a
# scratch folder (HDF5 results), then `python3 CHECKER <deck>.h5 ... EXTRA...` (EXTRA: files of
# tests/inp, e.g. a CalculiX .dat). Exit status: the checker's, 1 if a run fails.
set -u
frix=$1
checker=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
results=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
  deck=$1
  shift
  name=$(basename "$deck" .dck)
  if ! "$frix" "$here/$deck" --out "$work" --quiet > "$work/$name.log" 2>&1; then
    echo "FAIL: frix $deck"
    cat "$work/$name.log"
    exit 1
  fi
  results+=("$work/$name.h5")
done
[ $# -gt 0 ] && shift
extra=()
for file in "$@"; do extra+=("$here/$file"); done
cd "$here" && PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 "$here/$checker" "${results[@]}" "${extra[@]}"
