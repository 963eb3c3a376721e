#!/usr/bin/python3
"""ring_mesh.py: a gmsh 2.2 ASCII mesh of a hollow cylinder sector, 8-node hexahedra.

What it writes: the solid a <= r <= b, theta_start <= theta <= theta_end (degrees, measured
from the x axis towards y), 0 <= z <= L, cut into nr x ntheta x nz hexahedra (gmsh type 5,
whose node order is VTK's and frix's: nodes 1-4 counter-clockwise at the lower z, node k+4
above node k; every element has a positive Jacobian). The element edges are straight: the
nodes lie on the circles r = r_i, the faces between them are flat.

Radial division: nr elements whose sizes grow geometrically from the inside to the outside;
--grading G is the size of the outermost element divided by the innermost (G = 1: uniform;
G > 1: finer toward the inside, where the stresses of a pressurised tube vary most; with
G = (b/a)^((nr-1)/nr) the radii are r_i = a (b/a)^(i/nr), elements of one shape).

Node ids: node (i, j, k), i = 0..nr radially (inside out), j = 0..ntheta by angle (from
theta_start), k = 0..nz along z, has the id 1 + i + (nr+1) (j + (ntheta+1) k) (i fastest);
element (i, j, k), i < nr, j < ntheta, k < nz, the id 1 + i + nr (j + ntheta k). The
boundary quadrilaterals follow with ids from nr ntheta nz + 1, oriented with the outward
normal.

Physical groups (named in $PhysicalNames; frix reads a volume as an element set and a node
set, a surface as a surface and a node set, docs/deck-format.md "MESH FILE"):
  3D <name>          the volume (all hexahedra)
  2D <name>_inner    r = a                 2D <name>_outer    r = b
  2D <name>_theta0   theta = theta_start   2D <name>_theta1   theta = theta_end
  2D <name>_z0       z = 0                 2D <name>_z1       z = L
A $Comments section (which gmsh and frix skip) records the command line.

Example (the V4 quarter of docs/verification/v4_thick_cylinder.md):
    /usr/bin/python3 inputs/meshes/ring_mesh.py --inner 1 --outer 2 --theta 0 90 \\
        --length 0.1 --nr 20 --ntheta 8 --nz 1 --grading 2 -o quarter.msh
Only the standard library is used.
"""
import argparse
import math
import os
import sys


def radii(a, b, nr, grading):
    """nr + 1 radii from a to b, element sizes in geometric progression: last / first = grading."""
    if nr == 1 or grading == 1.0:
        sizes = [1.0] * nr
    else:
        q = grading ** (1.0 / (nr - 1))
        sizes = [q ** i for i in range(nr)]
    total = sum(sizes)
    r = [a]
    for h in sizes[:-1]:
        r.append(r[-1] + (b - a) * h / total)
    r.append(b)
    return r


def unit_direction(degrees):
    """(cos, sin) of an angle in degrees, exact at multiples of 90 degrees."""
    quarter = degrees / 90.0
    if quarter == round(quarter):
        return [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)][int(round(quarter)) % 4]
    angle = math.radians(degrees)
    return math.cos(angle), math.sin(angle)


def number(value):
    """Shortest text that reads back to the same double; no negative zero."""
    return repr(value + 0.0) if value != 0.0 else "0"


def build(args):
    nr, nt, nz = args.nr, args.ntheta, args.nz
    r = radii(args.inner, args.outer, nr, args.grading)
    t0, t1 = args.theta
    directions = [unit_direction(t0 + (t1 - t0) * j / nt) for j in range(nt + 1)]
    zs = [args.length * k / nz for k in range(nz + 1)]

    def node(i, j, k):
        return 1 + i + (nr + 1) * (j + (nt + 1) * k)

    nodes = []
    for k in range(nz + 1):
        for j in range(nt + 1):
            c, s = directions[j]
            for i in range(nr + 1):
                nodes.append((node(i, j, k), r[i] * c, r[i] * s, zs[k]))

    def hexa(i, j, k):
        bottom = [node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k)]
        return bottom + [n + (nr + 1) * (nt + 1) for n in bottom]

    volume = [hexa(i, j, k) for k in range(nz) for j in range(nt) for i in range(nr)]
    # boundary quadrilaterals, each listed counter-clockwise seen from outside
    inner = [[node(0, j, k), node(0, j, k + 1), node(0, j + 1, k + 1), node(0, j + 1, k)]
             for k in range(nz) for j in range(nt)]
    outer = [[node(nr, j, k), node(nr, j + 1, k), node(nr, j + 1, k + 1), node(nr, j, k + 1)]
             for k in range(nz) for j in range(nt)]
    theta0 = [[node(i, 0, k), node(i + 1, 0, k), node(i + 1, 0, k + 1), node(i, 0, k + 1)]
              for k in range(nz) for i in range(nr)]
    theta1 = [[node(i, nt, k), node(i, nt, k + 1), node(i + 1, nt, k + 1), node(i + 1, nt, k)]
              for k in range(nz) for i in range(nr)]
    z0 = [[node(i, j, 0), node(i, j + 1, 0), node(i + 1, j + 1, 0), node(i + 1, j, 0)]
          for j in range(nt) for i in range(nr)]
    z1 = [[node(i, j, nz), node(i + 1, j, nz), node(i + 1, j + 1, nz), node(i, j + 1, nz)]
          for j in range(nt) for i in range(nr)]
    name = args.name
    surfaces = [(f"{name}_inner", inner), (f"{name}_outer", outer),
                (f"{name}_theta0", theta0), (f"{name}_theta1", theta1),
                (f"{name}_z0", z0), (f"{name}_z1", z1)]
    return nodes, volume, surfaces


