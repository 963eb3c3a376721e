#!/usr/bin/python3
"""Hird & Russell's 1D solution of benchmark S1 (elastic block L >> H on a rigid base with a
Coulomb interface), and its comparison with a frix run.

Theory (docs/benchmarks.md S1; Hird & Russell, as quoted by the seed, 6.1.1). A block
of length L and height H, constrained modulus M = E(1-nu)/((1+nu)(1-2nu)), rests on a rigid
base through an interface of shear stiffness k_s (stress per length) and shear strength
tau_max = mu q. The face x = 0 is held, the face x = L carries the pressure p. The axial stress
is taken uniform over H, so the axial displacement w(x) >= 0 (towards x = 0, i.e. frix's
u_x = -w) obeys M H w'' = tau(x) with tau = k_s w (stick) or tau_max (slip):

    a^2 = k_s/(M H),  w1 = tau_max/k_s (elastic slip at which the interface yields),
    p1  = (k_s w1/(a H)) coth(a L)          the load at which slip starts at x = L;
    p <= p1 (stick everywhere):  w = C sinh(a x),  C = p/(M a cosh(a L));
    p >  p1: slip on x1 <= x <= L, x1 from p = (k_s w1/(a H)) [coth(a x1) + a (L - x1)],
             w = w1 sinh(a x)/sinh(a x1)                       for x <= x1,
             w = w1 + (s1 d + tau_max d^2/(2 H))/M, d = x - x1  for x >= x1,
             s1 = (k_s w1/(a H)) coth(a x1) (axial stress at the slip front).

Units: any consistent set (S1: kN, m, kPa; k_s in kPa/m).

As a module::

    import s1_analytical as s1
    theory = s1.Theory()                 # S1's data: E 1e5, nu 0, L 10, H 1, k_s 1e4, tau 30
    theory.displacement(300.0, x)        # w(x) at p = 300
    theory.slip_front(300.0)             # x1 (L when p <= p1)

Command line::

    s1_analytical.py curves --loads 50,100,150,200,250,300 -o s1_theory.csv
        # position, w at each load: for plot_line.py --analytic-csv (with --scale -1: frix's
        # u_x is -w), or --sign -1 to write u_x directly
    s1_analytical.py table                 # p, stick/slip, x1, w(L) per load level
    s1_analytical.py compare run.pvd [--gain] [--json F] [--csv F] [--plot PNG]
        # interface u_x of a frix run against w(x) at every load level of step 2: free-end
        # error, slipping nodes, slip front, interface tractions
"""

import csv
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import frix_results  # noqa: E402
from frix_results import UserError  # noqa: E402

DEFAULT_LOADS = (50.0, 100.0, 150.0, 200.0, 250.0, 300.0)


class Theory:
    """Hird & Russell's 1D solution for one set of data (defaults: benchmark S1)."""

    def __init__(self, young=1.0e5, poisson=0.0, length=10.0, height=1.0, shear_stiffness=1.0e4,
                 shear_strength=30.0):
        if young <= 0 or not -1.0 < poisson < 0.5 or length <= 0 or height <= 0 \
                or shear_stiffness <= 0 or shear_strength <= 0:
            raise UserError("need E > 0, -1 < nu < 0.5, L > 0, H > 0, k_s > 0, tau_max > 0")
        self.young, self.poisson = young, poisson
        self.length, self.height = length, height
        self.shear_stiffness, self.shear_strength = shear_stiffness, shear_strength
        #: constrained (oedometric) modulus M = E(1-nu)/((1+nu)(1-2nu))
        self.modulus = young * (1 - poisson) / ((1 + poisson) * (1 - 2 * poisson))
        #: a = sqrt(k_s/(M H)), 1/length
        self.a = np.sqrt(shear_stiffness / (self.modulus * height))
        #: w1 = tau_max/k_s, the relative displacement at which the interface yields
        self.w1 = shear_strength / shear_stiffness
        #: p1 = (k_s w1/(a H)) coth(a L), the end load at which slip starts
        self.p1 = self._front_load(length)

    def _front_load(self, x1):
        """p(x1) = (k_s w1/(a H)) [coth(a x1) + a (L - x1)]: the end load for slip front x1."""
        a, height = self.a, self.height
        return self.shear_stiffness * self.w1 / (a * height) * (
            1.0 / np.tanh(a * x1) + a * (self.length - x1))

    def slip_front(self, load):
        """x1 for the end load p: L while p <= p1 (no slip), else the root of p(x1) = p on
        (0, L) (p(x1) decreases monotonically from +inf at 0+ to p1 at L: bisection)."""
        if load <= self.p1:
            return self.length
        low, high = 0.0, self.length          # p(low) > load > p(high)
        low = 1e-12 * self.length
        for _ in range(200):
            middle = 0.5 * (low + high)
            if self._front_load(middle) > load:
                low = middle
            else:
                high = middle
            if high - low <= 1e-15 * self.length:
                break
        return 0.5 * (low + high)

    def displacement(self, load, x):
        """w(x) >= 0 (displacement towards x = 0) at end load p; x array-like in [0, L]."""
        x = np.asarray(x, dtype=float)
        a, modulus = self.a, self.modulus
        if load <= self.p1:
            return load / (modulus * a * np.cosh(a * self.length)) * np.sinh(a * x)
        x1 = self.slip_front(load)
        s1 = self.shear_stiffness * self.w1 / (a * self.height) / np.tanh(a * x1)
        d = np.maximum(x - x1, 0.0)
        stick = self.w1 * np.sinh(a * np.minimum(x, x1)) / np.sinh(a * x1)
        slip = self.w1 + (s1 * d + self.shear_strength * d ** 2 / (2 * self.height)) / modulus
        return np.where(x <= x1, stick, slip)

    def axial_stress(self, load, x):
        """Axial compressive stress s(x) = M w'(x) (uniform over H)."""
        x = np.asarray(x, dtype=float)
        a, modulus = self.a, self.modulus
        if load <= self.p1:
            return load * np.cosh(a * x) / np.cosh(a * self.length)
        x1 = self.slip_front(load)
        s1 = self.shear_stiffness * self.w1 / (a * self.height) / np.tanh(a * x1)
        stick = modulus * self.w1 * a * np.cosh(a * np.minimum(x, x1)) / np.sinh(a * x1)
        slip = s1 + self.shear_strength * np.maximum(x - x1, 0.0) / self.height
        return np.where(x <= x1, stick, slip)


