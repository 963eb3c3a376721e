#!/usr/bin/python3
"""Summarise S6(b) runs (pipe crossing a slope) for the elastic/Mohr-Coulomb soil comparison
of docs/verification/s6.md, from their HDF5 files (layout: docs/hdf5-layout.md).

usage: s6_soil_summary.py RUN.h5 [RUN.h5 ...] [--times 2,3] [--buried-z 6.5]

For each file and each pseudo time t (2: the seed's 1 x load, 3: 10 x; the increment whose
time is nearest) one block of lines:
- pipe von Mises stress of the element means of the Cauchy stress (MPa): the range over the
  buried elements (centroid z < BURIED_Z) and the largest over the whole pipe; sigma_zz range
  over the whole pipe;
- the pipe-soil interface (node set pipe_outer_soil, the contact slave nodes): mean and
  largest contact pressure (MPa), nodes in stick / slip, the largest accumulated slip (mm);
- the soil's yielded elements and integration points (fields/yielded; 0 for an elastic soil);
- the displacements (mm, measured from the end of the geostatic step) of the history node
  sets: crown / invert u_y and springline u_x at z = 2.5, 6 and 9.5, ground u_y at z = 2.5.

Run with /usr/bin/python3 (Debian's h5py and numpy).
"""
import argparse
import os

import h5py
import numpy as np

HISTORY_SETS = [("crown_z2.5", 1), ("invert_z2.5", 1), ("springline_z2.5", 0),
                ("crown_z6", 1), ("invert_z6", 1), ("crown_z9.5", 1), ("invert_z9.5", 1),
                ("springline_z9.5", 0), ("ground_z2.5", 1)]


def von_mises(s):
    """von Mises stress of Voigt rows (xx yy zz xy xz yz, tensor shears)."""
    return np.sqrt(0.5 * ((s[:, 0] - s[:, 1]) ** 2 + (s[:, 1] - s[:, 2]) ** 2
                          + (s[:, 2] - s[:, 0]) ** 2) + 3.0 * (s[:, 3] ** 2 + s[:, 4] ** 2
                                                               + s[:, 5] ** 2))


def nearest_increment(results, t):
    groups = results["increments"]
    names = [n for n in groups if groups[n].attrs.get("complete", 0) == 1]
    return groups[min(names, key=lambda n: abs(groups[n].attrs["time"] - t))]


def element_centroid_z(results, elements):
    conn = results["mesh/connectivity"][...][elements - 1]
    z = results["mesh/coordinates"][:, 2]
    return np.array([z[row[row > 0] - 1].mean() for row in conn])


def summary(results, group, buried_z):
    mesh = results["mesh"]
    pipe = mesh["element_sets/pipe"][...]
    soil = mesh["element_sets/soil"][...]
    stress = group["stress"][...]
    pipe_mean = stress[pipe - 1].mean(axis=1)
    vm = von_mises(pipe_mean)
    buried = element_centroid_z(results, pipe) < buried_z
    lines = ["pipe von Mises buried %.1f-%.1f, whole pipe largest %.1f; sigma_zz %.1f-%.1f"
             % (vm[buried].min(), vm[buried].max(), vm.max(), pipe_mean[:, 2].min(),
                pipe_mean[:, 2].max())]
    slaves = mesh["node_sets/pipe_outer_soil"][...] - 1
    status = group["contact/status"][...][slaves]
    pressure = group["contact/pressure"][...][slaves]
    slip = group["contact/slip"][...][slaves]
    lines.append("contact pressure mean %.3f largest %.3f; stick %d slip %d open %d; "
                 "largest slip %.3f mm" % (pressure.mean(), pressure.max(), (status == 1).sum(),
                                          (status == 2).sum(), (status == 0).sum(),
                                          1e3 * slip.max()))
    if "fields/yielded" in group:
        yielded = group["fields/yielded"][...][soil - 1] > 0.5
        lines.append("soil yielded: %d elements, %d points of %d"
                     % (yielded.any(axis=1).sum(), yielded.sum(), yielded.size))
    else:
        lines.append("soil yielded: (no yield field)")
    u = group["displacement"][...]
    parts = []
    for name, component in HISTORY_SETS:
        nodes = mesh["node_sets/" + name][...] - 1
        parts.append("%s %.3f" % (name, 1e3 * u[nodes, component].mean()))
    lines.append("u (mm): " + ", ".join(parts))
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("files", nargs="+")
    parser.add_argument("--times", default="2,3")
    parser.add_argument("--buried-z", type=float, default=6.5)
    args = parser.parse_args()
    for path in args.files:
        with h5py.File(path, "r") as results:
            for t in (float(x) for x in args.times.split(",")):
                group = nearest_increment(results, t)
                print("%s t = %g" % (os.path.basename(path), group.attrs["time"]))
                for line in summary(results, group, args.buried_z):
                    print("  " + line)


if __name__ == "__main__":
    main()
