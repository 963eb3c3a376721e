#!/usr/bin/python3
"""tube_plane_strain_1d.py: an independent 1D solution of the pressurised tube in plane strain.

A long tube a <= r <= b, internal pressure p, eps_z = 0 (ends held axially), small strain,
isotropic elasticity (E, nu) and von Mises plasticity with linear isotropic hardening
(sigma_y, H; H = 0: perfectly plastic). The axisymmetric problem has one unknown field u(r):
eps_r = du/dr, eps_theta = u/r, eps_z = 0; it is solved here by its own finite elements
(linear in r, 2 Gauss points, weight r dr), the radial return of Simo & Hughes (1998, Box 3.2)
with sigma_z a full stress component, and Newton's method with the consistent tangent. It
shares no code with frix and keeps the elastic compressibility that Hill's closed form of the
plastic front leaves out (it takes sigma_z = (sigma_r + sigma_theta)/2 in the plastic zone).

Prints for each requested pressure u_r(a), u_r(b) and the plastic front c (the outermost
Gauss point with a plastic strain, +- the point spacing there).

    /usr/bin/python3 tests/verification/tube_plane_strain_1d.py               # V4: a = 1, b = 2
    /usr/bin/python3 tests/verification/tube_plane_strain_1d.py --inner 0.15625 --outer 0.1625 \\
        --young 205000 --poisson 0.25 --sigy 420 --hard 75000 --pressure 9 90 --elements 50
"""
import argparse
import math

import numpy as np


