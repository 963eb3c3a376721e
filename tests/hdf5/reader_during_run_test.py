#!/usr/bin/env python3
"""A reader that opens the HDF5 results file while frix runs (docs/output.md, "Reading the
HDF5 file during a run").

usage: reader_during_run_test.py FRIX DECK

frix closes the file after every increment. The reader opens it with h5py (read-only, HDF5's
file locking on, the default) while frix is still running, and holds it open:
  1. waiting: frix must wait for the reader (its note "frix: waiting for ...") and, once the
     reader closes the file, finish with exit status 0 and a complete file: every increment,
     the history column equal to the CSV history;
  2. giving up: with FRIX_HDF5_LOCK_WAIT=1 and the reader holding on, frix must stop with exit
     status 1 and the message "cannot reopen results file", not crash; the increments it
     wrote before stay readable.
Made independent of timing: frix is stopped (SIGSTOP) during each attempt to open the file,
so that the reader gets in while frix is between two increments, before the run is over; it
opens and closes the file until 3 increments are there, then holds it. What it sees must be complete increments only
(each group with its `complete` attribute and its arrays).
"""
import os
import signal
import subprocess
import sys
import tempfile
import threading
import time

import h5py
import numpy as np


def start(frix, deck, out, environment):
    process = subprocess.Popen([frix, deck, '--out', out], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               env=environment, text=True)
    lines = []
    reader = threading.Thread(target=lambda: lines.extend(iter(process.stdout.readline, '')), daemon=True)
    reader.start()
    return process, lines, reader


def open_while_running(process, path, at_least, deadline=120.0):
    """Open `path` read-only while frix is stopped, once it holds `at_least` increments (the
    reader opens and closes it until then); None if frix ended first."""
    start_time = time.monotonic()
    while time.monotonic() - start_time < deadline:
        if process.poll() is not None:
            return None
        process.send_signal(signal.SIGSTOP)
        try:
            handle = h5py.File(path, 'r')
        except (OSError, FileNotFoundError):
            handle = None
        finally:
            process.send_signal(signal.SIGCONT)
        if handle is not None:
            if complete_increments(handle) >= at_least:
                return handle
            handle.close()
        time.sleep(0.005)
    return None


def complete_increments(handle):
    """Number of increment groups; fails unless each is complete and readable."""
    groups = handle['increments']
    for name in groups:
        group = groups[name]
        if group.attrs.get('complete') != 1:
            raise AssertionError(f'increment {name} seen without its complete attribute')
        if group['displacement'].shape[1] != 3 or not np.all(np.isfinite(group['displacement'][()])):
            raise AssertionError(f'increment {name}: displacement not readable')
    return len(groups)


def wait_for(predicate, seconds):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(0.01)
    return predicate()


def case_waiting(frix, deck, work, n_total):
    out = os.path.join(work, 'waiting')
    name = os.path.splitext(os.path.basename(deck))[0]
    path = os.path.join(out, name + '.h5')
    process, lines, reader = start(frix, deck, out, dict(os.environ))
    handle = open_while_running(process, path, 3)
    if handle is None:
        process.wait()
        return ['waiting: frix ended before the reader could open the file']
    seen = complete_increments(handle)
    problems = []
    if seen >= n_total:
        problems.append(f'waiting: the reader got in after the last increment ({seen})')
    if not wait_for(lambda: any('frix: waiting for' in line for line in lines), 120.0):
        problems.append('waiting: no "frix: waiting for" note while the reader held the file')
    if process.poll() is not None:
        problems.append(f'waiting: frix ended (status {process.returncode}) while the reader held the file')
    seen_later = complete_increments(handle)   # frix cannot have written meanwhile
    if seen_later != seen:
        problems.append(f'waiting: the increments changed under the reader ({seen} -> {seen_later})')
    handle.close()
    status = process.wait(timeout=300)
    reader.join()
    if status != 0:
        problems.append(f'waiting: frix exit status {status}: ' + ''.join(lines[-5:]))
        return problems
    history = np.genfromtxt(os.path.join(out, name + '_history.csv'), delimiter=',', names=True)
    with h5py.File(path, 'r') as f:
        n = complete_increments(f)
        values = [f['increments'][k]['history_columns']['r3_sum_bar_zmax'][0] for k in sorted(f['increments'])]
    if n != n_total:
        problems.append(f'waiting: {n} increments in the file, expected {n_total}')
    elif not np.array_equal(np.array(values), history['r3_sum_bar_zmax']):
        problems.append('waiting: the HDF5 history column differs from the CSV history')
    print(f'waiting: reader opened the file at {seen} of {n_total} increments; frix waited, then finished with '
          f'{n} increments')
    return problems


def case_giving_up(frix, deck, work, n_total):
    out = os.path.join(work, 'giving_up')
    name = os.path.splitext(os.path.basename(deck))[0]
    path = os.path.join(out, name + '.h5')
    environment = dict(os.environ, FRIX_HDF5_LOCK_WAIT='1')
    process, lines, reader = start(frix, deck, out, environment)
    handle = open_while_running(process, path, 3)
    if handle is None:
        process.wait()
        return ['giving up: frix ended before the reader could open the file']
    seen = complete_increments(handle)
    status = process.wait(timeout=300)   # the reader holds on
    reader.join()
    handle.close()
    text = ''.join(lines)
    problems = []
    if seen >= n_total:
        problems.append(f'giving up: the reader got in after the last increment ({seen})')
    if status != 1:
        problems.append(f'giving up: frix exit status {status}, expected 1')
    if 'cannot reopen results file' not in text:
        problems.append('giving up: no "cannot reopen results file" message: ' + text[-500:])
    for bad in ('Fortran runtime error', 'Backtrace', 'SIGSEGV', 'HDF5-DIAG'):
        if bad in text:
            problems.append(f'giving up: "{bad}" in the output')
    with h5py.File(path, 'r') as f:
        n = complete_increments(f)
    if n != seen:
        problems.append(f'giving up: {n} increments in the file after the stop, expected the {seen} seen')
    print(f'giving up: reader opened the file at {seen} of {n_total} increments; frix stopped with status {status}, '
          f'the file keeps {n} increments')
    return problems


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    frix, deck = sys.argv[1], os.path.abspath(sys.argv[2])
    n_total = 12   # the deck's NUMSTEP
    with tempfile.TemporaryDirectory() as work:
        problems = case_waiting(frix, deck, work, n_total) + case_giving_up(frix, deck, work, n_total)
    for problem in problems:
        print('FAIL ' + problem)
    print('FAIL' if problems else 'PASS')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
