#!/usr/bin/python3
"""check_insitu.py OUT BASE: the results of a soil block with a geostatic initial stress
(the decks of tests/soil_insitu; their headers give the problems) against the closed forms, from the HDF5 file, the VTK files, the history CSV and the
listing in OUT (written by run_deck_check.sh).

Step 1 (gravity and the initial stress, no other load): the displacements vanish to 1e-12 of
the elastic settlement the weight alone would cause (gamma H^2 / (2 M) of the top, M the
oedometric modulus of the softest layer), every Newton increment converges with 0 iterations,
the bottom's reaction equals the weight, and the stress at every integration point (HDF5,
at its reference position) and at every element centre (VTK cell field) equals
  sigma_v = -(q + gamma (z0 - z)),  sigma_xx = sigma_yy = K0 sigma_v,  no shear
of its layer, to 1e-10 of the largest.
Step 2 (RESET_DISPLACEMENT, a surcharge p f(t) on the top): the oedometric closed form added to
the initial stress, d sigma_zz = -p f, d sigma_xx = d sigma_yy = -nu / (1 - nu) p f, and the
reported displacement u_z(z) = -p f int_0^z dz / M(z) (u_x = u_y = 0), the reaction the weight
plus p f A. A Mohr-Coulomb soil stays elastic (REGION 0 everywhere): its stress ratio moves
from K0 = 1 - sin(phi) towards nu / (1 - nu), inside (K_a, K_p); insitu_mohr_coulomb_active
goes past K_a: its step 2 is checked on the Mohr-Coulomb edge instead (check_active), with the
elements' mean sigma_zz against the closed form."""
import math
import re
import sys
import xml.etree.ElementTree as ElementTree

import h5py
import numpy as np

GAUSS = np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
                  [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]], dtype=float)  # hex8_corner
POINTS = GAUSS / math.sqrt(3.0)


def oedometric(young, nu):
    return young * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu))


# layers from the top: (bottom z, unit weight, K0, E, nu); datum of the first at TOP, each next
# layer's datum its top with the weight of the layers above as its surcharge
SOIL = [(0.0, 18.0, 0.5, 20000.0, 0.3)]
CASES = {
    'insitu_elastic': dict(layers=SOIL, top=4.0, area=4.0, p=50.0, plastic=False),
    'insitu_mohr_coulomb': dict(layers=SOIL, top=4.0, area=4.0, p=50.0, plastic=True),
    'insitu_layers': dict(layers=[(2.0, 18.0, 0.5, 20000.0, 0.3), (0.0, 20.0, 0.6, 40000.0, 0.25)],
                          top=4.0, area=4.0, p=50.0, plastic=False, bottom='lower'),
}
# the active limit: step 2 checked on the Mohr-Coulomb edge (c, phi) instead of the elastic closed form
CASES['insitu_mohr_coulomb_active'] = dict(layers=[(0.0, 18.0, 0.5, 20000.0, 0.1)], top=4.0, area=4.0, p=200.0,
                                           plastic=True, active=(1.0, math.radians(30.0)))
# augmented contact between the layers: penetrations within PENTOL, augmentations in step 1
CASES['insitu_layers_contact'] = dict(CASES['insitu_layers'], pentol=1e-9)


def layer_of(case, z):
    """(datum, q, gamma, K0, E, nu) of the layer holding height z."""
    datum, q = case['top'], 0.0
    for bottom, gamma, k0, young, nu in case['layers']:
        if z >= bottom - 1e-12:
            return datum, q, gamma, k0, young, nu
        q += gamma * (datum - bottom)
        datum = bottom
    raise ValueError(z)


def expected_stress(case, z, load):
    datum, q, gamma, k0, _, nu = layer_of(case, z)
    vertical = -(q + gamma * (datum - z))
    horizontal = k0 * vertical - nu / (1.0 - nu) * load
    return np.array([horizontal, horizontal, vertical - load, 0.0, 0.0, 0.0])


def expected_uz(case, z, load):
    """u_z(z) = -load int_0^z dz / M (the layers from the bottom)."""
    total = 0.0
    layers = sorted(((bottom, young, nu) for bottom, _, _, young, nu in case['layers']))
    tops = [b for b, _, _ in layers[1:]] + [case['top']]
    for (bottom, young, nu), top in zip(layers, tops):
        span = max(0.0, min(z, top) - bottom)
        total += span / oedometric(young, nu)
    return -load * total


def check_active(case, stress, region, centres, load, scale, label, check):
    """Mohr-Coulomb from K0 under the oedometric surcharge: horizontal stresses equal, no
    shear, the yielded points on the edge sigma_h = K_a sigma_zz + 2 c sqrt(K_a) (REGION 2), and
    every point yielded at the end of the step."""
    cohesion, phi = case['active']
    k_a = (1.0 - math.sin(phi)) / (1.0 + math.sin(phi))
    error = max(np.abs(stress[:, :, 0] - stress[:, :, 1]).max(), np.abs(stress[:, :, 3:]).max()) / scale
    check(error <= 1e-10, f'{label}: sigma_xx = sigma_yy and no shear, max error {error:.2e}')
    plastic = region > 0
    line = k_a * stress[:, :, 2] + 2.0 * cohesion * math.sqrt(k_a)
    error = np.abs(stress[:, :, 0] - line)[plastic].max() / scale if plastic.any() else 0.0
    check(plastic.any() and np.all(region[plastic] == 2) and error <= 1e-10,
          f'{label}: {plastic.sum()} of {plastic.size} points yielded, all on the edge (REGION 2) at '
          f'sigma_h = K_a sigma_zz + 2 c sqrt(K_a), max error {error:.2e}')
    if load == case['p']:
        check(plastic.all(), f'{label}: every point yielded at the full surcharge')