def parse_loads(text):
    try:
        loads = [float(item) for item in text.split(",") if item.strip()]
    except ValueError:
        raise UserError(f"--loads: not a comma list of numbers: '{text}'") from None
    if not loads or any(load < 0 for load in loads):
        raise UserError("--loads: need at least one load >= 0")
    return loads


def add_theory_options(parser):
    group = parser.add_argument_group("data (defaults: benchmark S1)")
    group.add_argument("--young", type=float, default=1.0e5, help="E (default 1e5)")
    group.add_argument("--poisson", type=float, default=0.0, help="nu (default 0)")
    group.add_argument("--length", type=float, default=10.0, help="L (default 10)")
    group.add_argument("--height", type=float, default=1.0, help="H (default 1)")
    group.add_argument("--shear-stiffness", type=float, default=1.0e4,
                       help="interface shear stiffness k_s = eps_T (default 1e4)")
    group.add_argument("--shear-strength", type=float, default=30.0,
                       help="tau_max = mu q (default 0.1 x 300 = 30)")


def theory_from(args):
    return Theory(args.young, args.poisson, args.length, args.height, args.shear_stiffness,
                  args.shear_strength)


def write_rows(path, header, rows):
    try:
        stream = open(path, "w", newline="", encoding="utf-8") if path != "-" else sys.stdout
        writer = csv.writer(stream)
        writer.writerow(header)
        for row in rows:
            writer.writerow([repr(float(item)) if isinstance(item, (float, np.floating)) else item
                             for item in row])
        if stream is not sys.stdout:
            stream.close()
    except OSError as error:
        raise UserError(f"cannot write {path}: {error}") from None


# ----------------------------------------------------------------------------- frix results

def block_cells(points, cells, interface_z, tolerance):
    """The elements above z = interface_z: the sliding block (a deformable base lies below)."""
    return cells[points[cells, 2].mean(axis=1) > interface_z + tolerance]


def interface_nodes(points, cells, interface_z, tolerance):
    """Indices of the points on z = interface_z that belong to an element lying above it
    (the sliding block; with a deformable base its top nodes share the coordinates)."""
    candidates = np.unique(block_cells(points, cells, interface_z, tolerance).ravel())
    return candidates[np.abs(points[candidates, 2] - interface_z) <= tolerance]


