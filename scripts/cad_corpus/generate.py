#!/usr/bin/env python3
"""Generates the third-party CAD gear corpus and its manifest (corpus.json).

Usage: generate.py OUTDIR [--small] [--gearsim PATH] [--openscad PATH]

Meshes (all in mm, plain spur prisms):
  - OpenSCAD MCAD external gears (Debian openscad-mcad, involute_gears.scad `gear(..., flat=true)`,
    extruded by linear_extrude): a 6×6 Latin square of (module 1|4, pressure angle 14.5|20|25) ×
    (involute_facets 5|24|48, binary|ASCII STL) → 36 groups, each with one tooth-count pair from
    12–80 and both backlash 0 and 0.05 mm: 4 meshes and 4 pairs per group;
  - MCAD rings: a disc minus MCAD's `gear_shape` of the ring's tooth count, in two conventions
    (`mcad`: the radii MCAD's `gear` uses, ring tip at the cutter's root r − 1.25·m, ring root at
    its tip r + m; `relieved`: ring tip r − 0.8·m, ring root r + 1.25·m), each with an MCAD pinion;
  - gearsim's own gears (`gearsim gears SPEC --out DIR`) read back as binary STL, OBJ and (module 1,
    20°) ASCII STL, module 1–4, up to 80 teeth, plus gearsim rings (h_a* 1 and 0.8);
  - noisy copies: ±0.5 µm uniform noise per coordinate, in-plane (one draw per outline vertex,
    shared by its top and bottom copies: still a prism) or 3D (one draw per vertex and axis).
--small writes 8 meshes (MCAD z17/z24 binary and ASCII, gearsim z18/z24, a noisy MCAD pair) and
4 pairs, for a ctest slice. Deterministic: same inputs, same files (noise seeded per mesh name).
"""
import json
import math
import os
import subprocess
import sys
import time
import zlib

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import stl_io  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, '..', '..'))
NOISE_MM = 0.5e-3               # ±0.5 µm, in the meshes' unit (mm)
FACE_PER_MODULE = 6.0           # face width = 6·m (6 mm at m = 1, 24 mm at m = 4)
TOOTH_PAIRS = [(12, 36), (17, 55), (24, 80), (12, 80), (17, 24), (36, 55)]  # each count twice
MODULE_PA = [(1, 14.5), (1, 20), (1, 25), (4, 14.5), (4, 20), (4, 25)]        # Latin-square rows
FACETS_FMT = [(f, fmt) for f in (5, 24, 48) for fmt in ('stl-binary', 'stl-ascii')]  # columns
FMT_TAG = {'stl-binary': 'bin', 'stl-ascii': 'asc', 'obj': 'obj'}
SCAD_FMT = {'stl-binary': 'binstl', 'stl-ascii': 'asciistl'}


def tag(x):
    """14.5 → '14p5', 0.05 → '0p05', 20.0 → '20' (for file names)."""
    s = ('%g' % x).replace('.', 'p')
    return s


