#!/usr/bin/python3
"""Tests of postproc/buried_pipe_closed_form.py (S5's closed form, docs/verification/s5.md).

- rigid ring (E_r = 1e20): no diameter change (below 1e-9 of the hole's);
- no ring (E_r = 1e-4, 1e-10 of the medium's stiffness; smaller values lose digits to
  cancellation): the unlined circular hole loaded after it is cut (Kirsch), written out
  independently below; agreement to 1e-5;
- K = 1: no ovalization (dD_v = dD_h);
- a flexible ring deforms less with no slip than with full slip (|dD| smaller).
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
from buried_pipe_closed_form import ring_in_medium  # noqa: E402


def kirsch_hole(p, k, e, nu, radius):
    """Diameter changes (horizontal, vertical) of an unlined hole in plane strain, far field
    sigma_v = p, sigma_h = k p (compression), applied with the hole present:
    u_r(R, theta) = (R/(4G)) [(S1 + S2)(kappa + 1)/2 + (S1 - S2)(kappa + 1) cos 2 theta],
    S1 = sigma_xx, S2 = sigma_zz (tension +), theta from x, kappa = 3 - 4 nu (Kirsch's
    displacements at r = R, e.g. Barber, Elasticity, chapter 8)."""
    g = e / (2 * (1 + nu))
    kappa = 3 - 4 * nu
    s1, s2 = -k * p, -p
    def u_r(theta):
        return radius / (4 * g) * ((s1 + s2) * (kappa + 1) / 2 + (s1 - s2) * (kappa + 1) * math.cos(2 * theta))
    return 2 * u_r(0.0), 2 * u_r(math.pi / 2)


def check(condition, message):
    if not condition:
        print("test_closed_form.py: FAIL: " + message)
        sys.exit(1)
    print("ok: " + message)


def main():
    p, nu, e, r = 100.0, 0.33, 2.7e3, 0.501
    k = nu / (1 - nu)
    hole_h, hole_v = kirsch_hole(p, k, e, nu, r)
    for slip in ("full", "none"):
        dh, dv, _, _ = ring_in_medium(p, k, e, nu, 1e-4, 0.3, 0.002, r, slip)
        check(abs(dh - hole_h) < 1e-5 * abs(hole_v) and abs(dv - hole_v) < 1e-5 * abs(hole_v),
              "%s slip, no ring = Kirsch's hole: %.9e %.9e against %.9e %.9e" % (slip, dh, dv, hole_h, hole_v))
        dh, dv, _, _ = ring_in_medium(p, k, e, nu, 1e20, 0.3, 0.002, r, slip)
        check(max(abs(dh), abs(dv)) < 1e-9 * abs(hole_v), "%s slip, rigid ring: %.3e %.3e" % (slip, dh, dv))
        dh, dv, _, _ = ring_in_medium(p, 1.0, e, nu, 2.1e8, 0.3, 0.002, r, slip)
        check(abs(dh - dv) < 1e-12 * abs(dh), "%s slip, K = 1: dD_h = dD_v = %.9e" % (slip, dh))
    full = ring_in_medium(p, k, e, nu, 2.1e8, 0.3, 0.002, r, "full")
    none = ring_in_medium(p, k, e, nu, 2.1e8, 0.3, 0.002, r, "none")
    check(abs(none[1]) < abs(full[1]) and abs(none[0]) < abs(full[0]),
          "no slip stiffer than full slip: dD_v %.6e against %.6e" % (none[1], full[1]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
