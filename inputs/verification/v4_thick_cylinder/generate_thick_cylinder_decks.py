#!/usr/bin/python3
"""Generate the V4 thick-cylinder mesh and decks (docs/verification/v4_thick_cylinder.md).

Plane strain quarter of a tube, a = 1, b = 2, one element through z (length 0.1), u_z = 0 on
both faces, symmetry u_y = 0 on theta = 0 and u_x = 0 on theta = 90 degrees. E = 210000,
nu = 0.3, von Mises perfectly plastic with sigma_y = 240 (MAT_3DMisesPlastic without HARD),
small strain (Geo_Lin). Internal pressure on the inner surface.

Mesh `quarter.msh` (inputs/meshes/ring_mesh.py): 20 radial elements, the outermost twice as
large as the innermost, x 8 around x 1. Node ids 1 + i + 21 (j + 9 k): node 1 = (a, 0, 0),
node 21 = (b, 0, 0), node 169 = (0, a, 0), node 189 = (0, b, 0).

Decks:
  cylinder_elastic_<v>.dck  p = 100 < p_y = 103.75 in one increment (v = hex8, eas9, eas21, eas30)
  cylinder_plastic_<v>.dck  load control: p = 150 (t = 1), 180 (t = 2), then towards
                            1.05 p_limit = 201.69 (t = 3), where the run stops at the limit
  cylinder_path_<v>.dck     the same to p = 180, then path control of u_x at node 1 past the
                            limit (the peak of the load factor is the model's limit load)

    /usr/bin/python3 inputs/verification/v4_thick_cylinder/generate_thick_cylinder_decks.py
"""
import math
import os
import textwrap
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
A, B, YOUNG, NU, SIGY = 1.0, 2.0, 210000.0, 0.3, 240.0
LENGTH, NR, NTHETA, GRADING = 0.1, 20, 8, 2.0
P_ELASTIC = 100.0
P_LIMIT = 2.0 / math.sqrt(3.0) * SIGY * math.log(B / A)     # Hill (1950) ch. V: 192.09
P_END = round(1.05 * P_LIMIT, 2)                            # 201.69
VARIANTS = {"hex8": 0, "eas9": 9, "eas21": 21, "eas30": 30}
MESH_ARGS = ["--inner", "1", "--outer", "2", "--theta", "0", "90", "--length", f"{LENGTH:g}",
             "--nr", str(NR), "--ntheta", str(NTHETA), "--nz", "1", "--grading", f"{GRADING:g}",
             "--name", "tube", "-o", "quarter.msh"]


def node(i, j, k=0):
    return 1 + i + (NR + 1) * (j + (NTHETA + 1) * k)


INNER_X, OUTER_X, INNER_Y, OUTER_Y = node(0, 0), node(NR, 0), node(0, NTHETA), node(NR, NTHETA)


def lame_ur(p, r):
    """Lame, plane strain: u_r = (1 + nu)/E ((1 - 2 nu) A r + B/r), A = p a^2/(b^2 - a^2),
    B = p a^2 b^2/(b^2 - a^2) (Timoshenko & Goodier, Theory of Elasticity, 3rd ed. 1970, ch. 4)."""
    a2, b2 = A * A, B * B
    ca, cb = p * a2 / (b2 - a2), p * a2 * b2 / (b2 - a2)
    return (1.0 + NU) / YOUNG * ((1.0 - 2.0 * NU) * ca * r + cb / r)


def first_yield():
    """von Mises at r = a with sigma_z = nu (sigma_r + sigma_theta):
    sigma_vm^2 = 3 (B/a^2)^2 + (1 - 2 nu)^2 A^2 = sigma_y^2."""
    return SIGY * (B * B - A * A) / math.sqrt(3.0 * B ** 4 + (1.0 - 2.0 * NU) ** 2 * A ** 4)


def mesh_comment():
    """The generator's command as comment lines of at most 96 characters."""
    return ["// " + line for line in textwrap.wrap(
        "made by inputs/meshes/ring_mesh.py " + " ".join(MESH_ARGS), 93, subsequent_indent="    ")]


