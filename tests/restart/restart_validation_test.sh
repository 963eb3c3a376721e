#!/usr/bin/env bash
# restart_validation_test.sh FRIX DECK: a restart file is validated, not trusted. DECK (an
# augmented contact deck with HDF5 output, increment 2.2 restartable) is run through; copies
# of its .h5 are then damaged one way each and a restart from increment 2.2 of each must exit
# 1 with a message naming the damage, and write no increment:
#   time NaN; time outside step 2; NaN in displacement; NaN in the contact multipliers;
#   displacement stored as integers; the increment's `complete` attribute 0 (not written out).
# Before the validation frix restarted from all of them (t = NaN gave "0 converged
# increments" and exit 0).
set -u
frix=$1; deck=$2
name=$(basename "$deck" .dck)
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
"$frix" "$deck" --out "$out/full" --quiet || { echo "FAIL: the uninterrupted run failed"; exit 1; }
damage() {   # damage KIND: a copy of the file with the damage KIND at increment 2.2
  cp "$out/full/$name.h5" "$out/$1.h5"
  /usr/bin/python3 - "$out/$1.h5" "$1" <<'PY'
import sys, h5py, numpy as np
path, kind = sys.argv[1:]
with h5py.File(path, "r+") as f:
    g = next(g for g in f["increments"].values()
             if g.attrs["step"] == 2 and g.attrs["increment"] == 2)
    if kind == "time_nan":
        g.attrs["time"] = np.nan
    elif kind == "time_outside":
        g.attrs["time"] = 2.5
    elif kind == "displacement_nan":
        d = g["displacement"][...]; d[3, 1] = np.nan; g["displacement"][...] = d
    elif kind == "multiplier_nan":
        d = g["contact/pass1_multiplier"][...]; d[0] = np.nan; g["contact/pass1_multiplier"][...] = d
    elif kind == "displacement_integer":
        d = g["displacement"][...]; del g["displacement"]
        g.create_dataset("displacement", data=np.rint(d).astype(np.int32))
    elif kind == "incomplete":
        g.attrs["complete"] = 0
PY
}
fail=0
check() {   # check KIND EXPECTED_TEXT
  damage "$1"
  "$frix" "$deck" --out "$out/from_$1" --quiet --restart "$out/$1.h5" --from 2.2 > "$out/$1.log" 2>&1
  status=$?
  if [ $status -ne 1 ]; then
    echo "FAIL $1: exit status $status, expected 1"; fail=1
  elif ! grep -q -- "$2" "$out/$1.log"; then
    echo "FAIL $1: message without \"$2\":"; cat "$out/$1.log"; fail=1
  elif ls "$out/from_$1"/*_listing.txt > /dev/null 2>&1 && grep -q "^STEP" "$out/from_$1"/*_listing.txt; then
    echo "FAIL $1: increments were written"; fail=1
  else
    echo "ok $1: $(head -c 300 "$out/$1.log")"
  fi
}
check time_nan "non-finite time"
check time_outside "outside the step"
check displacement_nan 'dataset "displacement" .* non-finite'
check multiplier_nan 'dataset "contact/pass1_multiplier" .* non-finite'
check displacement_integer 'holds integer values, expected floating-point'
check incomplete "has no increment 2 of step 2"
exit $fail
