#!/usr/bin/env python3
"""Meshes and decks of the buried-pipe benchmark (docs/verification/pipe_soil.md).

A rigid pipe of diameter D = 0.5 m, its centre H = 1 m below the ground, pulled sideways
(lateral) or upwards (uplift) through a Mohr-Coulomb soil: a sand (phi = 35 degrees) and an
undrained clay (c_u = 50 kPa, phi = 0, Tresca), both of unit weight 18 kN/m^3. The plateau of
the force per metre of pipe is compared with the design formulas of ALA (2001) and DNV
(docs/verification/pipe_soil.md; `design_resistances` below gives the numbers).

Plane strain as a slab one element thick (t = 0.1 m, u_y = 0 on both faces of the soil), x
across the pipe, z up, the ground at z = 0, the pipe's centre at (0, -H). The soil block is
[-L, L] x [-DEPTH, 0] (lateral, full model) or [0, L] x [-DEPTH, 0] (uplift, half model with
u_x = 0 on x = 0). The cross-section: an O-grid ring of `n_ring` layers between the pipe's
circle (4 m segments) and a square of half-width A = 0.5 m around it (m equal divisions per
side), inside a Cartesian grid: m / 2 equal rows between the square and the ground, columns
and rows growing geometrically from the square to the far sides and the bottom.

The pipe is a ring of HEX8 (wall 0.05 m) whose nodes all follow a reference node (kinematic
coupling, docs/couplings.md): rigid. Its outer surface is the master of a node-to-segment
contact pair with the soil's cavity (slave), with Coulomb friction (`MU`): the soil can slide
along the pipe and separate from it. Step 1 applies the soil's weight with the pipe held
(geostatic state, K0 from nu); step 2 (RESET_DISPLACEMENT) moves the reference node by a
prescribed displacement, x (lateral) or z (uplift).

    generate_pipe_soil_decks.py [--out DIR]      (default: this script's folder)

Python standard library only. Writes pipe_<full|half>_<tiny|coarse>.inp and the decks
pipe_<sand|clay>_<lateral|uplift>[_<variant>].dck listed in DECKS.
"""
import argparse
import csv
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "strip_footing"))
from generate_footing_decks import graded  # noqa: E402  (geometric grading of a mesh line)

# geometry (m)
DIAMETER, CENTRE_DEPTH, WALL = 0.5, 1.0, 0.05
RADIUS = DIAMETER / 2
SQUARE = 0.5            # half-width of the square around the pipe
HALF_WIDTH, DEPTH, THICKNESS = 5.0, 3.0, 0.1
UNIT_WEIGHT, GRAVITY = 18.0, 9.81           # kN/m^3, m/s^2: DENS = gamma / g (t/m^3)
REF_NODE, ROT_NODE = 900001, 900002
PIPE_NODE_OFFSET, PIPE_ELEMENT_OFFSET = 100000, 100000
# m (divisions per side of the square), ring layers, columns beside the square, rows below it
MESHES = {"tiny": (4, 3, 8, 4), "coarse": (8, 5, 10, 6)}

