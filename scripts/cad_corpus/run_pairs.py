#!/usr/bin/env python3
"""Runs every pair of a cad_corpus (generate.py) through `gearsim run` and classifies the outcome.

Usage: run_pairs.py CORPUS_DIR OUT_DIR [--gearsim PATH] [--filter SUBSTR] [--family PREFIX]
                    [--duration S] [--load-ramp S] [--speed RAD_S] [--force-per-module N_PER_MM]
                    [--dt S] [--timeout S] [--keep-logs] [--recognise]

Per pair: OUT_DIR/runs/<pair id>/scenario.yaml, then `gearsim run scenario.yaml --out DIR
--no-analyze` (one run at a time). The driver (pinion) turns at --speed (default 20 rad/s, motor
ramp 0.05 s); the driven gear carries a constant torque T = F·r_b,driven resisting its rotation,
F = --force-per-module × module in mm (default 100 N at m = 1 mm), no viscous part, ramped over
--load-ramp only when it is given. Time step: the largest of 2e-5, 1e-5, 5e-6, 2.5e-6, 1e-6 s with
ω_c·dt ≤ 1, ω_c = √(k/m_eq) the contact frequency estimated from disc inertias (or --dt).

Planetary sets (corpus.json `planetary`, after the pairs): the `planetary:` macro with the sun,
planet and ring meshes, N planets, the ring fixed; the sun driven at --speed, the carrier loaded
with T_c = F·N·r_b,sun·(1 + z_r/z_s), so that each of the 2N meshes carries F. Physical when the
sun–planet meshes' drive-flank minus back-flank forces sum to N·F within 3 %, the planet–ring
meshes' too, the ratio is within 0.1 % of 1 + z_r/z_s, no contact dropped and the deepest
contact is ≤ F/k + 2 µm. --recognise leaves out the meshes' teeth and tooth 0 and the set's
centre_distance_m (gearsim places the planets from the two meshes' zero-backlash distances).
--filter SUBSTR keeps the pairs and sets whose id holds SUBSTR, --family PREFIX those whose
family starts with PREFIX (e.g. freecad).

Classes:
  physical            completed; after the ramp the mean tooth force is within 3 % of T/r_b, no
                      contact was dropped, and the deepest contact is ≤ F/k + 2 µm (k: the pair's
                      stiffness_N_per_m in summary.json, one tooth pair)
  exploded-completed  completed, but not physical (the bad case): `why` says which test failed
  refused             exit 2 before the first step (no summary.json); `message` is gearsim's
  diverged            exit 4, status diverged (summary.json divergence: what, message)
  internal-error, timeout, crashed, other  as the names say
Writes OUT_DIR/results.csv and OUT_DIR/results.md (a row per pair, then counts per class and per
generating parameter, the worst rows, wall time). contacts.csv/state.csv are gzipped unless
--keep-logs.
"""
import csv
import gzip
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, '..', '..'))
DENSITY = 7850.0              # kg/m³, steel
STIFFNESS_PER_FACE = 1.4e10   # N/m per m face width (the scenarios' contact.stiffness_N_per_m_per_m)
MOTOR_RAMP_S = 0.05
FORCE_TOL = 0.03              # share of T/r_b
RATIO_TOL = 1e-3              # planetary sets: relative, mean speeds sun/carrier against 1 + z_r/z_s
PEN_MARGIN_UM = 2.0           # µm above F/k
DT_CHOICES = (2e-5, 1e-5, 5e-6, 2.5e-6, 1e-6)
OMEGA_DT_MAX = 1.0           # ω_c·dt bound of the time-step rule (contact period ≥ 2π steps)
CLASSES = ['physical', 'refused', 'exploded-completed', 'diverged', 'internal-error', 'timeout', 'crashed', 'other']


def opt(args, key, default, conv=str):
    return conv(args[args.index(key) + 1]) if key in args else default


def inertia_kg_m2(mesh):
    """Axial inertia estimate: an external gear as an annulus bore → pitch radius, a ring as an
    annulus pitch radius → rim, face width from the manifest."""
    r = mesh['module_m'] * mesh['teeth'] / 2
    b = mesh['face_width_m']
    if mesh['internal']:
        ro = mesh.get('outer_radius_m') or mesh['generator_args'].get('rim_diameter_m', 2.4 * r) / 2
        ri = r
    else:
        ro = r
        ri = (mesh.get('bore_diameter_m') or mesh['generator_args'].get('bore_diameter_m') or 0.0) / 2
    return DENSITY * math.pi * b * (ro ** 4 - ri ** 4) / 2


