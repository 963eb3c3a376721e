"""PASS:/FAIL: lines and their tally for the Python check scripts of the regression tests.

usage: from check_tally import check, summary; check(condition, message) for each check, then
sys.exit(summary()), which prints "N passed, N failed" and returns the exit status (1 if any
check failed). check_ranges(values, specs) checks the "key=low:high" specs of a script's
--check options against its measured values.
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


def check_ranges(values, specs):
    """Check each spec "key=low:high" (low <= values[key] <= high), print one line per spec;
    the exit status: 0 if every value lies in its range."""
    status = 0
    for spec in specs:
        key, bounds = spec.split("=")
        low, high = (float(b) for b in bounds.split(":"))
        ok = low <= values[key] <= high
        print(f"  {'ok  ' if ok else 'FAIL'} {key} = {values[key]:.6g} in [{low:g}, {high:g}]")
        status |= not ok
    return status
