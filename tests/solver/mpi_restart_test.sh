#!/usr/bin/env bash
# mpi_restart_test.sh FRIX DECK FROM: restart across process counts (docs/parallel.md). DECK
# (with HDF5 Yes) is run with SOLVER Petsc on one process and on 2 (mpirun -n 2); each run's
# HDF5 file is restarted from converged increment FROM on the other process count. Every
# run must end at the state of the uninterrupted one-process run, within 1e-10 of each
# field's largest value (displacements, EAS parameters, reactions, stresses and the material
# history): a restart reads the whole state on every process, whatever the number of
# processes that wrote it. A deck without SOLVER Petsc under mpirun -n 2 must be refused with
# a message naming SOLVER Petsc.
set -eu
frix=$1; deck=$2; from=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
name=$(basename "$deck" .dck)
deck_dir=$(cd "$(dirname "$deck")" && pwd)
copy=$deck_dir/.${name}_mpi_$$.dck   # next to the original, for its mesh files
out=$(mktemp -d)
trap 'rm -rf "$out" "$copy"' EXIT
awk '/^[[:space:]]*SOLVER[[:space:]]/ { next } { print } /-STATIC[[:space:]]*$/ { print "SOLVER       Petsc" }' \
    "$deck" > "$copy"
base=.${name}_mpi_$$
mpi=(mpirun -n 2 --oversubscribe)
[ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)

"$frix" "$copy" --out "$out/p1" --quiet
"${mpi[@]}" "$frix" "$copy" --out "$out/p2" --quiet
"${mpi[@]}" "$frix" "$copy" --out "$out/p1_to_p2" --quiet --restart "$out/p1/$base.h5" --from "$from"
"$frix" "$copy" --out "$out/p2_to_p1" --quiet --restart "$out/p2/$base.h5" --from "$from"

if "${mpi[@]}" "$frix" "$deck" --out "$out/own_solver" --quiet > "$out/own_solver.log" 2>&1; then
    echo "FAIL: the deck's own solver was accepted on 2 processes"; exit 1
fi
grep -q "needs SOLVER Petsc" "$out/own_solver.log" ||
    { echo "FAIL: no message naming SOLVER Petsc"; cat "$out/own_solver.log"; exit 1; }

/usr/bin/python3 - "$out" "$base" <<'PY'
import sys, h5py, numpy as np
out, base = sys.argv[1:]
fields = ('displacement', 'alpha', 'reaction', 'stress', 'history')
def last(run):
    with h5py.File(f"{out}/{run}/{base}.h5", 'r') as f:
        g = f['increments'][sorted(f['increments'])[-1]]
        return ((int(g.attrs['step']), int(g.attrs['increment'])),
                {k: g[k][...] for k in fields if k in g and g[k].size > 0})
ref_at, ref = last('p1')
fail = 0
for run in ('p2', 'p1_to_p2', 'p2_to_p1'):
    at, got = last(run)
    if at != ref_at:
        print(f"FAIL {run}: ends at step/increment {at}, not {ref_at}"); fail = 1; continue
    for k in ref:
        scale = np.max(np.abs(ref[k])) or 1.0
        err = np.max(np.abs(got[k] - ref[k])) / scale
        print(f"{run}: {k} max difference {err:.1e} of max |{k}| = {scale:.3e}")
        if not err <= 1e-10:
            print(f"FAIL {run}: {k}"); fail = 1
sys.exit(fail)
PY
echo "PASS: restarts between 1 and 2 processes end at the one-process state"