def plate_kg(mesh):
    """Mass estimate: a disc of the pitch radius (less its bore), face width from the manifest."""
    r = mesh['module_m'] * mesh['teeth'] / 2
    ri = (mesh.get('bore_diameter_m') or mesh['generator_args'].get('bore_diameter_m') or 0.0) / 2
    return DENSITY * math.pi * mesh['face_width_m'] * (r ** 2 - ri ** 2)


def plan_planetary(st, sun, planet, ring, args):
    """The planetary run's figures: per-mesh force F, carrier load, motor limit, carrier, time step."""
    m, n = sun['module_m'], st['planets']
    F = opt(args, '--force-per-module', 100.0, float) * m * 1e3
    speed = opt(args, '--speed', 20.0, float)
    ratio = 1 + ring['teeth'] / sun['teeth']
    a = m * (sun['teeth'] + planet['teeth']) / 2
    Js, Jp, mp = inertia_kg_m2(sun), inertia_kg_m2(planet), plate_kg(planet)
    # Carrier: a steel plate of radius a and the face width (assumed; the corpus has none).
    mc = DENSITY * math.pi * a ** 2 * sun['face_width_m']
    Jc = mc * a ** 2 / 2
    k = STIFFNESS_PER_FACE * min(sun['face_width_m'], planet['face_width_m'], ring['face_width_m'])
    rbs, rbp = sun['base_radius_m'], planet['base_radius_m']
    # Stiffest modes: the sun on its N meshes with the planets held, a planet between its two meshes.
    omega_c = math.sqrt(k * max(n * rbs ** 2 / Js + rbp ** 2 / Jp, 2 * rbp ** 2 / Jp))
    dt = opt(args, '--dt', None, float)
    if dt is None:
        dt = next((d for d in DT_CHOICES if omega_c * d <= OMEGA_DT_MAX), DT_CHOICES[-1])
    T_sun = n * F * rbs
    accel = speed / MOTOR_RAMP_S
    J_sun_side = Js + n * Jp * (sun['teeth'] / planet['teeth']) ** 2 + (Jc + n * mp * a ** 2) / ratio ** 2
    return dict(F_N=F, T_load=T_sun * ratio, T_max=3 * (T_sun + J_sun_side * accel), speed=speed, dt=dt,
                omega_c=omega_c, k_est=k, carrier_kg=mc, carrier_J=Jc, ratio=ratio, planets=n,
                load_ramp=opt(args, '--load-ramp', None, float), duration=opt(args, '--duration', 0.15, float))


def plan(pair, a, b, args):
    """The run's figures: forces, torques, time step."""
    m = a['module_m']
    F = opt(args, '--force-per-module', 100.0, float) * m * 1e3
    speed = opt(args, '--speed', 20.0, float)
    Ja, Jb = inertia_kg_m2(a), inertia_kg_m2(b)
    k = STIFFNESS_PER_FACE * min(a['face_width_m'], b['face_width_m'])
    m_eq = 1 / (a['base_radius_m'] ** 2 / Ja + b['base_radius_m'] ** 2 / Jb)
    omega_c = math.sqrt(k / m_eq)
    dt = opt(args, '--dt', None, float)
    if dt is None:
        dt = next((d for d in DT_CHOICES if omega_c * d <= OMEGA_DT_MAX), DT_CHOICES[-1])
    T_load = F * b['base_radius_m']
    T_drive = F * a['base_radius_m']
    # Motor limit: 3 × (steady torque + the torque to bring both gears up to speed over the ramp).
    ratio = b['teeth'] / a['teeth']
    accel = speed / MOTOR_RAMP_S
    T_max = 3 * (T_drive + (Ja + Jb / ratio ** 2) * accel)
    return dict(F_N=F, T_load=T_load, T_max=T_max, speed=speed, dt=dt, omega_c=omega_c, k_est=k,
                load_ramp=opt(args, '--load-ramp', None, float), duration=opt(args, '--duration', 0.15, float))


RECOGNISE = False  # --recognise: meshes without teeth/tooth0, pairs without centre distance


