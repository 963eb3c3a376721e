#!/usr/bin/python3
"""check_triaxial.py FRIX DECK: run triaxial_mohr_coulomb.dck and check every increment of its
CSV history against the closed form of the true triaxial test (the deck's header), and the last
increment's history variables in the HDF5 file (REGION 1: the plane; eps_p along the plane's flow).

Closed form (tension positive; s = sin phi, s_psi = sin psi, k = cos phi): the lateral stresses
are the cell pressures, sigma_xx = -100 t, sigma_yy = -150 t (t <= 1, then constant), and eps_zz
= u_z of the top (unit cube). Elastic: sigma_zz = E eps_zz + nu (sigma_xx + sigma_yy). Plastic, on
the plane sigma_1 = sigma_xx, sigma_3 = sigma_zz with c = c0 + H alpha:
  eps_p = d gamma (1 + s_psi, 0, -(1 - s_psi)),  alpha = 2 k d gamma,
  (sigma_xx - sigma_zz) + (sigma_xx + sigma_zz) s - 2 k (c0 + H alpha) = 0,
  eps_zz = (sigma_zz - nu (sigma_xx + sigma_yy)) / E + eps_p_zz,
linear in sigma_zz (solved below); the lateral strains are Hooke's of the stress plus eps_p."""
import math
import subprocess
import sys
import tempfile

import h5py
import numpy as np

E, NU, C0, PHI, PSI, H = 20000.0, 0.3, 10.0, math.radians(30.0), math.radians(10.0), 200.0
S, SP, K = math.sin(PHI), math.sin(PSI), math.cos(PHI)


def curve2(t):
    """u_z of the top, downwards: 0.00125 t up to t = 1, then to 0.03 at t = 2."""
    return 0.00125 * t if t <= 1.0 else 0.00125 + (0.03 - 0.00125) * (t - 1.0)


def closed_form(t):
    """(sigma_zz, eps_xx, eps_yy) at time t."""
    load = min(t, 1.0)
    sxx, syy, ezz = -100.0 * load, -150.0 * load, -curve2(t)
    szz = E * ezz + NU * (sxx + syy)
    plastic = np.zeros(3)
    if (sxx - szz) + (sxx + szz) * S - 2.0 * K * C0 > 0.0:
        k = 4.0 * K * K * H / (1.0 - SP)  # d(2 k c)/d(-eps_p_zz)
        szz = (sxx * (1.0 + S) - 2.0 * K * C0 + k * ezz + k * NU * (sxx + syy) / E) / ((1.0 - S) + k / E)
        gamma = -(ezz - (szz - NU * (sxx + syy)) / E) / (1.0 - SP)
        plastic = gamma * np.array([1.0 + SP, 0.0, -(1.0 - SP)])
    exx = (sxx - NU * (syy + szz)) / E + plastic[0]
    eyy = (syy - NU * (sxx + szz)) / E + plastic[1]
    return szz, exx, eyy, plastic


def main():
    frix, deck = sys.argv[1], sys.argv[2]
    name = deck.rsplit('/', 1)[-1][:-4]
    fail = False
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([frix, deck, '--out', out, '--quiet'], check=True)
        rows = np.atleast_1d(np.genfromtxt(f'{out}/{name}_history.csv', delimiter=',', names=True))
        worst, plastic_rows = 0.0, 0
        for row in rows:
            szz, exx, eyy, plastic = closed_form(float(row['time']))
            plastic_rows += plastic[0] > 0.0
            worst = max(worst, abs(row['r3_sum_sample_zmax'] - szz) / 100.0,
                        abs(row['u1_mean_sample_xmax'] - exx) / 0.03, abs(row['u2_mean_sample_ymax'] - eyy) / 0.03)
        print(f'{len(rows)} increments, {plastic_rows} plastic: largest error {worst:.1e} '
              '(stress / 100 kPa, strain / 0.03)')
        if len(rows) != 12 or plastic_rows < 5 or not worst <= 1e-9:
            print('FAIL: history against the closed form')
            fail = True
        with h5py.File(f'{out}/{name}.h5', 'r') as h5:
            last = h5['increments'][sorted(h5['increments'])[-1]]
            history = last['history'][...]   # (element, point, state)
        region, eps_p = history[:, :, 2], history[:, :, 3:9]
        expected = closed_form(2.0)[3]
        error = np.abs(eps_p[:, :, 0:3] - expected).max() / abs(expected[0])
        print(f'last increment: REGION {sorted(set(region.ravel()))}, eps_p (xx, yy, zz) error {error:.1e} '
              f'of {expected[0]:.4e}')
        if not (np.all(region == 1.0) and error <= 1e-9 and np.abs(eps_p[:, :, 3:]).max() <= 1e-12):
            print('FAIL: history variables')
            fail = True
    sys.exit(1 if fail else 0)


if __name__ == '__main__':
    main()
