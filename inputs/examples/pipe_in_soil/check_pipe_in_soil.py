"""Check a run of pipe_in_soil.dck: check_pipe_in_soil.py RESULTS.h5

- the run reached t = 1 (the last increment written is at the step's end);
- statics: the pull P, the sum of the x reactions on the pipe's two end faces (node sets
  pipe_end0 and pipe_end1), is positive, and the sum of the x reactions on the soil's supports
  (soil_bottom, soil_sides, soil_ends; each node counted once) is -P to 1e-6 of P: no other
  force acts on the model;
- plausibility: P lies between 0.1 and 1 times P_annulus = k u L, k = 8 pi G (1 - nu) /
  ((3 - 4 nu) ln(b/a) - (b^2 - a^2)/(b^2 + a^2)), the stiffness per unit length of a rigid
  disc of radius a = 0.5 bonded in a plane-strain elastic annulus held at radius b = 2 (the
  circle inscribed in the block; the laterally loaded pile of Baguelin, Frank & Said 1977,
  Geotechnique 27(3), quoted as recalled and not checked against the paper: an order of
  magnitude, hence the wide range). An estimate, not a bound: the model's pipe separates from the soil
  behind it and slides along it (mu = 0.3), and the block's top is free, all of which make it
  softer; measured P / P_annulus = 0.33;
- the deck's HISTORY totals at the last increment: r1_sum_pipe_end0 + r1_sum_pipe_end1 = P
  to 1e-9, the contact resultant c1_pair1 = -P to 1e-6 (the pipe is held by its ends and pushed
  back by the soil only), the ends' mean u_x 0.02;
- every pipe node moved by u_x = 0.02 at the ends (the prescribed pull) and the soil's
  largest u_x lies between 0 and 0.02 (pushed by the pipe, never beyond it).
Prints P and the statics error. Exit 0 if all hold.
"""
import csv
import sys

import h5py
import numpy as np


def main():
    failed = False
    with h5py.File(sys.argv[1], "r") as f:
        last = f["/increments"][sorted(f["/increments"])[-1]]
        time = last.attrs["time"]
        reaction = last["reaction"][()]
        u = last["displacement"][()]
        sets = {name: f["/mesh/node_sets/" + name][()] - 1 for name in f["/mesh/node_sets"]}
        soil_elements = f["/mesh/element_sets/soil"][()] - 1
        soil_nodes = np.unique(f["/mesh/connectivity"][()][soil_elements] - 1)
    print(f"last increment at t = {time}")
    failed |= abs(time - 1.0) > 1e-12

    pipe_ends = np.union1d(sets["pipe_end0"], sets["pipe_end1"])
    supports = np.union1d(np.union1d(sets["soil_bottom"], sets["soil_sides"]), sets["soil_ends"])
    pull = reaction[pipe_ends, 0].sum()
    soil = reaction[supports, 0].sum()
    statics = abs(pull + soil) / abs(pull)
    print(f"pull on the pipe's ends {pull:.6e} kN, x reactions of the soil's supports {soil:.6e} kN, "
          f"statics error {statics:.1e}")
    failed |= not (pull > 0 and statics <= 1e-6)

    # the deck's HISTORY totals (the CSV beside the HDF5 file) at the last increment: the two
    # ends' pulls add up to P, and the contact resultant on the pipe (the soil's push, along -x)
    # balances it to the Newton tolerance
    history = sys.argv[1][:-len(".h5")] + "_history.csv"
    with open(history) as handle:
        rows = list(csv.DictReader(handle))
    last_row = {key: float(value) for key, value in rows[-1].items()}
    ends = last_row["r1_sum_pipe_end0"] + last_row["r1_sum_pipe_end1"]
    push = last_row["c1_pair1"]
    print(f"history totals: r1_sum_pipe_end0 + r1_sum_pipe_end1 = {ends:.6e} kN, c1_pair1 = {push:.6e} kN, "
          f"u1_mean_pipe_end0 = {last_row['u1_mean_pipe_end0']:.6f}")
    failed |= not (abs(ends - pull) <= 1e-9 * abs(pull) and abs(push + pull) <= 1e-6 * abs(pull)
                   and abs(last_row["u1_mean_pipe_end0"] - 0.02) <= 1e-12)

    E, nu, a, b, u_pull, length = 2.0e4, 0.3, 0.5, 2.0, 0.02, 4.0
    G = E / (2 * (1 + nu))
    k = 8 * np.pi * G * (1 - nu) / ((3 - 4 * nu) * np.log(b / a) - (b**2 - a**2) / (b**2 + a**2))
    ratio = pull / (k * u_pull * length)
    print(f"P / P_annulus = {ratio:.3f} (P_annulus = {k * u_pull * length:.4e} kN)")
    failed |= not 0.1 <= ratio <= 1.0

    end_error = np.abs(u[pipe_ends, 0] - 0.02).max()
    soil_max = u[soil_nodes, 0].max()
    print(f"pipe ends' u_x error {end_error:.1e}, soil's largest u_x {soil_max:.6f}")
    failed |= not (end_error <= 1e-12 and 0 < soil_max <= 0.02 + 1e-9)
    print("FAIL" if failed else "OK")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
