#!/usr/bin/python3
"""Displacement differences between two frix runs of the same mesh at a set of nodes.

Reads two frix HDF5 results files (``HDF5 Yes``, docs/hdf5-layout.md), e.g. the same deck
with MU 0.1 and MU 0.3, and tabulates at every node of the selection

    d = scale (u_B - u_A)        (dx, dy, dz and |d|; run B minus run A)

at one increment common to both runs. The selection is one of:

- ``--pair ID``: the slave nodes of contact pair ID (its first pass, i.e. the nodes of its
  SLAVE surface; ``--all-passes``: every pass of the pair, with PASSES 2 also the master
  surface's nodes), read from ``<base>_contact.csv`` beside each ``.h5`` (docs/output.md),
- ``--surface NAME``: the nodes of a surface of the mesh (``/mesh/surfaces``),
- ``--node-set NAME``: a node set of the mesh (``/mesh/node_sets``).

The increment: by default the last time (load factor) present in both runs (runs with
different cut-backs number their increments differently, so increments are matched by time,
to 1e-9 relative); ``--time T``, ``--increment first`` or ``--increment STEP:INCREMENT`` (the
same step and increment in both, which must be at the same time).

The compared field is the written ``displacement`` of each increment group. With a deck
option that makes the written displacement relative to a reference state (e.g. resetting it
after a geostatic step), the differences are those of the relative displacements.

The runs must share the mesh (node ids, reference coordinates, connectivity) and the
selection must have the same nodes in both; otherwise, as for a missing file or no common
increment, the script stops with a one-line message and exit status 2.

Output: a summary on stdout (the largest difference of each component with its node and
reference position), ``--table CSV`` (one row per node), ``--plot PNG`` (the differences
against the reference coordinate ``--axis``, one curve per component).
"""

import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import frix_results  # noqa: E402
from frix_results import UserError  # noqa: E402

COMPONENTS = ("dx", "dy", "dz", "dmag")
AXES = {"x": 0, "y": 1, "z": 2}
TIME_TOLERANCE = 1e-9          # relative, to match increments of two runs by time


def build_parser():
    parser = frix_results.ArgumentParser(
        description="Displacement differences (run B minus run A) at the slave nodes of a "
                    "contact pair, a surface or a node set, between two frix HDF5 results "
                    "files of the same mesh, at one common increment.",
        epilog="Example (S6, mu 0.1 vs 0.3 in mm): compare_runs.py s6_mu0.1.h5 s6_mu0.3.h5 "
               "--pair 1 --scale 1000 --unit mm --table dd.csv --plot dd.png --axis z")
    parser.add_argument("run_a", metavar="A.h5", help="frix HDF5 results file of run A")
    parser.add_argument("run_b", metavar="B.h5", help="frix HDF5 results file of run B")
    which = parser.add_mutually_exclusive_group(required=True)
    which.add_argument("--pair", type=int, metavar="ID",
                       help="the slave nodes of contact pair ID (from <base>_contact.csv)")
    which.add_argument("--surface", metavar="NAME", help="the nodes of a mesh surface")
    which.add_argument("--node-set", metavar="NAME", help="the nodes of a mesh node set")
    parser.add_argument("--all-passes", action="store_true",
                        help="with --pair: the nodes of every pass of the pair (PASSES 2: also "
                             "the master surface's nodes), not only the first pass")
    parser.add_argument("--contact-csv", metavar="A.csv,B.csv",
                        help="with --pair: the contact CSV files of the two runs (default: "
                             "<base>_contact.csv beside each .h5)")
    parser.add_argument("--increment", default="last", metavar="SPEC",
                        help="last (default: the last time common to both runs), first (the "
                             "first common time) or STEP:INCREMENT (the same in both runs)")
    parser.add_argument("--time", type=float, default=None, metavar="T",
                        help="the increment at time (load factor) T in both runs")
    parser.add_argument("--scale", type=float, default=1.0, metavar="F",
                        help="multiply displacements and differences by F (e.g. 1000: m -> mm)")
    parser.add_argument("--unit", default="", metavar="TEXT",
                        help="unit of the scaled values, for the summary and plot (e.g. mm)")
    parser.add_argument("--table", metavar="CSV", help="write one row per node")
    parser.add_argument("--plot", metavar="PNG", help="plot the differences against --axis")
    parser.add_argument("--axis", choices=sorted(AXES), default=None,
                        help="position coordinate (reference) for the plot and the table's "
                             "order (default: the one along which the nodes spread most)")
    parser.add_argument("--labels", metavar="A,B",
                        help="names of the two runs (default: the files' names without .h5)")
    parser.add_argument("--title", default=None, help="plot title")
    return parser


