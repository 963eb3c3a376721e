#!/usr/bin/python3
"""Tip displacements of the inextensible elastica cantilever under a dead end load normal to
the undeformed axis (Euler-Bernoulli, Bisshopp & Drucker 1945; tabulated by Mattiasson 1981,
IJNME 17, 145-153), computed independently of frix by shooting:

    theta''(s) = -k cos(theta(s)),  s in [0, 1] (s = arc length / L, k = P L^2 / (E I)),
    theta(0) = 0 (clamped), theta'(1) = 0 (no end moment);
    x(1) = int cos(theta) ds,  y(1) = int sin(theta) ds  (in units of L).

Prints, per k: u/L = 1 - x(1) (horizontal shortening), v/L = y(1) (deflection), theta(1).
usage: elastica.py [k ...]   (default: 1 10)
"""
import sys
import numpy as np


def integrate(k, kappa0, n=1000):
    """RK4 for (theta, kappa, x, y) from s = 0 to 1 with theta'(0) = kappa0."""
    def f(z):
        th, ka = z[0], z[1]
        return np.array([ka, -k * np.cos(th), np.cos(th), np.sin(th)])
    z = np.array([0.0, kappa0, 0.0, 0.0])
    h = 1.0 / n
    for _ in range(n):
        a = f(z); b = f(z + h / 2 * a); c = f(z + h / 2 * b); d = f(z + h * c)
        z = z + h / 6 * (a + 2 * b + 2 * c + d)
    return z


def solve(k):
    # theta'(1) as a function of theta'(0) = kappa0 in (0, k]: bisection on the sign change
    lo, hi = 0.0, float(k)
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        if integrate(k, mid)[1] > 0.0:
            hi = mid
        else:
            lo = mid
    z = integrate(k, 0.5 * (lo + hi))
    return 1.0 - z[2], z[3], z[0]


if __name__ == "__main__":
    ks = [float(a) for a in sys.argv[1:]] or [1.0, 10.0]
    for k in ks:
        u, v, th = solve(k)
        print(f"k = {k:g}: u/L = {u:.5f}  v/L = {v:.5f}  theta_tip = {th:.5f}")
