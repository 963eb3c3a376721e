#!/usr/bin/env bash
# A full disk under a run with HDF5 on (docs/output.md, "When a write fails"): a real one, a
# small tmpfs, so that HDF5 meets ENOSPC wherever it writes, also while it closes the file.
#   disk_full_test.sh FRIX DECK        (DECK with HDF5 Yes; needs root for mount: else skipped,
#                                       exit status 77)
# The run is repeated on tmpfs of 64 to 320 KiB, the disk filling in every increment. Each run
# must end with exit status 1 and a message naming the .h5, no success line, no crash, and the
# .h5 must open with h5py, its complete increments holding their datasets. Before, tmpfs of
# 96 KiB and 224 KiB ended in SIGSEGV (exit status 139) in HDF5's clean-up at exit
# (H5F__close_cb <- H5_term_library <- exit: the failed H5Fclose had freed the file and kept
# its id).
set -u
frix=$1; deck=$2
work=$(mktemp -d)
mounted=
cleanup() { [ -n "$mounted" ] && umount "$work/disk"; rm -rf "$work"; }
trap cleanup EXIT
mkdir "$work/disk"
if [ "$(id -u)" -ne 0 ] || ! mount -t tmpfs -o size=64k tmpfs "$work/disk" 2> /dev/null; then
  echo "skipped: mounting a tmpfs needs root"; exit 77
fi
umount "$work/disk"
name=$(basename "${deck%.*}")
sed 's/^VTK .*$/VTK No  LISTING No  POS3D No  HDF5 Yes/' "$deck" > "$work/$name.dck"
failed=0
for size in 64 96 128 160 192 224 256 288 320; do
  mount -t tmpfs -o size=${size}k tmpfs "$work/disk" && mounted=1
  "$frix" "$work/$name.dck" --out "$work/disk/results" > "$work/stdout" 2> "$work/stderr"
  status=$?
  problems=()
  [ "$status" -eq 1 ] || problems+=("exit status $status, expected 1")
  grep -q "HDF5: cannot .*$name.h5" "$work/stderr" || problems+=("no message naming the .h5")
  grep -q 'converged increments; results in' "$work/stdout" && problems+=("success line")
  grep -qE 'Backtrace|SIGSEGV|Segmentation|Program received signal|HDF5-DIAG' "$work/stdout" "$work/stderr" \
    && problems+=("crash output")
  check=$(/usr/bin/python3 - "$work/disk/results/$name.h5" <<'PY'
import sys, h5py
try:
    with h5py.File(sys.argv[1], 'r') as f:
        groups = f['increments'] if 'increments' in f else {}
        complete = [k for k in groups if groups[k].attrs.get('complete') == 1]
        for k in complete:
            groups[k]['displacement'][()]
    print('%d complete increments' % len(complete))
except Exception as exc:
    print('h5py cannot read the file: %s' % exc)
    sys.exit(1)
PY
)
  [ $? -eq 0 ] || problems+=("$check")
  umount "$work/disk"; mounted=
  if [ ${#problems[@]} -gt 0 ]; then
    failed=1
    echo "FAIL: tmpfs of ${size} KiB: $(IFS=';'; echo "${problems[*]}")"; cat "$work/stderr"
  else
    echo "ok: tmpfs of ${size} KiB: exit status 1, $check: $(head -n 1 "$work/stderr")"
  fi
done
exit "$failed"
