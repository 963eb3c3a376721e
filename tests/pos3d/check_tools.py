"""Counting checks shared by the POS3D test scripts: `check` and `close` record a pass or a
failure (printing the failed label), `summary()` prints "N passed, N failed" and returns the
exit status."""
import numpy as np

counts = {"passed": 0, "failed": 0}


def check(condition, label):
    if condition:
        counts["passed"] += 1
    else:
        counts["failed"] += 1
        print(f"FAILED: {label}")


def close(actual, expected, rel, label):
    """Pass when |actual - expected| <= rel * max|expected| elementwise (same shapes)."""
    actual, expected = np.asarray(actual, float), np.asarray(expected, float)
    ok = actual.shape == expected.shape and bool(
        np.all(np.abs(actual - expected) <= rel * max(np.abs(expected).max(initial=0.0), 1e-300)))
    if not ok and actual.shape == expected.shape:
        print(f"  max difference {np.abs(actual - expected).max():.3e} (scale {np.abs(expected).max():.3e})")
    elif not ok:
        print(f"  shapes {actual.shape} vs {expected.shape}")
    check(ok, label)


def summary():
    print(f"{counts['passed']} passed, {counts['failed']} failed")
    return 1 if counts["failed"] else 0
