#!/usr/bin/env bash
# A run killed (SIGKILL) before its first increment leaves an HDF5 file that h5py opens, with
# no increment (docs/hdf5-layout.md, "Runs that stop early").
#   kill_test.sh FRIX FAIL_WRITES_LIB DECK      (DECK with HDF5 Yes)
# FAIL_WRITES_LIB (tests/io/fail_writes.c) kills the run at its 3rd, 6th and 12th write into
# the .h5, while the mesh is written: before the file was flushed right after its creation,
# h5py failed on it ("truncated file: eof = 96, stored_eof = 2048", "bad object header
# version number"). The 1st and 2nd writes are the creation's flush itself.
set -u
frix=$1; library=$2; deck=$3
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
name=$(basename "${deck%.*}")
failed=0
for write in 3 6 12; do
  rm -rf "$out/results"
  FRIX_FAIL_WRITE_PATH=.h5 FRIX_KILL_AT_WRITE=$write LD_PRELOAD="$library" \
    ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0" \
    "$frix" "$deck" --quiet --out "$out/results" > /dev/null 2>&1
  status=$?
  if [ "$status" -ne 137 ]; then
    echo "FAIL: killed at write $write: exit status $status, expected 137 (SIGKILL)"; failed=1; continue
  fi
  /usr/bin/python3 - "$out/results/$name.h5" "$write" <<'PY' || failed=1
import sys, h5py
path, write = sys.argv[1], sys.argv[2]
try:
    with h5py.File(path, 'r') as f:
        n = len(f['increments']) if 'increments' in f else 0
except Exception as exc:
    print('FAIL: killed at write %s: h5py cannot open the file: %s' % (write, exc))
    sys.exit(1)
if n != 0:
    print('FAIL: killed at write %s: %d increments, expected none' % (write, n))
    sys.exit(1)
print('ok: killed at write %s: h5py opens the file, no increment' % write)
PY
done
exit "$failed"
