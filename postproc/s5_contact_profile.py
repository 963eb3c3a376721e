#!/usr/bin/python3
"""Contact pressure and shear around a buried pipe against the angle from the crown, from a
frix HDF5 results file (S5, docs/verification/s5.md, and any pipe along a coordinate axis).

For every slave node of contact pass 1 (frix's order: first appearance over the slave
surface's faces) in one cross-section (--section, default the mesh's smallest coordinate
along the pipe: S5's front face y = 0; the pipe along --along, default y, its crown towards
--up, default z) it
takes frix's contact pressure p_N, tangential traction t and the normal n frix used (increment
group `contact/`, dataset `normal`: t is tangential to it). Files written before frix stored
`contact/normal` do not have it: n is then rebuilt (the facet normal of the master face in the
restart table `pass1_history` at its face coordinates, in the current configuration; with
--smoothed the smoothed normal of NORMALS Smoothed, from the nodal normals of the master faces;
the face coordinates are the committed anchor's, i.e. the contact point for frictionless and
slipping nodes, the stick point for sticking ones). It then resolves the
interface traction on the pipe, f = +-(p_N n + t), in the pipe's own frame: e_r the outward
normal of the deformed pipe surface at the node (the normalised sum of the normals of the
pipe faces at the node; on the symmetry plane x = 0 its x component is dropped, as the
mirrored face would do), e_theta = (e_r,z, 0, -e_r,x) pointing away from the crown:
    p_r   = -f . e_r       normal pressure on the pipe (compression positive)
    tau   =  f . e_theta   shear on the pipe
    t_frix = |t|           frix's own tangential traction (zero without friction)
    kink  = angle between n and e_r (degrees)
The angle is that of the node's reference position, from the crown (--axis: the pipe axis),
towards e_h = e_along x e_up (x for S5). In a half model (every node of the section on one
side of the plane through the axis and the crown) that plane is taken as a symmetry plane.
The sign of f: + when the pipe is the slave surface, - when it is the master (--pipe-master).
Columns printed (or written with --csv): node angle_deg p_N t_frix p_r tau kink_deg.
--plot PNG draws p_r and tau (and p_N) against the angle.
Run with /usr/bin/python3 (Debian's h5py, numpy, matplotlib).
"""
import argparse
import sys

import h5py
import numpy as np

# frix's HEX8 faces (docs/deck-format.md SURFACES), outward, 1-based local nodes
FACES = {1: (1, 4, 3, 2), 2: (5, 6, 7, 8), 3: (1, 2, 6, 5), 4: (2, 3, 7, 6), 5: (3, 4, 8, 7),
         6: (1, 5, 8, 4)}


def face_normal(x, xi1, xi2):
    """Unit normal (x_,1 x x_,2) of the bilinear face with corners x (4 x 3) at (xi1, xi2)."""
    s = np.array([-1.0, 1.0, 1.0, -1.0]); t = np.array([-1.0, -1.0, 1.0, 1.0])
    d1 = ((s * (1 + t * xi2)) / 4.0) @ x
    d2 = ((t * (1 + s * xi1)) / 4.0) @ x
    n = np.cross(d1, d2)
    return n / np.linalg.norm(n)


def smoothed_normal(x, master_faces, nodal_normals, face, xi1, xi2):
    """frix's smoothed normal: bilinear interpolation of the nodal normals, normalised."""
    s = np.array([-1.0, 1.0, 1.0, -1.0]); t = np.array([-1.0, -1.0, 1.0, 1.0])
    shape = (1 + s * xi1) * (1 + t * xi2) / 4.0
    m = sum(shape[a] * nodal_normals[node] for a, node in enumerate(master_faces[face]))
    return m / np.linalg.norm(m)


def pipe_frame(along, up):
    """The rotation Q (rows: the model's unit vectors e_h, e_along, e_up) into the frame in
    which the pipe axis is the second coordinate and the crown direction the third, as in S5;
    e_h = e_along x e_up, so that the frame is right-handed and normals keep their sign."""
    unit = {name: np.eye(3)[k] for k, name in enumerate("xyz")}
    if along not in unit or up not in unit or along == up:
        sys.exit("s5_contact_profile.py: --along and --up must be two different axes of x, y, z")
    return np.array([np.cross(unit[along], unit[up]), unit[along], unit[up]])


