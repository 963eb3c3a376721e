#!/usr/bin/python3
"""Write the S2 meshes and decks: the tension zone of an extended end-plate joint, the column
flange as a T-stub on a rigid end plate (docs/benchmarks.md S2, docs/verification/s2.md; seed
6.1.2, after Gebbeken, Rothert & Binder, J. Constr. Steel Res. 30 (1994) 177-196).

usage: generate_s2_decks.py [--help]

Run from anywhere; writes s2_coarse.msh, s2_fine.msh and the decks beside this script. Only the
standard library is used (the meshes are written directly in gmsh's 2.2 ASCII format).

Units kN, m, kPa (the seed's); the lengths below are in mm and written in m.

Reconstruction (the paper's geometry is not available; docs/verification/s2.md):
- Column HEB 200 (EN 10365 / DIN 1025-2 table): b = 200, h = 200, t_w = 9, t_f = 15,
  root radius r = 18. Bolts M20 10.9, gauge w = 110 (bolt axis 55 from the web's mid-plane,
  edge distance e = 45), two bolt rows 100 apart (p = 100) acting as a group.
- The T-stub: one eighth of the joint, i.e. a quarter of the column flange's T-stub of one
  bolt group: x >= 0 (the web's mid-plane x = 0 a symmetry plane), y >= 0 (the plane y = 0
  midway between the two bolt rows), and the web cut at the column's mid-depth z = 100 (the
  symmetry plane of the column, where the displacement is prescribed). The flange is 300 long
  (y from -150 to 150 in the full T-stub; 150 here), the group's effective length of
  EN 1993-1-8 Table 6.4 (non-circular, 2m + 0.625e + 0.5p per row, m = 36.1: 300.6), so that
  the model is the equivalent T-stub of the code.
- Flange: 0 <= x <= 100, 0 <= y <= 150, 0 <= z <= 15 (z = 0 its face on the end plate).
  Web: half thickness 4.5, from z = 15 to 100, with the root radius r = 18 modelled: the web's
  face x = x_w(z) = 4.5 + r - sqrt(r^2 - (15 + r - z)^2) for 15 <= z <= 33 (a quarter circle
  from x = 22.5 on the flange to the web face at z = 33), the web's elements fanned across.
- Bolt: a square shank of the stress area A_s = 245 mm^2 (side 15.65; it yields at
  1.0e6 kPa x 245 mm^2 = 245 kN), through a square hole of the area of the M20 clearance hole
  d_0 = 22 (side 19.50; no contact between shank and hole wall), its head a square block of
  the washer's bearing area (d_w = 37: side 32.79), 12.5 high (the M20 head height k),
  sharing its nodes with the flange's top face around the hole and with the shank's top.
  The shank ends at z = -36, fixed there (the nut on the rigid end plate's far side): the
  length from the head's mid-height to that end is the bolt elongation length of EN 1993-1-8
  Table 6.2, L_b = grip + (k + m_nut)/2 = (t_f 15 + end plate 20 + 2 washers 4) +
  (12.5 + 16)/2 = 57.25.
- End plate: rigid, the plane z = 0 (RIGID_PLANE, normal +z); the contact slave is the
  flange's face z = 0 (outside the hole).

Mesh (structured HEX8): a plan grid (x, y) with lines at the web's fan (0 ... 22.5), the
washer, hole and shank edges; the flange in n_f layers, the web in rows graded towards the
fillet, the head in n_h layers and the shank in n_s. Coarse: refine = 1; fine: refine = 2
(every division doubled).

Physical groups: 3D plate (flange and web, MAT 1), bolt (head and shank, MAT 2);
2D flange_bottom (z = 0, the contact slave), web_top (z = 100, loaded), sym_x (x = 0),
sym_y (y = 0), bolt_end (z = -36, the nut); 0D heel (0, 0, 0) under the web, tip (100, 0, 0)
the flange tip on the symmetry plane y = 0, tip_bolt (100, 50, 0) the tip in line with the bolt.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "meshes"))
from gmsh22_writer import write_gmsh22  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))

# HEB 200 and M20 10.9 (mm)
B_HALF, T_F, T_W, R_ROOT, Z_TOP = 100.0, 15.0, 9.0, 18.0, 100.0
X_BOLT, Y_BOLT, L_HALF = 55.0, 50.0, 150.0
A_S = 245.0                                   # stress area, mm^2
SHANK = math.sqrt(A_S)                        # 15.65
HOLE = math.sqrt(math.pi / 4) * 22.0          # 19.50
WASHER = math.sqrt(math.pi / 4) * 37.0        # 32.79
HEAD_HEIGHT = 12.5
END_PLATE, WASHER_T, NUT_HEIGHT = 20.0, 4.0, 16.0
L_B = (T_F + END_PLATE + 2 * WASHER_T) + (HEAD_HEIGHT + NUT_HEIGHT) / 2      # 57.25
Z_NUT = T_F + HEAD_HEIGHT / 2 - L_B                                          # -36
X_FAN = T_W / 2 + R_ROOT                      # 22.5: the fillet's toe on the flange
Z_FILLET = T_F + R_ROOT                       # 33: the fillet's end on the web

# St37 and the bolt (kPa)
YOUNG, NU, SIGY_PLATE, SIGY_BOLT = 2.1e8, 0.3, 2.4e5, 1.0e6
# the seed's penalty pairs (EPSN, EPST), read as multiples of the flange's stiffness scale M/t_f
PENALTY_PAIRS = [(1e3, 1e1), (1e2, 1e2), (1e3, 1e2), (1e4, 1e2)]
# the seed's pair scaled down by 1e3 and 1e4: where the penalty starts to matter
SOFT_PAIRS = [(1e0, 1e-2), (1e-1, 1e-3)]
CONSTRAINED_MODULUS = YOUNG * (1 - NU) / ((1 + NU) * (1 - 2 * NU))
PENALTY_SCALE = CONSTRAINED_MODULUS / (T_F / 1000.0)                         # kN/m^3


def web_face(z):
    """x of the web's face at height z (mm): the root radius's quarter circle, then t_w / 2."""
    if z >= Z_FILLET:
        return T_W / 2
    return T_W / 2 + R_ROOT - math.sqrt(max(R_ROOT ** 2 - (Z_FILLET - z) ** 2, 0.0))


def divide(points, counts, refine):
    """Grid lines through the given points, each interval cut into count x refine equal parts."""
    lines = [points[0]]
    for a, b, n in zip(points[:-1], points[1:], counts):
        m = n * refine
        lines += [a + (b - a) * k / m for k in range(1, m + 1)]
    return lines


def plan_lines(refine):
    """x and y lines (mm), and the number of x intervals under the web's fan."""
    xs = divide([0.0, X_FAN, X_BOLT - WASHER / 2, X_BOLT - HOLE / 2, X_BOLT - SHANK / 2,
                 X_BOLT + SHANK / 2, X_BOLT + HOLE / 2, X_BOLT + WASHER / 2, B_HALF],
                [2, 2, 1, 1, 2, 1, 1, 3], refine)
    ys = divide([0.0, Y_BOLT - WASHER / 2, Y_BOLT - HOLE / 2, Y_BOLT - SHANK / 2,
                 Y_BOLT + SHANK / 2, Y_BOLT + HOLE / 2, Y_BOLT + WASHER / 2, L_HALF],
                [3, 1, 1, 2, 1, 1, 4], refine)
    return xs, ys, 2 * refine


