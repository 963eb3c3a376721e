#!/usr/bin/env python3
"""Ironing benchmark (docs/verification/ironing.md): a stiff die with a cylindrical bottom is
pressed into a soft neo-Hookean slab and dragged along it with Coulomb friction.

Writes, for each mesh level h = 1.0, 0.75, 0.5 (and 0.25 with --fine), the gmsh 2.2 mesh
(ironing_h<h>.msh), the frix decks with mortar and with node-to-segment contact
(ironing_<method>_h<h>.dck) and the CalculiX inputs with the same mesh, materials, penalties and
loading, surface-to-surface (ironing_ccx_h<h>.inp) and mortar contact
(ironing_ccxmortar_h<h>.inp). Files are written only when their text changed. Python standard
library only.

Model (sources in docs/verification/ironing.md):
  slab   [0, 9] x [0, 4] x [0, 3], neo-Hookean E = 1, nu = 0.3, bottom fixed;
  die    cylindrical bottom of radius 3 (axis along y, lowest line at x = 2.5, z = 3), 5.2 wide
         in y (0.6 beyond each side of the slab), E = 1000, nu = 0.3; its top moved down by 1.4
         (step 1), then along x by 4.0 with the depth held (step 2);
  contact slab top (slave) / die bottom (master), mu = 0.3, EPSN = EPST = 1e3.
Half model: the symmetry plane y = 2 (u_y = 0 on both bodies), y in [0, 2]; the reaction
forces of the deck are those of the half model (the plot and the checker double them).
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "meshes"))
from gmsh22_writer import write_gmsh22  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))

# geometry (half model), materials, loading, contact
LX, LY, LZ = 9.0, 2.0, 3.0          # slab (y from 0 to the symmetry plane y = 2)
R, XC = 3.0, 2.5                    # die radius, x of its lowest line
DIE_Y0 = -0.6                       # the die reaches 0.6 beyond the slab's free side y = 0
THETA = math.radians(75.0)          # the die's arc spans -75..75 degrees (rise 2.22 > depth 1.4)
DIE_TOP = LZ + 2.6                  # flat top of the die
DEPTH, SLIDE = 1.4, 4.0
E_SLAB, E_DIE, NU = 1.0, 1000.0, 0.3
MU, EPSN, EPST = 0.3, 1.0e3, 1.0e3
# mesh levels h (the slab's element size): divisions of the slab (x, y, z) and of the die (arc, y, z)
LEVELS = {"1.0": ((9, 2, 3), (8, 3, 1)), "0.75": ((12, 3, 4), (11, 4, 1)), "0.5": ((18, 4, 6), (16, 5, 2))}
FINE = {"0.25": ((36, 8, 12), (32, 10, 4))}   # written with --fine only (not committed: 6144 nodes)
PRESS_STEPS, SLIDE_STEPS = 14, 40


def neo_hooke_abaqus(e, nu):
    """C10 = E / (4 (1 + nu)), D1 = 6 (1 - 2 nu) / E (docs/materials.md)."""
    return e / (4.0 * (1.0 + nu)), 6.0 * (1.0 - 2.0 * nu) / e


class Mesh:
    def __init__(self):
        self.nodes = []

    def grid(self, xyz, ni, nj, nk):
        """Nodes of a structured block, xyz(i, j, k) its positions; returns id(i, j, k)."""
        first = len(self.nodes) + 1
        for k in range(nk + 1):
            for j in range(nj + 1):
                for i in range(ni + 1):
                    self.nodes.append(xyz(i, j, k))
        return lambda i, j, k: first + i + (ni + 1) * (j + (nj + 1) * k)


def hexes(nid, ni, nj, nk):
    """HEX8 in VTK / gmsh / C3D8 order (1-4 counter-clockwise from above, 5-8 above them)."""
    out = []
    for k in range(nk):
        for j in range(nj):
            for i in range(ni):
                out.append(((i, j, k), [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                                        nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1),
                                        nid(i, j + 1, k + 1)]))
    return out


def build(divisions):
    (sx, sy, sz), (dx, dy, dz) = divisions
    mesh = Mesh()
    slab = mesh.grid(lambda i, j, k: (LX * i / sx, LY * j / sy, LZ * k / sz), sx, sy, sz)

    def die_xyz(i, j, k):
        t = -THETA + 2.0 * THETA * i / dx
        x, zb = XC + R * math.sin(t), LZ + R - R * math.cos(t)
        return (x, DIE_Y0 + (LY - DIE_Y0) * j / dy, zb + (DIE_TOP - zb) * k / dz)

    die = mesh.grid(die_xyz, dx, dy, dz)
    slab_h, die_h = hexes(slab, sx, sy, sz), hexes(die, dx, dy, dz)
    groups = {"slab_top": [], "slab_bottom": [], "slab_sym": [], "die_bottom": [], "die_top": [],
              "die_sym": []}
    top_ids, bottom_ids = [], []   # element ids (gmsh numbering: slab first, then die)
    for e, ((i, j, k), h) in enumerate(slab_h, start=1):
        if k == sz - 1:
            groups["slab_top"].append([h[4], h[5], h[6], h[7]])
            top_ids.append(e)
        if k == 0:
            groups["slab_bottom"].append([h[0], h[3], h[2], h[1]])
        if j == sy - 1:
            groups["slab_sym"].append([h[3], h[7], h[6], h[2]])
    for e, ((i, j, k), h) in enumerate(die_h, start=1 + len(slab_h)):
        if k == 0:
            groups["die_bottom"].append([h[0], h[3], h[2], h[1]])
            bottom_ids.append(e)
        if k == dz - 1:
            groups["die_top"].append([h[4], h[5], h[6], h[7]])
        if j == dy - 1:
            groups["die_sym"].append([h[3], h[7], h[6], h[2]])
    return mesh, [h for _, h in slab_h], [h for _, h in die_h], groups, top_ids, bottom_ids


def number(v):
    return repr(round(v, 12))


HEADER = """==================================================================
 Ironing (Puso & Laursen 2004, CMAME 193:4891-4913, example "ironing"; setup as documented in
 docs/verification/ironing.md): a stiff die with a cylindrical bottom (R = 3) pressed 1.4 into
 a soft slab 9 x 4 x 3, then dragged 4.0 along x. Half model (symmetry y = 2).
 Slab neo-Hookean (Abaqus/CalculiX form) E = 1, nu = 0.3; die E = 1000, nu = 0.3; total
 Lagrangian HEX8. Contact slab top (slave) / die bottom (master), MU 0.3, EPSN = EPST = 1e3.
 Mesh h = {h}: {size}. Written by inputs/ironing/generate_ironing.py.
 Reaction forces on the die top: columns r1_sum_die_top (Fx), r3_sum_die_top (Fz) of the
 history CSV, half model (x 2 for the whole die).
 units: consistent (none given by the source)
