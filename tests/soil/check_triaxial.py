#!/usr/bin/python3
"""check_triaxial.py FRIX DECK: run triaxial_mohr_coulomb.dck or triaxial_drucker_prager.dck and
check every increment of its CSV history against the closed form of its triaxial test (the
decks' headers), and the last increment's history variables in the HDF5 file (REGION 1: the
Mohr-Coulomb plane, the Drucker-Prager cone; eps_p along the flow).

Closed forms (tension positive; s = sin phi, s_psi = sin psi, k = cos phi, c = c0 + H alpha):
the lateral stresses are the cell pressures (sigma_xx, sigma_yy) t for t <= 1, then constant,
and eps_zz = u_z of the top (unit cube). Elastic: sigma_zz = E eps_zz + nu (sigma_xx + sigma_yy).
Plastic, with gamma the accumulated multiplier:
  Mohr-Coulomb (sigma_1 = sigma_xx = -100, sigma_2 = sigma_yy = -150, sigma_3 = sigma_zz), the plane:
    (sigma_xx - sigma_zz) + (sigma_xx + sigma_zz) s - 2 k c = 0,  alpha = 2 k gamma,
    eps_p = gamma (1 + s_psi, 0, -(1 - s_psi));
  Drucker-Prager, outer cone (sigma_xx = sigma_yy = -100 > sigma_zz, q = sigma_xx - sigma_zz):
    q / sqrt(3) + eta p - xi c = 0,  p = (2 sigma_xx + sigma_zz) / 3,  alpha = xi gamma,
    eps_p = gamma (n / sqrt(2) + eta_bar / 3 1),  n = (1, 1, -2) / sqrt(6);
and eps_zz = (sigma_zz - nu (sigma_xx + sigma_yy)) / E + eps_p_zz: two linear equations in
sigma_zz and gamma (solved below); the lateral strains are Hooke's of the stress plus eps_p."""
import math
import subprocess
import sys
import tempfile

import h5py
import numpy as np

E, NU, C0, PHI, PSI, H = 20000.0, 0.3, 10.0, math.radians(30.0), math.radians(10.0), 200.0
S, SP, K = math.sin(PHI), math.sin(PSI), math.cos(PHI)



def cone(sine, cosine):
    """eta, xi of the outer cone (docs/materials.md, MAT_3DDruckerPrager)."""
    return 6.0 * sine / (math.sqrt(3.0) * (3.0 - sine)), 6.0 * cosine / (math.sqrt(3.0) * (3.0 - sine))


# per deck: cell pressures, u_z of the top at t = 1, yield function f = a . (sigma_xx, sigma_zz)
# + b - g gamma - (linear in sigma_zz and gamma), flow per unit gamma (xx, yy, zz)
ETA, XI = cone(S, K)
ETA_BAR = cone(SP, math.cos(PSI))[0]
CASES = {
    'triaxial_mohr_coulomb': dict(
        cell=(-100.0, -150.0), top=0.00125,
        yield_function=lambda sxx, szz, gamma: (sxx - szz) + (sxx + szz) * S - 2.0 * K * (C0 + H * 2.0 * K * gamma),
        flow=np.array([1.0 + SP, 0.0, -(1.0 - SP)])),
    'triaxial_drucker_prager': dict(
        cell=(-100.0, -100.0), top=0.002,
        yield_function=lambda sxx, szz, gamma: (sxx - szz) / math.sqrt(3.0) + ETA * (2.0 * sxx + szz) / 3.0
        - XI * (C0 + H * XI * gamma),
        flow=np.array([1.0, 1.0, -2.0]) / math.sqrt(12.0) + ETA_BAR / 3.0)}


def closed_form(case, t):
    """(sigma_zz, eps_xx, eps_yy, eps_p) at time t."""
    load = min(t, 1.0)
    sxx, syy = case['cell'][0] * load, case['cell'][1] * load
    ezz = -(case['top'] * t if t <= 1.0 else case['top'] + (0.03 - case['top']) * (t - 1.0))
    szz = E * ezz + NU * (sxx + syy)
    gamma = 0.0
    f = case['yield_function']
    if f(sxx, szz, 0.0) > 0.0:
        # f(sigma_zz, gamma) = 0 and eps_zz = Hooke + gamma flow_zz: both linear, solved exactly
        f0, df_ds, df_dg = f(sxx, 0.0, 0.0), f(sxx, 1.0, 0.0) - f(sxx, 0.0, 0.0), f(sxx, 0.0, 1.0) - f(sxx, 0.0, 0.0)
        matrix = np.array([[df_ds, df_dg], [1.0 / E, case['flow'][2]]])
        szz, gamma = np.linalg.solve(matrix, [-f0, ezz + NU * (sxx + syy) / E])
    plastic = gamma * case['flow']
    exx = (sxx - NU * (syy + szz)) / E + plastic[0]
    eyy = (syy - NU * (sxx + szz)) / E + plastic[1]
    return szz, exx, eyy, plastic


def main():
    frix, deck = sys.argv[1], sys.argv[2]
    name = deck.rsplit('/', 1)[-1][:-4]
    case = CASES[name]
    fail = False
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([frix, deck, '--out', out, '--quiet'], check=True)
        rows = np.atleast_1d(np.genfromtxt(f'{out}/{name}_history.csv', delimiter=',', names=True))
        worst, plastic_rows = 0.0, 0
        for row in rows:
            szz, exx, eyy, plastic = closed_form(case, float(row['time']))
            plastic_rows += plastic[0] != 0.0
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
        expected = closed_form(case, 2.0)[3]
        error = np.abs(eps_p[:, :, 0:3] - expected).max() / abs(expected[0])
        print(f'last increment: REGION {sorted(set(region.ravel()))}, eps_p (xx, yy, zz) error {error:.1e} '
              f'of {expected[0]:.4e}')
        if not (np.all(region == 1.0) and error <= 1e-9 and np.abs(eps_p[:, :, 3:]).max() <= 1e-12):
            print('FAIL: history variables')
            fail = True
    sys.exit(1 if fail else 0)


if __name__ == '__main__':
    main()
