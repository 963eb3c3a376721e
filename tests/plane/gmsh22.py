"""Writes a gmsh 2.2 ASCII mesh, the format frix reads (docs/deck-format.md, MESH FILE); used
by make_hertz_mesh.py and make_s5_plane.py."""


def write(path, physical_names, nodes, elements):
    """physical_names: (dimension, tag, name) each; nodes: (id, "x y z" as written) each;
    elements: (gmsh type, physical tag, node ids) each, numbered from 1 in this order (the
    physical tag is also written as the elementary one)."""
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n%d\n" % len(physical_names))
        for dimension, tag, name in physical_names:
            f.write(f'{dimension} {tag} "{name}"\n')
        f.write("$EndPhysicalNames\n$Nodes\n%d\n" % len(nodes))
        for n, text in nodes:
            f.write(f"{n} {text}\n")
        f.write("$EndNodes\n$Elements\n%d\n" % len(elements))
        for k, (kind, physical, connectivity) in enumerate(elements, 1):
            f.write(f"{k} {kind} 2 {physical} {physical} " + " ".join(map(str, connectivity)) + "\n")
        f.write("$EndElements\n")
