#!/bin/bash
# Run the HDF5 round-trip program, then check with h5py that the file it leaves
# (hdf5_roundtrip.h5) follows docs/hdf5-layout.md: names, shapes, dtypes, attributes, and
# every value against the closed formulas documented in tests/hdf5/hdf5_roundtrip_suite.f90
# (recomputed here in numpy; one correctly rounded division each, so compared bitwise).
# Also runs postproc/h5_results.py on the file (list, dump) as a smoke test.
# Usage: h5py_layout_test.sh <path of the hdf5_roundtrip_check executable>
# Exit 0 if all checks pass, 1 if one fails, 2 on usage errors.
set -u
if [ $# -ne 1 ] || [ ! -x "$1" ]; then
    echo "usage: $0 <path of the hdf5_roundtrip_check executable>" >&2
    exit 2
fi
program=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
here=$(cd "$(dirname "$0")" && pwd)
reader=$here/../../postproc/h5_results.py
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if ! (cd "$work" && FRIX_TEST_OUTPUT_DIR="$work" "$program" > "$work/program.log" 2>&1); then
    cat "$work/program.log"
    echo "FAIL: hdf5_roundtrip_check itself failed" >&2
    exit 1
fi
/usr/bin/python3 - "$work/hdf5_roundtrip.h5" "$reader" <<'PYTHON'
import subprocess
import sys
import h5py
import numpy as np

path, reader = sys.argv[1], sys.argv[2]
failures = []
checks = 0

def check(condition, message):
    global checks
    checks += 1
    if not condition:
        failures.append(message)

def same(name, actual, expected):
    """Shape, and values bitwise (array_equal)."""
    actual = np.asarray(actual)
    expected = np.asarray(expected)
    check(actual.shape == expected.shape, f"{name}: shape {actual.shape}, expected {expected.shape}")
    if actual.shape == expected.shape:
        check(np.array_equal(actual, expected), f"{name}: values differ, max |diff| "
              f"{np.max(np.abs(actual.astype(float) - expected.astype(float))) if actual.size else 0}")

def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)

n_nodes, n_elements, n_points, max_eas, n_state, n_slaves = 12, 2, 8, 5, 2, 4
i = np.arange(1, n_nodes + 1)            # node, 1-based
c = np.arange(1, 4)
v = np.arange(1, 7)
p = np.arange(1, n_points + 1)
e = np.arange(1, n_elements + 1)

def nodal(k, divisor):                  # h5py shape (n_nodes, 3)
    return (1e6 * k + 1e4 * c[None, :] + i[:, None]) / divisor

def point_field(k, n_a, divisor):       # h5py shape (n_elements, n_points, n_a)
    a = np.arange(1, n_a + 1)
    return (1e6 * k + 1e4 * a[None, None, :] + 100 * p[None, :, None] + e[:, None, None]) / divisor

