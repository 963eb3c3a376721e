#!/usr/bin/env python3
"""Runs contact decks with two frix binaries and compares what they produce.

    bench/contact_equivalence.py --old OLD_FRIX --new NEW_FRIX [--timeout S] [--csv OUT] DECK ...

For every deck: both runs' exit status, Newton iterations, assemblies and assembly times
(`frix: stat`), and for every CSV file both runs wrote (history, contact) the largest
difference of a column relative to the largest magnitude of its quantity in the old run
(the components of a vector share one scale). Used to
check that a change of the contact kernel's implementation leaves the answers as they were
(docs/performance-contact.md). Error decks (`tests/errors`) are skipped. Exit 1 if a deck's
exit status or iteration count differs, or a run passed the time limit (exit status None).
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile
import time


def run(frix, deck, out, timeout):
    start = time.monotonic()
    try:
        proc = subprocess.run([frix, deck, '--out', out], capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, {}, time.monotonic() - start
    stats = dict(re.findall(r'^frix: stat (\S+)\s+(\S+)', proc.stdout, re.M))
    return proc.returncode, stats, time.monotonic() - start


def read_columns(path):
    with open(path, newline='') as handle:
        rows = list(csv.reader(handle))
    if not rows:
        return {}
    columns = {}
    for j, name in enumerate(rows[0]):
        values = []
        for row in rows[1:]:
            try:
                values.append(float(row[j]))
            except (ValueError, IndexError):
                values = None
                break
        if values is not None:
            columns[name] = values
    return columns


def quantity(name):
    """The quantity a column holds: its name up to the first digit or '_' (the components of
    one vector, traction_x/y/z, u1_n6/u3_n8, share it)."""
    return re.match(r'[A-Za-z]*', name).group(0)


def csv_difference(old_path, new_path):
    """Largest column difference relative to the largest magnitude of the column's quantity in
    the old run (so that a component that is zero to round-off, such as normal_y on a symmetry
    plane, is measured against its vector), and the column; or a reason they cannot be
    compared."""
    old, new = read_columns(old_path), read_columns(new_path)
    if old.keys() != new.keys():
        return math.inf, 'columns differ'
    scales = {}
    for name, values in old.items():
        key = quantity(name)
        scales[key] = max(scales.get(key, 0.0), max((abs(v) for v in values), default=0.0))
    worst, where = 0.0, ''
    for name, values in old.items():
        if len(values) != len(new[name]):
            return math.inf, 'rows differ'
        scale = scales[quantity(name)] or 1.0
        diff = max((abs(a - b) for a, b in zip(values, new[name])), default=0.0) / scale
        if diff > worst:
            worst, where = diff, name
    return worst, where


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--old', required=True)
    parser.add_argument('--new', required=True)
    parser.add_argument('--timeout', type=float, default=600.0)
    parser.add_argument('--csv', help='write the table as CSV here')
    parser.add_argument('decks', nargs='+')
    args = parser.parse_args()
    rows = []
    mismatches = 0
    header = ('deck', 'exit_old', 'exit_new', 'iterations_old', 'iterations_new', 'assemblies_old',
              'assemblies_new', 'contact_seconds_old', 'contact_seconds_new', 'wall_old', 'wall_new',
              'max_relative_difference', 'where')
    print(' '.join(header))
    for deck in args.decks:
        if '/errors/' in deck:
            continue
        with tempfile.TemporaryDirectory() as work:
            out_old, out_new = os.path.join(work, 'old'), os.path.join(work, 'new')
            code_old, stats_old, wall_old = run(args.old, deck, out_old, args.timeout)
            code_new, stats_new, wall_new = run(args.new, deck, out_new, args.timeout)
            worst, where = 0.0, ''
            names = sorted(f for f in os.listdir(out_old) if f.endswith('.csv')) if os.path.isdir(out_old) else []
            for name in names:
                if not os.path.exists(os.path.join(out_new, name)):
                    worst, where = math.inf, name + ' missing'
                    break
                diff, column = csv_difference(os.path.join(out_old, name), os.path.join(out_new, name))
                if diff > worst:
                    worst, where = diff, name.rsplit('_', 1)[-1] + ':' + column
        iterations = (stats_old.get('newton_iterations', '-'), stats_new.get('newton_iterations', '-'))
        if code_old is None or code_new is None or code_old != code_new or iterations[0] != iterations[1]:
            mismatches += 1   # a run past the time limit is not compared: counted too
        row = (deck, code_old, code_new, iterations[0], iterations[1], stats_old.get('assemblies', '-'),
               stats_new.get('assemblies', '-'),
               stats_old.get('contact_seconds', stats_old.get('assembly_seconds', '-')),
               stats_new.get('contact_seconds', '-'), f'{wall_old:.2f}', f'{wall_new:.2f}', f'{worst:.2e}', where)
        rows.append(row)
        print(' '.join(str(v) for v in row), flush=True)
    if args.csv:
        with open(args.csv, 'w', newline='') as handle:
            writer = csv.writer(handle)
            writer.writerow(header)
            writer.writerows(rows)
    print(f'{len(rows)} decks, {mismatches} with another exit status or iteration count or past the time limit')
    return 1 if mismatches else 0


if __name__ == '__main__':
    sys.exit(main())
