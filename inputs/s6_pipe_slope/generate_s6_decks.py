#!/usr/bin/python3
"""Write the S6(b) meshes and decks: the seed's pipe crossing a slope (docs/benchmarks.md S6 (b),
docs/verification/s6.md; seed 6.2.2).

usage: generate_s6_decks.py [--help]

Run from anywhere; writes s6_coarse.msh, s6_fine.msh and the decks beside this script. Only the
standard library is used (the meshes are written directly in gmsh's 2.2 ASCII format, as
inputs/meshes/ring_mesh.py does: see "Why no .geo" below).

Units MN, m, MPa. Coordinates as S6(a): pipe axis along z (0 ... 13), y vertical up, the
symmetry plane x = 0 (half model x >= 0).

Geometry (the seed gives the loads by length along the axis, not the slope nor the soil
block; the reconstruction, also in every deck's header and in s6.md):
- Pipe: outer radius b = 0.1625, inner 0.15625 (wall 0.00625), z from 0 to 13.
- Soil cover 1.0 above the crown (a usual minimum cover of pipelines): ground surface
  y_top = b + 1.0 = 1.1625 over 0 <= z <= 5.
- Soil block 3.0 wide from the axis (about 10 D; far side x = 3 on rollers) and 2.0 below the
  invert (bottom y = -2.1625, fixed).
- The slope: the soil's end face is the inclined plane through the crest line (y = y_top,
  z = 5) and the toe line (y = -a_box = -0.3, z = 6.5), a 1.4625 m drop over 1.5 m
  (44 degrees, about 1:1, a cut slope); the pipe (invert y = -0.1625) leaves the soil through
  it and is in the open, 0.1375 above the ground at the toe level, from there to its clamped end
  at z = 13. Below the toe the soil ends in a vertical face at z = 6.5 held axially (u_z = 0:
  the ground continuing beyond the toe).
- The toe lies at y = -a_box, the lower edge of the box around the cavity, a horizontal grid
  line of the cross-section, so that the slope face is one plane in a structured mesh.

Mesh (structured hexahedra, HEX8):
- Cross-section of the soil: a ring of cells between the cavity (radius b, 12 x refine
  facets over the half circumference, the pipe's) and the square box |y| <= a_box,
  0 <= x <= a_box (a_box = 0.3), and a tensor grid outside the box (x: nc to a_box, nf to 3.0
  graded; y: nb below the box, 2 nc in it, nt above it).
- Along z every cross-section node (x, y) carries N + 1 nodes at z = zeta_k z_end(y),
  zeta_k = k / N, z_end(y) the soil's end (5 + 1.5 (y_top - y)/(y_top + a_box) above the toe,
  6.5 below): the layers fan out from z = 0 to the slope face. z_end is linear in y above and
  below the toe line, so every layer interface and the slope face are planes and no element
  degenerates at the crest (a separate slope segment of straight layers would have zero
  thickness at the crest line).
- Pipe: 12 x refine elements around the half circumference x 1 through the wall x 26 x refine
  along z (0.5 / refine long).
- Coarse (refine = 1): soil 54 x 6 = 324, pipe 12 x 26 = 312, in all 636 HEX8 (the seed: 622).
  Fine (refine = 2): soil 216 x 12 = 2592, pipe 24 x 52 = 1248, in all 3840 HEX8.

Why no .geo: gmsh's Extrude copies the source mesh layer by layer and cannot fan the layers out
to an inclined end plane; the mesh is a direct map of a structured grid, written here with the
named physical groups the decks use (the gmsh file format, no gmsh run needed).

Physical groups (frix reads a volume as an element set and a node set, a surface as a surface
and a node set, a point as a node set of one node):
  3D soil, pipe
  2D soil_sym (x = 0), soil_far (x = 3), soil_bottom, soil_top (y = y_top, 0 <= z <= 5),
     surcharge (the part of soil_top with x <= a_box: the strip 0.6 wide over the pipe),
     soil_z0 (z = 0), soil_slope (the inclined face), soil_toe_face (z = 6.5 below the toe),
     cavity (the soil's face of the interface), pipe_outer, pipe_outer_soil (the faces of
     pipe_outer whose nodes all lie inside the soil, z <= z_end(y): the contact slave;
     coarse: z <= 6.0), pipe_inner, pipe_sym (x = 0, crown and
     invert edges of the wall), pipe_z0, pipe_z13
  0D crown_z2.5, invert_z2.5, springline_z2.5 (pipe outer surface, z = 2.5),
     crown_z6, invert_z6 (z = 6.0, where the crown is about to leave the slope face, at
     z = 6.026), crown_z9.5, invert_z9.5, springline_z9.5 (in the open span),
     ground_z2.5 (soil surface above the crown at z = 2.5)

Loads (every deck): step 1 the soil's weight (DENS 0.018 with GRAVITY 0 -1 0: the body force
is DENS x g = 0.018 MN/m^3, the unit weight, downward; CURVE 1 ramps it to 1 in step 1 and holds
it); step 2 the internal pressure 9.0 on pipe_inner (0 <= z <= 13) and the surcharge on
`surcharge` ramped to 1 x in 7 increments (the seed's 7 load steps); step 3 both raised to 10 x
(CURVE 2), the soil's weight held at 1 x (it is a state of the ground, not a load the
pipeline's operation raises). The surcharge: the seed's "1000 N/m" read as a line load of
1e-3 MN per metre of pipe spread over the strip |x| <= a_box (0.6 wide, about 2 D) above the
pipe over 0 <= z <= 5: q = 1e-3/0.6 = 1.6667e-3 MPa.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "meshes"))
from gmsh22_writer import write_gmsh22  # noqa: E402
from ring_mesh import radii  # noqa: E402  (n + 1 points from a to b, last / first size = grading)

HERE = os.path.dirname(os.path.abspath(__file__))

B = 0.1625            # pipe outer radius
A_IN = 0.15625        # pipe inner radius
COVER = 1.0           # soil above the crown
BELOW = 2.0           # soil below the invert
WIDTH = 3.0           # soil block from the axis
A_BOX = 0.3           # half size of the box around the cavity; the toe at y = -A_BOX
Y_TOP = B + COVER
Y_BOT = -(B + BELOW)
Z_CREST, Z_TOE = 5.0, 6.5
L_PIPE = 13.0
EPS = 1e-9


def z_end(y):
    """The soil's end along z at height y: the slope plane above the toe line, 6.5 below."""
    if y >= -A_BOX - EPS:
        return Z_CREST + (Z_TOE - Z_CREST) * (Y_TOP - y) / (Y_TOP + A_BOX)
    return Z_TOE


