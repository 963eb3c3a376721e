#!/usr/bin/python3
"""Plot a nodal field along a line of nodes of a frix result, against an analytical curve.

Nodes are chosen either geometrically (--line x0,y0,z0,x1,y1,z1: the nodes within --tol of
that segment, in the reference configuration) or by a node set file (--node-set: user node
ids, separated by blanks, commas or newlines, '#' comments). They are sorted by their position
along the line: the distance from (x0, y0, z0) along the segment's direction (with --node-set
and no --line: the coordinate named by --axis, default the axis of largest spread).

The analytical curve is a numpy expression (--analytic) of
    x  the position along the line (as above; same length unit as the mesh),
    t  the time (load factor) of the increment plotted,
with numpy functions (sin, exp, sinh, cosh, tanh, coth, sqrt, where, ... or np.<name>) and
no other names; or a CSV file (--analytic-csv): first column the position, every further
column a curve (one header line optional).

Several increments (--increments all, or a list) give one curve each, e.g. the interface
displacement at every load level. --csv writes the sampled values.
"""

import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import frix_results  # noqa: E402
from frix_results import UserError  # noqa: E402

AXES = {"x": 0, "y": 1, "z": 2}


def build_parser():
    parser = frix_results.ArgumentParser(
        description="Plot a nodal field of a frix .pvd/.vtu along a line of nodes (chosen by a "
                    "segment or a node set file), optionally against an analytical curve.",
        epilog="Example: plot_line.py run.pvd --line 0,0,0,10,0,0 --field displacement:x "
               "--increments all --analytic 't*x/1000' -o ux.png --csv ux.csv")
    parser.add_argument("result", help="<base>.pvd collection or one .vtu file")
    parser.add_argument("--field", default="displacement:0", metavar="NAME[:COMPONENT]",
                        help="point field and component: index 0.. or x/y/z (vectors), "
                             "xx/yy/zz/xy/yz/xz (tensors, VTK order), mag (default: "
                             "displacement:0)")
    parser.add_argument("--line", default=None, metavar="X0,Y0,Z0,X1,Y1,Z1",
                        help="segment: select the nodes within --tol of it and sort along it")
    parser.add_argument("--tol", type=float, default=None, metavar="DISTANCE",
                        help="distance tolerance of --line (default: 1e-6 x the mesh's "
                             "bounding-box diagonal)")
    parser.add_argument("--node-set", default=None, metavar="FILE",
                        help="file of node ids to plot instead of (or filtered by) --line")
    parser.add_argument("--node-numbering", choices=("id", "internal"), default="id",
                        help="node set file holds user ids (default; mapped through the "
                             "listing <base>_listing.txt or --listing) or internal 1-based "
                             "numbers (the .vtu point order)")
    parser.add_argument("--listing", default=None, metavar="FILE",
                        help="listing giving the user node ids (default <base>_listing.txt)")
    parser.add_argument("--axis", choices=("x", "y", "z"), default=None,
                        help="with --node-set and no --line: the coordinate used as position")
    parser.add_argument("--increments", default="last", metavar="SPEC",
                        help="last (default), all, or a comma list of 1-based positions in the "
                             ".pvd (negative: from the end) or STEP:INCREMENT")
    parser.add_argument("--merge", action="store_true",
                        help="average the values of nodes at the same position (within --tol)")
    parser.add_argument("--analytic", default=None, metavar="EXPR",
                        help="analytical curve: numpy expression in x (position along the "
                             "line) and t (time = load factor), e.g. 't*3*x/2000'; functions: "
                             "sin cos tan sinh cosh tanh coth exp log log10 sqrt abs sign "
                             "where minimum maximum clip hypot power arc*, pi, e, np.<ufunc>")
    parser.add_argument("--analytic-csv", default=None, metavar="FILE",
                        help="analytical curve(s) from a CSV: position, value[, value...]")
    parser.add_argument("--analytic-label", default="analytic", help="legend of --analytic")
    parser.add_argument("--scale", type=float, default=1.0, metavar="FACTOR",
                        help="multiply the field values by FACTOR")
    parser.add_argument("--csv", default=None, metavar="FILE", help="write the sampled values")
    parser.add_argument("--xlabel", default=None, help="x axis label")
    parser.add_argument("--ylabel", default=None, help="y axis label (default: the field)")
    parser.add_argument("--title", default=None, help="figure title")
    parser.add_argument("-o", "--output", default="line.png", metavar="PNG",
                        help="output image (default: line.png)")
    return parser


