#!/usr/bin/python3
"""Hexahedral mesh of one eighth of the necking bar, written as a gmsh 2.2 ASCII file.

The bar of the necking benchmark (Simo 1988; Simo & Armero 1992; Simo & Hughes 1998;
de Souza Neto, Peric & Owen 2008): length L = 53.334, radius R = 6.413 (mm), with a
geometric imperfection, the radius reduced by 1.8 % at the centre. One eighth of it is
meshed: x >= 0, y >= 0, 0 <= z <= L/2 (z = 0 is the necking section, z = L/2 the loaded end).

Cross-section: an O-grid (butterfly) of the quarter disc, a square core [0, a] x [0, a]
(a = CORE x R) with n_core x n_core quadrilaterals and a curved outer layer of 2 n_core x
n_ring quadrilaterals between the core's sides x = a, y = a and the arc of radius R; no
element is degenerate. The cross-section is swept along z in n_axial layers whose lengths
grow geometrically from z = 0 to z = L/2 (the last one GRADING times the first), so that the
neck is resolved more finely. The imperfection scales x and y of every node by R(z)/R:
  linear (default): R(z) = R (1 - d (1 - z/l)) for z < l, R beyond (l = IMPERFECTION_LENGTH,
                    default L/2: 0.982 R at the centre varying linearly to R at the end),
  cosine:           R(z) = R (1 - d/2 (1 + cos(pi z/l))) for z < l, R beyond
                    (GetFEM's demo_finite_strain_plasticity_3D.py with l = L/2),
  none:             R(z) = R,
with d = REDUCTION (default 0.018).

Physical groups (frix turns them into sets, docs/deck-format.md "MESH FILE"):
  volume  "bar"    every hexahedron (element set and node set)
  surface "sym_x"  the face x = 0        "sym_y"  the face y = 0
          "sym_z"  the face z = 0 (the necking section, symmetry plane)
          "end"    the face z = L/2 (loaded end)          "outer"  the lateral surface
  point   "neck"   the outer node at (R(0), 0, 0): its u_x is the radial displacement of the
                   necking section
  point   "end_outer" the outer node at (R, 0, L/2)
The node ids of "neck" and "end_outer" are printed (the decks' HISTORY lines need them).

Standard library only. Examples (from the project root):
  /usr/bin/python3 inputs/meshes/necking_bar_mesh.py -o inputs/verification/necking_bar/necking_bar_coarse.msh
  /usr/bin/python3 inputs/meshes/necking_bar_mesh.py --n-core 4 --n-ring 4 --n-axial 24 \\
      -o inputs/verification/necking_bar/necking_bar_fine.msh
Defaults (n_core 2, n_ring 2, n_axial 10: 120 hexahedra, 209 nodes) make the coarse mesh.
"""
import argparse
import math
import sys


def parse_arguments(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog="See the module docstring (the head of this file) for details.")
    parser.add_argument("-o", "--output", required=True, help="gmsh 2.2 ASCII file to write")
    parser.add_argument("--length", type=float, default=53.334, help="total bar length L (default 53.334)")
    parser.add_argument("--radius", type=float, default=6.413, help="bar radius R (default 6.413)")
    parser.add_argument("--reduction", type=float, default=0.018,
                        help="relative radius reduction d at the centre (default 0.018)")
    parser.add_argument("--imperfection", choices=("linear", "cosine", "none"), default="linear",
                        help="shape of the radius reduction along z (default linear)")
    parser.add_argument("--imperfection-length", type=float, default=None,
                        help="length l from the centre over which the radius returns to R (default L/2)")
    parser.add_argument("--n-core", type=int, default=2, help="divisions of the square core's side (default 2)")
    parser.add_argument("--n-ring", type=int, default=2, help="radial divisions of the outer layer (default 2)")
    parser.add_argument("--n-axial", type=int, default=10, help="element layers along z (default 10)")
    parser.add_argument("--grading", type=float, default=4.0,
                        help="length of the last layer (z = L/2) over the first (z = 0) (default 4)")
    parser.add_argument("--core", type=float, default=0.5,
                        help="side of the square core as a fraction of R (default 0.5)")
    arguments = parser.parse_args(argv)
    problems = []
    if arguments.length <= 0 or arguments.radius <= 0:
        problems.append("--length and --radius must be positive")
    if not 0 <= arguments.reduction < 1:
        problems.append("--reduction must be in [0, 1)")
    if arguments.n_core < 1 or arguments.n_ring < 1 or arguments.n_axial < 1:
        problems.append("--n-core, --n-ring and --n-axial must be at least 1")
    if arguments.grading <= 0:
        problems.append("--grading must be positive")
    if not 0.2 <= arguments.core <= 0.65:
        problems.append("--core must be in [0.2, 0.65] (a larger core squashes the corner elements)")
    if arguments.imperfection_length is not None and arguments.imperfection_length <= 0:
        problems.append("--imperfection-length must be positive")
    if problems:
        parser.error("; ".join(problems))
    return arguments


