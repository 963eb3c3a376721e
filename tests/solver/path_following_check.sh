#!/usr/bin/env bash
# Path following (CONTROL Path) on the St. Venant-Kirchhoff cube (E = 1000, nu = 0, dead
# pressure p on the top, the top corner node 8 driven down): uniaxial SVK gives
#   p t = -E lambda (lambda^2 - 1) / 2,   lambda = 1 + w,
# with its largest value E / (3 sqrt 3) at lambda = 1/sqrt 3 (the limit point).
#   path_following_check.sh <frix> <deck> <p> passes|lands|near
# All modes: exit 0, and every converged increment of the Path step on the analytical curve to
# 1e-8 (p scaled by the deck's curve factor where it has one: near).
# passes: the run ends with "reached its target" at w = TARGET (to 1e-12), the load factor rises
#   to the limit point (the largest converged t within 1e-4 of t* = E/(3 sqrt 3)/p, as the 20
#   increments sample it) and falls after it (at least 5 increments with t decreasing).
# lands: the last increment is t = 1 exactly (the increment that passed t = 1 repeated under
#   load control), below the limit point.
# near: TARGET lies within the displacement tolerance of the step's start; the step must end
#   at w = TARGET after its NUMSTEP increments (not repeat increments that do not move).
set -eu
frix=$1; deck=$2; pressure=$3; mode=$4
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
name=$(basename "$deck" .dck)
status=0
"$frix" "$deck" --out "$out" > "$out/log.txt" 2>&1 || status=$?
if [ "$status" -ne 0 ]; then echo "FAIL: frix exited with $status"; tail -5 "$out/log.txt"; exit 1; fi
target=$(awk '$1 == "STEP" && /CONTROL Path/ { for (i = 1; i < NF; i++) if ($i == "TARGET") print $(i + 1) }' "$deck")
numstep=$(awk '$1 == "STEP" && /CONTROL Path/ { for (i = 1; i < NF; i++) if ($i == "NUMSTEP") print $(i + 1) }' "$deck")
if [ "$mode" != lands ] && ! grep -q 'reached its target' "$out/log.txt"; then
  echo "FAIL: no 'reached its target' message"; exit 1
fi
/usr/bin/python3 - "$out/${name}_history.csv" "$pressure" "$mode" "$target" "$numstep" <<'PY'
import sys, math
import numpy as np
d = np.genfromtxt(sys.argv[1], delimiter=',', names=True)
p, mode, target, numstep = float(sys.argv[2]), sys.argv[3], float(sys.argv[4]), int(sys.argv[5])
E = 1000.0
path_step = np.atleast_1d(d['step']) == np.atleast_1d(d['step']).max()
t, w = np.atleast_1d(d['time'])[path_step], np.atleast_1d(d['u3_n8'])[path_step]
lam = 1 + w
# the near deck's pressure follows CURVE 1 POINTS 0 0 2 1: p t/2 (t in [1, 2])
load = p * t / 2 if mode == 'near' else p * t
analytical = -E * lam * (lam**2 - 1) / 2
err = np.max(np.abs(analytical - load) / np.abs(analytical))
fail = 0
if err > 1e-8:
    print(f"FAIL: equilibrium error {err:.2e} > 1e-8"); fail = 1
t_star = E / (3 * math.sqrt(3)) / p
if mode != 'lands' and abs(w[-1] - target) > 1e-12:
    print(f"FAIL: last w = {w[-1]!r}, TARGET {target!r}"); fail = 1
if mode == 'near':
    if len(t) != numstep:
        print(f"FAIL: {len(t)} increments in the Path step, NUMSTEP {numstep}"); fail = 1
    print(f"path following to a target near the start: {len(t)} increments, last w = {w[-1]!r}, "
          f"max equilibrium error {err:.1e}")
elif mode == 'passes':
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
