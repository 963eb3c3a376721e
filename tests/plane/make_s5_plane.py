#!/usr/bin/env python3
"""Writes the plane strain mesh of S5 (gmsh 2.2) from the one-layer HEX8 mesh of
inputs/s5_buried_pipe (x-z plane, one element through y from y = 0 to y = T):

  make_s5_plane.py INPUT.msh OUTPUT.msh

The nodes of y = 0 keep their numbers and move to (x, y) = (x, z) of the 3D mesh, z = 0; each
hexahedron becomes the quadrilateral of its y = 0 face, counter-clockwise in the x-y plane;
each quadrilateral of a physical surface that spans y becomes the line of its y = 0 nodes
(the surface's physical name kept, now a curve); the volumes' names go to the surfaces; the
surfaces lying in y = 0 or y = T ("front", "back") and the nodes of y = T are left out;
physical points are kept. A 2D model on this mesh with PLANE4 of THICKNESS T is the 3D model
with u_y = 0 (docs/verification/two-d.md).
"""
import math
import sys

import gmsh22


def read(path):
    with open(path) as f:
        lines = [line.strip() for line in f]
    names, nodes, elements = {}, {}, []
    k = lines.index("$PhysicalNames")
    for line in lines[k + 2:k + 2 + int(lines[k + 1])]:
        dim, tag, name = line.split(maxsplit=2)
        names[int(tag)] = (int(dim), name.strip('"'))
    k = lines.index("$Nodes")
    for line in lines[k + 2:k + 2 + int(lines[k + 1])]:
        n, x, y, z = line.split()
        nodes[int(n)] = (float(x), float(y), float(z))
    k = lines.index("$Elements")
    for line in lines[k + 2:k + 2 + int(lines[k + 1])]:
        fields = [int(v) for v in line.split()]
        kind, n_tags = fields[1], fields[2]
        elements.append((kind, fields[3], fields[3 + n_tags:]))
    return names, nodes, elements


def main():
    names, nodes, elements = read(sys.argv[1])
    front = {n for n, (x, y, z) in nodes.items() if y == 0.0}
    out = []   # (gmsh type, physical tag, nodes)
    for kind, physical, connectivity in elements:
        if kind == 15:                      # point
            out.append((15, physical, connectivity))
        elif kind == 5:                     # hexahedron: its y = 0 face, counter-clockwise in (x, z)
            face = [n for n in connectivity if n in front]
            cx = sum(nodes[n][0] for n in face) / 4
            cz = sum(nodes[n][2] for n in face) / 4
            face.sort(key=lambda n: math.atan2(nodes[n][2] - cz, nodes[n][0] - cx))
            out.append((3, physical, face))
        elif kind == 3:                     # quadrangle of a surface: the line of its y = 0 nodes
            edge = [n for n in connectivity if n in front]
            if len(edge) == 2:
                out.append((1, physical, edge))
        else:
            sys.exit(f"make_s5_plane.py: element type {kind} not expected")
    used = sorted({physical for _, physical, _ in out})
    dimension = {15: 0, 1: 1, 3: 2}
    dims = {physical: dimension[kind] for kind, physical, _ in out}
    gmsh22.write(sys.argv[2], [(dims[tag], tag, names[tag][1]) for tag in used],
                 [(n, f"{nodes[n][0]!r} {nodes[n][2]!r} 0") for n in sorted(front)], out)
    print(f"{sys.argv[2]}: {len(front)} nodes, {sum(1 for e in out if e[0] == 3)} quadrilaterals, "
          f"{sum(1 for e in out if e[0] == 1)} lines")


if __name__ == "__main__":
    main()
