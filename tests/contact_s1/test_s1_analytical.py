#!/usr/bin/python3
"""Checks of postproc/s1_analytical.py (Hird & Russell's 1D S1 solution) against an independent
computation: the 1D boundary-value problem M H w'' = tau(w), tau = min(k_s w, tau_max),
w(0) = 0, M w'(L) = p, solved by second-order finite differences (N = 4000 intervals) with
Newton's method on the piecewise-linear tau. The FD error is O((L/N)^2) (measured below 1e-7 of
w(L)); the tolerance is 1e-5 of w(L). Also: the CLI's CSV and table, and
errors. Prints PASS:/FAIL: lines and "N passed, N failed"; exit 0 if all pass."""
import os
import subprocess
import sys
import tempfile

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
postproc = os.path.join(here, "..", "..", "postproc")
sys.path.insert(0, postproc)
import s1_analytical  # noqa: E402

passed = failed = 0


def check(condition, message):
    global passed, failed
    passed, failed = (passed + 1, failed) if condition else (passed, failed + 1)
    print(("PASS: " if condition else "FAIL: ") + message)


def finite_difference(theory, load, n=4000):
    """w at n + 1 nodes from M H w'' = min(k_s w, tau_max), w(0) = 0, M w'(L) = p (ghost node
    for the Neumann end), Newton on the active set of tau; tridiagonal solves."""
    h = theory.length / n
    m_h = theory.modulus * theory.height / h ** 2
    w = np.zeros(n + 1)
    for _ in range(100):
        slip = theory.shear_stiffness * w > theory.shear_strength
        tau = np.where(slip, theory.shear_strength, theory.shear_stiffness * w)
        dtau = np.where(slip, 0.0, theory.shear_stiffness)
        right = np.concatenate([w[2:], [w[n - 1] + 2 * h * load / theory.modulus]])
        residual = np.concatenate([[w[0]], m_h * (w[:-2] - 2 * w[1:-1] + right[:-1])
                                   - tau[1:-1], [m_h * (w[n - 1] - 2 * w[n] + right[-1]) - tau[n]]])
        lower = np.full(n, m_h)          # row i, column i - 1 (rows 1..n)
        lower[-1] = 2 * m_h              # the ghost node doubles the last row's neighbour
        diagonal = np.concatenate([[1.0], -2 * m_h - dtau[1:]])
        upper = np.concatenate([[0.0], np.full(n - 1, m_h)])   # row i, column i + 1 (rows 0..n-1)
        step = solve_tridiagonal(lower, diagonal, upper, -residual)
        w += step
        if np.max(np.abs(step)) <= 1e-15 * max(np.max(np.abs(w)), 1e-30):
            break
    return np.linspace(0, theory.length, n + 1), w


def solve_tridiagonal(lower, diagonal, upper, rhs):
    """Thomas algorithm: lower[i - 1], diagonal[i], upper[i] are row i's entries."""
    n = rhs.size
    b = diagonal.astype(float).copy()
    d = rhs.astype(float).copy()
    for i in range(1, n):
        factor = lower[i - 1] / b[i - 1]
        b[i] -= factor * upper[i - 1]
        d[i] -= factor * d[i - 1]
    x = np.zeros(n)
    x[-1] = d[-1] / b[-1]
    for i in range(n - 2, -1, -1):
        x[i] = (d[i] - upper[i] * x[i + 1]) / b[i]
    return x


theory = s1_analytical.Theory()
check(abs(theory.a - np.sqrt(0.1)) < 1e-15 and theory.modulus == 1e5 and theory.w1 == 3e-3,
      "S1 data: M = 1e5, a = sqrt(0.1), w1 = 3e-3")
p1 = 30 / np.sqrt(0.1) / np.tanh(np.sqrt(0.1) * 10)       # (k_s w1/(a H)) coth(a L)
check(abs(theory.p1 - p1) < 1e-12 * p1, f"p1 = {theory.p1:.6f} (hand: {p1:.6f})")
for load in (50.0, 95.0, 100.0, 150.0, 200.0, 250.0, 300.0, 600.0):
    x, w_fd = finite_difference(theory, load)
    w = theory.displacement(load, x)
    error = np.max(np.abs(w - w_fd)) / w_fd[-1]
    check(error <= 1e-5, f"p = {load:g}: w(x) = finite differences (N = 4000) to 1e-5 w(L) "
          f"(max {error:.1e})")
    x1 = theory.slip_front(load)
    if load > theory.p1:
        s1 = float(theory.axial_stress(load, x1))
        balance = s1 + theory.shear_strength * (theory.length - x1) / theory.height
        check(abs(float(theory.displacement(load, x1)) - theory.w1) <= 1e-12 * theory.w1
              and abs(balance - load) <= 1e-10 * load and 0 < x1 < theory.length,
              f"p = {load:g}: w(x1) = w1 and s1 + tau_max (L - x1)/H = p at x1 = {x1:.6f}")
        fd_front = x[np.argmax(theory.shear_stiffness * w_fd >= theory.shear_strength)]
        check(abs(fd_front - x1) <= 2 * theory.length / 4000,
              f"p = {load:g}: slip front = FD's first slipping node ({fd_front:.4f})")
    else:
        check(x1 == theory.length, f"p = {load:g} <= p1: no slip (x1 = L)")
    end_stress = float(theory.axial_stress(load, theory.length))
    check(abs(end_stress - load) <= 1e-10 * load, f"p = {load:g}: M w'(L) = p")

script = os.path.join(postproc, "s1_analytical.py")
with tempfile.TemporaryDirectory() as work:
    path = os.path.join(work, "theory.csv")
    run = subprocess.run(["/usr/bin/python3", script, "curves", "--points", "11", "-o", path,
                          "--sign", "-1"], capture_output=True, text=True)
    data = np.genfromtxt(path, delimiter=",", names=True) if run.returncode == 0 else None
    check(data is not None and len(data) == 11 and len(data.dtype.names) == 7
          and np.allclose(data["u_x_p300"], -theory.displacement(300.0, data["x"]), rtol=1e-15),
          "CLI curves: 11 positions x 6 loads, u_x = -w")
    run = subprocess.run(["/usr/bin/python3", script, "curves", "--loads", "a,b"],
                         capture_output=True, text=True)
    check(run.returncode == 2 and "error: --loads" in run.stderr and "Traceback" not in run.stderr,
          "CLI: bad --loads is a one-line error, status 2")
    run = subprocess.run(["/usr/bin/python3", script, "compare", os.path.join(work, "none.pvd")],
                         capture_output=True, text=True)
    check(run.returncode == 2 and "Traceback" not in run.stderr, "CLI: missing result file, status 2")
print(f"{passed} passed, {failed} failed")
sys.exit(0 if failed == 0 else 1)
