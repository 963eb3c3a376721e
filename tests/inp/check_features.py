"""Check features.dck (the bar of features.inp): check_features.py H5

Uniaxial tension with nu = 0: u_x = p x / E (p = 1, E = 1000; 2e-3 at x = 2) and u_y = u_z = 0
at every node, to 1e-12 (closed form; linear elements represent it exactly), and the sets
and surfaces of the .inp as written there (ids and faces). Exit 0 if all hold.
"""
import sys

import h5py
import numpy as np


def main():
    failed = False
    with h5py.File(sys.argv[1], "r") as f:
        x = f["/mesh/coordinates"][()]
        ids = f["/mesh/node_ids"][()]
        element_ids = f["/mesh/element_ids"][()]
        u = f["/increments"][sorted(f["/increments"])[-1]]["displacement"][()]
        error = np.abs(u[:, 0] - x[:, 0] / 1000.0).max() + np.abs(u[:, 1:]).max()
        print(f"largest error against u_x = p x / E, u_y = u_z = 0: {error:.2e}")
        failed |= not error <= 1e-12

        def node_ids(name):
            return sorted(ids[f["/mesh/node_sets/" + name][()] - 1].tolist())

        def element_set(name):
            return sorted(element_ids[f["/mesh/element_sets/" + name][()] - 1].tolist())

        def faces(name):
            group = f["/mesh/surfaces/" + name]
            return sorted(zip(element_ids[group["elements"][()] - 1].tolist(), group["faces"][()].tolist()))

        expected = [
            ("node set Left", node_ids("Left"), [1, 4, 5, 8]),
            ("node set Right", node_ids("Right"), [10, 11, 12, 13]),
            ("node set Corner (defined twice)", node_ids("Corner"), [1, 4, 5]),
            ("element set First", element_set("First"), [1]),
            ("element set Bar (of a set and an id)", element_set("Bar"), [1, 2]),
            ("element set LastOne (GENERATE)", element_set("LastOne"), [2]),
            ("surface Pull", faces("Pull"), [(2, 4)]),
            ("surface Held", faces("Held"), [(1, 6)]),
            ("node sets", sorted(f["/mesh/node_sets"]), ["Corner", "Left", "Right"]),
            ("element sets", sorted(f["/mesh/element_sets"]), ["Bar", "First", "LastOne", "Second"]),
        ]
        for what, got, want in expected:
            if got != want:
                print(f"FAIL: {what}: {got}, expected {want}")
                failed = True
    print("FAIL" if failed else "OK")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
