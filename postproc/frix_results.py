"""Shared reading helpers for the frix post-processing scripts.

Reads the files a frix run writes (docs/output.md, docs/listing-format.md):

- ``<base>_history.csv``: ``step,increment,time,<label>...`` (:func:`read_history`),
- ``<base>.pvd`` + ``<base>_SSSS_IIII.vtu`` via meshio (:class:`ResultSeries`),
- ``<base>_listing.txt``: fixed-column blocks (:func:`read_listing`), used here for the user
  node ids, which the .vtu does not hold (its points are in internal order, the order of the
  listing's NODAL DISPLACEMENTS block).

Conventions kept from the files, never changed here:

- Tensors in the .vtu are in VTK's symmetric order XX, YY, ZZ, XY, YZ, XZ with tensor shears
  (docs/output.md). :func:`tensor_from_vtk` builds the 3 x 3 matrices from it.
- Stresses are Cauchy stresses, **tension positive**, in the deck's units.

User mistakes (missing file, malformed file, unknown column or field) raise
:class:`UserError`; :func:`run_main` turns it into a one-line message on stderr and exit
status 2, so no script shows a Python traceback for them.

Runs with Debian's ``/usr/bin/python3`` (numpy, matplotlib, meshio).
"""

import argparse
import ast
import csv
import os
import re
import sys
import xml.etree.ElementTree as ElementTree

import numpy as np

EXIT_USER_ERROR = 2

#: Component names accepted after ``field:`` for 3-component (vector) fields.
VECTOR_COMPONENTS = {"x": 0, "y": 1, "z": 2}
#: Component names accepted after ``field:`` for 6-component (tensor) fields, VTK order.
TENSOR_COMPONENTS = {"xx": 0, "yy": 1, "zz": 2, "xy": 3, "yz": 4, "xz": 5}
#: (row, column) of each VTK tensor component XX YY ZZ XY YZ XZ in the 3 x 3 matrix.
VTK_TENSOR_INDEX = ((0, 0), (1, 1), (2, 2), (0, 1), (1, 2), (0, 2))

#: Faces of an 8-node hexahedron (VTK type 12, the frix/VTK node order), each with its
#: nodes counter-clockwise seen from outside the element; in frix's face numbering 1..6
#: (``hex8_face_nodes`` in src/cells/frix_hex8_cell.f90, the ``faces`` of HDF5 surfaces).
HEX8_FACES = ((0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7))
#: Corner nodes of the faces of a tetrahedron (TET4 and TET10: VTK/Abaqus order), outward,
#: in frix's face numbering 1..4 (Abaqus S1-S4; ``tet4_face_nodes`` in
#: src/cells/frix_tet4_cell.f90).
TET_FACES = ((0, 2, 1), (0, 1, 3), (1, 2, 3), (2, 0, 3))


class CellType:
    """A volume cell as the scripts need it: its meshio name, VTK type code, node count and
    the corner nodes of its faces (0-based, in frix's face numbering)."""

    def __init__(self, meshio_name, vtk_type, n_nodes, faces):
        self.meshio_name = meshio_name
        self.vtk_type = vtk_type
        self.n_nodes = n_nodes
        self.faces = faces


#: The cells frix writes (src/cells), by meshio name; the table the readers below use.
CELL_TYPES = {cell.meshio_name: cell for cell in (
    CellType("hexahedron", 12, 8, HEX8_FACES),
    CellType("tetra", 10, 4, TET_FACES),
    CellType("tetra10", 24, 10, TET_FACES))}
CELL_TYPES_BY_VTK = {cell.vtk_type: cell for cell in CELL_TYPES.values()}


class UserError(Exception):
    """A mistake in the user's input (file or option): reported in one line, exit status 2."""


def run_main(main, argv=None):
    """Call ``main(argv)`` and turn a :class:`UserError` into ``prog: error: msg`` + exit 2."""
    program = os.path.basename(sys.argv[0])
    try:
        status = main(argv)
    except UserError as error:
        message = " ".join(str(error).split())
        print(f"{program}: error: {message}", file=sys.stderr)
        sys.exit(EXIT_USER_ERROR)
    except KeyboardInterrupt:
        sys.exit(130)
    sys.exit(status or 0)


class ArgumentParser(argparse.ArgumentParser):
    """argparse parser whose usage errors are one line (``prog: error: ... (see --help)``)
    with exit status 2, like the scripts' other user errors."""

    def error(self, message):
        self.exit(EXIT_USER_ERROR, f"{self.prog}: error: {message} (see --help)\n")