class Mesh:
    def __init__(self):
        self.nodes, self.ids = [], {}

    def node(self, key, xyz):
        if key not in self.ids:
            self.nodes.append(tuple(v / 1000.0 for v in xyz))
            self.ids[key] = len(self.nodes)
        return self.ids[key]


def inside(c, centre, side):
    return abs(c - centre) < side / 2


def build(refine):
    xs, ys, n_fan = plan_lines(refine)
    z_flange = divide([0.0, T_F], [3], refine)
    z_web = divide([T_F, T_F + 2, T_F + 6, Z_FILLET, Z_TOP], [1, 1, 1, 3], refine)
    z_head = divide([T_F, T_F + HEAD_HEIGHT], [2], refine)
    z_shank = divide([Z_NUT, T_F], [5], refine)
    mesh = Mesh()

    def plan(i, j, z):
        return mesh.node(("p", i, j, round(z, 9)), (xs[i], ys[j], z))

    def web(i, j, k):
        if k == 0:
            return plan(i, j, T_F)
        z = z_web[k]
        return mesh.node(("w", i, j, k), (web_face(z) * i / n_fan, ys[j], z))

    def brick(corner, i, j, k):
        lo = [corner(i, j, k), corner(i + 1, j, k), corner(i + 1, j + 1, k), corner(i, j + 1, k)]
        hi = [corner(i, j, k + 1), corner(i + 1, j, k + 1), corner(i + 1, j + 1, k + 1),
              corner(i, j + 1, k + 1)]
        return lo + hi

    def layered(zs):
        return lambda i, j, k: plan(i, j, zs[k])

    plate, bolt, groups = [], [], {n: [] for n in ("flange_bottom", "web_top", "sym_x", "sym_y",
                                                   "bolt_end")}
    centre = [(xs[i] + xs[i + 1]) / 2 for i in range(len(xs) - 1)]
    middle = [(ys[j] + ys[j + 1]) / 2 for j in range(len(ys) - 1)]
    in_hole = lambda i, j: inside(centre[i], X_BOLT, HOLE) and inside(middle[j], Y_BOLT, HOLE)
    for i in range(len(xs) - 1):
        for j in range(len(ys) - 1):
            if in_hole(i, j):
                continue
            for k in range(len(z_flange) - 1):
                plate.append(brick(layered(z_flange), i, j, k))
                add_faces(groups, plate[-1], i == 0, j == 0, bottom=k == 0)
    for i in range(n_fan):
        for j in range(len(ys) - 1):
            for k in range(len(z_web) - 1):
                plate.append(brick(web, i, j, k))
                add_faces(groups, plate[-1], i == 0, j == 0, top=k == len(z_web) - 2)
    for i in range(len(xs) - 1):
        for j in range(len(ys) - 1):
            if inside(centre[i], X_BOLT, WASHER) and inside(middle[j], Y_BOLT, WASHER):
                for k in range(len(z_head) - 1):
                    bolt.append(brick(layered(z_head), i, j, k))
            if inside(centre[i], X_BOLT, SHANK) and inside(middle[j], Y_BOLT, SHANK):
                for k in range(len(z_shank) - 1):
                    bolt.append(brick(layered(z_shank), i, j, k))
                    if k == 0:
                        groups["bolt_end"].append(bottom_face(bolt[-1]))
    points = [("heel", plan(0, 0, 0.0)), ("tip", plan(len(xs) - 1, 0, 0.0)),
              ("tip_bolt", plan(len(xs) - 1, ys.index(min(ys, key=lambda y: abs(y - Y_BOLT))),
                                0.0))]
    return mesh, plate, bolt, groups, points