class Mesh:
    """Nodes (merged by position key), hexahedra of named volumes."""

    def __init__(self):
        self.nodes = []           # (x, y, z)
        self.index = {}

    def node(self, x, y, z, body):
        key = (body, round(x, 9), round(y, 9), round(z, 9))
        if key not in self.index:
            self.nodes.append((x, y, z))
            self.index[key] = len(self.nodes)
        return self.index[key]


def box_point(j, nc):
    """The j-th point (j = 0 ... 4 nc) on the box boundary from (0, -a) over (a, -a), (a, a) to
    (0, a), nc segments per side half, matching the cavity's angles -90 + 45 j / nc degrees."""
    a = A_BOX
    side, k = divmod(j, nc)
    s = k / nc
    corners = [(0.0, -a), (a, -a), (a, 0.0), (a, a), (0.0, a)]
    if side == 4:
        return corners[4]
    (x0, y0), (x1, y1) = corners[side], corners[side + 1]
    return x0 + s * (x1 - x0), y0 + s * (y1 - y0)


def direction(deg):
    q = deg / 90.0
    if q == round(q):
        return [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)][int(round(q)) % 4]
    return math.cos(math.radians(deg)), math.sin(math.radians(deg))


def soil_section(refine):
    """Quadrilaterals of the soil cross-section, each a list of 4 (x, y) counter-clockwise."""
    nc, nr, nt, nb, nf = 3 * refine, 1 * refine, 2 * refine, 2 * refine, 3 * refine
    quads = []
    # ring between the cavity and the box: 4 nc cells around, nr radially
    for j in range(4 * nc):
        inner = [tuple(B * c for c in direction(-90.0 + 45.0 * jj / nc)) for jj in (j, j + 1)]
        outer = [box_point(jj, nc) for jj in (j, j + 1)]
        rings = [[(p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])) for p, q in zip(inner, outer)]
                 for s in [i / nr for i in range(nr + 1)]]
        for i in range(nr):
            # counter-clockwise in (x, y): angle grows with j, radius with i
            quads.append([rings[i][0], rings[i + 1][0], rings[i + 1][1], rings[i][1]])
    xs = radii(0.0, A_BOX, nc, 1.0) + radii(A_BOX, WIDTH, nf, 3.0 ** (1.0 / refine) if nf > 1 else 1)[1:]
    ys = (radii(Y_BOT, -A_BOX, nb, (1 / 3.0) ** (1.0 / refine)) + radii(-A_BOX, A_BOX, 2 * nc, 1.0)[1:]
          + radii(A_BOX, Y_TOP, nt, 1.0)[1:])
    for i in range(len(xs) - 1):
        for j in range(len(ys) - 1):
            xc, yc = 0.5 * (xs[i] + xs[i + 1]), 0.5 * (ys[j] + ys[j + 1])
            if xc < A_BOX and abs(yc) < A_BOX:
                continue      # the box: the ring fills it
            quads.append([(xs[i], ys[j]), (xs[i + 1], ys[j]), (xs[i + 1], ys[j + 1]), (xs[i], ys[j + 1])])
    return quads


