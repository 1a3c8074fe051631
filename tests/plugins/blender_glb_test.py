#!/usr/bin/env python3
"""Blender as the real client of our .glb: the wrapper converts the shared 3tnk unit (full
pipeline: faired, textured, decimated), then Debian's Blender imports it headless and checks:
it stands upright (height along Blender's z, the turret above the hull, the barrel pointing to the
front), one object per part (body, turret, barrel and a mesh object per section), the base colour
texture is sampled with interpolation 'Closest', and the normal map of the decimated mesh is wired
into the material (image -> Normal Map node in tangent space -> the shader's Normal input).

usage: blender_glb_test.py BUILD_DIR MODELS_DIR     (exit 77: skipped)
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
WRAPPER = HERE.parent.parent / "meshlab_scripts" / "voxelfair_convert.py"

BLENDER_SCRIPT = r'''
import sys, json
import numpy
numpy.bool = bool  # Debian's Blender 3.4 glTF importer still calls numpy's removed np.bool
import bpy
from mathutils import Vector

path, report = sys.argv[sys.argv.index("--") + 1:]
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=path)
objects = {o.name: o for o in bpy.context.scene.objects}

def bounds(objs):
    points = [o.matrix_world @ Vector(c) for o in objs for c in o.bound_box]
    return [min(p[a] for p in points) for a in range(3)], [max(p[a] for p in points) for a in range(3)]

def mesh_children(name):  # the part's own sections (the barrel hangs under the turret)
    return [o for o in objects[name].children if o.type == "MESH"] if name in objects else []

interpolations, normal_maps = set(), []
for m in bpy.data.materials:
    if not m.node_tree:
        continue
    for n in m.node_tree.nodes:
        if n.type != "TEX_IMAGE":
            continue
        targets = [(l.to_node, l.to_socket.name) for out in n.outputs for l in out.links]
        if any(node.type == "NORMAL_MAP" for node, _ in targets):
            for node, _ in targets:
                if node.type == "NORMAL_MAP":
                    into = [(l.to_node.type, l.to_socket.name) for l in node.outputs[0].links]
                    normal_maps.append({"image": n.image.name if n.image else None, "space": node.space,
                                        "into": into, "colorspace": n.image.colorspace_settings.name if n.image else None})
        else:
            interpolations.add(n.interpolation)
interpolations = sorted(interpolations)
out = {"objects": sorted(objects), "meshes": sorted(o.name for o in objects.values() if o.type == "MESH"),
       "interpolations": interpolations, "normal_maps": normal_maps}
for part in ("body", "turret", "barrel"):
    objs = mesh_children(part)
    if objs:
        out[part] = bounds(objs)
out["all"] = bounds([o for o in objects.values() if o.type == "MESH"])
json.dump(out, open(report, "w"))
'''


def main():
    build, models = Path(sys.argv[1]), Path(sys.argv[2])
    blender = shutil.which("blender")
    if not blender:
        print("SKIP: blender is not installed (apt-get install blender)")
        return 77
    tank = models / "vxl" / "3tnk.vxl"
    if not tank.is_file():
        print(f"SKIP: the shared models are absent: {models}")
        return 77
    with tempfile.TemporaryDirectory(prefix="voxelfair-blender-") as tmp:
        tmp = Path(tmp)
        subprocess.run([sys.executable, str(WRAPPER), "--build", str(build), str(tank), "--output", str(tmp / "out"),
                        "--formats", "glb", "--decimate", "0.1"], check=True)
        glb = tmp / "out" / "3tnk.glb"
        script, report = tmp / "check.py", tmp / "report.json"
        script.write_text(BLENDER_SCRIPT)
        # Blender's embedded Python finds its library through PATH: keep a pyenv's interpreter
        # (which runs this script on some machines) from shadowing Debian's, where numpy is.
        env = dict(os.environ, PATH=os.pathsep.join(p for p in os.environ.get("PATH", "").split(os.pathsep)
                                                    if "pyenv" not in p))
        result = subprocess.run([blender, "-b", "--factory-startup", "--python-exit-code", "1", "--python", str(script),
                                 "--", str(glb), str(report)], capture_output=True, text=True, timeout=300, env=env)
        if result.returncode != 0 or not report.is_file():
            print(result.stdout[-3000:], result.stderr[-3000:])
            print("FAIL: Blender could not import the .glb")
            return 1
        r = json.loads(report.read_text())
    print(json.dumps(r, indent=1))
    failures = []

    def expect(ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        if not ok:
            failures.append(what)

    expect({"body", "turret", "barrel"} <= set(r["objects"]), "one object per part: body, turret, barrel")
    expect(len(r["meshes"]) == 3, f"one mesh object per section (3 sections): {r['meshes']}")
    expect(r["interpolations"] == ["Closest"], f"base colour interpolation Closest: {r['interpolations']}")
    expect(len(r["normal_maps"]) > 0 and all(m["space"] == "TANGENT" and ("BSDF_PRINCIPLED", "Normal") in
                                             [tuple(i) for i in m["into"]] for m in r["normal_maps"]),
           f"the normal map feeds the shader's Normal through a tangent-space Normal Map node: {r['normal_maps']}")
    lo, hi = r["all"]
    size = [h - l for l, h in zip(lo, hi)]
    # Upright: the tank is longer (front along Blender's -y, glTF's +Z) than it is tall (z).
    expect(size[2] < size[1] and size[2] < 0.75 * max(size), f"upright: height along z {size[2]:.2f} m, extent {size}")
    body_top, turret_lo, turret_hi = r["body"][1][2], r["turret"][0][2], r["turret"][1][2]
    expect(turret_hi > body_top and turret_lo > r["body"][0][2], "the turret sits above the hull")
    # The barrel points to the front: glTF +Z is Blender's -Y.
    expect(r["barrel"][0][1] < r["turret"][0][1], "the barrel reaches past the turret towards the front (-y)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