def close_times(first, second):
    return abs(first - second) <= TIME_TOLERANCE * max(1.0, abs(first), abs(second))


def common_increments(run_a, run_b):
    """[(entry A, entry B)] with equal times, in A's order; for a time written more than
    once in a run (none in frix's pseudo time), its last increment."""
    pairs = []
    for entry_a in run_a.increments:
        matches = [entry_b for entry_b in run_b.increments if close_times(entry_a.time, entry_b.time)]
        if matches:
            if pairs and close_times(pairs[-1][0].time, entry_a.time):
                pairs.pop()
            pairs.append((entry_a, matches[-1]))
    return pairs


def select_increments(run_a, run_b, args):
    """The two increment entries to compare (UserError if there is no such common one)."""
    for run in (run_a, run_b):
        if not run.increments:
            raise UserError(f"{run.path}: no complete increment group under /increments")
    spec = str(args.increment).strip().lower()
    if args.time is not None:
        if spec != "last":
            raise UserError("give --time or --increment, not both")
        chosen = [pair for pair in common_increments(run_a, run_b)
                  if close_times(pair[0].time, args.time)]
        if not chosen:
            raise UserError(f"time {args.time:g} is not in both runs (times of {run_a.path}: "
                            f"{times(run_a)}; of {run_b.path}: {times(run_b)})")
        return chosen[-1]
    if spec in ("last", "first"):
        common = common_increments(run_a, run_b)
        if not common:
            raise UserError(f"{run_a.path} and {run_b.path} have no increment at a common time "
                            f"(times of A: {times(run_a)}; of B: {times(run_b)})")
        return common[-1 if spec == "last" else 0]
    if ":" not in spec:
        raise UserError(f"--increment '{args.increment}': use last, first or STEP:INCREMENT "
                        "(positions differ between runs)")
    entry_a, entry_b = run_a.select(spec), run_b.select(spec)
    if not close_times(entry_a.time, entry_b.time):
        raise UserError(f"increment {spec} is at t = {entry_a.time:.17g} in {run_a.path} but "
                        f"t = {entry_b.time:.17g} in {run_b.path}; choose one with --time")
    return entry_a, entry_b


def times(run):
    return ", ".join(f"{entry.time:g}" for entry in run.increments)


def check_same_mesh(run_a, run_b):
    """Node ids, reference coordinates and connectivity identical (coordinates to 1e-12 of
    the bounding box); returns (node_ids, coordinates)."""
    ids_a, ids_b = run_a.mesh_array("node_ids"), run_b.mesh_array("node_ids")
    x_a, x_b = run_a.mesh_array("coordinates"), run_b.mesh_array("coordinates")
    c_a, c_b = run_a.mesh_array("connectivity"), run_b.mesh_array("connectivity")
    prefix = f"{run_a.path} and {run_b.path} are not runs of the same mesh"
    if ids_a.shape != ids_b.shape or c_a.shape != c_b.shape:
        raise UserError(f"{prefix}: {ids_a.size} vs {ids_b.size} nodes, {len(c_a)} vs {len(c_b)} "
                        "elements")
    if not np.array_equal(ids_a, ids_b):
        raise UserError(f"{prefix}: the node ids differ")
    if not np.array_equal(c_a, c_b):
        raise UserError(f"{prefix}: the connectivity differs")
    size = max(float(np.ptp(x_a, axis=0).max()), 1.0e-300)
    worst = float(np.max(np.abs(x_a - x_b))) if x_a.size else 0.0
    if worst > 1e-12 * size:
        raise UserError(f"{prefix}: the node coordinates differ by up to {worst:.3e}")
    return ids_a.astype(int), np.asarray(x_a, dtype=float)