def use_agg_backend():
    """Select matplotlib's non-interactive Agg backend and return ``pyplot``."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as pyplot
    return pyplot


def save_figure(figure, path, dpi=150):
    """Save a figure to ``path`` (PNG by its extension); a write failure is a UserError."""
    try:
        figure.savefig(path, dpi=dpi, bbox_inches="tight")
    except (OSError, ValueError) as error:
        raise UserError(f"cannot write {path}: {error}") from None


def write_csv(path, header, rows):
    """Write a CSV table (a header row, then ``rows``); a write failure is a UserError."""
    try:
        with open(path, "w", newline="", encoding="utf-8") as stream:
            writer = csv.writer(stream)
            writer.writerow(header)
            writer.writerows(rows)
    except OSError as error:
        raise UserError(f"cannot write {path}: {error}") from None


def require_file(path, what="file"):
    """Raise UserError unless ``path`` is an existing readable file."""
    if not os.path.exists(path):
        raise UserError(f"{what} not found: {path}")
    if os.path.isdir(path):
        raise UserError(f"{what} is a folder, not a file: {path}")
    if not os.access(path, os.R_OK):
        raise UserError(f"{what} not readable: {path}")


def parse_floats(text, count, option):
    """Parse ``count`` comma-separated reals (e.g. ``--line``); UserError if malformed."""
    parts = [part.strip() for part in text.split(",")]
    if len(parts) != count:
        raise UserError(f"{option} needs {count} comma-separated numbers, got '{text}'")
    try:
        values = [float(part) for part in parts]
    except ValueError:
        raise UserError(f"{option} needs {count} comma-separated numbers, got '{text}'") from None
    if not all(np.isfinite(values)):
        raise UserError(f"{option} needs finite numbers, got '{text}'")
    return values


# ----------------------------------------------------------------------------- history CSV

class History:
    """A history CSV: ``columns`` (header labels) and ``data`` (rows x columns, float)."""

    def __init__(self, path, columns, data):
        self.path = path
        self.columns = columns
        self.data = data

    def column(self, name):
        """Values of column ``name``; UserError listing the available ones if absent."""
        if name not in self.columns:
            raise UserError(f"{self.path}: no column '{name}' (columns: {', '.join(self.columns)})")
        return self.data[:, self.columns.index(name)]

    def value_columns(self):
        """The requested DOF columns, i.e. all but step, increment and time."""
        return [name for name in self.columns if name not in ("step", "increment", "time")]


def read_history(path):
    """Read ``<base>_history.csv`` (docs/output.md); UserError if missing or malformed."""
    require_file(path, "history file")
    try:
        with open(path, encoding="utf-8") as stream:
            lines = [line.strip() for line in stream if line.strip()]
    except (OSError, UnicodeDecodeError) as error:
        raise UserError(f"cannot read {path}: {error}") from None
    if not lines:
        raise UserError(f"{path}: empty file, expected a header line 'step,increment,time,...'")
    columns = [name.strip() for name in lines[0].split(",")]
    if any(not name for name in columns) or len(set(columns)) != len(columns):
        raise UserError(f"{path}: line 1: malformed header '{lines[0]}'")
    rows = []
    for number, line in enumerate(lines[1:], start=2):
        fields = line.split(",")
        if len(fields) != len(columns):
            raise UserError(f"{path}: line {number}: {len(fields)} fields, "
                            f"header has {len(columns)}")
        try:
            rows.append([float(field) for field in fields])
        except ValueError:
            raise UserError(f"{path}: line {number}: not a number in '{line}'") from None
    data = np.array(rows, dtype=float).reshape(len(rows), len(columns))
    return History(path, columns, data)


# ----------------------------------------------------------------------------- listing

class ListingIncrement:
    """One converged increment of a listing: header values and its blocks.

    ``blocks`` maps a block title (e.g. ``"NODAL DISPLACEMENTS"``) to a tuple
    ``(key_label, labels, keys, values)``: ``keys`` is a list of the row keys (ints, or the
    text ``TOTAL``), ``values`` a (rows x labels) float array.
    """

    def __init__(self, step, increment, time, iterations):
        self.step = step
        self.increment = increment
        self.time = time
        self.iterations = iterations
        self.blocks = {}


_INCREMENT_HEADER = re.compile(
    r"^STEP\s+(\d+)\s+INCREMENT\s+(\d+)\s+TIME\s+(\S+)\s+ITERATIONS\s+(\d+)\s*$")


def read_listing(path):
    """Read a listing (docs/listing-format.md) into a list of :class:`ListingIncrement`."""
    require_file(path, "listing")
    try:
        with open(path, encoding="utf-8") as stream:
            lines = stream.read().splitlines()
    except (OSError, UnicodeDecodeError) as error:
        raise UserError(f"cannot read {path}: {error}") from None
    increments = []
    block = None
    for number, line in enumerate(lines, start=1):
        if not line.strip() or line.startswith("#"):
            continue
        if not line[0].isspace():
            match = _INCREMENT_HEADER.match(line)
            if match:
                try:
                    increments.append(ListingIncrement(int(match.group(1)), int(match.group(2)),
                                                       float(match.group(3)), int(match.group(4))))
                except ValueError:
                    raise UserError(f"{path}: line {number}: malformed increment header") from None
                block = None
            elif not increments:
                raise UserError(f"{path}: line {number}: block '{line.strip()}' before the first "
                                "STEP ... INCREMENT header")
            else:
                block = [line.strip(), None, [], [], []]
                increments[-1].blocks[block[0]] = block
            continue
        if block is None:
            raise UserError(f"{path}: line {number}: data row outside a block")
        fields = line.split()
        if block[1] is None:
            if not line[:10].strip():      # no key label (SUM OF REACTIONS): keys are text
                block[1], block[2] = "", fields
            else:
                block[1], block[2] = fields[0], fields[1:]
            continue
        if len(fields) != len(block[2]) + 1:
            raise UserError(f"{path}: line {number}: {len(fields) - 1} values, "
                            f"header has {len(block[2])}")
        key = fields[0]
        try:
            block[3].append(int(key) if re.fullmatch(r"[+-]?\d+", key) else key)
            block[4].append([float(field) for field in fields[1:]])
        except ValueError:
            raise UserError(f"{path}: line {number}: not a number in '{line.strip()}'") from None
    for increment in increments:
        for title, (_, key_label, labels, keys, values) in list(increment.blocks.items()):
            array = np.array(values, dtype=float).reshape(len(values), len(labels))
            increment.blocks[title] = (key_label, labels, keys, array)
    return increments


def node_ids_from_listing(path):
    """User node ids in internal order (= .vtu point order), from the listing's first
    ``NODAL DISPLACEMENTS`` block."""
    for increment in read_listing(path):
        if "NODAL DISPLACEMENTS" in increment.blocks:
            return np.array(increment.blocks["NODAL DISPLACEMENTS"][2], dtype=int)
    raise UserError(f"{path}: no NODAL DISPLACEMENTS block")


# ----------------------------------------------------------------------------- pvd / vtu

_VTU_NAME = re.compile(r"^(?P<base>.*)_(?P<step>\d{4,})_(?P<increment>\d{4,})\.vtu$")


class IncrementEntry:
    """One increment of a result series: ``position`` (1-based in the .pvd), ``time`` (load
    factor), ``step`` and ``increment`` numbers (from the file name, None if not frix-named),
    ``path`` of its .vtu."""

    def __init__(self, position, time, path):
        self.position = position
        self.time = time
        self.path = path
        match = _VTU_NAME.match(os.path.basename(path))
        self.step = int(match.group("step")) if match else None
        self.increment = int(match.group("increment")) if match else None

    def label(self):
        if self.step is not None:
            return f"step {self.step} incr {self.increment} (t = {self.time:g})"
        return f"t = {self.time:g}"


class ResultSeries:
    """The increments of a run, from a ``.pvd`` collection or a single ``.vtu``."""

    def __init__(self, path):
        require_file(path, "result file")
        self.path = path
        self.entries = []
        extension = os.path.splitext(path)[1].lower()
        if extension == ".pvd":
            self._read_pvd(path)
            self.base = os.path.splitext(path)[0]
        elif extension == ".vtu":
            mesh = read_vtu(path)
            time = float(np.ravel(mesh.field_data["TimeValue"])[0]) \
                if "TimeValue" in mesh.field_data else 0.0
            self.entries.append(IncrementEntry(1, time, path))
            match = _VTU_NAME.match(path)
            self.base = match.group("base") if match else os.path.splitext(path)[0]
            self._cache = {path: mesh}
            return
        else:
            raise UserError(f"{path}: expected a .pvd or .vtu file")
        self._cache = {}

    def _read_pvd(self, path):
        try:
            root = ElementTree.parse(path).getroot()
        except (ElementTree.ParseError, OSError) as error:
            raise UserError(f"{path}: not a readable .pvd (XML) file: {error}") from None
        folder = os.path.dirname(path)
        datasets = root.findall("./Collection/DataSet")
        if root.tag != "VTKFile" or not datasets:
            raise UserError(f"{path}: no <Collection><DataSet> entries, not a .pvd collection")
        for position, dataset in enumerate(datasets, start=1):
            try:
                time = float(dataset.get("timestep", "nan"))
            except ValueError:
                raise UserError(f"{path}: DataSet {position}: bad timestep "
                                f"'{dataset.get('timestep')}'") from None
            name = dataset.get("file")
            if not name:
                raise UserError(f"{path}: DataSet {position} has no file attribute")
            self.entries.append(IncrementEntry(position, time, os.path.join(folder, name)))

    def select(self, spec):
        """Entries chosen by ``spec``: ``last`` | ``first`` | ``all`` | a comma list of items,
        each a 1-based position in the collection (negative counts from the end) or
        ``STEP:INCREMENT``."""
        spec = str(spec).strip().lower()
        if spec == "all":
            return list(self.entries)
        chosen = []
        for item in [part.strip() for part in spec.split(",")]:
            if item == "last":
                chosen.append(self.entries[-1])
            elif item == "first":
                chosen.append(self.entries[0])
            elif re.fullmatch(r"\d+:\d+", item):
                step, increment = (int(part) for part in item.split(":"))
                found = [entry for entry in self.entries
                         if entry.step == step and entry.increment == increment]
                if not found:
                    raise UserError(f"{self.path}: no increment {item} (available: "
                                    f"{self.available()})")
                chosen.append(found[0])
            elif re.fullmatch(r"-?\d+", item):
                position = int(item)
                count = len(self.entries)
                if position == 0 or abs(position) > count:
                    raise UserError(f"{self.path}: increment position {position} out of range "
                                    f"1..{count} (or -1..-{count})")
                chosen.append(self.entries[position - 1 if position > 0 else position])
            else:
                raise UserError(f"bad increment selection '{item}': use last, first, all, a "
                                "1-based position or STEP:INCREMENT")
        return chosen

    def available(self):
        return ", ".join(f"{entry.step}:{entry.increment}" if entry.step is not None
                         else str(entry.position) for entry in self.entries)

    def mesh(self, entry):
        """The meshio mesh of an entry (read once, then cached)."""
        if entry.path not in self._cache:
            self._cache[entry.path] = read_vtu(entry.path)
        return self._cache[entry.path]

    def listing_path(self):
        """``<base>_listing.txt`` beside the results, or None if there is none."""
        candidate = self.base + "_listing.txt"
        return candidate if os.path.isfile(candidate) else None


def read_vtu(path):
    """Read one .vtu with meshio; UserError if missing, unreadable, without volume cells
    or with a cell type frix does not write."""
    require_file(path, "vtu file")
    import meshio
    try:
        # the format's own reader: meshio.read() prints and calls sys.exit(1) on a bad file
        mesh = meshio.vtu.read(path)
    except Exception as error:  # meshio raises many types (ReadError, ValueError, KeyError, ...)
        detail = str(error).strip() or "not a valid VTK XML UnstructuredGrid (.vtu) file"
        raise UserError(f"cannot read {path}: {detail}") from None
    unknown = sorted({block.type for block in mesh.cells} - set(CELL_TYPES))
    if unknown:
        raise UserError(f"{path}: cells of type {', '.join(unknown)}; the scripts read "
                        f"{', '.join(sorted(CELL_TYPES))}")
    if not mesh.cells:
        raise UserError(f"{path}: no cells")
    return mesh


def hexahedra(mesh):
    """Connectivity (n_elements x 8, 0-based point indices) of a .vtu of HEX8 cells only."""
    if [block.type for block in mesh.cells] != ["hexahedron"] * len(mesh.cells):
        raise UserError("this script reads meshes of hexahedra (HEX8) only")
    return np.vstack([np.asarray(block.data, dtype=int) for block in mesh.cells])


def mesh_cells(mesh):
    """The .vtu's cells in file order: a list of (CellType, 0-based node indices) per cell."""
    return [(CELL_TYPES[block.type], row) for block in mesh.cells
            for row in np.asarray(block.data, dtype=int)]


