#!/usr/bin/python3
"""Mohr-Coulomb check of the principal stresses of a frix result.

For every element (cell stresses, the mean over its integration points; or every node with
--point) the principal stresses are the eigenvalues of the symmetric 3 x 3 Cauchy stress
(numpy eigvalsh), ordered s1 >= s2 >= s3.

Sign convention. frix writes stresses **tension positive** (docs/output.md); soil mechanics
states Mohr-Coulomb with compression positive, sigma_1 >= sigma_3 the major and minor
compressive stresses:
    F = (sigma_1 - sigma_3)/2 - (sigma_1 + sigma_3)/2 sin(phi) - c cos(phi).
With sigma_1 = -s3 and sigma_3 = -s1 this is, in frix's convention (s1 the most tensile),
    f = (s1 - s3)/2 + (s1 + s3)/2 sin(phi) - c cos(phi)          [stress units]
(the radius of the Mohr circle minus its distance to the failure envelope measured along the
normal; 2 f = (s1 - s3) + (s1 + s3) sin(phi) - 2 c cos(phi)). f < 0: inside the envelope;
f >= 0: at or beyond failure. A state counts as failed when
f >= -rel_tol (|s1| + |s3| + c), so that states exactly on the envelope count despite round-off.
phi = 0 gives Tresca with shear strength c. Pure tension beyond c cot(phi) (the apex) fails.
Stresses given compression positive (--compression-positive) are negated first.

Input: a .pvd (the chosen increment, default the last) or a .vtu with the cell field
``stress`` (VTK order XX YY ZZ XY YZ XZ): element means, or with --point the recovered nodal
stresses; or a frix HDF5 results file (.h5, docs/hdf5-layout.md): the stresses at every
integration point (Voigt order xx yy zz xy xz yz there), an element counting as failed when
one of its points is. Output: a summary on stdout, optionally a table (--table out.csv) with
one row per element (node, integration point): element_id, block[, point], s1, s2, s3, f,
failed; optionally a .vtu (--vtk out.vtu) with the checked elements (cells s1, s2, s3, f,
failed, element_id, block; with HDF5 input the values of each element's point of largest f,
and failed_points) or, with --point, the mesh with these fields at the nodes, and the
displacement as point data, for ParaView (Threshold on `failed`, Warp By Vector).
"""

import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import frix_results  # noqa: E402
from frix_results import UserError  # noqa: E402


def mohr_coulomb(principal, cohesion, friction_angle_degrees):
    """Yield function f (tension positive, s1 >= s2 >= s3 in ``principal`` (n, 3)), see the
    module documentation; same unit as the stresses and ``cohesion``."""
    phi = math.radians(friction_angle_degrees)
    s1, s3 = principal[:, 0], principal[:, 2]
    return 0.5 * (s1 - s3) + 0.5 * (s1 + s3) * math.sin(phi) - cohesion * math.cos(phi)


