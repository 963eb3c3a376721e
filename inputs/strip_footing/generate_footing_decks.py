#!/usr/bin/env python3
"""Meshes and decks of the strip-footing benchmark (docs/verification/strip_footing.md).

A rigid strip footing of half-width b = 1 m pressed into a weightless c-phi soil: the limit
pressure q_u = c N_c against Prandtl's closed form N_c = (N_q - 1) cot(phi), N_q = exp(pi
tan(phi)) tan^2(45 + phi/2) (N_c = 2 + pi at phi = 0). Plane strain as a slab one element thick
(u_y = 0 on both faces); half the footing by symmetry (x = 0).

The soil block is [0, L] x [0, t] x [-H, 0] with L = 12 m, H = 6 m (wider and deeper than the
Prandtl mechanism, which at phi = 30 degrees reaches 8.6 m beyond the footing's edge and about
4 m down), x across the footing, z up, the footing on z = 0, 0 <= x <= b. Columns:
`n_footing` equal elements under the footing, then `n_side` growing geometrically to x = L;
rows: `n_depth` growing geometrically from the surface down; the smallest elements (b /
n_footing) at the footing's edge, where the mechanism fans out.

Soil: MAT_3DMohrCoulomb, E = 1e5 kPa, nu = 0.3, c = 10 kPa, associated flow (psi = phi);
HEX8 with EAS 3 (docs/verification/strip_footing.md says why not EAS 9). Load: the footing's
nodes pushed down by a prescribed displacement (rigid footing), smooth (u_x free) or rough
(u_x = 0). The total footing reaction and the bottom's (equilibrium) are HISTORY columns.

    generate_footing_decks.py [--out DIR]      (default: this script's folder)

Python standard library only. Writes footing_coarse.inp, footing_fine.inp, footing_finer.inp and the decks
footing_phi<phi>_<smooth|rough>[_fine].dck, footing_phi<phi>_rough_finer.dck.
"""
import argparse
import math
import pathlib

B_HALF, LENGTH, DEPTH, THICKNESS = 1.0, 12.0, 6.0, 0.1
COHESION, YOUNG, POISSON = 10.0, 1.0e5, 0.3
# n_footing, n_side, n_depth; the finer mesh for the rough footing, whose corner converges slower
MESHES = {"coarse": (8, 16, 16), "fine": (16, 24, 24), "finer": (32, 32, 32)}
# friction angle: (prescribed settlement in m, increments); the settlement is several times
# the one at which the pressure levels off (measured on the coarse mesh)
LOADING = {0: (0.02, 20), 20: (0.05, 40), 30: (0.05, 40)}


def bearing_factor(phi_degrees):
    """Prandtl's N_c of a weightless soil (Prandtl 1920; Terzaghi 1943)."""
    if phi_degrees == 0:
        return 2.0 + math.pi
    phi = math.radians(phi_degrees)
    n_q = math.exp(math.pi * math.tan(phi)) * math.tan(math.pi / 4 + phi / 2) ** 2
    return (n_q - 1.0) / math.tan(phi)


def graded(start, length, n, first):
    """n intervals from start over length, the first of size `first`, growing geometrically."""
    if n * first >= length:
        return [start + length * k / n for k in range(n + 1)]
    low, high = 1.0, 2.0
    while first * (high ** n - 1) / (high - 1) < length:
        high *= 2
    for _ in range(200):  # bisection for the ratio r: first (r^n - 1) / (r - 1) = length
        r = 0.5 * (low + high)
        if first * (r ** n - 1) / (r - 1) < length:
            low = r
        else:
            high = r
    points, size, x = [start], first, start
    for _ in range(n):
        x += size
        points.append(x)
        size *= 0.5 * (low + high)
    points[-1] = start + length
    return points


def write_mesh(path, n_footing, n_side, n_depth):
    """The block as an Abaqus/CalculiX input file: C3D8 nodes and elements, *ELSET soil."""
    h = B_HALF / n_footing
    xs = [B_HALF * k / n_footing for k in range(n_footing)] + graded(B_HALF, LENGTH - B_HALF, n_side, h)
    zs = [-z for z in graded(0.0, DEPTH, n_depth, h)][::-1]  # from -DEPTH up to 0
    ys = [0.0, THICKNESS]
    nx, nz = len(xs), len(zs)

    def node(i, j, k):  # i along x, j along y, k along z; ids from 1
        return 1 + i + nx * (k + nz * j)

    lines = ["** strip footing, generate_footing_decks.py: %d x %d x %d elements under the footing, "
             "beside it, in depth" % (n_footing, n_side, n_depth), "*NODE"]
    for j, y in enumerate(ys):
        for k, z in enumerate(zs):
            for i, x in enumerate(xs):
                lines.append("%d, %.15g, %.15g, %.15g" % (node(i, j, k), x, y, z))
    lines.append("*ELEMENT, TYPE=C3D8, ELSET=soil")
    e = 0
    for k in range(nz - 1):
        for i in range(nx - 1):
            e += 1
            # VTK / C3D8 order: the face z = z_k counter-clockwise seen from above, then z_k+1
            bottom = [node(i, 0, k), node(i + 1, 0, k), node(i + 1, 1, k), node(i, 1, k)]
            top = [node(i, 0, k + 1), node(i + 1, 0, k + 1), node(i + 1, 1, k + 1), node(i, 1, k + 1)]
            lines.append("%d, %s" % (e, ", ".join(str(n) for n in bottom + top)))
    pathlib.Path(path).write_text("\n".join(lines) + "\n")
    return e


