"""Check faces.dck against CalculiX: check_faces.py H5 CCX_DAT

frix's displacements of the slanted hexahedron with pressure 10 k on face Sk must agree with
CalculiX's (faces_ccx.dat, *DLOAD P1..P6, printed to 7 significant digits) to 2e-6 of the
largest displacement, node by node; they would not with another face numbering (swapping the
pressures of S1 and S2 gives differences of 0.67 of it, of S3 and S5 1.28). Exit 0 if they
agree.
"""
import sys

import numpy as np

from check_cantilever import last_displacement, read_ccx


def main():
    _, ids, u = last_displacement(sys.argv[1])
    ccx = read_ccx(sys.argv[2])
    if sorted(ccx) != sorted(ids.tolist()):
        print("FAIL: CalculiX's nodes are not frix's nodes")
        return 1
    scale = np.abs(u).max()
    error = max(np.abs(u[k] - ccx[int(i)]).max() for k, i in enumerate(ids)) / scale
    print(f"frix vs CalculiX: largest difference {error:.2e} of the largest displacement {scale:.6f}")
    print("OK" if error <= 2e-6 else "FAIL")
    return 0 if error <= 2e-6 else 1


if __name__ == "__main__":
    sys.exit(main())
