"""Check the cantilever read from CalculiX's .inp (tests/inp/README.md).

check_cantilever.py INP_H5 BLOCK_H5 CCX_DAT

- INP_H5: frix on cantilever_inp.dck (mesh from cantilever.inp); BLOCK_H5: frix on
  cantilever_block.dck (the same model by MESH BLOCK). Their displacements, matched node by
  node by position, must agree to 1e-10 of the largest displacement (round-off: the same
  equations in another numbering).
- CCX_DAT: CalculiX 2.20 on cantilever.inp (*NODE PRINT U, printed to 7 significant digits).
  frix's displacements by node id must agree to 2e-6 of the largest displacement (the print
  precision: 5e-7 relative per value, measured 3.9e-7).
- The sets of the .inp (Nfix, Ntip, Eall, TipFace) are there with their sizes.
Exit 0 if all hold.
"""
import sys

import h5py
import numpy as np


def last_displacement(path):
    with h5py.File(path, "r") as f:
        groups = sorted(f["/increments"])
        u = f["/increments"][groups[-1]]["displacement"][()]
        return f["/mesh/coordinates"][()], f["/mesh/node_ids"][()], u


def read_ccx(path):
    values = {}
    with open(path) as dat:
        for line in dat:
            parts = line.split()
            if len(parts) == 4 and parts[0].isdigit():
                values[int(parts[0])] = np.array([float(p) for p in parts[1:]])
    return values


def main():
    inp_h5, block_h5, ccx_dat = sys.argv[1:4]
    failed = False
    x_inp, ids_inp, u_inp = last_displacement(inp_h5)
    x_block, _, u_block = last_displacement(block_h5)
    scale = np.abs(u_inp).max()

    key = lambda x: tuple(np.round(x, 9))
    block_at = {key(x): k for k, x in enumerate(x_block)}
    if len(block_at) != len(x_inp) or any(key(x) not in block_at for x in x_inp):
        print("FAIL: the two meshes do not have the same nodes")
        return 1
    order = [block_at[key(x)] for x in x_inp]
    block_error = np.abs(u_inp - u_block[order]).max() / scale
    print(f"inp vs MESH BLOCK: largest difference {block_error:.2e} of the largest displacement {scale:.6f}")
    failed |= not block_error <= 1e-10

    ccx = read_ccx(ccx_dat)
    if sorted(ccx) != sorted(ids_inp.tolist()):
        print("FAIL: CalculiX's nodes are not frix's nodes")
        return 1
    ccx_error = max(np.abs(u_inp[k] - ccx[int(i)]).max() for k, i in enumerate(ids_inp)) / scale
    print(f"inp vs CalculiX:   largest difference {ccx_error:.2e} of the largest displacement")
    failed |= not ccx_error <= 2e-6

    with h5py.File(inp_h5, "r") as f:
        sizes = {"node_sets/Nfix": 9, "node_sets/Ntip": 9, "element_sets/Eall": 40,
                 "surfaces/TipFace/faces": 4}
        for name, size in sizes.items():
            got = f["/mesh/" + name].shape[0]
            if got != size:
                print(f"FAIL: {name} has {got} entries, expected {size}")
                failed = True
        faces = f["/mesh/surfaces/TipFace/faces"][()]
        if not np.all(faces == 5):
            print(f"FAIL: TipFace faces {faces}, expected 5 (S5)")
            failed = True
    print("FAIL" if failed else "OK")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
