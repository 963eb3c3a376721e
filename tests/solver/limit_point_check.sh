#!/usr/bin/env bash
# The SVK cube of limit_point_cutback.dck: the last converged load factor must approach the
# analytical limit point t* = E/(3 sqrt 3)/250 = 0.769800358 from below (cut-backs work), and
# never pass it (no spurious convergence beyond the limit, where no equilibrium exists).
# At each converged t the top displacement must satisfy the uniaxial SVK equilibrium
# 250 t = -E lambda (lambda^2 - 1)/2 with lambda = 1 + w (w < 0): checked to 1e-8 relative.
set -eu
frix=$1; deck=$2
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
"$frix" "$deck" --out "$out" --quiet > /dev/null 2>&1 || true
/usr/bin/python3 - "$out/limit_point_cutback_history.csv" <<'PY'
import sys, math
import numpy as np
d = np.genfromtxt(sys.argv[1], delimiter=',', names=True)
E, p = 1000.0, 250.0
t_star = E / (3 * math.sqrt(3)) / p
t, w = d['time'], d['u3_n8']
fail = 0
if not (t_star - 5e-3 < t[-1] <= t_star):
    print(f"FAIL: last converged t = {t[-1]:.9f}, limit {t_star:.9f}"); fail = 1
lam = 1 + w
nominal = -E * lam * (lam**2 - 1) / 2
err = np.max(np.abs(nominal - p * t) / (p * t))
if err > 1e-8:
    print(f"FAIL: equilibrium error {err:.2e}"); fail = 1
print(f"limit point: last t = {t[-1]:.9f} (analytical {t_star:.9f}), {len(t)} increments, "
      f"max equilibrium error {err:.1e}")
sys.exit(fail)
PY