def mesh_yaml(mesh, corpus_dir):
    path = os.path.join(corpus_dir, mesh['file'])
    if RECOGNISE:
        return '{file: %s, unit: %s}' % (json.dumps(path), mesh['unit'])
    return '{file: %s, unit: %s, teeth: %d, tooth0_deg: %r}' % (json.dumps(path), mesh['unit'], mesh['teeth'],
                                                                mesh['tooth0_deg'])


def scenario_head(run_id, p, what):
    return ['# cad_corpus %s %s (written by run_pairs.py)' % (what, run_id),
            'name: %s' % json.dumps(run_id), 'duration_s: %r' % p['duration'], 'seed: 0',
            'solver: {time_step_s: %r}' % p['dt'],
            'output: {sample_rate_hz: %r, per_step_log: false}' % float(round(1 / p['dt'])),
            'contact: {stiffness_N_per_m_per_m: %r, damping_ratio: 0.05, friction: 0.05}' % STIFFNESS_PER_FACE]


def planetary_text(st, sun, planet, ring, p, corpus_dir):
    """A planetary set: sun driven, ring fixed (the macro's default), carrier loaded (−T_c about +z)."""
    ramp = ', ramp_time_s: %r' % p['load_ramp'] if p['load_ramp'] is not None else ''
    member = lambda mesh: '{density_kg_m3: %r, mesh: %s}' % (DENSITY, mesh_yaml(mesh, corpus_dir))  # noqa: E731
    body = ['planetary:', '  sun: %s' % member(sun), '  planet: %s' % member(planet), '  ring: %s' % member(ring),
            '  planets: %d' % st['planets'],
            *([] if RECOGNISE else ['  centre_distance_m: %r' % st['centre_distance_m']]),
            '  carrier: {mass_kg: %.6g, inertia_z_kg_m2: %.6g}' % (p['carrier_kg'], p['carrier_J']),
            'motors: [{joint: sun, target_speed_rad_s: %r, ramp_time_s: %r, max_torque_N_m: %.6g}]'
            % (p['speed'], MOTOR_RAMP_S, p['T_max']),
            'loads: [{joint: carrier, constant_torque_N_m: %.9g, viscous_N_m_s_per_rad: 0%s}]' % (-p['T_load'], ramp)]
    return '\n'.join(scenario_head(st['id'], p, 'planetary set') + body) + '\n'


def scenario_text(pair, a, b, p, corpus_dir):
    head = scenario_head(pair['id'], p, 'pair')
    ramp = ', ramp_time_s: %r' % p['load_ramp'] if p['load_ramp'] is not None else ''
    motor = ('motors: [{joint: pinion, target_speed_rad_s: %r, ramp_time_s: %r, max_torque_N_m: %.6g}]'
             % (p['speed'], MOTOR_RAMP_S, p['T_max']))
    # External: the wheel turns the other way (−z), so the resisting torque is +T about +z.
    # Internal (the pair macro puts the ring at the origin, the pinion on +x): both turn +z, the
    # ring's resisting torque is −T.
    driven = 'ring' if pair['internal'] else 'wheel'
    body = ['pair:',
            '  driver: {name: pinion, density_kg_m3: %r, mesh: %s}' % (DENSITY, mesh_yaml(a, corpus_dir)),
            '  driven: {name: %s, density_kg_m3: %r, mesh: %s}' % (driven, DENSITY, mesh_yaml(b, corpus_dir)),
            *([] if RECOGNISE else ['  centre_distance_m: %r' % pair['centre_distance_m']]),
            motor,
            'loads: [{joint: %s, constant_torque_N_m: %.9g, viscous_N_m_s_per_rad: 0%s}]'
            % (driven, -p['T_load'] if pair['internal'] else p['T_load'], ramp)]
    return '\n'.join(head + body) + '\n'


def read_contacts(path):
    """contacts.csv as {pair prefix "a__b": [(t, force_N, tooth_pairs, max_depth_um), …]}."""
    with open(path) as f:
        rows = [r for r in csv.reader(f)]
    head, rows = rows[0], [r for r in rows[1:] if r]
    out = {}
    for fi, h in enumerate(head):
        if h.endswith('_force_N'):
            prefix = h[:-len('_force_N')]
            ni, di = head.index(prefix + '_tooth_pairs'), head.index(prefix + '_max_depth_um')
            out[prefix] = [(float(r[0]), float(r[fi]), float(r[ni]), float(r[di])) for r in rows]
    return out


