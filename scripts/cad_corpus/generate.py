#!/usr/bin/env python3
"""Generates the third-party CAD gear corpus and its manifest (corpus.json).

Usage: generate.py OUTDIR [--small] [--gearsim PATH] [--openscad PATH] [--freecad PATH [--only-freecad]]

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
  - with --freecad PATH (freecadcmd, Debian `freecad`): FreeCAD PartDesign involute gears
    (freecad_gears.py), external (padded, with a bore) and internal (pocketed from a disc),
    14.5|20|25°, module 1–3, face 4·m, each written at 4 tessellations: MeshPart.meshFromShape at
    0.002 mm/3°, 0.02 mm/10°, 0.1 mm/0.5 rad and Mesh.export's default; external pairs, pinions
    in rings and planetary sets (sun, planets, ring; corpus.json `planetary`). Skipped with a
    message when freecadcmd is absent; --only-freecad writes the FreeCAD family alone.
--small writes 8 meshes (MCAD z17/z24 binary and ASCII, gearsim z18/z24, a noisy MCAD pair) and
4 pairs, for a ctest slice. Deterministic: same inputs, same files (noise seeded per mesh name).
"""
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
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
FC_FACE_PER_MODULE = 4.0        # FreeCAD family: face width = 4·m
FC_DISC_PER_MODULE = 5.0        # FreeCAD rings: disc radius = pitch radius + 5·m (root at + 1.25·m)
# FreeCAD tessellations: (tag, method, linear deflection mm, angular deflection deg). 0.5 rad is
# MeshPart.meshFromShape's default angle; `export` is Mesh.export with no tolerance: FreeCAD 0.20's
# MaxDeviationExport preference, 0.1 mm (its files equal meshFromShape's at 0.1 mm / 0.1 rad).
FC_TESSELLATIONS = [('l0p002a3', 'meshFromShape', 0.002, 3.0), ('l0p02a10', 'meshFromShape', 0.02, 10.0),
                    ('l0p1r0p5', 'meshFromShape', 0.1, math.degrees(0.5)), ('export', 'export', None, None)]
FC_ALL = [t[0] for t in FC_TESSELLATIONS]


def tag(x):
    """14.5 → '14p5', 0.05 → '0p05', 20.0 → '20' (for file names)."""
    s = ('%g' % x).replace('.', 'p')
    return s


