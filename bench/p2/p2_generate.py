#!/usr/bin/python3
"""P2 generator: two stacked elastic blocks with non-matching meshes and Coulomb friction,
written as a frix deck and as a CalculiX input file with the SAME nodes (ids and coordinates),
elements (ids and C3D8/HEX8 node order), surfaces, loads and penalty parameters.

Problem (units N, mm, MPa; reconstruction decisions of benchmark P2, docs/benchmarks.md,
documented in docs/performance-p2.md):
- lower block [0,1] x [0,1] x [0,0.5], n x n x n/2 HEX8, base z = 0 fixed (u = 0);
- upper block [0.2,0.8] x [0.2,0.8] x [0.5,0.8], m x m x mz HEX8 with m = round(0.7 n) + 1
  rounded to an odd number (never a divisor-compatible division: non-matching with the lower
  mesh, whose element edges fall on multiples of 1/n), mz = ceil(m/2);
  both E = 1000, nu = 0.3, linear elastic, small strain (frix Geo_Lin / CalculiX without
  NLGEOM); plain 2x2x2 trilinear hexahedra (frix HEX8 EAS 0 = CalculiX C3D8);
- contact: slave = upper block bottom, master = lower block top, node-to-surface penalty,
  eps_N = 1e5 N/mm^3 (pressure per penetration), eps_T = 1e4 N/mm^3 (stick slope), mu = 0.3;
- step 1: dead pressure q = 10 MPa on the upper top face, upper top face held in x and y,
  NSTEP1 equal increments;
- step 2: pressure held, the upper top face pushed in +x to u_x = DELTA = 0.02 mm (u_y = 0),
  NSTEP2 equal increments. Full sliding needs a tangential force mu q A = 0.3 * 10 * 0.36 =
  1.08 N; the estimated stick limit is u_x ~ 0.005 mm (shear of both blocks + tau/eps_T), so
  the last increments slide.

Usage: p2_generate.py N OUTDIR [--nstep1 2] [--nstep2 4]
Writes OUTDIR/p2_nN.dck (frix) and OUTDIR/p2_nN.inp (CalculiX), and OUTDIR/p2_nN_ids.json
(node sets used by the comparison).
"""
import argparse
import json
import math
import os

YOUNG = 1000.0
POISSON = 0.3
EPS_N = 1.0e5
EPS_T = 1.0e4
MU = 0.3
PRESSURE = 10.0
DELTA = 0.02
# CalculiX LINEAR law: tension at large clearance sigma_inf (must be > 0 in CalculiX; frix has
# none). 1e-4 q: its shift of the contact pressure (about sigma_inf) is below 1e-4 relative.
SIGMA_INF = 1.0e-3


def block(origin, size, divisions, node_start, element_start):
    """Structured HEX8 block: nodes x fastest, then y, then z (as frix MESH BLOCK)."""
    nx, ny, nz = divisions
    nodes = {}
    nid = node_start
    index = {}
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                nid += 1
                nodes[nid] = (origin[0] + size[0] * i / nx, origin[1] + size[1] * j / ny,
                              origin[2] + size[2] * k / nz)
                index[(i, j, k)] = nid
    elements = {}
    eid = element_start
    position = {}
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                eid += 1
                n1 = index[(i, j, k)]
                n2 = index[(i + 1, j, k)]
                n3 = index[(i + 1, j + 1, k)]
                n4 = index[(i, j + 1, k)]
                n5 = index[(i, j, k + 1)]
                n6 = index[(i + 1, j, k + 1)]
                n7 = index[(i + 1, j + 1, k + 1)]
                n8 = index[(i, j + 1, k + 1)]
                elements[eid] = (n1, n2, n3, n4, n5, n6, n7, n8)
                position[eid] = (i, j, k)
    return nodes, elements, index, position