def pipe_section(refine):
    n = 12 * refine
    quads = []
    for j in range(n):
        d0, d1 = direction(-90.0 + 180.0 * j / n), direction(-90.0 + 180.0 * (j + 1) / n)
        quads.append([(A_IN * d0[0], A_IN * d0[1]), (B * d0[0], B * d0[1]),
                      (B * d1[0], B * d1[1]), (A_IN * d1[0], A_IN * d1[1])])
    return quads


# local faces of a HEX8, outward (docs/deck-format.md SURFACES)
HEX_FACES = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (0, 4, 7, 3)]


def extrude(mesh, quads, body, zfun, nlayers):
    hexes = []
    for q in quads:
        for k in range(nlayers):
            bottom = [mesh.node(x, y, zfun(x, y, k), body) for x, y in q]
            top = [mesh.node(x, y, zfun(x, y, k + 1), body) for x, y in q]
            hexes.append(bottom + top)
    return hexes


def boundary_faces(hexes):
    count = {}
    for h in hexes:
        for f in HEX_FACES:
            face = tuple(h[i] for i in f)
            key = tuple(sorted(face))
            count.setdefault(key, []).append(face)
    return [v[0] for v in count.values() if len(v) == 1]


def classify_soil(mesh, faces):
    groups = {n: [] for n in ("soil_sym", "soil_far", "soil_bottom", "soil_top", "surcharge",
                              "soil_z0", "soil_slope", "soil_toe_face", "cavity")}
    for f in faces:
        p = [mesh.nodes[n - 1] for n in f]
        xs, ys, zs = [q[0] for q in p], [q[1] for q in p], [q[2] for q in p]
        if max(xs) < EPS:
            groups["soil_sym"].append(f)
        elif min(xs) > WIDTH - EPS:
            groups["soil_far"].append(f)
        elif max(ys) < Y_BOT + EPS:
            groups["soil_bottom"].append(f)
        elif min(ys) > Y_TOP - EPS:
            groups["soil_top"].append(f)
            if max(xs) < A_BOX + EPS:
                groups["surcharge"].append(f)
        elif max(zs) < EPS:
            groups["soil_z0"].append(f)
        elif all(abs(math.hypot(q[0], q[1]) - B) < 1e-7 for q in p):
            groups["cavity"].append(f)
        elif max(ys) < -A_BOX + EPS:
            groups["soil_toe_face"].append(f)
        else:
            groups["soil_slope"].append(f)
    return groups


def classify_pipe(mesh, faces):
    groups = {n: [] for n in ("pipe_inner", "pipe_outer", "pipe_outer_soil", "pipe_sym", "pipe_z0",
                              "pipe_z13")}
    for f in faces:
        p = [mesh.nodes[n - 1] for n in f]
        xs, zs = [q[0] for q in p], [q[2] for q in p]
        r = [math.hypot(q[0], q[1]) for q in p]
        if max(zs) < EPS:
            groups["pipe_z0"].append(f)
        elif min(zs) > L_PIPE - EPS:
            groups["pipe_z13"].append(f)
        elif max(xs) < EPS:
            groups["pipe_sym"].append(f)
        elif all(abs(v - A_IN) < 1e-7 for v in r):
            groups["pipe_inner"].append(f)
        elif all(abs(v - B) < 1e-7 for v in r):
            groups["pipe_outer"].append(f)
            if all(q[2] <= z_end(q[1]) + EPS for q in p):     # every node inside the soil
                groups["pipe_outer_soil"].append(f)
        else:
            raise RuntimeError("unclassified pipe face %s" % (p,))
    return groups