def cross_section(radius, core, n_core, n_ring):
    """Nodes (x, y) and counter-clockwise quadrilaterals of the quarter disc of radius `radius`.

    Returns (points, quads, edges) with edges a dict of boundary edge lists: 'x0' (on x = 0),
    'y0' (on y = 0) and 'outer' (on the arc), each edge a pair of point indices, and the
    index of the point (radius, 0)."""
    a = core * radius
    points = []
    core_index = {}
    for j in range(n_core + 1):
        for i in range(n_core + 1):
            core_index[i, j] = len(points)
            points.append((a * i / n_core, a * j / n_core))

    def boundary(k):
        """The core node k = 0 .. 2 n_core along x = a (upwards), then y = a (leftwards)."""
        return core_index[n_core, k] if k <= n_core else core_index[2 * n_core - k, n_core]

    ring_index = {}
    for k in range(2 * n_core + 1):
        px, py = points[boundary(k)]
        angle = 0.5 * math.pi * k / (2 * n_core)
        qx, qy = radius * math.cos(angle), radius * math.sin(angle)
        if k == 2 * n_core:
            qx = 0.0      # exactly on x = 0
        if k == 0:
            qy = 0.0
        ring_index[k, 0] = boundary(k)
        for j in range(1, n_ring + 1):
            s = j / n_ring
            ring_index[k, j] = len(points)
            points.append((px + s * (qx - px), py + s * (qy - py)))

    quads = []
    for j in range(n_core):
        for i in range(n_core):
            quads.append((core_index[i, j], core_index[i + 1, j], core_index[i + 1, j + 1], core_index[i, j + 1]))
    for k in range(2 * n_core):
        for j in range(n_ring):
            quads.append((ring_index[k, j], ring_index[k, j + 1], ring_index[k + 1, j + 1], ring_index[k + 1, j]))

    edges = {"x0": [], "y0": [], "outer": []}
    for j in range(n_core):
        edges["x0"].append((core_index[0, j], core_index[0, j + 1]))
    for i in range(n_core):
        edges["y0"].append((core_index[i, 0], core_index[i + 1, 0]))
    for j in range(n_ring):
        edges["y0"].append((ring_index[0, j], ring_index[0, j + 1]))
        edges["x0"].append((ring_index[2 * n_core, j], ring_index[2 * n_core, j + 1]))
    for k in range(2 * n_core):
        edges["outer"].append((ring_index[k, n_ring], ring_index[k + 1, n_ring]))
    return points, quads, edges, ring_index[0, n_ring]


def axial_levels(half_length, n_axial, grading):
    """z of the n_axial + 1 levels, layer lengths in geometric progression (last/first = grading)."""
    if n_axial == 1 or abs(grading - 1.0) < 1e-12:
        return [half_length * m / n_axial for m in range(n_axial + 1)]
    ratio = grading ** (1.0 / (n_axial - 1))
    first = half_length * (ratio - 1.0) / (ratio ** n_axial - 1.0)
    levels = [0.0]
    for m in range(n_axial):
        levels.append(levels[-1] + first * ratio ** m)
    levels[-1] = half_length
    return levels