def divisions_for(n):
    lower = (n, n, max(1, n // 2))
    m = int(round(0.7 * n)) + 1
    if m % 2 == 0:
        m += 1
    upper = (m, m, int(math.ceil(m / 2)))
    return lower, upper


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('n', type=int)
    parser.add_argument('outdir')
    parser.add_argument('--nstep1', type=int, default=2)
    parser.add_argument('--nstep2', type=int, default=4)
    args = parser.parse_args()
    n = args.n
    lower_div, upper_div = divisions_for(n)
    lower_nodes, lower_elements, lower_index, lower_pos = block(
        (0.0, 0.0, 0.0), (1.0, 1.0, 0.5), lower_div, 0, 0)
    upper_nodes, upper_elements, upper_index, upper_pos = block(
        (0.2, 0.2, 0.5), (0.6, 0.6, 0.3), upper_div, len(lower_nodes), len(lower_elements))
    nodes = {**lower_nodes, **upper_nodes}
    elements = {**lower_elements, **upper_elements}

    # sets
    lower_bottom = [nid for (i, j, k), nid in lower_index.items() if k == 0]
    upper_top = [nid for (i, j, k), nid in upper_index.items() if k == upper_div[2]]
    upper_bottom_nodes = [nid for (i, j, k), nid in upper_index.items() if k == 0]
    # faces: master = lower top (HEX8 face 2, zeta = +1; CalculiX S2); slave = upper bottom
    # (face 1, zeta = -1; S1); load = upper top (face 2; S2)
    master_faces = [eid for eid, (i, j, k) in lower_pos.items() if k == lower_div[2] - 1]
    slave_faces = [eid for eid, (i, j, k) in upper_pos.items() if k == 0]
    load_faces = [eid for eid, (i, j, k) in upper_pos.items() if k == upper_div[2] - 1]
    # centre line of the slave surface along x at y = 0.5 (nodes of the upper bottom with
    # j = m/2 when m even; m is odd, so take the row nearest y = 0.5)
    j_mid = upper_div[1] // 2
    centre_row = [upper_index[(i, j_mid, 0)] for i in range(upper_div[0] + 1)]

    os.makedirs(args.outdir, exist_ok=True)
    base = os.path.join(args.outdir, 'p2_n%d' % n)
    t1 = args.nstep1
    t2 = args.nstep2
    header = (
        'P2: two stacked blocks, non-matching meshes, node-to-surface penalty contact with\n'
        'Coulomb friction (bench/p2/p2_generate.py; docs/performance-p2.md).\n'
        'Units N, mm, MPa. Lower block 1 x 1 x 0.5, %d x %d x %d HEX8, base fixed.\n'
        'Upper block 0.6 x 0.6 x 0.3 at (0.2, 0.2, 0.5), %d x %d x %d HEX8.\n'
        'E = %g, nu = %g (both). Slave: upper bottom; master: lower top.\n'
        'EPSN = %g, EPST = %g, MU = %g. Step 1: q = %g on the upper top (x, y held),\n'
        '%d increments. Step 2: upper top u_x to %g, %d increments.\n'
        % (lower_div + upper_div + (YOUNG, POISSON, EPS_N, EPS_T, MU, PRESSURE, t1, DELTA, t2)))

    # ---------------------------------------------------------------- frix deck
    with open(base + '.dck', 'w') as f:
        f.write('=' * 70 + '\n' + header + '=' * 70 + '\n')
        f.write('-' * 57 + 'PROBLEM TYP\nPROBLEMTYP   Structure\n')
        f.write('-' * 62 + 'STATIC\nKINTYP Geo_Lin\nMAXITER 30  TOLRESID 1.0e-8  '
                'TOLDISP 1.0e-8\nMAXCUT 6  EXTRAPOLATION Linear\nSOLVER Auto\n')
        f.write('-' * 57 + 'LOAD CURVES\n')
        f.write('CURVE 1 POINTS 0.0 0.0  1.0 1.0  2.0 1.0   // q: ramp in step 1, held\n')
        f.write('CURVE 2 POINTS 0.0 0.0  1.0 0.0  2.0 1.0   // u_x: 0 in step 1, ramp in '
                'step 2\n')
        f.write('-' * 59 + 'MATERIALS\n')
        f.write('MAT 1 MAT_Struct_LinearElastic YOUNG %g NUE %g\n' % (YOUNG, POISSON))
        f.write('-' * 57 + 'NODE COORDS\n')
        for nid, x in nodes.items():
            f.write('NODE %d COORD %.17g %.17g %.17g\n' % ((nid,) + x))
        f.write('-' * 50 + 'STRUCTURE ELEMENTS\n')
        for eid, conn in elements.items():
            f.write('%d SOLID HEX8 %s MAT 1\n' % (eid, ' '.join(str(c) for c in conn)))
        f.write('-' * 60 + 'NODE SETS\n')
        f.write('SET lower_bottom BOX -1 -1 -0.001  2 2 0.001\n')
        f.write('SET upper_top BOX -1 -1 0.799  2 2 0.801\n')
        f.write('-' * 61 + 'SURFACES\n')
        f.write('SURF master_top FACES %s\n' % ' '.join('%d 2' % e for e in master_faces))
        f.write('SURF slave_bottom FACES %s\n' % ' '.join('%d 1' % e for e in slave_faces))
        f.write('SURF loaded_top FACES %s\n' % ' '.join('%d 2' % e for e in load_faces))
        f.write('-' * 48 + 'DIRICHLET CONDITIONS\n')
        f.write('SET lower_bottom DOF 1 1 1 VAL 0 0 0\n')
        f.write('SET upper_top DOF 1 1 0 VAL %g 0 0 CURVE 2 0 0\n' % DELTA)
        f.write('-' * 50 + 'NEUMANN CONDITIONS\n')
        f.write('SURF loaded_top PRESSURE %g CURVE 1\n' % PRESSURE)
        f.write('-' * 50 + 'CONTACT CONDITIONS\n')
        f.write('PAIR 1 SLAVE slave_bottom MASTER master_top EPSN %g EPST %g MU %g '
                'GAPTOL 1e-6\n' % (EPS_N, EPS_T, MU))
        f.write('-' * 63 + 'STEPS\n')
        f.write('STEP 1 NUMSTEP %d CONTROL Load\n' % t1)
        f.write('STEP 2 NUMSTEP %d CONTROL Displacement\n' % t2)
        f.write('-' * 61 + 'RESULTS\n')
        f.write('VTK Yes  LISTING Yes\n')
        f.write('HISTORY NODE %d DOF 1 KIND R\n' % upper_top[len(upper_top) // 2])
        f.write('-' * 65 + 'END\n')

    # ---------------------------------------------------------------- CalculiX input
    def write_ids(f, ids, per_line=8):
        for start in range(0, len(ids), per_line):
            f.write(', '.join(str(i) for i in ids[start:start + per_line]) + '\n')

    with open(base + '.inp', 'w') as f:
        for line in header.splitlines():
            f.write('** ' + line + '\n')
        f.write('*NODE, NSET=NALL\n')
        for nid, x in nodes.items():
            f.write('%d, %.17g, %.17g, %.17g\n' % ((nid,) + x))
        f.write('*ELEMENT, TYPE=C3D8, ELSET=EALL\n')
        for eid, conn in elements.items():
            f.write('%d, %s\n' % (eid, ', '.join(str(c) for c in conn)))
        f.write('*NSET, NSET=LOWER_BOTTOM\n')
        write_ids(f, sorted(lower_bottom))
        f.write('*NSET, NSET=UPPER_TOP\n')
        write_ids(f, sorted(upper_top))
        f.write('*SURFACE, NAME=MASTER_TOP, TYPE=ELEMENT\n')
        for e in master_faces:
            f.write('%d, S2\n' % e)
        f.write('*SURFACE, NAME=SLAVE_BOTTOM, TYPE=ELEMENT\n')
        for e in slave_faces:
            f.write('%d, S1\n' % e)
        f.write('*MATERIAL, NAME=ELASTIC\n*ELASTIC\n%g, %g\n' % (YOUNG, POISSON))
        f.write('*SOLID SECTION, ELSET=EALL, MATERIAL=ELASTIC\n')
        f.write('*CONTACT PAIR, INTERACTION=SI1, TYPE=NODE TO SURFACE\n')
        f.write('SLAVE_BOTTOM, MASTER_TOP\n')
        f.write('*SURFACE INTERACTION, NAME=SI1\n')
        f.write('*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n')
        f.write('%g, %g\n' % (EPS_N, SIGMA_INF))
        f.write('*FRICTION\n%g, %g\n' % (MU, EPS_T))
        f.write('*BOUNDARY\nLOWER_BOTTOM, 1, 3\n')
        # step 1
        f.write('*STEP, INC=1000\n*STATIC, DIRECT\n%.17g, 1.0\n' % (1.0 / t1))
        f.write('*BOUNDARY\nUPPER_TOP, 1, 2\n')
        f.write('*DLOAD\n')
        for e in load_faces:
            f.write('%d, P2, %g\n' % (e, PRESSURE))
        f.write('*NODE PRINT, NSET=UPPER_TOP, TOTALS=ONLY\nRF\n')
        f.write('*NODE PRINT, NSET=LOWER_BOTTOM, TOTALS=ONLY\nRF\n')
        f.write('*CONTACT PRINT\nCSTR, CDIS\n')
        f.write('*NODE FILE\nU\n*CONTACT FILE\nCSTR, CDIS\n')
        f.write('*END STEP\n')
        # step 2
        f.write('*STEP, INC=1000\n*STATIC, DIRECT\n%.17g, 1.0\n' % (1.0 / t2))
        f.write('*BOUNDARY\nUPPER_TOP, 1, 1, %g\nUPPER_TOP, 2, 2, 0\n' % DELTA)
        f.write('*NODE PRINT, NSET=UPPER_TOP, TOTALS=ONLY\nRF\n')
        f.write('*NODE PRINT, NSET=LOWER_BOTTOM, TOTALS=ONLY\nRF\n')
        f.write('*CONTACT PRINT\nCSTR, CDIS\n')
        f.write('*NODE FILE\nU\n*CONTACT FILE\nCSTR, CDIS\n')
        f.write('*END STEP\n')

    with open(base + '_ids.json', 'w') as f:
        json.dump({'n': n, 'lower_divisions': lower_div, 'upper_divisions': upper_div,
                   'nodes': len(nodes), 'elements': len(elements),
                   'lower_bottom': sorted(lower_bottom), 'upper_top': sorted(upper_top),
                   'slave_nodes': sorted(upper_bottom_nodes), 'centre_row': centre_row,
                   'slave_area': 0.36, 'pressure': PRESSURE, 'mu': MU, 'eps_n': EPS_N,
                   'eps_t': EPS_T, 'delta': DELTA, 'sigma_inf': SIGMA_INF,
                   'nstep1': t1, 'nstep2': t2}, f)


if __name__ == '__main__':
    main()
