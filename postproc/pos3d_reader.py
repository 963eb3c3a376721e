#!/usr/bin/python3
"""Reader for Tecgraf's POS3D "neutral file" as written by frix (docs/pos3d.md).

Independent of the Fortran writer: it parses the blocks as the format describes them
(docs/pos3d.md, "The format") into numpy arrays.

    /usr/bin/python3 postproc/pos3d_reader.py FILE [--summary]

As a module:
    from pos3d_reader import read_pos3d
    model = read_pos3d("results/s1.pos")
    model.coords            # (n_nodes, 3)
    model.bricks            # (n_bricks, 8) 1-based node ids, Tecgraf order
    model.steps[-1].displacement[:, :3]

Conventions checked here (the format's, not frix's):
- ids are 1-based; frix writes them consecutive 1..n, the reader requires that (so that row
  i of every array is id i + 1).
- BRICK8 node order: nodes 1-4 on the face t = +1, counter-clockwise in (r, s); nodes 5-8 on
  t = -1 (node k + 4 below node k). `TECGRAF_BRICK8_SIGNS` are those natural coordinates.
- Gauss point k of a brick (frix's output) sits at TECGRAF_BRICK8_SIGNS[k] / sqrt(3).
"""
import argparse
import re
import sys

import numpy as np

#: natural coordinates (r, s, t) of the Tecgraf BRICK8 nodes 1..8 (rows)
TECGRAF_BRICK8_SIGNS = np.array([
    [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1],
    [-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1]], dtype=float)