def radius_factor(z, arguments, half_length):
    """R(z)/R of the imperfection."""
    d = arguments.reduction
    span = arguments.imperfection_length if arguments.imperfection_length is not None else half_length
    if arguments.imperfection == "none" or z >= span:
        return 1.0
    if arguments.imperfection == "linear":
        return 1.0 - d * (1.0 - z / span)
    return 1.0 - 0.5 * d * (1.0 + math.cos(math.pi * z / span))


def build(arguments):
    half_length = 0.5 * arguments.length
    points, quads, edges, outer_point = cross_section(arguments.radius, arguments.core,
                                                      arguments.n_core, arguments.n_ring)
    levels = axial_levels(half_length, arguments.n_axial, arguments.grading)
    n2d = len(points)

    def node(level, local):
        return level * n2d + local + 1

    nodes = []
    for level, z in enumerate(levels):
        factor = radius_factor(z, arguments, half_length)
        for local, (x, y) in enumerate(points):
            nodes.append((node(level, local), factor * x, factor * y, z))

    hexahedra = []
    for level in range(len(levels) - 1):
        for quad in quads:
            hexahedra.append([node(level, q) for q in quad] + [node(level + 1, q) for q in quad])

    surfaces = {"sym_z": [[node(0, q) for q in quad] for quad in quads],
                "end": [[node(len(levels) - 1, q) for q in quad] for quad in quads]}
    for name, key in (("sym_x", "x0"), ("sym_y", "y0"), ("outer", "outer")):
        surfaces[name] = [[node(level, p), node(level, q), node(level + 1, q), node(level + 1, p)]
                          for level in range(len(levels) - 1) for p, q in edges[key]]
    points_named = {"neck": node(0, outer_point), "end_outer": node(len(levels) - 1, outer_point)}
    return nodes, hexahedra, surfaces, points_named, levels


def write_gmsh(path, nodes, hexahedra, surfaces, points_named):
    groups = [(0, 1, "neck"), (0, 2, "end_outer"), (2, 3, "sym_x"), (2, 4, "sym_y"), (2, 5, "sym_z"),
              (2, 6, "end"), (2, 7, "outer"), (3, 8, "bar")]
    lines = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$PhysicalNames", str(len(groups))]
    lines += [f'{dim} {tag} "{name}"' for dim, tag, name in groups]
    lines += ["$EndPhysicalNames", "$Nodes", str(len(nodes))]
    lines += [f"{i} {x:.15g} {y:.15g} {z:.15g}" for i, x, y, z in nodes]
    lines += ["$EndNodes"]
    elements = []
    for dim, tag, name in groups:
        if dim == 0:
            elements.append((15, tag, [points_named[name]]))
        elif dim == 2:
            elements += [(3, tag, quad) for quad in surfaces[name]]
        else:
            elements += [(5, tag, hexahedron) for hexahedron in hexahedra]
    lines += ["$Elements", str(len(elements))]
    lines += [f"{number} {kind} 2 {tag} {tag} " + " ".join(str(n) for n in connectivity)
              for number, (kind, tag, connectivity) in enumerate(elements, start=1)]
    lines += ["$EndElements"]
    with open(path, "w", encoding="ascii") as stream:
        stream.write("\n".join(lines) + "\n")


def main(argv=None):
    arguments = parse_arguments(argv)
    nodes, hexahedra, surfaces, points_named, levels = build(arguments)
    write_gmsh(arguments.output, nodes, hexahedra, surfaces, points_named)
    neck = nodes[points_named["neck"] - 1]
    print(f"{arguments.output}: {len(hexahedra)} hexahedra, {len(nodes)} nodes; "
          f"neck node {points_named['neck']} at ({neck[1]:.6g}, {neck[2]:.6g}, {neck[3]:.6g}), "
          f"end_outer node {points_named['end_outer']}; first layer dz = {levels[1] - levels[0]:.4g}, "
          f"last {levels[-1] - levels[-2]:.4g}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