def mesh_groups(summary, contacts, planets):
    """The meshes judged together: a pair's one mesh, or a planetary set's sun–planet meshes and
    its planet–ring meshes (names "a__b" as in contacts.csv, with their summary records; from
    contacts.csv alone when there is no summary)."""
    pairs = (summary or {}).get('gear_pairs') or [{'a': k.split('__')[0], 'b': k.split('__')[1]} for k in contacts or {}]
    named = [('%s__%s' % (g['a'], g['b']), g) for g in pairs]
    if not planets:
        return [('', named[:1])]
    return [('', [x for x in named if x[1]['a'] == 'sun']), ('ring_', [x for x in named if x[1]['b'] == 'ring'])]


def classify(row, rc, summary, contacts, p, ramp_end, stderr):
    """Fills the row's figures and class from the run's outputs (a pair, or a planetary set when
    p has 'planets': each mesh is judged against F, the sums against N·F)."""
    planets = p.get('planets', 0)
    row['exit'] = rc
    if summary:
        row['status'] = summary.get('status', '')
        row['pen_run_um'] = summary.get('max_penetration_um')
        pairs = summary.get('gear_pairs') or []
        k = min(g['stiffness_N_per_m'] for g in pairs) if pairs else p['k_est']
        row['limit_um'] = p['F_N'] / k * 1e6 + PEN_MARGIN_UM
        warnings = summary.get('warnings', [])
        div = summary.get('divergence')
        dropped = any('dropped' in w for w in warnings) or (div and div.get('what') == 'dropped contacts')
        row['dropped'] = 'yes' if dropped else 'no'
        row['wall_s'] = round(summary.get('wall_seconds', 0), 2)
        if planets and summary.get('ratio') and summary.get('ratio_nominal'):
            row['ratio_err_pct'] = 100 * (summary['ratio'] / summary['ratio_nominal'] - 1)
        if div:
            row['message'] = '%s at t=%.4g s: %s' % (div.get('what'), div.get('time_s', 0), div.get('message', ''))
        elif warnings:
            row['message'] = ' | '.join(warnings)
    groups = mesh_groups(summary, contacts, planets)
    n = max(planets, 1)
    if contacts and groups[0][1]:
        for tag, members in groups:
            series = [contacts[name] for name, _ in members if name in contacts]
            if not series:
                continue
            after = [i for i, c in enumerate(series[0]) if c[0] >= ramp_end - 1e-12]
            if not after:
                continue
            # Mean force per mesh over all flanks (contacts.csv), then drive and back flank apart
            # (gearsim's summary, every step of the steady window): the torque is carried by their
            # difference; without backlash both touch.
            row[tag + 'F_mean_N'] = sum(s[i][1] for s in series for i in after) / (len(after) * len(series))
            row[tag + 'F_err_pct'] = 100 * (row[tag + 'F_mean_N'] / p['F_N'] - 1)
            flanks = [g.get('mean_normal_force_N') for _, g in members]
            if all(flanks):
                drive = [max(f['ccw_flanks_of_a'], f['cw_flanks_of_a']) for f in flanks]
                back = [min(f['ccw_flanks_of_a'], f['cw_flanks_of_a']) for f in flanks]
                row[tag + 'F_drive_N'], row[tag + 'F_back_N'] = sum(drive) / n, sum(back) / n
                net = [d - b for d, b in zip(drive, back)]
                row[tag + 'F_err_pct'] = 100 * (sum(net) / (n * p['F_N']) - 1)
                if planets and not tag:
                    row['share_spread_pct'] = 100 * (max(net) - min(net)) / (sum(net) / n) if sum(net) else None
            if not tag:
                row['tooth_pairs_mean'] = sum(s[i][2] for s in series for i in after) / (len(after) * len(series))
                row['no_contact_share'] = sum(1 for i in after if any(s[i][2] == 0 for s in series)) / len(after)
        every = [c for _, members in groups for name, _ in members for c in contacts.get(name, [])]
        if 'F_mean_N' in row:
            row['pen_after_um'] = max(c[3] for c in every if c[0] >= ramp_end - 1e-12)
        row['pen_before_um'] = max((c[3] for c in every if c[0] < ramp_end), default=0.0)
    if rc == 'timeout':
        row['class'] = 'timeout'
    elif isinstance(rc, int) and rc < 0:
        row['class'] = 'crashed'
        row['message'] = 'signal %d: %s' % (-rc, stderr[-300:])
    elif rc == 2 and not summary:
        row['class'] = 'refused'
        row['message'] = stderr.strip().splitlines()[-1] if stderr.strip() else '(no message)'
    elif rc == 3:
        row['class'] = 'internal-error'
        row['message'] = stderr.strip()[-300:]
    elif rc == 4 or row.get('status') == 'diverged':
        row['class'] = 'diverged'
    elif rc == 0 and row.get('status') == 'completed':
        why = []
        if 'F_mean_N' not in row:
            why.append('no samples after the ramp')
        else:
            if abs(row['F_err_pct']) > 100 * FORCE_TOL:
                why.append('force %+.1f%%' % row['F_err_pct'])
            if planets and abs(row.get('ring_F_err_pct', 0)) > 100 * FORCE_TOL:
                why.append('planet-ring force %+.1f%%' % row['ring_F_err_pct'])
            if planets and abs(row.get('ratio_err_pct', 0)) > 100 * RATIO_TOL:
                why.append('ratio %+.3f%%' % row['ratio_err_pct'])
            if row['pen_after_um'] > row['limit_um']:
                why.append('penetration %.2f > %.2f um' % (row['pen_after_um'], row['limit_um']))
        if row['dropped'] == 'yes':
            why.append('dropped contacts')
        row['why'] = '; '.join(why)
        row['class'] = 'exploded-completed' if why else 'physical'
        # A load applied at t = 0 kicks the driven gear across its backlash before the motor holds:
        # reported, not classified (the class looks at the run after the ramp).
        if row.get('pen_before_um', 0) > row['limit_um']:
            row['note'] = 'start kick: %.2f um before the ramp end' % row['pen_before_um']
    else:
        row['class'] = 'other'
        row['message'] = (row.get('message') or stderr.strip()[-300:])
    return row


