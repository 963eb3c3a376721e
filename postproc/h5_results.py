#!/usr/bin/python3
"""Inspect a frix HDF5 results file (layout: docs/hdf5-layout.md).

Commands:
  info FILE                  root attributes, mesh sizes, sets and surfaces
  list FILE                  one row per increment: group, step, increment, time, datasets
  dump FILE FIELD [select]   print one dataset as text (numpy.savetxt, 17 significant digits)

FIELD is a dataset of an increment group ('displacement', 'stress', 'contact/gap', ...) or
an absolute path ('/mesh/coordinates', '/mesh/node_sets/FIXED'). An increment is selected
by --step S --increment K, by its running number --number N (the group name 00000N), or
--last (default). Arrays of rank 3 (element, point, component) are printed one row per
(element, point), element-major; --indices prepends 1-based index columns.

Run with /usr/bin/python3 (Debian's h5py and numpy).
"""
import argparse
import sys

import h5py
import numpy as np


def text(value):
    """An attribute as str (frix writes fixed-length byte strings)."""
    if isinstance(value, bytes):
        return value.decode("utf-8", errors="replace")
    if isinstance(value, np.ndarray) and value.shape == ():
        return text(value[()])
    return str(value)


def increments(results, include_incomplete=False):
    """[(group name, step, increment, time, complete)] in the order written."""
    rows = []
    group = results.get("increments")
    if group is None:
        return rows
    for name in sorted(group.keys(), key=lambda n: (len(n), n)):
        attrs = group[name].attrs
        complete = int(attrs.get("complete", 0)) == 1
        if not complete and not include_incomplete:
            continue
        rows.append((name, int(attrs.get("step", -1)), int(attrs.get("increment", -1)),
                     float(attrs.get("time", np.nan)), complete))
    return rows


def select(results, arguments):
    """The increment group chosen by --step/--increment, --number or --last."""
    rows = increments(results)
    available = " ".join(f"{step}/{increment}" for _, step, increment, _, _ in rows) or "none"
    if arguments.number is not None:
        name = f"{arguments.number:06d}"
        matches = [row for row in rows if row[0] == name]
        what = f"running number {arguments.number}"
    elif arguments.step is not None or arguments.increment is not None:
        if arguments.step is None or arguments.increment is None:
            raise SystemExit("h5_results.py: --step and --increment go together")
        matches = [row for row in rows if row[1] == arguments.step and row[2] == arguments.increment]
        what = f"increment {arguments.increment} of step {arguments.step}"
    else:
        matches = rows[-1:]
        what = "any increment"
    if not matches:
        raise SystemExit(f"h5_results.py: {arguments.file} has no {what}; available (step/increment): {available}")
    return results["increments"][matches[-1][0]]


def command_info(results, arguments):
    for key in sorted(results.attrs.keys()):
        value = text(results.attrs[key]).replace("\n", "\n    ")
        print(f"{key}: {value}")
    mesh = results.get("mesh")
    if mesh is not None:
        print(f"nodes: {mesh['coordinates'].shape[0]}")
        print(f"elements: {mesh['connectivity'].shape[0]}")
        for kind in ("node_sets", "element_sets"):
            for name, dataset in mesh.get(kind, {}).items():
                print(f"{kind[:-1].replace('_', ' ')} {name}: {dataset.shape[0]}")
        for name, surface in mesh.get("surfaces", {}).items():
            print(f"surface {name}: {surface['elements'].shape[0]} faces")
    print(f"increments: {len(increments(results))}")


def command_list(results, arguments):
    print("# group    step increment  time                     datasets")
    for name, step, increment, time, complete in increments(results, arguments.all):
        group = results["increments"][name]
        fields = []
        group.visititems(lambda key, item: fields.append(key) if isinstance(item, h5py.Dataset) else None)
        flag = "" if complete else "  (incomplete)"
        print(f"{name:8s} {step:6d} {increment:9d}  {time:<24.17g} {','.join(sorted(fields))}{flag}")


def command_dump(results, arguments):
    if arguments.field.startswith("/"):
        location = results
        path = arguments.field
    else:
        location = select(results, arguments)
        path = arguments.field
        attrs = location.attrs
        print(f"# {location.name}: step {int(attrs['step'])} increment {int(attrs['increment'])} "
              f"time {float(attrs['time']):.17g}")
    if path not in location or not isinstance(location[path], h5py.Dataset):
        names = []
        location.visititems(lambda key, item: names.append(key) if isinstance(item, h5py.Dataset) else None)
        raise SystemExit(f"h5_results.py: no dataset {path} in {location.name}; datasets: {', '.join(names)}")
    values = location[path][()]
    print(f"# {path}: shape {values.shape} (h5py order), dtype {values.dtype}")
    if values.ndim == 0:
        values = values.reshape(1, 1)
    elif values.ndim == 1:
        values = values.reshape(-1, 1)
    elif values.ndim > 2:
        outer = values.shape[:-1]
        values = values.reshape(-1, values.shape[-1])
        if arguments.indices:
            index = np.indices(outer).reshape(len(outer), -1).T + 1
            values = np.hstack([index, values])
    elif arguments.indices:
        values = np.hstack([np.arange(1, values.shape[0] + 1)[:, None], values])
    if np.issubdtype(values.dtype, np.integer):
        np.savetxt(sys.stdout, values, fmt="%d")
    else:
        np.savetxt(sys.stdout, values, fmt="%.17g")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    commands = parser.add_subparsers(dest="command", required=True)
    info = commands.add_parser("info", help="root attributes, mesh sizes, sets")
    info.add_argument("file")
    listing = commands.add_parser("list", help="list the increments")
    listing.add_argument("file")
    listing.add_argument("--all", action="store_true", help="also groups without the 'complete' mark")
    dump = commands.add_parser("dump", help="print one dataset")
    dump.add_argument("file")
    dump.add_argument("field", help="dataset of the increment group, or an absolute path like /mesh/coordinates")
    dump.add_argument("--step", type=int)
    dump.add_argument("--increment", type=int)
    dump.add_argument("--number", type=int, help="running number of the increment group (000001 = 1)")
    dump.add_argument("--last", action="store_true", help="the last increment (the default)")
    dump.add_argument("--indices", action="store_true", help="prepend 1-based index columns")
    arguments = parser.parse_args()
    try:
        results = h5py.File(arguments.file, "r")
    except (OSError, FileNotFoundError) as failure:
        raise SystemExit(f"h5_results.py: cannot open {arguments.file}: {failure}")
    with results:
        {"info": command_info, "list": command_list, "dump": command_dump}[arguments.command](results, arguments)


if __name__ == "__main__":
    main()
