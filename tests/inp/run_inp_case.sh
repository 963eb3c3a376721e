#!/bin/bash
# run_inp_case.sh FRIX CHECKER DECK... [-- EXTRA...]: runs frix on each deck in a scratch folder
# (HDF5 results), then `python3 CHECKER <deck>.h5 ... EXTRA...` (EXTRA: files such as a
# CalculiX .dat). Relative paths are relative to tests/inp. Exit status: the checker's, 1 if a
# run fails.
set -u
frix=$1
checker=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
in_here() { case $1 in /*) echo "$1" ;; *) echo "$here/$1" ;; esac; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
results=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
  deck=$1
  shift
  name=$(basename "$deck" .dck)
  if ! "$frix" "$(in_here "$deck")" --out "$work" --quiet > "$work/$name.log" 2>&1; then
    echo "FAIL: frix $deck"
    cat "$work/$name.log"
    exit 1
  fi
  results+=("$work/$name.h5")
done
[ $# -gt 0 ] && shift
extra=()
for file in "$@"; do extra+=("$(in_here "$file")"); done
checker=$(in_here "$checker")
cd "$(dirname "$checker")" && PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 "$checker" "${results[@]}" "${extra[@]}"