POINTS = [  # name, body, (x, y, z)
    ("crown_z2.5", "pipe", (0.0, B, 2.5)), ("invert_z2.5", "pipe", (0.0, -B, 2.5)),
    ("springline_z2.5", "pipe", (B, 0.0, 2.5)),
    ("crown_z6", "pipe", (0.0, B, 6.0)), ("invert_z6", "pipe", (0.0, -B, 6.0)),
    ("crown_z9.5", "pipe", (0.0, B, 9.5)), ("invert_z9.5", "pipe", (0.0, -B, 9.5)),
    ("springline_z9.5", "pipe", (B, 0.0, 9.5)),
    ("ground_z2.5", "soil", (0.0, Y_TOP, 2.5)),
]


def number(v):
    return repr(v + 0.0) if v != 0.0 else "0"


def build(refine):
    mesh = Mesh()
    n_soil = 6 * refine
    soil = extrude(mesh, soil_section(refine), "soil", lambda x, y, k: z_end(y) * k / n_soil, n_soil)
    n_pipe = 26 * refine
    pipe = extrude(mesh, pipe_section(refine), "pipe", lambda x, y, k: L_PIPE * k / n_pipe, n_pipe)
    surfaces = classify_soil(mesh, boundary_faces(soil))
    surfaces.update(classify_pipe(mesh, boundary_faces(pipe)))
    points = []
    for name, body, (x, y, z) in POINTS:
        key = (body, round(x, 9), round(y, 9), round(z, 9))
        points.append((name, mesh.index[key]))
    return mesh, soil, pipe, surfaces, points


def write_mesh(path, refine):
    """Write the mesh (only if its text changed: a run reading it meanwhile is not disturbed)."""
    mesh, soil, pipe, surfaces, points = build(refine)
    write_gmsh22(path, "written by inputs/s6_pipe_slope/generate_s6_decks.py, refine %d" % refine, mesh.nodes,
                 [("soil", soil), ("pipe", pipe)], surfaces, points, number)
    return len(mesh.nodes), len(soil), len(pipe)


def soil_volume(refine):
    """Exact soil volume of the mesh: each cell's z_end is linear in y over the cell, so the
    column volume is the cell's area times z_end at its centroid (used by the tests' weight
    check: the soil's weight is 0.018 x this)."""
    total = 0.0
    for q in soil_section(refine):
        area = cx = cy = 0.0
        for (x0, y0), (x1, y1) in zip(q, q[1:] + q[:1]):
            c = x0 * y1 - x1 * y0
            area += c
            cx += (x0 + x1) * c
            cy += (y0 + y1) * c
        area *= 0.5
        cy /= 6.0 * area
        total += area * z_end(cy)
    return total