==================================================================
---------------------------------------------------------PROBLEM TYP
PROBLEMTYP   Structure
--------------------------------------------------------------STATIC
KINTYP       Tot_Lagr
MAXITER      30
TOLRESID     1.0e-8
TOLDISP      1.0e-8
MAXCUT       6
SOLVER       Auto
---------------------------------------------------------LOAD CURVES
CURVE 1 POINTS 0.0 0.0  1.0 1.0  2.0 1.0
CURVE 2 POINTS 0.0 0.0  1.0 0.0  2.0 1.0
-----------------------------------------------------------MATERIALS
MAT 1 MAT_Struct_NeoHookeAbaqus C10 {c10s} D1 {d1s}     // slab: E = 1, nu = 0.3
MAT 2 MAT_Struct_NeoHookeAbaqus C10 {c10d} D1 {d1d}     // die: E = 1000, nu = 0.3
------------------------------------------------------------MESH FILE
FILE {mesh}
--------------------------------------------------STRUCTURE ELEMENTS
SET slab SOLID HEX8 MAT 1
SET die SOLID HEX8 MAT 2
------------------------------------------------DIRICHLET CONDITIONS
SET slab_bottom DOF 1 1 1 VAL 0.0 0.0 0.0
SET slab_sym DOF 0 1 0 VAL 0.0 0.0 0.0
SET die_sym DOF 0 1 0 VAL 0.0 0.0 0.0
SET die_top DOF 1 1 1 VAL {slide} 0.0 {depth} CURVE 2 0 1
--------------------------------------------------CONTACT CONDITIONS
PAIR 1 SLAVE slab_top MASTER die_bottom EPSN {epsn} EPST {epst} MU {mu} {pair}
---------------------------------------------------------------STEPS
STEP 1 NUMSTEP {press} CONTROL Load
STEP 2 NUMSTEP {slide_steps} CONTROL Load
-------------------------------------------------------------RESULTS
VTK {vtk}  LISTING No
HISTORY SET die_top DOF 1 KIND R SUM
HISTORY SET die_top DOF 3 KIND R SUM
HISTORY CONTACT 1 NORMAL
-----------------------------------------------------------------END
"""

METHODS = {"mortar": "DISCRETIZATION Mortar", "nts": "NORMALS Smoothed"}


def deck(h, size, method):
    c10s, d1s = neo_hooke_abaqus(E_SLAB, NU)
    c10d, d1d = neo_hooke_abaqus(E_DIE, NU)
    return HEADER.format(h=h, size=size, c10s=number(c10s), d1s=number(d1s), c10d=number(c10d),
                         d1d=number(d1d), mesh="ironing_h%s.msh" % h, slide=SLIDE, depth=-DEPTH,
                         epsn=EPSN, epst=EPST, mu=MU, pair=METHODS[method], press=PRESS_STEPS,
                         slide_steps=SLIDE_STEPS, vtk="No")


def ccx_input(mesh, slab, die, groups, top_ids, bottom_ids, contact):
    """The same model for CalculiX 2.20 (C3D8, *HYPERELASTIC NEO HOOKE, contact `contact`
    (SURFACE TO SURFACE or MORTAR) with the same slopes (*SURFACE BEHAVIOR LINEAR: EPSN,
    *FRICTION stick slope: EPST), the same two steps)."""
    c10s, d1s = neo_hooke_abaqus(E_SLAB, NU)
    c10d, d1d = neo_hooke_abaqus(E_DIE, NU)
    out = ["*HEADING", "Ironing, written by inputs/ironing/generate_ironing.py", "*NODE"]
    out += ["%d, %s, %s, %s" % (i, number(x), number(y), number(z)) for i, (x, y, z) in enumerate(mesh.nodes, 1)]
    out.append("*ELEMENT, TYPE=C3D8, ELSET=SLAB")
    out += ["%d, %s" % (e, ", ".join(map(str, h))) for e, h in enumerate(slab, 1)]
    out.append("*ELEMENT, TYPE=C3D8, ELSET=DIE")
    out += ["%d, %s" % (e, ", ".join(map(str, h))) for e, h in enumerate(die, 1 + len(slab))]
    for name in ("slab_bottom", "slab_sym", "die_sym", "die_top"):
        ids = sorted({n for f in groups[name] for n in f})
        out.append("*NSET, NSET=%s" % name.upper())
        out += [", ".join(map(str, ids[i:i + 12])) for i in range(0, len(ids), 12)]
    out.append("*SURFACE, NAME=SLABTOP")          # C3D8 face S2: nodes 5-8-7-6 (top)
    out += ["%d, S2" % e for e in top_ids]
    out.append("*SURFACE, NAME=DIEBOTTOM")        # C3D8 face S1: nodes 1-2-3-4 (bottom)
    out += ["%d, S1" % e for e in bottom_ids]
    out += ["*MATERIAL, NAME=SOFT", "*HYPERELASTIC, NEO HOOKE", "%s, %s" % (number(c10s), number(d1s)),
            "*MATERIAL, NAME=STIFF", "*HYPERELASTIC, NEO HOOKE", "%s, %s" % (number(c10d), number(d1d)),
            "*SOLID SECTION, ELSET=SLAB, MATERIAL=SOFT", "*SOLID SECTION, ELSET=DIE, MATERIAL=STIFF",
            "*SURFACE INTERACTION, NAME=SI", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR",
            "%g" % EPSN, "*FRICTION", "%g, %g" % (MU, EPST),
            "*CONTACT PAIR, INTERACTION=SI, TYPE=%s" % contact, "SLABTOP, DIEBOTTOM",
            "*BOUNDARY", "SLAB_BOTTOM, 1, 3, 0.0", "SLAB_SYM, 2, 2, 0.0", "DIE_SYM, 2, 2, 0.0",
            "DIE_TOP, 1, 2, 0.0"]
    steps = [("DIE_TOP, 3, 3, %g" % -DEPTH, PRESS_STEPS), ("DIE_TOP, 1, 1, %g" % SLIDE, SLIDE_STEPS)]
    for bc, n in steps:
        out += ["*STEP, NLGEOM, INC=10000", "*STATIC", "%g, 1.0, 1e-6, %g" % (1.0 / n, 1.0 / n),
                "*BOUNDARY", bc, "*NODE PRINT, NSET=DIE_TOP, TOTALS=ONLY", "RF", "*END STEP"]
    return "\n".join(out) + "\n"


def write(name, text):
    path = os.path.join(HERE, name)
    if not os.path.exists(path) or open(path).read() != text:
        with open(path, "w") as f:
            f.write(text)


def main():
    levels = dict(LEVELS, **FINE) if "--fine" in sys.argv[1:] else LEVELS
    for h, divisions in levels.items():
        mesh, slab, die, groups, top_ids, bottom_ids = build(divisions)
        size = "slab %d + die %d HEX8, %d nodes" % (len(slab), len(die), len(mesh.nodes))
        write_gmsh22(os.path.join(HERE, "ironing_h%s.msh" % h), "written by inputs/ironing/generate_ironing.py, h %s" % h,
                     mesh.nodes, [("slab", slab), ("die", die)], groups, [], number)
        for method in METHODS:
            write("ironing_%s_h%s.dck" % (method, h), deck(h, size, method))
        for contact, name in (("SURFACE TO SURFACE", "ccx"), ("MORTAR", "ccxmortar")):
            write("ironing_%s_h%s.inp" % (name, h), ccx_input(mesh, slab, die, groups, top_ids, bottom_ids, contact))
        print("h %s: %s" % (h, size))


if __name__ == "__main__":
    main()