def interface_areas(points, cells, nodes, interface_z, tolerance):
    """Tributary area of each interface node: a quarter of each bottom face of the block at
    the node (exact for the parallelogram faces of a structured block)."""
    position = {int(node): k for k, node in enumerate(nodes)}
    area = np.zeros(nodes.size)
    for cell in block_cells(points, cells, interface_z, tolerance):
        bottom = [node for node in cell if abs(points[node, 2] - interface_z) <= tolerance]
        if len(bottom) != 4:
            continue
        corners = points[bottom]
        centre = corners.mean(axis=0)
        angle = np.arctan2(corners[:, 1] - centre[1], corners[:, 0] - centre[0])
        ring = corners[np.argsort(angle)]
        face_area = 0.5 * abs(np.sum(ring[:, 0] * np.roll(ring[:, 1], -1)
                                     - np.roll(ring[:, 0], -1) * ring[:, 1]))
        for node in bottom:
            area[position[int(node)]] += face_area / 4.0
    return area


def compare_run(path, theory, load_max=300.0, gain=False, interface_z=0.0, mu=0.1):
    """Per load level of step 2: the interface nodes' u_x against -w(x) and contact data.

    Returns a dict: 'levels' (list of dicts, one per step-2 increment) and 'nodes' (rows for a
    CSV). p = load_max (t - 1) during step 2 (the S1 deck's curve 2). With gain=True the
    displacements are those gained in step 2 (minus the last increment of step 1).
    """
    series = frix_results.ResultSeries(path)
    entries = series.entries
    first = series.mesh(entries[0])
    points = np.asarray(first.points, dtype=float)
    cells = frix_results.hexahedra(first)
    extent = np.ptp(points, axis=0)
    tolerance = 1e-6 * float(np.linalg.norm(extent))
    nodes = interface_nodes(points, cells, interface_z, tolerance)
    if nodes.size == 0:
        raise UserError(f"{path}: no node on z = {interface_z} below an element")
    area = interface_areas(points, cells, nodes, interface_z, tolerance)
    block_nodes = np.unique(block_cells(points, cells, interface_z, tolerance).ravel())
    support = block_nodes[np.abs(points[block_nodes, 0] - points[block_nodes, 0].min())
                          <= tolerance]
    x = points[nodes, 0]
    positions = np.unique(np.round(x / tolerance) * tolerance)
    group = np.searchsorted(positions, np.round(x / tolerance) * tolerance)

    def by_position(values):
        return np.bincount(group, weights=values) / np.bincount(group)

    step1 = [entry for entry in entries if entry.step == 1]
    reference = np.zeros(nodes.size)
    if gain:
        if not step1:
            raise UserError(f"{path}: --gain needs step 1 in the results")
        reference = frix_results.field_values(series.mesh(step1[-1]), "displacement:x")[nodes]
    result = {"file": path, "gain": gain, "theory": {
        "M": theory.modulus, "a": float(theory.a), "w1": theory.w1, "p1": float(theory.p1)},
        "levels": [], "nodes": []}
    for entry in [entry for entry in entries if entry.step == 2]:
        mesh = series.mesh(entry)
        load = load_max * (entry.time - 1.0)
        ux = frix_results.field_values(mesh, "displacement:x")[nodes] - reference
        w_fem = by_position(-ux)
        w_theory = theory.displacement(load, positions)
        status = np.asarray(mesh.point_data["contact_status"]).ravel()[nodes]
        pressure = np.asarray(mesh.point_data["contact_pressure"]).ravel()[nodes]
        traction = np.asarray(mesh.point_data["contact_traction"])[nodes]
        shear = np.linalg.norm(traction, axis=1)
        slipping = status == 2
        sticking = status == 1
        first_slip = float(x[slipping].min()) if slipping.any() else None
        last_stick = float(x[sticking].max()) if sticking.any() else None
        if first_slip is None:
            front = float(theory.length)
        elif last_stick is None:
            front = float(positions[0])
        else:
            front = 0.5 * (first_slip + last_stick)
        free_end = int(np.argmax(positions))
        x1_theory = float(theory.slip_front(load))
        # slip-zone interior: one H beyond the theory's front and 1.5 H from the loaded end,
        # where the couples of the end load and of the shear jump at the front have decayed
        interior = slipping & (x >= x1_theory + theory.height) \
            & (x <= theory.length - 1.5 * theory.height)
        reaction = frix_results.field_values(mesh, "reaction:x")[support]
        # stick nodes: t_x = eps_T (anchor - position) with the anchor committed at the end of
        # step 1 (where u_x = 0 in variants a, b, d): t_x = -eps_T u_x
        ux_total = frix_results.field_values(mesh, "displacement:x")[nodes]
        level = {
            "step": entry.step, "increment": entry.increment, "time": entry.time, "p": load,
            "w_end_frix": float(w_fem[free_end]), "w_end_theory": float(w_theory[free_end]),
            "error_end": float(w_fem[free_end] / w_theory[free_end] - 1.0)
            if w_theory[free_end] != 0 else None,
            "max_error_over_w_end": float(np.max(np.abs(w_fem - w_theory)) / w_theory[free_end])
            if w_theory[free_end] != 0 else None,
            "slipping_nodes": int(slipping.sum()), "sticking_nodes": int(sticking.sum()),
            "open_nodes": int((status == 0).sum()), "interface_nodes": int(nodes.size),
            "slip_positions": int(np.unique(group[slipping]).size),
            "first_slip_x": first_slip, "last_stick_x": last_stick, "front_frix": front,
            "front_theory": x1_theory,
            "normal_force": float(np.sum(pressure * area)),
            "shear_force_x": float(np.sum(traction[:, 0] * area)),
            "support_reaction_x": float(np.sum(reaction)),
            "interface_area": float(np.sum(area)),
            "interior_slip_nodes": int(interior.sum()),
            "interior_pressure_max_dev": float(np.max(np.abs(pressure[interior] / theory.shear_strength
                                                              * mu - 1.0))) if interior.any() else None,
            "interior_shear_mean": float(np.mean(shear[interior])) if interior.any() else None,
            "stick_traction_vs_ks_max_dev": float(np.max(np.abs(
                traction[sticking, 0] + theory.shear_stiffness * ux_total[sticking]))
                / theory.shear_strength) if sticking.any() else None,
            "pressure_min": float(pressure.min()), "pressure_max": float(pressure.max()),
            "pressure_mean": float(pressure.mean()),
            "slip_shear_over_mu_pressure_max_dev": float(np.max(np.abs(
                shear[slipping] / (mu * pressure[slipping]) - 1.0))) if slipping.any() else None,
            "slip_shear_min": float(shear[slipping].min()) if slipping.any() else None,
            "slip_shear_max": float(shear[slipping].max()) if slipping.any() else None,
            "stick_shear_over_mu_pressure_max": float(np.max(
                shear[sticking] / (mu * pressure[sticking]))) if sticking.any() else None,
        }
        result["levels"].append(level)
        for k, node in enumerate(nodes):
            result["nodes"].append([entry.step, entry.increment, load, int(node) + 1,
                                    float(points[node, 0]), float(points[node, 1]), float(-ux[k]),
                                    float(theory.displacement(load, points[node, 0])),
                                    int(status[k]), float(pressure[k]), float(traction[k, 0])])
    if not result["levels"]:
        raise UserError(f"{path}: no increment of step 2")
    result["positions"] = positions.tolist()
    return result