class Corpus:
    def __init__(self, outdir, openscad, gearsim):
        self.outdir, self.openscad, self.gearsim = outdir, openscad, gearsim
        self.meshes, self.pairs, self.by_name = [], [], {}
        self.pair_keys = set()

    def add_mesh(self, rec):
        self.meshes.append(rec)
        self.by_name[rec['name']] = rec
        return rec

    def add_pair(self, driver, driven, note=''):
        a, b = self.by_name[driver], self.by_name[driven]
        if (driver, driven) in self.pair_keys:
            return
        self.pair_keys.add((driver, driven))
        assert a['module_m'] == b['module_m'] and a['pressure_angle_deg'] == b['pressure_angle_deg']
        m, internal = a['module_m'], a['internal'] or b['internal']
        if internal:
            ring, pin = (a, b) if a['internal'] else (b, a)
            centre = m * (ring['teeth'] - pin['teeth']) / 2
        else:
            centre = m * (a['teeth'] + b['teeth']) / 2
        self.pairs.append({
            'id': 'P%03d_%s__%s' % (len(self.pairs), driver, driven),
            'driver': driver, 'driven': driven, 'internal': internal,
            'centre_distance_m': centre,
            # Circular backlash at the pitch circle: each mesh's tooth is thinned by backlash/2.
            'backlash_m': (a['backlash_m'] + b['backlash_m']) / 2,
            'family': a['family'] if not internal else ('mcad-ring' if a['tool'] == b['tool'] == 'openscad-mcad' else 'gearsim-ring'),
            'note': note,
        })

    # --- MCAD -------------------------------------------------------------------------------
    def run_openscad(self, scad_text, stem, fmt):
        scad_dir = os.path.join(self.outdir, 'scad')
        os.makedirs(scad_dir, exist_ok=True)
        scad = os.path.join(scad_dir, stem + '.scad')
        open(scad, 'w').write(scad_text)
        out = os.path.join(self.outdir, 'mcad', stem + '.stl')
        os.makedirs(os.path.dirname(out), exist_ok=True)
        r = subprocess.run([self.openscad, '-o', out, '--export-format', SCAD_FMT[fmt], scad],
                           capture_output=True, text=True)
        if r.returncode != 0 or not os.path.exists(out):
            raise SystemExit('openscad failed on %s:\n%s' % (scad, r.stderr))
        return os.path.relpath(out, self.outdir)

    def mcad_gear(self, m, pa, facets, fmt, z, backlash_mm, holes=False):
        """An MCAD external gear (dedup by its parameters); returns its mesh name."""
        name = 'mcad_m%s_z%d_a%s_f%d_b%s_%s%s' % (tag(m), z, tag(pa), facets, tag(backlash_mm), FMT_TAG[fmt],
                                                  '_web' if holes else '')
        if name in self.by_name:
            return name
        r = m * z / 2.0
        face = FACE_PER_MODULE * m
        root_d = 2 * (r - 1.25 * m)
        bore = max(1.0, round(0.25 * root_d / m) * m)
        circles = 5 if holes else 0
        hub_d, rim_width = bore + 4 * m, 3 * m
        args = dict(number_of_teeth=z, circular_pitch=180.0 * m, pressure_angle=pa, clearance=0.25 * m,
                    gear_thickness=face, rim_thickness=face, hub_thickness=face, rim_width=rim_width,
                    hub_diameter=hub_d, bore_diameter=bore, circles=circles, backlash=backlash_mm,
                    involute_facets=facets)
        text = ('// %s: MCAD gear, 2D (flat=true) then extruded: a plain spur prism\n'
                'use <MCAD/involute_gears.scad>\n$fn = 48;  // bore and web holes; teeth use involute_facets\n'
                'linear_extrude(height=%r, convexity=10)\n  gear(%s, flat=true);\n'
                % (name, face, ', '.join('%s=%r' % kv for kv in args.items())))
        path = self.run_openscad(text, name, fmt)
        self.add_mesh({
            'name': name, 'file': path, 'family': 'mcad', 'tool': 'openscad-mcad', 'teeth': z,
            'module_m': m * 1e-3, 'pressure_angle_deg': pa, 'backlash_m': backlash_mm * 1e-3,
            'facets': facets, 'internal': False, 'format': fmt, 'unit': 'mm',
            'face_width_m': face * 1e-3, 'bore_diameter_m': bore * 1e-3, 'web_holes': circles,
            'base_radius_m': r * math.cos(math.radians(pa)) * 1e-3,
            'tip_radius_m': (r + m) * 1e-3, 'root_radius_m': (r - 1.25 * m) * 1e-3,
            'tooth0_deg': 0.0, 'noise': None, 'generator_args': args,
        })
        return name

    def mcad_ring(self, m, pa, facets, fmt, z, backlash_mm, convention):
        """A disc minus MCAD's gear_shape of z teeth. The cutter is thickened by backlash/2 at the
        pitch circle (MCAD backlash argument −backlash), so the ring's teeth are thinned by it."""
        name = 'mcadring_m%s_z%d_a%s_f%d_b%s_%s_%s' % (tag(m), z, tag(pa), facets, tag(backlash_mm), convention,
                                                       FMT_TAG[fmt])
        if name in self.by_name:
            return name
        r = m * z / 2.0
        face = FACE_PER_MODULE * m
        if convention == 'mcad':     # the radii MCAD's gear() gives its tooth: addendum m, dedendum 1.25·m
            cutter_root, cutter_tip = r - 1.25 * m, r + m
        else:                         # 'relieved': ring addendum 0.8·m, ring dedendum 1.25·m
            cutter_root, cutter_tip = r - 0.8 * m, r + 1.25 * m
        outer = r + 6 * m
        mcad_backlash = -backlash_mm
        half_thick = (360.0 / z - mcad_backlash / r * 180 / math.pi) / 4
        args = dict(number_of_teeth=z, pitch_radius=r, root_radius=cutter_root,
                    base_radius=r * math.cos(math.radians(pa)), outer_radius=cutter_tip,
                    half_thick_angle=half_thick, involute_facets=facets)
        text = ('// %s: a disc of radius %r minus MCAD gear_shape (an internal gear), extruded\n'
                'use <MCAD/involute_gears.scad>\n'
                'linear_extrude(height=%r, convexity=10)\n  difference() {\n    circle(r=%r, $fn=%d);\n'
                '    gear_shape(%s);\n  }\n'
                % (name, outer, face, outer, max(96, 2 * z), ', '.join('%s=%r' % kv for kv in args.items())))
        path = self.run_openscad(text, name, fmt)
        self.add_mesh({
            'name': name, 'file': path, 'family': 'mcad-ring', 'tool': 'openscad-mcad', 'teeth': z,
            'module_m': m * 1e-3, 'pressure_angle_deg': pa, 'backlash_m': backlash_mm * 1e-3,
            'facets': facets, 'internal': True, 'format': fmt, 'unit': 'mm',
            'face_width_m': face * 1e-3, 'outer_radius_m': outer * 1e-3, 'ring_convention': convention,
            'base_radius_m': r * math.cos(math.radians(pa)) * 1e-3,
            'tip_radius_m': cutter_root * 1e-3, 'root_radius_m': cutter_tip * 1e-3,
            # Tooth 0 of the cutter is on +x, so a ring gap is there and ring tooth 0 half a pitch on.
            'tooth0_deg': 180.0 / z, 'noise': None,
            'generator_args': dict(args, mcad_backlash_argument=mcad_backlash, disc_radius=outer),
        })
        return name

    # --- gearsim's own ------------------------------------------------------------------------
    def gearsim_set(self, m, pa, gears, formats):
        """gears: list of (name, kind, teeth, extra spec keys). Writes a spec, runs gearsim gears."""
        spec_name = 'gs_m%s_a%s' % (tag(m), tag(pa))
        d = os.path.join(self.outdir, 'gearsim')
        os.makedirs(d, exist_ok=True)
        face = FACE_PER_MODULE * m
        lines = ['# cad_corpus: gearsim\'s own gears, read back from STL/OBJ by run_pairs.py',
                 'name: %s' % spec_name, 'density_kg_m3: 7850', 'defaults:',
                 '  module_m: %r' % (m * 1e-3), '  pressure_angle_deg: %r' % pa,
                 '  face_width_m: %r' % (face * 1e-3), 'gears:']
        for gname, kind, z, extra in gears:
            keys = ', '.join(['kind: %s' % kind, 'teeth: %d' % z] + ['%s: %r' % kv for kv in extra.items()])
            lines.append('  %s: {%s}' % (gname, keys))
        spec = os.path.join(d, spec_name + '.yaml')
        open(spec, 'w').write('\n'.join(lines) + '\n')
        out = os.path.join(d, spec_name)
        fm = {'stl-binary': 'stl', 'stl-ascii': 'stl-ascii', 'obj': 'obj'}
        r = subprocess.run([self.gearsim, 'gears', spec, '--out', out, '--json', '--formats'] +
                           [fm[f] for f in formats], capture_output=True, text=True)
        if r.returncode != 0:
            raise SystemExit('gearsim gears failed on %s (exit %d):\n%s' % (spec, r.returncode, r.stderr))
        table = json.load(open(os.path.join(out, 'gearset.json')))['gears']
        ext = {'stl-binary': '.stl', 'stl-ascii': '.ascii.stl', 'obj': '.obj'}
        for gname, kind, z, extra in gears:
            g = table[gname]
            for fmt in formats:
                name = '%s_%s_%s' % (spec_name, gname, FMT_TAG[fmt])
                internal = kind == 'internal'
                self.add_mesh({
                    'name': name, 'file': os.path.relpath(os.path.join(out, gname + ext[fmt]), self.outdir),
                    'family': 'gearsim-ring' if internal else 'gearsim', 'tool': 'gearsim', 'teeth': z,
                    'module_m': m * 1e-3, 'pressure_angle_deg': pa, 'backlash_m': 0.0, 'facets': None,
                    'internal': internal, 'format': fmt, 'unit': 'mm', 'face_width_m': face * 1e-3,
                    'base_radius_m': g['base_diameter_m'] / 2, 'tip_radius_m': g['tip_diameter_m'] / 2,
                    'root_radius_m': g['root_diameter_m'] / 2, 'tooth0_deg': 0.0, 'noise': None,
                    'generator_args': dict(extra, spec=os.path.relpath(spec, self.outdir), gear=gname,
                                           chordal_deviation_m=g['mesh']['chordal_deviation_m']),
                })

    # --- noise --------------------------------------------------------------------------------
    def noisy(self, base, mode):
        src = self.by_name[base]
        name = '%s_n%s' % (base, '2d' if mode == 'inplane' else '3d')
        if name in self.by_name:
            return name
        seed = zlib.crc32(name.encode())
        tris, fmt = stl_io.read_stl(os.path.join(self.outdir, src['file']))
        out = os.path.join(self.outdir, 'noise', name + '.stl')
        os.makedirs(os.path.dirname(out), exist_ok=True)
        stl_io.write_stl(out, stl_io.add_noise(tris, NOISE_MM, seed, mode), fmt, name)
        rec = dict(src, name=name, file=os.path.relpath(out, self.outdir), format=fmt,
                   family=src['family'] + '+noise',
                   noise={'mode': mode, 'amplitude_m': NOISE_MM * 1e-3, 'distribution': 'uniform per coordinate',
                          'seed': seed, 'base': base})
        return self.add_mesh(rec)['name']

    def noisy_pair(self, a, b, mode):
        self.add_pair(a, b)  # the clean twin, for comparison
        self.add_pair(self.noisy(a, mode), self.noisy(b, mode))