def meshio_cell_blocks(cells, cell_values=None):
    """[(CellType, nodes)] as meshio cell blocks (each run of one type a block, the order
    kept): ([(meshio name, connectivity)], and each array of ``cell_values`` (a dict of
    per-cell arrays) split into the blocks' lists, as meshio's cell_data wants them)."""
    blocks, lengths = [], []
    for cell, nodes in cells:
        if blocks and blocks[-1][0] == cell.meshio_name:
            blocks[-1][1].append(nodes)
            lengths[-1] += 1
        else:
            blocks.append((cell.meshio_name, [nodes]))
            lengths.append(1)
    splits = np.cumsum(lengths)[:-1]
    data = {name: np.split(np.asarray(values), splits)
            for name, values in (cell_values or {}).items()}
    return [(name, np.asarray(rows, dtype=int)) for name, rows in blocks], data


def boundary_faces(cells):
    """Faces of the given cells [(CellType, nodes)] that belong to one cell only: (list of
    faces, each an array of its corner point indices, outward; the owner's position in
    ``cells``)."""
    counts, faces = {}, []
    for owner, (cell, nodes) in enumerate(cells):
        for corners in cell.faces:
            face = nodes[list(corners)]
            key = tuple(sorted(face))
            counts[key] = counts.get(key, 0) + 1
            faces.append((key, face, owner))
    single = [(face, owner) for key, face, owner in faces if counts[key] == 1]
    return [face for face, _ in single], np.array([owner for _, owner in single], dtype=int)