def severity(r):
    """How bad a row is, for the worst-rows table: completed-but-wrong first, by its excess."""
    if r['class'] == 'exploded-completed':
        f = abs(r.get('F_err_pct') or 0) / (100 * FORCE_TOL)
        pen = (r.get('pen_after_um') or 0) / (r.get('limit_um') or 1)
        return (3, max(f, pen))
    if r['class'] in ('crashed', 'internal-error', 'timeout', 'other'):
        return (2, 0)
    if r['class'] == 'diverged':
        return (1, r.get('pen_run_um') or 0)
    return (0, 0)


COLUMNS = ['id', 'family', 'internal', 'module_mm', 'pa_deg', 'facets', 'format', 'backlash_mm', 'z_driver', 'z_driven',
           'z_planet', 'planets', 'noise', 'web_holes', 'dt_s', 'omega_c_dt', 'exit', 'status', 'class', 'F_nom_N', 'F_mean_N',
           'F_drive_N', 'F_back_N', 'F_err_pct', 'ring_F_drive_N', 'ring_F_back_N', 'ring_F_err_pct', 'share_spread_pct',
           'ratio_err_pct', 'tooth_pairs_mean', 'no_contact_share', 'pen_after_um', 'pen_before_um', 'pen_run_um', 'limit_um', 'dropped',
           'wall_s', 'why', 'note', 'message']


def fmt(v, digits=3):
    if v is None or v == '':
        return ''
    if isinstance(v, float):
        return '%.*g' % (digits, v)
    return str(v)


