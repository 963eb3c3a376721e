#!/bin/bash
# Read back the .pvd/.vtu files written by the io unit suite `vtk_writer` with meshio and
# compare every array with values recomputed here from the formulas documented in
# tests/unit/io/test_vtk_writer.f90 (write_two_increments) and test_io_fixtures.f90.
# Usage: vtk_readback_test.sh <path of the test_io executable>
# Exit 0 if all checks pass, 1 if one fails, 2 on usage errors.
set -u
if [ $# -ne 1 ] || [ ! -x "$1" ]; then
    echo "usage: $0 <path of the test_io executable>" >&2
    exit 2
fi
test_io=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if ! FRIX_TEST_OUTPUT_DIR="$work" "$test_io" vtk_writer > "$work/unit.log"; then
    cat "$work/unit.log"
    echo "FAIL: the vtk_writer suite itself failed" >&2
    exit 1
fi
/usr/bin/python3 - "$work" <<'PYTHON'
import sys, os
import xml.etree.ElementTree as ElementTree
import numpy as np
import meshio

folder = sys.argv[1]
failures = []

def check(condition, message):
    if not condition:
        failures.append(message)

def close(actual, expected, message, rel=1e-14):
    # 17 written digits round-trip binary64; the only error left is the recovery's round-off
    # (a few ulp of the largest entry), hence rel 1e-14 of the array's largest |value|.
    actual = np.asarray(actual, dtype=float)
    expected = np.asarray(expected, dtype=float)
    if actual.shape != expected.shape:
        failures.append(f"{message}: shape {actual.shape}, expected {expected.shape}")
        return
    scale = max(np.max(np.abs(expected)), 1e-300)
    worst = np.max(np.abs(actual - expected))
    if not worst <= rel * scale:
        failures.append(f"{message}: worst deviation {worst:.3e} > {rel * scale:.3e}")

def von_mises(s):  # frix Voigt order xx yy zz xy xz yz, tensor shears
    return np.sqrt(0.5 * ((s[:, 0] - s[:, 1])**2 + (s[:, 1] - s[:, 2])**2 + (s[:, 2] - s[:, 0])**2)
                   + 3.0 * (s[:, 3]**2 + s[:, 4]**2 + s[:, 5]**2))

def to_vtk_order(voigt, shear_factor):  # xx yy zz xy xz yz -> XX YY ZZ XY YZ XZ
    return np.column_stack([voigt[:, 0], voigt[:, 1], voigt[:, 2], shear_factor * voigt[:, 3],
                            shear_factor * voigt[:, 5], shear_factor * voigt[:, 4]])

# The fixture mesh: node i (1-based) at (mod(i-1,3), mod((i-1)/3,2), (i-1)/6).
index = np.arange(12)
points = np.column_stack([index % 3, (index // 3) % 2, index // 6]).astype(float)
connectivity = np.array([[1, 2, 5, 4, 7, 8, 11, 10], [2, 3, 6, 5, 8, 9, 12, 11]]) - 1
base = np.array([1.0, 2.0, 3.0, 4.0, 5.0, 6.0])

pvd = ElementTree.parse(os.path.join(folder, "vtk_two_elements.pvd")).getroot()
datasets = pvd.findall("./Collection/DataSet")
check(pvd.get("type") == "Collection", "pvd type is Collection")
check([float(d.get("timestep")) for d in datasets] == [0.5, 1.0], "pvd timesteps 0.5, 1.0")
check([d.get("file") for d in datasets] == ["vtk_two_elements_0001_0001.vtu", "vtk_two_elements_0001_0002.vtu"],
      "pvd file names")

for k, dataset in enumerate(datasets, start=1):
    mesh = meshio.read(os.path.join(folder, dataset.get("file")))
    tag = f"increment {k}: "
    close(mesh.points, points, tag + "points")
    check(len(mesh.cells) == 1 and mesh.cells[0].type == "hexahedron", tag + "one block of hexahedra")
    check(np.array_equal(mesh.cells[0].data, connectivity), tag + "connectivity (0-based, VTK order)")
    x, y, z = points.T
    close(mesh.point_data["displacement"], k * np.column_stack([1e-3 * x, -2e-3 * y, 3e-3 * z + 1e-4 * x]),
          tag + "displacement")
    reaction = np.zeros((12, 3)); reaction[0, 0] = k
    close(mesh.point_data["reaction"], reaction, tag + "reaction")
    # Element e has stress k e base 1e3 at every point; a node gets the mean over its elements.
    in_element = np.zeros((12, 2))
    for e in range(2):
        in_element[connectivity[e], e] = 1.0
    node_factor = (in_element @ np.array([1.0, 2.0])) / in_element.sum(axis=1)
    node_stress = k * np.outer(node_factor, base) * 1e3
    node_strain = k * np.outer(node_factor, base) * 1e-3
    close(mesh.point_data["stress"], to_vtk_order(node_stress, 1.0), tag + "point stress (VTK order)")
    close(mesh.point_data["strain"], to_vtk_order(node_strain, 0.5), tag + "point strain (tensor shears)")
    close(mesh.point_data["von_mises"].ravel(), von_mises(node_stress), tag + "point von_mises")
    cell_stress = k * np.outer([1.0, 2.0], base) * 1e3
    cell_strain = k * np.outer([1.0, 2.0], base) * 1e-3
    close(mesh.cell_data["stress"][0], to_vtk_order(cell_stress, 1.0), tag + "cell stress")
    close(mesh.cell_data["strain"][0], to_vtk_order(cell_strain, 0.5), tag + "cell strain")
    close(mesh.cell_data["von_mises"][0].ravel(), von_mises(cell_stress), tag + "cell von_mises")
    check(list(mesh.cell_data["element_id"][0]) == [7, 9], tag + "element ids")
    check(list(mesh.cell_data["block"][0]) == [1, 2], tag + "blocks")
    close(mesh.field_data["TimeValue"], [0.5 * k], tag + "TimeValue")
    if k == 1:
        close(mesh.point_data["contact_pressure"].ravel(), x, tag + "extra point field")
        close(mesh.cell_data["cell_marker"][0].ravel(), [10.0, 20.0], tag + "extra cell field")
    else:
        check("contact_pressure" not in mesh.point_data, tag + "extra point field dropped")
        check("cell_marker" not in mesh.cell_data, tag + "extra cell field dropped")

for failure in failures:
    print("FAIL:", failure)
print(f"vtk readback: {len(failures)} failed checks")
sys.exit(1 if failures else 0)
PYTHON