def plot_comparison(result, theory, path, title=None):
    pyplot = frix_results.use_agg_backend()
    figure, axes = pyplot.subplots(figsize=(7, 5))
    colors = pyplot.rcParams["axes.prop_cycle"].by_key()["color"]
    rows = np.array([row[:8] for row in result["nodes"]], dtype=float)
    fine = np.linspace(0.0, theory.length, 401)
    for number, level in enumerate(result["levels"]):
        color = colors[number % len(colors)]
        mine = rows[rows[:, 2] == level["p"]]
        order = np.argsort(mine[:, 4])
        x, w = mine[order, 4], mine[order, 6]
        positions = np.unique(x)
        w_mean = np.array([w[x == value].mean() for value in positions])
        axes.plot(positions, 1e3 * w_mean, "o", color=color, markersize=3.5,
                  label=f"frix p = {level['p']:g}")
        axes.plot(fine, 1e3 * theory.displacement(level["p"], fine), "-", color=color,
                  linewidth=1)
        x1 = theory.slip_front(level["p"])
        if x1 < theory.length:
            axes.plot([x1], [1e3 * theory.w1], "k|", markersize=10)
    axes.plot([], [], "k-", linewidth=1, label="Hird & Russell w(x)")
    axes.plot([], [], "k|", markersize=10, label="theory slip front x1")
    axes.set_xlabel("x (m)")
    axes.set_ylabel(("gained " if result["gain"] else "") + "interface -u_x = w (mm)")
    axes.set_title(title or "S1: interface displacement at every load level")
    axes.grid(True, alpha=0.3)
    axes.legend(fontsize="small")
    frix_results.save_figure(figure, path, dpi=100)


