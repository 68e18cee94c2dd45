# Builds FreeCAD PartDesign involute gears and exports them as binary STL (run by freecadcmd).
#
# Usage (generate.py does this): GEARSIM_FC_JOBS=/abs/jobs.json freecadcmd freecad_gears.py
#
# jobs.json (data only, nothing in it is evaluated; relative paths are from the jobs file's folder):
#   {"results": "results.json" (optional),
#    "jobs": [{"name", "teeth", "module_mm", "pressure_angle_deg", "high_precision", "internal",
#              "face_mm", "bore_diameter_mm" (external, 0: none), "disc_radius_mm" (internal),
#              "meshes": [{"file": "x.stl", "method": "export"},
#                         {"file": …, "method": "meshFromShape", "linear_deflection_mm": 0.002,
#                          "angular_deflection_rad": 0.0524}]}]}
#
# Each gear is a PartDesign Body: an external gear is the InvoluteGear profile (PartDesign
# workbench, InvoluteGearFeature: NumberOfTeeth, Modules, PressureAngle, HighPrecision,
# ExternalGear) padded by the face width, less a bore pocketed through all; an internal gear is a
# padded disc with the internal InvoluteGear profile pocketed through all. The shape is modelled
# at the origin about +z, from z = 0 to the face width.
#
# Meshes: "export" is `Mesh.export([body], file)` with FreeCAD's default tessellation, done first
# on the freshly recomputed body (OpenCASCADE keeps a shape's triangulation and a later export
# would reuse a finer one); "meshFromShape" is `MeshPart.meshFromShape(Shape=copy, LinearDeflection,
# AngularDeflection, Relative=False)` on a copy of the shape without its triangulation, then
# `Mesh.write` (binary STL). Writes the results file: FreeCAD's version and per gear the shape's
# validity, volume, face count, per mesh its triangle and point counts and seconds.
import json
import os
import time

import FreeCAD
import Mesh
import MeshPart
import Part

import InvoluteGearFeature


def num(job, key, lo, hi):
    """A number of the job, checked against its range (the jobs file is data)."""
    v = float(job[key])
    if not lo <= v <= hi:
        raise ValueError('%s = %r outside [%g, %g]' % (key, v, lo, hi))
    return v


def gear_body(doc, job):
    """The PartDesign Body of one gear; returns (body, gear profile)."""
    teeth = int(job['teeth'])
    if not 3 <= teeth <= 1000:
        raise ValueError('teeth = %d outside [3, 1000]' % teeth)
    module = num(job, 'module_mm', 0.01, 100)
    angle = num(job, 'pressure_angle_deg', 1, 45)
    face = num(job, 'face_mm', 0.01, 2000)
    internal = bool(job['internal'])
    body = doc.addObject('PartDesign::Body', 'Body')
    gear = InvoluteGearFeature.makeInvoluteGear('InvoluteGear')
    gear.NumberOfTeeth = teeth
    gear.Modules = FreeCAD.Units.Quantity(module, FreeCAD.Units.Length)
    gear.PressureAngle = FreeCAD.Units.Quantity(angle, FreeCAD.Units.Angle)
    gear.HighPrecision = bool(job['high_precision'])
    gear.ExternalGear = not internal
    body.addObject(gear)
    if internal:
        disc = body.newObject('Sketcher::SketchObject', 'Disc')
        disc.addGeometry(Part.Circle(FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(0, 0, 1),
                                     num(job, 'disc_radius_mm', 0.01, 1e5)))
        pad = body.newObject('PartDesign::Pad', 'Pad')
        pad.Profile = disc
        pad.Length = face
        pocket = body.newObject('PartDesign::Pocket', 'Teeth')
        pocket.Profile = gear
        pocket.Type = 'ThroughAll'
        pocket.Midplane = True
    else:
        pad = body.newObject('PartDesign::Pad', 'Pad')
        pad.Profile = gear
        pad.Length = face
        bore = num(job, 'bore_diameter_mm', 0, 1e5)
        if bore > 0:
            sketch = body.newObject('Sketcher::SketchObject', 'BoreSketch')
            sketch.addGeometry(Part.Circle(FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(0, 0, 1), bore / 2))
            pocket = body.newObject('PartDesign::Pocket', 'Bore')
            pocket.Profile = sketch
            pocket.Type = 'ThroughAll'
            pocket.Midplane = True
    doc.recompute()
    return body


def export(body, job, folder):
    """Writes the job's meshes; the default export first (see the file's head)."""
    out = []
    meshes = sorted(job['meshes'], key=lambda m: m['method'] != 'export')
    for m in meshes:
        path = os.path.join(folder, str(m['file']))
        if not path.endswith('.stl'):
            raise ValueError('mesh file %r: an .stl path expected' % path)
        t0 = time.monotonic()
        if m['method'] == 'export':
            Mesh.export([body], path)
            mesh = Mesh.Mesh(path)
        elif m['method'] == 'meshFromShape':
            mesh = MeshPart.meshFromShape(Shape=body.Shape.copy(),
                                          LinearDeflection=num(m, 'linear_deflection_mm', 1e-5, 10),
                                          AngularDeflection=num(m, 'angular_deflection_rad', 1e-3, 3.2),
                                          Relative=False)
            mesh.write(path)
        else:
            raise ValueError('mesh method %r: export or meshFromShape expected' % m['method'])
        out.append({'file': path, 'triangles': mesh.CountFacets, 'points': mesh.CountPoints,
                    'seconds': round(time.monotonic() - t0, 3)})
    return out


def main():
    jobs_file = os.path.abspath(os.environ['GEARSIM_FC_JOBS'])
    folder = os.path.dirname(jobs_file)
    with open(jobs_file) as f:
        spec = json.load(f)
    results = {'freecad_version': FreeCAD.Version()[:4], 'jobs': []}
    for i, job in enumerate(spec['jobs']):
        doc = FreeCAD.newDocument('gear%d' % i)
        body = gear_body(doc, job)
        shape = body.Shape
        results['jobs'].append({'name': str(job['name']), 'valid': shape.isValid(), 'solids': len(shape.Solids),
                                'volume_mm3': shape.Volume, 'faces': len(shape.Faces),
                                'meshes': export(body, job, folder) if shape.isValid() and len(shape.Solids) == 1 else []})
        FreeCAD.closeDocument(doc.Name)
    if 'results' in spec:
        with open(os.path.join(folder, str(spec['results'])), 'w') as f:
            json.dump(results, f, indent=1)


main()