# soils: MAT_3DMohrCoulomb properties (kPa, degrees); pipe-soil friction coefficient
SOILS = {
    # sand: phi = 35 degrees; a small cohesion (1 kPa) keeps the surface elements off the apex;
    # E = 30 MPa (a medium dense sand), nu = 0.3 (K0 = nu / (1 - nu) = 0.43 = 1 - sin 35 deg);
    # mu = tan(f phi), f = 0.7: ALA's coating factor of smooth steel; PENALTY_FACTOR 1: with the
    # default 10 the contact status chattered where the soil separates (docs/verification/pipe_soil.md)
    "sand": dict(young=3.0e4, nu=0.3, cohesion=1.0, phi=35.0, psi=35.0, mu=math.tan(math.radians(0.7 * 35.0)),
                 penalty_factor=1.0),
    # undrained clay: Tresca (phi = 0) with c = c_u = 50 kPa, E = 500 c_u, nu = 0.49; mu = 0.5 on
    # the total pressure (in front of the pipe mu p > c_u: the interface is as rough as the clay)
    # MAXITER 60: Newton needs 15-20 iterations near the plateau, and a cut increment grows back
    # only after increments of at most MAXITER / 3 iterations (docs/solver.md)
    "clay": dict(young=2.5e4, nu=0.49, cohesion=50.0, phi=0.0, psi=0.0, mu=0.5, penalty_factor=1.0,
                 maxiter=60),
}
# deck name: (soil, direction, displacement in m, increments, soil overrides, mesh)
DECKS = {
    "pipe_sand_lateral": ("sand", "lateral", 0.10, 40, {}, "coarse"),
    "pipe_sand_uplift": ("sand", "uplift", 0.05, 40, {}, "coarse"),
    "pipe_clay_lateral": ("clay", "lateral", 0.10, 40, {}, "coarse"),
    "pipe_clay_uplift": ("clay", "uplift", 0.10, 40, {}, "coarse"),
    "pipe_sand_uplift_tiny": ("sand", "uplift", 0.03, 10, {}, "tiny"),
    "pipe_clay_uplift_tiny": ("clay", "uplift", 0.05, 10, {}, "tiny"),
    "pipe_sand_lateral_tiny": ("sand", "lateral", 0.06, 12, {}, "tiny"),
    "pipe_clay_lateral_tiny": ("clay", "lateral", 0.06, 12, {}, "tiny"),
    "pipe_sand_uplift_tiny_free": ("sand", "uplift", 0.03, 10, {"free": True}, "tiny"),
    "pipe_clay_uplift_tiny_free": ("clay", "uplift", 0.05, 10, {"free": True}, "tiny"),
    "pipe_sand_uplift_tiny_psi5": ("sand", "uplift", 0.03, 10, {"psi": 5.0}, "tiny"),
    "pipe_sand_uplift_tiny_psi5_free": ("sand", "uplift", 0.03, 10, {"psi": 5.0, "free": True}, "tiny"),
    "pipe_sand_lateral_tiny_psi5": ("sand", "lateral", 0.06, 12, {"psi": 5.0}, "tiny"),
    "pipe_sand_lateral_tiny_eas0": ("sand", "lateral", 0.06, 12, {"eas": 0}, "tiny"),
    "pipe_sand_uplift_smooth": ("sand", "uplift", 0.05, 40, {"mu": 0.0}, "coarse"),
}


def design_resistances(soil, direction):
    """The design resistances (kN per metre of pipe) of ALA (2001) App. B and DNV with their N
    values: a dict name -> (value, text). H = CENTRE_DEPTH (to the pipe's centre), x = H / D.
    Sources and what could not be verified: docs/verification/pipe_soil.md."""
    x, gamma, d, h = CENTRE_DEPTH / DIAMETER, UNIT_WEIGHT, DIAMETER, CENTRE_DEPTH
    cover = h - d / 2
    if soil == "sand":
        phi = SOILS["sand"]["phi"]
        if direction == "lateral":
            # ALA Table B-? (Hansen 1961 curves), phi = 35 degrees: a, b, c, d, e
            a, b, c, dd, e = 6.816, 2.019, -0.146, 7.651e-3, -1.683e-4
            n_qh = a + b * x + c * x ** 2 + dd * x ** 3 + e * x ** 4
            return {"ALA": (n_qh * gamma * h * d, "N_qh = %.2f" % n_qh)}
        n_q = math.exp(math.pi * math.tan(math.radians(phi))) * math.tan(math.radians(45 + phi / 2)) ** 2
        n_qv = min(phi * h / (44 * d), n_q)
        # DNV-RP-F110 (2007) eq. B.3: R = (1 + f H/D) gamma' H D with H the cover, f = 0.5 (dense)
        f110 = 0.5
        dnv = (1 + f110 * cover / d) * gamma * cover * d
        values = {"ALA": (n_qv * gamma * h * d, "N_qv = %.2f" % n_qv),
                  "DNV-RP-F110": (dnv, "eq. B.3, f = %.1f, cover %.2f m" % (f110, cover))}
        # DNVGL-RP-F114 eq. 5.6 (drained): gamma H D + gamma D^2 (1/2 - pi/8) + f gamma (H + D/2)^2,
        # H the cover, f = 0.29 / 0.47 / 0.62 for loose / medium / dense sand
        for density, f in (("loose", 0.29), ("medium", 0.47), ("dense", 0.62)):
            r = gamma * cover * d + gamma * d ** 2 * (0.5 - math.pi / 8) + f * gamma * (cover + d / 2) ** 2
            values["DNVGL-RP-F114 " + density] = (r, "eq. 5.6, f = %.2f" % f)
        return values
    c_u = SOILS["clay"]["cohesion"]
    if direction == "lateral":
        n_ch = min(6.752 + 0.065 * x - 11.063 / (x + 1) ** 2 + 7.119 / (x + 1) ** 3, 9.0)
        return {"ALA": (n_ch * c_u * d, "N_ch = %.2f, N_qh = 0" % n_ch)}
    n_cv = min(2 * x, 10.0)
    return {"ALA": (n_cv * c_u * d, "N_cv = %.1f, N_qv = 0" % n_cv),
            # OTC 6486: gamma H D + 2 H c_u (H the cover)
            "OTC 6486": (gamma * cover * d + 2 * cover * c_u, "gamma H D + 2 H c_u, cover %.2f m" % cover)}


