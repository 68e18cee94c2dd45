#!/usr/bin/env python3
"""Checks gear recognition on every mesh of a corpus against its generating parameters.

Usage: recognise.py CORPUS_DIR OUTDIR [--gearsim PATH] [--family PREFIX]

Runs `gearsim inspect MESH --json` on each mesh of CORPUS_DIR/corpus.json (generate.py) and compares
what it recognised with what generated the mesh: tooth count, tooth 0 (modulo the pitch), internal
or external, module (0.5 %), pressure angle (0.2°) and base radius (2 µm) — the acceptance figures
of the CAD-gear issue. Writes OUTDIR/recognition.csv (one row per mesh) and OUTDIR/recognition.md
(counts, inspect wall times, the worst deviations, failures grouped by reason, every failure).
--family PREFIX checks only the meshes whose family starts with PREFIX (e.g. freecad). Exit code
0 only when every mesh passes.
"""
import csv
import json
import math
import os
import re
import statistics
import subprocess
import sys
import time

sys.dont_write_bytecode = True
HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, '..', '..'))

MODULE_TOL = 0.005        # relative
ANGLE_TOL_DEG = 0.2
BASE_RADIUS_TOL_MM = 2e-3
TOOTH0_TOL = 0.02         # of a pitch (gearsim's kTooth0Tolerance)


def opt(args, name, default):
    return args[args.index(name) + 1] if name in args else default


def check(mesh, corpus_dir, gearsim):
    path = os.path.join(corpus_dir, mesh['file'])
    row = {'mesh': mesh['name'], 'teeth': mesh['teeth'], 'internal': mesh['internal'], 'module_mm': mesh['module_m'] * 1e3,
           'pressure_angle_deg': mesh['pressure_angle_deg'], 'noise': mesh.get('noise') or '',
           'tessellation': mesh.get('tessellation') or mesh.get('facets') or '', 'why': ''}
    t0 = time.monotonic()
    r = subprocess.run([gearsim, 'inspect', path, '--unit', mesh['unit'], '--json'], capture_output=True, text=True,
                       timeout=600)
    row['inspect_s'] = round(time.monotonic() - t0, 3)
    if r.returncode != 0:
        row['why'] = 'inspect failed: ' + (r.stderr.strip().splitlines() or ['?'])[-1]
        return row
    j = json.loads(r.stdout)
    g = j.get('gear')
    if g is None:
        row['why'] = 'not a prism: ' + j.get('not_prismatic_because', '?')
        return row
    if not g.get('recognised'):
        row['why'] = 'not recognised: ' + g.get('reason', '?')
        return row
    z = mesh['teeth']
    pitch = 360.0 / z
    row['got_teeth'] = g['teeth']
    row['got_internal'] = g['internal']
    d0 = (g['tooth0_deg'] - mesh['tooth0_deg'] + pitch / 2) % pitch - pitch / 2
    row['tooth0_off_pitch'] = d0 / pitch
    row['involute'] = g['involute']
    row['flank_table_departure_um'] = g.get('flank_table', {}).get('departure_um', '')
    why = []
    if g['teeth'] != z:
        why.append('teeth %d' % g['teeth'])
    if g['internal'] != mesh['internal']:
        why.append('internal %s' % g['internal'])
    if abs(d0) > TOOTH0_TOL * pitch:
        why.append('tooth0 off %.3f pitch' % (d0 / pitch))
    if not g['involute']:
        why.append('flanks not involute (rms %.3g/%.3g um)' % (g['flank_ccw']['rms_um'], g['flank_cw']['rms_um']))
    else:
        row['got_module_mm'] = g['module_mm']
        row['got_pressure_angle_deg'] = g['pressure_angle_deg']
        row['base_radius_err_um'] = (g['base_radius_mm'] - mesh['base_radius_m'] * 1e3) * 1e3
        row['module_err'] = g['module_mm'] / (mesh['module_m'] * 1e3) - 1
        row['angle_err_deg'] = g['pressure_angle_deg'] - mesh['pressure_angle_deg']
        if abs(row['module_err']) > MODULE_TOL:
            why.append('module %.4g mm' % g['module_mm'])
        if abs(row['angle_err_deg']) > ANGLE_TOL_DEG:
            why.append('pressure angle %.3f deg' % g['pressure_angle_deg'])
        if abs(row['base_radius_err_um']) > BASE_RADIUS_TOL_MM * 1e3:
            why.append('base radius off %.2f um' % row['base_radius_err_um'])
    row['why'] = '; '.join(why)
    return row