with h5py.File(path, "r") as f:
    # root attributes
    check(text(f.attrs.get("frix_version", b"")) == "0.1.0", "frix_version attribute")
    check(text(f.attrs.get("deck_path", b"")) == "tests/hdf5/none.dck", "deck_path attribute")
    check(text(f.attrs.get("title", b"")) == "roundtrip test\nsecond title line", "title attribute")
    check(int(f.attrs.get("layout_version", -1)) == 1, "layout_version attribute")
    check(set(f.keys()) == {"mesh", "increments"}, f"root groups {sorted(f.keys())}")

    # mesh (values from two_element_mesh in the suite)
    m = f["mesh"]
    x = np.array([[(k - 1) % 3, ((k - 1) // 3) % 2, (k - 1) // 6] for k in i], dtype=float)
    same("mesh/coordinates", m["coordinates"][()], x)
    check(m["coordinates"].dtype == np.float64, "coordinates dtype")
    same("mesh/node_ids", m["node_ids"][()], 100 + i)
    same("mesh/connectivity", m["connectivity"][()],
         [[1, 2, 5, 4, 7, 8, 11, 10], [2, 3, 6, 5, 8, 9, 12, 11]])
    check(m["connectivity"].dtype == np.int32, "connectivity dtype")
    same("mesh/element_ids", m["element_ids"][()], [7, 9])
    same("mesh/element_block", m["element_block"][()], [1, 2])
    check(set(m["node_sets"].keys()) == {"FIXED", "empty set"}, f"node sets {list(m['node_sets'].keys())}")
    same("mesh/node_sets/FIXED", m["node_sets/FIXED"][()], [1, 4, 7, 10])
    same("mesh/node_sets/empty set", m["node_sets/empty set"][()], np.zeros(0, dtype=np.int32))
    same("mesh/element_sets/RIGHT", m["element_sets/RIGHT"][()], [2])
    same("mesh/surfaces/TOP/elements", m["surfaces/TOP/elements"][()], [1, 2])
    same("mesh/surfaces/TOP/faces", m["surfaces/TOP/faces"][()], [2, 2])
    same("mesh/surfaces/END/elements", m["surfaces/END/elements"][()], [2])
    same("mesh/surfaces/END/faces", m["surfaces/END/faces"][()], [4])

    # increments
    names = list(f["increments"].keys())
    check(names == ["000001", "000002", "000003"], f"increment groups {names}")
    expected_keys = {"displacement", "reaction", "stress", "strain", "alpha", "history"}
    for k, (step, increment) in enumerate([(1, 1), (1, 2), (2, 1)], start=1):
        name = f"{k:06d}"
        if name not in f["increments"]:
            continue
        g = f["increments"][name]
        check(int(g.attrs["step"]) == step and int(g.attrs["increment"]) == increment,
              f"{name}: step/increment attributes")
        check(g.attrs["time"] == k / 3.0, f"{name}: time {g.attrs['time']} != {k}/3")
        check(int(g.attrs.get("complete", 0)) == 1, f"{name}: complete attribute")
        keys = set(g.keys())
        check(keys == (expected_keys | {"contact"} if k == 3 else expected_keys), f"{name}: datasets {sorted(keys)}")
        same(f"{name}/displacement", g["displacement"][()], nodal(k, 3.0))
        same(f"{name}/reaction", g["reaction"][()], nodal(k, -7.0))
        same(f"{name}/stress", g["stress"][()], point_field(k, 6, 3.0))
        same(f"{name}/strain", g["strain"][()], point_field(k, 6, 11.0))
        j = np.arange(1, max_eas + 1)
        same(f"{name}/alpha", g["alpha"][()], (1e6 * k + 100 * j[None, :] + e[:, None]) / 13.0)
        same(f"{name}/history", g["history"][()], point_field(k, n_state, 17.0))
    contact = f["increments/000003/contact"]
    n = np.arange(1, n_slaves + 1)
    same("contact/gap", contact["gap"][()], -n / 9.0)
    same("contact/traction", contact["traction"][()], (10 * c[None, :] + n[:, None]) / 9.0)
    same("contact/status", contact["status"][()], n % 2)
    check(contact["status"].dtype == np.int32, "contact/status dtype")

# the inspector CLI
def run(*arguments):
    return subprocess.run(["/usr/bin/python3", reader, *arguments], capture_output=True, text=True)

result = run("--help")
check(result.returncode == 0 and "list" in result.stdout and "dump" in result.stdout, "h5_results.py --help")
result = run("list", path)
rows = [line.split() for line in result.stdout.splitlines() if line.strip() and not line.startswith("#")]
check(result.returncode == 0 and len(rows) == 3, f"h5_results.py list: {result.stdout!r} {result.stderr!r}")
if len(rows) == 3:
    check([r[:3] for r in rows] == [["000001", "1", "1"], ["000002", "1", "2"], ["000003", "2", "1"]],
          f"h5_results.py list rows {rows}")
result = run("dump", path, "displacement", "--step", "1", "--increment", "2")
if result.returncode == 0:
    values = np.loadtxt(result.stdout.splitlines(), ndmin=2)
    same("h5_results.py dump displacement", values, nodal(2, 3.0))
else:
    check(False, f"h5_results.py dump failed: {result.stderr}")
result = run("dump", path, "contact/traction", "--number", "3")
if result.returncode == 0:
    values = np.loadtxt(result.stdout.splitlines(), ndmin=2)
    same("h5_results.py dump contact/traction", values, (10 * c[None, :] + n[:, None]) / 9.0)
else:
    check(False, f"h5_results.py dump contact failed: {result.stderr}")
result = run("dump", path, "displacement", "--step", "7", "--increment", "1")
check(result.returncode != 0 and "1/1 1/2 2/1" in result.stderr, f"h5_results.py wrong step: {result.stderr!r}")

for message in failures:
    print("FAIL:", message)
print(f"{checks - len(failures)} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
PYTHON
