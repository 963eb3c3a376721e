#!/usr/bin/python3
"""V6 Hertz (plane strain): contact pressure of a frix run against Hertz's solution.

usage: v6_hertz_check.py RUN_BASE --load P --radius R --young E --poisson NU
                         [--check KEY=LO:HI ...] [--csv FILE] [--plot PNG] [--listing-reference]

Reads <base>_contact.csv (last increment, pass 1: the cylinder's nodes), <base>.pvd and
<base>_listing.txt (reference coordinates of the slave nodes). The model is the half model of
inputs/v6_hertz: cylinder of radius R touching the block at x = 0, symmetry plane x = 0, one
element through y (both rows y = 0 and y = T are averaged). --listing-reference: the
reference x of a slave node is its current x (contact table) less its u_x of the listing's
last increment, no .pvd read (plane models of tests/plane: their VTK quads are not read by
postproc/frix_results).
Hertz (Johnson, Contact Mechanics, 1985, eqs. 4.43-4.45; two cylinders / cylinder on a
half-space, same E and nu on both sides):
    1/E* = 2 (1 - nu^2)/E,  a = sqrt(4 P R/(pi E*)),  p0 = 2 P/(pi a),
    p(x) = p0 sqrt(1 - x^2/a^2) for |x| <= a.
Quantities (printed; --check KEY=LO:HI fails when outside):
    p0_ratio    frix pressure at the node x = 0 / p0
    a_fit_ratio half width of the least-squares fit p^2 = p0f^2 (1 - x^2/af^2) over the nodes
                with p > 0 and x <= 0.8 af (iterated), / a
    p0_fit_ratio p0f / p0
    a_last_ratio, a_open_ratio   reference x of the last node in contact and of the first open
                node, / a (a lies between them when the mesh is right)
    force_ratio  integral of p dx by the trapezoidal rule over the nodes (to the first open
                 node) / (P/2): the half model carries P/2
    max_err      max |p(x_i) - p_Hertz(x_i)| / p0 over the nodes with x_i <= 0.9 a
    max_err_all  the same over every slave node (up to and beyond the contact edge)
    ripple       max |e_i - (e_(i-1) + e_(i+1))/2| / p0 over the nodes 0 < x_i <= 0.9 a, e the
                 error p - p_Hertz: how far a node's error stands off its neighbours' (a
                 node-to-node ripple of amplitude r gives 2 r; a smooth error next to nothing)
"""
import argparse
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/tests/", 1)[0] + "/tests")
from check_tally import check_ranges  # noqa: E402