def build_parser():
    parser = frix_results.ArgumentParser(
        description="Principal stresses and the Mohr-Coulomb yield function f per element of a "
                    "frix .pvd/.vtu; counts the elements at or beyond failure (f >= 0). frix "
                    "stresses are tension positive; f = (s1-s3)/2 + (s1+s3)/2 sin(phi) - c "
                    "cos(phi) with s1 >= s2 >= s3.",
        epilog="Example (the seed's check): mohr_coulomb.py soil.pvd --c 0.020 --phi 30 "
               "--block 1 --table mc.csv")
    parser.add_argument("result", help="<base>.pvd collection, one .vtu file, or a frix HDF5 "
                        "results file (.h5: integration-point stresses)")
    parser.add_argument("--c", type=float, required=True, metavar="COHESION",
                        help="cohesion c (stress units of the deck, e.g. MPa), >= 0")
    parser.add_argument("--phi", type=float, required=True, metavar="DEGREES",
                        help="friction angle phi in degrees, 0 <= phi < 90")
    parser.add_argument("--increment", default="last", metavar="SPEC",
                        help="last (default), first, 1-based position in the .pvd or .h5 "
                             "(negative: from the end) or STEP:INCREMENT")
    parser.add_argument("--block", default=None, metavar="N[,N...]",
                        help="only elements of these blocks (cell field 'block'), e.g. the soil")
    parser.add_argument("--element-set", default=None, metavar="NAME",
                        help="only the elements of this element set (HDF5 input: "
                             "/mesh/element_sets/NAME)")
    parser.add_argument("--point", action="store_true",
                        help="use the nodal (recovered) stresses instead of the element means")
    parser.add_argument("--stress-field", default="stress", metavar="NAME",
                        help="6-component stress field, VTK order (default: stress)")
    parser.add_argument("--compression-positive", action="store_true",
                        help="the stress field is compression positive (negate it first)")
    parser.add_argument("--rel-tol", type=float, default=1e-12, metavar="R",
                        help="count f >= -R (|s1| + |s3| + c) as failure (default 1e-12)")
    parser.add_argument("--table", default=None, metavar="CSV",
                        help="write one row per element/node: id, block, s1, s2, s3, f, failed")
    parser.add_argument("--vtk", default=None, metavar="VTU",
                        help="write the checked elements (or with --point the nodes) with the "
                             "fields s1, s2, s3, f, failed as a .vtu for ParaView")
    parser.add_argument("--exit-code", action="store_true",
                        help="exit 1 when at least one element is at or beyond failure")
    return parser


class Geometry:
    """The mesh of the checked result, for --vtk and --element-set: reference ``points``
    (n, 3), ``cells`` (a list of (frix_results.CellType, 0-based nodes) per element),
    ``displacement`` (n, 3) or None, and
    ``element`` (0-based cell of each stress row; None for nodal rows)."""

    def __init__(self, points, cells, displacement, element):
        self.points = points
        self.cells = cells
        self.displacement = displacement
        self.element = element


def h5_geometry(args, gauss, n_points):
    """Geometry (and the element set's 0-based elements, or None) of the HDF5 increment of
    ``gauss``, read only when --vtk or --element-set asks for it."""
    with frix_results.H5Results(args.result) as results:
        entry = results.select(f"{gauss.step}:{gauss.increment}")
        members = None if args.element_set is None else results.element_set(args.element_set)
        if args.vtk is None:
            return None, members
        points = np.asarray(results.mesh_array("coordinates"), dtype=float)
        cells = results.cells()
        displacement = np.asarray(results.dataset(entry, "displacement"), dtype=float)
    element = np.repeat(np.arange(len(gauss.element_ids)), n_points)
    return Geometry(points, cells, displacement, element), members