def write_results(out_dir, rows, wall, args):
    with open(os.path.join(out_dir, 'results.csv'), 'w', newline='') as f:
        w = csv.DictWriter(f, COLUMNS, extrasaction='ignore')
        w.writeheader()
        for r in rows:
            w.writerow({k: fmt(r.get(k), 6) for k in COLUMNS})
    md = ['# cad_corpus results', '',
          '%d pairs, harness wall %.0f s (%s). Driver %s rad/s, F = %s N per mm of module, load ramp %s, '
          'duration %s s. physical: |(F_drive − F_back)/(T/r_b) − 1| ≤ 3 %% after the ramp (mean normal forces on the '
          'driving and the back flanks), no dropped contacts, '
          'deepest contact after the ramp ≤ F/k + 2 µm.'
          % (len(rows), wall, time.strftime('%Y-%m-%d %H:%M'), opt(args, '--speed', '20'),
             opt(args, '--force-per-module', '100'), opt(args, '--load-ramp', 'none'), opt(args, '--duration', '0.15')),
          '', '## Counts', '']
    counts = {c: sum(1 for r in rows if r['class'] == c) for c in CLASSES}
    md += ['| class | pairs |', '|---|---|'] + ['| %s | %d |' % (c, n) for c, n in counts.items() if n] + ['']
    present = [c for c in CLASSES if counts[c]]
    for key in ('family', 'internal', 'module_mm', 'pa_deg', 'facets', 'format', 'backlash_mm', 'z_driver', 'z_driven',
                'noise', 'web_holes'):
        md += ['### by %s' % key, '', '| %s | %s |' % (key, ' | '.join(present)), '|---' * (len(present) + 1) + '|']
        values = sorted({fmt(r.get(key)) for r in rows}, key=lambda s: (len(s) > 0 and s[0].isdigit(), _num(s), s))
        for v in values:
            sel = [r for r in rows if fmt(r.get(key)) == v]
            md.append('| %s | %s |' % (v or '–', ' | '.join(str(sum(1 for r in sel if r['class'] == c)) for c in present)))
        md.append('')
    refusals = {}
    for r in rows:
        if r['class'] == 'refused':
            kind = _message_kind(r.get('message', ''))
            refusals[kind] = refusals.get(kind, 0) + 1
    if refusals:
        md += ['## Refusals by message', '', '| message (figures as #) | pairs |', '|---|---|']
        md += ['| %s | %d |' % (k.replace('|', '/'), n) for k, n in sorted(refusals.items(), key=lambda kv: -kv[1])] + ['']
    short = ['id', 'class', 'dt_s', 'F_drive_N', 'F_back_N', 'F_err_pct', 'ring_F_err_pct', 'tooth_pairs_mean', 'pen_after_um', 'pen_run_um', 'limit_um',
             'dropped', 'why', 'message']
    worst = sorted([r for r in rows if severity(r)[0] > 0], key=severity, reverse=True)[:10]
    md += ['## Worst rows', '', _table(worst, short), '', '## Every pair', '', _table(rows, short), '']
    open(os.path.join(out_dir, 'results.md'), 'w').write('\n'.join(md))


def _num(s):
    try:
        return float(s)
    except ValueError:
        return 0.0


def _message_kind(msg):
    """The message with its figures replaced by #: groups refusals of the same kind."""
    msg = re.sub(r'^\S*scenario\.yaml:\d+:\d+: ', '', msg.replace('gearsim: error: ', ''))
    msg = re.sub(r'\S*\.(stl|obj|ply)\b', 'FILE', msg)
    return re.sub(r'[-+]?\d+(\.\d+)?(e[-+]?\d+)?', '#', msg)[:200]


def _table(rows, cols):
    out = ['| ' + ' | '.join(cols) + ' |', '|---' * len(cols) + '|']
    for r in rows:
        cells = [fmt(r.get(c)).replace('|', '/').replace('\n', ' ') for c in cols]
        cells[-1] = cells[-1][:220]
        out.append('| ' + ' | '.join(cells) + ' |')
    return '\n'.join(out)


def run_one(gearsim, run_dir, text, timeout):
    """Writes the scenario into a fresh run_dir and runs it; returns (exit code, stdout, stderr,
    summary, contacts)."""
    if os.path.isdir(run_dir):
        shutil.rmtree(run_dir)
    os.makedirs(run_dir)
    scen = os.path.join(run_dir, 'scenario.yaml')
    open(scen, 'w').write(text)
    out = os.path.join(run_dir, 'out')
    try:
        r = subprocess.run([gearsim, 'run', scen, '--out', out, '--no-analyze'], capture_output=True, text=True,
                           timeout=timeout)
        rc, stdout, stderr = r.returncode, r.stdout, r.stderr
    except subprocess.TimeoutExpired as e:
        rc, stdout, stderr = 'timeout', str(e.stdout or ''), str(e.stderr or '')
    open(os.path.join(run_dir, 'stdout.txt'), 'w').write(stdout)
    open(os.path.join(run_dir, 'stderr.txt'), 'w').write(stderr)
    sp = os.path.join(out, 'summary.json')
    summary = json.load(open(sp)) if os.path.exists(sp) else None
    cp = os.path.join(out, 'contacts.csv')
    contacts = read_contacts(cp) if os.path.exists(cp) and os.path.getsize(cp) > 0 else None
    return rc, stdout, stderr, summary, contacts