def design_band(soil, direction):
    """The band the plateau must lie in: 0.7 x the lowest to 1.3 x the highest design value
    (the +-30 % spread of the design formulas, docs/verification/pipe_soil.md)."""
    values = [v for v, _ in design_resistances(soil, direction).values()]
    return 0.7 * min(values), 1.3 * max(values)


def free_pull_force(soil, direction):
    """The force (kN, on the slab of the model) of a path-controlled pull: twice the band's top,
    so that the load factor stays below 1 over step 2."""
    factor = 2 if direction == "uplift" else 1
    return 2 * design_band(soil, direction)[1] * THICKNESS / factor


def pull_history(out, base, first=1.0 + 1e-12):
    """Step 2 of a run of deck `base` from OUT/base_history.csv (the rows from time `first` on;
    first = 1: with the end of step 1): a list of (row, displacement of the pipe in m, pull on
    the model's slab in kN, force per metre of pipe in kN/m). The pull is the reference node's
    reaction, or the applied force F (t - 1) of a `free` deck."""
    soil, direction, displacement, _, overrides, _ = DECKS[base]
    dof, factor = (3, 2.0) if direction == "uplift" else (1, 1.0)
    with open(pathlib.Path(out) / f"{base}_history.csv") as f:
        rows = [r for r in csv.DictReader(f) if float(r["time"]) >= first]
    history = []
    for r in rows:
        t = float(r["time"])
        if overrides.get("free", False):
            pull, moved = free_pull_force(soil, direction) * (t - 1.0), float(r["u%d_n%d" % (dof, REF_NODE)])
        else:
            pull, moved = float(r["r%d_n%d" % (dof, REF_NODE)]), displacement * (t - 1.0)
        history.append((r, moved, pull, factor * pull / THICKNESS))
    return history


def soil_weight(mesh_name, half):
    """Weight of the slab's soil (kN): the block less the cavity, a polygon of 4 m sides."""
    sides = 4 * MESHES[mesh_name][0]
    area = 2 * HALF_WIDTH * DEPTH - 0.5 * sides * RADIUS ** 2 * math.sin(2 * math.pi / sides)
    return UNIT_WEIGHT * THICKNESS * area * (0.5 if half else 1.0)


def square_point(k, m):
    """Point k (0 <= k < 4 m) of the square's boundary, counter-clockwise from its corner at
    45 degrees, m equal divisions per side; relative to the pipe's centre."""
    side, j = divmod(k % (4 * m), m)
    s = SQUARE * (1 - 2 * j / m)
    return [(s, SQUARE), (-SQUARE, s), (-s, -SQUARE), (SQUARE, -s)][side]