def bottom_face(h):
    return [h[0], h[3], h[2], h[1]]             # outward normal -z


def add_faces(groups, h, on_x0, on_y0, bottom=False, top=False):
    """Put the faces of hexahedron h that lie on x = 0, y = 0, the flange's bottom or the web's
    top into their groups, each oriented outwards."""
    if on_x0:
        groups["sym_x"].append([h[0], h[4], h[7], h[3]])
    if on_y0:
        groups["sym_y"].append([h[0], h[1], h[5], h[4]])
    if bottom:
        groups["flange_bottom"].append(bottom_face(h))
    if top:
        groups["web_top"].append([h[4], h[5], h[6], h[7]])


def number(v):
    return repr(round(v, 12))


def write_mesh(path, refine):
    """Write the mesh (only if its text changed); returns a one-line summary of its size."""
    mesh, plate, bolt, groups, points = build(refine)
    write_gmsh22(path, "written by inputs/s2_end_plate/generate_s2_decks.py, refine %d" % refine, mesh.nodes,
                 [("plate", plate), ("bolt", bolt)], groups, points, number)
    return "plate %d + bolt %d = %d HEX8, %d nodes" % (len(plate), len(bolt),
                                                        len(plate) + len(bolt), len(mesh.nodes))


HEADER = """==================================================================
 S2: the tension zone of an extended end-plate joint, column flange T-stub on a rigid end
 plate (seed 6.1.2, after Gebbeken, Rothert & Binder 1994; docs/verification/s2.md). {title}
 Units kN, m, kPa. One eighth of the joint: x >= 0 (web mid-plane), y >= 0 (midway between
 the two bolt rows), z <= 0.1 (the column's mid-depth). Mesh {mesh}: {counts}.
 Reconstruction (the paper's geometry is not available): column HEB 200 (t_f = 15 mm,
 t_w = 9 mm, root radius 18 mm modelled as a quarter circle), flange half width 100 mm,
 T-stub 300 mm long (150 mm here: the group's effective length of EN 1993-1-8 Table 6.4);
 M20 10.9 bolt at x = 55 mm (gauge 110, e = 45), y = 50 mm (pitch 100 between the rows):
 a square shank of the stress area 245 mm^2 in a clearance hole of the area of d_0 = 22 mm,
 its head (washer area, d_w = 37 mm; 12.5 mm high) sharing nodes with the flange's top, its
 end fixed at z = -36 mm (the nut on the far side of the 20 mm end plate; L_b = 57.25 mm of
 EN 1993-1-8 Table 6.2 from the head's mid-height).
 St37: E = 2.1e8, nu = 0.3, J2 without hardening, sigma_y = 2.4e5 (plate: flange and web);
 bolt: the same law with sigma_y = 1.0e6 (yields at 245 kN).
 End plate: the rigid plane z = 0. Contact flange_bottom / plane: EPSN {epsn:.4e}
 EPST {epst:.4e} (the seed's pair ({seed_n:g}, {seed_t:g}) times the flange's stiffness scale
 M/t_f = {scale:.4e} kN/m^3), MU 0.1, GAPTOL 1e-4.
 Supports: u_x = 0 on x = 0, u_y = 0 on y = 0, the bolt's end fixed; web top z = 0.1:
 u_x = 0 (no out-of-plane displacement) and u_z prescribed to {u_end:g} m in {n_inc}
 increments. The T-stub's force is 4 x r3_sum_web_top (a quarter of the T-stub).{preload_text}
 Generated by inputs/s2_end_plate/generate_s2_decks.py
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
EXTRAPOLATION Linear
MU_CONTINUATION 4 2        // a failed increment again with mu x 4, x 2, then as given
SOLVER       Auto
---------------------------------------------------------LOAD CURVES
{curves}-----------------------------------------------------------MATERIALS
MAT 1 MAT_3DMisesPlastic YOUNG 2.1e8 NUE 0.3 SIGY 2.4e5      // St37, flange and web
MAT 2 MAT_3DMisesPlastic YOUNG 2.1e8 NUE 0.3 SIGY 1.0e6      // bolt
-----------------------------------------------------------MESH FILE
FILE {mesh}
--------------------------------------------------STRUCTURE ELEMENTS
SET plate SOLID HEX8 EAS {eas} MAT 1
SET bolt  SOLID HEX8 EAS {eas} MAT 2
------------------------------------------------DIRICHLET CONDITIONS
SET sym_x    DOF 1 0 0 VAL 0.0 0.0 0.0              // web mid-plane
SET sym_y    DOF 0 1 0 VAL 0.0 0.0 0.0              // midway between the bolt rows
{supports}--------------------------------------------------CONTACT CONDITIONS
{pair_line}
---------------------------------------------------------------STEPS
{steps}-------------------------------------------------------------RESULTS
{results}
HISTORY SET web_top DOF 3 KIND U MEAN
HISTORY SET web_top DOF 3 KIND R SUM
HISTORY SET bolt_end DOF 3 KIND R SUM
HISTORY CONTACT 1 FORCE DOF 3
HISTORY CONTACT 1 NORMAL
HISTORY SET heel DOF 3 KIND U
HISTORY SET tip DOF 3 KIND U
HISTORY SET tip_bolt DOF 3 KIND U
-----------------------------------------------------------------END
"""

