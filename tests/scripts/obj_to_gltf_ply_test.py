#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""scripts/obj_to_gltf_ply.py exports the bundled Cornell box to glTF (.gltf with its .bin, and
.glb) and PLY (ascii and binary), and `hmcr solve` of each, with the bundled scene file's views,
sides and rays, writes the same .vtp bytes as the bundled OBJ scene. A glTF whose light is
brighter does not (the comparison can fail).

Usage: obj_to_gltf_ply_test.py HMCR SOURCE_DIR. Exit code 1 on failure."""
import filecmp
import json
import os
import subprocess
import sys
import tempfile

HMCR, SOURCE = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
SCRIPT = os.path.join(SOURCE, "scripts", "obj_to_gltf_ply.py")
RAYS = "100000"
problems = []
checks = 0


def solve(scene, out):
    run = subprocess.run([HMCR, "solve", scene, "--rays", RAYS, "--seed", "3", "-q", "-o", out],
                         capture_output=True, text=True)
    if run.returncode != 0:
        problems.append(f"hmcr solve {scene}: {run.stderr.strip()}")
    return out


with tempfile.TemporaryDirectory() as tmp:
    meshes = os.path.join(tmp, "meshes")
    subprocess.run([sys.executable, SCRIPT, meshes], check=True)
    for name in os.listdir(meshes):
        if os.path.getsize(os.path.join(meshes, name)) > 50_000:
            problems.append(f"{name} is larger than 50 kB")
    obj = solve("cornell", os.path.join(tmp, "obj", "cornell.vtp"))
    scene = json.load(open(os.path.join(SOURCE, "scenes", "cornell", "cornell.json")))

    def scene_of(mesh, folder):
        """A scene file named cornell.json (the .vtp records the scene's name) for the mesh."""
        os.makedirs(os.path.join(tmp, folder))
        path = os.path.join(tmp, folder, "cornell.json")
        json.dump(dict(scene, mesh=os.path.join("..", "meshes", mesh)), open(path, "w"))
        return path

    for mesh in ["cornell.gltf", "cornell.glb", "cornell.ply", "cornell-binary.ply"]:
        folder = mesh.replace(".", "-")
        out = solve(scene_of(mesh, folder), os.path.join(tmp, folder, "out", "cornell.vtp"))
        checks += 1
        if not (os.path.exists(obj) and os.path.exists(out) and filecmp.cmp(obj, out, False)):
            problems.append(f"{mesh}: its .vtp differs from the OBJ's")

    # The control: twice the light's emissive strength is another solution.
    gltf = json.load(open(os.path.join(meshes, "cornell.gltf")))
    for m in gltf["materials"]:
        strength = m.get("extensions", {}).get("KHR_materials_emissive_strength")
        if strength:
            strength["emissiveStrength"] *= 2
    json.dump(gltf, open(os.path.join(meshes, "brighter.gltf"), "w"))
    out = solve(scene_of("brighter.gltf", "brighter"), os.path.join(tmp, "brighter", "out",
                                                                   "cornell.vtp"))
    checks += 1
    if not os.path.exists(out) or filecmp.cmp(obj, out, False):
        problems.append("a brighter light gave the OBJ's .vtp (or none): the comparison cannot "
                        "fail")

for p in problems:
    print("FAIL:", p)
failed = min(len(problems), checks)
print(f"{checks - failed} passed, {failed} failed")
sys.exit(1 if problems else 0)