def parse_field_spec(spec):
    """Split ``name[:component]`` into (name, component or None)."""
    name, _, component = spec.partition(":")
    name = name.strip()
    if not name:
        raise UserError(f"bad field '{spec}': expected NAME or NAME:COMPONENT")
    return name, (component.strip() or None)


def _component_index(name, component, width):
    """Column of ``component`` (an index or a name x/y/z, xx/yy/zz/xy/yz/xz) in a field of
    ``width`` columns; None means the whole field (allowed only for 1 column)."""
    if component is None:
        return None
    key = component.lower()
    if re.fullmatch(r"\d+", key):
        index = int(key)
    elif width == 3 and key in VECTOR_COMPONENTS:
        index = VECTOR_COMPONENTS[key]
    elif width == 6 and key in TENSOR_COMPONENTS:
        index = TENSOR_COMPONENTS[key]
    elif key in ("mag", "magnitude"):
        return "magnitude"
    else:
        raise UserError(f"field '{name}': unknown component '{component}'")
    if index >= width:
        raise UserError(f"field '{name}' has {width} components (0..{width - 1}), not {index}")
    return index


def field_values(mesh, spec, location="point"):
    """Values (1D array) of ``spec`` = ``name[:component]`` at the points or cells.

    ``component`` is a 0-based index, a name (x, y, z for vectors; xx, yy, zz, xy, yz, xz for
    the VTK-ordered tensors) or ``mag`` (Euclidean norm of the row). A field with more than
    one component needs a component, except vectors (3), whose default is the magnitude.
    """
    name, component = parse_field_spec(spec)
    if location == "point":
        data = mesh.point_data
    elif location == "cell":
        data = {key: np.concatenate(value) for key, value in mesh.cell_data.items()}
    else:
        raise ValueError(location)
    if name not in data:
        raise UserError(f"no {location} field '{name}' (available: {', '.join(sorted(data))})")
    values = np.asarray(data[name], dtype=float)
    if values.ndim == 1:
        values = values[:, None]
    width = values.shape[1]
    index = _component_index(name, component, width)
    if index is None:
        if width == 1:
            return values[:, 0]
        if width == 3:
            return np.linalg.norm(values, axis=1)
        raise UserError(f"field '{name}' has {width} components: choose one as {name}:INDEX")
    if index == "magnitude":
        return np.linalg.norm(values, axis=1)
    return values[:, index]