MESHES = {"coarse": ("s2_coarse.msh", 1), "fine": ("s2_fine.msh", 2)}
U_END, N_INC = 0.002, 20


PAIR_LINE = ("PAIR 1 SLAVE flange_bottom MASTER RIGID_PLANE POINT 0 0 0 NORMAL 0 0 1 {penalties}"
             "MU 0.1 GAPTOL 1.0e-4{method}")
PENALTIES = "EPSN {epsn:.4e} EPST {epst:.4e} "

PLAIN = dict(
    pair_line=PAIR_LINE.format(penalties=PENALTIES, method=""),
    preload_text="",
    curves="CURVE 1 POINTS 0.0 0.0  1.0 1.0\n",
    supports="SET bolt_end DOF 1 1 1 VAL 0.0 0.0 0.0              "
             "// the nut on the end plate's far side\n"
             "SET web_top  DOF 1 0 1 VAL 0.0 0.0 {u_end:g} CURVE 0 0 1   "
             "// pulled off the end plate\n",
    steps="STEP 1 NUMSTEP {n_inc} CONTROL Displacement\n")

# Bolt preload by the turn of the nut: step 1 moves the bolt's end by -PRELOAD_SHORTENING (m)
# with the web held, step 2 pulls the web. The shortening gives about the preload
# F_p,C = 0.7 f_ub A_s = 171.5 kN of EN 1993-1-8 3.6.1 (the run reports the force reached).
PRELOAD_SHORTENING, PRELOAD_INCREMENTS = 2.05e-4, 5
PRELOADED = dict(
    pair_line=PAIR_LINE.format(penalties=PENALTIES, method=""),
    preload_text="\n Bolt preload by the turn of the nut: step 1 moves the bolt's end by "
                 "{shortening:g} m\n"
                 " (u_z, in {n_pre} increments) with the web held, towards the EN 1993-1-8 3.6.1\n"
                 " preload F_p,C = 0.7 f_ub A_s = 171.5 kN; step 2 pulls the web.",
    curves="CURVE 1 POINTS 0.0 0.0  1.0 0.0  2.0 1.0      "
           "// the web: held in step 1, pulled in step 2\n"
           "CURVE 2 POINTS 0.0 0.0  1.0 1.0  2.0 1.0      "
           "// the nut: turned in step 1, then held\n",
    supports="SET bolt_end DOF 1 1 1 VAL 0.0 0.0 -{shortening:g} CURVE 0 0 2   // the nut turned\n"
             "SET web_top  DOF 1 0 1 VAL 0.0 0.0 {u_end:g} CURVE 0 0 1   "
             "// pulled off the end plate\n",
    steps="STEP 1 NUMSTEP {n_pre} CONTROL Displacement      // preload\n"
          "STEP 2 NUMSTEP {n_inc} CONTROL Displacement\n")