def gzip_logs(out):
    for name in ('contacts.csv', 'state.csv'):
        f = os.path.join(out, name)
        if os.path.exists(f):
            with open(f, 'rb') as src, gzip.open(f + '.gz', 'wb') as dst:
                shutil.copyfileobj(src, dst)
            os.remove(f)


def main(argv):
    args = argv[1:]
    if len(args) < 2 or args[0].startswith('-'):
        print(__doc__)
        return 2
    corpus_dir, out_dir = os.path.abspath(args[0]), os.path.abspath(args[1])
    gearsim = os.path.abspath(opt(args, '--gearsim', os.path.join(REPO, 'build', 'bin', 'gearsim')))
    timeout = opt(args, '--timeout', 300.0, float)
    global RECOGNISE
    RECOGNISE = '--recognise' in args
    manifest = json.load(open(os.path.join(corpus_dir, 'corpus.json')))
    meshes = {m['name']: m for m in manifest['meshes']}
    keep = lambda x: opt(args, '--filter', '') in x['id'] and x['family'].startswith(opt(args, '--family', ''))  # noqa: E731
    runs = [('pair', x) for x in manifest['pairs'] if keep(x)] + \
           [('planetary', x) for x in manifest.get('planetary', []) if keep(x)]
    os.makedirs(out_dir, exist_ok=True)
    rows, t0 = [], time.monotonic()
    for n, (kind, item) in enumerate(runs):
        run_dir = os.path.join(out_dir, 'runs', item['id'])
        if kind == 'pair':
            a, b = meshes[item['driver']], meshes[item['driven']]
            p = plan(item, a, b, args)
            text = scenario_text(item, a, b, p, corpus_dir)
        else:
            a, planet, b = meshes[item['sun']], meshes[item['planet']], meshes[item['ring']]
            p = plan_planetary(item, a, planet, b, args)
            text = planetary_text(item, a, planet, b, p, corpus_dir)
        rc, stdout, stderr, summary, contacts = run_one(gearsim, run_dir, text, timeout)
        ramp_end = max(MOTOR_RAMP_S, p['load_ramp'] or 0.0)
        noise = a['noise']['mode'] if a.get('noise') else ''
        row = {'id': item['id'], 'family': item['family'],
               'internal': 'planetary' if kind == 'planetary' else 'yes' if item['internal'] else 'no',
               'module_mm': a['module_m'] * 1e3, 'pa_deg': a['pressure_angle_deg'],
               'facets': a['facets'] or a.get('tessellation') or 'gearsim',
               'format': a['format'] if a['format'] == b['format'] else a['format'] + '+' + b['format'],
               'backlash_mm': item.get('backlash_m', 0.0) * 1e3, 'z_driver': a['teeth'], 'z_driven': b['teeth'],
               'z_planet': planet['teeth'] if kind == 'planetary' else '',
               'planets': item['planets'] if kind == 'planetary' else '', 'noise': noise,
               'web_holes': 'yes' if a.get('web_holes') or b.get('web_holes') else 'no',
               'dt_s': p['dt'], 'omega_c_dt': p['omega_c'] * p['dt'], 'F_nom_N': p['F_N']}
        classify(row, rc, summary, contacts, p, ramp_end, stderr)
        rows.append(row)
        if '--keep-logs' not in args:
            gzip_logs(os.path.join(run_dir, 'out'))
        print('[%d/%d] %-70s %-18s %s' % (n + 1, len(runs), item['id'][:70], row['class'],
                                          row.get('why') or (row.get('message') or '')[:100]), flush=True)
        write_results(out_dir, rows, time.monotonic() - t0, args)
    write_results(out_dir, rows, time.monotonic() - t0, args)
    counts = {c: sum(1 for r in rows if r['class'] == c) for c in CLASSES}
    print('done in %.0f s: %s' % (time.monotonic() - t0, ', '.join('%s %d' % kv for kv in counts.items() if kv[1])))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
