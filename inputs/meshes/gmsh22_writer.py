"""Write a hexahedral mesh as a gmsh 2.2 ASCII file with physical groups, as frix's gmsh reader
reads it (docs/deck-format.md, MESH FILE). Used by the deck generators of inputs/ (S2, S6).
Python standard library only."""
import io
import os


def write_gmsh22(path, comment, nodes, volumes, surfaces, points, number):
    """Write the file at `path` only if its text changed (a run reading it meanwhile is not
    disturbed). `nodes`: (x, y, z) per node, ids from 1; `volumes`: [(name, hexahedra)], each
    hexahedron 8 node ids in VTK order (gmsh type 5); `surfaces`: {name: [4 node ids]} (type 3);
    `points`: [(name, node id)] (type 15); physical tags 1, 2, ... in that order. `number`
    formats a coordinate."""
    names = [(3, n) for n, _ in volumes] + [(2, n) for n in surfaces] + [(0, n) for n, _ in points]
    out = io.StringIO()
    out.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n")
    out.write("$Comments\n%s\n$EndComments\n" % comment)
    out.write("$PhysicalNames\n%d\n" % len(names))
    for tag, (dim, name) in enumerate(names, start=1):
        out.write('%d %d "%s"\n' % (dim, tag, name))
    out.write("$EndPhysicalNames\n$Nodes\n%d\n" % len(nodes))
    for i, (x, y, z) in enumerate(nodes, start=1):
        out.write("%d %s %s %s\n" % (i, number(x), number(y), number(z)))
    out.write("$EndNodes\n")
    rows = []
    for tag, (_, hexes) in enumerate(volumes, start=1):
        rows += ["5 2 %d %d %s" % (tag, tag, " ".join(map(str, h))) for h in hexes]
    for tag, name in enumerate(surfaces, start=1 + len(volumes)):
        rows += ["3 2 %d %d %s" % (tag, tag, " ".join(map(str, f))) for f in surfaces[name]]
    for tag, (name, node) in enumerate(points, start=1 + len(volumes) + len(surfaces)):
        rows.append("15 2 %d %d %d" % (tag, tag, node))
    out.write("$Elements\n%d\n" % len(rows))
    for i, row in enumerate(rows, start=1):
        out.write("%d %s\n" % (i, row))
    out.write("$EndElements\n")
    text = out.getvalue()
    if not os.path.exists(path) or open(path).read() != text:
        with open(path, "w") as f:
            f.write(text)
