#!/usr/bin/python3
"""Join the results of a run and of its restart into one series (as `abaqus restartjoin`).

`frix DECK --restart FIRST.h5 --from S.I --out DIR` writes a new set of result files holding
only the increments after S.I (docs/hdf5-layout.md, "Restart"). This script writes one series
from the two, JOINED_BASE being a path without extension:

- ``JOINED_BASE_history.csv`` and ``JOINED_BASE_contact.csv``: the first run's rows up to and
  including the restarted increment S.I, then every row of the restart (the two files must
  have the same columns: the same deck);
- ``JOINED_BASE.pvd``: the first run's data sets up to S.I, then the restart's, their .vtu
  files referenced where they are (paths relative to the joined .pvd; nothing is copied);
- ``JOINED_BASE.h5`` (when both runs wrote HDF5): the mesh of the restart's file, the first
  run's complete increment groups up to S.I, then the restart's, renumbered 000001, 000002, ...
  in that order, each keeping its attributes (step, increment, time).

S.I is read from the restart's files: the restart's first row (or data set, or increment
group) follows it, so the first run's rows that come before the restart's first (step,
increment) are kept. Files that one of the runs did not write are skipped with a note.
"""

import os
import sys
import xml.etree.ElementTree as ElementTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import frix_results  # noqa: E402
from frix_results import UserError  # noqa: E402


def build_parser():
    parser = frix_results.ArgumentParser(
        description="Join the result files of a frix run and of its restart (--restart) into "
                    "one series: history and contact CSV, .pvd, HDF5.",
        epilog="Example: join_restart.py out/full/pipe out/restarted/pipe out/joined/pipe")
    parser.add_argument("first", help="base of the first run's files (path without extension, "
                                      "e.g. out/full/pipe for out/full/pipe_history.csv)")
    parser.add_argument("restart", help="base of the restarted run's files")
    parser.add_argument("joined", help="base of the joined files to write")
    return parser


def step_increment(row):
    """(step, increment) of a CSV row whose first two fields are integers."""
    try:
        return int(row[0]), int(row[1])
    except (IndexError, ValueError):
        raise UserError(f"a row without step and increment: {','.join(row)[:60]}") from None


def join_csv(first, restart, joined):
    """The first file's rows before the restart's first (step, increment), then the restart's."""
    with open(first) as handle:
        first_lines = handle.read().splitlines()
    with open(restart) as handle:
        restart_lines = handle.read().splitlines()
    if not first_lines or not restart_lines:
        raise UserError(f"{first if not first_lines else restart}: empty file")
    if first_lines[0] != restart_lines[0]:
        raise UserError(f"{first} and {restart} have different columns (not the same deck?)")
    rows = [line for line in restart_lines[1:] if line.strip()]
    kept = first_lines[1:]
    if rows:
        start = step_increment(rows[0].split(","))
        kept = [line for line in kept if line.strip() and step_increment(line.split(",")) < start]
    with open(joined, "w") as handle:
        handle.write("\n".join([first_lines[0]] + kept + rows) + "\n")
    return len(kept), len(rows)


def pvd_data_sets(path):
    """The .pvd's DataSet elements with their file paths made absolute."""
    try:
        root = ElementTree.parse(path).getroot()
    except ElementTree.ParseError as error:
        raise UserError(f"{path}: not a VTK collection: {error}") from None
    folder = os.path.dirname(os.path.abspath(path))
    data_sets = root.findall("./Collection/DataSet")
    for data_set in data_sets:
        data_set.set("file", os.path.normpath(os.path.join(folder, data_set.get("file", ""))))
    return data_sets


def vtu_step_increment(path):
    """(step, increment) of frix's <base>_SSSS_IIII.vtu."""
    stem = os.path.splitext(os.path.basename(path))[0].split("_")
    try:
        return int(stem[-2]), int(stem[-1])
    except (IndexError, ValueError):
        raise UserError(f"{path}: not a frix .vtu name <base>_SSSS_IIII.vtu") from None


def join_pvd(first, restart, joined):
    restart_sets = pvd_data_sets(restart)
    kept = pvd_data_sets(first)
    if restart_sets:
        start = vtu_step_increment(restart_sets[0].get("file"))
        kept = [d for d in kept if vtu_step_increment(d.get("file")) < start]
    folder = os.path.dirname(os.path.abspath(joined))
    lines = ['<?xml version="1.0"?>',
             '<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">', "<Collection>"]
    for data_set in kept + restart_sets:
        data_set.set("file", os.path.relpath(data_set.get("file"), folder))
        lines.append("<DataSet " + " ".join(f'{key}="{value}"' for key, value in data_set.attrib.items())
                     + "/>")
    lines += ["</Collection>", "</VTKFile>"]
    with open(joined, "w") as handle:
        handle.write("\n".join(lines) + "\n")
    return len(kept), len(restart_sets)


def complete_groups(increments):
    """The complete increment groups in file order, with their (step, increment)."""
    groups = []
    for name in sorted(increments):
        group = increments[name]
        if group.attrs.get("complete", 0) == 1:
            groups.append(((int(group.attrs["step"]), int(group.attrs["increment"])), group))
    return groups


def join_hdf5(first, restart, joined):
    import h5py
    with h5py.File(first, "r") as one, h5py.File(restart, "r") as two, h5py.File(joined, "w") as out:
        for name, item in two.items():
            if name != "increments":
                two.copy(item, out, name)
        for key, value in two.attrs.items():
            out.attrs[key] = value
        restart_groups = complete_groups(two["increments"])
        kept = complete_groups(one["increments"])
        if restart_groups:
            kept = [(key, group) for key, group in kept if key < restart_groups[0][0]]
        increments = out.create_group("increments")
        for number, (_, group) in enumerate(kept + restart_groups, start=1):
            group.file.copy(group, increments, "%06d" % number)
    return len(kept), len(restart_groups)


def main(argv=None):
    args = build_parser().parse_args(argv)
    os.makedirs(os.path.dirname(os.path.abspath(args.joined)), exist_ok=True)
    joiners = (("_history.csv", join_csv), ("_contact.csv", join_csv), (".pvd", join_pvd),
               (".h5", join_hdf5))
    written = 0
    for suffix, join in joiners:
        first, restart, joined = (base + suffix for base in (args.first, args.restart, args.joined))
        missing = [path for path in (first, restart) if not os.path.isfile(path)]
        if missing:
            print(f"{suffix[1:]}: skipped ({' and '.join(missing)} not found)")
            continue
        kept, added = join(first, restart, joined)
        print(f"{joined}: {kept} of the first run, then {added} of the restart")
        written += 1
    if written == 0:
        raise UserError(f"nothing to join: no result file of {args.first} and {args.restart} "
                        "found in pairs")
    return 0


if __name__ == "__main__":
    frix_results.run_main(main)