def has_field(mesh, name, location):
    """True if the mesh has a ``location`` (point/cell) field ``name``."""
    return name in (mesh.point_data if location == "point" else mesh.cell_data)


def cell_array(mesh, name):
    """Cell data array ``name`` over all cells in file order, or None if absent."""
    if name not in mesh.cell_data:
        return None
    return np.concatenate([np.asarray(block) for block in mesh.cell_data[name]])


def node_ids(series, mesh, listing=None):
    """User node ids of the .vtu points: point data ``node_id`` if written, else the
    listing's node column (``listing`` or ``<base>_listing.txt``); None if neither exists."""
    if "node_id" in mesh.point_data:
        return np.asarray(mesh.point_data["node_id"], dtype=int).ravel()
    path = listing or series.listing_path()
    if path is None:
        return None
    ids = node_ids_from_listing(path)
    if ids.size != len(mesh.points):
        raise UserError(f"{path}: {ids.size} nodes, but the .vtu has {len(mesh.points)} points")
    return ids


def read_id_file(path):
    """Integers separated by blanks, commas or newlines; ``#`` starts a comment."""
    require_file(path, "node set file")
    ids = []
    with open(path, encoding="utf-8", errors="replace") as stream:
        for number, line in enumerate(stream, start=1):
            for token in re.split(r"[\s,;]+", line.split("#", 1)[0].strip()):
                if not token:
                    continue
                if not re.fullmatch(r"[+-]?\d+", token):
                    raise UserError(f"{path}: line {number}: '{token}' is not a node id")
                ids.append(int(token))
    if not ids:
        raise UserError(f"{path}: no node ids")
    return ids


# ----------------------------------------------------------------------------- contact CSV

