#!/usr/bin/env python3
"""Deterministic fuzzer of frix's input: mutated decks and gmsh meshes run through frix.

    python3 tests/fuzz/fuzz_decks.py --frix build/frix [--seed 1] [--count 300] [--jobs 2]
                                     [--failures-dir DIR] [--only N[,N...]] [--timeout 30]

Every mutant is a copy of a small base deck (and of its gmsh mesh, written beside the mutant
deck, the deck's FILE line pointing at it) with 1-3 mutations: deleted, duplicated, swapped or
truncated lines, a number turned into NaN, Inf, 1e308, 1e400, 0, -1, 2147483648, text, ...,
junk bytes, a repeated deck section or gmsh $Section block. Mutant N of seed S depends on
(S, N) only, so `--seed S --only N` rebuilds it. frix is run on every mutant, `--check` first
and then for real (`--quiet --out DIR`), each under a timeout, and must:
  - not die by a signal, not hang, exit with 0 or 1 (2 is for command-line errors only),
  - print no crash report (Fortran runtime error, backtrace, sanitizer report, ...),
  - when the deck is rejected (`--check` exits 1), name the place: `deck.dck:LINE:COL: error:`
    entries and the closing `deck.dck: N error(s) in the deck`, the same in the real run,
  - when the analysis fails after the deck was accepted, say something (exit 1, not silently)
    and not reject the deck that --check accepted,
  - when it exits 0, write no NaN, Inf or overflowed field (`*****`, `2.5+307`) into any
    result file (.vtu, .pvd, .csv, listing, .pos; .h5 with h5py when it is available).
With --fail-writes LIB (tests/io/fail_writes.c, built as libfrix_fail_writes.so) and
--faults N, N runs of the unmutated base decks follow, each with LIB preloaded so that the
writes into one result file (or into any) fail with ENOSPC after a random number of bytes, as
on a full disk. Fault run N of seed S depends on (S, N) only (`--only-fault N`). Each must:
  - not die by a signal, exit with 0 or 1, print no crash report,
  - when a write was refused: exit 1 with a message `cannot ...` (`HDF5: cannot ...`) naming
    a file of the run, no success line (`converged increments; results in`), no `.tmp` file
    left; when none was: exit 0.
A failing mutant is copied into --failures-dir with MUTATION.txt (a one-line description),
frix's stdout and stderr, and a reproduce command is printed. Exit status 1 if any mutant
failed, 0 otherwise. See tests/fuzz/README.md.
"""
import argparse
import concurrent.futures
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

