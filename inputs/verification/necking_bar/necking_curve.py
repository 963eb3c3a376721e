#!/usr/bin/python3
"""necking_curve.py RUN_BASE MESH [-o CSV] [--check-ratio REF TOL] [--check-peak REF TOL] [--section PNG]

The curves of the necking bar (docs/verification/necking_bar.md) from a frix run on one
eighth of the bar (inputs/meshes/necking_bar_mesh.py): RUN_BASE is the run's base path
(`out/necking_bar_coarse_eas9` for `out/necking_bar_coarse_eas9_listing.txt`), MESH its gmsh
file, whose physical groups "end" (the face z = L/2) and "neck" (the outer node of the
section z = 0 on y = 0) are used.

Per converged increment (from the listing, docs/listing-format.md):
  u_end       prescribed end displacement (u_z of the face z = L/2), on the half bar
  u_r_neck    radial displacement of the outer node of the necking section (its u_x)
  ratio       current / initial radius of the necking section at that node, (r0 + u_r) / r0
              with r0 the imperfect radius of that section (the node's x in the mesh)
  area_ratio  the same from the section's area, sqrt(A / A0) with A, A0 the current and the
              initial area of the section z = 0 as meshed (face "sym_z"): the mean radius
              ratio, equal to `ratio` where the section stays circular; on a coarse mesh the
              section does not (the nodes at 45 degrees move in more than those on the axes)
  force       axial force of the whole bar: 4 x the sum of the end face's reactions R_z
              (the model is a quarter of the cross-section)
  nominal_stress  force / A_neck, A_neck the initial area of the necking section as meshed
              (4 x the area of the face "sym_z": the meshed polygon, up to 2.5 % below
              pi r0^2 on a coarse mesh)
  iterations  Newton iterations of the increment
written to CSV (-o, default RUN_BASE_curve.csv), for postproc/plot_history.py.

--section PNG draws the necking section z = 0 (its elements, undeformed in grey and at the
last increment in black, with circles of the mean radii) and the outer generator y = 0 at
the last increment: it shows whether the section stayed circular.

Checks (exit status 1 if one fails, 2 on a usage error):
  --check-ratio REF TOL  |area_ratio(last increment) - REF| <= TOL (absolute)
  --check-peak REF TOL   |max nominal_stress - REF| <= TOL |REF| (relative), and the force of
                         the last increment at least 0.5 % below its maximum
Run with /usr/bin/python3 (numpy; matplotlib for --section).
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "postproc"))
import frix_results  # noqa: E402


def read_gmsh_groups(path):
    """Coordinates {id: (x, y, z)}, the node ids of each named physical group and the
    quadrilaterals (node id lists) of each (2.2 ASCII)."""
    frix_results.require_file(path, "mesh")
    try:
        with open(path, encoding="ascii") as stream:
            lines = stream.read().splitlines()
        return parse_gmsh_groups(lines)
    except (OSError, UnicodeDecodeError, ValueError, IndexError) as error:
        raise frix_results.UserError(f"{path}: not a gmsh 2.2 ASCII mesh of necking_bar_mesh.py ({error})") from None


def parse_gmsh_groups(lines):
    names, coordinates, groups, quads = {}, {}, {}, {}
    i = lines.index("$PhysicalNames")
    for line in lines[i + 2:i + 2 + int(lines[i + 1])]:
        dim, tag, name = line.split(maxsplit=2)
        names[int(tag)] = name.strip('"')
    i = lines.index("$Nodes")
    for line in lines[i + 2:i + 2 + int(lines[i + 1])]:
        fields = line.split()
        coordinates[int(fields[0])] = tuple(float(v) for v in fields[1:4])
    i = lines.index("$Elements")
    for line in lines[i + 2:i + 2 + int(lines[i + 1])]:
        fields = [int(v) for v in line.split()]
        n_tags = fields[2]
        name = names.get(fields[3])
        if name is not None:
            groups.setdefault(name, set()).update(fields[3 + n_tags:])
            if fields[1] == 3:
                quads.setdefault(name, []).append(fields[3 + n_tags:])
    return coordinates, groups, quads


def section_area(coordinates, quads, displacements=None):
    """Area of the quarter section z = 0 as meshed (a polygon; shoelace formula), in the
    reference configuration or, with `displacements` {id: (ux, uy, uz)}, the current one (the
    section stays in the plane z = 0 by symmetry)."""
    area = 0.0
    for quad in quads:
        points = [coordinates[n][:2] for n in quad]
        if displacements is not None:
            points = [(x + displacements[n][0], y + displacements[n][1]) for (x, y), n in zip(points, quad)]
        area += 0.5 * abs(sum(points[k][0] * points[k - 3][1] - points[k - 3][0] * points[k][1]
                              for k in range(4)))
    return area


def last_displacements(base):
    increment = frix_results.read_listing(base + "_listing.txt")[-1]
    block = increment.blocks["NODAL DISPLACEMENTS"]
    return increment, dict(zip(block[2], block[3]))


def plot_section(base, mesh, path):
    """The section z = 0 before and after, and the outer generator on y = 0 (PNG)."""
    plt = frix_results.use_agg_backend()
    coordinates, groups, quads = read_gmsh_groups(mesh)
    increment, u = last_displacements(base)
    figure, (left, right) = plt.subplots(1, 2, figsize=(10, 4.8), gridspec_kw={"width_ratios": [1, 1.3]})
    for quad in quads["sym_z"]:
        loop = quad + quad[:1]
        left.plot([coordinates[n][0] for n in loop], [coordinates[n][1] for n in loop], color="0.75", lw=0.6)
        left.plot([coordinates[n][0] + u[n][0] for n in loop], [coordinates[n][1] + u[n][1] for n in loop],
                  color="k", lw=0.8)
    area0 = section_area(coordinates, quads["sym_z"])
    area = section_area(coordinates, quads["sym_z"], u)
    angles = [0.5 * math.pi * k / 90 for k in range(91)]
    for value, style in ((area0, "--"), (area, ":")):
        radius = math.sqrt(4.0 * value / math.pi)
        left.plot([radius * math.cos(a) for a in angles], [radius * math.sin(a) for a in angles], "r" + style, lw=0.8)
    left.set_aspect("equal")
    left.set_xlabel("x")
    left.set_ylabel("y")
    left.set_title("section z = 0 (red: circles of equal area)")
    generator = sorted((n for n in groups["outer"] if abs(coordinates[n][1]) < 1e-12), key=lambda n: coordinates[n][2])
    right.plot([coordinates[n][2] for n in generator], [coordinates[n][0] for n in generator], color="0.6",
               marker=".", lw=0.8, label="initial")
    right.plot([coordinates[n][2] + u[n][2] for n in generator], [coordinates[n][0] + u[n][0] for n in generator],
               color="k", marker=".", lw=0.8, label=f"t = {increment.time:.4g}")
    right.set_xlabel("z")
    right.set_ylabel("outer radius on y = 0")
    right.set_ylim(bottom=0)
    right.legend()
    right.set_title("outer generator")
    figure.suptitle(os.path.basename(base))
    frix_results.save_figure(figure, path)


def curve(base, mesh):
    coordinates, groups, quads = read_gmsh_groups(mesh)
    for name in ("end", "neck", "sym_z"):
        if name not in groups:
            raise frix_results.UserError(f"{mesh}: no physical group '{name}'")
    (neck,) = groups["neck"]
    end = groups["end"]
    r0 = coordinates[neck][0]
    area = 4.0 * section_area(coordinates, quads["sym_z"])
    rows = []
    for increment in frix_results.read_listing(base + "_listing.txt"):
        displacement = increment.blocks["NODAL DISPLACEMENTS"]
        reaction = increment.blocks["REACTIONS (constrained DOFs only)"]
        u = dict(zip(displacement[2], displacement[3]))
        force = 4.0 * sum(row[2] for key, row in zip(reaction[2], reaction[3]) if key in end)
        u_end = max(u[n][2] for n in end)
        u_r = u[neck][0]
        rows.append((increment.step, increment.increment, increment.time, u_end, u_r,
                     (r0 + u_r) / r0, math.sqrt(4.0 * section_area(coordinates, quads["sym_z"], u) / area),
                     force, force / area, increment.iterations))
    return r0, area, rows


def main(argv=None):
    parser = frix_results.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("base", help="run base path (BASE_listing.txt is read)")
    parser.add_argument("mesh", help="the run's gmsh mesh (physical groups 'end' and 'neck')")
    parser.add_argument("-o", "--output", help="CSV to write (default BASE_curve.csv)")
    parser.add_argument("--check-ratio", nargs=2, type=float, metavar=("REF", "TOL"))
    parser.add_argument("--check-peak", nargs=2, type=float, metavar=("REF", "TOL"))
    parser.add_argument("--section", metavar="PNG", help="draw the necking section at the last increment")
    arguments = parser.parse_args(argv)
    if arguments.section:
        plot_section(arguments.base, arguments.mesh, arguments.section)
    r0, area, rows = curve(arguments.base, arguments.mesh)
    if not rows:
        raise frix_results.UserError(f"{arguments.base}_listing.txt: no converged increment")
    output = arguments.output or arguments.base + "_curve.csv"
    with open(output, "w", encoding="ascii") as stream:
        stream.write("step,increment,time,u_end,u_r_neck,ratio,area_ratio,force,nominal_stress,iterations\n")
        for row in rows:
            stream.write("%d,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d\n" % row)
    peak = max(rows, key=lambda row: row[7])
    last = rows[-1]
    print(f"necking bar: r0 = {r0:.6f}, necking section area {area:.4f} (as meshed); at u_end = {last[3]:.6g}: "
          f"u_r = {last[4]:.6f}, ratio = {last[5]:.6f}, area_ratio = {last[6]:.6f}; peak force {peak[7]:.1f} "
          f"(nominal stress {peak[8]:.3f}) at u_end = {peak[3]:.4f}; {len(rows)} increments, "
          f"{sum(row[9] for row in rows)} Newton iterations; curve in {output}")
    status = 0
    if arguments.check_ratio:
        reference, tolerance = arguments.check_ratio
        ok = abs(last[6] - reference) <= tolerance
        print(f"{'ok  ' if ok else 'FAIL'} radius ratio (area_ratio) at u_end = {last[3]:.6g}: {last[6]:.6f}, "
              f"expected {reference:.6f} +- {tolerance:.4f}")
        status |= 0 if ok else 1
    if arguments.check_peak:
        reference, tolerance = arguments.check_peak
        error = (peak[8] - reference) / abs(reference)
        # a maximum: the force has fallen by 0.5 % after it (else the run stopped before it)
        passed = last[7] < 0.995 * peak[7]
        ok = abs(error) <= tolerance and passed
        if not passed:
            print("FAIL the largest force is not a maximum: the run ends before the force falls by 0.5 %")
        print(f"{'ok  ' if ok else 'FAIL'} peak nominal stress of the necking section: {peak[8]:.3f}, "
              f"expected {reference:.3f}, "
              f"relative error {error:+.3e} (tolerance {tolerance:.1e})")
        status |= 0 if ok else 1
    return status


if __name__ == "__main__":
    frix_results.run_main(main)
