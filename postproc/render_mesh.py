#!/usr/bin/python3
"""Render the deformed mesh of a frix result, coloured by a field, to a PNG (matplotlib 3D).

Only the boundary faces are drawn (the cell faces that belong to exactly one element: the
quadrilaterals of HEX8, the triangles of TET4 and TET10 by their corners), as a
Poly3DCollection. Node positions are the reference coordinates plus --scale times the point
field ``displacement`` (--scale 0: reference shape; --scale auto: the largest displacement
drawn as 10 % of the bounding-box diagonal). A point field colours each face with the mean of
its corner nodes; a cell field (--cell) with the value of its element.

Field names are those of the .vtu (docs/output.md): von_mises, displacement:2 (z), stress:xx
or stress:0 (VTK order XX YY ZZ XY YZ XZ), strain:..., reaction:..., or any extra field.
"""

import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import frix_results  # noqa: E402
from frix_results import UserError  # noqa: E402


def build_parser():
    parser = frix_results.ArgumentParser(
        description="Render the deformed boundary of a frix .pvd/.vtu result coloured by a "
                    "field (PNG, matplotlib 3D, with a colorbar).",
        epilog="Example: render_mesh.py run.pvd --field von_mises --scale auto --view 25,-60 "
               "-o vm.png")
    parser.add_argument("result", help="<base>.pvd collection or one .vtu file")
    parser.add_argument("--field", default="von_mises", metavar="NAME[:COMPONENT]",
                        help="field to colour by: von_mises (default), displacement:2, "
                             "stress:xx, ... (vectors without component: magnitude)")
    parser.add_argument("--cell", action="store_true",
                        help="use the cell (element mean) field instead of the point field")
    parser.add_argument("--increment", default="last", metavar="SPEC",
                        help="last (default), first, 1-based position in the .pvd (negative: "
                             "from the end) or STEP:INCREMENT")
    parser.add_argument("--block", default=None, metavar="N[,N...]",
                        help="only the elements of these blocks (cell field 'block', the order "
                             "of the deck's STRUCTURE ELEMENTS SET lines), e.g. a pipe inside soil")
    parser.add_argument("--scale", default="1", metavar="FACTOR|auto",
                        help="displacement magnification (default 1; 0 = reference shape; "
                             "auto = largest displacement shown as 10%% of the mesh diagonal)")
    parser.add_argument("--view", default="25,-60", metavar="ELEV,AZIM",
                        help="camera elevation and azimuth in degrees (default 25,-60)")
    parser.add_argument("--up", default="z", choices=("x", "y", "z"),
                        help="the model axis drawn vertical (default z; y for a model whose "
                             "gravity acts along -y)")
    parser.add_argument("--cmap", default="viridis", help="matplotlib colormap (default viridis)")
    parser.add_argument("--range", default=None, metavar="MIN,MAX",
                        help="colour range (default: the field's range)")
    parser.add_argument("--undeformed", action="store_true",
                        help="also draw the reference shape's boundary edges (grey)")
    parser.add_argument("--no-edges", action="store_true", help="do not draw element edges")
    parser.add_argument("--title", default=None, help="figure title (default: field, "
                        "increment and scale)")
    parser.add_argument("-o", "--output", default="mesh.png", metavar="PNG",
                        help="output image (default: mesh.png)")
    return parser


def magnification(text, points, displacement):
    if text.strip().lower() == "auto":
        largest = float(np.max(np.linalg.norm(displacement, axis=1))) if displacement.size else 0.0
        diagonal = float(np.linalg.norm(np.ptp(points, axis=0)))
        return 0.1 * diagonal / largest if largest > 0.0 else 1.0
    try:
        factor = float(text)
    except ValueError:
        raise UserError(f"--scale: '{text}' is neither a number nor 'auto'") from None
    if not np.isfinite(factor):
        raise UserError(f"--scale: '{text}' is not finite")
    return factor


# The model axes drawn as the plot's (horizontal, depth, vertical) for each --up: a cyclic
# permutation, so that the drawn frame stays right-handed.
DRAWN_AXES = {"z": (0, 1, 2), "y": (2, 0, 1), "x": (1, 2, 0)}


