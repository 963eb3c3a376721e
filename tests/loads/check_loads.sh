#!/usr/bin/env bash
# Body force and follower pressure against closed-form solutions (see the decks' headers).
#   check_loads.sh FRIX DIR_OF_DECKS
set -eu
frix=$1; here=$2
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
"$frix" "$here/self_weight_column.dck" --out "$out" --quiet
"$frix" "$here/follower_hydrostatic.dck" --out "$out" --quiet
/usr/bin/python3 - "$out" <<'PY'
import sys, math
import numpy as np
out = sys.argv[1]
fail = 0
def check(label, got, expected, tol):
    global fail
    err = abs(got - expected) / abs(expected)
    ok = err <= tol
    fail |= not ok
    print(f"{'ok  ' if ok else 'FAIL'} {label}: {got:.12g} expected {expected:.12g} (rel. error {err:.1e}, tol {tol:.0e})")
d = np.atleast_1d(np.genfromtxt(f"{out}/self_weight_column_history.csv", delimiter=',', names=True))
rho, g, H, E = 2.0, 9.81, 10.0, 1000.0
u = lambda z: -rho * g * (H * z - z * z / 2) / E
check("self weight, top u_z", d['u3_n44'][-1], u(10.0), 1e-12)
check("self weight, mid-height u_z", d['u3_n24'][-1], u(5.0), 1e-12)
# neo-Hookean hydrostatic state under follower pressure: sigma = -p I with uniform stretch l,
# (mu (l^2 - 1) + 3 lambda ln l) / l^3 = -p; Newton on l.
E, nu = 1000.0, 0.3
mu, lam = E / (2 * (1 + nu)), E * nu / ((1 + nu) * (1 - 2 * nu))
d = np.genfromtxt(f"{out}/follower_hydrostatic_history.csv", delimiter=',', names=True)
for t, ux, uz in zip(d['time'], d['u1_n27'], d['u3_n27']):
    p = 150.0 * t
    f = lambda l: (mu * (l * l - 1) + 3 * lam * math.log(l)) / l**3 + p
    l = 1.0
    for _ in range(60):
        h = 1e-7
        l -= f(l) / ((f(l + h) - f(l - h)) / (2 * h))
    check(f"follower pressure p = {p:g}: corner u_x", ux, l - 1.0, 1e-9)
    check(f"follower pressure p = {p:g}: corner u_z", uz, l - 1.0, 1e-9)
sys.exit(fail)
PY
