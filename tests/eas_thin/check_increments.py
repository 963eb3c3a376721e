#!/usr/bin/python3
"""check_increments.py: the increments of a run, from its listing (docs/listing-format.md).

    check_increments.py BASE INCREMENTS MAX_ITERATIONS

BASE is the run's base path (BASE_listing.txt; tests/verification/run_case.sh --script passes
it). Passes when the listing holds exactly INCREMENTS converged increments (a cut-back adds
increments: an increment cut once is done as two) and none took more than MAX_ITERATIONS Newton
iterations. Exit status 0 when both hold, 1 otherwise.
"""
import sys


def main(argv):
    if len(argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    base, expected, bound = argv[1], int(argv[2]), int(argv[3])
    iterations = []
    with open(base + "_listing.txt") as listing:
        for line in listing:
            if line.startswith("STEP"):
                iterations.append(int(line.split()[-1]))
    ok = len(iterations) == expected and iterations and max(iterations) <= bound
    print(f"{'ok  ' if ok else 'FAIL'} {len(iterations)} increments (expected {expected}, i.e. no "
          f"cut-back), Newton iterations {iterations} (at most {bound} each)")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