def main(argv=None):
    args = build_parser().parse_args(argv)
    elevation, azimuth = frix_results.parse_floats(args.view, 2, "--view")
    color_range = frix_results.parse_floats(args.range, 2, "--range") if args.range else None
    series = frix_results.ResultSeries(args.result)
    entries = series.select(args.increment)
    if len(entries) != 1:
        raise UserError("--increment must select exactly one increment")
    entry = entries[0]
    mesh = series.mesh(entry)
    points = np.asarray(mesh.points, dtype=float)
    all_cells = frix_results.mesh_cells(mesh)
    displacement = np.asarray(mesh.point_data["displacement"], dtype=float) \
        if "displacement" in mesh.point_data else np.zeros_like(points)
    factor = magnification(args.scale, points, displacement)
    drawn = list(DRAWN_AXES[args.up])
    points, displacement = points[:, drawn], displacement[:, drawn]
    deformed = points + factor * displacement

    cells = np.arange(len(all_cells))
    if args.block:
        try:
            wanted = [int(item) for item in args.block.split(",") if item.strip()]
        except ValueError:
            raise UserError(f"--block: '{args.block}' is not a comma list of integers") from None
        block_array = frix_results.cell_array(mesh, "block")
        if block_array is None:
            raise UserError("--block: the result has no cell field 'block'")
        cells = np.flatnonzero(np.isin(np.asarray(block_array).astype(int).ravel(), wanted))
        if cells.size == 0:
            raise UserError(f"--block: no element in block(s) {args.block}")
    faces, owners = frix_results.boundary_faces([all_cells[cell] for cell in cells])
    if args.cell:
        values = frix_results.field_values(mesh, args.field, "cell")[cells][owners]
    else:
        nodal = frix_results.field_values(mesh, args.field, "point")
        values = np.array([nodal[face].mean() for face in faces])
    low, high = color_range if color_range else (float(values.min()), float(values.max()))
    if high <= low:                      # a constant field: widen so the colormap works
        spread = max(abs(low), 1.0) * 1e-12
        low, high = low - spread, high + spread

    pyplot = frix_results.use_agg_backend()
    from matplotlib import cm, colors
    from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection
    try:
        colormap = pyplot.get_cmap(args.cmap)
    except ValueError:
        raise UserError(f"--cmap: unknown colormap '{args.cmap}'") from None
    normalize = colors.Normalize(vmin=low, vmax=high)
    figure = pyplot.figure(figsize=(8, 6))
    axes = figure.add_subplot(projection="3d")
    collection = Poly3DCollection([deformed[face] for face in faces], facecolors=colormap(normalize(values)),
                                  edgecolors="none" if args.no_edges else "k",
                                  linewidths=0.0 if args.no_edges else 0.3)
    axes.add_collection3d(collection)
    used = np.unique(np.concatenate(faces))
    shown = deformed[used]
    if args.undeformed:
        edges = [points[np.append(face, face[0])] for face in faces]
        axes.add_collection3d(Line3DCollection(edges, colors="0.6", linewidths=0.4))
        shown = np.vstack([deformed[used], points[used]])
    lower, upper = shown.min(axis=0), shown.max(axis=0)
    extent = np.maximum(upper - lower, 1e-9 * max(float(np.max(upper - lower)), 1.0))
    axes.set_xlim(lower[0], lower[0] + extent[0])
    axes.set_ylim(lower[1], lower[1] + extent[1])
    axes.set_zlim(lower[2], lower[2] + extent[2])
    axes.set_box_aspect(tuple(extent))
    axis_names = "xyz"
    axes.set_xlabel(axis_names[drawn[0]])
    axes.set_ylabel(axis_names[drawn[1]])
    axes.set_zlabel(axis_names[drawn[2]])
    axes.view_init(elev=elevation, azim=azimuth)
    mappable = cm.ScalarMappable(norm=normalize, cmap=colormap)
    mappable.set_array(values)
    figure.colorbar(mappable, ax=axes, shrink=0.7, pad=0.12,
                    label=f"{args.field} ({'cell' if args.cell else 'point'})")
    axes.set_title(args.title or f"{args.field}, {entry.label()}, displacement x {factor:.4g}")
    frix_results.save_figure(figure, args.output)
    print(f"wrote {args.output} ({len(faces)} boundary faces, scale {factor:.6g})")
    print(f"vertical axis {axis_names[drawn[2]]}, drawn height {extent[2]:.6g}")
    return 0


if __name__ == "__main__":
    frix_results.run_main(main)