def vtk_cell_stress(path):
    root = ElementTree.parse(path).getroot()
    for cell_data in root.iter('CellData'):
        for array in cell_data.iter('DataArray'):
            if array.get('Name') == 'stress':
                return np.array(array.text.split(), dtype=float).reshape(-1, 6)
    raise ValueError(f'{path}: no cell stress')


def iterations(out, base):
    text = open(f'{out}/{base}_listing.txt').read()
    return [(int(s), int(i), int(n)) for s, i, n in
            re.findall(r'STEP\s+(\d+)\s+INCREMENT\s+(\d+)\s+TIME\s+\S+\s+ITERATIONS\s+(\d+)', text)]


def main(out, base):
    case = CASES[base]
    failures = []

    def check(ok, message):
        print(('ok   ' if ok else 'FAIL ') + message)
        if not ok:
            failures.append(message)

    gammas = [g for _, g, _, _, _ in case['layers']]
    thickness = [top - bottom for top, (bottom, *_) in
                 zip([case['top']] + [b for b, *_ in case['layers'][:-1]], case['layers'])]
    weight = case['area'] * sum(g * t for g, t in zip(gammas, thickness))
    softest = min(oedometric(young, nu) for *_, young, nu in case['layers'])
    settlement = max(gammas) * case['top'] ** 2 / (2.0 * softest)
    history = np.genfromtxt(f'{out}/{base}_history.csv', delimiter=',', names=True)
    with h5py.File(f'{out}/{base}.h5', 'r') as f:
        x = f['mesh/coordinates'][()]
        connectivity = f['mesh/connectivity'][()] - 1
        shape = np.array([[np.prod(1.0 + GAUSS[a] * POINTS[g]) / 8.0 for a in range(8)] for g in range(8)])
        positions = np.einsum('ga,ead->egd', shape, x[connectivity])   # (n_elements, 8, 3)
        centres = x[connectivity].mean(axis=1)
        for name in sorted(f['increments']):
            group = f['increments'][name]
            step, increment, time = int(group.attrs['step']), int(group.attrs['increment']), float(group.attrs['time'])
            load = case['p'] * max(0.0, min(time - 1.0, 1.0))
            label = f'step {step} increment {increment} (t = {time:g})'
            stress = group['stress'][()]
            expected = np.array([[expected_stress(case, p[2], load) for p in element] for element in positions])
            scale = np.abs(expected).max()
            region = group['history'][()][:, :, 2] if case['plastic'] else None   # REGION of the soil laws
            if 'active' in case and step == 2:
                check_active(case, stress, region, centres, load, scale, label, check)
                expected = np.repeat(expected.mean(axis=1, keepdims=True), 8, axis=1)
                stress = np.repeat(stress.mean(axis=1, keepdims=True), 8, axis=1)[:, :, 2:3]
                expected = expected[:, :, 2:3]
            error = np.abs(stress - expected).max() / scale
            check(error <= 1e-10, f'{label}: stress at the points against the closed form, max error {error:.2e} '
                                  f'of {scale:g}' + (' (the elements\' mean sigma_zz)' if stress.shape[2] == 1 else ''))
            u = group['displacement'][()]
            if 'active' in case and step == 2:
                pass   # plastic: no closed form of the settlement
            elif step == 1:
                size = np.abs(u).max() / settlement
                check(size <= 1e-12, f'{label}: |u| {np.abs(u).max():.2e} = {size:.2e} x the elastic '
                                     f'settlement {settlement:.4g}')
            else:
                uz = np.array([expected_uz(case, z, load) for z in x[:, 2]])
                error = max(np.abs(u[:, :2]).max(), np.abs(u[:, 2] - uz).max()) / abs(expected_uz(case, case['top'], load))
                allowed = max(1e-10, 2.0 * case.get('pentol', 0.0) / abs(expected_uz(case, case['top'], load)))
                check(error <= allowed, f'{label}: reported u against -p z / M, max error {error:.2e} of the top\'s '
                                      f'{expected_uz(case, case["top"], load):.6g}')
            row = history[(history['step'] == step) & (history['increment'] == increment)]
            reaction = float(row[f'r3_sum_{case.get("bottom", "soil")}_zmin'][0])
            target = weight + load * case['area']
            check(abs(reaction - target) <= 1e-11 * target, f'{label}: bottom reaction {reaction:.12g} '
                                                           f'against weight + p A = {target:.12g}')
            if case['plastic'] and not ('active' in case and step == 2):
                check(np.all(region == 0), f'{label}: every point elastic (REGION 0)')
            vtu = f'{out}/{base}_{step:04d}_{increment:04d}.vtu'
            cells = vtk_cell_stress(vtu)
            expected_cells = np.array([expected_stress(case, c[2], load) for c in centres])
            if 'active' in case and step == 2:   # the vertical stress of the elements' mean
                cells, expected_cells = cells[:, 2], expected_cells[:, 2]
            error = np.abs(cells - expected_cells).max() / scale
            check(error <= 1e-9, f'{label}: VTK cell stress (element centre) includes sigma0, max error {error:.2e}')
    steps = iterations(out, base)
    first = [n for s, _, n in steps if s == 1]
    if 'pentol' in case:   # the augmentations of each increment iterate: shown, not checked
        print(f'info step 1: Newton iterations per increment {first} (with the augmentations)')
    else:
        check(len(first) > 0 and all(n == 0 for n in first), f'step 1: Newton iterations per increment {first} '
                                                              '(0: the initial state is in equilibrium)')
    print(f'{base}: {len(failures)} failure(s)')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1], sys.argv[2]))