def format_table(result):
    lines = ["   p   w(L) frix   w(L) theory  error %  max|dw|/w(L) %  slip nodes (positions)"
             "   x1 frix  x1 theory  p_N min..max      |t|/(mu p_N)-1 (slip)"]
    for level in result["levels"]:
        error = 100 * level["error_end"] if level["error_end"] is not None else float("nan")
        deviation = level["slip_shear_over_mu_pressure_max_dev"]
        lines.append(
            f"{level['p']:5.0f} {level['w_end_frix']:.5e} {level['w_end_theory']:.5e} "
            f"{error:8.2f} {100 * level['max_error_over_w_end']:10.2f}      "
            f"{level['slipping_nodes']:4d} ({level['slip_positions']:2d})            "
            f"{level['front_frix']:7.3f} {level['front_theory']:8.3f}  "
            f"{level['pressure_min']:7.2f}..{level['pressure_max']:7.2f}  "
            + (f"{deviation:.1e}" if deviation is not None else "-"))
    return "\n".join(lines)


# ----------------------------------------------------------------------------- command line

def build_parser():
    parser = frix_results.ArgumentParser(
        description="Hird & Russell's analytical solution of benchmark S1 (block on a "
                    "frictional base): curves, table, and comparison with a frix run.")
    commands = parser.add_subparsers(dest="command", required=True)
    curves = commands.add_parser("curves", help="CSV of w(x) per load level (position, w...)")
    curves.add_argument("--loads", default="50,100,150,200,250,300",
                        help="comma list of end loads p (default 50..300 by 50)")
    curves.add_argument("--points", type=int, default=201, help="positions (default 201)")
    curves.add_argument("--sign", type=float, choices=(1.0, -1.0), default=1.0,
                        help="+1: w (default; frix's u_x = -w), -1: u_x")
    curves.add_argument("-o", "--output", default="-", help="CSV file (default: stdout)")
    table = commands.add_parser("table", help="p1, and per load: x1, w(L)")
    table.add_argument("--loads", default="50,100,150,200,250,300")
    compare = commands.add_parser("compare", help="a frix run (.pvd) against the theory")
    compare.add_argument("result", help="<base>.pvd of an S1 run")
    compare.add_argument("--gain", action="store_true",
                         help="use the displacement gained in step 2 (variant c)")
    compare.add_argument("--load-max", type=float, default=300.0,
                         help="p at the end of step 2 (p = LOAD_MAX (t - 1)); default 300")
    compare.add_argument("--interface-z", type=float, default=0.0, help="default 0")
    compare.add_argument("--mu", type=float, default=0.1, help="friction coefficient (0.1)")
    compare.add_argument("--json", default=None, help="write the per-level results (JSON)")
    compare.add_argument("--csv", default=None,
                         help="per node and level: step,increment,p,point,x,y,w_frix,w_theory,"
                              "status,pressure,traction_x")
    compare.add_argument("--plot", default=None, metavar="PNG", help="interface w(x) plot")
    compare.add_argument("--title", default=None)
    for sub in (curves, table, compare):
        add_theory_options(sub)
    return parser


def main(argv=None):
    args = build_parser().parse_args(argv)
    theory = theory_from(args)
    if args.command == "curves":
        loads = parse_loads(args.loads)
        if args.points < 2:
            raise UserError("--points must be >= 2")
        x = np.linspace(0.0, theory.length, args.points)
        columns = [args.sign * theory.displacement(load, x) for load in loads]
        name = "w" if args.sign > 0 else "u_x"
        write_rows(args.output, ["x"] + [f"{name} p={load:g}" for load in loads],
                   zip(x, *columns))
    elif args.command == "table":
        print(f"M = {theory.modulus:g}, a = {theory.a:.6g}, w1 = {theory.w1:g}, "
              f"p1 = {theory.p1:.6g}")
        print("     p  regime      x1        w(L)")
        for load in parse_loads(args.loads):
            print(f"{load:6g}  {'stick' if load <= theory.p1 else 'slip ':5s} "
                  f"{theory.slip_front(load):9.5f}  {float(theory.displacement(load, theory.length)):.6e}")
    else:
        result = compare_run(args.result, theory, args.load_max, args.gain, args.interface_z,
                             args.mu)
        print(f"{args.result}: p1 = {theory.p1:.4g}" + (" (displacements gained in step 2)"
                                                          if args.gain else ""))
        print(format_table(result))
        if args.json:
            try:
                with open(args.json, "w", encoding="utf-8") as stream:
                    json.dump({key: value for key, value in result.items() if key != "nodes"},
                              stream, indent=1)
            except OSError as error:
                raise UserError(f"cannot write {args.json}: {error}") from None
        if args.csv:
            write_rows(args.csv, ["step", "increment", "p", "point", "x", "y", "w_frix",
                                  "w_theory", "status", "pressure", "traction_x"],
                       result["nodes"])
        if args.plot:
            plot_comparison(result, theory, args.plot, args.title)
            print(f"wrote {args.plot}")
    return 0


if __name__ == "__main__":
    frix_results.run_main(main)