def section(name):
    return "-" * (68 - len(name)) + name


def header(lines):
    return ["=" * 66] + [" " + line for line in lines] + ["=" * 66]


def common(eas, kintyp="Geo_Lin", maxcut=4):
    element = "HEX8" + (f" EAS {eas}" if eas else "")
    return {
        "static": [section("PROBLEM TYP"), "PROBLEMTYP   Structure",
                   section("STATIC"), f"KINTYP       {kintyp}", "MAXITER      25",
                   "TOLRESID     1.0e-9", "TOLDISP      1.0e-9", f"MAXCUT       {maxcut}",
                   "SOLVER       Auto"],
        "body": [section("MATERIALS"),
                 f"MAT 1 MAT_3DMisesPlastic YOUNG {YOUNG:.1f} NUE {NU} SIGY {SIGY:.1f}   // perfectly plastic (no HARD)",
                 section("MESH FILE"),
                 ] + mesh_comment() + ["FILE quarter.msh",
                 section("STRUCTURE ELEMENTS"),
                 f"SET tube SOLID {element} MAT 1",
                 section("DIRICHLET CONDITIONS"),
                 "SET tube_theta0 DOF 0 1 0 VAL 0.0 0.0 0.0    // symmetry y = 0",
                 "SET tube_theta1 DOF 1 0 0 VAL 0.0 0.0 0.0    // symmetry x = 0",
                 "SET tube_z0     DOF 0 0 1 VAL 0.0 0.0 0.0    // plane strain",
                 "SET tube_z1     DOF 0 0 1 VAL 0.0 0.0 0.0"],
        "history": [f"HISTORY NODE {INNER_X} DOF 1 KIND U    // u_r(a) at theta = 0",
                    f"HISTORY NODE {OUTER_X} DOF 1 KIND U   // u_r(b) at theta = 0",
                    f"HISTORY NODE {INNER_Y} DOF 2 KIND U  // u_r(a) at theta = 90",
                    f"HISTORY NODE {OUTER_Y} DOF 2 KIND U  // u_r(b) at theta = 90"],
    }


MESH_TEXT = ("Mesh quarter.msh: 20 radial elements graded 2:1 toward the inside x 8 around "
             "x 1 through z (0.1)")


def elastic_deck(variant, eas):
    c = common(eas)
    title = header([
        f"V4a thick cylinder, elastic: HEX8{' EAS ' + str(eas) if eas else ''}, small strain, plane strain quarter",
        "a = 1, b = 2, E = 210000, nu = 0.3, von Mises sigma_y = 240 (perfectly plastic, no HARD).",
        MESH_TEXT + ".",
        "Supports: u_y = 0 on theta = 0, u_x = 0 on theta = 90 deg, u_z = 0 on both faces.",
        f"Internal pressure p = {P_ELASTIC:g} in one increment: below first yield p_y = {first_yield():.2f},",
        "so no point yields (listing: YIELDING POINTS 0).",
        "Expected (Lame, plane strain, Timoshenko & Goodier ch. 4):",
        f"  u_r(a) = {lame_ur(P_ELASTIC, A):.6e} (u1_n{INNER_X}, u2_n{INNER_Y}),"
        f" u_r(b) = {lame_ur(P_ELASTIC, B):.6e} (u1_n{OUTER_X}, u2_n{OUTER_Y}), within 0.5 %.",
        "Generated by inputs/verification/v4_thick_cylinder/generate_thick_cylinder_decks.py"])
    lines = title + c["static"] + c["body"] + [
        section("NEUMANN CONDITIONS"), f"SURF tube_inner PRESSURE {P_ELASTIC:g}",
        section("STEPS"), "STEP 1 NUMSTEP 1 CONTROL Load",
        section("RESULTS"), "VTK Yes  LISTING Yes  EVERY 1"] + c["history"] + [section("END")]
    return lines