def circle_point(k, m, r):
    angle = math.pi / 4 + 2 * math.pi * k / (4 * m)
    return (r * math.cos(angle), r * math.sin(angle))


class Mesh2d:
    """Cross-section: nodes keyed by their rounded coordinates, quadrilaterals
    counter-clockwise in (x, z), marked edges for surfaces."""

    def __init__(self):
        self.nodes, self.ids, self.quads = [], {}, []

    def node(self, x, z):
        key = (round(x, 9), round(z, 9))
        if key not in self.ids:
            self.ids[key] = len(self.nodes)
            self.nodes.append((x, z))
        return self.ids[key]

    def quad(self, points, edge=None):
        """points: four (x, z) counter-clockwise; edge: index of the marked edge (points e, e+1)."""
        self.quads.append(([self.node(*p) for p in points], edge))


def cross_section(m, n_ring, n_side, n_below, half):
    zc = -CENTRE_DEPTH
    soil, pipe = Mesh2d(), Mesh2d()
    h = 2 * SQUARE / m
    xs = graded(SQUARE, HALF_WIDTH - SQUARE, n_side, h)
    xs = [-x for x in xs[::-1]] + [-SQUARE + h * (i + 1) for i in range(m - 1)] + xs
    zs = graded(SQUARE, DEPTH - CENTRE_DEPTH - SQUARE, n_below, h)
    zs = [zc - z for z in zs[::-1]] + [zc - SQUARE + h * (k + 1) for k in range(m - 1)]
    n_above = max(1, round((CENTRE_DEPTH - SQUARE) / h))
    zs += [zc + SQUARE + (CENTRE_DEPTH - SQUARE) * k / n_above for k in range(n_above + 1)]
    for k in range(len(zs) - 1):
        for i in range(len(xs) - 1):
            xm, zm = 0.5 * (xs[i] + xs[i + 1]), 0.5 * (zs[k] + zs[k + 1]) - zc
            if abs(xm) < SQUARE and abs(zm) < SQUARE:
                continue
            soil.quad([(xs[i], zs[k]), (xs[i + 1], zs[k]), (xs[i + 1], zs[k + 1]), (xs[i], zs[k + 1])])
    # O-grid ring: layer l from the circle (l = 0) to the square (l = n_ring), graded
    ratio = 1.25
    blend = [(ratio ** l - 1) / (ratio ** n_ring - 1) for l in range(n_ring + 1)]

    def ring_point(k, l):
        cx, cz = circle_point(k, m, RADIUS)
        sx, sz = square_point(k, m)
        return (cx + blend[l] * (sx - cx), zc + cz + blend[l] * (sz - cz))

    for k in range(4 * m):
        for l in range(n_ring):
            soil.quad([ring_point(k, l), ring_point(k, l + 1), ring_point(k + 1, l + 1), ring_point(k + 1, l)],
                      edge=3 if l == 0 else None)  # edge 3: points 3-0, on the circle
        inner = [circle_point(j, m, RADIUS - WALL) for j in (k, k + 1)]
        outer = [circle_point(j, m, RADIUS) for j in (k, k + 1)]
        pipe.quad([(inner[0][0], zc + inner[0][1]), (outer[0][0], zc + outer[0][1]),
                   (outer[1][0], zc + outer[1][1]), (inner[1][0], zc + inner[1][1])], edge=1)
    if half:
        for mesh in (soil, pipe):
            mesh.quads = [(q, e) for q, e in mesh.quads if sum(mesh.nodes[n][0] for n in q) > 0]
    return soil, pipe


# C3D8 face of a hexahedron built by `extrude` from the quadrilateral's edge (e, e+1)
EDGE_FACE = {0: "S1", 1: "S4", 2: "S2", 3: "S6"}


