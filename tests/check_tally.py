"""PASS:/FAIL: lines and their tally for the Python check scripts of the regression tests.

usage: from check_tally import check, summary; check(condition, message) for each check, then
sys.exit(summary()), which prints "N passed, N failed" and returns the exit status (1 if any
check failed).
"""

passed = 0
failed = 0


def check(condition, message):
    """Print PASS:/FAIL: message and count it."""
    global passed, failed
    if condition:
        passed += 1
        print(f"PASS: {message}")
    else:
        failed += 1
        print(f"FAIL: {message}")


def summary():
    """Print the tally; the exit status: 0 if every check passed."""
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0
