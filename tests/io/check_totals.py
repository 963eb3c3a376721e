#!/usr/bin/env python3
"""Check history columns of a run against closed forms in the pseudo time t.

usage: check_totals.py BASE LABEL=EXPRESSION[@TOL] ...

BASE is the run's result prefix (BASE_history.csv, BASE_listing.txt, BASE.h5). Each
LABEL=EXPRESSION names a history column (docs/output.md) and its expected value, a Python
expression in t (min, max, abs allowed), e.g. 'r3_sum_bar_zmax=5*t'. TOL is the error
allowed relative to the largest expected magnitude of the column, 1 when it is 0
(default 1e-10). The
column is checked in every row of the CSV history, in every TOTALS block of the listing
(at most 5e-10 relative more: the listing's 10 digits) and in every increment of the HDF5
file (group history_columns); a file that is not there is skipped, the CSV must be.
Exit 0 if every value holds, 1 otherwise; prints the largest relative error per column.
"""
import os
import sys

import numpy as np


def parse_expectations(arguments):
    expectations = []
    for argument in arguments:
        label, expression = argument.split('=', 1)
        tolerance = 1e-10
        if '@' in expression:
            expression, text = expression.rsplit('@', 1)
            tolerance = float(text)
        expectations.append((label, expression, tolerance))
    return expectations


def expected(expression, t):
    return float(eval(expression, {'__builtins__': {}, 'min': min, 'max': max, 'abs': abs}, {'t': t}))


def csv_rows(base):
    data = np.genfromtxt(base + '_history.csv', delimiter=',', names=True)
    data = np.atleast_1d(data)
    return [(float(row['time']), {name: float(row[name]) for name in data.dtype.names}) for row in data]


def listing_rows(base):
    path = base + '_listing.txt'
    if not os.path.exists(path):
        return None
    rows, time, block = [], None, None
    with open(path) as listing:
        for line in listing:
            if line.startswith('STEP '):
                time = float(line.split()[5])
                block = None
            elif line.startswith('TOTALS'):
                block = {}
                rows.append((time, block))
            elif line.startswith(' ') and block is not None:
                label, value = line.split()
                block[label] = float(value)
            elif not line.startswith(' '):
                block = None
    return rows


def hdf5_rows(base):
    path = base + '.h5'
    if not os.path.exists(path):
        return None
    import h5py
    rows = []
    with h5py.File(path, 'r') as f:
        for name in sorted(f['increments']):
            group = f['increments'][name]
            columns = group['history_columns']
            rows.append((float(group.attrs['time']), {k: float(columns[k][0]) for k in columns}))
    return rows


def check(source, rows, expectations, extra):
    failed = False
    if not rows:
        print(f'FAIL {source}: no rows')
        return True
    for label, expression, tolerance in expectations:
        scale = max(abs(expected(expression, t)) for t, _ in rows) or 1.0
        worst = 0.0
        for t, values in rows:
            if label not in values:
                print(f'FAIL {source}: no column {label} at t = {t}')
                return True
            error = abs(values[label] - expected(expression, t)) / scale
            worst = max(worst, error)
            if error > tolerance + extra:
                print(f'FAIL {source}: {label} = {values[label]!r} at t = {t}, expected {expected(expression, t)!r}')
                failed = True
        print(f'{source}: {label}: {len(rows)} rows, largest relative error {worst:.2e} (allowed {tolerance + extra:.0e})')
    return failed


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    base = sys.argv[1]
    expectations = parse_expectations(sys.argv[2:])
    failed = check('csv', csv_rows(base), expectations, 0.0)
    listing = listing_rows(base)
    if listing is not None:
        failed |= check('listing', listing, expectations, 5e-10)
    hdf5 = hdf5_rows(base)
    if hdf5 is not None:
        failed |= check('hdf5', hdf5, expectations, 0.0)
    print('FAIL' if failed else 'PASS')
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