def contact_pair_nodes(path, pair, all_passes=False):
    """User node ids of contact pair ``pair`` from ``<base>_contact.csv`` (docs/output.md),
    in the file's order (frix's pass order) and the passes they come from: the pair's first
    pass (its SLAVE surface's nodes), or with ``all_passes`` every pass of the pair (with
    ``PASSES 2`` also the master surface's nodes). Read from the file's first increment: the
    slave nodes of a pair do not change during a run."""
    require_file(path, "contact CSV file")
    try:
        with open(path, encoding="utf-8") as stream:
            header = stream.readline().strip().split(",")
            columns = {name: header.index(name) for name in ("step", "increment", "pair",
                                                             "pass", "node")}
            rows, first = [], None
            for number, line in enumerate(stream, start=2):
                fields = line.split(",")
                if len(fields) != len(header):
                    raise UserError(f"{path}: line {number}: {len(fields)} fields, header has "
                                    f"{len(header)}")
                key = (fields[columns["step"]], fields[columns["increment"]])
                if first is None:
                    first = key
                elif key != first:
                    break
                rows.append([int(fields[columns[name]]) for name in ("pair", "pass", "node")])
    except ValueError as error:
        raise UserError(f"{path}: not a frix contact CSV file (header 'step,increment,time,"
                        f"pair,pass,node,...'): {error}") from None
    except (OSError, UnicodeDecodeError) as error:
        raise UserError(f"cannot read {path}: {error}") from None
    rows = np.array(rows, dtype=int).reshape(-1, 3)
    pairs = sorted(set(rows[:, 0].tolist()))
    if pair not in pairs:
        raise UserError(f"{path}: no contact pair {pair} (pairs: "
                        f"{', '.join(map(str, pairs)) or 'none, no converged increment'})")
    rows = rows[rows[:, 0] == pair]
    passes = sorted(set(rows[:, 1].tolist()))
    if not all_passes:
        rows = rows[rows[:, 1] == passes[0]]
        passes = passes[:1]
    ids, seen = [], set()
    for node in rows[:, 2]:
        if node not in seen:
            seen.add(node)
            ids.append(int(node))
    return np.array(ids, dtype=int), passes


# ----------------------------------------------------------------------------- HDF5

class GaussStresses:
    """Integration-point stresses of one increment of a frix HDF5 results file
    (docs/hdf5-layout.md): ``stress`` (n_elements x n_points x 6, **VTK order** XX YY ZZ XY YZ
    XZ after conversion from the file's Voigt order xx yy zz xy xz yz), ``element_ids``,
    ``blocks``, and ``step``, ``increment``, ``time`` of the increment."""

    def __init__(self, path, stress, element_ids, blocks, step, increment, time):
        self.path = path
        self.stress = stress
        self.element_ids = element_ids
        self.blocks = blocks
        self.step = step
        self.increment = increment
        self.time = time

    def label(self):
        return f"step {self.step} incr {self.increment} (t = {self.time:g})"


class H5Increment:
    """One complete increment group of a frix HDF5 results file: ``name`` (``000001``, ...),
    ``position`` (1-based among the complete groups), ``step``, ``increment``, ``time``."""

    def __init__(self, name, position, step, increment, time):
        self.name = name
        self.position = position
        self.step = step
        self.increment = increment
        self.time = time

    def key(self):
        return f"{self.step}:{self.increment}"

    def label(self):
        return f"step {self.step} incr {self.increment} (t = {self.time:g})"