HERE = os.path.dirname(os.path.realpath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

# Base inputs: small decks that run in well under a second. (path relative to the repository)
BASES = [
    'inputs/examples/block_tension/block_tension.dck',           # MESH BLOCK, curves, two steps
    'tests/fuzz/bases/inline_two_hex.dck',                       # NODE COORDS, element lines, FACES
    'tests/restart/restart_s1.dck',                              # rigid-plane contact, friction, HDF5
    'inputs/v5_contact_patch/v5_u3_2pass_coulomb.dck',           # two-body contact, two passes
    'tests/fuzz/bases/contact_smoothed.dck',                     # smoothed normals, MU_CONTINUATION
    'inputs/verification/v2_cook/cook_stress_hex8_2x2.dck',      # gmsh 2.2 mesh
    'tests/fuzz/bases/gmsh41_block.dck',                         # gmsh 4.1 mesh, POS3D, HDF5
    'tests/solver/limit_point_path.dck',                         # path following (CONTROL Path)
]

SPECIAL_NUMBERS = ['NaN', 'Inf', '-Inf', '1e308', '-1e308', '1e400', '1e-400', '0', '-1',
                   '2147483648', 'text']
TEXT_WORDS = ['abc', 'one', '1e', '1.2.3', '+-1', '0x10', '1,5', 'D3', '.', '-']
EXTRA_NUMBERS = ['-0', '1e-300', '-2147483649', '2147483647', '99999999999999999999', '1d308',
                 '4.9e-324', 'nan(0x1)', '+Infinity', '1e+308', '1.7976931348623157e308',
                 '1e200', '-1e160', '1e155', '1e-310', '1e-200', '1e30', '-1e30', '1e-30']

CRASH_MARKERS = [b'Fortran runtime error', b'Backtrace', b'SIGSEGV', b'SIGFPE', b'SIGBUS',
                 b'SIGILL', b'SIGABRT', b'Program received signal', b'AddressSanitizer',
                 b'runtime error:', b'LeakSanitizer', b'ERROR STOP', b'Segmentation fault',
                 b'double free', b'free(): ', b'malloc(): ', b'HDF5-DIAG', b'Error termination',
                 b'Error allocating']

SECTION_RE = re.compile(rb'^\s*-{6,}')
NUMBER_RE = re.compile(rb'(?<![\w.+\-])[+-]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][+-]?\d+)?(?![\w.])')
GMSH_BLOCK_RE = re.compile(rb'^\$(\w+)\s*$')


# ----------------------------------------------------------------------------- files as lines
def split_lines(data):
    """Lines with their '\n' (CR stays inside a line, as frix sees it)."""
    if not data:
        return []
    parts = data.split(b'\n')
    lines = [p + b'\n' for p in parts[:-1]]
    if parts[-1]:
        lines.append(parts[-1])
    return lines


def preview(line, width=50):
    text = repr(bytes(line.rstrip(b'\n')))[2:-1]
    return text if len(text) <= width else text[:width - 3] + '...'


def is_gmsh(name):
    return name.lower().endswith('.msh')


def deck_body_start(lines):
    """Index of the first section line (lines before it are the title)."""
    for i, line in enumerate(lines):
        if SECTION_RE.match(line):
            return i
    return len(lines)


def pick_line(rng, name, lines, candidates=None):
    """A line index; in a deck, one of the title lines only now and then (they are free text)."""
    if candidates is None:
        candidates = range(len(lines))
    candidates = list(candidates)
    if not is_gmsh(name) and rng.random() < 0.9:
        first = deck_body_start(lines)
        body = [i for i in candidates if i >= first]
        if body:
            candidates = body
    return rng.choice(candidates)


# ----------------------------------------------------------------------------- mutations
# Each takes (rng, files, name) and returns a description, or None if it does not apply.
def mut_delete_line(rng, files, name):
    lines = split_lines(files[name])
    if not lines:
        return None
    i = pick_line(rng, name, lines)
    desc = 'delete line %d (%s)' % (i + 1, preview(lines[i]))
    del lines[i]
    files[name] = b''.join(lines)
    return desc


def mut_duplicate_line(rng, files, name):
    lines = split_lines(files[name])
    if not lines:
        return None
    i = pick_line(rng, name, lines)
    line = lines[i] if lines[i].endswith(b'\n') else lines[i] + b'\n'
    lines.insert(i + 1, line)
    files[name] = b''.join(lines)
    return 'duplicate line %d (%s)' % (i + 1, preview(line))


def mut_swap_lines(rng, files, name):
    lines = split_lines(files[name])
    if len(lines) < 2:
        return None
    if not lines[-1].endswith(b'\n'):
        lines[-1] += b'\n'
    i = pick_line(rng, name, lines, range(len(lines) - 1))
    j = i + 1 if rng.random() < 0.5 else pick_line(rng, name, lines)
    if i == j:
        j = i + 1
    i, j = min(i, j), max(i, j)
    lines[i], lines[j] = lines[j], lines[i]
    files[name] = b''.join(lines)
    return 'swap lines %d and %d (%s <-> %s)' % (i + 1, j + 1, preview(lines[j], 30),
                                                   preview(lines[i], 30))


def mut_truncate(rng, files, name):
    data = files[name]
    lines = split_lines(data)
    if not lines:
        return None
    if rng.random() < 0.25:
        # the file ends early, possibly in the middle of a line
        cut = rng.randrange(len(data))
        files[name] = data[:cut]
        line_no = data[:cut].count(b'\n') + 1
        return 'truncate the file after byte %d (in line %d)' % (cut, line_no)
    candidates = [i for i, l in enumerate(lines) if len(l.rstrip(b'\n')) > 1]
    if not candidates:
        return None
    i = pick_line(rng, name, lines, candidates)
    body = lines[i].rstrip(b'\n')
    k = rng.randrange(1, len(body))
    lines[i] = body[:k] + (b'\n' if lines[i].endswith(b'\n') else b'')
    files[name] = b''.join(lines)
    return 'truncate line %d after %d characters (%s)' % (i + 1, k, preview(body[:k]))


def number_positions(name, data):
    """(line index, start, end) of the numbers worth mutating: in a deck, not in the title nor in
    comments nor in section lines; in a gmsh file, everywhere."""
    lines = split_lines(data)
    positions = []
    first = 0 if is_gmsh(name) else deck_body_start(lines)
    for i in range(first, len(lines)):
        line = lines[i]
        if not is_gmsh(name):
            if SECTION_RE.match(line):
                continue
            cut = line.find(b'//')
            if cut >= 0:
                line = line[:cut]
        for m in NUMBER_RE.finditer(line):
            positions.append((i, m.start(), m.end()))
    return positions


def mut_number(rng, files, name):
    positions = number_positions(name, files[name])
    if not positions:
        return None
    i, start, end = rng.choice(positions)
    lines = split_lines(files[name])
    line = lines[i]
    old = line[start:end]
    roll = rng.random()
    if roll < 0.7:
        new = rng.choice(SPECIAL_NUMBERS)
        if new == 'text':
            new = rng.choice(TEXT_WORDS)
    else:
        new = rng.choice(EXTRA_NUMBERS)
    if new == '2147483647' and re.search(rb'NUMSTEP\s*$', line[:start], re.I):
        new = '2147483648'     # 2^31-1 increments is a valid, endless run: not a hang to find
    lines[i] = line[:start] + new.encode() + line[end:]
    files[name] = b''.join(lines)
    return 'line %d col %d: number %s -> %s' % (i + 1, start + 1, old.decode('latin-1'), new)


def junk_bytes(rng):
    kinds = [
        lambda: b'\x00',
        lambda: b'\t',
        lambda: b'\r',
        lambda: b'\r\n',
        lambda: bytes([rng.randrange(0x80, 0x100)]),                  # a lone non-ASCII byte
        lambda: rng.choice(['é', 'µ', '°', '–', '\u00a0', '→', '💥']).encode('utf-8'),
        lambda: bytes([rng.randrange(0x01, 0x20)]),                   # control characters
        lambda: b'\x7f',
        lambda: bytes([rng.randrange(0x21, 0x7f)]),                   # printable ASCII
        lambda: b' ',
        lambda: b'\xff\xfe',                                          # a UTF-16 byte-order mark
        lambda: b'\xef\xbb\xbf',                                      # a UTF-8 byte-order mark
    ]
    n = rng.randint(1, 6)
    return b''.join(rng.choice(kinds)() for _ in range(n))


def mut_junk(rng, files, name):
    data = files[name]
    lines = split_lines(data)
    junk = junk_bytes(rng)
    if not lines:
        files[name] = junk
        return 'the file is junk %r' % junk
    i = pick_line(rng, name, lines)
    body = lines[i].rstrip(b'\n')
    k = rng.randrange(len(body) + 1)
    if rng.random() < 0.3 and k < len(body):
        # overwrite instead of insert
        lines[i] = body[:k] + junk + body[k + len(junk):] + lines[i][len(body):]
        verb = 'overwrite'
    else:
        lines[i] = body[:k] + junk + lines[i][k:]
        verb = 'insert'
    files[name] = b''.join(lines)
    return '%s junk %s at line %d col %d' % (verb, repr(junk)[2:-1], i + 1, k + 1)


def deck_sections(lines):
    """[(name, first line index, end index)] of the sections, END excluded."""
    starts = [i for i, l in enumerate(lines) if SECTION_RE.match(l)]
    sections = []
    for n, s in enumerate(starts):
        e = starts[n + 1] if n + 1 < len(starts) else len(lines)
        title = lines[s].split(b'//')[0].strip().lstrip(b'-').strip()
        if title.upper() == b'END':
            continue
        sections.append((title.decode('latin-1'), s, e))
    return sections


def gmsh_blocks(lines):
    blocks = []
    open_name, open_at = None, None
    for i, line in enumerate(lines):
        m = GMSH_BLOCK_RE.match(line)
        if not m:
            continue
        word = m.group(1).decode('latin-1')
        if open_name is None and not word.startswith('End'):
            open_name, open_at = word, i
        elif open_name is not None and word == 'End' + open_name:
            blocks.append((open_name, open_at, i + 1))
            open_name = None
    return blocks


def mut_repeat_section(rng, files, name):
    lines = split_lines(files[name])
    if lines and not lines[-1].endswith(b'\n'):
        lines[-1] += b'\n'
    blocks = gmsh_blocks(lines) if is_gmsh(name) else deck_sections(lines)
    if not blocks:
        return None
    title, s, e = rng.choice(blocks)
    copy = lines[s:e]
    if rng.random() < 0.6:
        at = e                                         # right after itself
    else:
        at = rng.choice([b[1] for b in blocks] + [b[2] for b in blocks])
    lines[at:at] = copy
    files[name] = b''.join(lines)
    what = '$%s block' % title if is_gmsh(name) else 'section %s' % title
    return 'repeat the %s (lines %d-%d) at line %d' % (what, s + 1, e, at + 1)


MUTATIONS = [  # (name, weight, function)
    ('delete', 12, mut_delete_line),
    ('duplicate', 10, mut_duplicate_line),
    ('swap', 10, mut_swap_lines),
    ('truncate', 10, mut_truncate),
    ('number', 36, mut_number),
    ('junk', 12, mut_junk),
    ('repeat', 10, mut_repeat_section),
]


# ----------------------------------------------------------------------------- bases
class Base:
    def __init__(self, relpath):
        self.relpath = relpath
        self.path = os.path.join(REPO, relpath)
        self.deck_name = os.path.basename(self.path)
        self.name = os.path.splitext(self.deck_name)[0]
        with open(self.path, 'rb') as f:
            deck = f.read()
        self.mesh_name = None
        mesh = None
        lines = split_lines(deck)
        in_mesh_file = False
        for i, line in enumerate(lines):
            if SECTION_RE.match(line):
                in_mesh_file = re.sub(rb'\s+', b' ', line.split(b'//')[0].strip().lstrip(b'-')) \
                    .strip().upper() == b'MESH FILE'
                continue
            m = re.match(rb'^(\s*FILE\s+)(\S+)(.*)$', line, re.S)
            if in_mesh_file and m:
                mesh_path = os.path.join(os.path.dirname(self.path), m.group(2).decode())
                self.mesh_name = os.path.basename(mesh_path)
                with open(mesh_path, 'rb') as f:
                    mesh = f.read()
                lines[i] = m.group(1) + self.mesh_name.encode() + m.group(3)
        self.files = {self.deck_name: b''.join(lines)}
        if mesh is not None:
            self.files[self.mesh_name] = mesh


def make_mutant(bases, seed, index):
    rng = random.Random('frix-fuzz:%d:%d' % (seed, index))
    base = rng.choice(bases)
    files = dict(base.files)
    n_mutations = rng.choices([1, 2, 3], weights=[50, 30, 20])[0]
    descriptions = []
    kinds = []
    weights = [w for _, w, _ in MUTATIONS]
    attempts = 0
    while len(descriptions) < n_mutations and attempts < 50:
        attempts += 1
        if base.mesh_name and rng.random() < 0.5:
            target = base.mesh_name
        else:
            target = base.deck_name
        kind, _, function = rng.choices(MUTATIONS, weights=weights)[0]
        desc = function(rng, files, target)
        if desc is not None:
            descriptions.append('%s: %s' % (target, desc))
            kinds.append(kind + ('(mesh)' if is_gmsh(target) else ''))
    if files == base.files:
        descriptions.append('(the mutations cancelled out)')
    return base, files, descriptions, kinds


# ----------------------------------------------------------------------------- running frix
class RunResult:
    def __init__(self, status, stdout, stderr, timed_out, seconds):
        self.status, self.stdout, self.stderr = status, stdout, stderr
        self.timed_out, self.seconds = timed_out, seconds


def run_frix(args, cwd, timeout, extra_env=None):
    env = dict(os.environ)
    env.update(extra_env or {})
    env.setdefault('OMP_NUM_THREADS', '1')
    env.setdefault('OPENBLAS_NUM_THREADS', '1')
    start = time.monotonic()
    process = subprocess.Popen(args, cwd=cwd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, env=env, start_new_session=True)
    try:
        stdout, stderr = process.communicate(timeout=timeout)
        timed_out = False
    except subprocess.TimeoutExpired:
        try:
            os.killpg(process.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        stdout, stderr = process.communicate()
        timed_out = True
    return RunResult(process.returncode, stdout, stderr, timed_out, time.monotonic() - start)


def crash_problems(run, what):
    problems = []
    if run.timed_out:
        problems.append('%s: no answer within the timeout (%.0f s): a hang' % (what, run.seconds))
        return problems
    if run.status < 0 or run.status >= 128:
        sig = -run.status if run.status < 0 else run.status - 128
        try:
            signame = signal.Signals(sig).name
        except ValueError:
            signame = 'signal %d' % sig
        problems.append('%s: killed by %s (exit status %d)' % (what, signame, run.status))
    elif run.status not in (0, 1):
        problems.append('%s: exit status %d (expected 0 or 1; 2 is for command-line errors)'
                        % (what, run.status))
    for marker in CRASH_MARKERS:
        for stream, text in (('stdout', run.stdout), ('stderr', run.stderr)):
            if marker in text:
                problems.append('%s: %s holds "%s"' % (what, stream, marker.decode()))
    return problems


def deck_error_problems(run, deck_name, what):
    """A rejected deck: located entries and the closing count."""
    problems = []
    name = re.escape(deck_name.encode())
    lines = [l for l in run.stderr.split(b'\n') if l.strip()]
    located = re.compile(rb'^' + name + rb':\d+(:\d+)?: error: ')
    summary = re.compile(rb'^' + name + rb': \d+ error\(s\) in the deck\s*$')
    if not lines:
        return ['%s: exit status 1 without any message on stderr' % what]
    if not any(located.match(l) for l in lines):
        problems.append('%s: the deck was rejected without a located error (no line starting '
                        '"%s:LINE:COL: error:")' % (what, deck_name))
    if not summary.match(lines[-1]):
        problems.append('%s: the message does not end with "%s: N error(s) in the deck"'
                        % (what, deck_name))
    for l in lines:
        if l.startswith(deck_name.encode() + b': error: ') and b'more errors not shown' not in l:
            problems.append('%s: an error without a line number: %s' % (what, preview(l, 120)))
    return problems


COUNTER_LOCK = threading.Lock()
MAX_SHOWN = 8             # offending output lines shown per failing mutant
MAX_PER_FILE = 3          # ... and per result file
NAN_WORDS = {b'nan', b'inf', b'infinity'}
LOST_EXPONENT = re.compile(rb'^[+-]?\d*\.\d+[+-]\d{2,4}$')
QUOTED = re.compile(rb"'[^'\n]*'|\"[^\"\n]*\"")
TOKEN = re.compile(rb'[^\s,;<>=()\[\]{}]+')


def bad_token(token):
    word = token.lstrip(b'+-').lower()
    if word in NAN_WORDS or word.startswith(b'nan('):
        return True
    if len(token) >= 2 and token.strip(b'*') == b'':
        return True
    return bool(LOST_EXPONENT.match(token))


def text_file_problems(path, label):
    problems = []
    with open(path, 'rb') as f:
        data = f.read()
    for number, line in enumerate(data.split(b'\n'), start=1):
        if line.startswith(b'#'):
            continue
        stripped = QUOTED.sub(b' ', line)
        bad = [t for t in TOKEN.findall(stripped) if bad_token(t)]
        if bad:
            problems.append('%s:%d: %s  [%s]' % (label, number, preview(line, 110),
                                                 ', '.join(t.decode('latin-1') for t in bad[:4])))
    return problems


def hdf5_problems(path, label):
    try:
        import h5py
        import numpy
    except ImportError:
        return None
    problems = []

    def check_array(where, value):
        array = numpy.asarray(value)
        if array.dtype.names:
            for field in array.dtype.names:
                check_array(where + '.' + field, array[field])
            return
        if array.dtype.kind in 'fc':
            bad = ~numpy.isfinite(array)
            if bad.any():
                problems.append('%s: %s holds %d non-finite values (first: %r)'
                                % (label, where, int(bad.sum()), array[bad].flat[0]))

    try:
        with h5py.File(path, 'r') as f:
            def visit(name, item):
                for key, value in item.attrs.items():
                    check_array('%s@%s' % (name, key), value)
                if isinstance(item, h5py.Dataset):
                    check_array(name, item[()])
            for key, value in f.attrs.items():
                check_array('/@' + key, value)
            f.visititems(visit)
    except Exception as exc:      # a file frix says it wrote must be readable
        problems.append('%s: cannot be read by h5py: %s' % (label, exc))
    return problems


def output_problems(out_dir, counters):
    """Offending lines of the result files: (total count, the first few of each file)."""
    total, shown = 0, []
    for label, found in output_problems_by_file(out_dir, counters):
        total += len(found)
        shown += found[:MAX_PER_FILE]
        if len(found) > MAX_PER_FILE:
            shown.append('%s: ... %d more' % (label, len(found) - MAX_PER_FILE))
    return total, shown


def output_problems_by_file(out_dir, counters):
    problems = []
    for root, _, names in os.walk(out_dir):
        for name in sorted(names):
            path = os.path.join(root, name)
            label = os.path.relpath(path, out_dir)
            if name.endswith('.h5'):
                found = hdf5_problems(path, label)
                if found is None:
                    with COUNTER_LOCK:
                        counters['h5_unchecked'] += 1
                    continue
            else:
                found = text_file_problems(path, label)
            if found:
                problems.append((label, found))
    return problems


# ----------------------------------------------------------------------------- one mutant
class Outcome:
    def __init__(self, index, base, descriptions, kinds):
        self.index, self.base, self.descriptions, self.kinds = index, base, descriptions, kinds
        self.category = None          # rejected | completed | analysis_failure | failed
        self.problems = []
        self.evidence = []            # (title, bytes) shown with a failure
        self.saved_dir = None


def check_mutant(args, bases, index, work_root, counters):
    base, files, descriptions, kinds = make_mutant(bases, args.seed, index)
    outcome = Outcome(index, base, descriptions, kinds)
    mutant_dir = os.path.join(work_root, 'm%05d' % index)
    os.makedirs(mutant_dir)
    for name, data in files.items():
        with open(os.path.join(mutant_dir, name), 'wb') as f:
            f.write(data)
    deck = base.deck_name
    frix = os.path.abspath(args.frix)

    check = run_frix([frix, '--check', '--quiet', deck], mutant_dir, args.timeout)
    outcome.problems += crash_problems(check, 'frix --check')
    out_dir = os.path.join(mutant_dir, 'out')
    real = run_frix([frix, deck, '--quiet', '--out', 'out'], mutant_dir, args.timeout)
    outcome.problems += crash_problems(real, 'frix (run)')
    runs = [('frix --check', check), ('frix (run)', real)]

    if not outcome.problems:
        if check.status == 1:
            outcome.category = 'rejected'
            outcome.problems += deck_error_problems(check, deck, 'frix --check')
            if real.status != 1:
                outcome.problems.append('frix (run): exit status %d on a deck that --check '
                                        'rejects' % real.status)
            elif real.stderr != check.stderr:
                outcome.problems.append('frix (run): its deck errors differ from --check\'s')
        elif real.status == 0:
            outcome.category = 'completed'
            total, shown = output_problems(out_dir, counters)
            if total:
                outcome.problems.append('exit status 0, but the result files hold non-finite or '
                                        'overflowed values (%d lines or datasets):' % total)
                outcome.problems += ['    ' + p for p in shown[:MAX_SHOWN]]
                if len(shown) > MAX_SHOWN:
                    outcome.problems.append('    ...')
        else:
            outcome.category = 'analysis_failure'
            if not real.stderr.strip() and not real.stdout.strip():
                outcome.problems.append('frix (run): exit status 1 without any message')
            if re.search(rb'error\(s\) in the deck', real.stderr):
                outcome.problems.append('frix (run): rejects the deck that --check accepted')

    if outcome.problems:
        outcome.category = 'failed'
        for what, run in runs:
            outcome.evidence.append(('%s: exit status %s%s' % (what, run.status,
                                     ', timed out' if run.timed_out else ''),
                                     run.stdout, run.stderr))
        outcome.saved_dir = save_failure(args, outcome, mutant_dir, files, runs)
    shutil.rmtree(mutant_dir, ignore_errors=True)
    return outcome


def save_failure(args, outcome, mutant_dir, files, runs):
    target = os.path.join(os.path.abspath(args.failures_dir),
                          'seed%d-%05d-%s' % (args.seed, outcome.index, outcome.base.name))
    shutil.rmtree(target, ignore_errors=True)
    os.makedirs(target)
    for name, data in files.items():
        with open(os.path.join(target, name), 'wb') as f:
            f.write(data)
    with open(os.path.join(target, 'MUTATION.txt'), 'w') as f:
        f.write('%s (base %s, seed %d, mutant %d): %s\n' % (
            outcome.base.deck_name, outcome.base.relpath, args.seed, outcome.index,
            '; '.join(outcome.descriptions)))
    for what, run in runs:
        tag = 'check' if '--check' in what else 'run'
        with open(os.path.join(target, 'frix_%s.stdout' % tag), 'wb') as f:
            f.write(run.stdout)
        with open(os.path.join(target, 'frix_%s.stderr' % tag), 'wb') as f:
            f.write(run.stderr)
        with open(os.path.join(target, 'frix_%s.status' % tag), 'w') as f:
            f.write('%s%s\n' % (run.status, ' (timed out)' if run.timed_out else ''))
    with open(os.path.join(target, 'PROBLEMS.txt'), 'w') as f:
        f.write('\n'.join(outcome.problems) + '\n')
    return target


def failure_class(outcome):
    """A short signature grouping failures that look alike (for the closing list)."""
    text = b'\n'.join(stderr + b'\n' + stdout for _, stdout, stderr in outcome.evidence)
    m = re.search(rb'At line (\d+) of file (\S+)\s*(?:\([^)]*\))?\s*\n\s*Fortran runtime error: ([^\n]*)', text)
    if m:
        where = '%s:%s' % (os.path.basename(m.group(2).decode('latin-1')), m.group(1).decode())
        p = 'Fortran runtime error at %s: %s' % (where, m.group(3).decode('latin-1').strip())
    elif re.search(rb"In file '([^']*)', around line (\d+): ([^\n]*)", text):
        m = re.search(rb"In file '([^']*)', around line (\d+): ([^\n]*)", text)
        p = 'Fortran runtime error at %s:%s: %s' % (os.path.basename(m.group(1).decode('latin-1')),
                                                    m.group(2).decode(), m.group(3).decode('latin-1'))
        p = re.sub(r'\d{6,}', 'N', p)
    elif re.search(rb'Fortran runtime error: ([^\n]*)', text):
        p = 'Fortran runtime error: ' + re.search(rb'Fortran runtime error: ([^\n]*)',
                                                  text).group(1).decode('latin-1').strip()
    else:
        p = outcome.problems[0]
        p = re.sub(r' \(\d+ lines or datasets\):', '', p)
        p = re.sub(r' \(\d+ s\)', '', p)
    return '%s [%s]' % (p[:160], outcome.base.deck_name)


def show(data, limit=12):
    lines = data.decode('utf-8', 'replace').rstrip('\n').split('\n') if data.strip() else []
    if len(lines) > limit:
        lines = lines[:limit // 2] + ['    ... (%d lines)' % (len(lines) - limit)] + lines[-limit // 2:]
    return '\n'.join('      | ' + l for l in lines)


# ----------------------------------------------------------------------------- write failures
# Result files whose writes fail in a fault run ('' = every file of the run).
FAULT_TARGETS = ['', '.h5', '_listing.txt', '.vtu', '.pvd', '.pos', '_history.csv', '_contact.csv']


def make_fault(bases, seed, index):
    """Fault run `index` of `seed`: (base, target file pattern, bytes before the failure)."""
    rng = random.Random('frix-fuzz-fault:%d:%d' % (seed, index))
    base = rng.choice(bases)
    target = rng.choice(FAULT_TARGETS) if rng.random() < 0.6 else ''
    limit = int(10 ** rng.uniform(0, 6))   # 1 B .. 1 MB, log-uniform: every stage of a run
    return base, target, limit


def check_fault(args, bases, index, work_root):
    base, target, limit = make_fault(bases, args.seed, index)
    descriptions = ['writes into %s fail after %d bytes' % (('*' + target) if target else 'any file',
                                                              limit)]
    outcome = Outcome(index, base, descriptions, ['fault'])
    run_dir = os.path.join(work_root, 'f%05d' % index)
    os.makedirs(run_dir)
    for name, data in base.files.items():
        with open(os.path.join(run_dir, name), 'wb') as f:
            f.write(data)
    report = os.path.join(run_dir, 'refused')
    env = {'FRIX_FAIL_WRITE_PATH': target, 'FRIX_FAIL_WRITE_AFTER': str(limit),
           'FRIX_FAIL_WRITE_REPORT': report, 'LD_PRELOAD': os.path.abspath(args.fail_writes),
           'ASAN_OPTIONS': ':'.join(filter(None, [os.environ.get('ASAN_OPTIONS', ''),
                                                  'verify_asan_link_order=0']))}
    run = run_frix([os.path.abspath(args.frix), base.deck_name, '--out', 'out'], run_dir,
                   args.timeout, env)
    outcome.problems += crash_problems(run, 'frix (run)')
    refused = os.path.exists(report)
    if not outcome.problems:
        if refused:
            outcome.category = 'write_failure'
            if run.status != 1:
                outcome.problems.append('exit status %d after a refused write, expected 1'
                                        % run.status)
            if not re.search(rb'cannot [^\n]*out/' + re.escape(base.name.encode()), run.stderr):
                outcome.problems.append('no message "cannot ..." naming a result file')
            if b'converged increments; results in' in run.stdout:
                outcome.problems.append('the success line after a refused write')
            leftovers = [n for _, _, names in os.walk(os.path.join(run_dir, 'out'))
                         for n in names if n.endswith('.tmp')]
            if leftovers:
                outcome.problems.append('temporary files left: %s' % ', '.join(leftovers))
        else:
            outcome.category = 'completed'
            if run.status != 0:
                outcome.problems.append('exit status %d, no write refused' % run.status)
    if outcome.problems:
        outcome.category = 'failed'
        outcome.evidence.append(('frix (run): exit status %s%s' % (
            run.status, ', timed out' if run.timed_out else ''), run.stdout, run.stderr))
    shutil.rmtree(run_dir, ignore_errors=True)
    return outcome


# ----------------------------------------------------------------------------- main
def limit_memory(args):
    """Cap the address space of the frix processes (inherited from this one), so that a mutant
    asking frix for an absurd allocation fails there instead of filling the machine's memory.
    Sanitizer builds reserve terabytes of address space: no limit for them."""
    if args.memory_limit_mb <= 0:
        return
    try:
        import resource
        with open(args.frix, 'rb') as f:
            binary = f.read()
        if b'__asan_init' in binary or b'__tsan_init' in binary:
            return
        limit = args.memory_limit_mb * 1024 * 1024
        soft, hard = resource.getrlimit(resource.RLIMIT_AS)
        if hard != resource.RLIM_INFINITY:
            limit = min(limit, hard)
        if soft == resource.RLIM_INFINITY or soft > limit:
            resource.setrlimit(resource.RLIMIT_AS, (limit, hard))
    except (ImportError, OSError, ValueError):
        pass


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--frix', default=os.environ.get('FRIX'), help='the frix executable')
    parser.add_argument('--seed', type=int, default=1, help='the seed (default 1)')
    parser.add_argument('--count', type=int, default=300, help='number of mutants (default 300)')
    parser.add_argument('--first', type=int, default=0, help='index of the first mutant')
    parser.add_argument('--only', default=None, help='run these mutants only: N[,N...]')
    parser.add_argument('--jobs', type=int, default=2, help='parallel frix processes (default 2)')
    parser.add_argument('--timeout', type=float, default=30.0, help='seconds per frix run')
    parser.add_argument('--failures-dir', default='fuzz_failures',
                        help='where failing mutants are written (default ./fuzz_failures)')
    parser.add_argument('--bases', default=None,
                        help='comma-separated substrings: use only base decks matching one')
    parser.add_argument('--list', action='store_true',
                        help='print the mutants\' descriptions without running frix')
    parser.add_argument('--memory-limit-mb', type=int, default=4096,
                        help='address-space limit of each frix process (RLIMIT_AS; default 4096 MB, '
                             '0: none; not applied to a sanitizer build)')
    parser.add_argument('--verbose', action='store_true', help='one line per mutant')
    parser.add_argument('--fail-writes', default=None,
                        help='the write-failure library (tests/io/fail_writes.c) for --faults')
    parser.add_argument('--faults', type=int, default=0,
                        help='runs of the base decks with a write failure (needs --fail-writes)')
    parser.add_argument('--only-fault', default=None, help='run these fault runs only: N[,N...]')
    args = parser.parse_args(argv)
    if not args.frix and not args.list:
        parser.error('--frix (or the environment variable FRIX) is required')
    if (args.faults or args.only_fault) and not args.fail_writes:
        parser.error('--faults needs --fail-writes LIB')
    return args


def main(argv):
    args = parse_args(argv)
    relpaths = BASES
    if args.bases:
        keys = [k for k in args.bases.split(',') if k]
        relpaths = [p for p in BASES if any(k in p for k in keys)]
        if not relpaths:
            print('fuzz: no base deck matches --bases %s' % args.bases)
            return 2
    bases = [Base(p) for p in relpaths]
    if args.only:
        indices = [int(x) for x in args.only.split(',') if x.strip()]
    elif args.only_fault:
        indices = []
    else:
        indices = list(range(args.first, args.first + args.count))
    if args.only_fault:
        faults = [int(x) for x in args.only_fault.split(',') if x.strip()]
    else:
        faults = list(range(args.faults)) if not args.only else []

    if args.list:
        for index in indices:
            base, _, descriptions, _ = make_mutant(bases, args.seed, index)
            print('%5d %s: %s' % (index, base.deck_name, '; '.join(descriptions)))
        return 0
    if not os.path.isfile(args.frix) or not os.access(args.frix, os.X_OK):
        print('fuzz: FAIL: no executable %s' % args.frix)
        return 1

    limit_memory(args)
    start = time.monotonic()
    counters = {'h5_unchecked': 0}
    work_root = tempfile.mkdtemp(prefix='frix-fuzz-')
    try:
        # the unmutated bases must run cleanly, or the mutants say nothing
        broken = []
        for base in bases:
            d = os.path.join(work_root, 'base-' + base.name)
            os.makedirs(d)
            for name, data in base.files.items():
                with open(os.path.join(d, name), 'wb') as f:
                    f.write(data)
            run = run_frix([os.path.abspath(args.frix), base.deck_name, '--quiet', '--out', 'out'],
                           d, args.timeout)
            problems = crash_problems(run, 'frix')
            if run.status != 0:
                problems.append('exit status %d' % run.status)
            else:
                problems += output_problems(os.path.join(d, 'out'), counters)[1]
            if problems:
                broken.append((base, problems, run))
        if broken:
            for base, problems, run in broken:
                print('fuzz: FAIL: the unmutated base deck %s does not run cleanly: %s'
                      % (base.relpath, '; '.join(problems)))
                print(show(run.stderr))
            return 1

        outcomes = []
        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
            futures = [pool.submit(check_mutant, args, bases, i, work_root, counters)
                       for i in indices]
            futures += [pool.submit(check_fault, args, bases, i, work_root) for i in faults]
            for future in futures:
                outcome = future.result()
                outcomes.append(outcome)
                if args.verbose:
                    print('%5d %-18s %-24s %s' % (outcome.index, outcome.category,
                                                  outcome.base.deck_name,
                                                  '; '.join(outcome.descriptions)), flush=True)
    finally:
        shutil.rmtree(work_root, ignore_errors=True)

    elapsed = time.monotonic() - start
    failed = [o for o in outcomes if o.category == 'failed']
    frix_abs = os.path.abspath(args.frix)
    me = os.path.abspath(__file__)
    for o in failed:
        print('')
        fault = o.kinds == ['fault']
        print('FAIL: %s %d of seed %d (base %s): %s' % ('fault run' if fault else 'mutant', o.index,
                                                         args.seed, o.base.relpath,
                                                         '; '.join(o.descriptions)))
        for p in o.problems:
            print(('        ' + p.strip()) if p.startswith('    ') else ('    - ' + p))
        for title, stdout, stderr in o.evidence:
            print('    %s' % title)
            if stdout.strip():
                print('      stdout:')
                print(show(stdout))
            if stderr.strip():
                print('      stderr:')
                print(show(stderr))
        if fault:
            print('    reproduce: python3 %s --frix %s --fail-writes %s --seed %d --only-fault %d'
                  % (me, frix_abs, os.path.abspath(args.fail_writes), args.seed, o.index))
            continue
        print('    mutant saved in %s (MUTATION.txt, frix_*.stderr)' % o.saved_dir)
        print('    reproduce: cd %s && %s %s --quiet --out out' % (o.saved_dir, frix_abs,
                                                                 o.base.deck_name))
        print('           or: python3 %s --frix %s --seed %d --only %d' % (me, frix_abs,
                                                                         args.seed, o.index))
    if failed:
        classes = {}
        for o in failed:
            classes.setdefault(failure_class(o), []).append(o.index)
        print('')
        print('fuzz: failures by kind (first problem [base deck]: mutants):')
        for key, members in sorted(classes.items(), key=lambda kv: -len(kv[1])):
            shown = ', '.join(str(i) for i in members[:8]) + (' ...' if len(members) > 8 else '')
            print('  %4d x %s: %s' % (len(members), key, shown))

    mutants = [o for o in outcomes if o.kinds != ['fault']]
    fault_runs = [o for o in outcomes if o.kinds == ['fault']]
    count = {c: sum(1 for o in mutants if o.category == c)
             for c in ('rejected', 'completed', 'analysis_failure', 'failed')}
    print('')
    note = ''
    if counters['h5_unchecked']:
        note = '; %d .h5 files not checked (no h5py in this python)' % counters['h5_unchecked']
    print('fuzz: seed %d, mutants %s, %d base decks, %d jobs, %.1f s%s'
          % (args.seed, '%d..%d' % (min(indices), max(indices)) if indices else 'none',
             len(bases), args.jobs, elapsed, note))
    print('fuzz: %d mutants: %d rejected with a located error, %d ran to completion, '
          '%d analysis failures; %d failed' % (len(mutants), count['rejected'],
                                               count['completed'], count['analysis_failure'],
                                               count['failed']))
    if fault_runs:
        print('fuzz: %d fault runs: %d met a write failure, %d ran to completion; %d failed'
              % (len(fault_runs), sum(1 for o in fault_runs if o.category == 'write_failure'),
                 sum(1 for o in fault_runs if o.category == 'completed'),
                 sum(1 for o in fault_runs if o.category == 'failed')))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
