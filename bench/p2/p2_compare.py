#!/usr/bin/python3
"""P2 report: reads the frix and CalculiX runs of bench/p2/run_p2.sh and writes the markdown
comparison (and a pressure plot per size).

Usage: p2_compare.py WORKDIR RESULT_MD [--sizes 8 16 24] [--img-prefix PATH]
WORKDIR holds, per size n: p2_n<n>_ids.json (generator), frix_n<n>/ (frix --out),
frix_n<n>.log (frix stdout + GNU time line), p2_n<n>.dat/.sta/.cvg (CalculiX),
ccx_n<n>.log (ccx stdout + GNU time line).

Quantities (all from the codes' own output files):
- reactions: frix listing block REACTIONS summed over the node sets (RX of the upper top =
  force the support exerts, so -RX is the friction force transmitted); CalculiX *NODE PRINT
  TOTALS=ONLY of the same sets (RF, same sign convention: force of the support on the body).
- contact pressure per slave node: frix <base>_contact.csv column pressure; CalculiX
  *CONTACT PRINT CSTR column press (both force per area at the slave node).
- slipping nodes: frix status 2; CalculiX |(tang1, tang2)| >= (1 - 1e-6) mu press (the return
  map puts slipping nodes exactly on the cone).
- Newton iterations per increment: frix listing increment headers; CalculiX .sta ITRS.
- wall time: GNU time elapsed of each run (single thread: OMP_NUM_THREADS=1,
  OPENBLAS_NUM_THREADS=1).
"""
import argparse
import csv
import json
import math
import os
import re

import numpy as np


def read_time(log):
    """(wall s, max RSS MB, user + sys CPU s) from the GNU time line."""
    wall = (float('nan'), float('nan'), float('nan'))
    with open(log) as f:
        for line in f:
            m = re.match(r'^wall ([0-9.]+) s rss ([0-9]+) kB(?: user ([0-9.]+) s sys ([0-9.]+) s)?',
                         line)
            if m:
                cpu = float(m.group(3)) + float(m.group(4)) if m.group(3) else float('nan')
                wall = (float(m.group(1)), float(m.group(2)) / 1024.0, cpu)
    return wall


def read_frix(work, n):
    base = os.path.join(work, 'frix_n%d' % n, 'p2_n%d' % n)
    out = {'increments': [], 'reactions': {}, 'stats': {}}
    with open(os.path.join(work, 'frix_n%d.log' % n)) as f:
        for line in f:
            m = re.match(r'^frix: stat (\S+)\s+(\S+)', line)
            if m:
                out['stats'][m.group(1)] = float(m.group(2))
    out['wall'], out['rss'], out['cpu'] = read_time(os.path.join(work, 'frix_n%d.log' % n))
    # listing: increment headers, iteration logs, reactions
    current = None
    block = None
    with open(base + '_listing.txt') as f:
        for line in f:
            if line.startswith('#') or not line.strip():
                continue
            if not line.startswith(' '):
                m = re.match(r'STEP\s+(\d+)\s+INCREMENT\s+(\d+)\s+TIME\s+(\S+)\s+ITERATIONS\s+'
                             r'(\d+)', line)
                if m:
                    current = {'step': int(m.group(1)), 'increment': int(m.group(2)),
                               'time': float(m.group(3)), 'iterations': int(m.group(4)),
                               'log': [], 'reactions': {}}
                    out['increments'].append(current)
                    block = None
                else:
                    block = line.strip()
                continue
            tokens = line.split()
            if not re.match(r'^-?\d+$', tokens[0]):
                continue        # column header
            if block == 'ITERATION LOG':
                current['log'].append((int(tokens[0]), float(tokens[1]), float(tokens[2]),
                                       float(tokens[3])))
            elif block and block.startswith('REACTIONS'):
                current['reactions'][int(tokens[0])] = [float(t) for t in tokens[1:4]]
    # contact csv
    out['contact'] = {}
    with open(base + '_contact.csv') as f:
        for row in csv.DictReader(f):
            key = round(float(row['time']), 6)
            out['contact'].setdefault(key, {})[int(row['node'])] = (
                float(row['pressure']), float(row['traction_x']), float(row['traction_y']),
                int(row['status']))
    return out