def load_stresses(args):
    """(stress rows (n, 6) VTK order, ids, blocks, integration point numbers or None, kind,
    description, Geometry or None, rows of the element set or None) from the .pvd/.vtu
    (element means or nodes) or the HDF5 file (points)."""
    extension = os.path.splitext(args.result)[1].lower()
    if extension in (".h5", ".hdf5"):
        if args.point:
            raise UserError("--point works with .pvd/.vtu results, not with HDF5")
        gauss = frix_results.read_h5_stresses(args.result, args.increment)
        n_elements, n_points, _ = gauss.stress.shape
        geometry, members = None, None
        if args.vtk is not None or args.element_set is not None:
            geometry, members = h5_geometry(args, gauss, n_points)
        in_set = None if members is None else np.repeat(np.isin(np.arange(n_elements), members),
                                                        n_points)
        return (gauss.stress.reshape(-1, 6), np.repeat(gauss.element_ids, n_points),
                np.repeat(gauss.blocks, n_points), np.tile(np.arange(1, n_points + 1), n_elements),
                "elements", f"{args.result} ({gauss.label()}, integration points)", geometry,
                in_set)
    if args.element_set is not None:
        raise UserError("--element-set needs an HDF5 results file (a .pvd/.vtu has no element "
                        "sets); use --block")
    series = frix_results.ResultSeries(args.result)
    entries = series.select(args.increment)
    if len(entries) != 1:
        raise UserError("--increment must select exactly one increment")
    entry = entries[0]
    mesh = series.mesh(entry)
    location = "point" if args.point else "cell"
    if not frix_results.has_field(mesh, args.stress_field, location):
        raise UserError(f"{entry.path}: no {location} field '{args.stress_field}'")
    description = f"{entry.path} ({entry.label()}, {'nodes' if args.point else 'element means'})"
    displacement = (np.asarray(mesh.point_data["displacement"], dtype=float)
                    if "displacement" in mesh.point_data else None)
    cells = frix_results.mesh_cells(mesh)
    if args.point:
        stress = np.asarray(mesh.point_data[args.stress_field], dtype=float)
        ids = frix_results.node_ids(series, mesh)
        ids = np.arange(1, len(stress) + 1) if ids is None else ids
        geometry = Geometry(np.asarray(mesh.points, dtype=float), cells, displacement, None)
        return stress, ids, np.full(len(stress), -1), None, "nodes", description, geometry, None
    stress = frix_results.cell_array(mesh, args.stress_field).astype(float)
    element_ids = frix_results.cell_array(mesh, "element_id")
    ids = np.arange(1, len(stress) + 1) if element_ids is None else element_ids.astype(int).ravel()
    block_array = frix_results.cell_array(mesh, "block")
    blocks = np.full(len(stress), -1) if block_array is None else block_array.astype(int).ravel()
    geometry = Geometry(np.asarray(mesh.points, dtype=float), cells, displacement,
                        np.arange(len(stress)))
    return stress, ids, blocks, None, "elements", description, geometry, None


def write_vtk(path, geometry, rows, ids, blocks, principal, f, failed, points, what):
    """The checked elements as cells of their types (or with nodal rows the whole mesh with
    point fields) with s1, s2, s3, f, failed, the ids and the displacement (point data)."""
    import meshio
    fields = {"s1": principal[:, 0], "s2": principal[:, 1], "s3": principal[:, 2], "f": f}
    if what == "nodes":
        # nodal rows: every node, in the mesh's order (--block is refused with --point)
        point_data = dict(fields)
        point_data["failed"] = failed.astype(np.int32)
        point_data["node_id"] = ids.astype(np.int32)
        used = np.arange(len(geometry.points))
        cell_blocks, cell_data = frix_results.meshio_cell_blocks(geometry.cells)
    else:
        element = geometry.element[rows]
        kept = np.unique(element)
        # the row of largest f of each element (its worst integration point)
        order = np.lexsort((-f, element))
        first = order[np.searchsorted(element[order], kept)]
        values = {name: values[first] for name, values in fields.items()}
        values["failed"] = np.array([failed[element == cell].any() for cell in kept],
                                    dtype=np.int32)
        values["element_id"] = ids[first].astype(np.int32)
        values["block"] = blocks[first].astype(np.int32)
        if points is not None:
            values["failed_points"] = np.bincount(np.searchsorted(kept, element[failed]),
                                                  minlength=kept.size).astype(np.int32)
        used = np.unique(np.concatenate([geometry.cells[cell][1] for cell in kept]))
        renumbered = [(geometry.cells[cell][0], np.searchsorted(used, geometry.cells[cell][1]))
                      for cell in kept]
        cell_blocks, cell_data = frix_results.meshio_cell_blocks(renumbered, values)
        point_data = {}
    if geometry.displacement is not None:
        point_data["displacement"] = geometry.displacement[used]
    mesh = meshio.Mesh(geometry.points[used], cell_blocks, point_data=point_data,
                       cell_data=cell_data)
    try:
        meshio.vtu.write(path, mesh)
    except OSError as error:
        raise UserError(f"cannot write {path}: {error}") from None
    return sum(len(connectivity) for _, connectivity in cell_blocks)