#: natural coordinates of the VTK hexahedron nodes 1..8 (bottom face zeta = -1 first)
VTK_HEXAHEDRON_SIGNS = np.array([
    [-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
    [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]], dtype=float)

_TOKEN = re.compile(r"'[^']*'|\S+")


class Pos3dError(Exception):
    """A missing, unreadable or malformed neutral file."""


class Step:
    """One result step: id, label, factor, displacement (n_nodes, 6), nodal scalars
    (n_nodes, k) named nodal_scalar_names, Gauss scalars (n_bricks, n_points, k) named
    gauss_scalar_names."""

    def __init__(self, step_id):
        self.id = step_id
        self.label = None
        self.factor = None
        self.displacement = None
        self.displacement_label = None
        self.nodal_scalar_names = []
        self.nodal_scalars = None
        self.gauss_scalar_names = []
        self.gauss_scalars = None

    def nodal(self, name):
        """Column of the nodal scalar `name`."""
        return self.nodal_scalars[:, self.nodal_scalar_names.index(name)]

    def gauss(self, name):
        """(n_bricks, n_points) values of the Gauss scalar `name`."""
        return self.gauss_scalars[:, :, self.gauss_scalar_names.index(name)]


class Pos3dModel:
    """Contents of a neutral file."""

    def __init__(self):
        self.title = ""
        self.n_nodes_declared = None
        self.coords = np.zeros((0, 3))
        self.materials = np.zeros((0, 2))      # rows: E, nu of material id row + 1
        self.n_elements_declared = None
        self.brick_material = np.zeros(0, dtype=int)
        self.brick_integration_order = np.zeros(0, dtype=int)
        self.bricks = np.zeros((0, 8), dtype=int)
        self.result_labels = []
        self.case_step_labels = []
        self.steps = []
        self.ignored_blocks = []


class _Block:
    """The tokens following a tag, each with its line number."""

    def __init__(self, path, tag, line_number):
        self.path, self.tag, self.line_number = path, tag, line_number
        self.tokens = []       # (text, line number)
        self.position = 0

    def error(self, message, line_number=None):
        return Pos3dError(f"{self.path}:{line_number or self.line_number}: {self.tag}: {message}")

    def next(self, what):
        if self.position >= len(self.tokens):
            raise self.error(f"missing {what} (block ended)")
        token = self.tokens[self.position]
        self.position += 1
        return token

    def integer(self, what, minimum=None):
        text, line = self.next(what)
        try:
            value = int(text)
        except ValueError:
            raise self.error(f"{what}: expected an integer, got {text!r}", line) from None
        if minimum is not None and value < minimum:
            raise self.error(f"{what}: expected >= {minimum}, got {value}", line)
        return value

    def real(self, what):
        text, line = self.next(what)
        try:
            value = float(text.replace("D", "E").replace("d", "e"))
        except ValueError:
            raise self.error(f"{what}: expected a number, got {text!r}", line) from None
        if not np.isfinite(value):
            raise self.error(f"{what}: not finite: {text!r}", line)
        return value

    def string(self, what):
        text, line = self.next(what)
        if len(text) < 2 or text[0] != "'" or text[-1] != "'":
            raise self.error(f"{what}: expected a quoted string, got {text!r}", line)
        return text[1:-1]

    def expect_id(self, expected, what):
        value = self.integer(what)
        if value != expected:
            raise self.error(f"{what}: ids must run 1, 2, ...: expected {expected}, got {value}",
                             self.tokens[self.position - 1][1])

    def finish(self):
        if self.position != len(self.tokens):
            text, line = self.tokens[self.position]
            raise self.error(f"unexpected extra data {text!r}", line)


def _read_node_rows(block, n, k, what):
    """n rows "node id (1..n), k reals" as an (n, k) array."""
    values = np.empty((n, k))
    for i in range(n):
        block.expect_id(i + 1, "node id")
        values[i] = [block.real(what) for _ in range(k)]
    return values


def _blocks(path):
    try:
        with open(path, encoding="ascii", errors="strict") as stream:
            lines = stream.read().splitlines()
    except FileNotFoundError:
        raise Pos3dError(f"{path}: no such file") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise Pos3dError(f"{path}: cannot read: {exc}") from None
    blocks, current = [], None
    for number, line in enumerate(lines, start=1):
        if line.startswith("%"):
            current = _Block(path, line.split()[0][1:], number)
            blocks.append(current)
            rest = line.split(None, 1)[1:]
            current.tokens += [(t, number) for t in _TOKEN.findall(rest[0])] if rest else []
        elif current is not None:
            current.tokens += [(t, number) for t in _TOKEN.findall(line)]
    if not blocks:
        raise Pos3dError(f"{path}: not a neutral file (no %BLOCK tag)")
    return blocks


def read_pos3d(path):
    """Parse the neutral file `path`; raises Pos3dError when it is missing or malformed."""
    model = Pos3dModel()
    step = None
    ended = False
    for block in _blocks(path):
        if ended:
            raise block.error("block after %END")
        tag = block.tag
        if tag == "HEADER":
            model.title = block.string("title") if block.tokens else ""
        elif tag == "NODE":
            model.n_nodes_declared = block.integer("number of nodes", 0)
        elif tag == "NODE.COORD":
            n = block.integer("number of nodes", 0)
            coords = np.empty((n, 3))
            for i in range(n):
                block.expect_id(i + 1, "node id")
                coords[i] = [block.real("coordinate") for _ in range(3)]
            model.coords = coords
        elif tag == "MATERIAL":
            block.integer("number of materials", 0)
        elif tag == "MATERIAL.ISOTROPIC":
            n = block.integer("number of materials", 0)
            materials = np.empty((n, 2))
            for i in range(n):
                block.expect_id(i + 1, "material id")
                materials[i] = [block.real("E"), block.real("nu")]
            model.materials = materials
        elif tag == "ELEMENT":
            model.n_elements_declared = block.integer("number of elements", 0)
        elif tag == "ELEMENT.BRICK8":
            n = block.integer("number of bricks", 0)
            model.bricks = np.empty((n, 8), dtype=int)
            model.brick_material = np.empty(n, dtype=int)
            model.brick_integration_order = np.empty(n, dtype=int)
            for i in range(n):
                block.expect_id(i + 1, "element id")
                model.brick_material[i] = block.integer("material", 1)
                model.brick_integration_order[i] = block.integer("integration order", 1)
                model.bricks[i] = [block.integer("node", 1) for _ in range(8)]
        elif tag == "RESULT":
            n = block.integer("number of results", 0)
            for i in range(n):
                block.expect_id(i + 1, "result id")
                model.result_labels.append(block.string("result label"))
        elif tag == "RESULT.CASE":
            block.integer("case id", 1)
            n = block.integer("number of steps", 0)
            for i in range(n):
                block.expect_id(i + 1, "step id")
                model.case_step_labels.append(block.string("step label"))
        elif tag == "RESULT.CASE.STEP":
            step = Step(block.integer("step id", 1))
            if step.id != len(model.steps) + 1:
                raise block.error(f"steps must run 1, 2, ...: expected {len(model.steps) + 1}, got {step.id}")
            if step.id <= len(model.case_step_labels):
                step.label = model.case_step_labels[step.id - 1]
            model.steps.append(step)
        elif tag.startswith("RESULT.CASE.STEP."):
            if step is None:
                raise block.error("result data before %RESULT.CASE.STEP")
            _read_step_block(block, tag[len("RESULT.CASE.STEP."):], step, model)
        elif tag == "END":
            ended = True
        else:
            model.ignored_blocks.append(tag)
            continue
        block.finish()
    if not ended:
        raise Pos3dError(f"{path}: no %END (file truncated?)")
    _check_consistency(path, model)
    return model


def _read_step_block(block, name, step, model):
    if name == "FACTOR":
        step.factor = block.real("factor")
    elif name == "NODAL.DISPLACEMENT":
        n = block.integer("number of nodes", 0)
        step.displacement_label = block.string("label")
        step.displacement = _read_node_rows(block, n, 6, "displacement")
    elif name == "NODAL.SCALAR":
        k = block.integer("number of scalars", 0)
        step.nodal_scalar_names = [block.string("scalar name") for _ in range(k)]
    elif name == "NODAL.SCALAR.DATA":
        n = block.integer("number of nodes", 0)
        k = len(step.nodal_scalar_names)
        step.nodal_scalars = _read_node_rows(block, n, k, "scalar")
    elif name == "ELEMENT.GAUSS.SCALAR":
        k = block.integer("number of scalars", 0)
        step.gauss_scalar_names = [block.string("scalar name") for _ in range(k)]
    elif name == "ELEMENT.GAUSS.SCALAR.DATA":
        n = block.integer("number of elements", 0)
        k = len(step.gauss_scalar_names)
        values = None
        for i in range(n):
            block.expect_id(i + 1, "element id")
            points = block.integer("number of points", 1)
            if values is None:
                values = np.empty((n, points, k))
            elif points != values.shape[1]:
                raise block.error(f"element {i + 1}: {points} points, element 1 has {values.shape[1]}")
            for p in range(points):
                values[i, p] = [block.real("Gauss scalar") for _ in range(k)]
        step.gauss_scalars = values if values is not None else np.zeros((0, 0, k))
    else:
        model.ignored_blocks.append(block.tag)
        block.position = len(block.tokens)


def _check_consistency(path, model):
    n_nodes, n_bricks = len(model.coords), len(model.bricks)
    problems = []
    if model.n_nodes_declared is not None and model.n_nodes_declared != n_nodes:
        problems.append(f"%NODE says {model.n_nodes_declared} nodes, %NODE.COORD has {n_nodes}")
    if model.n_elements_declared is not None and model.n_elements_declared != n_bricks:
        problems.append(f"%ELEMENT says {model.n_elements_declared} elements, %ELEMENT.BRICK8 has {n_bricks}")
    if n_bricks and model.bricks.max() > n_nodes:
        problems.append(f"a brick refers to node {model.bricks.max()} > {n_nodes} nodes")
    if n_bricks and len(model.materials) and model.brick_material.max() > len(model.materials):
        problems.append(f"a brick refers to material {model.brick_material.max()} > {len(model.materials)}")
    if len(model.case_step_labels) != len(model.steps):
        problems.append(f"%RESULT.CASE lists {len(model.case_step_labels)} steps, the file has {len(model.steps)}")
    for step in model.steps:
        if step.factor is None:
            problems.append(f"step {step.id}: no FACTOR")
        if step.displacement is not None and len(step.displacement) != n_nodes:
            problems.append(f"step {step.id}: displacement of {len(step.displacement)} nodes")
        if step.nodal_scalars is not None and len(step.nodal_scalars) != n_nodes:
            problems.append(f"step {step.id}: nodal scalars of {len(step.nodal_scalars)} nodes")
        if step.gauss_scalars is not None and len(step.gauss_scalars) != n_bricks:
            problems.append(f"step {step.id}: Gauss scalars of {len(step.gauss_scalars)} elements")
    if problems:
        raise Pos3dError(f"{path}: " + "; ".join(problems))


def _trilinear_jacobians(coords, bricks, signs, points):
    """det J at each natural point (rows of `points`) of each brick, its nodes at natural
    coordinates `signs`: x(xi) = sum_a N_a(xi) x_a, N_a = prod_i (1 + s_ai xi_i) / 8."""
    x = coords[bricks - 1]                       # (n_bricks, 8, 3)
    dets = np.empty((len(bricks), len(points)))
    for q, xi in enumerate(points):
        factors = 1.0 + signs * xi               # (8, 3)
        dn = np.empty((8, 3))
        for i in range(3):
            others = [j for j in range(3) if j != i]
            dn[:, i] = signs[:, i] * factors[:, others[0]] * factors[:, others[1]] / 8.0
        jacobian = np.einsum("eai,aj->eij", x, dn)   # dx_i / dxi_j
        dets[:, q] = np.linalg.det(jacobian)
    return dets


def brick_volumes(model, convention="tecgraf"):
    """Volume of each brick by 2x2x2 Gauss quadrature of det J (exact for trilinear bricks),
    reading the node list with `convention` "tecgraf" (nodes 1-4 on t = +1) or "vtk" (nodes
    1-4 on zeta = -1). A right-handed (r, s, t) gives positive volume; reading a brick with
    the wrong convention mirrors it in t and gives the negative volume."""
    signs = TECGRAF_BRICK8_SIGNS if convention == "tecgraf" else VTK_HEXAHEDRON_SIGNS
    points = VTK_HEXAHEDRON_SIGNS / np.sqrt(3.0)
    return _trilinear_jacobians(model.coords, model.bricks, signs, points).sum(axis=1)


def gauss_point_positions(model):
    """(n_bricks, 8, 3) reference positions of the Gauss points, point k at
    TECGRAF_BRICK8_SIGNS[k] / sqrt(3) (frix's point order in the file)."""
    points = TECGRAF_BRICK8_SIGNS / np.sqrt(3.0)
    shape = np.prod(1.0 + points[:, None, :] * TECGRAF_BRICK8_SIGNS[None, :, :], axis=2) / 8.0  # (point, node)
    return np.einsum("pa,eai->epi", shape, model.coords[model.bricks - 1])


def summary(model):
    lines = [f"title: {model.title}",
             f"nodes: {len(model.coords)}", f"bricks: {len(model.bricks)}",
             f"materials: {len(model.materials)}", f"steps: {len(model.steps)}"]
    if len(model.coords):
        lo, hi = model.coords.min(axis=0), model.coords.max(axis=0)
        lines.append("coordinate range: " + "  ".join(f"{a}: [{l:.6g}, {h:.6g}]" for a, l, h in zip("xyz", lo, hi)))
    for i, (e, nu) in enumerate(model.materials, start=1):
        lines.append(f"material {i}: E = {e:.6g}, nu = {nu:.6g}, bricks: {int(np.sum(model.brick_material == i))}")
    if len(model.bricks):
        volumes = brick_volumes(model)
        lines.append(f"brick volumes (Tecgraf order): min {volumes.min():.6g}, max {volumes.max():.6g}, "
                     f"total {volumes.sum():.6g}")
    for step in model.steps:
        lines.append(f"step {step.id} '{step.label}': factor {step.factor:.6g}")
        if step.displacement is not None and len(step.displacement):
            u = step.displacement[:, :3]
            lines.append("  displacement range: " + "  ".join(
                f"{a}: [{l:.6g}, {h:.6g}]" for a, l, h in zip("uvw", u.min(axis=0), u.max(axis=0))))
        for k, name in enumerate(step.nodal_scalar_names):
            if step.nodal_scalars is not None and len(step.nodal_scalars):
                column = step.nodal_scalars[:, k]
                lines.append(f"  nodal {name}: [{column.min():.6g}, {column.max():.6g}]")
        for k, name in enumerate(step.gauss_scalar_names):
            if step.gauss_scalars is not None and step.gauss_scalars.size:
                values = step.gauss_scalars[:, :, k]
                lines.append(f"  gauss {name}: [{values.min():.6g}, {values.max():.6g}]")
    if model.ignored_blocks:
        lines.append("ignored blocks: " + ", ".join(sorted(set(model.ignored_blocks))))
    return "\n".join(lines)


def main(argv=None):
    parser = argparse.ArgumentParser(
        description="Read a POS3D neutral file (Tecgraf) written by frix and check its structure.")
    parser.add_argument("file", help="the neutral file, e.g. results/s1.pos")
    parser.add_argument("--summary", action="store_true", help="print counts and value ranges")
    arguments = parser.parse_args(argv)
    try:
        model = read_pos3d(arguments.file)
    except Pos3dError as exc:
        print(f"pos3d_reader: error: {exc}", file=sys.stderr)
        return 1
    if arguments.summary:
        print(summary(model))
    else:
        print(f"{arguments.file}: {len(model.coords)} nodes, {len(model.bricks)} bricks, {len(model.steps)} steps")
    return 0


if __name__ == "__main__":
    sys.exit(main())
