#!/usr/bin/env bash
# A result file that cannot be written (a full disk) ends the run cleanly (docs/output.md,
# "When a write fails").
#   write_failure_test.sh FRIX FAIL_WRITES_LIB DECK CASE
# runs DECK (tests/io/write_failure.dck, every result file on) with FAIL_WRITES_LIB
# (tests/io/fail_writes.c) preloaded so that the writes into one file fail with ENOSPC once the
# file has grown by some bytes, during the third or a later increment. CASE names the file:
#   hdf5, listing, history, contact, vtu, pvd, pos   (HDF5 off but for `hdf5`)
#   listing_hdf5                                     (the listing fails with HDF5 on)
#   hdf5_device    the .h5's writes fail although the room for the increment was there (a
#                  failing device: FRIX_FAIL_WRITE_STRICT), so that HDF5's close fails too;
#                  before, SIGSEGV (exit status 139) in HDF5's clean-up at exit. The .h5 may
#                  then be damaged: it is not read back.
# Expected: exit status 1, a message naming the file and "No space left on device" (HDF5:
# "HDF5: cannot write ... in "<file>""), no success line, no crash report (before, the run
# ended with exit status 0 and the success line beside truncated or empty files, or with
# SIGSEGV in HDF5's clean-up at exit), no temporary file left, and the increments written
# before the failure readable: the .pvd and every .vtu it lists parse, the CSV files hold whole
# rows, the listing whole lines, the .pos ends with %END, the .h5 opens with h5py and its
# complete increments hold their datasets.
set -u
frix=$1; library=$2; deck=$3; case=$4
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
name=$(basename "${deck%.*}")
fail() { echo "FAIL: $*"; failed=1; }
failed=0

hdf5=No
strict=
case $case in
  hdf5_device) file=.h5; limit=60000; hdf5=Yes; strict=1 ;;
  hdf5) file=.h5; limit=200000; hdf5=Yes ;;
  listing) file=_listing.txt; limit=50000 ;;
  listing_hdf5) file=_listing.txt; limit=50000; hdf5=Yes ;;
  history) file=_history.csv; limit=200 ;;
  contact) file=_contact.csv; limit=30000 ;;
  vtu) file=.vtu; limit=200000 ;;
  pvd) file=.pvd; limit=700 ;;
  pos) file=.pos; limit=200000 ;;
  *) echo "unknown case $case"; exit 2 ;;
esac
sed "s/HDF5 Yes/HDF5 $hdf5/" "$deck" > "$out/$name.dck"
mkdir "$out/results"

if [ -n "$strict" ]; then export FRIX_FAIL_WRITE_STRICT=1; fi
# ASan must come first among the libraries: allow the preloaded one (Sanitize build)
FRIX_FAIL_WRITE_PATH="$file" FRIX_FAIL_WRITE_AFTER=$limit FRIX_FAIL_WRITE_REPORT="$out/refused" \
  LD_PRELOAD="$library" ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0" \
  "$frix" "$out/$name.dck" --out "$out/results" > "$out/stdout" 2> "$out/stderr"
status=$?

[ -e "$out/refused" ] || fail "no write was refused: the limit of $limit bytes is not reached"
[ "$status" -eq 1 ] || fail "exit status $status, expected 1"
grep -q "$name[^\"]*$file" "$out/stderr" || fail "the message does not name the file *$file"
if [ "$hdf5" = Yes ] && [ "$file" = .h5 ]; then
  grep -q 'HDF5: cannot write' "$out/stderr" || fail "the message does not say what failed"
else
  grep -q 'cannot write .*: No space left on device' "$out/stderr" || fail "the message does not say what failed"
fi
grep -q 'converged increments; results in' "$out/stdout" && fail "success line after a failed write"
if grep -qE 'Fortran runtime error|Backtrace|SIGSEGV|Segmentation|Program received signal|HDF5-DIAG' \
   "$out/stdout" "$out/stderr"; then fail "crash output"; fi
leftovers=$(find "$out/results" -name '*.tmp')
[ -z "$leftovers" ] || fail "temporary files left: $leftovers"

[ -n "$strict" ] && hdf5=damaged
/usr/bin/python3 - "$out/results/$name" "$hdf5" <<'PY' || failed=1
import sys, os, csv, xml.etree.ElementTree as ET
base, hdf5 = sys.argv[1], sys.argv[2] == 'Yes'
problems = []
folder = os.path.dirname(base)
collection = ET.parse(base + '.pvd').getroot()
datasets = [d.get('file') for d in collection.iter('DataSet')]
for name in datasets:
    try:
        ET.parse(os.path.join(folder, name))
    except Exception as exc:
        problems.append('%s listed in the .pvd does not parse: %s' % (name, exc))
if not datasets:
    problems.append('the .pvd lists no increment')
for suffix in ('_history.csv', '_contact.csv'):
    with open(base + suffix, newline='') as f:
        rows = list(csv.reader(f))
    if len(rows) < 2:
        problems.append('%s holds no increment' % suffix)
    if any(len(row) != len(rows[0]) for row in rows):
        problems.append('%s holds a cut row' % suffix)
with open(base + '_listing.txt', 'rb') as f:
    listing = f.read()
if not listing.endswith(b'\n') or b'NODAL DISPLACEMENTS' not in listing:
    problems.append('the listing holds no whole increment or ends inside a line')
with open(base + '.pos') as f:
    if f.read().rstrip('\n').split('\n')[-1] != '%END':
        problems.append('the .pos does not end with %END')
if hdf5:
    import h5py
    with h5py.File(base + '.h5', 'r') as f:
        groups = f['increments']
        complete = [k for k in groups if groups[k].attrs.get('complete') == 1]
        if not complete:
            problems.append('the .h5 holds no complete increment')
        for k in complete:
            if groups[k]['displacement'].shape[1] != 3:
                problems.append('.h5 increment %s: displacement not (n, 3)' % k)
for p in problems:
    print('FAIL: ' + p)
sys.exit(1 if problems else 0)
PY

if [ "$failed" -ne 0 ]; then
  echo "--- stdout"; tail -n 5 "$out/stdout"; echo "--- stderr"; cat "$out/stderr"; ls -l "$out/results"
  exit 1
fi
echo "ok: $case: exit status 1, \"$(head -n 1 "$out/stderr")\", the increments before it readable"