def solve(args):
    a, b, young, nu, sigy, hard = args.inner, args.outer, args.young, args.poisson, args.sigy, args.hard
    n = args.elements
    lam = young * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))
    mu = young / (2.0 * (1.0 + nu))
    kappa = lam + 2.0 * mu / 3.0
    nodes = np.linspace(a, b, n + 1)
    xi = np.array([-1.0, 1.0]) / math.sqrt(3.0)
    shape = np.stack([(1.0 - xi) / 2.0, (1.0 + xi) / 2.0], axis=1)             # (g, 2)
    h = np.diff(nodes)                                                          # (e,)
    rg = nodes[:-1, None] * shape[None, :, 0] + nodes[1:, None] * shape[None, :, 1]  # (e, g)
    weight = rg * h[:, None] / 2.0
    # B: strains (r, theta, z) from the element's two nodal u: (e, g, 3, 2)
    bmat = np.zeros((n, 2, 3, 2))
    bmat[:, :, 0, 0] = -1.0 / h[:, None]
    bmat[:, :, 0, 1] = 1.0 / h[:, None]
    bmat[:, :, 1, :] = shape[None, :, :] / rg[:, :, None]
    eps_p = np.zeros((n, 2, 3))
    alpha = np.zeros((n, 2))
    u = np.zeros(n + 1)
    identity_dev = np.eye(3) - np.ones((3, 3)) / 3.0

    def response(u, eps_p, alpha):
        strain = np.einsum("egij,ej->egi", bmat, np.stack([u[:-1], u[1:]], axis=1))
        elastic = strain - eps_p
        volume = elastic.sum(axis=2)
        trial = 2.0 * mu * (elastic - volume[..., None] / 3.0)
        norm = np.linalg.norm(trial, axis=2)
        radius = math.sqrt(2.0 / 3.0) * (sigy + hard * alpha)
        plastic = norm > radius * (1.0 + 1e-12)
        dgamma = np.where(plastic, (norm - radius) / (2.0 * mu + 2.0 / 3.0 * hard), 0.0)
        normal = trial / np.where(norm > 0.0, norm, 1.0)[..., None]
        stress = volume[..., None] * kappa + trial - 2.0 * mu * dgamma[..., None] * normal
        theta = np.where(plastic, 1.0 - 2.0 * mu * dgamma / np.where(norm > 0.0, norm, 1.0), 1.0)
        theta_bar = np.where(plastic, 1.0 / (1.0 + hard / (3.0 * mu)) - (1.0 - theta), 0.0)
        tangent = (kappa * np.ones((3, 3))[None, None] + 2.0 * mu * theta[..., None, None] * identity_dev
                   - 2.0 * mu * theta_bar[..., None, None] * np.einsum("egi,egj->egij", normal, normal))
        return (stress, tangent, eps_p + dgamma[..., None] * normal,
                alpha + math.sqrt(2.0 / 3.0) * dgamma, plastic)

    def assemble(u, p):
        stress, tangent, new_eps_p, new_alpha, plastic = response(u, eps_p, alpha)
        fe = np.einsum("egij,egi,eg->ej", bmat, stress, weight)                 # (e, 2)
        ke = np.einsum("egia,egij,egjb,eg->eab", bmat, tangent, bmat, weight)  # (e, 2, 2)
        residual = np.zeros(n + 1)
        np.add.at(residual, np.arange(n), fe[:, 0])
        np.add.at(residual, np.arange(1, n + 1), fe[:, 1])
        residual[0] -= p * a
        stiffness = np.zeros((n + 1, n + 1))
        index = np.arange(n)
        stiffness[index, index] += ke[:, 0, 0]
        stiffness[index + 1, index + 1] += ke[:, 1, 1]
        stiffness[index, index + 1] += ke[:, 0, 1]
        stiffness[index + 1, index] += ke[:, 1, 0]
        return residual, stiffness, new_eps_p, new_alpha, plastic

    targets = sorted(args.pressure)
    p_old = 0.0
    results = []
    for target in targets:
        steps = max(1, int(math.ceil((target - p_old) / args.step)))
        for s in range(1, steps + 1):
            p = p_old + (target - p_old) * s / steps
            for _ in range(60):
                residual, stiffness, new_eps_p, new_alpha, plastic = assemble(u, p)
                if np.linalg.norm(residual) <= 1e-10 * p * a:
                    break
                correction = np.linalg.solve(stiffness, residual)
                u -= correction
                if np.linalg.norm(correction) <= 1e-14 * np.linalg.norm(u):
                    residual, stiffness, new_eps_p, new_alpha, plastic = assemble(u, p)
                    break
            else:
                raise SystemExit(f"no convergence at p = {p:g} (beyond the limit load?)")
            eps_p, alpha = new_eps_p, new_alpha
        p_old = target
        if plastic.any():
            outer = rg[plastic].max()
            beyond = rg[(~plastic) & (rg > outer)]
            front = (outer, (beyond.min() - outer) if beyond.size else None)
        else:
            front = None
        results.append((target, u[0], u[-1], front))
    return results


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--inner", type=float, default=1.0)
    parser.add_argument("--outer", type=float, default=2.0)
    parser.add_argument("--young", type=float, default=210000.0)
    parser.add_argument("--poisson", type=float, default=0.3)
    parser.add_argument("--sigy", type=float, default=240.0)
    parser.add_argument("--hard", type=float, default=0.0, help="linear hardening modulus H (default 0)")
    parser.add_argument("--pressure", type=float, nargs="+", default=[100.0, 150.0, 180.0])
    parser.add_argument("--elements", type=int, default=400, help="radial elements (default 400)")
    parser.add_argument("--step", type=float, default=1.0, help="largest pressure increment (default 1)")
    args = parser.parse_args()
    print(f"tube a = {args.inner:g}, b = {args.outer:g}, E = {args.young:g}, nu = {args.poisson:g}, "
          f"sigma_y = {args.sigy:g}, H = {args.hard:g}; {args.elements} elements, plane strain")
    for p, ua, ub, front in solve(args):
        text = f"p = {p:g}: u_r(a) = {ua:.9e}, u_r(b) = {ub:.9e}"
        if front is not None:
            c, spacing = front
            if spacing is None:
                text += ", every point plastic"
            else:
                text += f", plastic front c = {c:.5f} (next point {spacing:.5f} further out)"
        else:
            text += ", elastic"
        print(text)


if __name__ == "__main__":
    main()
