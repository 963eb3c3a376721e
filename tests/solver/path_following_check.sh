#!/usr/bin/env bash
# Path following (CONTROL Path) on the St. Venant-Kirchhoff cube (E = 1000, nu = 0, dead
# pressure p on the top, the top corner node 8 driven down): uniaxial SVK gives
#   p t = -E lambda (lambda^2 - 1) / 2,   lambda = 1 + w,
# with its largest value E / (3 sqrt 3) at lambda = 1/sqrt 3 (the limit point).
#   path_following_check.sh <frix> <deck> <p> passes|lands
# Both modes: exit 0, and every converged increment on the analytical curve to 1e-8.
# passes: the run ends with "reached its target" at w = TARGET, the load factor rises to the
#   limit point (the largest converged t within 1e-4 of t* = E/(3 sqrt 3)/p, as the 20
#   increments sample it) and falls after it (at least 5 increments with t decreasing).
# lands: the last increment is t = 1 exactly (the increment that passed t = 1 repeated under
#   load control), below the limit point.
set -eu
frix=$1; deck=$2; pressure=$3; mode=$4
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
name=$(basename "$deck" .dck)
status=0
"$frix" "$deck" --out "$out" > "$out/log.txt" 2>&1 || status=$?
if [ "$status" -ne 0 ]; then echo "FAIL: frix exited with $status"; tail -5 "$out/log.txt"; exit 1; fi
if [ "$mode" = passes ] && ! grep -q 'reached its target' "$out/log.txt"; then
  echo "FAIL: no 'reached its target' message"; exit 1
fi
/usr/bin/python3 - "$out/${name}_history.csv" "$pressure" "$mode" <<'PY'
import sys, math
import numpy as np
d = np.genfromtxt(sys.argv[1], delimiter=',', names=True)
p, mode = float(sys.argv[2]), sys.argv[3]
E = 1000.0
t, w = np.atleast_1d(d['time']), np.atleast_1d(d['u3_n8'])
lam = 1 + w
analytical = -E * lam * (lam**2 - 1) / 2 / p
err = np.max(np.abs(analytical - t) / np.abs(analytical))
fail = 0
if err > 1e-8:
    print(f"FAIL: equilibrium error {err:.2e} > 1e-8"); fail = 1
t_star = E / (3 * math.sqrt(3)) / p
if mode == 'passes':
    k = int(np.argmax(t))
    falling = int(np.sum(np.diff(t[k:]) < 0))
    if abs(t[k] - t_star) > 1e-4:
        print(f"FAIL: largest t {t[k]:.6f}, limit point {t_star:.6f}"); fail = 1
    if falling < 5:
        print(f"FAIL: only {falling} increments past the limit point"); fail = 1
    print(f"path following: largest t = {t[k]:.6f} (limit point {t_star:.6f}) at w = {w[k]:.4f}, "
          f"{falling} increments beyond it, last t = {t[-1]:.6f} at w = {w[-1]:.4f}; "
          f"max equilibrium error {err:.1e}")
else:
    if t[-1] != 1.0:
        print(f"FAIL: last t = {t[-1]!r}, expected 1 exactly"); fail = 1
    print(f"path following to t = 1: last w = {w[-1]:.9f}, {len(t)} increments, "
          f"max equilibrium error {err:.1e}")
sys.exit(fail)
PY