class H5Results:
    """A frix HDF5 results file (docs/hdf5-layout.md), opened read-only.

    ``increments``: the complete increment groups (:class:`H5Increment`, in the order
    written; groups without the ``complete`` attribute are ignored). Mesh arrays are read on
    demand (:meth:`mesh_array`, :meth:`node_set`, :meth:`surface_nodes`), increment datasets
    with :meth:`dataset`. Every read error is a :class:`UserError` naming the file. Use as a
    context manager or call :meth:`close`."""

    def __init__(self, path):
        require_file(path, "HDF5 file")
        try:
            import h5py
        except ImportError:
            raise UserError("reading HDF5 needs h5py (Debian: python3-h5py)") from None
        self.path = path
        try:
            self.file = h5py.File(path, "r")
        except OSError as error:
            raise UserError(f"cannot read {path} as a frix HDF5 results file: {error}") from None
        try:
            names = sorted(self.file["increments"], key=lambda name: (len(name), name))
            self.increments = []
            for name in names:
                attrs = self.file["increments"][name].attrs
                if int(attrs.get("complete", 0)) != 1:
                    continue
                self.increments.append(H5Increment(name, len(self.increments) + 1,
                                                   int(attrs["step"]), int(attrs["increment"]),
                                                   float(attrs["time"])))
        except (OSError, KeyError, ValueError, TypeError) as error:
            self.close()
            raise UserError(f"cannot read {path} as a frix HDF5 results file: {error}") from None

    def __enter__(self):
        return self

    def __exit__(self, *exception):
        self.close()

    def close(self):
        if getattr(self, "file", None) is not None:
            self.file.close()
            self.file = None

    def available(self):
        return ", ".join(entry.key() for entry in self.increments) or "none"

    def select(self, spec="last"):
        """The increment chosen by ``spec``: last | first | 1-based position among the
        complete groups (negative from the end) | STEP:INCREMENT."""
        if not self.increments:
            raise UserError(f"{self.path}: no complete increment group under /increments")
        spec = str(spec).strip().lower()
        if spec in ("last", "first"):
            return self.increments[-1 if spec == "last" else 0]
        if re.fullmatch(r"\d+:\d+", spec):
            for entry in self.increments:
                if entry.key() == spec:
                    return entry
            raise UserError(f"{self.path}: no increment {spec} (available: {self.available()})")
        count = len(self.increments)
        if re.fullmatch(r"-?\d+", spec) and 1 <= abs(int(spec)) <= count:
            return self.increments[int(spec) - 1 if int(spec) > 0 else int(spec)]
        raise UserError(f"{self.path}: bad increment selection '{spec}' (1..{count}, "
                        "last, first or STEP:INCREMENT)")

    def _read(self, location, what):
        try:
            return self.file[location][()]
        except (OSError, KeyError, ValueError, TypeError) as error:
            raise UserError(f"cannot read {what} from {self.path} as a frix HDF5 results file: "
                            f"{error}") from None

    def mesh_array(self, name):
        """``/mesh/<name>`` (coordinates, node_ids, connectivity, element_ids, element_block)."""
        return np.asarray(self._read(f"mesh/{name}", f"/mesh/{name}"))

    def dataset(self, entry, name):
        """Dataset ``name`` (e.g. ``displacement``, ``stress``) of increment ``entry``."""
        location = f"increments/{entry.name}/{name}"
        return np.asarray(self._read(location, "/" + location))

    def _names(self, kind):
        group = self.file.get(f"mesh/{kind}")
        return sorted(group.keys()) if group is not None else []

    def node_set(self, name):
        """0-based internal node numbers of ``/mesh/node_sets/<name>``."""
        if name not in self._names("node_sets"):
            raise UserError(f"{self.path}: no node set '{name}' (node sets: "
                            f"{', '.join(self._names('node_sets')) or 'none'})")
        return np.asarray(self._read(f"mesh/node_sets/{name}", "a node set"), dtype=int) - 1

    def element_set(self, name):
        """0-based internal element numbers of ``/mesh/element_sets/<name>``."""
        if name not in self._names("element_sets"):
            raise UserError(f"{self.path}: no element set '{name}' (element sets: "
                            f"{', '.join(self._names('element_sets')) or 'none'})")
        return np.asarray(self._read(f"mesh/element_sets/{name}", "an element set"),
                          dtype=int) - 1

    def surface_nodes(self, name):
        """0-based internal node numbers (sorted, unique) of the faces of surface ``name``."""
        if name not in self._names("surfaces"):
            raise UserError(f"{self.path}: no surface '{name}' (surfaces: "
                            f"{', '.join(self._names('surfaces')) or 'none'})")
        elements = np.asarray(self._read(f"mesh/surfaces/{name}/elements", "a surface"), dtype=int)
        faces = np.asarray(self._read(f"mesh/surfaces/{name}/faces", "a surface"), dtype=int)
        cells = self.cells()
        nodes = [cells[element - 1][1][corner]
                 for element, face in zip(elements, faces)
                 for corner in cells[element - 1][0].faces[face - 1]]
        return np.unique(np.asarray(nodes, dtype=int))

    def cells(self):
        """The mesh's cells: a list of (CellType, 0-based node numbers) per element, from
        /mesh/connectivity and /mesh/cell_types (absent: every cell a HEX8)."""
        connectivity = self.mesh_array("connectivity").astype(int) - 1
        if "cell_types" in self.file["mesh"]:
            types = self.mesh_array("cell_types").astype(int)
        else:
            types = np.full(len(connectivity), CELL_TYPES["hexahedron"].vtk_type)
        unknown = sorted(set(types.tolist()) - set(CELL_TYPES_BY_VTK))
        if unknown:
            raise UserError(f"{self.path}: VTK cell types {unknown} in /mesh/cell_types; the "
                            f"scripts read {sorted(CELL_TYPES_BY_VTK)}")
        return [(CELL_TYPES_BY_VTK[code], row[:CELL_TYPES_BY_VTK[code].n_nodes])
                for code, row in zip(types, connectivity)]


def read_h5_stresses(path, spec="last"):
    """Gauss-point stresses of the increment ``spec`` (last | first | 1-based position among
    the complete increment groups, negative from the end | STEP:INCREMENT) of an HDF5 file."""
    with H5Results(path) as results:
        entry = results.select(spec)
        voigt = np.asarray(results.dataset(entry, "stress"), dtype=float)
        element_ids = results.mesh_array("element_ids").astype(int)
        blocks = results.mesh_array("element_block").astype(int)
    if voigt.ndim != 3 or voigt.shape[2] != 6 or voigt.shape[0] != element_ids.size:
        raise UserError(f"{path}: stress has shape {voigt.shape}, expected "
                        f"({element_ids.size}, n_points, 6)")
    return GaussStresses(path, voigt[:, :, [0, 1, 2, 3, 5, 4]], element_ids, blocks,
                         entry.step, entry.increment, entry.time)