class Corpus:
    def __init__(self, outdir, openscad, gearsim, freecad=None):
        self.outdir, self.openscad, self.gearsim, self.freecad = outdir, openscad, gearsim, freecad
        self.meshes, self.pairs, self.by_name = [], [], {}
        self.pair_keys = set()
        self.planetary, self.fc_jobs, self.fc_version = [], {}, None

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
            'family': a['family'] if not internal else (
                'freecad-ring' if a['tool'] == b['tool'] == 'freecad' else
                'mcad-ring' if a['tool'] == b['tool'] == 'openscad-mcad' else 'gearsim-ring'),
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

    # --- FreeCAD -----------------------------------------------------------------------------
    def fc_gear(self, m, pa, z, internal, tess, high_precision=True):
        """A FreeCAD PartDesign involute gear at tessellation `tess` (a tag of FC_TESSELLATIONS);
        its file is written by run_freecad(). Returns its mesh name."""
        name = '%s_m%s_z%d_a%s_%s%s' % ('fcring' if internal else 'fc', tag(m), z, tag(pa), tess,
                                       '' if high_precision else '_lp')
        if name in self.by_name:
            return name
        r = m * z / 2.0
        face = FC_FACE_PER_MODULE * m
        args = {'NumberOfTeeth': z, 'Modules_mm': m, 'PressureAngle_deg': pa, 'HighPrecision': high_precision,
                'ExternalGear': not internal, 'face_mm': face}
        if internal:
            args['disc_radius_mm'] = r + FC_DISC_PER_MODULE * m
            # FreeCAD's internal gear (fcgear/involute.py): tip r − 0.6·m, root r + 1.25·m.
            tip, root = r - 0.6 * m, r + 1.25 * m
        else:
            args['bore_diameter_mm'] = max(1.0, round(0.25 * (2 * r - 2.5 * m) / m) * m)
            tip, root = r + m, r - 1.25 * m
        key = (m, pa, z, internal, high_precision)
        job = self.fc_jobs.setdefault(key, {
            'name': name.replace('_' + tess, ''), 'teeth': z, 'module_mm': m, 'pressure_angle_deg': pa,
            'high_precision': high_precision, 'internal': internal, 'face_mm': face,
            'bore_diameter_mm': args.get('bore_diameter_mm', 0.0), 'disc_radius_mm': args.get('disc_radius_mm', 0.0),
            'meshes': []})
        t = next(t for t in FC_TESSELLATIONS if t[0] == tess)
        path = os.path.join(self.outdir, 'freecad', name + '.stl')
        mesh_job = {'file': path, 'method': t[1]}
        if t[1] == 'meshFromShape':
            mesh_job.update(linear_deflection_mm=t[2], angular_deflection_rad=math.radians(t[3]))
        job['meshes'].append(mesh_job)
        self.add_mesh({
            'name': name, 'file': os.path.relpath(path, self.outdir), 'family': 'freecad-ring' if internal else 'freecad',
            'tool': 'freecad', 'teeth': z, 'module_m': m * 1e-3, 'pressure_angle_deg': pa, 'backlash_m': 0.0,
            'facets': None, 'tessellation': tess,
            'tessellation_params': {'method': t[1], 'linear_deflection_m': t[2] and t[2] * 1e-3,
                                    'angular_deflection_deg': t[3]},
            'high_precision': high_precision, 'internal': internal, 'format': 'stl-binary', 'unit': 'mm',
            'face_width_m': face * 1e-3,
            **({'outer_radius_m': args['disc_radius_mm'] * 1e-3} if internal else
               {'bore_diameter_m': args['bore_diameter_mm'] * 1e-3}),
            'base_radius_m': r * math.cos(math.radians(pa)) * 1e-3, 'tip_radius_m': tip * 1e-3,
            'root_radius_m': root * 1e-3,
            # The profile puts tooth 0 (an external tooth, or a ring's tooth pointing inward) on +x:
            # fcgear/involute.py rotates each flank's pitch point to ∓pitch/4 and draws the tip arc
            # across +x; `gearsim inspect` finds it there within 0.001° on every mesh.
            'tooth0_deg': 0.0, 'noise': None, 'generator_args': args,
        })
        return name

    def fc_planetary(self, m, pa, zs, zp, zr, planets, tess, high_precision=True):
        """A planetary set of FreeCAD gears (z_r = z_s + 2·z_p, (z_s + z_r)/planets whole), plus
        its sun–planet and planet–ring meshes as pairs."""
        assert zr == zs + 2 * zp and (zs + zr) % planets == 0
        sun, planet = self.fc_gear(m, pa, zs, False, tess, high_precision), self.fc_gear(m, pa, zp, False, tess, high_precision)
        ring = self.fc_gear(m, pa, zr, True, tess, high_precision)
        self.add_pair(sun, planet, 'planetary set member')
        self.add_pair(planet, ring, 'planetary set member')
        self.planetary.append({
            'id': 'S%03d_%s_%dx%s_%s' % (len(self.planetary), sun, planets, planet.split('_')[2], ring.split('_')[2]),
            'sun': sun, 'planet': planet, 'ring': ring, 'planets': planets, 'family': 'freecad-planetary',
            'centre_distance_m': m * (zs + zp) / 2 * 1e-3, 'ratio_nominal': 1 + zr / zs,
        })

    def run_freecad(self):
        """Runs freecad_gears.py under freecadcmd on every gear asked for; fills in the meshes'
        triangle counts. A private HOME keeps the user's FreeCAD preferences out."""
        if not self.fc_jobs:
            return
        d = os.path.join(self.outdir, 'freecad')
        os.makedirs(d, exist_ok=True)
        jobs_file, results_file = os.path.join(d, 'jobs.json'), os.path.join(d, 'freecad_results.json')
        if os.path.exists(results_file):
            os.remove(results_file)
        with open(jobs_file, 'w') as f:
            json.dump({'results': results_file, 'jobs': list(self.fc_jobs.values())}, f, indent=1)
        home = tempfile.mkdtemp(prefix='gearsim_freecad_')
        try:
            r = subprocess.run([self.freecad, os.path.join(HERE, 'freecad_gears.py')], capture_output=True, text=True,
                               env=dict(os.environ, GEARSIM_FC_JOBS=jobs_file, HOME=home), cwd=home)
        finally:
            shutil.rmtree(home, ignore_errors=True)
        if r.returncode != 0 or not os.path.exists(results_file):
            raise SystemExit('freecadcmd failed (exit %d) on %s:\n%s' % (r.returncode, jobs_file, (r.stdout + r.stderr)[-3000:]))
        with open(results_file) as f:
            results = json.load(f)
        self.fc_version = '.'.join(results['freecad_version'][:3])
        counts = {}
        for job in results['jobs']:
            if not job['valid'] or job['solids'] != 1:
                raise SystemExit('FreeCAD made an invalid shape for %s: %r' % (job['name'], job))
            for mesh in job['meshes']:
                counts[os.path.relpath(mesh['file'], self.outdir)] = mesh['triangles']
        for rec in self.meshes:
            if rec['tool'] == 'freecad':
                rec['triangles'] = counts[rec['file']]

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


