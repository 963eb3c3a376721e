#!/usr/bin/python3
"""Plot columns of frix history files (<base>_history.csv) on one figure.

Each CSV has the columns step, increment, time, then one per requested DOF: u<d>_n<id>
(displacement component d = 1, 2, 3 of user node id) or r<d>_n<id> (reaction). By default
every DOF column is plotted against ``time`` (the load factor / pseudo time). Choose the axes
with --x and --y, e.g. a load-displacement curve with the displacement on x:
``--x u3_n31 --y time`` or ``--x u1_n3 --y=-r1_n1`` (a leading '-' negates a column).
When a deck's loads follow a load curve, --curve T,F,T,F,... (the deck's CURVE ... POINTS)
plots the load factor f(time) wherever ``time`` is plotted.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np  # noqa: E402
import frix_results  # noqa: E402
from frix_results import UserError  # noqa: E402


def build_parser():
    parser = frix_results.ArgumentParser(
        description="Plot load factor (time) against history columns of one or several frix "
                    "<base>_history.csv files on one figure (PNG).",
        epilog="Example: plot_history.py run_a_history.csv run_b_history.csv --x u1_n3 "
               "--y time -o curve.png")
    parser.add_argument("csv", nargs="+", help="history CSV file(s) written by frix")
    parser.add_argument("--x", default="time", metavar="COLUMN",
                        help="column on the x axis (default: time = load factor); a leading "
                             "'-' plots the negated column, e.g. -r1_n1")
    parser.add_argument("--y", default=None, metavar="COLUMN[,COLUMN...]",
                        help="column(s) on the y axis, comma-separated (default: every column "
                             "but step, increment, time; with --x other than time: time); "
                             "'-COLUMN' negates one")
    parser.add_argument("--curve", default=None, metavar="T,F[,T,F...]",
                        help="the deck's load curve (CURVE ... POINTS t1 f1 t2 f2 ...): plot "
                             "the load factor f(time), piecewise linear and constant beyond "
                             "the ends, wherever time is plotted")
    parser.add_argument("--labels", default=None, metavar="LABEL[,LABEL...]",
                        help="legend label per CSV file, comma-separated (default: file stem)")
    parser.add_argument("--xlabel", default=None, help="x axis label (default: the column)")
    parser.add_argument("--ylabel", default=None, help="y axis label (default: the column(s))")
    parser.add_argument("--title", default=None, help="figure title")
    parser.add_argument("--no-markers", action="store_true", help="lines without markers")
    parser.add_argument("-o", "--output", default="history.png", metavar="PNG",
                        help="output image (default: history.png)")
    return parser


def file_stem(path):
    stem = os.path.splitext(os.path.basename(path))[0]
    return stem[:-len("_history")] if stem.endswith("_history") else stem


def parse_curve(text):
    """(times, factors) of ``--curve T,F,T,F,...``; UserError unless at least two pairs with
    strictly increasing times (the deck's rule for CURVE ... POINTS)."""
    try:
        values = [float(v) for v in text.replace(",", " ").split()]
    except ValueError:
        raise UserError(f"--curve: not a number in '{text}'") from None
    if len(values) < 4 or len(values) % 2:
        raise UserError(f"--curve needs pairs T,F (at least two), got '{text}'")
    times, factors = values[0::2], values[1::2]
    if any(t1 <= t0 for t0, t1 in zip(times, times[1:])):
        raise UserError(f"--curve: the times must increase strictly, got '{text}'")
    return times, factors


def signed_column(history, spec, curve=None):
    """Column ``spec`` of a history, negated if ``spec`` is ``-NAME`` (e.g. a reaction); with a
    curve, ``time`` becomes the load factor f(time)."""
    spec = spec.strip()
    if spec.startswith("-") and spec[1:] in history.columns:
        return -signed_column(history, spec[1:], curve)
    values = history.column(spec)
    if spec == "time" and curve is not None:
        values = np.interp(values, curve[0], curve[1])
    return values


def main(argv=None):
    args = build_parser().parse_args(argv)
    curve = parse_curve(args.curve) if args.curve is not None else None
    time_label = "load factor f(time)" if curve is not None else "load factor (time)"
    histories = [frix_results.read_history(path) for path in args.csv]
    labels = [file_stem(path) for path in args.csv]
    if args.labels is not None:
        labels = [label.strip() for label in args.labels.split(",")]
        if len(labels) != len(args.csv):
            raise UserError(f"--labels has {len(labels)} labels for {len(args.csv)} CSV files")

    pyplot = frix_results.use_agg_backend()
    figure, axes = pyplot.subplots(figsize=(7, 5))
    y_names_all = []
    for history, label in zip(histories, labels):
        x = signed_column(history, args.x, curve)
        if args.y is not None:
            y_names = [name.strip() for name in args.y.split(",") if name.strip()]
        elif args.x != "time":
            y_names = ["time"]
        else:
            y_names = history.value_columns()
        if not y_names:
            raise UserError(f"{history.path}: no columns to plot (columns: "
                            f"{', '.join(history.columns)})")
        for name in y_names:
            y = signed_column(history, name, curve)
            curve_label = label if len(y_names) == 1 else f"{label}: {name}"
            axes.plot(x, y, marker=None if args.no_markers else "o", markersize=4,
                      label=curve_label)
            if name not in y_names_all:
                y_names_all.append(name)
    axes.set_xlabel(args.xlabel or (time_label if args.x == "time" else args.x))
    axes.set_ylabel(args.ylabel or ", ".join(
        time_label if name == "time" else name for name in y_names_all))
    if args.title:
        axes.set_title(args.title)
    axes.grid(True, alpha=0.3)
    axes.legend()
    frix_results.save_figure(figure, args.output)
    print(f"wrote {args.output}")
    return 0


if __name__ == "__main__":
    frix_results.run_main(main)