def read_ccx(work, n):
    base = os.path.join(work, 'p2_n%d' % n)
    out = {'increments': [], 'totals': {}, 'contact': {}, 'cvg': []}
    out['wall'], out['rss'], out['cpu'] = read_time(os.path.join(work, 'ccx_n%d.log' % n))
    with open(base + '.sta') as f:
        for line in f:
            tokens = line.split()
            if len(tokens) == 7 and tokens[0].isdigit():
                out['increments'].append({'step': int(tokens[0]), 'increment': int(tokens[1]),
                                          'attempt': int(tokens[2]),
                                          'iterations': int(tokens[3]),
                                          'time': float(tokens[4])})
    with open(base + '.cvg') as f:
        for line in f:
            tokens = line.split()
            if len(tokens) == 9 and tokens[0].isdigit():
                out['cvg'].append((int(tokens[0]), int(tokens[1]), int(tokens[2]),
                                   int(tokens[3]), int(tokens[4]), float(tokens[5]),
                                   float(tokens[6])))
    mode = None
    with open(base + '.dat') as f:
        for line in f:
            m = re.match(r'\s*total force \(fx,fy,fz\) for set (\S+) and time\s+(\S+)', line)
            if m:
                mode = ('total', m.group(1), round(float(m.group(2)), 6))
                continue
            m = re.match(r'\s*contact stress .* and time\s+(\S+)', line)
            if m:
                mode = ('cstr', round(float(m.group(1)), 6))
                out['contact'][mode[1]] = {}
                continue
            if re.match(r'\s*[a-z]', line):
                mode = None
                continue
            tokens = line.split()
            if not tokens or mode is None:
                continue
            if mode[0] == 'total' and len(tokens) == 3:
                out['totals'][(mode[1], mode[2])] = [float(t) for t in tokens]
            elif mode[0] == 'cstr' and len(tokens) == 4:
                # CalculiX prints the shear as slave-minus-master relative-displacement
                # direction times the stick slope, i.e. the traction on the MASTER; the
                # traction on the slave (as frix prints it) is its negative.
                out['contact'][mode[1]][int(tokens[0])] = (
                    float(tokens[1]), -float(tokens[2]), -float(tokens[3]))
    return out


def frix_sum(inc, nodes, component):
    return sum(inc['reactions'].get(i, [0.0, 0.0, 0.0])[component] for i in nodes)