# The penalty study's two answers to the seed's spread: the augmented Lagrangian (normal and
# tangential) at the softest pair, and the automatic penalties (docs/contact.md).
AUGMENTED = dict(PLAIN, pair_line=PAIR_LINE.format(penalties=PENALTIES, method=" METHOD Augmented TMETHOD Augmented"),
                 preload_text="\n Contact by the augmented Lagrangian (METHOD Augmented, TMETHOD Augmented) at these "
                              "penalties:\n the penetration and the stick slip end below their tolerances whatever the "
                              "penalty.")
AUTOMATIC = dict(PLAIN, pair_line=PAIR_LINE.format(penalties="", method=""),
                 preload_text="\n No EPSN or EPST on the PAIR line: frix's automatic penalties are used instead of "
                              "the pair above\n (docs/contact.md, \"Automatic penalties\").")


def deck(mesh, counts, eas, pair, title, results="VTK Yes  LISTING Yes  HDF5 Yes", variant=PLAIN):
    seed_n, seed_t = pair
    values = dict(title=title, mesh=mesh, counts=counts, eas=eas, seed_n=seed_n, seed_t=seed_t,
                  epsn=seed_n * PENALTY_SCALE, epst=seed_t * PENALTY_SCALE, scale=PENALTY_SCALE,
                  u_end=U_END, n_inc=N_INC, results=results, shortening=PRELOAD_SHORTENING,
                  n_pre=PRELOAD_INCREMENTS)
    values.update({k: v.format(**values) for k, v in variant.items()})
    return HEADER.format(**values) + BODY.format(**values)


