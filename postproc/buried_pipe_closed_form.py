#!/usr/bin/python3
"""Diameter changes of a thin elastic ring in an infinite, weightless, linear elastic medium
under a uniform far-field stress (the buried-pipe problem of Burns & Richard 1964 and Hoeg
1968), full slip and no slip, plane strain (docs/verification/s5.md "Closed-form check").

The far field (compression positive) is sigma_v = p vertical, sigma_h = K p horizontal,
applied after the ring is in place. The medium around the hole of radius R is the Michell
solution: a uniform part (mean stress p (1 + K)/2, terms 1 and log r of the Airy function) and
a cos 2 theta part (Airy function (B r^2 + D r^-2 + E) cos 2 theta, B from the far field); the
ring is a thin curved beam of radius R (membrane strain (v' + w)/R, curvature change
(v' - w'')/R^2, plane-strain modulus E_r/(1 - nu_r^2), area t and inertia t^3/12 per unit
length), loaded by the medium's tractions at r = R. Conditions at r = R: radial displacement
continuous, and either the tangential displacement continuous (no slip) or the shear traction
zero (full slip). This is the problem Burns & Richard and Hoeg solved; the script solves the
same equations (2 unknowns for the uniform part, 4 for the cos 2 theta part) instead of
quoting their printed formulas. Results: Delta D_h = 2 (w0 + w2), Delta D_v = 2 (w0 - w2), w0
and w2 the uniform and cos 2 theta amplitudes of the ring's radial displacement (theta from the
springline), negative = shortening. Also printed: the flexibility and compressibility ratios in
the form of Hoeg / Einstein & Schwartz, F = E_m R^3 (1 - nu_r^2) / (E_r I (1 + nu_m)),
C = E_m R (1 - nu_r^2) / (E_r t (1 + nu_m)(1 - 2 nu_m)).
"""
import argparse
import math
import sys

import numpy as np


def ring_in_medium(p, k, e_m, nu_m, e_r, nu_r, t, radius, slip):
    """Return (dD_h, dD_v, w0, w2) for far field p (vertical), k p (horizontal), compression
    positive; slip 'full' or 'none'."""
    g = e_m / (2.0 * (1.0 + nu_m))
    kappa = 3.0 - 4.0 * nu_m
    e_plane = e_r / (1.0 - nu_r ** 2)
    ea, ei = e_plane * t, e_plane * t ** 3 / 12.0
    r = radius
    # uniform part: sigma_rr = s0 + a/r^2, u_r = s0 r (1 - 2 nu)/(2 G) - a/(2 G r) (tension +)
    s0 = -p * (1.0 + k) / 2.0
    # ring: w0 = q_r r^2 / EA with q_r = sigma_rr(R) (outward load on the ring)
    # s0 r (1-2nu)/(2G) - a/(2 G r) = (s0 + a/r^2) r^2 / EA
    lhs = -1.0 / (2.0 * g * r) - 1.0 / ea
    rhs = s0 * r ** 2 / ea - s0 * r * (1.0 - 2.0 * nu_m) / (2.0 * g)
    a = rhs / lhs
    w0 = (s0 + a / r ** 2) * r ** 2 / ea
    # cos 2 theta part, Airy function (B r^2 + D r^-2 + E) cos 2 theta, theta from the x axis
    b = -p * (1.0 - k) / 4.0
    # medium at r = R (tension +): coefficients of [D, E] and the B part
    ur = np.array([2.0 / r ** 3, (kappa + 1.0) / r]) / (2 * g); ur_b = -2.0 * b * r / (2 * g)
    ut = np.array([2.0 / r ** 3, -(kappa - 1.0) / r]) / (2 * g); ut_b = 2.0 * b * r / (2 * g)
    srr = np.array([-6.0 / r ** 4, -4.0 / r ** 2]); srr_b = -2.0 * b
    srt = np.array([-6.0 / r ** 4, -2.0 / r ** 2]); srt_b = 2.0 * b
    # ring: w = W cos 2t, v = V sin 2t, loads q_r = Qr cos 2t, q_t = Qt sin 2t
    #   EA (2V + W)/R^2 + 4 EI (2V + 4W)/R^4 = Qr
    #   2 EA (2V + W)/R^2 + 2 EI (2V + 4W)/R^4 = Qt
    # unknowns x = [W, V, D, E]
    m = np.zeros((4, 4)); f = np.zeros(4)
    m[0, :2] = [ea / r ** 2 + 16 * ei / r ** 4, 2 * ea / r ** 2 + 8 * ei / r ** 4]
    m[0, 2:] = -srr; f[0] = srr_b
    m[1, :2] = [2 * ea / r ** 2 + 8 * ei / r ** 4, 4 * ea / r ** 2 + 4 * ei / r ** 4]
    m[1, 2:] = -srt; f[1] = srt_b
    m[2, 0] = 1.0; m[2, 2:] = -ur; f[2] = ur_b                 # w = u_r
    if slip == "none":
        m[3, 1] = 1.0; m[3, 2:] = -ut; f[3] = ut_b             # v = u_theta
    else:
        m[3, 2:] = srt; f[3] = -srt_b                          # sigma_rt = 0
    w2 = np.linalg.solve(m, f)[0]
    return 2.0 * (w0 + w2), 2.0 * (w0 - w2), w0, w2


def ratios(e_m, nu_m, e_r, nu_r, t, radius):
    flex = e_m * radius ** 3 * (1 - nu_r ** 2) / (e_r * t ** 3 / 12.0 * (1 + nu_m))
    comp = e_m * radius * (1 - nu_r ** 2) / (e_r * t * (1 + nu_m) * (1 - 2 * nu_m))
    return flex, comp


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog=__doc__.split("\n\n", 1)[1])
    parser.add_argument("--p", type=float, default=100.0, help="vertical far-field stress (100)")
    parser.add_argument("--k", type=float, default=None,
                        help="K = sigma_h/sigma_v (default K0 = nu_m/(1 - nu_m), the oedometric "
                             "state of a block with rollers on its sides)")
    parser.add_argument("--em", type=float, default=2.7e3, help="medium's Young modulus (2.7e3)")
    parser.add_argument("--num", type=float, default=0.33, help="medium's Poisson ratio (0.33)")
    parser.add_argument("--er", type=float, default=2.1e8, help="ring's Young modulus (2.1e8)")
    parser.add_argument("--nur", type=float, default=0.3, help="ring's Poisson ratio (0.3)")
    parser.add_argument("--t", type=float, default=0.002, help="wall thickness (0.002)")
    parser.add_argument("--radius", type=float, default=0.501,
                        help="ring (mid-wall) radius (0.501 = D0/2 + t/2)")
    args = parser.parse_args()
    k = args.k if args.k is not None else args.num / (1.0 - args.num)
    flex, comp = ratios(args.em, args.num, args.er, args.nur, args.t, args.radius)
    print("K = %.6f  F = %.6g  C = %.6g" % (k, flex, comp))
    print("%-10s %16s %16s %16s %16s" % ("slip", "dD_h", "dD_v", "w0", "w2"))
    for slip in ("full", "none"):
        dh, dv, w0, w2 = ring_in_medium(args.p, k, args.em, args.num, args.er, args.nur, args.t,
                                        args.radius, slip)
        print("%-10s %16.9e %16.9e %16.9e %16.9e" % (slip, dh, dv, w0, w2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
