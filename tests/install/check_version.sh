#!/bin/bash
# check_version.sh FRIX VERSION: `FRIX --version` exits with status 0, prints "frix VERSION"
# (VERSION: the project VERSION of CMakeLists.txt) on its first line, then the compiler and
# the SuiteSparse, CHOLMOD, UMFPACK, METIS and HDF5 versions, and nothing on stderr.
# Prints PASS:/FAIL: lines; exit 0 if all pass.
set -u
[ $# -eq 2 ] || { echo "usage: check_version.sh FRIX VERSION" >&2; exit 2; }
frix=$1; version=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$frix" --version > "$work/out" 2> "$work/err"
status=$?
failed=0
check() {  # check DESCRIPTION COMMAND...
    local what=$1; shift
    if "$@"; then echo "PASS: $what"; else echo "FAIL: $what"; failed=1; fi
}
check "exit status 0 (got $status)" test "$status" -eq 0
check "first line is \"frix $version\" (got \"$(head -n 1 "$work/out")\")" \
      test "$(head -n 1 "$work/out")" = "frix $version"
check "a compiler line" grep -q '^compiler: .' "$work/out"
for library in SuiteSparse CHOLMOD UMFPACK METIS HDF5; do
    check "$library version" grep -Eq "$library [0-9]+\.[0-9]+\.[0-9]+" "$work/out"
done
check "nothing on stderr" test ! -s "$work/err"
cat "$work/out" "$work/err"
exit $failed
