"""Write the meshes and boundary conditions of the tetrahedron patch tests (check_patch.py):

- patch.inp: 2 x 2 x 2 unit cubes of [0, 1]^3, each split into 6 tetrahedra along its main
  diagonal (Kuhn's split): 48 C3D4, one interior node; patch_dirichlet.txt: the DIRICHLET
  lines of the 26 boundary nodes, u = A x with the A of check_patch.py (pasted in patch.dck);
- patch10.inp and patch10.dck: the same 48 tetrahedra as C3D10 (mid-edge nodes at the middle
  of each straight edge, node order of C3D10: 5: 1-2, 6: 2-3, 7: 3-1, 8: 1-4, 9: 2-4, 10: 3-4),
  the interior corner node moved off the centre to (0.55, 0.47, 0.52) so that the tetrahedra
  around it are not the regular split; the deck moves every boundary node by u = A x.
Run in this folder: python3 make_patch.py"""
import itertools

import numpy as np

from check_patch import GRADIENT

N = 2
CENTRE_MOVED = np.array([0.55, 0.47, 0.52])
MID_EDGES = [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]   # C3D10 nodes 5-10


def node_id(i, j, k):
    return 1 + i + (N + 1) * (j + (N + 1) * k)


def kuhn_tets(nodes):
    """The 48 tetrahedra (corner ids, positive volume) of the 2 x 2 x 2 cubes."""
    tets = []
    for k, j, i in itertools.product(range(N), repeat=3):
        for path in itertools.permutations(range(3)):
            corner = [0, 0, 0]
            tet = [node_id(i, j, k)]
            for d in path:
                corner[d] += 1
                tet.append(node_id(i + corner[0], j + corner[1], k + corner[2]))
            x = np.array([nodes[a] for a in tet])
            if np.linalg.det(x[1:] - x[0]) < 0:
                tet[1], tet[2] = tet[2], tet[1]
            tets.append(tet)
    return tets


def write_tet4(nodes, tets):
    with open("patch.inp", "w") as f:
        f.write("** 2 x 2 x 2 unit cubes, 6 tetrahedra each (Kuhn split), written by make_patch.py\n")
        f.write("*NODE, NSET=Nall\n")
        for a, x in nodes.items():
            f.write(f"{a}, {x[0]:.6f}, {x[1]:.6f}, {x[2]:.6f}\n")
        f.write("*ELEMENT, TYPE=C3D4, ELSET=Eall\n")
        for e, tet in enumerate(tets, 1):
            f.write(f"{e}, " + ", ".join(map(str, tet)) + "\n")
    with open("patch_dirichlet.txt", "w") as f:
        f.write(dirichlet_lines(nodes))


def dirichlet_lines(nodes):
    """u = A x on every node of the cube's boundary."""
    lines = []
    for a, x in nodes.items():
        if np.any((np.abs(x) < 1e-12) | (np.abs(x - 1) < 1e-12)):
            u = GRADIENT @ x
            lines.append(f"NODE {a} DOF 1 1 1 VAL {u[0]:.17e} {u[1]:.17e} {u[2]:.17e}\n")
    return "".join(lines)


def write_tet10(nodes, tets):
    corners = dict(nodes)
    corners[node_id(1, 1, 1)] = CENTRE_MOVED
    all_nodes = dict(corners)
    mid_id = {}
    elements = []
    for tet in tets:
        element = list(tet)
        for a, b in MID_EDGES:
            key = tuple(sorted((tet[a], tet[b])))
            if key not in mid_id:
                mid_id[key] = 1000 + len(mid_id) + 1
                all_nodes[mid_id[key]] = 0.5 * (corners[key[0]] + corners[key[1]])
            element.append(mid_id[key])
        elements.append(element)
    with open("patch10.inp", "w") as f:
        f.write("** the 48 tetrahedra of patch.inp as C3D10, the interior corner node moved, written by make_patch.py\n")
        f.write("*NODE, NSET=Nall\n")
        for a, x in all_nodes.items():
            f.write(f"{a}, {x[0]:.17e}, {x[1]:.17e}, {x[2]:.17e}\n")
        f.write("*ELEMENT, TYPE=C3D10, ELSET=Eall\n")
        for e, element in enumerate(elements, 1):
            f.write(f"{e}, " + ", ".join(map(str, element[:8])) + ",\n" + ", ".join(map(str, element[8:])) + "\n")
    with open("patch10.dck", "w") as f:
        f.write(PATCH10_HEAD + dirichlet_lines(all_nodes) + PATCH10_TAIL)


PATCH10_HEAD = """ patch10: the TET10 patch test (check_patch.py), written by make_patch.py: the 48 quadratic
 tetrahedra of patch10.inp filling the unit cube, its interior corner node off the centre,
 every boundary node moved by u = A x, the others free; the stress at every integration point
 must be the constant of eps = sym(A). Linear elastic E = 210000, nu = 0.3.
---------------------------------------------------------PROBLEM TYP
PROBLEMTYP   Structure
--------------------------------------------------------------STATIC
KINTYP Geo_Lin  MAXITER 5  TOLRESID 1.0e-12  TOLDISP 1.0e-12
-----------------------------------------------------------MATERIALS
MAT 1 MAT_Struct_LinearElastic YOUNG 210000.0 NUE 0.3
-----------------------------------------------------------MESH FILE
FILE patch10.inp
--------------------------------------------------STRUCTURE ELEMENTS
SET Eall SOLID TET10 MAT 1
------------------------------------------------DIRICHLET CONDITIONS
"""
PATCH10_TAIL = """---------------------------------------------------------------STEPS
STEP 1 NUMSTEP 1 CONTROL Load
-------------------------------------------------------------RESULTS
VTK Yes  LISTING Yes  HDF5 Yes
-----------------------------------------------------------------END
"""


def main():
    nodes = {node_id(i, j, k): np.array([i, j, k]) / N
             for k in range(N + 1) for j in range(N + 1) for i in range(N + 1)}
    tets = kuhn_tets(nodes)
    write_tet4(nodes, tets)
    write_tet10(nodes, tets)


if __name__ == "__main__":
    main()