# ----------------------------------------------------------------------------- tensors

def tensor_from_vtk(components):
    """(n, 6) VTK-ordered symmetric tensors XX YY ZZ XY YZ XZ -> (n, 3, 3) matrices."""
    components = np.asarray(components, dtype=float)
    if components.ndim != 2 or components.shape[1] != 6:
        raise UserError(f"expected 6 tensor components per row, got shape {components.shape}")
    tensors = np.empty((components.shape[0], 3, 3))
    for column, (row, col) in enumerate(VTK_TENSOR_INDEX):
        tensors[:, row, col] = components[:, column]
        tensors[:, col, row] = components[:, column]
    return tensors


def tensor_from_voigt(components):
    """(n, 6) frix Voigt order xx yy zz xy xz yz (tensor shears, stresses) -> (n, 3, 3)."""
    components = np.asarray(components, dtype=float)
    return tensor_from_vtk(components[:, [0, 1, 2, 3, 5, 4]])


def principal_values(tensors):
    """Eigenvalues of symmetric (n, 3, 3) tensors, sorted s1 >= s2 >= s3 (shape (n, 3))."""
    return np.linalg.eigvalsh(tensors)[:, ::-1]


# ----------------------------------------------------------------------------- expressions

#: Names an ``--analytic`` expression may use besides its variables.
SAFE_FUNCTIONS = {name: getattr(np, name) for name in (
    "sin", "cos", "tan", "arcsin", "arccos", "arctan", "arctan2", "sinh", "cosh", "tanh",
    "arcsinh", "arccosh", "arctanh", "exp", "log", "log10", "sqrt", "abs", "sign", "where",
    "minimum", "maximum", "clip", "heaviside", "pi", "e", "hypot", "power")}
SAFE_FUNCTIONS["coth"] = lambda value: 1.0 / np.tanh(value)
_SAFE_NODES = (ast.Expression, ast.BinOp, ast.UnaryOp, ast.BoolOp, ast.Compare, ast.IfExp,
               ast.Call, ast.Name, ast.Load, ast.Constant, ast.Attribute, ast.operator,
               ast.unaryop, ast.boolop, ast.cmpop, ast.Tuple, ast.keyword)


def compile_expression(text, variables):
    """Check and compile a numpy expression of ``variables`` (restricted namespace: the
    variables, ``np``/``numpy`` and :data:`SAFE_FUNCTIONS`; no builtins, no private names).
    Returns a function of keyword arguments ``variables``."""
    try:
        tree = ast.parse(text, mode="eval")
    except SyntaxError as error:
        raise UserError(f"bad expression '{text}': {error.msg}") from None
    allowed = set(variables) | set(SAFE_FUNCTIONS) | {"np", "numpy"}
    for node in ast.walk(tree):
        if not isinstance(node, _SAFE_NODES):
            raise UserError(f"expression '{text}': {type(node).__name__} not allowed")
        if isinstance(node, ast.Name) and node.id not in allowed:
            raise UserError(f"expression '{text}': unknown name '{node.id}' (allowed: "
                            f"{', '.join(sorted(allowed))})")
        if isinstance(node, ast.Attribute):
            if node.attr.startswith("_") or not isinstance(node.value, ast.Name) \
                    or node.value.id not in ("np", "numpy") \
                    or not (node.attr in SAFE_FUNCTIONS
                            or isinstance(getattr(np, node.attr, None), np.ufunc)):
                raise UserError(f"expression '{text}': only np.<function> attributes allowed "
                                "(numpy ufuncs and the functions listed in --help)")
        if isinstance(node, ast.Constant) and not isinstance(node.value, (int, float)):
            raise UserError(f"expression '{text}': only numeric constants allowed")
    code = compile(tree, "<expression>", "eval")

    def evaluate(**values):
        namespace = {"__builtins__": {}, "np": np, "numpy": np}
        namespace.update(SAFE_FUNCTIONS)
        namespace.update(values)
        try:
            with np.errstate(all="ignore"):
                result = eval(code, namespace)  # restricted: checked AST, no builtins
        except Exception as error:
            raise UserError(f"expression '{text}' failed: {type(error).__name__}: {error}") \
                from None
        reference = next(iter(values.values()))
        return np.broadcast_to(np.asarray(result, dtype=float), np.shape(reference)).copy()

    return evaluate
