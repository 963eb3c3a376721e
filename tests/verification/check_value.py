#!/usr/bin/python3
"""check_value.py CSV COLUMN FACTOR EXPECTED REL_TOL LABEL

Take the last row of a frix history CSV (docs/output.md), value = FACTOR * row[COLUMN], and
pass when |value - EXPECTED| <= REL_TOL |EXPECTED|. Prints value, expected and the relative
error; exit status 1 when the check fails, 2 on a usage error.
"""
import csv
import sys

if len(sys.argv) != 7:
    print(__doc__)
    sys.exit(2)
path, column, factor, expected, tol, label = sys.argv[1:]
with open(path) as f:
    rows = list(csv.DictReader(f))
if not rows or column not in rows[-1]:
    print(f"check_value: no column {column} in {path}")
    sys.exit(2)
value = float(factor) * float(rows[-1][column])
expected, tol = float(expected), float(tol)
error = (value - expected) / abs(expected)
ok = abs(error) <= tol
print(f"{'ok  ' if ok else 'FAIL'} {label}: {value:.6f}, expected {expected:.6f}, "
      f"relative error {error:+.3e} (tolerance {tol:.1e})")
sys.exit(0 if ok else 1)