def build_freecad(c):
    """The FreeCAD family: every gear at every tessellation of FC_TESSELLATIONS; pairs of the same
    tessellation, plus the finest driver with the default export's driven gear."""
    externals = [(20, 1, 18, 40), (20, 2, 24, 56), (20, 3, 17, 30), (14.5, 1, 32, 48), (14.5, 2, 36, 64),
                 (14.5, 3, 32, 40), (25, 1, 12, 30), (25, 2, 14, 45), (25, 3, 16, 24)]
    internals = [(14.5, 1, 30, 80), (20, 1, 17, 40), (20, 1, 12, 24), (20, 2, 24, 60), (25, 3, 18, 45)]  # α, m, z_p, z_r
    planetary = [(20, 1, 20, 30, 80, 4), (14.5, 2, 32, 32, 96, 4), (25, 3, 14, 19, 52, 3)]  # α, m, z_s, z_p, z_r, N
    for pa, m, z1, z2 in externals:
        for tess in FC_ALL:
            c.add_pair(c.fc_gear(m, pa, z1, False, tess), c.fc_gear(m, pa, z2, False, tess))
        c.add_pair(c.fc_gear(m, pa, z1, False, 'l0p002a3'), c.fc_gear(m, pa, z2, False, 'export'), 'mixed tessellations')
    for pa, m, zp, zr in internals:
        for tess in FC_ALL:
            c.add_pair(c.fc_gear(m, pa, zp, False, tess), c.fc_gear(m, pa, zr, True, tess))
    for pa, m, zs, zp, zr, n in planetary:
        for tess in FC_ALL:
            c.fc_planetary(m, pa, zs, zp, zr, n, tess)
    # HighPrecision = False: one quartic Bézier per flank instead of two cubics.
    for tess in ('l0p002a3', 'export'):
        c.add_pair(c.fc_gear(1, 20, 18, False, tess, False), c.fc_gear(1, 20, 40, False, tess, False))
        c.fc_planetary(1, 20, 20, 30, 80, 4, tess, False)
    c.run_freecad()


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
    freecad = opt('--freecad', None)
    only_freecad = '--only-freecad' in args
    if freecad is not None and shutil.which(freecad) is None:
        print('FreeCAD family skipped: no freecadcmd at %r (Debian: apt-get install freecad)' % freecad)
        if only_freecad:
            return 2
        freecad = None
    if only_freecad and freecad is None:
        print('--only-freecad needs --freecad PATH')
        return 2
    c = Corpus(outdir, opt('--openscad', 'openscad'), gearsim, freecad and shutil.which(freecad))
    os.makedirs(outdir, exist_ok=True)
    t0 = time.monotonic()
    if not only_freecad:
        (build_small if '--small' in args else build_full)(c)
    if freecad:
        build_freecad(c)
    wall = time.monotonic() - t0
    manifest = {
        'description': 'cad_corpus: third-party (OpenSCAD MCAD) and gearsim gear meshes, in mm, and the pairs to run',
        'generator': 'scripts/cad_corpus/generate.py' + (' --small' if '--small' in args else ''),
    }
    if not only_freecad:
        ver = subprocess.run([c.openscad, '--version'], capture_output=True, text=True)
        manifest['openscad_version'] = (ver.stdout + ver.stderr).strip()
        manifest['mcad_library'] = '/usr/share/openscad/libraries/MCAD/involute_gears.scad (Debian openscad-mcad)'
    if freecad:
        manifest['description'] = manifest['description'].replace(
            '(OpenSCAD MCAD) and gearsim', 'FreeCAD' if only_freecad else '(OpenSCAD MCAD, FreeCAD) and gearsim')
        manifest['generator'] += ' --freecad' + (' --only-freecad' if only_freecad else '')
        manifest['freecad'] = {
            'version': c.fc_version, 'script': 'scripts/cad_corpus/freecad_gears.py (run by freecadcmd)',
            'gears': 'PartDesign InvoluteGear (fcgear/involute.py): external addendum m, dedendum 1.25·m, fillet '
                     '0.375·m; internal tip r − 0.6·m, root r + 1.25·m; no backlash; face 4·m; externals padded '
                     'less a bore, rings a disc of radius r + 5·m less the internal profile',
            'tessellations': {t[0]: ('Mesh.export, default tolerance' if t[1] == 'export' else
                                     'MeshPart.meshFromShape(LinearDeflection=%g mm, AngularDeflection=%.4g deg, '
                                     'Relative=False)' % (t[2], t[3])) for t in FC_TESSELLATIONS},
        }
    manifest.update({
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
    })
    if freecad:
        manifest['conventions']['face_width_m'] += ' (FreeCAD family: %g·module)' % FC_FACE_PER_MODULE
    if c.planetary:
        manifest['conventions']['planetary'] = ('sun, planets equally spaced, ring fixed; centre_distance_m = '
                                                'm·(z_s + z_p)/2; ratio_nominal = 1 + z_r/z_s (sun to carrier)')
        manifest['planetary'] = c.planetary
    with open(os.path.join(outdir, 'corpus.json'), 'w') as f:
        json.dump(manifest, f, indent=1)
    print('%d meshes, %d pairs%s in %s (%.1f s)' % (len(c.meshes), len(c.pairs),
                                                     ', %d planetary sets' % len(c.planetary) if c.planetary else '',
                                                     outdir, wall))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