def plastic_deck(variant, eas, path):
    c = common(eas, maxcut=8)
    p_c1, p_c2 = 150.0, 180.0
    if path:
        last = "STEP 3 NUMSTEP 20 CONTROL Path NODE 1 DOF 1 TARGET 0.02   // u_r(a) past the limit"
        what = [f"Step 3: path control, u_x of node {INNER_X} (u_r(a)) driven to 0.02 in 20 increments; the",
                f"load p = 180 + (t - 2)({P_END:.2f} - 180) is solved for and levels off at the model's limit load.",
                "Expected: the peak pressure within 2 % of p_limit = (2/sqrt 3) sigma_y ln(b/a) = 192.09",
                "(plane strain, von Mises, Hill 1950 ch. V)."]
    else:
        last = "STEP 3 NUMSTEP 10 CONTROL Load"
        what = [f"Step 3: p from 180 towards {P_END:.2f} = 1.05 p_limit in 10 increments (load control).",
                "Expected: frix stops at the limit load (exit status 1, 'failed ... at the smallest",
                "increment allowed'); the last converged pressure is within 2 % of",
                "p_limit = (2/sqrt 3) sigma_y ln(b/a) = 192.09 (plane strain, von Mises, Hill 1950 ch. V)."]
    title = header([
        f"V4b/c thick cylinder, elastic-perfectly plastic: HEX8{' EAS ' + str(eas) if eas else ''}, small strain,",
        "plane strain quarter, " + ("path control past the limit" if path else "load control to the limit"),
        "a = 1, b = 2, E = 210000, nu = 0.3, von Mises sigma_y = 240 (perfectly plastic, no HARD).",
        MESH_TEXT + ".",
        "Supports: u_y = 0 on theta = 0, u_x = 0 on theta = 90 deg, u_z = 0 on both faces.",
        "Internal pressure p = f(t), CURVE 1: p = 150 at t = 1 (15 increments), 180 at t = 2 (6 increments).",
        "Expected plastic front (Hill 1950 ch. V, k = sigma_y/sqrt 3, p = k (2 ln(c/a) + 1 - c^2/b^2)):",
        f"  c = {hill_front(p_c1):.4f} at p = 150, c = {hill_front(p_c2):.4f} at p = 180 (EQPS > 0 inside c; HDF5 fields/eqps).",
    ] + what + ["Generated by inputs/verification/v4_thick_cylinder/generate_thick_cylinder_decks.py"])
    lines = title + c["static"] + [
        section("LOAD CURVES"),
        f"CURVE 1 POINTS 0.0 0.0  1.0 {p_c1:g}  2.0 {p_c2:g}  3.0 {P_END:.2f}   // the pressure"
    ] + c["body"] + [
        section("NEUMANN CONDITIONS"), "SURF tube_inner PRESSURE 1.0 CURVE 1",
        section("STEPS"), "STEP 1 NUMSTEP 15 CONTROL Load", "STEP 2 NUMSTEP 6 CONTROL Load", last,
        section("RESULTS"), "VTK Yes  LISTING Yes  HDF5 Yes  EVERY 1"] + c["history"] + [section("END")]
    return lines


def hill_front(p):
    """c with p = k (2 ln(c/a) + 1 - c^2/b^2), k = sigma_y/sqrt(3) (bisection on [a, b])."""
    k = SIGY / math.sqrt(3.0)
    low, high = A, B
    for _ in range(200):
        c = 0.5 * (low + high)
        if k * (2.0 * math.log(c / A) + 1.0 - c * c / (B * B)) < p:
            low = c
        else:
            high = c
    return 0.5 * (low + high)


def write(name, lines):
    with open(os.path.join(HERE, name), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote", os.path.relpath(os.path.join(HERE, name), ROOT))


def main():
    subprocess.run([sys.executable, os.path.join(ROOT, "inputs", "meshes", "ring_mesh.py")] + MESH_ARGS,
                   cwd=HERE, check=True)
    for variant, eas in VARIANTS.items():
        write(f"cylinder_elastic_{variant}.dck", elastic_deck(variant, eas))
    for variant in ("hex8", "eas9", "eas21"):
        write(f"cylinder_plastic_{variant}.dck", plastic_deck(variant, VARIANTS[variant], False))
    write("cylinder_path_eas9.dck", plastic_deck("eas9", 9, True))


if __name__ == "__main__":
    main()