def build_full(c):
    # MCAD externals: Latin square rows (module, pressure angle) × columns (facets, format).
    for ri, (m, pa) in enumerate(MODULE_PA):
        for ci, (facets, fmt) in enumerate(FACETS_FMT):
            za, zb = TOOTH_PAIRS[(ri + ci) % 6]
            holes = (ri + ci // 2) % 2 == 0
            g = {(z, b): c.mcad_gear(m, pa, facets, fmt, z, b, holes and z >= 55) for z in (za, zb) for b in (0, 0.05)}
            c.add_pair(g[za, 0], g[zb, 0])
            c.add_pair(g[za, 0.05], g[zb, 0.05])
            c.add_pair(g[za, 0], g[zb, 0.05])
            c.add_pair(g[za, 0.05], g[zb, 0])
    # MCAD rings with an MCAD pinion of the same module, pressure angle, facets, format, backlash.
    rings = [(1, 20, 24, 'stl-binary', 60, 24, 0, 'mcad'), (1, 20, 24, 'stl-binary', 60, 24, 0, 'relieved'),
             (1, 20, 24, 'stl-binary', 60, 24, 0.05, 'relieved'), (1, 20, 5, 'stl-ascii', 48, 17, 0, 'relieved'),
             (4, 20, 24, 'stl-binary', 80, 36, 0, 'mcad'), (4, 20, 24, 'stl-binary', 80, 36, 0, 'relieved'),
             (1, 25, 48, 'stl-binary', 60, 24, 0, 'relieved'), (1, 14.5, 24, 'stl-ascii', 80, 36, 0, 'relieved')]
    for m, pa, facets, fmt, zr, zp, b, conv in rings:
        pin = c.mcad_gear(m, pa, facets, fmt, zp, b)
        c.add_pair(pin, c.mcad_ring(m, pa, facets, fmt, zr, b, conv))
    # gearsim's own gears, module 1–4, up to 80 teeth (20° needs z ≥ 18 against undercut, 14.5° z ≥ 32).
    bore = lambda m, z: {'bore_diameter_m': round(0.25 * (z - 2.5) * m) * 1e-3}  # noqa: E731
    three = ['stl-binary', 'stl-ascii', 'obj']
    two = ['stl-binary', 'obj']
    c.gearsim_set(1, 20, [('z%d' % z, 'external', z, bore(1, z)) for z in (18, 24, 40, 80)] +
                  [('ring60', 'internal', 60, {'rim_diameter_m': 72e-3}),
                   ('ring60_ha08', 'internal', 60, {'rim_diameter_m': 72e-3, 'addendum_coeff': 0.8})], three)
    c.gearsim_set(2, 20, [('z%d' % z, 'external', z, bore(2, z)) for z in (20, 31, 56)], two)
    # At 25° the standard rack's tip fillet (ρ_f* = 0.38) does not fit its tip land: ρ_f* = 0.25.
    c.gearsim_set(2, 25, [('z%d' % z, 'external', z, dict(bore(2, z), root_fillet_coeff=0.25)) for z in (14, 40)], two)
    c.gearsim_set(3, 20, [('z%d' % z, 'external', z, bore(3, z)) for z in (18, 45)], two)
    c.gearsim_set(4, 20, [('z%d' % z, 'external', z, bore(4, z)) for z in (24, 80)], two)
    c.gearsim_set(1, 14.5, [('z%d' % z, 'external', z, bore(1, z)) for z in (32, 64)], two)
    gs_pairs = {('gs_m1_a20', f): [(18, 24), (24, 80), (18, 40), (40, 80)] for f in three}
    for f in two:
        gs_pairs[('gs_m2_a20', f)] = [(20, 31), (20, 56), (31, 56)]
        gs_pairs[('gs_m2_a25', f)] = [(14, 40)]
        gs_pairs[('gs_m3_a20', f)] = [(18, 45)]
        gs_pairs[('gs_m4_a20', f)] = [(24, 80)]
        gs_pairs[('gs_m1_a14p5', f)] = [(32, 64)]
    for (spec, f), zz in gs_pairs.items():
        for za, zb in zz:
            c.add_pair('%s_z%d_%s' % (spec, za, FMT_TAG[f]), '%s_z%d_%s' % (spec, zb, FMT_TAG[f]))
    for f in two:
        for ring in ('ring60', 'ring60_ha08'):
            c.add_pair('gs_m1_a20_z24_%s' % FMT_TAG[f], 'gs_m1_a20_%s_%s' % (ring, FMT_TAG[f]))
    # Noisy copies: in-plane (still prisms) and 3D (prism broken by up to 1 µm in height).
    n = lambda *a: c.mcad_gear(*a)  # noqa: E731
    c.noisy_pair(n(1, 20, 24, 'stl-binary', 17, 0.05), n(1, 20, 24, 'stl-binary', 36, 0.05), 'inplane')
    c.noisy_pair(n(1, 20, 48, 'stl-ascii', 24, 0.05), n(1, 20, 48, 'stl-ascii', 55, 0.05), 'inplane')
    c.noisy_pair(n(4, 20, 24, 'stl-binary', 24, 0.05), n(4, 20, 24, 'stl-binary', 80, 0.05), 'inplane')
    c.noisy_pair(n(1, 25, 5, 'stl-ascii', 24, 0), n(1, 25, 5, 'stl-ascii', 36, 0), 'inplane')
    c.noisy_pair('gs_m1_a20_z18_bin', 'gs_m1_a20_z24_bin', 'inplane')
    c.noisy_pair('gs_m1_a20_z18_asc', 'gs_m1_a20_z24_asc', 'inplane')
    c.noisy_pair('gs_m4_a20_z24_bin', 'gs_m4_a20_z80_bin', 'inplane')
    c.noisy_pair(n(1, 20, 24, 'stl-binary', 17, 0.05), n(1, 20, 24, 'stl-binary', 36, 0.05), '3d')
    c.noisy_pair('gs_m1_a20_z18_bin', 'gs_m1_a20_z24_bin', '3d')


def build_small(c):
    a, b = c.mcad_gear(1, 20, 24, 'stl-binary', 17, 0.05), c.mcad_gear(1, 20, 24, 'stl-binary', 24, 0.05)
    c.add_pair(a, b)
    c.add_pair(c.mcad_gear(1, 20, 5, 'stl-ascii', 17, 0), c.mcad_gear(1, 20, 5, 'stl-ascii', 24, 0))
    c.add_pair(c.noisy(a, 'inplane'), c.noisy(b, 'inplane'))
    bore = lambda z: {'bore_diameter_m': round(0.25 * (z - 2.5)) * 1e-3}  # noqa: E731
    c.gearsim_set(1, 20, [('z18', 'external', 18, bore(18)), ('z24', 'external', 24, bore(24))], ['stl-binary'])
    c.add_pair('gs_m1_a20_z18_bin', 'gs_m1_a20_z24_bin')


def main(argv):
    args = argv[1:]
    if not args or args[0].startswith('-'):
        print(__doc__)
        return 2
    opt = lambda k, d: args[args.index(k) + 1] if k in args else d  # noqa: E731
    outdir = os.path.abspath(args[0])
    gearsim = os.path.abspath(opt('--gearsim', os.path.join(REPO, 'build', 'bin', 'gearsim')))
    c = Corpus(outdir, opt('--openscad', 'openscad'), gearsim)
    os.makedirs(outdir, exist_ok=True)
    t0 = time.monotonic()
    (build_small if '--small' in args else build_full)(c)
    wall = time.monotonic() - t0
    ver = subprocess.run([c.openscad, '--version'], capture_output=True, text=True)
    manifest = {
        'description': 'cad_corpus: third-party (OpenSCAD MCAD) and gearsim gear meshes, in mm, and the pairs to run',
        'generator': 'scripts/cad_corpus/generate.py' + (' --small' if '--small' in args else ''),
        'openscad_version': (ver.stdout + ver.stderr).strip(),
        'mcad_library': '/usr/share/openscad/libraries/MCAD/involute_gears.scad (Debian openscad-mcad)',
        'conventions': {
            'units': 'keys ending _m are metres, _deg degrees; mesh files are in mm (unit "mm")',
            'backlash_m': 'mesh: circular backlash argument (each tooth thinned by backlash_m/2 at the pitch circle); '
                          'pair: total circular backlash at the pitch circle, (b_driver + b_driven)/2',
            'tooth0_deg': 'polar angle of tooth 0\'s centre line (an internal gear\'s tooth points inward)',
            'centre_distance_m': 'standard: m·(z1 + z2)/2 external, m·(z_ring − z_pinion)/2 internal',
            'face_width_m': '%g·module' % FACE_PER_MODULE,
        },
        'generation_wall_s': round(wall, 1),
        'meshes': c.meshes,
        'pairs': c.pairs,
    }
    with open(os.path.join(outdir, 'corpus.json'), 'w') as f:
        json.dump(manifest, f, indent=1)
    print('%d meshes, %d pairs in %s (%.1f s)' % (len(c.meshes), len(c.pairs), outdir, wall))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