def extrude(mesh, node_offset, element_offset):
    """Nodes (id -> x, y, z) and hexahedra (id -> 8 node ids, marked face) of a slab y in
    [0, THICKNESS]: node a + 4 is the next point of the quadrilateral, nodes 1-4 the edge
    (0, 1) at y = 0 and y = t (right-handed for a counter-clockwise quadrilateral)."""
    used = sorted({n for q, _ in mesh.quads for n in q})
    number = {n: i for i, n in enumerate(used)}
    count = len(used)
    nodes = {}
    for n in used:
        x, z = mesh.nodes[n]
        for j, y in enumerate((0.0, THICKNESS)):
            nodes[node_offset + 1 + number[n] + count * j] = (x, y, z)
    hexes = {}
    for e, (q, edge) in enumerate(mesh.quads):
        a = [node_offset + 1 + number[n] for n in q]
        b = [i + count for i in a]
        p = [mesh.nodes[n] for n in q]
        area = (p[1][0] - p[0][0]) * (p[3][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[3][0] - p[0][0])
        assert area > 0, "quadrilateral %d is not counter-clockwise" % e
        hexes[element_offset + 1 + e] = ([a[0], a[1], b[1], b[0], a[3], a[2], b[2], b[3]],
                                         EDGE_FACE[edge] if edge is not None else None)
    return nodes, hexes


def write_mesh(path, mesh_name, half):
    m, n_ring, n_side, n_below = MESHES[mesh_name]
    soil, pipe = cross_section(m, n_ring, n_side, n_below, half)
    soil_nodes, soil_hexes = extrude(soil, 0, 0)
    pipe_nodes, pipe_hexes = extrude(pipe, PIPE_NODE_OFFSET, PIPE_ELEMENT_OFFSET)
    lines = ["** buried pipe, generate_pipe_soil_decks.py: %s model, %s mesh (%d soil, %d pipe HEX8)"
             % ("half" if half else "full", mesh_name, len(soil_hexes), len(pipe_hexes)), "*NODE"]
    for nodes in (soil_nodes, pipe_nodes):
        lines += ["%d, %.15g, %.15g, %.15g" % (i, *xyz) for i, xyz in sorted(nodes.items())]
    for name, hexes in (("soil", soil_hexes), ("pipe", pipe_hexes)):
        lines.append("*ELEMENT, TYPE=C3D8, ELSET=%s" % name)
        lines += ["%d, %s" % (e, ", ".join(map(str, c))) for e, (c, _) in sorted(hexes.items())]

    def node_set(name, ids):
        lines.append("*NSET, NSET=%s" % name)
        ids = sorted(ids)
        lines.extend(", ".join(map(str, ids[i:i + 16])) for i in range(0, len(ids), 16))

    node_set("pipe_nodes", pipe_nodes)
    node_set("pipe_crown", [i for i, p in pipe_nodes.items()
                            if abs(p[0]) < 1e-9 and p[1] == 0.0 and abs(p[2] + CENTRE_DEPTH - RADIUS) < 1e-9])
    node_set("soil_front", [i for i, p in soil_nodes.items() if p[1] == 0.0])
    node_set("soil_back", [i for i, p in soil_nodes.items() if p[1] == THICKNESS])
    if half:
        node_set("soil_symmetry", [i for i, p in soil_nodes.items() if abs(p[0]) < 1e-9])
    for name, hexes in (("cavity", soil_hexes), ("pipe_outer", pipe_hexes)):
        lines.append("*SURFACE, NAME=%s" % name)
        lines += ["%d, %s" % (e, face) for e, (_, face) in sorted(hexes.items()) if face]
    pathlib.Path(path).write_text("\n".join(lines) + "\n")
    return len(soil_hexes), len(pipe_hexes)


def deck_text(name, soil_name, direction, displacement, increments, overrides, mesh_name, counts):
    s = dict(SOILS[soil_name], **overrides)
    half = direction == "uplift"
    model = "half" if half else "full"
    x_min = 0.0 if half else -HALF_WIDTH
    dof = 1 if direction == "lateral" else 3
    move = "%g 0 0" % displacement if dof == 1 else "0 0 %g" % displacement
    factor = 2 if half else 1
    design = design_resistances(soil_name, direction)
    design_text = "; ".join("%s %.1f kN/m (%s)" % (k, v, t) for k, (v, t) in design.items())
    # the symmetry plane x = 0 of the half model holds pipe nodes, which the coupling moves
    near = "SET soil_symmetry DOF 1 0 0 VAL 0 0 0" if half else "SET sides      DOF 1 0 0 VAL 0 0 0"
    # free: the pipe follows the soil in step 1 (u_z free, weightless) and is pulled by a force
    # in step 2, path-controlled by its crown's u_z (docs/verification/pipe_soil.md)
    free = s.get("free", False)
    pull_force = free_pull_force(soil_name, direction)
    ref_line = ("NODE %d   DOF 1 1 0 VAL 0 0 0\n" % REF_NODE +
                "------------------------------------------------NEUMANN CONDITIONS\n" +
                "NODE %d   FORCE 0 0 %.6g CURVE 1" % (REF_NODE, pull_force)) if free else \
        "NODE %d   DOF 1 1 1 VAL %s CURVE 1 1 1" % (REF_NODE, move)
    control = ("Path SET pipe_crown DOF 3 TARGET %g" % displacement) if free else "Displacement"
    friction = "MU %.4f " % s["mu"] if s["mu"] > 0 else ""
    if free:
        steps_text = ("Step 1: the soil's weight, the weightless pipe free to settle with it. Step 2\n"
                      " (RESET_DISPLACEMENT): a force F f(t) = %g (t - 1) kN pulls the reference node up,\n"
                      " path-controlled: the pipe's crown rises to u_z = %g m (total) in %d increments.\n"
                      " Force per metre of pipe: %d x %g (t - 1) / t." % (pull_force, displacement, increments,
                                                                          factor, pull_force))
    else:
        steps_text = ("Step 1: the soil's weight, pipe held (geostatic state). Step 2 (RESET_DISPLACEMENT):\n"
                      " the pipe's reference node moved %g m in %s in %d increments.\n"
                      " Force per metre of pipe: %d x r%d_n%d / t." % (displacement, "x" if dof == 1 else "z",
                                                                       increments, factor, dof, REF_NODE))
    friction += "PENALTY_FACTOR %g " % s["penalty_factor"] if "penalty_factor" in s else ""
    return f"""==================================================================
 Buried pipe pulled {'sideways' if dof == 1 else 'upwards'} through {soil_name}
 (docs/verification/pipe_soil.md; written by generate_pipe_soil_decks.py).
 Rigid pipe D = {DIAMETER:g} m, centre {CENTRE_DEPTH:g} m below the ground; plane strain as a slab
 t = {THICKNESS:g} m thick (u_y = 0 on the soil's faces); {model} model, {mesh_name} mesh
 ({counts[0]} soil HEX8 EAS 3, {counts[1]} pipe HEX8 coupled to node {REF_NODE}); soil block
 {HALF_WIDTH:g} m {'wide (u_x = 0 on x = 0: symmetry)' if half else 'each side of the pipe'}, {DEPTH:g} m deep.
 Soil: Mohr-Coulomb E = {s['young']:g} kPa, nu = {s['nu']:g}, c = {s['cohesion']:g} kPa,
 phi = {s['phi']:g}, psi = {s['psi']:g} degrees, unit weight {UNIT_WEIGHT:g} kN/m^3.
 Pipe-soil contact: node-to-segment, Coulomb mu = {s['mu']:.3f}.
 {steps_text}
 Design: {design_text}.
 units: kN, m, kPa
==================================================================
---------------------------------------------------------PROBLEM TYP
PROBLEMTYP   Structure
--------------------------------------------------------------STATIC
KINTYP       Geo_Lin
MAXITER      {s.get('maxiter', 30)}
MAXCUT       8
TOLRESID     1.0e-6
TOLDISP      1.0e-6
---------------------------------------------------------LOAD CURVES
CURVE 1 POINTS 0.0 0.0  1.0 0.0  2.0 1.0
-----------------------------------------------------------MATERIALS
MAT 1 MAT_3DMohrCoulomb YOUNG {s['young']:g} NUE {s['nu']:g} COHESION {s['cohesion']:g} PHI {s['phi']:g} PSI {s['psi']:g} DENS {UNIT_WEIGHT / GRAVITY:.10g}
MAT 2 MAT_Struct_LinearElastic YOUNG 2.1e8 NUE 0.3
------------------------------------------------------------MESH FILE
FILE pipe_{model}_{mesh_name}.inp
---------------------------------------------------------NODE COORDS
NODE {REF_NODE} COORD 0 {THICKNESS / 2:g} {-CENTRE_DEPTH:g}
NODE {ROT_NODE} COORD 0 {THICKNESS / 2:g} {-CENTRE_DEPTH:g}
--------------------------------------------------STRUCTURE ELEMENTS
SET soil SOLID HEX8 MAT 1 EAS {s.get('eas', 3)}
SET pipe SOLID HEX8 MAT 2
------------------------------------------------------------NODE SETS
{'' if half else 'SET sides   BOX %g -1 -%g  %g 1 1' % (x_min, DEPTH + 1, x_min) + chr(10)}SET far     BOX {HALF_WIDTH:g} -1 -{DEPTH + 1:g}  {HALF_WIDTH:g} 1 1
SET bottom  BOX {x_min - 1:g} -1 -{DEPTH:g}  {HALF_WIDTH + 1:g} 1 -{DEPTH:g}
-----------------------------------------------------------COUPLINGS
COUPLING 1 KINEMATIC SET pipe_nodes REF_NODE {REF_NODE} ROT_NODE {ROT_NODE}
------------------------------------------------DIRICHLET CONDITIONS
{near}
SET far        DOF 1 0 0 VAL 0 0 0
SET bottom     DOF 1 0 1 VAL 0 0 0
SET soil_front DOF 0 1 0 VAL 0 0 0
SET soil_back  DOF 0 1 0 VAL 0 0 0
NODE {ROT_NODE}   DOF 1 1 1 VAL 0 0 0
{ref_line}
------------------------------------------------------------BODY FORCE
SET soil GRAVITY 0 0 -{GRAVITY:g}
--------------------------------------------------CONTACT CONDITIONS
PAIR 1 SLAVE cavity MASTER pipe_outer {friction}GAPTOL 1.0e-6
---------------------------------------------------------------STEPS
STEP 1 NUMSTEP 2 CONTROL Load
STEP 2 NUMSTEP {increments} CONTROL {control} RESET_DISPLACEMENT
-------------------------------------------------------------RESULTS
VTK Yes LISTING No EVERY {increments}
HISTORY NODE {REF_NODE} DOF 1 KIND R
HISTORY NODE {REF_NODE} DOF 3 KIND R
HISTORY NODE {REF_NODE} DOF {dof} KIND U
HISTORY SET bottom DOF 3 KIND R SUM
HISTORY CONTACT 1 FORCE DOF {dof}
-----------------------------------------------------------------END
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default=str(pathlib.Path(__file__).resolve().parent))
    out = pathlib.Path(parser.parse_args().out)
    out.mkdir(parents=True, exist_ok=True)
    counts = {}
    for mesh_name in MESHES:
        for half in (False, True):
            counts[(mesh_name, half)] = write_mesh(out / ("pipe_%s_%s.inp" % ("half" if half else "full", mesh_name)),
                                                   mesh_name, half)
    for name, (soil, direction, displacement, increments, overrides, mesh_name) in DECKS.items():
        text = deck_text(name, soil, direction, displacement, increments, overrides, mesh_name,
                         counts[(mesh_name, direction == "uplift")])
        (out / (name + ".dck")).write_text(text)


if __name__ == "__main__":
    main()