def main(argv=None):
    args = build_parser().parse_args(argv)
    if not (np.isfinite(args.c) and args.c >= 0.0):
        raise UserError(f"--c must be a finite cohesion >= 0, got {args.c}")
    if not (np.isfinite(args.phi) and 0.0 <= args.phi < 90.0):
        raise UserError(f"--phi must be in [0, 90) degrees, got {args.phi}")
    if not (np.isfinite(args.rel_tol) and args.rel_tol >= 0.0):
        raise UserError(f"--rel-tol must be >= 0, got {args.rel_tol}")
    if args.point and args.block is not None:
        raise UserError("--block works with element stresses, not with --point")
    stress, ids, blocks, points, what, description, geometry, in_set = load_stresses(args)
    if stress.ndim != 2 or stress.shape[1] != 6:
        raise UserError(f"{args.result}: field '{args.stress_field}' has shape {stress.shape}, "
                        "expected 6 components")
    if not np.all(np.isfinite(stress)):
        raise UserError(f"{args.result}: field '{args.stress_field}' has NaN or Inf values")
    if args.compression_positive:
        stress = -stress
    keep = np.ones(len(stress), dtype=bool)
    if args.block is not None:
        try:
            wanted = [int(item) for item in args.block.split(",") if item.strip()]
        except ValueError:
            raise UserError(f"--block: '{args.block}' is not a comma list of integers") from None
        keep = np.isin(blocks, wanted)
        if not keep.any():
            raise UserError(f"no element in block(s) {args.block} (blocks present: "
                            f"{', '.join(str(b) for b in np.unique(blocks))})")
    if in_set is not None:
        keep &= in_set
        if not keep.any():
            raise UserError(f"no element of element set {args.element_set}"
                            + (f" in block(s) {args.block}" if args.block is not None else ""))
    rows = np.flatnonzero(keep)
    stress, ids, blocks = stress[keep], ids[keep], blocks[keep]
    points = points[keep] if points is not None else None

    principal = frix_results.principal_values(frix_results.tensor_from_vtk(stress))
    f = mohr_coulomb(principal, args.c, args.phi)
    tolerance = args.rel_tol * (np.abs(principal[:, 0]) + np.abs(principal[:, 2]) + args.c)
    failed = f >= -tolerance

    print(f"Mohr-Coulomb check of {description}, c = {args.c:g}, phi = {args.phi:g} deg, "
          "stresses tension positive, s1 >= s2 >= s3")
    if points is None:
        print(f"{int(failed.sum())} of {len(f)} {what} at or beyond failure (f >= 0)")
    else:
        unique_ids = np.unique(ids)
        failed_ids = np.unique(ids[failed])
        print(f"{failed_ids.size} of {unique_ids.size} {what} at or beyond failure (f >= 0 at "
              f"one or more integration points)")
        print(f"{int(failed.sum())} of {len(f)} integration points at or beyond failure")
    worst = int(np.argmax(f))
    where = f"{what[:-1]} {ids[worst]}" + (f" point {points[worst]}" if points is not None else "")
    print(f"largest f = {f[worst]:.6e} at {where} "
          f"(s1 = {principal[worst, 0]:.6e}, s3 = {principal[worst, 2]:.6e})")
    if args.table is not None:
        header = (["node_id" if what == "nodes" else "element_id", "block"]
                  + (["point"] if points is not None else []) + ["s1", "s2", "s3", "f", "failed"])
        frix_results.write_csv(args.table, header,
                               ([int(ids[row]), int(blocks[row])]
                                + ([int(points[row])] if points is not None else [])
                                + [repr(float(value)) for value in principal[row]]
                                + [repr(float(f[row])), int(failed[row])] for row in range(len(f))))
        print(f"wrote {args.table} ({len(f)} rows)")
    if args.vtk is not None:
        count = write_vtk(args.vtk, geometry, rows, ids, blocks, principal, f, failed, points,
                          what)
        print(f"wrote {args.vtk} ({count} {'cells, point fields' if what == 'nodes' else 'cells'})")
    return 1 if (args.exit_code and failed.any()) else 0


if __name__ == "__main__":
    frix_results.run_main(main)