def select_points(points, args, node_ids):
    """Indices of the selected points and their positions along the line, sorted."""
    diagonal = float(np.linalg.norm(points.max(axis=0) - points.min(axis=0))) or 1.0
    tolerance = args.tol if args.tol is not None else 1e-6 * diagonal
    if tolerance < 0:
        raise UserError("--tol must not be negative")
    candidates = np.arange(len(points))
    if args.node_set is not None:
        wanted = frix_results.read_id_file(args.node_set)
        if args.node_numbering == "internal":
            bad = [number for number in wanted if not 1 <= number <= len(points)]
            if bad:
                raise UserError(f"{args.node_set}: internal node number(s) out of range "
                                f"1..{len(points)}: {bad[:5]}")
            candidates = np.array(wanted, dtype=int) - 1
        else:
            if node_ids is None:
                raise UserError("user node ids unknown: the .vtu has no node_id field and no "
                                "listing was found (give --listing or --node-numbering internal)")
            index_of = {int(node): index for index, node in enumerate(node_ids)}
            missing = [node for node in wanted if node not in index_of]
            if missing:
                raise UserError(f"{args.node_set}: node id(s) not in the mesh: {missing[:5]}")
            candidates = np.array([index_of[node] for node in wanted], dtype=int)
        candidates = np.unique(candidates)
    if args.line is not None:
        values = frix_results.parse_floats(args.line, 6, "--line")
        start, end = np.array(values[:3]), np.array(values[3:])
        length = float(np.linalg.norm(end - start))
        if length == 0.0:
            raise UserError("--line: start and end points coincide")
        direction = (end - start) / length
        relative = points[candidates] - start
        position = relative @ direction
        distance = np.linalg.norm(relative - np.outer(position, direction), axis=1)
        keep = (distance <= tolerance) & (position >= -tolerance) & (position <= length + tolerance)
        candidates, position = candidates[keep], position[keep]
    else:
        if args.node_set is None:
            raise UserError("give --line X0,Y0,Z0,X1,Y1,Z1 or --node-set FILE")
        chosen = points[candidates]
        axis = AXES[args.axis] if args.axis else int(np.argmax(np.ptp(chosen, axis=0)))
        position = chosen[:, axis]
    if candidates.size == 0:
        raise UserError(f"no node within {tolerance:g} of the line {args.line}")
    order = np.argsort(position, kind="stable")
    return candidates[order], position[order], tolerance


def merge_positions(position, values, tolerance):
    """Average values whose positions differ by at most ``tolerance`` (sorted input)."""
    groups = np.concatenate([[0], np.cumsum(np.diff(position) > tolerance)])
    count = groups[-1] + 1
    merged_position = np.array([position[groups == group].mean() for group in range(count)])
    merged_values = np.array([values[groups == group].mean() for group in range(count)])
    return merged_position, merged_values