def contact_csv_paths(args):
    if args.contact_csv is not None:
        paths = [part.strip() for part in args.contact_csv.split(",")]
        if len(paths) != 2 or not all(paths):
            raise UserError(f"--contact-csv needs two files A.csv,B.csv, got '{args.contact_csv}'")
        return paths
    return [os.path.splitext(path)[0] + "_contact.csv" for path in (args.run_a, args.run_b)]


def select_nodes(run_a, run_b, node_ids, args):
    """0-based internal numbers of the selected nodes (the same in both runs) and a text."""
    if args.pair is not None:
        selected = []
        for path in contact_csv_paths(args):
            ids, passes = frix_results.contact_pair_nodes(path, args.pair, args.all_passes)
            selected.append(ids)
        if not np.array_equal(np.sort(selected[0]), np.sort(selected[1])):
            raise UserError(f"contact pair {args.pair} has different slave nodes in the two runs "
                            f"({selected[0].size} and {selected[1].size} nodes): not the same "
                            "mesh or pair")
        position = {int(node): index for index, node in enumerate(node_ids)}
        missing = [int(node) for node in selected[0] if int(node) not in position]
        if missing:
            raise UserError(f"contact CSV node {missing[0]} is not a node of {run_a.path}")
        internal = np.array([position[int(node)] for node in selected[0]], dtype=int)
        what = (f"contact pair {args.pair} (pass{'es' if len(passes) > 1 else ''} "
                f"{', '.join(map(str, passes))})")
        return internal, what
    if args.surface is not None:
        nodes = [run.surface_nodes(args.surface) for run in (run_a, run_b)]
        what = f"surface {args.surface}"
    else:
        nodes = [run.node_set(args.node_set) for run in (run_a, run_b)]
        what = f"node set {args.node_set}"
    if not np.array_equal(nodes[0], nodes[1]):
        raise UserError(f"{what} has different nodes in {run_a.path} and {run_b.path}")
    if nodes[0].size == 0:
        raise UserError(f"{what} of {run_a.path} is empty")
    return nodes[0], what


def displacement(run, entry, n_nodes):
    values = np.asarray(run.dataset(entry, "displacement"), dtype=float)
    if values.shape != (n_nodes, 3):
        raise UserError(f"{run.path}: displacement of {entry.label()} has shape {values.shape}, "
                        f"expected ({n_nodes}, 3)")
    if not np.all(np.isfinite(values)):
        raise UserError(f"{run.path}: displacement of {entry.label()} has NaN or Inf values")
    return values


def plot(args, position, difference, labels, unit, title):
    pyplot = frix_results.use_agg_backend()
    figure, axes = pyplot.subplots(figsize=(7, 4.5))
    # a ring of nodes at one position (a pipe's cross-section) gives several values there:
    # every node as a marker, the line through the value of largest magnitude at each position
    tolerance = 1e-9 * max(float(np.ptp(position)), 1.0)
    groups = np.split(np.arange(position.size), np.flatnonzero(np.diff(position) > tolerance) + 1)
    repeated = len(groups) < position.size
    for column, name in enumerate(("dx", "dy", "dz", "|d|")):
        values = difference[:, column]
        extreme = [group[np.argmax(np.abs(values[group]))] for group in groups]
        line, = axes.plot(position[extreme], values[extreme], "-",
                          label=name + (" (largest |.| at each position)" if repeated else ""))
        axes.plot(position, values, "o", markersize=3.5, color=line.get_color())
    axes.axhline(0.0, color="0.6", linewidth=0.8)
    axes.set_xlabel(f"{args.axis} (reference position)")
    axes.set_ylabel(f"u({labels[1]}) - u({labels[0]})" + (f" [{unit}]" if unit else ""))
    axes.set_title(title)
    axes.grid(True, alpha=0.4)
    axes.legend()
    frix_results.save_figure(figure, args.plot)
    pyplot.close(figure)


