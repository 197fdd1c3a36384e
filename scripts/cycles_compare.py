#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""hmcr's Cornell box against Blender Cycles: per pixel and per face.

Needs Debian's python3 (/usr/bin/python3) with python3-numpy, which the `blender` package pulls
in; nothing else outside the standard library.

    scripts/cycles_compare.py --hmcr build/hmcr --work cycles-work

It runs, keeping every output in --work so that a second call reuses what is there:

1. Blender (`blender -b -P scripts/cycles_compare.py -- --render ...`): this file again, inside
   Blender, builds the Cornell box from scenes/cornell/cornell.obj + .mtl (the same coordinates,
   no axis conversion), one object per face, a diffuse BSDF of Kd on every face and an emission of
   radiance Ke on the light, the camera view of scenes/cornell/cornell.json, and renders it with
   Cycles on the CPU, --cycles-seeds times with independent seeds, each a linear PFM of radiance.
2. hmcr's path tracer: the camera view at --trace-width with the uniform sampler (the one of
   `hmcr trace-reference`), `hmcr trace --sampler uniform`, with two seeds;
3. the radiosity reference: `hmcr reference cornell` with seeds 1 and 3 (each solves two seeds
   and keeps the first's solution), and `hmcr render --pfm` of each solution at 512 x 512;
4. the comparison, in linear luminance:
   (a) per pixel, Cycles box-filtered to the trace's size against hmcr's trace;
   (b) per face, the mean over the pixels that lie wholly inside one OBJ face (found by casting
       4 x 4 rays per pixel through hmcr's camera), Cycles against the radiosity reference;
   (c) the same per face at the trace's size, Cycles against the trace and the radiosity
       reference against the trace: it tells which of (b)'s two sides a difference belongs to;
   (d) (b) on the floor in bands of the distance to the blocks' bases.
   Each difference has a standard error from the seeds' scatter; for the radiosity reference it
   has one degree of freedom (two seeds), so its z is a rough scale, not a test.
   docs/results.md#agreement-with-blender-cycles shows a run and how to read it.

Cycles against hmcr's OBJ: Blender's faces are two-sided, hmcr's one-sided.  The back of every
wall, the floor, the ceiling and the light faces out of the box, and the back of a block's face
into the closed block: a path from the camera meets a back face only through a crack between
faces.  Cycles' emission shader of strength S and colour C gives the surface radiance S C and
hmcr's `Ke` is the radiance, so the light's shader is colour Ke / max(Ke) at strength max(Ke).

What a run shows (the numbers in docs/results.md): Cycles and hmcr's trace agree to the noise per
pixel and per face, so (b)'s differences are the radiosity reference's.  Its stop criterion's bias
is below 0.01% (the reference's truncation estimate), far below them.  On the floor, (b)'s largest
z, (d) puts the difference within 20 mm of the blocks' bases, about two of the floor's 8.7 mm
elements: the floor is one patch that runs under the blocks, so its elements across a base
average the lit floor with the unlit floor beneath the block.
"""

import argparse
import json
import math
import os
import struct
import subprocess
import sys
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE_DIR = os.path.join(HERE, "..", "scenes", "cornell")
LUMINANCE = (0.2126, 0.7152, 0.0722)


# ---------------------------------------------------------------- the scene and its camera


def read_obj():
    """The Cornell box's vertices, faces (group, material, corner indices) and materials."""
    vertices, faces, materials = [], [], {}
    group, material = "default", None
    with open(os.path.join(SCENE_DIR, "cornell.obj")) as f:
        for line in f:
            w = line.split("#", 1)[0].split()
            if w and w[0] == "v":
                vertices.append([float(x) for x in w[1:4]])
            elif w and w[0] == "f":
                faces.append((group, material, [int(x.split("/")[0]) - 1 for x in w[1:]]))
            elif w and w[0] == "g":
                group = w[1]
            elif w and w[0] == "usemtl":
                material = w[1]
    name = None
    with open(os.path.join(SCENE_DIR, "cornell.mtl")) as f:
        for line in f:
            w = line.split("#", 1)[0].split()
            if w and w[0] == "newmtl":
                name = w[1]
                materials[name] = {"Kd": [0.0] * 3, "Ke": [0.0] * 3}
            elif w and w[0] in ("Kd", "Ke"):
                materials[name][w[0]] = [float(x) for x in w[1:4]]
    return vertices, faces, materials


def camera_view(name="camera"):
    with open(os.path.join(SCENE_DIR, "cornell.json")) as f:
        return next(v for v in json.load(f)["views"] if v["name"] == name)


def camera_frame(view):
    """Right, up and forward unit vectors of hmcr's pinhole (docs/design.md §6.4)."""
    def norm(a):
        n = math.sqrt(sum(x * x for x in a))
        return [x / n for x in a]

    def cross(a, b):
        return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]

    forward = norm([l - p for l, p in zip(view["look_at"], view["position"])])
    right = norm(cross(forward, view["up"]))
    return right, cross(right, forward), forward


# ---------------------------------------------------------------- inside Blender


def blender_render(args):
    import bpy
    import mathutils
    import numpy as np

    vertices, faces, materials = read_obj()
    view = camera_view()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene

    shaders = {}
    for name, m in materials.items():
        mat = bpy.data.materials.new(name)
        mat.use_nodes = True
        nodes, links = mat.node_tree.nodes, mat.node_tree.links
        nodes.clear()
        out = nodes.new("ShaderNodeOutputMaterial")
        diffuse = nodes.new("ShaderNodeBsdfDiffuse")
        diffuse.inputs["Color"].default_value = (*m["Kd"], 1.0)
        diffuse.inputs["Roughness"].default_value = 0.0  # Lambertian
        shader = diffuse.outputs["BSDF"]
        if max(m["Ke"]) > 0:
            # Radiance Ke: colour Ke / max(Ke) at strength max(Ke).
            emission = nodes.new("ShaderNodeEmission")
            k = max(m["Ke"])
            emission.inputs["Color"].default_value = (*[c / k for c in m["Ke"]], 1.0)
            emission.inputs["Strength"].default_value = k
            add = nodes.new("ShaderNodeAddShader")
            links.new(shader, add.inputs[0])
            links.new(emission.outputs["Emission"], add.inputs[1])
            shader = add.outputs["Shader"]
        links.new(shader, out.inputs["Surface"])
        shaders[name] = mat

    for i, (group, material, corners) in enumerate(faces):
        mesh = bpy.data.meshes.new(f"{group}.{i}")
        mesh.from_pydata([vertices[c] for c in corners], [], [list(range(len(corners)))])
        mesh.materials.append(shaders[material])
        obj = bpy.data.objects.new(mesh.name, mesh)
        obj.pass_index = i + 1
        scene.collection.objects.link(obj)

    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    scene.world = world

    cam_data = bpy.data.cameras.new("camera")
    cam_data.sensor_fit = "VERTICAL"
    cam_data.angle_y = math.radians(view["fov"])
    cam_data.clip_start, cam_data.clip_end = 1e-3, 100.0
    cam = bpy.data.objects.new("camera", cam_data)
    right, up, forward = camera_frame(view)
    # Blender's camera looks down its local -Z with +Y up.
    rot = mathutils.Matrix([[right[i], up[i], -forward[i]] for i in range(3)])
    cam.matrix_world = mathutils.Matrix.Translation(view["position"]) @ rot.to_4x4()
    scene.collection.objects.link(cam)
    scene.camera = cam

    render = scene.render
    render.engine = "CYCLES"
    render.resolution_x, render.resolution_y = view["width"], view["height"]
    render.resolution_percentage = 100
    render.film_transparent = False
    render.threads_mode = "FIXED"
    render.threads = args.threads
    render.use_compositing = False
    render.use_sequencer = False
    c = scene.cycles
    c.device = "CPU"
    c.samples = args.samples
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.seed = args.seed
    c.pixel_filter_type = "BOX"  # hmcr's pixel is the mean over its square
    c.filter_width = 1.0
    c.max_bounces = c.diffuse_bounces = 64  # hmcr's trace: 64 bounces, roulette from the 3rd
    c.glossy_bounces = c.transmission_bounces = c.volume_bounces = 0
    c.transparent_max_bounces = 0
    c.min_light_bounces = 0
    c.sample_clamp_direct = c.sample_clamp_indirect = 0.0  # no clamping: unbiased
    c.light_sampling_threshold = 0.0
    c.caustics_reflective = c.caustics_refractive = True
    c.film_exposure = 1.0
    scene.view_settings.view_transform = "Standard"  # Filmic off
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    settings = render.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_depth = "32"
    settings.color_mode = "RGB"
    settings.exr_codec = "ZIP"

    exr = os.path.splitext(args.render)[0] + ".exr"
    render.filepath = exr
    bpy.ops.render.render(write_still=True)
    image = bpy.data.images.load(exr)
    image.colorspace_settings.name = "Linear"
    w, h = image.size
    pixels = np.array(image.pixels[:], dtype=np.float32).reshape(h, w, image.channels)
    write_pfm(args.render, pixels[:, :, :3], bottom_first=True)
    os.remove(exr)


# ---------------------------------------------------------------- images


def write_pfm(path, rgb, bottom_first):
    """rgb: rows x columns x 3, the top row first unless bottom_first (a PFM's order)."""
    import numpy as np
    rows = rgb if bottom_first else rgb[::-1]
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (rows.shape[1], rows.shape[0]))
        f.write(np.ascontiguousarray(rows, dtype="<f4").tobytes())


def read_pfm(path):
    """The image, the top row first (rows x columns x 3, float64)."""
    import numpy as np
    with open(path, "rb") as f:
        assert f.readline().strip() == b"PF"
        w, h = (int(x) for x in f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4")
    return data.reshape(h, w, 3)[::-1].astype(np.float64)


def write_png(path, rgb, exposure):
    """8-bit sRGB of exposure x radiance, the top row first (for looking at)."""
    import numpy as np
    v = np.clip(rgb * exposure, 0.0, 1.0)
    s = np.where(v <= 0.0031308, 12.92 * v, 1.055 * np.power(v, 1 / 2.4) - 0.055)
    rows = np.round(255 * s).astype(np.uint8)
    h, w, _ = rows.shape
    scanlines = b"".join(b"\0" + rows[y].tobytes() for y in range(h))  # filter 0 per row

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data
                + struct.pack(">I", zlib.crc32(kind + data)))
    with open(path, "wb") as f:
        header = struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)  # 8-bit RGB
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header)
                + chunk(b"IDAT", zlib.compress(scanlines)) + chunk(b"IEND", b""))


