#!/usr/bin/env python3
"""Run every deck of inputs/ and tests/ with two frix binaries and compare their result files
byte for byte: listing, CSV histories and contact tables, VTK (.pvd, .vtu) and POS3D files.
Lines that name the version of frix ("# frix version 0.1.0") or the deck's path are left out
of the comparison. Used to show that a change of the code's structure leaves every result
unchanged (docs/architecture.md).

    scripts/compare_builds.py OLD_FRIX NEW_FRIX [--work DIR] [--timeout S] [--jobs N]

Decks that the first binary rejects (error decks) are compared by their messages; decks
that take longer than --timeout seconds with the first binary are listed as skipped.
Exit status 0 when every compared deck gives identical files, 1 otherwise.
"""
import argparse
import concurrent.futures
import filecmp
import os
import pathlib
import re
import shutil
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
COMPARED = (".txt", ".csv", ".pvd", ".vtu", ".pos")
IGNORED_LINE = re.compile(rb"^(# frix version |# deck |frix version )")


def run(frix, deck, out, timeout):
    out.mkdir(parents=True, exist_ok=True)
    start = time.time()
    try:
        result = subprocess.run([str(frix), str(deck), "--out", str(out), "--quiet"],
                                capture_output=True, timeout=timeout, cwd=ROOT)
    except subprocess.TimeoutExpired:
        return None, time.time() - start
    (out / "stderr.txt").write_bytes(result.stderr)
    (out / "status.txt").write_text(str(result.returncode))
    return result.returncode, time.time() - start


def normalised(path):
    return [line for line in path.read_bytes().splitlines() if not IGNORED_LINE.match(line)]


def compare_directories(old, new):
    """Names of the compared files that differ, or are missing on one side."""
    differing = []
    names = sorted({p.name for p in old.iterdir()} | {p.name for p in new.iterdir()})
    for name in names:
        if not (name.endswith(COMPARED) or name in ("status.txt", "stderr.txt")):
            continue
        a, b = old / name, new / name
        if not (a.exists() and b.exists()):
            differing.append(name + " (missing in " + ("new" if a.exists() else "old") + ")")
        elif not filecmp.cmp(a, b, shallow=False) and normalised(a) != normalised(b):
            differing.append(name)
    return differing


def one_deck(args, deck):
    relative = deck.relative_to(ROOT)
    key = str(relative).replace("/", "__").removesuffix(".dck")
    old_dir, new_dir = args.work / "old" / key, args.work / "new" / key
    for d in (old_dir, new_dir):
        shutil.rmtree(d, ignore_errors=True)
    status, seconds = run(args.old, deck, old_dir, args.timeout)
    if status is None:
        return relative, "skipped", f"longer than {args.timeout} s", seconds
    run(args.new, deck, new_dir, 10 * args.timeout)
    differing = compare_directories(old_dir, new_dir)
    if differing:
        return relative, "DIFFERENT", ", ".join(differing), seconds
    n_files = sum(1 for p in old_dir.iterdir() if p.name.endswith(COMPARED))
    return relative, "identical", f"{n_files} result files, exit status {status}", seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("old", type=pathlib.Path)
    parser.add_argument("new", type=pathlib.Path)
    parser.add_argument("--work", type=pathlib.Path, default=pathlib.Path("compare-builds"))
    parser.add_argument("--timeout", type=float, default=60.0)
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    args.old, args.new, args.work = args.old.resolve(), args.new.resolve(), args.work.resolve()
    decks = sorted(p for folder in ("inputs", "tests") for p in (ROOT / folder).rglob("*.dck")
                   if "fuzz" not in p.parts)
    counts = {}
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for relative, verdict, detail, seconds in pool.map(lambda d: one_deck(args, d), decks):
            counts[verdict] = counts.get(verdict, 0) + 1
            print(f"{verdict:9s} {relative}  ({detail}; {seconds:.1f} s)", flush=True)
    print("compare_builds: " + ", ".join(f"{n} {v}" for v, n in sorted(counts.items())))
    return 1 if counts.get("DIFFERENT") else 0


if __name__ == "__main__":
    sys.exit(main())