def write(args, out, command):
    nodes, volume, surfaces = build(args)
    out.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n")
    out.write("$Comments\n")
    out.write("written by inputs/meshes/ring_mesh.py: hollow cylinder sector of 8-node hexahedra\n")
    out.write(f"command: {command}\n")
    out.write("$EndComments\n")
    out.write(f"$PhysicalNames\n{1 + len(surfaces)}\n")
    for tag, (surface_name, _) in enumerate(surfaces, start=1):
        out.write(f'2 {tag} "{surface_name}"\n')
    out.write(f'3 1 "{args.name}"\n$EndPhysicalNames\n')
    out.write(f"$Nodes\n{len(nodes)}\n")
    for node_id, x, y, z in nodes:
        out.write(f"{node_id} {number(x)} {number(y)} {number(z)}\n")
    out.write("$EndNodes\n")
    n_quads = sum(len(quads) for _, quads in surfaces)
    out.write(f"$Elements\n{len(volume) + n_quads}\n")
    element = 0
    for hexa in volume:
        element += 1
        out.write(f"{element} 5 2 1 1 " + " ".join(map(str, hexa)) + "\n")
    for tag, (_, quads) in enumerate(surfaces, start=1):
        for quad in quads:
            element += 1
            out.write(f"{element} 3 2 {tag} {tag + 1} " + " ".join(map(str, quad)) + "\n")
    out.write("$EndElements\n")
    return len(nodes), len(volume)


def main(argv=None):
    parser = argparse.ArgumentParser(
        description="Write a gmsh 2.2 ASCII mesh of a hollow cylinder sector (8-node hexahedra) "
                    "with physical groups for the volume, the inner and outer surfaces, the two "
                    "angular planes and the two end faces.")
    parser.add_argument("--inner", type=float, required=True, metavar="A", help="inner radius a")
    parser.add_argument("--outer", type=float, required=True, metavar="B", help="outer radius b")
    parser.add_argument("--theta", type=float, nargs=2, default=[0.0, 90.0],
                        metavar=("START", "END"),
                        help="angle range in degrees from the x axis (default 0 90)")
    parser.add_argument("--length", type=float, required=True, metavar="L",
                        help="axial length along z (from z = 0)")
    parser.add_argument("--nr", type=int, required=True, help="elements through the wall")
    parser.add_argument("--ntheta", type=int, required=True, help="elements around")
    parser.add_argument("--nz", type=int, default=1, help="elements along z (default 1)")
    parser.add_argument("--grading", type=float, default=1.0, metavar="G",
                        help="outermost / innermost radial element size (default 1: uniform; "
                             "> 1: finer toward the inside)")
    parser.add_argument("--name", default="ring",
                        help="volume group name, prefix of the surface names (default ring)")
    parser.add_argument("-o", "--output", required=True, metavar="MSH",
                        help="mesh file to write ('-' for standard output)")
    args = parser.parse_args(argv)
    t0, t1 = args.theta
    problems = []
    if not 0.0 < args.inner < args.outer:
        problems.append("need 0 < inner < outer")
    if not 0.0 < t1 - t0 < 360.0:
        problems.append("need 0 < END - START < 360 degrees (a closed ring is not supported)")
    if not args.length > 0.0:
        problems.append("need length > 0")
    if min(args.nr, args.ntheta, args.nz) < 1:
        problems.append("need nr, ntheta, nz >= 1")
    if not args.grading > 0.0:
        problems.append("need grading > 0")
    if not args.name or any(ch.isspace() or ch in '"/' for ch in args.name):
        problems.append("the name may not be empty nor contain blanks, quotes or '/'")
    if problems:
        parser.error("; ".join(problems))
    # the command in canonical form (the output's folder left out, so that the file does not
    # depend on where it was written)
    def text(value):
        shortest = repr(float(value))
        return shortest[:-2] if shortest.endswith(".0") else shortest

    command = (f"ring_mesh.py --inner {text(args.inner)} --outer {text(args.outer)} "
               f"--theta {text(t0)} {text(t1)} --length {text(args.length)} --nr {args.nr} "
               f"--ntheta {args.ntheta} --nz {args.nz} --grading {text(args.grading)} --name {args.name} "
               f"-o {os.path.basename(args.output) if args.output != '-' else '-'}")
    if args.output == "-":
        n_nodes, n_elements = write(args, sys.stdout, command)
    else:
        with open(args.output, "w") as out:
            n_nodes, n_elements = write(args, out, command)
        print(f"wrote {args.output}: {n_nodes} nodes, {n_elements} hexahedra", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