def deck_text(phi, rough, mesh, n_elements):
    settlement, increments = LOADING[phi]
    n_c = bearing_factor(phi)
    footing_dofs = "1 0 1" if rough else "0 0 1"
    title = "rough" if rough else "smooth"
    return f"""==================================================================
 Strip footing on a weightless c-phi soil, phi = {phi} degrees, {title} footing, {mesh} mesh
 ({n_elements} HEX8 EAS 3; docs/verification/strip_footing.md; written by
 generate_footing_decks.py). Plane strain as a slab one element thick (u_y = 0 on both
 faces), half the footing by symmetry (x = 0): footing half-width b = {B_HALF:g} m, soil block
 {LENGTH:g} m wide and {DEPTH:g} m deep, slab thickness t = {THICKNESS:g} m.
 Mohr-Coulomb, c = {COHESION:g} kPa, phi = psi = {phi} degrees (associated flow), E = {YOUNG:g} kPa,
 nu = {POISSON:g}. The footing's nodes are pushed down {settlement:g} m in {increments} increments
 ({'u_x = 0: rough' if rough else 'u_x free: smooth'}).
 Closed form (Prandtl): q_u = c N_c, N_c = {n_c:.3f}, q_u = {COHESION * n_c:.2f} kPa; the footing's
 limit pressure is -r3_sum_footing / (b t).
 units: kN, m, kPa
==================================================================
---------------------------------------------------------PROBLEM TYP
PROBLEMTYP   Structure
--------------------------------------------------------------STATIC
KINTYP       Geo_Lin
MAXITER      30
MAXCUT       8
TOLRESID     1.0e-8
TOLDISP      1.0e-8
-----------------------------------------------------------MATERIALS
MAT 1 MAT_3DMohrCoulomb YOUNG {YOUNG:g} NUE {POISSON:g} COHESION {COHESION:g} PHI {phi:.1f} PSI {phi:.1f}
------------------------------------------------------------MESH FILE
FILE footing_{mesh}.inp
--------------------------------------------------STRUCTURE ELEMENTS
SET soil SOLID HEX8 MAT 1 EAS 3
------------------------------------------------------------NODE SETS
SET footing   BOX 0 -1 0  {B_HALF:g} 1 0
SET symmetry  BOX 0 -1 -{DEPTH + 1:g}  0 1 1
SET far       BOX {LENGTH:g} -1 -{DEPTH + 1:g}  {LENGTH:g} 1 1
SET bottom    BOX -1 -1 -{DEPTH:g}  {LENGTH + 1:g} 1 -{DEPTH:g}
SET front     BOX -1 0 -{DEPTH + 1:g}  {LENGTH + 1:g} 0 1
SET back      BOX -1 {THICKNESS:g} -{DEPTH + 1:g}  {LENGTH + 1:g} {THICKNESS:g} 1
------------------------------------------------DIRICHLET CONDITIONS
SET symmetry DOF 1 0 0 VAL 0 0 0
SET far      DOF 1 0 0 VAL 0 0 0
SET bottom   DOF 1 0 1 VAL 0 0 0
SET front    DOF 0 1 0 VAL 0 0 0
SET back     DOF 0 1 0 VAL 0 0 0
SET footing  DOF {footing_dofs} VAL 0 0 -{settlement:g}
---------------------------------------------------------------STEPS
STEP 1 NUMSTEP {increments} CONTROL Displacement
-------------------------------------------------------------RESULTS
VTK Yes LISTING Yes EVERY {increments}
HISTORY SET footing DOF 3 KIND R SUM
HISTORY SET bottom DOF 3 KIND R SUM
HISTORY SET footing DOF 3 KIND U MEAN
-----------------------------------------------------------------END
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default=str(pathlib.Path(__file__).resolve().parent))
    out = pathlib.Path(parser.parse_args().out)
    out.mkdir(parents=True, exist_ok=True)
    for mesh, divisions in MESHES.items():
        n_elements = write_mesh(out / f"footing_{mesh}.inp", *divisions)
        suffix = "" if mesh == "coarse" else "_" + mesh
        for phi in LOADING:
            for rough in ((True,) if mesh == "finer" else (False, True)):
                name = f"footing_phi{phi}_{'rough' if rough else 'smooth'}{suffix}.dck"
                (out / name).write_text(deck_text(phi, rough, mesh, n_elements))


if __name__ == "__main__":
    main()