def pressure_stats(frix_p, ccx_p, ids):
    """frix_p: node -> (p, tx, ty, status); ccx_p: node -> (p, tx, ty)."""
    slaves = ids['slave_nodes']
    pf = np.array([frix_p[i][0] if i in frix_p else 0.0 for i in slaves])
    pc = np.array([ccx_p[i][0] if i in ccx_p else 0.0 for i in slaves])
    tf = np.array([math.hypot(frix_p[i][1], frix_p[i][2]) if i in frix_p else 0.0
                   for i in slaves])
    tc = np.array([math.hypot(ccx_p[i][1], ccx_p[i][2]) if i in ccx_p else 0.0 for i in slaves])
    mu = ids['mu']
    slip_f = sum(1 for i in slaves if i in frix_p and frix_p[i][3] == 2)
    slip_c = int(np.sum((pc > 0) & (tc >= (1 - 1e-6) * mu * pc)))
    centre = ids['centre_row'][len(ids['centre_row']) // 2]
    k = slaves.index(centre)
    return {'mean_f': pf.mean(), 'mean_c': pc.mean(), 'max_f': pf.max(), 'max_c': pc.max(),
            'centre_f': pf[k], 'centre_c': pc[k], 'dmax': np.max(np.abs(pf - pc)),
            'tmax_f': tf.max(), 'tmax_c': tc.max(), 'dtmax': np.max(np.abs(tf - tc)),
            'slip_f': slip_f, 'slip_c': slip_c, 'n_slave': len(slaves),
            'closed_f': int(np.sum(pf > 0)), 'closed_c': int(np.sum(pc > 0))}


def orders(r):
    """Estimated convergence orders q_k = log(r_{k+1}/r_k)/log(r_k/r_{k-1}) of a decreasing
    error sequence r (pairs where r does not decrease are skipped)."""
    rates = []
    for k in range(1, len(r) - 1):
        if r[k] < r[k - 1] and r[k + 1] < r[k]:
            rates.append(math.log(r[k + 1] / r[k]) / math.log(r[k] / r[k - 1]))
    return rates


def quadratic_rates(log, floor=1e-11):
    """Orders of the relative residual norms, over the rows above the round-off floor."""
    return orders([row[2] for row in log if row[2] > floor])


def energy_rates(log, floor=1e-20):
    """Orders of the energy-norm error: sqrt(energy) of iteration k + 1 is |du . r|^(1/2) of the
    full Newton correction made from iterate k, i.e. the K^-1 norm of r_k (the error of
    iterate k in the energy norm when K is the exact tangent); rows whose energy has fallen
    below floor x the first one are round-off and dropped."""
    e = [row[3] for row in log[1:]]
    if not e or e[0] <= 0.0:
        return []
    return orders([math.sqrt(x) for x in e if x > floor * e[0]])


def plot_pressure(frix, ccx, ids, times, path):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    row = ids['centre_row']
    fig, axes = plt.subplots(1, len(times), figsize=(4.2 * len(times), 3.4), sharey=True)
    for ax, t in zip(axes, times):
        xf = []
        # x of the slave nodes of the centre row: from the frix csv (current x) is not the
        # reference one; use the generator's layout: 0.2 + 0.6 i / m
        m = len(row) - 1
        xs = [0.2 + 0.6 * i / m for i in range(m + 1)]
        pf = [frix['contact'][t][i][0] for i in row]
        pc = [ccx['contact'][t][i][0] if i in ccx['contact'][t] else 0.0 for i in row]
        tf = [frix['contact'][t][i][1] for i in row]
        tc = [ccx['contact'][t][i][1] if i in ccx['contact'][t] else 0.0 for i in row]
        ax.plot(xs, pf, 'o-', label='frix p')
        ax.plot(xs, pc, 's--', label='CalculiX p')
        ax.plot(xs, tf, 'o-', label='frix t_x')
        ax.plot(xs, tc, 's--', label='CalculiX t_x')
        ax.set_title('n = %d, t = %g' % (ids['n'], t))
        ax.set_xlabel('x (mm), row y = %.3f' % (0.2 + 0.6 * (len(row) // 2) / m))
        ax.grid(True, alpha=0.3)
    axes[0].set_ylabel('contact stress on the slave (MPa)')
    axes[-1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('work')
    parser.add_argument('result')
    parser.add_argument('--sizes', type=int, nargs='+', default=[8, 16, 24])
    parser.add_argument('--img-prefix', default=None)
    parser.add_argument('--machine', default=None)
    args = parser.parse_args()
    lines = []
    add = lines.append
    add('# P2 results: stacked blocks with frictional contact, frix vs CalculiX\n')
    add('Generated by `bench/p2/run_p2.sh` (`bench/p2/p2_compare.py`); setup and discussion in '
        '`docs/performance-p2.md`.\n')
    if args.machine and os.path.exists(args.machine):
        add('## Machine\n')
        add('```')
        add(open(args.machine).read().rstrip())
        add('```\n')
    summary = []
    details = []
    for n in args.sizes:
        ids = json.load(open(os.path.join(args.work, 'p2_n%d_ids.json' % n)))
        try:
            frix = read_frix(args.work, n)
        except (OSError, ValueError) as exc:
            summary.append((n, ids, None, None, 'frix output missing: %s' % exc))
            continue
        try:
            ccx = read_ccx(args.work, n)
        except (OSError, ValueError) as exc:
            ccx = None
        summary.append((n, ids, frix, ccx, None))

    add('## Size, time, Newton iterations\n')
    add('Times: wall = elapsed, cpu = user + sys (GNU time); on a shared 2-core machine the '
        'CPU time is the comparable one. s/iter = cpu / Newton iterations.\n')
    add('| n (lower) | upper | nodes | frix equations | frix wall / cpu (s) | frix iters | '
        'frix s/iter | frix MB | CalculiX wall / cpu (s) | CalculiX iters | CalculiX s/iter | '
        'CalculiX MB |')
    add('|---|---|---|---|---|---|---|---|---|---|---|---|')
    for n, ids, frix, ccx, problem in summary:
        if frix is None:
            add('| %d | | | | %s | | | | | |' % (n, problem))
            continue
        fit = sum(inc['iterations'] for inc in frix['increments'])
        cit = sum(inc['iterations'] for inc in ccx['increments']) if ccx else 0
        add('| %s | %s | %d | %d | %.1f / %.1f | %d | %.3f | %.0f | %s | %s | %s | %s |' % (
            'x'.join(str(d) for d in ids['lower_divisions']),
            'x'.join(str(d) for d in ids['upper_divisions']), ids['nodes'],
            frix['stats'].get('equations', 0), frix['wall'], frix['cpu'], fit,
            frix['cpu'] / max(fit, 1), frix['rss'],
            '%.1f / %.1f' % (ccx['wall'], ccx['cpu']) if ccx else '-', cit if ccx else '-',
            '%.3f' % (ccx['cpu'] / max(cit, 1)) if ccx else '-',
            '%.0f' % ccx['rss'] if ccx else '-'))
    add('')
    add('Iterations per increment (step.increment: frix / CalculiX):\n')
    add('| n | ' + ' | '.join('%d.%d' % (inc['step'], inc['increment'])
                             for inc in summary[0][2]['increments']) + ' |')
    add('|---|' + '---|' * len(summary[0][2]['increments']))
    for n, ids, frix, ccx, problem in summary:
        if frix is None:
            continue
        cells = []
        for k, inc in enumerate(frix['increments']):
            c = [x for x in (ccx['increments'] if ccx else [])
                 if abs(x['time'] - inc['time']) < 1e-9]
            cells.append('%d / %s' % (inc['iterations'],
                                      '+'.join(str(x['iterations']) for x in c) or '-'))
        add('| %d | %s |' % (n, ' | '.join(cells)))
    add('')
    add('frix time split (s): assembly / symbolic analysis / numeric factorization / solve / '
        'total (frix `stat` lines):\n')
    add('| n | assembly | analyse | factorize | solve | total | factorizations | factor nnz | '
        'peak MB |')
    add('|---|---|---|---|---|---|---|---|---|')
    for n, ids, frix, ccx, problem in summary:
        if frix is None:
            continue
        s = frix['stats']
        add('| %d | %.2f | %.2f | %.2f | %.2f | %.2f | %d | %d | %.0f |' % (
            n, s.get('assembly_seconds', 0), s.get('analyse_seconds', 0),
            s.get('factorize_seconds', 0), s.get('solve_seconds', 0),
            s.get('total_seconds', 0), s.get('factorizations', 0),
            s.get('factor_nonzeros', 0), s.get('peak_memory_mb', 0)))
    add('')

    add('## Reactions and contact stresses\n')
    add('Applied: q A = %g x 0.36 = %.3f N downward; full sliding limit mu q A = %.3f N.\n'
        % (summary[0][1]['pressure'], summary[0][1]['pressure'] * 0.36,
           summary[0][1]['mu'] * summary[0][1]['pressure'] * 0.36))
    add('| n | t | code | RZ base (N) | -RX top (N) | node mean p | max p | p centre | '
        'max shear | closed/slave | slip |')
    add('|---|---|---|---|---|---|---|---|---|---|---|')
    diffs = []
    for n, ids, frix, ccx, problem in summary:
        if frix is None:
            continue
        for t in (1.0, 2.0):
            inc = [x for x in frix['increments'] if abs(x['time'] - t) < 1e-9][0]
            rz = frix_sum(inc, ids['lower_bottom'], 2)
            rx = frix_sum(inc, ids['upper_top'], 0)
            if ccx and (t in ccx['contact']):
                st = pressure_stats(frix['contact'][t], ccx['contact'][t], ids)
                crz = ccx['totals'][('LOWER_BOTTOM', t)][2]
                crx = ccx['totals'][('UPPER_TOP', t)][0]
            else:
                st = pressure_stats(frix['contact'][t], {}, ids)
                crz = crx = float('nan')
            add('| %d | %g | frix | %.5f | %.5f | %.4f | %.4f | %.4f | %.4f | %d/%d | %d |' % (
                n, t, rz, -rx, st['mean_f'], st['max_f'], st['centre_f'], st['tmax_f'],
                st['closed_f'], st['n_slave'], st['slip_f']))
            add('| | | CalculiX | %.5f | %.5f | %.4f | %.4f | %.4f | %.4f | %d/%d | %d |' % (
                crz, -crx, st['mean_c'], st['max_c'], st['centre_c'], st['tmax_c'],
                st['closed_c'], st['n_slave'], st['slip_c']))
            # relative difference of the friction force only where there is one (at t = 1
            # both RX are round-off around 0: their ratio means nothing)
            limit = 1e-6 * ids['mu'] * ids['pressure'] * ids['slave_area']
            diffs.append((n, t, st['dmax'], st['dtmax'],
                          (rx - crx) / crx if abs(crx) > limit else float('nan'), rx - crx))
    add('')
    add('Largest nodal difference frix - CalculiX over the slave nodes (MPa; q = %g) and '
        'relative difference of the friction force:\n' % summary[0][1]['pressure'])
    add('| n | t | max abs dp | max abs d(shear) | d(RX) (N) | d(RX)/RX |')
    add('|---|---|---|---|---|---|')
    for n, t, dp, dt, drx, arx in diffs:
        add('| %d | %g | %.4f | %.4f | %+.1e | %s |' % (
            n, t, dp, dt, arx, '-' if math.isnan(drx) else '%+.2e' % drx))
    add('')
    add('Friction force -RX of the upper top (N) at every increment of step 2, frix / CalculiX '
        '(relative difference):\n')
    times = [inc['time'] for inc in summary[0][2]['increments'] if inc['step'] == 2]
    add('| n | ' + ' | '.join('t = %g' % t for t in times) + ' |')
    add('|---|' + '---|' * len(times))
    for n, ids, frix, ccx, problem in summary:
        if frix is None or not ccx:
            continue
        cells = []
        for t in times:
            inc = [x for x in frix['increments'] if abs(x['time'] - t) < 1e-9]
            key = ('UPPER_TOP', round(t, 6))
            if not inc or key not in ccx['totals']:
                cells.append('-')
                continue
            rx = frix_sum(inc[0], ids['upper_top'], 0)
            crx = ccx['totals'][key][0]
            cells.append('%.5f / %.5f (%+.1e)' % (-rx, -crx, (rx - crx) / crx))
        add('| %d | %s |' % (n, ' | '.join(cells)))
    add('')

    add('## Newton convergence (frix ITERATION LOG, relative residual norms)\n')
    for n, ids, frix, ccx, problem in summary:
        if frix is None:
            continue
        add('### n = %d\n' % n)
        add('| incr | relative residual norms, ITER 0, 1, ... | orders (residual) | '
            'energy norms sqrt(abs(du . r)), ITER 1, 2, ... | orders (energy) |')
        add('|---|---|---|---|---|')
        for inc in frix['increments']:
            add('| %d.%d | %s | %s | %s | %s |' % (
                inc['step'], inc['increment'],
                ' '.join('%.1e' % row[2] for row in inc['log']),
                ' '.join('%.2f' % q for q in quadratic_rates(inc['log'])),
                ' '.join('%.1e' % math.sqrt(row[3]) for row in inc['log'][1:]),
                ' '.join('%.2f' % q for q in energy_rates(inc['log']))))
        add('')
        if ccx:
            add('CalculiX (.cvg: largest residual force in % of the mean force, per '
                'iteration):\n')
            add('| incr | RESID. FORCE (%) per iteration | contact elements |')
            add('|---|---|---|')
            keys = sorted(set((r[0], r[1], r[2]) for r in ccx['cvg']))
            for key in keys:
                rows = [r for r in ccx['cvg'] if (r[0], r[1], r[2]) == key]
                add('| %d.%d (att %d) | %s | %s |' % (
                    key[0], key[1], key[2], ' '.join('%.1e' % r[5] for r in rows),
                    ' '.join(str(r[4]) for r in rows)))
            add('')
        if args.img_prefix and ccx:
            path = '%s_n%d_pressure.png' % (args.img_prefix, n)
            plot_pressure(frix, ccx, ids, [1.0, 2.0], path)
            add('![contact stresses n = %d](%s)\n' % (n, os.path.basename(path)))
    with open(args.result, 'w') as f:
        f.write('\n'.join(lines) + '\n')


if __name__ == '__main__':
    main()