HEADER = """==================================================================
 S6(b): the seed's pipe crossing a slope (seed 6.2.2; docs/verification/s6.md). {title}
 Units MN, m, MPa. Pipe axis along z (0 ... 13), y vertical up, half model x >= 0 (symmetry
 plane x = 0 through the axis). Mesh {mesh}: {counts}.
 Reconstruction (the seed gives no slope nor soil block): cover 1.0 above the crown (a usual
 minimum cover), soil block 3.0 wide from the axis (about 10 D), 2.0 below the invert; ground
 y = 1.1625 over 0 <= z <= 5; the soil's end face is the slope plane from the crest (y = 1.1625,
 z = 5) to the toe (y = -0.3, z = 6.5), 44 degrees, the pipe leaving the soil through it; below
 the toe a vertical face at z = 6.5 held axially (the ground continues). Pipe in the open from
 the slope to z = 13, clamped there.
 Pipe: D = 0.325, wall 0.00625, E = 205000, nu = 0.3, von Mises, sigma_y = 420, H = 75000
 (isotropic), HEX8 EAS 9 (S6(a): 0.02 % from Lame, EAS 3 0.4 % stiff). Soil: E = 50, nu = 0.3,
 linear elastic, unit weight 0.018 MN/m^3 (DENS 0.018 with GRAVITY 0 -1 0), HEX8 EAS 9.
 Supports: u_x = 0 on x = 0 (soil and pipe) and on the far side x = 3; soil bottom fixed;
 u_z = 0 at z = 0 (soil and pipe: the buried line continues) and on the face below the toe;
 pipe clamped at z = 13.
 Contact pipe_outer_soil (slave: the pipe's outer faces inside the soil) / cavity, zero gap:
 {contact}
 Step 1: soil weight (geostatic, pipe in place, no pressure, no surcharge).
 Step 2: internal pressure 9.0 on the whole inner surface and the surcharge 1e-3 MN/m
 (the seed's 1000 N/m) as q = 1.6667e-3 MPa on the strip x <= 0.3 (0.6 wide) over
 0 <= z <= 5, both to 1 x in 7 increments. Step 3: both to 10 x in {n3} increments, the soil's
 weight held at 1 x. Load factor f(t) = CURVE 2.
 Displacements from step 2 on are reported from the end of the geostatic step
 (RESET_DISPLACEMENT; the VTK and HDF5 files also hold the total displacement).
 Generated by inputs/s6_pipe_slope/generate_s6_decks.py
==================================================================
"""

BODY = """---------------------------------------------------------PROBLEM TYP
PROBLEMTYP   Structure
--------------------------------------------------------------STATIC
KINTYP       Geo_Lin
MAXITER      30
TOLRESID     1.0e-8
TOLDISP      1.0e-8
MAXCUT       6
EXTRAPOLATION Linear                    // each increment starts from the last one's rate
SOLVER       Auto
---------------------------------------------------------LOAD CURVES
CURVE 1 POINTS 0.0 0.0  1.0 1.0  3.0 1.0              // soil weight: on in step 1, held
CURVE 2 POINTS 0.0 0.0  1.0 0.0  2.0 1.0  3.0 10.0    // load factor f: 1 x at t = 2, 10 x at t = 3
-----------------------------------------------------------MATERIALS
MAT 1 MAT_Struct_LinearElastic YOUNG 50.0 NUE 0.3 DENS 0.018                 // soil
MAT 2 MAT_3DMisesPlastic YOUNG 205000.0 NUE 0.3 SIGY 420.0 HARD 75000.0      // steel pipe
-----------------------------------------------------------MESH FILE
FILE {mesh}
--------------------------------------------------STRUCTURE ELEMENTS
SET soil SOLID HEX8 EAS 9 MAT 1
SET pipe SOLID HEX8 EAS 9 MAT 2
------------------------------------------------DIRICHLET CONDITIONS
SET soil_sym      DOF 1 0 0 VAL 0.0 0.0 0.0     // symmetry plane x = 0
SET pipe_sym      DOF 1 0 0 VAL 0.0 0.0 0.0
SET soil_far      DOF 1 0 0 VAL 0.0 0.0 0.0     // far side x = 3 on rollers
SET soil_bottom   DOF 1 1 1 VAL 0.0 0.0 0.0     // bottom fixed
SET soil_z0       DOF 0 0 1 VAL 0.0 0.0 0.0     // z = 0: the buried line continues
SET pipe_z0       DOF 0 0 1 VAL 0.0 0.0 0.0
SET soil_toe_face DOF 0 0 1 VAL 0.0 0.0 0.0     // below the toe: the ground continues
SET pipe_z13      DOF 1 1 1 VAL 0.0 0.0 0.0     // clamped end
--------------------------------------------------NEUMANN CONDITIONS
SURF pipe_inner PRESSURE 9.0 CURVE 2            // internal pressure, 0 <= z <= 13
SURF surcharge  PRESSURE 1.6667e-3 CURVE 2      // 1e-3 MN/m over the 0.6 wide strip
------------------------------------------------------------BODY FORCE
SET soil GRAVITY 0.0 -1.0 0.0 CURVE 1           // DENS x g = 0.018 MN/m^3 downward
--------------------------------------------------CONTACT CONDITIONS
PAIR 1 SLAVE pipe_outer_soil MASTER cavity {pair}
---------------------------------------------------------------STEPS
STEP 1 NUMSTEP 1 CONTROL Load                   // geostatic: the soil's weight
STEP 2 NUMSTEP 7 CONTROL Load RESET_DISPLACEMENT   // pressure and surcharge to 1 x (seed: 7 steps);
                                                // displacements reported from the end of step 1
{step3}-------------------------------------------------------------RESULTS
{results}
HISTORY SET crown_z2.5 DOF 2 KIND U
HISTORY SET invert_z2.5 DOF 2 KIND U
HISTORY SET springline_z2.5 DOF 1 KIND U
HISTORY SET crown_z6 DOF 2 KIND U
HISTORY SET invert_z6 DOF 2 KIND U
HISTORY SET crown_z9.5 DOF 2 KIND U
HISTORY SET invert_z9.5 DOF 2 KIND U
HISTORY SET springline_z9.5 DOF 1 KIND U
HISTORY SET ground_z2.5 DOF 2 KIND U
-----------------------------------------------------------------END
"""

