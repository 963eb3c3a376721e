"""S3 under path following (inputs/s3_punch/s3_coarse_mu0_path.dck and
s3_coarse_mu0.1_path.dck, docs/verification/s3.md "A limit point of the discrete model"), from
the run's history CSV: the largest load factor must lie within 1e-3 of LIMIT, the last state
that load control reaches with increments down to 1e-5 (MAXCUT 14; s3.md: an independent
approach to the same limit point from below: 0.61067 without friction, 0.7917 with mu = 0.1),
and the load factor must fall over at least 5 increments after it (the limit point is passed).
Measured: 0.610624 against 0.61067 (4.6e-5), 0.791907 against 0.7917 (2.1e-4); the largest
converged t is a sample of the path (corner steps of 0.023 near the maximum after cut-backs)
and LIMIT lies below the true maximum, hence 1e-3.
usage: check_s3_path.py HISTORY_CSV LIMIT"""
import sys

import numpy as np

d = np.genfromtxt(sys.argv[1], delimiter=',', names=True)
limit = float(sys.argv[2])
t, corner = d['time'], d['u3_n1025']
k = int(np.argmax(t))
falling = int(np.sum(np.diff(t[k:]) < 0))
fail = 0
if abs(t[k] - limit) > 1e-3:
    print(f"FAIL: largest load factor {t[k]:.6f}, expected {limit} +- 1e-3")
    fail = 1
if falling < 5:
    print(f"FAIL: only {falling} increments with a falling load after the largest")
    fail = 1
print(f"S3 path: largest t = {t[k]:.6f} at corner u_z = {corner[k]:.4f}, "
      f"{falling} increments beyond it, last t = {t[-1]:.6f} at corner u_z = {corner[-1]:.4f}")
sys.exit(fail)