def reason_kind(why):
    """A failure's reason with its figures replaced by #, to group them. A prism refusal is told
    apart by the axis gearsim tried: every corpus mesh is modelled about z, so a normal along z
    means a vertex between the caps, any other normal an axis not found."""
    figures = lambda text: re.sub(r'[-+]?\d+(\.\d+)?(e[-+]?\d+)?', '#', text)  # noqa: E731
    m = re.search(r"face cluster's normal \(([^)]*)\):? ?(.*)", why)
    if m:
        n = [float(x) for x in m.group(1).split(',')]
        if abs(n[2]) > 0.999:
            return 'not a prism along z, the true axis (a vertex between the caps): ' + figures(m.group(2))[:100]
        return 'not a prism along a wrong axis (normal off z): the caps not found'
    return figures(why)[:140]


def main(argv):
    args = argv[1:]
    if len(args) < 2:
        print(__doc__)
        return 2
    corpus_dir, outdir = args[0], args[1]
    gearsim = opt(args, '--gearsim', os.path.join(REPO, 'build', 'bin', 'gearsim'))
    with open(os.path.join(corpus_dir, 'corpus.json')) as f:
        corpus = json.load(f)
    os.makedirs(outdir, exist_ok=True)
    rows = []
    family = opt(args, '--family', '')
    for mesh in [m for m in corpus['meshes'] if m['family'].startswith(family)]:
        rows.append(check(mesh, corpus_dir, gearsim))
        print('%-48s %s' % (mesh['name'], rows[-1]['why'] or 'ok'), flush=True)
    keys = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    with open(os.path.join(outdir, 'recognition.csv'), 'w', newline='') as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)
    failed = [r for r in rows if r['why']]

    def worst(key):
        vals = [abs(r[key]) for r in rows if isinstance(r.get(key), float)]
        return max(vals) if vals else float('nan')
    lines = ['# Gear recognition on %d meshes' % len(rows), '',
             '| figure | worst | limit |', '|---|---|---|',
             '| tooth 0 (fraction of a pitch) | %.2e | %g |' % (worst('tooth0_off_pitch'), TOOTH0_TOL),
             '| module (relative) | %.2e | %g |' % (worst('module_err'), MODULE_TOL),
             '| pressure angle (deg) | %.2e | %g |' % (worst('angle_err_deg'), ANGLE_TOL_DEG),
             '| base radius (um) | %.3f | %g |' % (worst('base_radius_err_um'), BASE_RADIUS_TOL_MM * 1e3), '',
             'Passed: %d of %d.' % (len(rows) - len(failed), len(rows)), '']
    times = sorted(r['inspect_s'] for r in rows)
    if times:
        slowest = max(rows, key=lambda r: r['inspect_s'])
        lines += ['`gearsim inspect` wall time per mesh: median %.2f s, max %.2f s (%s), total %.0f s.'
                  % (statistics.median(times), times[-1], slowest['mesh'], sum(times)), '']
    if failed:
        kinds = {}
        for r in failed:
            kinds.setdefault(reason_kind(r['why']), []).append(r['mesh'])
        lines += ['| reason (figures as #) | meshes | e.g. |', '|---|---|---|']
        lines += ['| %s | %d | %s |' % (k.replace('|', '/'), len(v), v[0])
                  for k, v in sorted(kinds.items(), key=lambda kv: -len(kv[1]))] + ['']
    summary = len(lines)
    if failed:
        lines += ['| mesh | why |', '|---|---|'] + ['| %s | %s |' % (r['mesh'], r['why']) for r in failed]
    with open(os.path.join(outdir, 'recognition.md'), 'w') as f:
        f.write('\n'.join(lines) + '\n')
    print('\n'.join(lines[:summary]))
    return 0 if not failed else 1


if __name__ == '__main__':
    sys.exit(main(sys.argv))