def read_analytic_csv(path):
    """(position, curves, names) from a CSV of position, value[, value...]."""
    frix_results.require_file(path, "analytic CSV")
    with open(path, encoding="utf-8", errors="replace") as stream:
        rows = [row for row in csv.reader(stream) if row and not row[0].startswith("#")]
    if not rows:
        raise UserError(f"{path}: empty file")
    names = None
    try:
        [float(field) for field in rows[0]]
    except ValueError:
        names, rows = [field.strip() for field in rows[0]], rows[1:]
    try:
        data = np.array([[float(field) for field in row] for row in rows], dtype=float)
    except ValueError:
        raise UserError(f"{path}: a field is not a number") from None
    if data.ndim != 2 or data.shape[0] < 2 or data.shape[1] < 2:
        raise UserError(f"{path}: need at least 2 rows of 'position, value'")
    if names is None or len(names) != data.shape[1]:
        names = ["position"] + [f"analytic {column}" for column in range(1, data.shape[1])]
    order = np.argsort(data[:, 0])
    return data[order, 0], data[order, 1:], names[1:]


def main(argv=None):
    args = build_parser().parse_args(argv)
    series = frix_results.ResultSeries(args.result)
    entries = series.select(args.increments)
    analytic = frix_results.compile_expression(args.analytic, ("x", "t")) \
        if args.analytic is not None else None
    reference = read_analytic_csv(args.analytic_csv) if args.analytic_csv is not None else None

    first = series.mesh(entries[0])
    points = np.asarray(first.points, dtype=float)
    need_ids = args.node_set is not None and args.node_numbering == "id"
    node_ids = frix_results.node_ids(series, first, args.listing) if need_ids or args.csv else None
    indices, position, tolerance = select_points(points, args, node_ids)

    pyplot = frix_results.use_agg_backend()
    figure, axes = pyplot.subplots(figsize=(7, 5))
    colors = pyplot.rcParams["axes.prop_cycle"].by_key()["color"]
    rows = []
    for number, entry in enumerate(entries):
        mesh = series.mesh(entry)
        if len(mesh.points) != len(points):
            raise UserError(f"{entry.path}: {len(mesh.points)} points, the first increment has "
                            f"{len(points)}")
        values = frix_results.field_values(mesh, args.field, "point")[indices] * args.scale
        color = colors[number % len(colors)]
        label = entry.label() if len(entries) > 1 else args.field
        plot_position, plot_values = (merge_positions(position, values, tolerance)
                                      if args.merge else (position, values))
        axes.plot(plot_position, plot_values, "o-", color=color, markersize=4, label=label)
        exact = None
        if analytic is not None:
            fine = np.linspace(position.min(), position.max(), 201)
            axes.plot(fine, analytic(x=fine, t=np.full_like(fine, entry.time)), "k--",
                      linewidth=1, zorder=3, label=args.analytic_label if number == 0 else None)
            exact = analytic(x=position, t=np.full_like(position, entry.time))
        for row, index in enumerate(indices):
            rows.append([entry.step, entry.increment, entry.time, index + 1,
                         node_ids[index] if node_ids is not None else "",
                         *points[index], position[row], values[row]]
                        + ([exact[row]] if exact is not None else []))
    if reference is not None:
        reference_position, curves, names = reference
        for column, name in enumerate(names):
            axes.plot(reference_position, curves[:, column], "k--" if column == 0 else "--",
                      linewidth=1, label=name)
    axes.set_xlabel(args.xlabel or ("position along the line" if args.line else
                                    "coordinate"))
    axes.set_ylabel(args.ylabel or args.field)
    if args.title:
        axes.set_title(args.title)
    axes.grid(True, alpha=0.3)
    axes.legend(fontsize="small")
    frix_results.save_figure(figure, args.output)
    print(f"wrote {args.output} ({indices.size} nodes, {len(entries)} increment(s))")

    if args.csv is not None:
        header = ["step", "increment", "time", "point", "node_id", "x", "y", "z", "position",
                  "value"] + (["analytic"] if analytic is not None else [])
        frix_results.write_csv(args.csv, header,
                               (["" if item is None else
                                 (repr(float(item)) if isinstance(item, (float, np.floating)) else item)
                                 for item in row] for row in rows))
        print(f"wrote {args.csv} ({len(rows)} rows)")
    return 0


if __name__ == "__main__":
    frix_results.run_main(main)