STEP3 = "STEP 3 NUMSTEP {n3} CONTROL Load                  // on to 10 x\n"
MESHES = [("s6_coarse.msh", 1, ""), ("s6_fine.msh", 2, "_fine")]
MUS = ["0.1", "0.3", "0.6"]


def deck(mu, mesh, counts, title, ten_x=True, gravity10=False, pipe_end_free=False,
         results="VTK Yes  LISTING Yes  HDF5 Yes", mc_psi=None):
    """One deck's text: the benchmark deck, or a variant (steps 1-2 only, the soil's weight
    raised with the loads, the pipe's end z = 0 free axially, Mohr-Coulomb soil with the
    dilation angle mc_psi)."""
    pair = "EPSN 1.0e3 EPST 1.0e2 MU %s GAPTOL 1.0e-6" % mu
    text = HEADER.format(title=title, mesh=mesh, counts=counts[mesh],
                         contact=pair + " (NORMALS default)", n3=18)
    body = BODY.format(mesh=mesh, pair=pair, step3=STEP3.format(n3=18) if ten_x else "",
                       results=results)
    if not ten_x:
        text = text.replace(" Step 3: both to 10 x in 18 increments, the soil's\n weight held at 1 x.",
                            " (Step 3, to 10 x, left out.)\n")
    if gravity10:
        text = text.replace("the soil's\n weight held at 1 x.", "the soil's\n weight too (CURVE 1).")
        body = body.replace("CURVE 1 POINTS 0.0 0.0  1.0 1.0  3.0 1.0              // soil weight: on in step 1, held",
                            "CURVE 1 POINTS 0.0 0.0  1.0 1.0  2.0 1.0  3.0 10.0   // soil weight: 1 x, then 10 x")
    if pipe_end_free:
        text = text.replace(" u_z = 0 at z = 0 (soil and pipe: the buried line continues)",
                            " u_z = 0 at z = 0 on the soil only (the pipe's end z = 0 free axially)")
        body = body.replace("SET pipe_z0       DOF 0 0 1 VAL 0.0 0.0 0.0\n", "")
    if mc_psi is not None:
        text, body = mohr_coulomb_soil(text, body, mc_psi)
    return text + body


def mohr_coulomb_soil(text, body, psi):
    """The soil Mohr-Coulomb with the seed's strength (its Table 3 check: c = 0.020 MPa,
    phi = 30 degrees), dilation angle psi, perfectly plastic, no tension cut-off; HEX8 EAS 3
    (EAS 9 and 21 lose the enhanced stiffness where points become perfectly plastic:
    docs/verification/strip_footing.md)."""
    text = text.replace(" linear elastic, unit weight 0.018 MN/m^3 (DENS 0.018 with GRAVITY 0 -1 0), HEX8 EAS 9.",
                        " Mohr-Coulomb (the seed's c = 0.020, phi = 30 degrees), psi = %s degrees,\n"
                        " perfectly plastic, no tension cut-off, unit weight 0.018 MN/m^3 (DENS 0.018\n"
                        " with GRAVITY 0 -1 0), HEX8 EAS 3 (plastic soil)." % psi)
    body = body.replace("MAT 1 MAT_Struct_LinearElastic YOUNG 50.0 NUE 0.3 DENS 0.018                 // soil",
                        "MAT 1 MAT_3DMohrCoulomb YOUNG 50.0 NUE 0.3 COHESION 0.020 PHI 30.0 PSI %s DENS 0.018"
                        "  // soil" % psi)
    body = body.replace("SET soil SOLID HEX8 EAS 9 MAT 1", "SET soil SOLID HEX8 EAS 3 MAT 1")
    return text, body