def profile(path, slave, master, axis_x, axis_z, pipe_master, increment=None, smoothed=False,
            along="y", up="z", section=None):
    """The table of the module head for the pipe along --along with its crown towards --up;
    (axis_x, axis_z): the pipe axis in the section's (e_h, e_up) coordinates; `section`: the
    position along the axis of the section taken (default: the smallest)."""
    frame = pipe_frame(along, up)
    with h5py.File(path, "r") as f:
        groups = sorted(f["increments"].keys())
        g = f["increments"][groups[-1] if increment is None else "%06d" % increment]
        xref = f["mesh/coordinates"][:]
        ids = f["mesh/node_ids"][:]
        conn = f["mesh/connectivity"][:]
        u = g["displacement"][:]
        p = g["contact/pressure"][:]
        trac = g["contact/traction"][:]
        status = g["contact/status"][:]
        hist = g["contact/pass1_history"][:]
        stored_normal = g["contact/normal"][:] if "normal" in g["contact"] else None
        slave_el = f["mesh/surfaces/%s/elements" % slave][:]
        slave_face = f["mesh/surfaces/%s/faces" % slave][:]
        surf_el = f["mesh/surfaces/%s/elements" % master][:]
        surf_face = f["mesh/surfaces/%s/faces" % master][:]
    xref, u, trac = xref @ frame.T, u @ frame.T, trac @ frame.T
    if stored_normal is not None:
        stored_normal = stored_normal @ frame.T
    x = xref + u
    if section is None:
        section = xref[:, 1].min()
    # slave nodes in frix's pass order: first appearance over the slave surface's faces
    slaves, seen = [], set()
    for e, fc in zip(slave_el, slave_face):
        for a in FACES[int(fc)]:
            node = conn[e - 1][a - 1] - 1
            if node not in seen:
                seen.add(node)
                slaves.append(node)
    if len(slaves) != len(hist):
        sys.exit("s5_contact_profile.py: %d slave nodes but %d rows in pass1_history"
                 % (len(slaves), len(hist)))
    corners = ((-1, -1), (1, -1), (1, 1), (-1, 1))
    master_faces = [[conn[e - 1][a - 1] - 1 for a in FACES[int(fc)]]
                    for e, fc in zip(surf_el, surf_face)]
    nodal_normals = {}
    if smoothed:                               # docs/contact.md "Normals"
        for nodes in master_faces:
            for a, node in enumerate(nodes):
                nodal_normals[node] = nodal_normals.get(node, 0.0) + face_normal(x[nodes], *corners[a])
        for node in nodal_normals:
            nodal_normals[node] /= np.linalg.norm(nodal_normals[node])
    # the pipe's own normal at each slave node, current configuration: the normalised sum of
    # the slave faces' normals at the node (the slave surface's smoothed nodal normal)
    slave_normals = {}
    for e, fc in zip(slave_el, slave_face):
        nodes = [conn[e - 1][a - 1] - 1 for a in FACES[int(fc)]]
        for a, node in enumerate(nodes):
            slave_normals[node] = slave_normals.get(node, 0.0) + face_normal(x[nodes], *corners[a])
    in_section = [k for k, i in enumerate(slaves) if abs(xref[i, 1] - section) <= 1e-9]
    # a half model (every section node on one side of the plane through the axis and the
    # crown, as S5): that plane is a symmetry plane
    half_model = all(xref[slaves[k], 0] - axis_x >= -1e-9 for k in in_section) or \
        all(xref[slaves[k], 0] - axis_x <= 1e-9 for k in in_section)
    rows = []
    for k in in_section:
        i = slaves[k]
        face = int(hist[k, 0])
        el = conn[surf_el[face - 1] - 1]           # internal numbers, 1-based
        corner = [el[a - 1] - 1 for a in FACES[int(surf_face[face - 1])]]
        if stored_normal is not None and np.linalg.norm(stored_normal[i]) > 0.0:
            n = stored_normal[i]                # the normal frix used
        elif smoothed:
            n = smoothed_normal(x, master_faces, nodal_normals, face - 1, hist[k, 1], hist[k, 2])
        else:
            n = face_normal(x[corner], hist[k, 1], hist[k, 2])
        force = p[i] * n + trac[i]
        if pipe_master:
            force = -force
        dx, dz = xref[i, 0] - axis_x, xref[i, 2] - axis_z
        angle = np.arctan2(dx, dz)              # from the crown, towards +x (reference)
        e_r = slave_normals[i] * (-1.0 if pipe_master else 1.0)   # out of the pipe, current
        if half_model and abs(xref[i, 0] - axis_x) < 1e-9:
            e_r[0] = 0.0                        # on the symmetry plane: mirrored neighbour
        e_r[1] = 0.0
        e_r /= np.linalg.norm(e_r)
        e_t = np.array([e_r[2], 0.0, -e_r[0]])
        kink = np.degrees(np.arccos(min(1.0, abs(n @ e_r))))
        rows.append((ids[i], np.degrees(angle), p[i], np.linalg.norm(trac[i]), -force @ e_r,
                     force @ e_t, kink))
    rows.sort(key=lambda r: r[1])
    return np.array(rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog=__doc__.split("\n\n", 1)[1])
    parser.add_argument("h5", help="frix HDF5 results file (RESULTS HDF5 Yes)")
    parser.add_argument("--slave", default="pipe_outer", help="slave surface name (pipe_outer)")
    parser.add_argument("--master", default="cavity", help="master surface name (cavity)")
    parser.add_argument("--pipe-master", action="store_true",
                        help="the pipe is the master surface (the soil cavity is the slave)")
    parser.add_argument("--axis", default="0,-2",
                        help="the pipe axis's position in the section: horizontal,vertical "
                             "coordinates (0,-2; with the defaults of --along and --up: x,z)")
    parser.add_argument("--along", default="y", choices=("x", "y", "z"),
                        help="the model axis the pipe runs along (y)")
    parser.add_argument("--up", default="z", choices=("x", "y", "z"),
                        help="the model axis towards the crown (z); the horizontal axis of "
                             "the section is along x up")
    parser.add_argument("--section", type=float, default=None,
                        help="the section's coordinate along the pipe (default: the smallest "
                             "of the mesh, S5's front face)")
    parser.add_argument("--smoothed", action="store_true",
                        help="files without contact/normal only: the pair used NORMALS Smoothed, "
                             "rebuild frix's smoothed normal")
    parser.add_argument("--increment", type=int, default=None, help="running increment number (last)")
    parser.add_argument("--csv", help="write the table to this CSV file")
    parser.add_argument("--plot", help="plot p_r and tau against the angle into this PNG")
    args = parser.parse_args()
    ax, az = (float(v) for v in args.axis.split(","))
    table = profile(args.h5, args.slave, args.master, ax, az, args.pipe_master, args.increment,
                    args.smoothed, args.along, args.up, args.section)
    header = "node,angle_deg,p_N,t_frix,p_r,tau,kink_deg"
    if args.csv:
        np.savetxt(args.csv, table, delimiter=",", header=header, comments="",
                   fmt=["%d"] + ["%.10e"] * 6)
    else:
        print(header.replace(",", " "))
        for r in table:
            print("%6d %9.3f %13.6e %13.6e %13.6e %13.6e %8.4f" % tuple(r))
    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(figsize=(6, 4))
        axes.plot(table[:, 1], table[:, 4], "o-", label="radial pressure p_r")
        axes.plot(table[:, 1], table[:, 5], "s-", label="shear tau (true frame)")
        axes.plot(table[:, 1], table[:, 2], ":", label="frix p_N")
        axes.set_xlabel("angle from the crown (degrees)")
        axes.set_ylabel("interface traction on the pipe (kPa)")
        axes.legend(); axes.grid(True)
        fig.tight_layout(); fig.savefig(args.plot, dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
