"""Write patch.inp (2 x 2 x 2 unit cubes of [0, 1]^3, each split into 6 tetrahedra along its
main diagonal, Kuhn's split: 48 C3D4, one interior node) and patch_dirichlet.txt (the DIRICHLET
lines of the 26 boundary nodes: u = A x with the A of check_patch.py)."""
import itertools

import numpy as np

from check_patch import GRADIENT

N = 2


def node_id(i, j, k):
    return 1 + i + (N + 1) * (j + (N + 1) * k)


def main():
    nodes = {node_id(i, j, k): np.array([i, j, k]) / N
             for k in range(N + 1) for j in range(N + 1) for i in range(N + 1)}
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
    with open("patch.inp", "w") as f:
        f.write("** 2 x 2 x 2 unit cubes, 6 tetrahedra each (Kuhn split), written by make_patch.py\n")
        f.write("*NODE, NSET=Nall\n")
        for a, x in nodes.items():
            f.write(f"{a}, {x[0]:.6f}, {x[1]:.6f}, {x[2]:.6f}\n")
        f.write("*ELEMENT, TYPE=C3D4, ELSET=Eall\n")
        for e, tet in enumerate(tets, 1):
            f.write(f"{e}, " + ", ".join(map(str, tet)) + "\n")
    with open("patch_dirichlet.txt", "w") as f:
        for a, x in nodes.items():
            if np.any((x == 0) | (x == 1)):
                u = GRADIENT @ x
                f.write(f"NODE {a} DOF 1 1 1 VAL {u[0]:.17e} {u[1]:.17e} {u[2]:.17e}\n")


if __name__ == "__main__":
    main()
