"""The demo's GLBs through Blender and back (run by .ci/run).

Usage: python3 verify/blender_check.py OUT_DIR PDESCULPT [BLENDER]

For each of OUT_DIR/demo.glb, demo-sketch.glb and demo-pde6.glb:
  1. pdesculpt reads it (`convert --json`): its parts and height;
  2. Blender (headless, verify/blender_import.py) imports it and checks
     the mesh objects are exactly the expected names, one each, and the
     height agrees with pdesculpt's within HEIGHT_TOL_M, then exports the
     scene back to GLB;
  3. pdesculpt reads Blender's GLB (`convert --json`, `render`): the same
     parts, triangle count and height; the body of Blender's demo.glb goes
     through `profile extract`, `template fit --template` and
     `pde6 body --mesh` (watertight).
Expected names: demo.glb body, skirt, teddy (the demo's three models);
demo-sketch.glb the bundled female document's parts, transitions and
removed parts as demo.json lists them (`sketched.parts`); demo-pde6.glb the
parts pdesculpt reads (Blender must agree on names and count).
Exit 1 on any failure.
"""

import json
import os
import subprocess
import sys
import tempfile

# Heights agree to 2 mm: both readers see the same f32 coordinates; the
# bound only leaves room for Blender's f32 transforms.
HEIGHT_TOL_M = 0.002


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.stderr.write(r.stdout + r.stderr)
        raise SystemExit(f"blender_check: failed: {' '.join(cmd)}")
    return r.stdout


def blender_env():
    """The environment for Blender: PATH without this interpreter's own
    bin folder. A pyenv python puts its folder first in PATH, and Blender's
    embedded Python (also 3.11) then takes that installation's standard
    library instead of Debian's, where the importer's numpy lives."""
    env = dict(os.environ)
    own = os.path.dirname(os.path.realpath(sys.executable))
    if not own.startswith("/usr/bin"):
        env["PATH"] = os.pathsep.join(
            p for p in env.get("PATH", "").split(os.pathsep)
            if os.path.realpath(p) != own)
    return env


def read(pdesculpt, glb, tmp):
    out = os.path.join(tmp, os.path.basename(glb) + ".obj")
    info = json.loads(run([pdesculpt, "--json", "convert", glb, "-o", out]))
    lo, hi = info["bbox"]["min"], info["bbox"]["max"]
    info["height"] = hi[1] - lo[1]
    return info


def body_inputs(pdesculpt, body, tmp):
    """The body of Blender's export as the input of every mesh-reading
    command: its outlines, a template fit to them, a pde6 reconstruction."""
    failures = []
    svg = {}
    for view in ["front", "side"]:
        svg[view] = os.path.join(tmp, f"{view}.svg")
        run([pdesculpt, "profile", "extract", body, "--view", view, "-o", svg[view]])
    fit = json.loads(run([pdesculpt, "--json", "template", "fit", "--template", body,
                          "--front", svg["front"], "--side", svg["side"],
                          "-o", os.path.join(tmp, "fit.glb")]))
    recon = json.loads(run([pdesculpt, "--json", "pde6", "body", "--mesh", body,
                            "-o", os.path.join(tmp, "recon.glb")]))
    if not recon["topology"]["watertight"]:
        failures.append("pde6 body --mesh on Blender's body is not watertight")
    print(f"blender_check: Blender's body read by profile extract, template fit "
          f"({fit['vertices']} vertices), pde6 body --mesh (watertight "
          f"{recon['topology']['watertight']}, {recon['triangles']} triangles)")
    return failures


def main():
    out_dir, pdesculpt = sys.argv[1], sys.argv[2]
    blender = sys.argv[3] if len(sys.argv) > 3 else "blender"
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(out_dir, "demo.json")) as f:
        demo = json.load(f)
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, expected in [
            ("demo.glb", ["body", "skirt", "teddy"]),
            ("demo-sketch.glb", demo["sketched"]["parts"]),
            ("demo-pde6.glb", None),
        ]:
            glb = os.path.join(out_dir, name)
            ours = read(pdesculpt, glb, tmp)
            objects = expected if expected is not None else ours["groups"]
            if sorted(ours["groups"]) != sorted(objects):
                failures.append(f"{name}: pdesculpt reads parts {ours['groups']}, expected {objects}")
            back = os.path.join(tmp, name.replace(".glb", "-blender.glb"))
            r = subprocess.run(
                [blender, "-b", "--factory-startup", "--python-exit-code", "1",
                 "--python", os.path.join(here, "blender_import.py"), "--",
                 glb, "--objects", ",".join(objects),
                 "--height", str(ours["height"]), "--height-tol", str(HEIGHT_TOL_M),
                 "--export", back],
                capture_output=True, text=True, env=blender_env())
            lines = [ln for ln in r.stdout.splitlines() if ln.startswith("blender_import:")]
            print("\n".join(lines))
            if r.returncode != 0:
                sys.stderr.write(r.stdout[-3000:] + r.stderr[-3000:])
                failures.append(f"{name}: Blender's check failed (exit {r.returncode})")
                continue
            theirs = read(pdesculpt, back, tmp)
            if sorted(theirs["groups"]) != sorted(objects):
                failures.append(f"{name}: Blender's export reads as {theirs['groups']}")
            if theirs["triangles"] != ours["triangles"]:
                failures.append(f"{name}: Blender's export has {theirs['triangles']} triangles, ours {ours['triangles']}")
            if abs(theirs["height"] - ours["height"]) > HEIGHT_TOL_M:
                failures.append(f"{name}: Blender's export is {theirs['height']:.4f} m tall, ours {ours['height']:.4f} m")
            if name == "demo.glb":
                failures += body_inputs(pdesculpt, back + "#body", tmp)
            png = os.path.join(out_dir, name.replace(".glb", "-blender.png"))
            run([pdesculpt, "render", back, "-o", png])
            print(f"blender_check: {name}: {len(objects)} objects, {ours['height']:.3f} m; "
                  f"Blender's export read back ({theirs['triangles']} triangles), rendered {png}")
    for f in failures:
        print(f"blender_check: FAIL {f}")
    sys.exit(1 if failures else 0)


main()