sys.path.insert(0, __file__.rsplit("/tests/", 1)[0] + "/postproc")
import frix_results as fr  # noqa: E402


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("base")
    parser.add_argument("--load", type=float, required=True, help="P, load per unit length (full cylinder)")
    parser.add_argument("--radius", type=float, required=True)
    parser.add_argument("--young", type=float, required=True)
    parser.add_argument("--poisson", type=float, required=True)
    parser.add_argument("--check", action="append", default=[])
    parser.add_argument("--csv", default=None, help="write x, p, p_Hertz per node")
    parser.add_argument("--plot", default=None, help="PNG of p(x) against Hertz")
    parser.add_argument("--label", default=None)
    parser.add_argument("--listing-reference", action="store_true",
                        help="reference x from the contact table's x and the listing's u_x")
    args = parser.parse_args(argv)

    e_star = args.young / (2.0 * (1.0 - args.poisson ** 2))
    a = np.sqrt(4.0 * args.load * args.radius / (np.pi * e_star))
    p0 = 2.0 * args.load / (np.pi * a)

    data = np.genfromtxt(args.base + "_contact.csv", delimiter=",", names=True)
    data = data[(data["step"] == data["step"][-1]) & (data["increment"] == data["increment"][-1])
                & (data["pass"] == 1)]
    if args.listing_reference:
        _, labels, keys, values = fr.read_listing(args.base + "_listing.txt")[-1].blocks["NODAL DISPLACEMENTS"]
        u_x = dict(zip(keys, values[:, labels.index("UX")]))
        x_ref = np.array([x - u_x[int(n)] for x, n in zip(data["x"], data["node"])])
    else:
        series = fr.ResultSeries(args.base + ".pvd")
        mesh = series.mesh(series.select("last")[0])
        ids = fr.node_ids(series, mesh)
        index_of = {int(n): k for k, n in enumerate(ids)}
        x_ref = np.array([mesh.points[index_of[int(n)], 0] for n in data["node"]])
    # average the y = 0 and y = T rows (same reference x)
    keys = np.round(x_ref / (1e-9 * args.radius)).astype(np.int64)
    unique_keys, inverse = np.unique(keys, return_inverse=True)
    x = np.bincount(inverse, x_ref) / np.bincount(inverse)
    p = np.bincount(inverse, data["pressure"]) / np.bincount(inverse)
    order = np.argsort(x)
    x, p = x[order], p[order]

    values = {}
    if abs(x[0]) > 1e-9 * args.radius:
        raise fr.UserError(f"no slave node at x = 0 (first at {x[0]})")
    values["p0_ratio"] = p[0] / p0
    contact = p > 0
    last = np.max(np.nonzero(contact)[0])
    values["a_last_ratio"] = x[last] / a
    values["a_open_ratio"] = x[last + 1] / a if last + 1 < len(x) else np.nan
    a_fit = x[last]
    for _ in range(20):
        use = contact & (x <= 0.8 * a_fit)
        coeff = np.polyfit(x[use] ** 2, p[use] ** 2, 1)    # p^2 = c0 + c1 x^2
        a_fit_new = np.sqrt(-coeff[1] / coeff[0])
        if abs(a_fit_new - a_fit) < 1e-12 * a:
            break
        a_fit = a_fit_new
    values["a_fit_ratio"] = a_fit / a
    values["p0_fit_ratio"] = np.sqrt(coeff[1]) / p0
    end = min(last + 2, len(x))
    values["force_ratio"] = np.trapz(p[:end], x[:end]) / (0.5 * args.load)
    hertz = p0 * np.sqrt(np.clip(1.0 - (x / a) ** 2, 0.0, None))
    inner = x <= 0.9 * a
    values["max_err"] = np.max(np.abs(p[inner] - hertz[inner])) / p0
    values["max_err_all"] = np.max(np.abs(p - hertz)) / p0
    error = (p - hertz) / p0
    middle = [i for i in np.nonzero(inner)[0] if 0 < i < len(x) - 1]
    values["ripple"] = max(abs(error[i] - 0.5 * (error[i - 1] + error[i + 1])) for i in middle)
    values["nodes_in_contact"] = float(last + 1)

    label = args.label or args.base.rsplit("/", 1)[-1]
    print(f"{label}: Hertz a = {a:.6g}, p0 = {p0:.6g}")
    print(f"{label}: " + "  ".join(f"{k}={v:.5g}" for k, v in values.items()))
    if args.csv:
        np.savetxt(args.csv, np.column_stack([x, p, hertz]), delimiter=",", header="x,p,p_hertz",
                   comments="", fmt="%.17g")
    if args.plot:
        fr.use_agg_backend()
        import matplotlib.pyplot as plt
        figure, axes = plt.subplots(figsize=(6, 4))
        xs = np.linspace(0, a, 200)
        axes.plot(xs / a, np.sqrt(1 - (xs / a) ** 2), "k--", label="Hertz")
        axes.plot(x / a, p / p0, "o-", ms=3, label=f"frix ({label})")
        axes.set_xlim(0, 1.6)
        axes.set_xlabel("x / a")
        axes.set_ylabel("p / p0")
        axes.set_title(f"V6 Hertz: a = {a:.4g}, p0 = {p0:.4g}")
        axes.grid(alpha=0.3)
        axes.legend()
        fr.save_figure(figure, args.plot, dpi=100)
    return check_ranges(values, args.check)


if __name__ == "__main__":
    sys.exit(fr.run_main(main))
