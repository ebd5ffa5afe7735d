"""Imports a GLB into Blender (headless), checks its objects, exports it back.

Usage (run by .ci/run):
  blender -b --factory-startup --python-exit-code 1 \
      --python verify/blender_import.py -- IN.glb \
      --objects a,b,c [--height METRES --height-tol METRES] [--export OUT.glb]

Checks, each printed, exit 1 on a failure:
  * the mesh objects Blender made are exactly --objects (names as given,
    no ".001" suffix from a clash), one each;
  * every mesh object has vertices and faces;
  * the height of all mesh objects together (Blender's Z, glTF's Y) is
    --height within --height-tol;
then exports the scene back to GLB (--export) for pdesculpt to read.

Blender 3.4's glTF importer uses `numpy.bool`, an alias numpy 1.24 removed
(Debian 12 ships numpy 1.24 with Blender 3.4): the alias is restored before
the importer loads.
"""

import argparse
import json
import sys

import numpy

if not hasattr(numpy, "bool"):
    numpy.bool = numpy.bool_  # removed in numpy 1.24; Blender 3.4 uses it

import bpy  # noqa: E402  (Blender's module, after the alias)
from mathutils import Vector  # noqa: E402


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="blender_import.py")
    p.add_argument("glb")
    p.add_argument("--objects", required=True,
                   help="comma-separated names of the mesh objects expected")
    p.add_argument("--height", type=float)
    p.add_argument("--height-tol", type=float, default=0.01)
    p.add_argument("--export")
    return p.parse_args(argv)


def world_z_range(objects):
    lo, hi = float("inf"), float("-inf")
    for o in objects:
        for v in o.data.vertices:
            z = (o.matrix_world @ Vector(v.co)).z
            lo, hi = min(lo, z), max(hi, z)
    return lo, hi


def root_of(o):
    while o.parent is not None:
        o = o.parent
    return o.name


def main():
    a = parse_args()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=a.glb)
    meshes = [o for o in bpy.context.scene.objects if o.type == "MESH"]
    names = sorted(o.name for o in meshes)
    expected = sorted(n for n in a.objects.split(",") if n)
    failures = []
    if names != expected:
        failures.append(f"objects {names} != expected {expected}")
    for o in meshes:
        if len(o.data.vertices) == 0 or len(o.data.polygons) == 0:
            failures.append(f"object {o.name} is empty")
    lo, hi = world_z_range(meshes)
    height = hi - lo
    if a.height is not None and abs(height - a.height) > a.height_tol:
        failures.append(f"height {height:.4f} m != {a.height} +- {a.height_tol} m")
    report = {
        "file": a.glb,
        "mesh_objects": len(meshes),
        "names": names,
        "roots": sorted({root_of(o) for o in meshes}),
        "height_m": round(height, 4),
        "faces": sum(len(o.data.polygons) for o in meshes),
    }
    print("blender_import:", json.dumps(report))
    if a.export:
        bpy.ops.export_scene.gltf(filepath=a.export, export_format="GLB")
        print(f"blender_import: exported {a.export}")
    for f in failures:
        print(f"blender_import: FAIL {a.glb}: {f}")
    if failures:
        sys.exit(1)
    print(f"blender_import: ok {a.glb} ({len(meshes)} objects, {height:.3f} m)")


main()
