#!/usr/bin/env python3
"""Writes the plane strain Hertz mesh (gmsh 2.2 ASCII) of hertz_plane.dck: the half (x >= 0,
symmetry about x = 0) of an elastic cylinder of radius R pressed on an elastic block.

  make_hertz_mesh.py [--radius R] [--half-width A] [--per-a N] [--growth G] [--slab T] [-o FILE]

Cylinder: the part of the disc of radius R centred at (0, R) with x <= 0.8 R and y <= R (its
bottom the circle y = R - sqrt(R^2 - x^2), touching the block at the origin; top edge y = R).
Block: [0, 5 R] x [-5 R, 0]. Both structured QUAD4 meshes, counter-clockwise: element size
A / N over x in [0, 2 A] (A the expected contact half-width) and over a depth 2 A below the
block's top and above the cylinder's bottom, growing by the factor G beyond. The cylinder's
columns are 1.3 times wider than the block's near the contact (non-matching edges).

Physical groups: surfaces "cylinder", "block"; curves "cylinder_bottom" (the circular edge),
"cylinder_top" (y = R), "cylinder_xmin", "block_top", "block_bottom", "block_xmin".

--slab T: the same model as one layer of HEX8 from z = 0 to z = T (the plane mesh's nodes
keep their numbers in z = 0, those of z = T follow them); the groups are then volumes and
the quadrilateral faces over the curves.
"""
import argparse
import math

import gmsh22


def graded(length, fine, fine_length, growth):
    """Coordinates 0 .. length: steps `fine` up to fine_length, then each `growth` times the
    last, the last step stretched or shrunk to end at `length`."""
    x = [0.0]
    step = fine
    while x[-1] < fine_length - 1e-12 * length:
        x.append(min(x[-1] + fine, fine_length))
    while x[-1] < length - 1e-12 * length:
        step *= growth
        if x[-1] + 1.5 * step >= length:
            x.append(length)
        else:
            x.append(x[-1] + step)
    return x


def block_mesh(nodes, xs, ys, first):
    """Nodes of the grid xs x ys (x fastest) from number `first`, and its quads (CCW)."""
    ids = []
    for j, y in enumerate(ys):
        row = []
        for x in xs:
            nodes.append((x, y))
            row.append(first + len(nodes) - 1)
        ids.append(row)
    quads = [(ids[j][i], ids[j][i + 1], ids[j + 1][i + 1], ids[j + 1][i])
             for j in range(len(ys) - 1) for i in range(len(xs) - 1)]
    return ids, quads


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--radius", type=float, default=1.0)
    parser.add_argument("--half-width", type=float, default=0.05)
    parser.add_argument("--per-a", type=int, default=20)
    parser.add_argument("--growth", type=float, default=1.15)
    parser.add_argument("--slab", type=float, default=None, help="thickness of a HEX8 layer")
    parser.add_argument("-o", "--output", default="hertz_plane.msh")
    args = parser.parse_args()
    r, a = args.radius, args.half_width
    h = a / args.per_a

    nodes = []   # (x, y), numbered from 1 in order
    # block: x in [0, 5R], y in [-5R, 0] (fine at the top)
    bx = graded(5 * r, h, 2 * a, args.growth)
    depth = graded(5 * r, h, 2 * a, args.growth)
    by = [-d for d in reversed(depth)]
    block_ids, block_quads = block_mesh(nodes, bx, by, 1)
    # cylinder: columns x in [0, 0.8R] (1.3 h near the contact), rows from the circle to y = R
    cx = graded(0.8 * r, 1.3 * h, 2 * a, args.growth)
    heights = graded(1.0, 1.3 * h / r, 2 * a / r, args.growth)   # parameter along each column
    cyl_ids = []
    for t in heights:
        row = []
        for x in cx:
            bottom = r - math.sqrt(r * r - x * x)
            # the fine rows keep the size 1.3 h near the circle: the first part of the
            # parameter maps to the distance above the circle, the rest stretches to y = R
            nodes.append((x, bottom + t * (r - bottom)))
            row.append(len(nodes))
        cyl_ids.append(row)
    cyl_quads = [(cyl_ids[j][i], cyl_ids[j][i + 1], cyl_ids[j + 1][i + 1], cyl_ids[j + 1][i])
                 for j in range(len(heights) - 1) for i in range(len(cx) - 1)]

    lines = {
        "block_top": [(block_ids[-1][i], block_ids[-1][i + 1]) for i in range(len(bx) - 1)],
        "block_bottom": [(block_ids[0][i + 1], block_ids[0][i]) for i in range(len(bx) - 1)],
        "block_xmin": [(block_ids[j + 1][0], block_ids[j][0]) for j in range(len(by) - 1)],
        "cylinder_bottom": [(cyl_ids[0][i], cyl_ids[0][i + 1]) for i in range(len(cx) - 1)],
        "cylinder_top": [(cyl_ids[-1][i + 1], cyl_ids[-1][i]) for i in range(len(cx) - 1)],
        "cylinder_xmin": [(cyl_ids[j + 1][0], cyl_ids[j][0]) for j in range(len(heights) - 1)],
    }
    surfaces = {"block": block_quads, "cylinder": cyl_quads}
    names = list(lines) + list(surfaces)
    tag = {name: k + 1 for k, name in enumerate(names)}
    n_plane = len(nodes)
    # gmsh types: 1 line, 3 quadrangle, 5 hexahedron; a slab lifts each by one dimension
    kinds = {"line": 1, "area": 3}
    coordinates = [(x, y, 0.0) for x, y in nodes]
    if args.slab is not None:
        coordinates += [(x, y, args.slab) for x, y in nodes]
        lines = {n: [(a, b, b + n_plane, a + n_plane) for a, b in e] for n, e in lines.items()}
        surfaces = {n: [q + tuple(k + n_plane for k in q) for q in e] for n, e in surfaces.items()}
        kinds = {"line": 3, "area": 5}
    dimension = 1 + (args.slab is not None)
    gmsh22.write(args.output,
                 [(dimension + (name in surfaces), tag[name], name) for name in names],
                 [(k, f"{x:.12g} {y:.12g} {z:.12g}") for k, (x, y, z) in enumerate(coordinates, 1)],
                 [(kinds["line"], tag[n], e) for n in lines for e in lines[n]] +
                 [(kinds["area"], tag[n], e) for n in surfaces for e in surfaces[n]])
    print(f"{args.output}: {len(coordinates)} nodes, {len(block_quads)} + {len(cyl_quads)} quads "
          f"(block {len(bx) - 1} x {len(by) - 1}, cylinder {len(cx) - 1} x {len(heights) - 1})")


if __name__ == "__main__":
    main()
