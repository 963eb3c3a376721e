#!/bin/bash
# check_first_increment.sh FRIX: friction acts in the first increment of an analysis for
# nodes that touch at t = 0 (first_increment_friction.dck: mean bottom u_x = 10/(eps_T A) =
# 1e-3, exact from the sum of the stick tractions; tolerance 1e-8 relative, the Newton
# tolerance). Prints PASS:/FAIL: lines and "N passed, N failed"; exit 0 if all pass.
set -u
frix=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if ! "$frix" "$here/first_increment_friction.dck" --out "$work" --quiet > "$work/log" 2>&1; then
    echo "FAIL: frix failed: $(tail -n 2 "$work/log" | tr '\n' ' ')"; echo "0 passed, 1 failed"; exit 1
fi
/usr/bin/python3 - "$work/first_increment_friction_contact.csv" <<'PY'
import csv, sys
rows = [row for row in csv.DictReader(open(sys.argv[1])) if row["step"] == "1"]
ux = [float(row["x"]) - round(float(row["x"])) for row in rows]   # reference x is 0 or 1
mean = sum(ux) / len(ux)
ok = len(rows) == 4 and abs(mean - 1e-3) <= 1e-11 and all(row["status"] == "1" for row in rows)
print(("PASS" if ok else "FAIL") + f": 4 bottom nodes stick, mean u_x = {mean:.10e} (expected 1e-3)")
print(f"{int(ok)} passed, {int(not ok)} failed")
sys.exit(0 if ok else 1)
PY
