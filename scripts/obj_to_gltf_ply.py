#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Exports an OBJ scene (by default the bundled Cornell box) to glTF 2.0 and PLY, laid out as
Blender's exporters lay them out, without Blender (docs/usage.md#ply-and-gltf):

- glTF (NAME.gltf with NAME.bin, and the binary NAME.glb): one mesh and one node per object (OBJ
  `g` or `o`), one primitive per material; every face has vertices of its own (a flat-shaded
  face's normal is its own), its positions and normals float32, its triangles a fan
  (0 1 2)(0 2 3)...; materials with pbrMetallicRoughness.baseColorFactor = Kd (metallic 0),
  emissiveFactor and KHR_materials_emissive_strength for Ke. The strength is the smallest power of
  two at least Ke's largest channel, so that factor x strength is Ke exactly. doubleSided is
  false: the bundled OBJ scenes are one-sided (their scene files say "sides": 1).
- PLY (NAME.ply in ascii, NAME-binary.ply in binary little endian): the OBJ's vertices and
  faces, each face with float `red green blue` (Kd) and `emission_red emission_green
  emission_blue` (Ke), hmcr's convention for PLY emission.

Reads the OBJ subset the bundled scenes use: v, f (positions only), g, o, usemtl, mtllib with
newmtl, Kd and Ke. Standard library only.  Usage:
    scripts/obj_to_gltf_ply.py OUT_DIR [--obj scenes/cornell/cornell.obj]
"""

import argparse
import json
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_OBJ = os.path.join(HERE, "..", "scenes", "cornell", "cornell.obj")


def read_mtl(path):
    materials, current = {}, None
    with open(path) as f:
        for line in f:
            words = line.split("#")[0].split()
            if not words:
                continue
            if words[0] == "newmtl":
                current = materials.setdefault(" ".join(words[1:]),
                                               {"Kd": [0.0] * 3, "Ke": [0.0] * 3})
            elif words[0] in ("Kd", "Ke") and current is not None:
                current[words[0]] = [float(x) for x in words[1:4]]
    return materials


def read_obj(path):
    """Positions, materials, and objects: [(name, [(material, [faces])])] in file order."""
    positions, materials, objects = [], {}, []
    material = None
    for line in open(path):
        words = line.split("#")[0].split()
        if not words:
            continue
        key = words[0]
        if key == "v":
            positions.append([float(x) for x in words[1:4]])
        elif key in ("g", "o"):
            objects.append((" ".join(words[1:]), []))
        elif key == "mtllib":
            materials.update(read_mtl(os.path.join(os.path.dirname(path), words[1])))
        elif key == "usemtl":
            material = " ".join(words[1:])
        elif key == "f":
            if not objects:
                objects.append(("object", []))
            groups = objects[-1][1]
            if not groups or groups[-1][0] != material:
                groups.append((material, []))
            groups[-1][1].append([int(w.split("/")[0]) - 1 for w in words[1:]])
    return positions, materials, objects


def normal(points):
    """The Newell normal of a polygon, unit length."""
    n = [0.0, 0.0, 0.0]
    for i, p in enumerate(points):
        q = points[(i + 1) % len(points)]
        n[0] += (p[1] - q[1]) * (p[2] + q[2])
        n[1] += (p[2] - q[2]) * (p[0] + q[0])
        n[2] += (p[0] - q[0]) * (p[1] + q[1])
    length = math.sqrt(sum(x * x for x in n)) or 1.0
    return [x / length for x in n]


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def gltf_material(name, m):
    ke = m["Ke"]
    strength = 1.0
    while strength < max(ke):
        strength *= 2
    out = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": m["Kd"] + [1.0],
                                                  "metallicFactor": 0.0,
                                                  "roughnessFactor": 0.5}}
    if max(ke) > 0:
        out["emissiveFactor"] = [x / strength for x in ke]
        if strength != 1:
            out["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": strength}}
    return out


def write_gltf(positions, materials, objects, out_dir, name):
    names = list(materials)
    blob = bytearray()
    views, accessors, meshes, nodes = [], [], [], []

    def add_view(data, target):
        while len(blob) % 4:
            blob.append(0)
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data),
                      "target": target})
        blob.extend(data)
        return len(views) - 1

    for object_name, groups in objects:
        primitives = []
        for material, faces in groups:
            points, normals, indices = [], [], []
            for face in faces:
                corners = [positions[i] for i in face]
                n = normal(corners)
                first = len(points)
                points.extend(corners)
                normals.extend([n] * len(corners))
                for k in range(1, len(corners) - 1):
                    indices.extend([first, first + k, first + k + 1])
            floats = [f32(x) for p in points for x in p]
            lows = [min(floats[c::3]) for c in range(3)]
            highs = [max(floats[c::3]) for c in range(3)]
            position = add_view(struct.pack(f"<{len(floats)}f", *floats), 34962)
            normal_view = add_view(struct.pack(f"<{3 * len(normals)}f",
                                               *[x for n in normals for x in n]), 34962)
            index = add_view(struct.pack(f"<{len(indices)}H", *indices), 34963)
            accessors.append({"bufferView": position, "componentType": 5126,
                              "count": len(points), "type": "VEC3", "min": lows, "max": highs})
            accessors.append({"bufferView": normal_view, "componentType": 5126,
                              "count": len(points), "type": "VEC3"})
            accessors.append({"bufferView": index, "componentType": 5123,
                              "count": len(indices), "type": "SCALAR"})
            primitives.append({"attributes": {"POSITION": len(accessors) - 3,
                                              "NORMAL": len(accessors) - 2},
                               "indices": len(accessors) - 1, "material": names.index(material)})
        meshes.append({"name": object_name, "primitives": primitives})
        nodes.append({"name": object_name, "mesh": len(meshes) - 1})
    while len(blob) % 4:
        blob.append(0)
    gltf = {
        "asset": {"version": "2.0", "generator": "hmcr scripts/obj_to_gltf_ply.py"},
        "extensionsUsed": ["KHR_materials_emissive_strength"],
        "scene": 0,
        "scenes": [{"name": "Scene", "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "materials": [gltf_material(n, materials[n]) for n in names],
        "meshes": meshes,
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob), "uri": name + ".bin"}],
    }
    with open(os.path.join(out_dir, name + ".bin"), "wb") as f:
        f.write(blob)
    with open(os.path.join(out_dir, name + ".gltf"), "w") as f:
        json.dump(gltf, f, indent=1)
    # GLB: the same JSON without the buffer's uri, then the buffer as the BIN chunk.
    del gltf["buffers"][0]["uri"]
    text = json.dumps(gltf, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    size = 12 + 8 + len(text) + 8 + len(blob)
    with open(os.path.join(out_dir, name + ".glb"), "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, size))
        f.write(struct.pack("<I4s", len(text), b"JSON") + text)
        f.write(struct.pack("<I4s", len(blob), b"BIN\0") + bytes(blob))


PLY_FACE_PROPERTIES = ["red", "green", "blue", "emission_red", "emission_green",
                       "emission_blue"]


def write_ply(positions, materials, objects, path, binary):
    faces = [(face, materials[m]) for _, groups in objects for m, fs in groups for face in fs]
    header = ["ply", "format " + ("binary_little_endian" if binary else "ascii") + " 1.0",
              "comment " + os.path.basename(path) + " by hmcr scripts/obj_to_gltf_ply.py",
              f"element vertex {len(positions)}",
              "property float x", "property float y", "property float z",
              f"element face {len(faces)}", "property list uchar int vertex_indices"]
    header += ["property float " + p for p in PLY_FACE_PROPERTIES]
    header.append("end_header")
    with open(path, "wb") as f:
        f.write(("\n".join(header) + "\n").encode())
        for p in positions:
            f.write(struct.pack("<3f", *p) if binary else (" ".join(map(repr, p)) + "\n").encode())
        for face, m in faces:
            colour = m["Kd"] + m["Ke"]
            if binary:
                f.write(struct.pack(f"<B{len(face)}i6f", len(face), *face, *colour))
            else:
                f.write((" ".join(map(str, [len(face)] + face)) + " " +
                         " ".join(map(repr, colour)) + "\n").encode())


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out_dir")
    parser.add_argument("--obj", default=DEFAULT_OBJ)
    args = parser.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    name = os.path.splitext(os.path.basename(args.obj))[0]
    positions, materials, objects = read_obj(args.obj)
    write_gltf(positions, materials, objects, args.out_dir, name)
    write_ply(positions, materials, objects, os.path.join(args.out_dir, name + ".ply"), False)
    write_ply(positions, materials, objects, os.path.join(args.out_dir, name + "-binary.ply"),
              True)


if __name__ == "__main__":
    main()