def write_decks(counts):
    coarse, fine = MESHES["coarse"][0], MESHES["fine"][0]
    seed = PENALTY_PAIRS[0]
    write("s2_eas9", deck(coarse, counts[coarse], 9, seed, "Coarse mesh, HEX8 EAS 9, the seed's "
                          "penalties (1e3, 1e1)."))
    write("s2_eas9_fine", deck(fine, counts[fine], 9, seed, "Fine mesh, HEX8 EAS 9, the seed's "
                               "penalties (1e3, 1e1)."))
    write("s2_eas3", deck(coarse, counts[coarse], 3, seed, "Coarse mesh, HEX8 EAS 3 (the seed's "
                          "Hexa8-E3)."))
    write("s2_hex8", deck(coarse, counts[coarse], 0, seed, "Coarse mesh, plain HEX8 (EAS 0)."))
    write("s2_eas9_preload", deck(coarse, counts[coarse], 9, seed, "Coarse mesh, HEX8 EAS 9, "
                                  "the seed's penalties, bolt preload.", variant=PRELOADED))
    for pair in PENALTY_PAIRS[1:] + SOFT_PAIRS:
        write("s2_eas9_n%g_t%g" % pair, deck(coarse, counts[coarse], 9, pair,
                                             "Coarse mesh, HEX8 EAS 9, penalties (%g, %g)." % pair))
    softest = SOFT_PAIRS[-1]
    write("s2_eas9_augmented", deck(coarse, counts[coarse], 9, softest, "Coarse mesh, HEX8 EAS 9, "
                                    "augmented Lagrangian at the penalties (%g, %g)." % softest, variant=AUGMENTED))
    write("s2_eas9_autopenalty", deck(coarse, counts[coarse], 9, seed, "Coarse mesh, HEX8 EAS 9, "
                                      "automatic penalties.", variant=AUTOMATIC))


def write(name, text):
    with open(os.path.join(HERE, name + ".dck"), "w") as f:
        f.write(text)
    print("wrote", name + ".dck")


def main():
    if len(sys.argv) > 1:
        print(__doc__)
        return 0 if sys.argv[1] in ("-h", "--help") else 2
    counts = {}
    for mesh, refine in MESHES.values():
        counts[mesh] = write_mesh(os.path.join(HERE, mesh), refine)
        print("wrote", mesh, counts[mesh])
    write_decks(counts)
    return 0


if __name__ == "__main__":
    sys.exit(main())