def box_reduce(img, factor):
    h, w, _ = img.shape
    return img.reshape(h // factor, factor, w // factor, factor, 3).mean(axis=(1, 3))


# ---------------------------------------------------------------- patch ids per pixel


def patch_ids(view, sub=4):
    """Per pixel (top row first) the index of the OBJ face seen through all of its sub x sub
    sample points, or -1 where they see different faces or nothing."""
    import numpy as np
    vertices, faces, _ = read_obj()
    v = np.array(vertices)
    tris = [(i, c[0], c[k], c[k + 1]) for i, (_, _, c) in enumerate(faces)
            for k in range(1, len(c) - 1)]
    right, up, forward = (np.array(a) for a in camera_frame(view))
    w, h = view["width"], view["height"]
    t = math.tan(math.radians(view["fov"]) / 2)
    offsets = (np.arange(sub) + 0.5) / sub
    xs = (np.arange(w)[:, None] + offsets[None, :]).ravel()
    ys = (np.arange(h)[:, None] + offsets[None, :]).ravel()
    px = (2 * xs / w - 1) * t * w / h
    py = (1 - 2 * ys / h) * t
    d = (forward[None, None, :] + px[None, :, None] * right + py[:, None, None] * up)
    d = d.reshape(-1, 3)
    o = np.array(view["position"])
    best_t = np.full(len(d), np.inf)
    best_id = np.full(len(d), -1)
    for pid, a, b, c in tris:  # Moller-Trumbore, both sides
        e1, e2 = v[b] - v[a], v[c] - v[a]
        p = np.cross(d, e2)
        det = p @ e1
        ok = np.abs(det) > 1e-12
        inv = np.where(ok, 1 / np.where(ok, det, 1), 0)
        s = o - v[a]
        u = (p @ s) * inv
        q = np.cross(s, e1)
        vv = (d @ q) * inv
        tt = (q @ e2) * inv
        hit = ok & (u >= 0) & (vv >= 0) & (u + vv <= 1) & (tt > 0) & (tt < best_t)
        best_t[hit], best_id[hit] = tt[hit], pid
    ids = best_id.reshape(h, sub, w, sub).transpose(0, 2, 1, 3).reshape(h, w, sub * sub)
    same = (ids == ids[:, :, :1]).all(axis=2)
    return np.where(same, ids[:, :, 0], -1), faces


# ---------------------------------------------------------------- the comparison


def luminance(img):
    import numpy as np
    return img @ np.array(LUMINANCE)


def seed_mean(runs):
    """Per pixel luminance: the mean of independent runs and the variance of that mean, from the
    runs' scatter (pixels are independent, so a sum of these variances is the variance of the
    sum)."""
    import numpy as np
    lum = np.array([luminance(x) for x in runs])
    return lum.mean(axis=0), lum.var(axis=0, ddof=1) / len(lum)


def per_pixel(cycles_runs, traces):
    """(a): Cycles (K seeds, box-reduced to the trace's size) against hmcr's trace
    (two seeds), in luminance: the relative difference of the image means with its standard
    error, and the RMS of the per-pixel relative differences against what the noise alone
    gives."""
    import numpy as np
    c, c_var = seed_mean(cycles_runs)
    t, t_var = seed_mean(traces)
    diff = c.sum() / t.sum() - 1
    se = math.sqrt(c_var.sum() + t_var.sum()) / t.sum()
    rgb = []
    for ch in range(3):
        cc = np.array([x[:, :, ch] for x in cycles_runs])
        tc = np.array([x[:, :, ch] for x in traces])
        rgb.append((cc.mean(axis=0).sum() / tc.mean(axis=0).sum() - 1,
                    math.sqrt(cc.var(axis=0, ddof=1).sum() / len(cc)
                              + tc.var(axis=0, ddof=1).sum() / len(tc)) / tc.mean(axis=0).sum()))
    lit = t > 0
    return {"pixels": int(c.size), "lit_pixels": int(lit.sum()),
            "mean_relative_difference": diff, "se": se, "rgb": rgb,
            "rms_relative_difference": float(np.sqrt(np.mean(((c - t)[lit] / t[lit]) ** 2))),
            "rms_relative_noise": float(np.sqrt(np.mean((c_var + t_var)[lit] / t[lit] ** 2))),
            "squared_difference_over_variance": float(((c - t) ** 2).sum() / (c_var + t_var).sum())}


def pixel_noise(runs):
    """A face statistic of independent runs of a path tracer: the mean over the face's pixels
    and its standard error, from the per-pixel variance of the runs' mean (pixels independent)."""
    mean, var = seed_mean(runs)

    def stat(mask):
        n = mask.sum()
        return mean[mask].mean(), math.sqrt(var[mask].sum()) / n
    return stat


def solution_noise(runs):
    """A face statistic of radiosity solutions (seeds 1 and 3): the first's mean over the face's
    pixels, and as its standard error the two seeds' difference over sqrt 2 (one degree of
    freedom: its pixels share elements, so they are not independent)."""
    lum = [luminance(x) for x in runs]

    def stat(mask):
        m = [x[mask].mean() for x in lum]
        return m[0], abs(m[1] - m[0]) / math.sqrt(2) if len(m) > 1 else 0.0
    return stat


def patch_rows(ids, faces, test, base):
    """Per face with 4 or more interior pixels: the two statistics, test / base - 1 and its
    standard error."""
    rows = []
    for pid, (group, _, _) in enumerate(faces):
        mask = ids == pid
        if mask.sum() < 4:
            continue
        (ma, sa), (mb, sb) = test(mask), base(mask)
        rows.append({"patch": pid, "group": group, "pixels": int(mask.sum()), "test": ma,
                     "test_se": sa, "base": mb, "base_se": sb, "difference": ma / mb - 1,
                     "se": math.hypot(sa / mb, ma * sb / mb ** 2)})
    return rows


def floor_by_block_distance(view, ids, faces, cycles, radiosity, bands_mm=(0, 5, 10, 20, 50)):
    """(d): the floor's interior pixels in bands of their distance (on the floor, from each
    pixel's centre ray) to the blocks' bases: per band the pixels, Cycles / radiosity reference
    - 1 with Cycles' standard error, and the band's share of the floor's whole difference."""
    import numpy as np
    vertices, _, _ = read_obj()
    v = np.array(vertices)
    floor = [i for i, (group, _, _) in enumerate(faces) if group == "floor"]
    mask = np.isin(ids, floor)
    bases = [(v[a][[0, 2]], v[b][[0, 2]]) for group, _, c in faces if "block" in group
             for a, b in zip(c, c[1:] + c[:1]) if v[a][1] == 0 and v[b][1] == 0]
    right, up, forward = (np.array(a) for a in camera_frame(view))
    rows, cols = np.nonzero(mask)
    t = math.tan(math.radians(view["fov"]) / 2)
    px = (2 * (cols + 0.5) / view["width"] - 1) * t * view["width"] / view["height"]
    py = (1 - 2 * (rows + 0.5) / view["height"]) * t
    d = forward + px[:, None] * right + py[:, None] * up
    o = np.array(view["position"])
    hit = (o + (-o[1] / d[:, 1])[:, None] * d)[:, [0, 2]]  # the floor is y = 0
    dist = np.full(len(hit), np.inf)
    for a, b in bases:
        s = np.clip((hit - a) @ (b - a) / ((b - a) @ (b - a)), 0, 1)
        dist = np.minimum(dist, np.linalg.norm(hit - a - s[:, None] * (b - a), axis=1))
    c, c_var = seed_mean(cycles)
    c, c_var, r = c[mask], c_var[mask], luminance(radiosity[0])[mask]
    total = c.sum() - r.sum()
    out = []
    for lo, hi in zip(bands_mm, list(bands_mm[1:]) + [math.inf]):
        m = (dist >= lo / 1000) & (dist < hi / 1000)
        out.append({"from_mm": lo, "to_mm": hi, "pixels": int(m.sum()),
                    "difference": c[m].sum() / r[m].sum() - 1,
                    "se": math.sqrt(c_var[m].sum()) / r[m].sum(),
                    "share": (c[m].sum() - r[m].sum()) / total})
    return out


# ---------------------------------------------------------------- the driver


def run(command):
    print("$", " ".join(command), flush=True)
    subprocess.run(command, check=True)


def main():
    if "--" in sys.argv:  # inside Blender
        ap = argparse.ArgumentParser()
        ap.add_argument("--render", required=True)
        ap.add_argument("--samples", type=int, required=True)
        ap.add_argument("--seed", type=int, required=True)
        ap.add_argument("--threads", type=int, default=2)
        blender_render(ap.parse_args(sys.argv[sys.argv.index("--") + 1:]))
        return

    import system_python  # outside Blender only: Blender's Python has its own numpy

    system_python.need("numpy")
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--hmcr", default=os.path.join(HERE, "..", "build", "hmcr"))
    ap.add_argument("--blender", default="blender")
    ap.add_argument("--work", required=True, help="folder for every output; reused if there")
    ap.add_argument("--cycles-samples", type=int, default=256, help="per seed")
    ap.add_argument("--cycles-seeds", type=int, default=4)
    ap.add_argument("--trace-width", type=int, default=256)
    ap.add_argument("--trace-spp", type=int, default=2048, help="per seed (two seeds)")
    ap.add_argument("--reference-rays", default="200000000")
    ap.add_argument("--sequence", help="the radiosity reference's ray sequence (default: hmcr's)")
    ap.add_argument("--threads", type=int, default=2)
    args = ap.parse_args()
    hmcr = os.path.abspath(args.hmcr)
    work = os.path.abspath(args.work)
    os.makedirs(work, exist_ok=True)
    view = camera_view()

    cycles = []
    for s in range(1, args.cycles_seeds + 1):
        path = os.path.join(work, f"cycles-{s}.pfm")
        if not os.path.exists(path):
            run([args.blender, "-b", "--python-exit-code", "1", "-P", os.path.abspath(__file__),
                 "--", "--render", path, "--samples", str(args.cycles_samples), "--seed", str(s),
                 "--threads", str(args.threads)])
        cycles.append(read_pfm(path))
    traces = []
    for s in (1, 2):
        pfm = os.path.join(work, f"trace-{s}.pfm")
        if not os.path.exists(pfm):
            run([hmcr, "trace", "cornell", "--view", "camera", "--sampler", "uniform",
                 "--width", str(args.trace_width), "--spp", str(args.trace_spp), "--seed", str(s),
                 "--threads", str(args.threads), "-q", "--pfm", pfm,
                 "-o", os.path.join(work, f"trace-{s}.png")])
        traces.append(read_pfm(pfm))
    radiosity = []
    for s in (1, 3):
        folder = os.path.join(work, f"reference-{s}")
        pfm = os.path.join(work, f"radiosity-{s}.pfm")
        if not os.path.exists(os.path.join(folder, "reference.vtp")):
            sequence = ["--sequence", args.sequence] if args.sequence else []
            run([hmcr, "reference", "cornell", "--rays", args.reference_rays, "--seed", str(s),
                 "--threads", str(args.threads), "-q", "-o", folder] + sequence)
        if not os.path.exists(pfm):
            run([hmcr, "render", os.path.join(folder, "reference.vtp"), "--scene", "cornell",
                 "--view", "camera", "--samples", "4", "--pfm", pfm,
                 "-o", os.path.join(work, f"radiosity-{s}.png")])
        radiosity.append(read_pfm(pfm))

    factor = view["width"] // args.trace_width
    args.box = factor
    small = [box_reduce(x, factor) for x in cycles]
    a = per_pixel(small, traces)
    ids, faces = patch_ids(view)
    b = patch_rows(ids, faces, pixel_noise(cycles), solution_noise(radiosity))
    small_view = dict(view, width=args.trace_width, height=view["height"] // factor)
    small_ids, _ = patch_ids(small_view)
    c = {"cycles_vs_trace": patch_rows(small_ids, faces, pixel_noise(small), pixel_noise(traces)),
         "radiosity_vs_trace": patch_rows(small_ids, faces,
                                          solution_noise([box_reduce(x, factor)
                                                          for x in radiosity]),
                                          pixel_noise(traces))}
    c["floor_by_block_distance"] = floor_by_block_distance(view, ids, faces, cycles, radiosity)
    lum = luminance(radiosity[0])
    exposure = 0.18 / lum[lum > 0].mean()
    for name, img in (("cycles", sum(cycles) / len(cycles)), ("radiosity", radiosity[0]),
                      ("trace", sum(traces) / len(traces))):
        write_png(os.path.join(work, f"look-{name}.png"), img, exposure)
    report(a, b, c, args, work)


def print_rows(rows, test, base):
    print(f"  {'patch':>5} {'face':<12} {'pixels':>6} {test:>9} {base:>9} "
          f"{'difference':>10} {'s.e.':>7} {'z':>6}")
    for r in rows:
        z = r["difference"] / r["se"] if r["se"] else float("nan")
        print(f"  {r['patch']:>5} {r['group']:<12} {r['pixels']:>6} {r['test']:>9.5f} "
              f"{r['base']:>9.5f} {100 * r['difference']:>+9.3f}% {100 * r['se']:>6.3f}% "
              f"{z:>6.1f}")


def report(a, b, c, args, work):
    print(f"\n(a) per pixel, {args.trace_width} x {args.trace_width}: Cycles "
          f"{args.cycles_seeds} x {args.cycles_samples} spp (box-filtered {args.box} x {args.box}) "
          f"against hmcr's trace, 2 x {args.trace_spp} spp")
    print(f"  image mean luminance, Cycles / trace - 1: {100 * a['mean_relative_difference']:+.4f}%"
          f" ± {100 * a['se']:.4f}%  (R, G, B: "
          + ", ".join(f"{100 * d:+.4f} ± {100 * s:.4f}%" for d, s in a["rgb"]) + ")")
    print(f"  RMS per-pixel relative difference {100 * a['rms_relative_difference']:.3f}%, from "
          f"the noise alone {100 * a['rms_relative_noise']:.3f}%; sum of squared differences / "
          f"sum of their variances {a['squared_difference_over_variance']:.4f}")
    print("\n(b) per face, mean luminance over its interior pixels at 512 x 512, "
          "Cycles / radiosity reference - 1:")
    print_rows(b, "Cycles", "hmcr")
    print(f"\n(c) per face at {args.trace_width} x {args.trace_width}, against hmcr's trace: "
          "Cycles / trace - 1")
    print_rows(c["cycles_vs_trace"], "Cycles", "trace")
    print("    radiosity reference / trace - 1")
    print_rows(c["radiosity_vs_trace"], "radiosity", "trace")
    print("\n(d) the floor's interior pixels by their distance to the blocks' bases: "
          "Cycles / radiosity reference - 1")
    for r in c["floor_by_block_distance"]:
        print(f"  {r['from_mm']:>3} to {r['to_mm']:>3} mm {r['pixels']:>6} pixels "
              f"{100 * r['difference']:>+8.3f}% ± {100 * r['se']:.3f}%, "
              f"{100 * r['share']:>4.0f}% of the floor's difference")
    with open(os.path.join(work, "comparison.json"), "w") as f:
        json.dump({"per_pixel": a, "per_patch": b, **c}, f, indent=1)


if __name__ == "__main__":
    main()