def write_decks(counts):
    for mesh, refine, tag in MESHES:
        for mu in MUS:
            write("s6_mu%s%s" % (mu, tag), deck(mu, mesh, counts, "mu = %s%s." % (
                mu, ", refined mesh" if refine > 1 else "")))
    coarse = "s6_coarse.msh"
    # sensitivity to the reading of "all loads raised to 10 x": the soil's weight raised with
    # them in step 3 (CURVE 1 to 10 at t = 3), mu = 0.1 and 0.3
    for mu in ("0.1", "0.3"):
        write("s6_mu%s_g10" % mu, deck(mu, coarse, counts, "mu = %s, soil weight also raised to "
                                       "10 x in step 3." % mu, gravity10=True))
    # sensitivity to the pipe's support at z = 0: axially free (the axial restraint of the buried
    # part then comes from friction alone)
    for mu in MUS:
        write("s6_mu%s_free0" % mu, deck(mu, coarse, counts, "mu = %s, the pipe's end z = 0 free "
                                         "axially." % mu, pipe_end_free=True))
    # the short deck of the default test: the coarse mesh, mu = 0.3, steps 1 and 2 only (to 1 x)
    write("s6_mu0.3_1x", deck("0.3", coarse, counts, "mu = 0.3, steps 1 and 2 only (to 1 x: the "
                              "default test).", ten_x=False, results="VTK No  LISTING Yes  HDF5 No"))
    # the soil Mohr-Coulomb instead of elastic (the seed's after-the-fact check made a model):
    # a low dilation psi = 5 and associated flow psi = 30, the seed's loads to 10 x; steps 1-2
    # only for the default test; and the soil's weight also raised to 10 x
    for psi, tag in (("5.0", ""), ("30.0", "_psi30")):
        write("s6_mu0.3_mc%s" % tag, deck("0.3", coarse, counts, "mu = 0.3, Mohr-Coulomb soil, "
                                          "psi = %s." % psi, mc_psi=psi))
    # the other friction coefficients and the refined mesh, psi = 5
    for mu in ("0.1", "0.6"):
        write("s6_mu%s_mc" % mu, deck(mu, coarse, counts, "mu = %s, Mohr-Coulomb soil, psi = 5.0."
                                      % mu, mc_psi="5.0"))
    write("s6_mu0.3_fine_mc", deck("0.3", "s6_fine.msh", counts, "mu = 0.3, refined mesh, "
                                   "Mohr-Coulomb soil, psi = 5.0.", mc_psi="5.0"))
    write("s6_mu0.3_1x_mc", deck("0.3", coarse, counts, "mu = 0.3, Mohr-Coulomb soil, psi = 5.0, "
                                 "steps 1 and 2 only (to 1 x: a default test).", ten_x=False,
                                 results="VTK No  LISTING Yes  HDF5 Yes", mc_psi="5.0"))
    write("s6_mu0.3_g10_mc", deck("0.3", coarse, counts, "mu = 0.3, Mohr-Coulomb soil, psi = 5.0, "
                                  "soil weight also raised to 10 x in step 3.", gravity10=True,
                                  mc_psi="5.0"))


def write(name, text):
    with open(os.path.join(HERE, name + ".dck"), "w") as f:
        f.write(text)
    print("wrote", name + ".dck")


def main():
    if len(sys.argv) > 1:
        print(__doc__)
        return 0 if sys.argv[1] in ("-h", "--help") else 2
    counts = {}
    for mesh, refine, _ in MESHES:
        n_nodes, n_soil, n_pipe = write_mesh(os.path.join(HERE, mesh), refine)
        counts[mesh] = "soil %d + pipe %d = %d HEX8, %d nodes" % (n_soil, n_pipe, n_soil + n_pipe,
                                                                   n_nodes)
        print("wrote", mesh, counts[mesh], "soil volume %.9g" % soil_volume(refine))
    write_decks(counts)
    return 0


if __name__ == "__main__":
    sys.exit(main())