def main(argv=None):
    args = build_parser().parse_args(argv)
    if not np.isfinite(args.scale) or args.scale == 0.0:
        raise UserError(f"--scale must be a finite non-zero number, got {args.scale}")
    if args.pair is None and (args.all_passes or args.contact_csv is not None):
        raise UserError("--all-passes and --contact-csv go with --pair")
    labels = [os.path.splitext(os.path.basename(path))[0] for path in (args.run_a, args.run_b)]
    if args.labels is not None:
        labels = [part.strip() for part in args.labels.split(",")]
        if len(labels) != 2 or not all(labels):
            raise UserError(f"--labels needs two names A,B, got '{args.labels}'")
    with frix_results.H5Results(args.run_a) as run_a, frix_results.H5Results(args.run_b) as run_b:
        node_ids, coordinates = check_same_mesh(run_a, run_b)
        nodes, what = select_nodes(run_a, run_b, node_ids, args)
        entry_a, entry_b = select_increments(run_a, run_b, args)
        u_a = displacement(run_a, entry_a, node_ids.size)[nodes] * args.scale
        u_b = displacement(run_b, entry_b, node_ids.size)[nodes] * args.scale
    ids, x = node_ids[nodes], coordinates[nodes]
    if args.axis is None:
        args.axis = "xyz"[int(np.argmax(np.ptp(x, axis=0)))]
    position = x[:, AXES[args.axis]]
    order = np.lexsort((ids, position))
    ids, x, position, u_a, u_b = ids[order], x[order], position[order], u_a[order], u_b[order]
    difference = u_b - u_a
    difference = np.column_stack([difference, np.linalg.norm(difference, axis=1)])
    unit = args.unit
    at = (entry_a.label() if entry_a.key() == entry_b.key()
          else f"{entry_a.label()} of A, {entry_b.label()} of B")
    print(f"Displacement differences B - A, B = {args.run_b}, A = {args.run_a}")
    print(f"at {at}; {len(ids)} nodes of {what}; scale {args.scale:g}"
          + (f" ({unit})" if unit else ""))
    print(f"{'':5s} {'largest':>14s} {'node':>8s} {'x':>12s} {'y':>12s} {'z':>12s}")
    for column, name in enumerate(COMPONENTS):
        row = int(np.argmax(np.abs(difference[:, column])))
        print(f"{name:5s} {difference[row, column]:14.6e} {ids[row]:8d} "
              f"{x[row, 0]:12.6g} {x[row, 1]:12.6g} {x[row, 2]:12.6g}")
    if args.table is not None:
        header = (["node_id", "x", "y", "z", "position", "ua_x", "ua_y", "ua_z", "ub_x", "ub_y",
                   "ub_z"] + list(COMPONENTS))
        rows = [[int(ids[k])] + [repr(float(value)) for value in
                                 (*x[k], position[k], *u_a[k], *u_b[k], *difference[k])]
                for k in range(len(ids))]
        frix_results.write_csv(args.table, header, rows)
        print(f"wrote {args.table} ({len(rows)} rows)")
    if args.plot is not None:
        title = args.title or f"{labels[1]} - {labels[0]}, {what}, {entry_b.label()}"
        plot(args, position, difference, labels, unit, title)
        print(f"wrote {args.plot}")
    return 0


if __name__ == "__main__":
    frix_results.run_main(main)
