#!/usr/bin/env bash
# A run stopped by a signal (docs/solver.md, "Stopping a run").
#   stop_signal_test.sh FRIX DECK INT|TERM   frix stops at its next safe point:
#       exit status 3, "stopped by SIG<name>" on stderr, no temporary file left, and every
#       result file complete and readable (the .pvd and each .vtu parse as XML, the POS3D file
#       ends with %END, the HDF5 file opens and lists the converged increments, the CSV files
#       have their header and one row per converged increment (history) or per slave node and
#       increment (contact)).
#   stop_signal_test.sh FRIX DECK KILL       SIGKILL during the first increment (nothing can
#       be done then): the contact CSV still holds its header line, and h5py opens the HDF5
#       file, which holds the mesh and no increment.
# The signal is sent once the history CSV shows two converged increments (for KILL: once the
# first Newton iteration is printed).
set -u
frix=$1; deck=$2; signal=$3
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
base=$out/$(basename "${deck%.*}")
fail() { echo "FAIL: $*"; failed=1; }
failed=0

"$frix" "$deck" --out "$out" > "$out/stdout" 2> "$out/stderr" &
pid=$!
for _ in $(seq 1 1200); do   # up to 120 s
  if [ "$signal" = KILL ]; then
    grep -q 'iter  0' "$out/stdout" 2>/dev/null && break
  else
    [ "$(cat "${base}_history.csv" 2>/dev/null | wc -l)" -ge 3 ] && break
  fi
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.1
done
if ! kill -0 "$pid" 2>/dev/null; then
  echo "FAIL: the run ended before the signal could be sent"; cat "$out/stderr"; exit 1
fi
kill -s "$signal" "$pid"
wait "$pid"
status=$?

if [ "$signal" = KILL ]; then
  header=$(head -n 1 "${base}_contact.csv" 2>/dev/null)
  case "$header" in
    step,increment,time,pair,pass,node,*) ;;
    *) fail "the contact CSV has no header after SIGKILL: \"$header\"" ;;
  esac
  /usr/bin/python3 - "${base}.h5" <<'PY' || failed=1
import sys, h5py
try:
    with h5py.File(sys.argv[1], 'r') as f:
        n, nodes = len(f['increments']), f['mesh/coordinates'].shape[0]
except Exception as exc:
    print('FAIL: h5py cannot open the HDF5 file after SIGKILL: %s' % exc)
    sys.exit(1)
if n != 0 or nodes == 0:
    print('FAIL: the HDF5 file after SIGKILL: %d increments, %d nodes' % (n, nodes))
    sys.exit(1)
PY
  [ "$failed" -eq 0 ] && echo "ok: SIGKILL during the first increment leaves the contact CSV header and a readable .h5"
  exit "$failed"
fi

[ "$status" -eq 3 ] || fail "exit status $status, expected 3"
grep -q "stopped by SIG$signal" "$out/stderr" || fail "stderr lacks \"stopped by SIG$signal\""
if grep -qE 'Fortran runtime error|Backtrace|SIGSEGV' "$out/stdout" "$out/stderr"; then fail "crash output"; fi
leftovers=$(find "$out" -name '*.tmp')
[ -z "$leftovers" ] || fail "temporary files left: $leftovers"
n=$(sed -n 's/.*results of the \([0-9]*\) converged increments.*/\1/p' "$out/stderr")
[ -n "$n" ] && [ "$n" -ge 2 ] || fail "the message does not give the converged increments: $(cat "$out/stderr")"
tail -n 1 "${base}.pos" | grep -q '^%END' || fail "the POS3D file does not end with %END"
/usr/bin/python3 - "$base" "${n:-0}" <<'PY' || failed=1
import sys, glob, csv, xml.etree.ElementTree as ET
import h5py
base, n = sys.argv[1], int(sys.argv[2])
ok = True
def fail(message):
    global ok
    print("FAIL:", message); ok = False
pvd = ET.parse(base + ".pvd").getroot()
files = [d.get("file") for d in pvd.iter("DataSet")]
if len(files) != n: fail(f"{len(files)} data sets in the .pvd, expected {n}")
directory = base.rsplit("/", 1)[0]
for f in files:
    ET.parse(directory + "/" + f)
with open(base + "_history.csv") as handle:
    rows = list(csv.reader(handle))
if rows[0][:3] != ["step", "increment", "time"] or len(rows) - 1 != n:
    fail(f"history CSV: header {rows[0][:3]}, {len(rows) - 1} rows, expected {n}")
with open(base + "_contact.csv") as handle:
    rows = list(csv.reader(handle))
increments = {(r[0], r[1]) for r in rows[1:]}
if rows[0][0] != "step" or len(increments) != n:
    fail(f"contact CSV: {len(increments)} increments, expected {n}")
with h5py.File(base + ".h5", "r") as h5:
    complete = [g for g in h5["increments"].values() if g.attrs.get("complete", 0) == 1]
    if len(complete) != n: fail(f"{len(complete)} complete increments in the HDF5 file, expected {n}")
sys.exit(0 if ok else 1)
PY
if [ "$failed" -ne 0 ]; then
  echo "--- stderr"; cat "$out/stderr"; exit 1
fi
echo "ok: SIG$signal: exit status 3 after $n converged increments, files complete, no temporary file"
