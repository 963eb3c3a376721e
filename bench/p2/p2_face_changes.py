#!/usr/bin/python3
"""P2 diagnosis: which slave nodes sit on which master face at each converged increment of a
frix run of bench/p2/run_p2.sh, which of them changed face during an increment, and how close
they are to a face edge (docs/performance-p2.md, Newton convergence).

Usage: p2_face_changes.py WORKDIR N

Reads p2_n<N>.dck (reference coordinates), p2_n<N>_ids.json (slave node ids) and
frix_n<N>/p2_n<N>_listing.txt (NODAL DISPLACEMENTS of every converged increment). The master
surface is the top z = 0.5 of the lower block (n x n faces of size 1/n); the face of a slave
node is the one whose deformed quadrilateral (x, y of its 4 nodes) contains the node's current
(x, y) - the master surface is flat within the penalty overclosure (1e-4), so this is the face
of the closest point except within ~1e-4 of an edge. xi = parent coordinates on that face
(inverse bilinear map, Newton); 1 - max|xi| is the distance to the nearest edge.
Output: per increment of step 2, the nodes that changed face since the previous converged
increment (node, old face, new face, slip direction) and the smallest 1 - max|xi|.
"""
import json
import os
import re
import sys

import numpy as np


def read_deck_nodes(path):
    coords = {}
    with open(path) as f:
        for line in f:
            m = re.match(r'^NODE\s+(\d+)\s+COORD\s+(\S+)\s+(\S+)\s+(\S+)', line)
            if m:
                coords[int(m.group(1))] = np.array([float(m.group(k)) for k in (2, 3, 4)])
    return coords


def read_listing_displacements(path):
    """[(step, increment, {node: u})] of every converged increment."""
    out = []
    block = None
    with open(path) as f:
        for line in f:
            if line.startswith('#') or not line.strip():
                continue
            if not line.startswith(' '):
                m = re.match(r'STEP\s+(\d+)\s+INCREMENT\s+(\d+)', line)
                if m:
                    out.append((int(m.group(1)), int(m.group(2)), {}))
                    block = None
                else:
                    block = line.strip()
                continue
            tokens = line.split()
            if block == 'NODAL DISPLACEMENTS' and re.match(r'^\d+$', tokens[0]):
                out[-1][2][int(tokens[0])] = np.array([float(t) for t in tokens[1:4]])
    return out


def inverse_bilinear(corners, p):
    """Parent coordinates of p in the quadrilateral corners (4 x 2, counter-clockwise from
    (-1, -1)); Newton on x(xi) = sum N_a(xi) x_a."""
    signs = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]], dtype=float)
    xi = np.zeros(2)
    for _ in range(20):
        n = (1 + signs[:, 0] * xi[0]) * (1 + signs[:, 1] * xi[1]) / 4
        dn = np.stack([signs[:, 0] * (1 + signs[:, 1] * xi[1]) / 4,
                       signs[:, 1] * (1 + signs[:, 0] * xi[0]) / 4], axis=1)
        r = n @ corners - p
        jac = corners.T @ dn
        step = np.linalg.solve(jac, r)
        xi -= step
        if np.max(np.abs(step)) < 1e-14:
            break
    return xi


def main():
    work, n = sys.argv[1], int(sys.argv[2])
    coords = read_deck_nodes(os.path.join(work, 'p2_n%d.dck' % n))
    ids = json.load(open(os.path.join(work, 'p2_n%d_ids.json' % n)))
    slaves = ids['slave_nodes']
    increments = read_listing_displacements(
        os.path.join(work, 'frix_n%d' % n, 'p2_n%d_listing.txt' % n))
    # lower block node id = 1 + i + (n+1) j + (n+1)^2 k (p2_generate.py), top layer k = n/2
    top = (n // 2) * (n + 1) ** 2

    def master(i, j):
        return 1 + i + (n + 1) * j + top

    previous = None
    for step, increment, u in increments:
        x = {k: coords[k] + u.get(k, 0.0) for k in coords}
        faces = {}
        edge = {}
        for s in slaves:
            p = x[s][:2]
            i0, j0 = int(np.floor(coords[s][0] * n)), int(np.floor(coords[s][1] * n))
            found = None
            for di in range(-1, 2):
                for dj in range(-1, 2):
                    i, j = i0 + di, j0 + dj
                    if not (0 <= i < n and 0 <= j < n):
                        continue
                    corners = np.array([x[master(i, j)][:2], x[master(i + 1, j)][:2],
                                        x[master(i + 1, j + 1)][:2], x[master(i, j + 1)][:2]])
                    xi = inverse_bilinear(corners, p)
                    if np.max(np.abs(xi)) <= 1 + 1e-12:
                        found = (i, j)
                        edge[s] = 1 - np.max(np.abs(xi))
                        break
                if found:
                    break
            faces[s] = found
        closest = min(edge.values())
        node_min = min(edge, key=edge.get)
        line = '%d.%d: min 1-max|xi| = %.3e (node %d)' % (step, increment, closest, node_min)
        if previous is not None:
            moved = [(s, previous[s], faces[s]) for s in slaves if faces[s] != previous[s]]
            line += '; %d slave nodes changed face' % len(moved)
            print(line)
            for s, old, new in moved:
                print('   node %5d  face (i,j) %s -> %s  x = %.6f y = %.6f  1-max|xi| = %.3e'
                      % (s, old, new, x[s][0], x[s][1], edge[s]))
        else:
            print(line)
        previous = faces


if __name__ == '__main__':
    main()
