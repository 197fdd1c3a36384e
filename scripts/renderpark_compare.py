#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""hmcr against RenderPark's port (rpkCpp), one thread, the Cornell box: times, errors or noise.

What it does, in order (docs/performance.md#against-renderpark shows a run):

1. Converts hmcr's Cornell box (an OBJ with Kd reflectances and Ke radiances, metres) to MGF so
   that rpkCpp solves the same scene (see `write_mgf` for the colour and emission semantics).
2. Builds rpkCpp in a temporary folder from its public repository: the tarball of a pinned commit
   from GitHub, or, with `--rpk-source DIR` (or $RPK_SOURCE), a git directory already on the
   machine (a clone or a bare mirror: its tree is exported with `git archive`), or a source
   folder.  Nothing of rpkCpp is kept in hmcr's repository.
3. Times: runs each program once to read its element and ray counts, then N pairs of
   whole-process runs, alternated (hmcr first in odd pairs, rpkCpp first in even ones) under
   /usr/bin/time, and prints both medians, the ratio of the medians and the median of the
   paired ratios.
   Errors (`--error`): adds to the copy of rpkCpp a writer of its final leaves (rpk_leaves.py),
   runs it, turns the leaves into two foreign solutions (constant per leaf, and rpkCpp's own
   Gouraud display) and measures them with `hmcr error --foreign` against a point reference,
   beside hmcr's solves at rpkCpp's ray count and at rpkCpp's CPU time
   (docs/performance.md#renderparks-error).
   Noise (`--noise`): adds to the copy of rpkCpp, beside the leaf writer, a few lines of this
   project's (rpk_leaves.NOISE_EDITS) that make its stochastic Jacobi honour
   -srr-sampling-sequence, seed drand48 from $HMCR_RPK_SEED and, with $HMCR_RPK_DOUBLE, sum the
   received radiance in double. Then on fixed meshes (hmcr `--max-depth 0`, rpkCpp
   `-srr-hierarchical no -srr-clustering none`), the Cornell box and RenderPark MGF scenes
   (`--mgf`, default rpkCpp's etc/cube.mgf; hmcr reads it with `--sides 1`, as RenderPark
   does), one thread, each engine against its own converged solve at `--converged-factor`
   times the rays (hmcr: sobol, seed 1000; rpkCpp: Niederreiter with double sums): the
   per-patch relative RMS deviation of scripts/fixed_mesh_noise.py over the channels lit in
   both references, on the patches matched between the engines by centroid, normal and area;
   the median whole-process CPU seconds; the efficiency 1 / (deviation^2 x seconds) relative to
   rpkCpp Niederreiter's. hmcr's rows (`--variants`) and rpkCpp PseudoRandom run seeds 1..k;
   rpkCpp Niederreiter, which has no seed, runs k ray-unit counts `--curve-step` apart around
   the units that shoot `--rays` (docs/performance.md#renderparks-noise-per-patch).

Standard library only.  Usage:
    scripts/renderpark_compare.py --hmcr build/hmcr [--rpk-source DIR] [--pairs 7]
    scripts/renderpark_compare.py --error --hmcr build/hmcr [--rpk-source DIR] [--reference DIR]
    scripts/renderpark_compare.py --noise --hmcr build/hmcr [--rpk-source DIR] [--seeds 8]
"""

import argparse
import ctypes
import functools
import json
import math
import os
import re
import shutil
import statistics
import struct
import subprocess
import sys
import tarfile
import tempfile
import urllib.request
import zlib

RPK_REPOSITORY = "https://github.com/OscarChavarro/rpkCpp"
RPK_COMMIT = "37e5ff4e"  # the commit this comparison was measured with
RPK_TARBALL = "https://codeload.github.com/OscarChavarro/rpkCpp/tar.gz/{commit}"

# rpkCpp's default monitor primaries and white (src/tonemap/ToneMappingContext.cpp): its
# internal RGB.  Its MGF reader turns (x, y, Y) into XYZ, then into RGB by these primaries.
RPK_PRIMARIES = ((0.640, 0.330), (0.290, 0.600), (0.150, 0.060))
RPK_WHITE = (1.0 / 3.0, 1.0 / 3.0)
# rpkCpp divides `ed` (lm/m^2) by this to get W/m^2 (src/common/cie.cpp, WHITE_EFFICACY).
RPK_WHITE_EFFICACY = 183.07

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import patch_noise  # noqa: E402  (beside this script)
import rpk_leaves  # noqa: E402
CORNELL_OBJ = os.path.join(HERE, "..", "scenes", "cornell", "cornell.obj")


# ---------------------------------------------------------------- colour conversion


def _solve3(m, v):
    """Solves m x = v for a 3 x 3 matrix by Cramer's rule."""
    def det(a):
        return (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
                - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
                + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))
    d = det(m)
    out = []
    for c in range(3):
        mc = [row[:] for row in m]
        for r in range(3):
            mc[r][c] = v[r]
        out.append(det(mc) / d)
    return out


def rgb_to_xyz_matrix(primaries, white):
    """The RGB -> XYZ matrix of the given (x, y) primaries, RGB (1, 1, 1) mapping to the white
    with Y = 1 (the construction of rpkCpp's computeColorConversionTransforms)."""
    cols = [(x / y, 1.0, (1.0 - x - y) / y) for x, y in primaries]
    m = [[cols[c][r] for c in range(3)] for r in range(3)]
    wx, wy = white
    scale = _solve3(m, [wx / wy, 1.0, (1.0 - wx - wy) / wy])
    return [[m[r][c] * scale[c] for c in range(3)] for r in range(3)]


def rgb_to_mgf_colour(rgb):
    """(x, y, Y) of a linear rgb in rpkCpp's RGB: the MGF `cxy x y` and the luminance that
    `rd` or `ed` carries.  rpkCpp reads them back to this rgb (up to float rounding)."""
    m = rgb_to_xyz_matrix(RPK_PRIMARIES, RPK_WHITE)
    xyz = [sum(m[r][c] * rgb[c] for c in range(3)) for r in range(3)]
    s = sum(xyz)
    return xyz[0] / s, xyz[1] / s, xyz[1]


# ---------------------------------------------------------------- OBJ + MTL -> MGF


def read_obj(obj_path):
    """Vertices, faces (material, group, vertex indices from 0) and the MTL's Kd and Ke."""
    vertices, faces, materials = [], [], {}
    material, group, mtllib = None, "default", None
    with open(obj_path) as f:
        for line in f:
            words = line.split("#", 1)[0].split()
            if not words:
                continue
            if words[0] == "v":
                vertices.append(tuple(float(w) for w in words[1:4]))
            elif words[0] == "f":
                faces.append((material, group, [int(w.split("/")[0]) - 1 for w in words[1:]]))
            elif words[0] == "usemtl":
                material = words[1]
            elif words[0] == "g":
                group = words[1]
            elif words[0] == "mtllib":
                mtllib = os.path.join(os.path.dirname(obj_path), words[1])
    name = None
    with open(mtllib) as f:
        for line in f:
            words = line.split("#", 1)[0].split()
            if words and words[0] == "newmtl":
                name = words[1]
                materials[name] = {"Kd": (0.0, 0.0, 0.0), "Ke": (0.0, 0.0, 0.0)}
            elif words and words[0] in ("Kd", "Ke"):
                materials[name][words[0]] = tuple(float(w) for w in words[1:4])
    return vertices, faces, materials


def write_mgf(obj_path, mgf_path):
    """Writes the OBJ scene as MGF for rpkCpp, the same scene in rpkCpp's units.

    - Geometry: the same vertices in metres (MGF has no unit; rpkCpp's thresholds are relative)
      and the same faces with the same corner order: MGF and OBJ both face a polygon toward the
      side from which its corners turn counter-clockwise.  Materials are `sides 1`, as hmcr's
      faces are one-sided.
    - Reflectance: hmcr's Kd is linear RGB.  MGF states a colour as CIE (x, y) and `rd` as its
      luminance Y; rpkCpp turns (x, y, Y) into its RGB by its default primaries (not Rec. 709:
      green is at (0.29, 0.60)) with an equal-energy white.  So Kd is taken to XYZ through the
      inverse of that same transform: rpkCpp reads back Kd exactly.
    - Emission: hmcr's Ke is radiance (W sr^-1 m^-2), the emitted radiosity E = pi Ke (W/m^2).
      MGF's `ed` is a luminous exitance (lm/m^2), which rpkCpp divides by its white efficacy,
      183.07 lm/W, to get the exitance in W/m^2 (its radiance is that over pi).  So the light's
      `ed` is 183.07 x Y(pi Ke) with the chromaticity of Ke: rpkCpp emits the same watts.
    """
    vertices, faces, materials = read_obj(obj_path)
    out = ["# hmcr's Cornell box for rpkCpp, written by scripts/renderpark_compare.py.",
           "# Colours are in rpkCpp's RGB (its default primaries); ed = 183.07 Y(pi Ke).", ""]
    for name, mat in materials.items():
        out += [f"m {name} =", "\tsides 1"]
        x, y, lum = rgb_to_mgf_colour(mat["Kd"])
        out += ["\tc", f"\t\tcxy {x:.9f} {y:.9f}", f"\trd {lum:.9f}"]
        if any(mat["Ke"]):
            x, y, lum = rgb_to_mgf_colour([math.pi * k for k in mat["Ke"]])
            out += ["\tc", f"\t\tcxy {x:.9f} {y:.9f}", f"\ted {RPK_WHITE_EFFICACY * lum:.9f}"]
    out.append("")
    for i, (px, py, pz) in enumerate(vertices):
        out += [f"v v{i} =", f"\tp {px!r} {py!r} {pz!r}"]
    out.append("")
    group = None
    for material, g, corners in faces:
        if g != group:
            if group is not None:
                out.append("o")
            out.append(f"o {g}")
            group = g
        out += [f"m {material}", "f " + " ".join(f"v{c}" for c in corners)]
    if group is not None:
        out.append("o")
    with open(mgf_path, "w") as f:
        f.write("\n".join(out) + "\n")


# ---------------------------------------------------------------- rpkCpp's build


def fetch_rpk_source(source, commit, dest):
    """Puts rpkCpp's CMakeLists.txt and src/ (and etc/) into dest."""
    os.makedirs(dest)
    if source and os.path.isdir(os.path.join(source, "src")):
        for part in ("CMakeLists.txt", "src", "etc"):
            src = os.path.join(source, part)
            (shutil.copytree if os.path.isdir(src) else shutil.copy)(src, os.path.join(dest, part))
        return f"the source folder {source}"
    if source:  # a git directory: a clone's .git, a bare repository or a mirror
        archive = subprocess.run(["git", "--git-dir", source, "archive", commit,
                                  "CMakeLists.txt", "src", "etc"],
                                 check=True, capture_output=True).stdout
        subprocess.run(["tar", "-x", "-C", dest], input=archive, check=True)
        return f"git archive {commit} of {source}"
    url = RPK_TARBALL.format(commit=commit)
    tarball = os.path.join(dest, "rpk.tar.gz")
    urllib.request.urlretrieve(url, tarball)
    with tarfile.open(tarball) as t:
        top = t.getnames()[0].split("/")[0]
        wanted = (["CMakeLists.txt"], ["src"], ["etc"])  # below the tarball's top folder
        t.extractall(dest, members=[m for m in t.getmembers() if m.name.split("/")[1:2] in wanted])
    for part in os.listdir(os.path.join(dest, top)):
        shutil.move(os.path.join(dest, top, part), dest)
    return url


def build_rpk(source_dir, jobs):
    build = os.path.join(source_dir, "build")
    subprocess.run(["cmake", "-S", source_dir, "-B", build, "-DCMAKE_BUILD_TYPE=Release"],
                   check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["cmake", "--build", build, "-j", str(jobs)], check=True,
                   stdout=subprocess.DEVNULL)
    return os.path.join(build, "rpk")


# ---------------------------------------------------------------- the runs


def rpk_command(rpk, mgf, args, clustering):
    return [rpk, mgf, "-raytracing-method", "none", "-radiance-method", "StochJacobi",
            "-iterations", str(args.iterations), "-srr-ray-units", str(args.ray_units),
            "-srr-hierarchical", "yes", "-srr-epsilon", str(args.rpk_epsilon),
            "-srr-clustering", clustering]


def hmcr_command(args, out_dir):
    return [args.hmcr, "solve", "cornell", "--oracle", "power", "--threads", "1",
            "--refine-share", "1", "--epsilon", str(args.hmcr_epsilon), "--rays", str(args.rays), "-q",
            "-o", os.path.join(out_dir, "cornell.vtp")] + \
        (["--sequence", args.sequence] if args.sequence else [])


def timed(command, cwd):
    """Whole-process wall seconds, CPU seconds and peak resident MB of one run, and its stderr."""
    r = subprocess.run(["/usr/bin/time", "-f", "TIME %e %U %S %M"] + command, cwd=cwd,
                       capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{command[0]} failed ({r.returncode}):\n{r.stderr[-2000:]}")
    wall, user, system, kb = re.findall(r"TIME (\S+) (\S+) (\S+) (\S+)", r.stderr)[-1]
    return float(wall), float(user) + float(system), int(kb) / 1024, r.stderr


def rpk_counts(stderr, patches):
    """Elements, clusters, surface elements, rays and the final total flux of an rpkCpp run."""
    e, c, s = (int(v) for v in re.findall(r"(\d+) elements \((\d+) clusters, (\d+) surfaces\)",
                                          stderr)[-1])
    rays = int(re.findall(r"Radiance rays: (\d+)", stderr)[-1])
    flux = re.findall(r"total flux = ([-\d.e+ ]+)", stderr)
    # The S surface elements are the patches and their descendants; every subdivision makes 4
    # children, so the leaves are S - (S - patches) / 4.
    leaves = s - (s - patches) // 4
    return {"elements": e, "clusters": c, "surface_elements": s, "leaves": leaves, "rays": rays,
            "total_flux": [float(v) for v in flux[-1].split()] if flux else None,
            "emitted_flux": [float(v) for v in flux[0].split()] if flux else None}


@functools.cache
def liblz4():
    """The liblz4 that VTK links, loaded once."""
    return ctypes.CDLL("liblz4.so.1")


def lz4_block(data, size):
    """One LZ4 block of VTK's LZ4 compressor."""
    out = ctypes.create_string_buffer(size)
    n = liblz4().LZ4_decompress_safe(data, out, len(data), size)
    if n != size:
        raise ValueError(f"an LZ4 block of {len(data)} bytes gives {n} bytes, not {size}")
    return out.raw


def vtp_array(path, name, section=None):
    """One appended, compressed array of hmcr's .vtp (docs/design.md §11.4) as a flat list: the
    first of that name, or the first after the tag `section` (such as "<Polys>")."""
    with open(path, "rb") as f:
        data = f.read()
    head = data[:data.index(b"<AppendedData")].decode()
    lz4 = 'compressor="vtkLZ4DataCompressor"' in head  # zlib in files of older versions
    start = head.index(section) if section else 0
    tag = re.search(r'<DataArray type="(\w+)" Name="%s"[^>]*offset="(\d+)"' % name,
                    head[start:])
    kind = {"Float32": "f", "Float64": "d", "Int32": "i", "Int64": "q"}[tag.group(1)]
    offset = int(tag.group(2))
    start = data.index(b"_", data.index(b"<AppendedData")) + 1 + offset
    blocks, block_size, last_size = struct.unpack_from("<3I", data, start)
    sizes = struct.unpack_from(f"<{3 + blocks}I", data, start)[3:]
    pos, raw = start + 4 * (3 + blocks), b""
    for k, size in enumerate(sizes):
        whole = last_size if k == blocks - 1 and last_size else block_size
        block = data[pos:pos + size]
        raw += lz4_block(block, whole) if lz4 else zlib.decompress(block)
        pos += size
    return struct.unpack(f"<{len(raw) // struct.calcsize(kind)}{kind}", raw)


def hmcr_counts(out_dir):
    """Element and ray counts of hmcr's summary, and its solution's total flux sum(B A), W."""
    with open(os.path.join(out_dir, "cornell.json")) as f:
        summary = json.load(f)
    vtp = os.path.join(out_dir, "cornell.vtp")
    b, area = vtp_array(vtp, "ElementRadiosity"), vtp_array(vtp, "ElementArea")
    flux = [sum(b[3 * i + c] * a for i, a in enumerate(area)) for c in range(3)]
    return {**{k: summary["counts"][k] for k in ("elements", "leaves", "rays")},
            "emitted_flux": summary["power"]["emitted_w"], "total_flux": flux}


def compare(name, commands, cwd, pairs):
    """Paired, alternated runs of two commands: their medians and ratios."""
    times = {k: [] for k in commands}
    ratios, cpu_ratios = [], []
    order = list(commands)
    for p in range(pairs):
        pair = {}
        for k in (order if p % 2 == 0 else order[::-1]):
            pair[k] = timed(commands[k], cwd)
            times[k].append(pair[k])
        ratios.append(pair[order[0]][0] / pair[order[1]][0])
        cpu_ratios.append(pair[order[0]][1] / pair[order[1]][1])
        print(f"  pair {p + 1}: " + ", ".join(f"{k} {pair[k][0]:.2f} s" for k in order),
              flush=True)
    med = {k: statistics.median(t[0] for t in v) for k, v in times.items()}
    cpu = {k: statistics.median(t[1] for t in v) for k, v in times.items()}
    mem = {k: statistics.median(t[2] for t in v) for k, v in times.items()}
    a, b = order
    print(f"{name}: {pairs} pairs; median wall {a} {med[a]:.2f} s (CPU {cpu[a]:.2f} s, "
          f"{mem[a]:.0f} MB), {b} {med[b]:.2f} s (CPU {cpu[b]:.2f} s, {mem[b]:.0f} MB); "
          f"ratio of medians {med[a] / med[b]:.3f}, median paired ratio "
          f"{statistics.median(ratios):.3f} (range {min(ratios):.3f}-{max(ratios):.3f}); "
          f"CPU: ratio of medians {cpu[a] / cpu[b]:.3f}, median paired ratio "
          f"{statistics.median(cpu_ratios):.3f} (range {min(cpu_ratios):.3f}-"
          f"{max(cpu_ratios):.3f})")
    return {"pairs": [{k: times[k][i][:3] for k in order} for i in range(pairs)],
            "median_s": med, "median_cpu_s": cpu, "median_peak_mb": mem,
            "ratio_of_medians": med[a] / med[b], "median_paired_ratio": statistics.median(ratios),
            "cpu_ratio_of_medians": cpu[a] / cpu[b],
            "cpu_median_paired_ratio": statistics.median(cpu_ratios)}


# ---------------------------------------------------------------- errors (--error)


def cpu_runs(command, cwd, repeats, env=None):
    """The median whole-process CPU seconds of `repeats` runs, and the last run's stderr."""
    cpu, stderr = [], ""
    for _ in range(repeats):
        r = subprocess.run(["/usr/bin/time", "-f", "TIME %e %U %S %M"] + command, cwd=cwd,
                           capture_output=True, text=True, env=env)
        if r.returncode != 0:
            sys.exit(f"{command[0]} failed ({r.returncode}):\n{r.stderr[-2000:]}")
        _, user, system, _ = re.findall(r"TIME (\S+) (\S+) (\S+) (\S+)", r.stderr)[-1]
        cpu.append(float(user) + float(system))
        stderr = r.stderr
    return statistics.median(cpu), stderr


def hmcr_error(args, solution, foreign):
    """`hmcr error`'s object error (with its standard error) and view PSNRs of one solution."""
    out = solution + ".error.json"
    command = [args.hmcr, "error", solution, "--reference", args.reference, "--scene", "cornell",
               "-o", out] + (["--foreign"] if foreign else [])
    r = subprocess.run(command, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"hmcr error failed ({r.returncode}):\n{r.stderr[-2000:]}")
    with open(out) as f:
        metrics = json.load(f)
    o = metrics["object_error"]
    return {"object_error": o["relative_l2"], "standard_error": o["standard_error"],
            "unmatched": o["unmatched"],
            "psnr_a": {v: m["psnr_a"] for v, m in metrics["views"].items()}}


def hmcr_solve_command(args, config, rays, seed, out):
    """hmcr's solve of the Cornell box in one of the measured settings, at `rays` rays."""
    command = [args.hmcr, "solve", "cornell", "--threads", "1", "--rays", str(rays), "--seed",
               str(seed), "-q", "-o", out]
    if args.sequence:
        command += ["--sequence", args.sequence]
    if config == "matched":  # the timing comparison's: power, rpkCpp's leaves, refined once
        command += ["--oracle", "power", "--refine-share", "1", "--epsilon",
                    str(args.hmcr_epsilon)]
    return command


def hmcr_at(args, config, rays, work, name, seed=1, repeats=None):
    """One hmcr solve: its CPU seconds, leaves, powers, repairs and errors."""
    out = os.path.join(work, f"{name}.vtp")
    cpu, _ = cpu_runs(hmcr_solve_command(args, config, rays, seed, out), work,
                      repeats or args.repeats)
    with open(os.path.join(work, f"{name}.json")) as f:
        summary = json.load(f)
    b, area = vtp_array(out, "ElementRadiosity"), vtp_array(out, "ElementArea")
    return {"requested_rays": rays, "rays": summary["counts"]["rays"],
            "leaves": summary["counts"]["leaves"], "cpu_s": cpu,
            "emitted_w": summary["power"]["emitted_w"],
            "total_w": [sum(b[3 * i + c] * a for i, a in enumerate(area)) for c in range(3)],
            "repairs": summary["scene"]["repairs"]["count"],
            "patches": summary["scene"]["patches"], **hmcr_error(args, out, False)}


def with_seeds(args, config, first, work, name):
    """The first seed's solve with the object errors of seeds 2..k at the same rays."""
    errors = [first["object_error"]]
    for seed in range(2, args.seeds + 1):
        errors.append(hmcr_at(args, config, first["requested_rays"], work, f"{name}-{seed}",
                              seed, 1)["object_error"])
    return {**first, "seed_errors": errors, "mean_error": statistics.mean(errors)}


def hmcr_at_equal_time(args, config, first, target_cpu, work):
    """hmcr's solve whose CPU time matches target_cpu: the rays scaled by the time ratio, then
    corrected once along the line through the two runs (a solve's time is a + b rays)."""
    name = f"hmcr-{config}-time"
    rays = int(first["requested_rays"] * target_cpu / first["cpu_s"])
    second = hmcr_at(args, config, rays, work, name)
    slope = (second["cpu_s"] - first["cpu_s"]) / (second["rays"] - first["rays"])
    if slope > 0:
        rays = int(second["requested_rays"] + (target_cpu - second["cpu_s"]) / slope)
        second = hmcr_at(args, config, rays, work, name)
    return with_seeds(args, config, second, work, name)


def rpk_solutions(args, rpk, mgf, clustering, work):
    """rpkCpp's run with its leaves written, their checks and both foreign solutions' errors."""
    command = rpk_command(rpk, mgf, args, clustering)
    cpu, stderr = cpu_runs(command, work, args.repeats)
    leaf_file = os.path.join(work, f"rpk-{clustering}.leaves")
    _, stderr = cpu_runs(command, work, 1, env={**os.environ,
                                                 rpk_leaves.LEAF_FILE_VARIABLE: leaf_file})
    if not os.path.exists(leaf_file):
        sys.exit(f"{rpk} wrote no leaves: it is not a build of this script's (use --rpk-source)")
    vertices, faces, _ = read_obj(CORNELL_OBJ)
    faces = [[vertices[v] for v in corners] for _, _, corners in faces]
    try:
        leaves = rpk_leaves.read_leaves(leaf_file)
        patches = rpk_leaves.leaf_patches(leaves, rpk_leaves.FaceFinder(faces), leaf_file)
    except ValueError as e:
        sys.exit(str(e))
    result = {"command": command[2:], "cpu_s": cpu, **rpk_counts(stderr, len(faces)),
              "leaves": len(leaves.leaves),
              "checks": rpk_leaves.check_units(leaves, faces, patches)}
    for kind, make in (("constant", rpk_leaves.constant_solution),
                       ("gouraud", rpk_leaves.gouraud_solution)):
        solution = make(leaves, patches)
        path = os.path.join(work, f"rpk-{clustering}-{kind}.vtp")
        rpk_leaves.write_vtp(solution, path)
        result[kind] = {"integral_w": rpk_leaves.solution_power(solution),
                        **hmcr_error(args, path, True)}
    return result


def verify_units(clustering, rpk, hmcr_emitted):
    """Stops unless the leaves emit hmcr's watts and hold rpkCpp's own total flux (1e-3)."""
    checks = rpk["checks"]
    for what, got, want in (("emitted power", checks["emitted_w"], hmcr_emitted),
                            ("total flux", checks["total_w"], rpk["total_flux"])):
        if any(abs(g - w) > 1e-3 * max(abs(w), 1e-12) for g, w in zip(got, want)):
            sys.exit(f"rpkCpp ({clustering}): the leaves' {what} {fmt_w(got)} W is not "
                     f"{fmt_w(want)} W: the units or the leaves are wrong")


def make_reference(args, work):
    if args.reference:
        return os.path.abspath(args.reference)
    ref = os.path.join(work, "reference")
    command = [args.hmcr, "reference", "cornell", "-o", ref, "-q", "--points",
               str(args.reference_points), "--paths", str(args.reference_paths), "--spp",
               str(args.reference_spp)]
    print("reference:", " ".join(["hmcr"] + command[1:]), flush=True)
    subprocess.run(command, check=True)
    return ref


def print_errors(results):
    """The comparison as a table: one row a solution."""
    print("| solution | rays | leaves | CPU s | object error ± se | hmcr seeds | PSNRa, dB |")
    print("|:--|--:|--:|--:|--:|--:|--:|")

    def row(name, r, seeds=""):
        psnr = ", ".join(f"{p:.2f}" for p in r["psnr_a"].values())
        print(f"| {name} | {r['rays']:,} | {r['leaves']:,} | {r['cpu_s']:.2f} | "
              f"{r['object_error']:.4f} ± {r['standard_error']:.4f} | {seeds} | {psnr} |")

    for clustering, rpk in results["rpk"].items():
        for kind in ("constant", "gouraud"):
            row(f"rpkCpp {clustering}, {kind}", {**rpk, **rpk[kind]})
    for name, h in results["hmcr"].items():
        seeds = ", ".join(f"{e:.4f}" for e in h["seed_errors"])
        row(f"hmcr {name}", h, f"{seeds} (mean {h['mean_error']:.4f})")
    for clustering, rpk in results["rpk"].items():
        c = rpk["checks"]
        print(f"rpkCpp {clustering}: emitted {fmt_w(c['emitted_w'])} W, total flux "
              f"{fmt_w(c['total_w'])} W (its own: {fmt_w(rpk['total_flux'])}), Gouraud "
              f"integral {fmt_w(rpk['gouraud']['integral_w'])} W; leaf areas "
              f"{c['leaf_area_vs_rpk']:.1e} from rpkCpp's, faces {c['face_area_vs_scene']:.1e} "
              f"from the scene's; Ed / sourceRad {c['ed_over_src']}")
    for name, h in results["hmcr"].items():
        print(f"hmcr {name}: emitted {fmt_w(h['emitted_w'])} W, total flux "
              f"{fmt_w(h['total_w'])} W")


def fmt_w(values):
    return "(" + ", ".join(f"{v:.4f}" for v in values) + ")"


def main_error(args, work, rpk, mgf):
    """--error: every object error, printed and (with --json) written."""
    args.reference = make_reference(args, work)
    results = {"machine": os.uname().nodename, "reference": args.reference, "rpk": {},
               "hmcr": {}}
    for clustering in args.clustering.split(","):
        results["rpk"][clustering] = rpk_solutions(args, rpk, mgf, clustering, work)
    rpk0 = results["rpk"][args.clustering.split(",")[0]]
    for config in ("matched", "default"):
        first = hmcr_at(args, config, rpk0["rays"], work, f"hmcr-{config}-rays")
        if first["repairs"] or first["patches"] != len(read_obj(CORNELL_OBJ)[1]):
            sys.exit("hmcr's patches are not the OBJ's faces (repaired): PatchId would be wrong")
        for clustering, rpk_result in results["rpk"].items():
            verify_units(clustering, rpk_result, first["emitted_w"])
        results["hmcr"][f"{config}, equal rays"] = with_seeds(args, config, first, work,
                                                              f"hmcr-{config}-rays")
        results["hmcr"][f"{config}, equal CPU time"] = hmcr_at_equal_time(
            args, config, first, rpk0["cpu_s"], work)
    print_errors(results)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=1)


# ---------------------------------------------------------------- noise per second (--noise)


class Patch:
    """One engine's patch on a fixed mesh: its area, centroid, unit normal and mean B (3)."""

    def __init__(self, area, centroid, normal, b):
        self.area, self.centroid, self.normal, self.b = area, centroid, normal, list(b)


def _patch(polygons, values):
    """A patch of polygons (lists of points) and their B: area-weighted centroid and B."""
    area, centroid, normal, b = 0.0, [0.0] * 3, [0.0] * 3, [0.0] * 3
    for points, value in zip(polygons, values):
        a, n = rpk_leaves.polygon_area(points), rpk_leaves.newell(points)
        c = rpk_leaves.centroid(points)  # exact for triangles and parallelograms
        area += a
        for k in range(3):
            centroid[k] += a * c[k]
            normal[k] += n[k]
            b[k] += a * value[k]
    length = math.sqrt(sum(n * n for n in normal))
    return Patch(area, [c / area for c in centroid], [n / length for n in normal],
                 [v / area for v in b])


def hmcr_patches(vtp):
    """hmcr's patches of a fixed-mesh solve, by PatchId: its cells' area-weighted B."""
    b, patch_ids = vtp_array(vtp, "ElementRadiosity"), vtp_array(vtp, "PatchId")
    points = vtp_array(vtp, "Points", "<Points>")
    connectivity = vtp_array(vtp, "connectivity", "<Polys>")
    offsets = vtp_array(vtp, "offsets", "<Polys>")
    if len(offsets) != len(patch_ids):
        raise ValueError(f"{vtp}: {len(offsets)} polygons for {len(patch_ids)} cells")
    cells = {}
    for i, end in enumerate(offsets):
        first = offsets[i - 1] if i else 0
        corners = [tuple(points[3 * v:3 * v + 3]) for v in connectivity[first:end]]
        cells.setdefault(patch_ids[i], []).append((corners, b[3 * i:3 * i + 3]))
    if sorted(cells) != list(range(len(cells))):
        raise ValueError(f"{vtp}: the PatchIds are not 0..{len(cells) - 1}")
    return [_patch(*zip(*cells[p])) for p in range(len(cells))]


def rpk_patches(leaf_file):
    """rpkCpp's patches from its leaf file (on a fixed mesh, one leaf a patch), B = pi RAD, and
    the power they emit (sum pi SRC A, per channel)."""
    leaves = rpk_leaves.read_leaves(leaf_file)
    polygons, emitted = {}, [0.0] * 3
    for leaf in leaves.leaves:
        corners = [leaves.vertices[v] for v in leaf["corners"]]
        polygons.setdefault(leaf["patch"], []).append((corners, rpk_leaves.leaf_radiosity(leaf)))
        a = rpk_leaves.polygon_area(corners)
        for k in range(3):
            emitted[k] += math.pi * leaf["src"][k] * a
    return [_patch(*zip(*polygons[p])) for p in sorted(polygons)], emitted


def match_patches(ours, theirs, tolerance=1e-4):
    """For each of `theirs`, the index of the patch of `ours` with the same centroid (within
    tolerance x the scenes' extent), facing the same way and of the same area (1e-3); a
    ValueError when one has none or two share one."""
    lo = [min(p.centroid[k] for p in ours + theirs) for k in range(3)]
    hi = [max(p.centroid[k] for p in ours + theirs) for k in range(3)]
    reach = tolerance * max(max(h - l for h, l in zip(hi, lo)), 1e-30)
    out = []
    for j, t in enumerate(theirs):
        found = [i for i, o in enumerate(ours)
                 if max(abs(a - b) for a, b in zip(o.centroid, t.centroid)) <= reach
                 and sum(a * b for a, b in zip(o.normal, t.normal)) > 0.99
                 and abs(o.area - t.area) <= 1e-3 * max(o.area, t.area)]
        if len(found) != 1:
            raise ValueError(f"patch {j} (centroid {t.centroid}, area {t.area:.6g}) matches "
                             f"{len(found)} patches of the other engine, not one")
        out.append(found[0])
    if len(set(out)) != len(out):
        raise ValueError("two patches match the same patch of the other engine")
    return out


def ray_unit_curve(units, count, step):
    """`count` ray units spread evenly around `units`, `step` apart relatively (the
    deterministic sequence's curve over ray counts: its error at one count is one sample)."""
    return [max(1, round(units * (1 + step * (k - (count - 1) / 2)))) for k in range(count)]


def efficiency(rms, cpu):
    return 1.0 / (rms * rms * cpu)


def rpk_noise_command(rpk, mgf, units, sequence, iterations):
    """rpkCpp's stochastic Jacobi on the scene's patches (no hierarchy, no clusters)."""
    return [rpk, mgf, "-raytracing-method", "none", "-radiance-method", "StochJacobi",
            "-iterations", str(iterations), "-srr-ray-units", str(units), "-srr-hierarchical",
            "no", "-srr-clustering", "none", "-srr-sampling-sequence", sequence]


def hmcr_noise_run(args, scene, variant, seed, rays, work, name):
    out = os.path.join(work, f"{name}.vtp")
    command = patch_noise.hmcr_command(args.hmcr, scene["hmcr"], variant, seed, rays, out,
                                       scene["hmcr_options"])
    cpu, _ = cpu_runs(command, work, 1)
    with open(os.path.join(work, f"{name}.json")) as f:
        summary = json.load(f)
    return {"cpu_s": cpu, "patches": hmcr_patches(out), "rays": summary["counts"]["rays"],
            "emitted": summary["power"]["emitted_w"], "faces": summary["counts"]["faces"]}


def rpk_noise_run(args, rpk, scene, units, sequence, work, name, seed=None, double=False):
    leaf_file = os.path.join(work, f"{name}.leaves")
    env = {**os.environ, rpk_leaves.LEAF_FILE_VARIABLE: leaf_file}
    if seed is not None:
        env[rpk_leaves.SEED_VARIABLE] = str(seed)
    if double:
        env[rpk_leaves.DOUBLE_VARIABLE] = "1"
    command = rpk_noise_command(rpk, scene["mgf"], units, sequence, args.iterations)
    cpu, stderr = cpu_runs(command, work, 1, env)
    if not os.path.exists(leaf_file):
        sys.exit(f"{rpk} wrote no leaves: it is not a build of this script's (use --rpk-source)")
    patches, emitted = rpk_patches(leaf_file)
    return {"cpu_s": cpu, "patches": patches, "emitted": emitted, "units": units,
            "rays": int(re.findall(r"Radiance rays: (\d+)", stderr)[-1])}


def rpk_units_for(args, rpk, scene, rays, work):
    """The ray units that shoot about `rays` rays (rpkCpp's rays grow in proportion)."""
    units = 1000
    for _ in range(2):
        got = rpk_noise_run(args, rpk, scene, units, "Niederreiter", work, "calibrate")["rays"]
        units = max(1, round(units * rays / got))
    return units


def noise_scene(args, rpk, scene, work):
    """Every row of one scene's table, with its references' checks."""
    name, rays = scene["name"], args.rays
    print(f"{name}: references ...", flush=True)
    hmcr_ref = hmcr_noise_run(args, scene, "sobol", 1000, rays * args.converged_factor, work,
                              f"{name}-hmcr-converged")
    units = rpk_units_for(args, rpk, scene, rays, work)
    rpk_ref = rpk_noise_run(args, rpk, scene, units * args.converged_factor, "Niederreiter",
                            work, f"{name}-rpk-converged", double=True)
    try:
        order = match_patches(hmcr_ref["patches"], rpk_ref["patches"])
    except ValueError as e:
        sys.exit(f"{name}: hmcr's and rpkCpp's patches differ: {e}")
    if len(order) != len(hmcr_ref["patches"]):
        sys.exit(f"{name}: hmcr has {len(hmcr_ref['patches'])} patches, rpkCpp "
                 f"{len(order)}")
    scale = scene["hmcr_per_rpk_unit"]  # hmcr's lm/m^2 per rpkCpp's W/m^2 for MGF
    hmcr_emitted = [e / scale for e in hmcr_ref["emitted"]]
    emitted_diff = max(abs(h - r) / r for h, r in zip(hmcr_emitted, rpk_ref["emitted"]))
    if emitted_diff > 2e-3:
        sys.exit(f"{name}: hmcr emits {fmt_w(hmcr_emitted)}, rpkCpp {fmt_w(rpk_ref['emitted'])}"
                 ": not the same scene")

    def in_rpk_order(patches):  # hmcr's patches, in rpkCpp's order (matched by geometry)
        return [patches[i].b for i in order]

    h_ref = in_rpk_order(hmcr_ref["patches"])
    r_ref = [p.b for p in rpk_ref["patches"]]
    lit = patch_noise.lit_channels(h_ref, r_ref)
    cross = patch_noise.relative_rms([[[v / scale for v in b] for b in h_ref]], r_ref, lit)

    rows = {f"hmcr {v}": [] for v in args.variants.split(",")}
    rows.update({"rpkCpp PseudoRandom": [], "rpkCpp Niederreiter": []})
    curve = ray_unit_curve(units, args.seeds, args.curve_step)
    for k in range(args.seeds):  # interleaved, so that the machine's load falls on every row
        seed = k + 1
        for v in args.variants.split(","):
            run = hmcr_noise_run(args, scene, v, seed, rays, work, f"{name}-hmcr-{v}-{seed}")
            rows[f"hmcr {v}"].append({**run, "b": in_rpk_order(run["patches"])})
        run = rpk_noise_run(args, rpk, scene, units, "PseudoRandom", work,
                            f"{name}-rpk-random-{seed}", seed=seed)
        rows["rpkCpp PseudoRandom"].append({**run, "b": [p.b for p in run["patches"]]})
        run = rpk_noise_run(args, rpk, scene, curve[k], "Niederreiter", work,
                            f"{name}-rpk-nied-{k}")
        rows["rpkCpp Niederreiter"].append({**run, "b": [p.b for p in run["patches"]]})
        print(f"  {name}: run {seed} of {args.seeds}", flush=True)
    # rpkCpp's float sums at the measured rays, against double sums of the same rays
    single = rpk_noise_run(args, rpk, scene, units, "Niederreiter", work, f"{name}-rpk-float")
    double = rpk_noise_run(args, rpk, scene, units, "Niederreiter", work, f"{name}-rpk-double",
                           double=True)
    float_vs_double = patch_noise.relative_rms([[p.b for p in single["patches"]]],
                                   [p.b for p in double["patches"]], lit)
    table = {}
    for row, runs in rows.items():
        reference = r_ref if row.startswith("rpkCpp") else h_ref
        table[row] = {"rms": patch_noise.relative_rms([r["b"] for r in runs], reference, lit),
                      "cpu_s": statistics.median(r["cpu_s"] for r in runs),
                      "rays": statistics.mean(r["rays"] for r in runs),
                      "cpu_s_runs": [r["cpu_s"] for r in runs],
                      "rays_runs": [r["rays"] for r in runs]}
        table[row]["efficiency"] = efficiency(table[row]["rms"], table[row]["cpu_s"])
    return {"name": name, "patches": len(order), "lit_channels": len(lit),
            "rpk_units": units, "rpk_curve_units": curve,
            "hmcr_converged_rays": hmcr_ref["rays"], "rpk_converged_rays": rpk_ref["rays"],
            "emitted_hmcr": hmcr_emitted, "emitted_rpk": rpk_ref["emitted"],
            "emitted_difference": emitted_diff, "references_difference": cross,
            "rpk_float_vs_double": float_vs_double, "rows": table}


def print_noise(result):
    base = result["rows"]["rpkCpp Niederreiter"]["efficiency"]
    print(f"\n{result['name']}: {result['patches']} patches, {result['lit_channels']} lit patch "
          f"channels; references: hmcr sobol at {result['hmcr_converged_rays']:,} rays, rpkCpp "
          f"Niederreiter with double sums at {result['rpk_converged_rays']:,} rays")
    print("| engine, variant | rays | per-patch RMS deviation | CPU s | efficiency, "
          "1 / (deviation² × s), relative to rpkCpp Niederreiter |")
    print("|:--|--:|--:|--:|--:|")
    for row, r in result["rows"].items():
        print(f"| {row} | {r['rays'] / 1e6:.3f} M | {100 * r['rms']:.3f}% | {r['cpu_s']:.2f} | "
              f"{r['efficiency'] / base:.2f}× |")
    sobol = result["rows"].get("hmcr sobol")
    if sobol:
        print(f"hmcr sobol / rpkCpp Niederreiter: {sobol['efficiency'] / base:.2f} (target 2)")
    print(f"emitted: hmcr {fmt_w(result['emitted_hmcr'])}, rpkCpp {fmt_w(result['emitted_rpk'])}"
          f" (largest relative difference {result['emitted_difference']:.1e}); the two "
          f"references differ by {100 * result['references_difference']:.2f}% per patch (RMS); "
          f"rpkCpp's float sums against double at {result['rpk_units']} ray units: "
          f"{100 * result['rpk_float_vs_double']:.3f}%")


def rpk_etc_scene(args, work, name):
    """rpkCpp's etc/NAME: in the copy built here, else exported from --rpk-source."""
    path = os.path.join(work, "rpkCpp", "etc", name)
    if os.path.exists(path):
        return path
    if args.rpk_source and os.path.isdir(os.path.join(args.rpk_source, "etc")):
        return os.path.join(args.rpk_source, "etc", name)
    if not args.rpk_source:
        sys.exit("--noise with --rpk needs --mgf FILE or --rpk-source DIR for etc/" + name)
    archive = subprocess.run(["git", "--git-dir", args.rpk_source, "archive",
                              args.rpk_commit, "etc/" + name],
                             check=True, capture_output=True).stdout
    subprocess.run(["tar", "-x", "-C", work], input=archive, check=True)
    return os.path.join(work, "etc", name)


def main_noise(args, work, rpk):
    """--noise: the fixed-mesh noise table of each scene, printed and (with --json) written."""
    cornell_mgf = os.path.join(work, "cornell.mgf")
    scenes = [{"name": "cornell", "hmcr": "cornell", "hmcr_options": [], "mgf": cornell_mgf,
               "hmcr_per_rpk_unit": 1.0}]
    for path in (args.mgf.split(",") if args.mgf else []):
        # hmcr states an MGF scene in lm/m^2 (its ed as written), rpkCpp in W/m^2 (ed / 183.07);
        # RenderPark reads every surface one-sided, hmcr then with --sides 1.
        scenes.append({"name": os.path.splitext(os.path.basename(path))[0],
                       "hmcr": os.path.abspath(path), "hmcr_options": ["--sides", "1"],
                       "mgf": os.path.abspath(path), "hmcr_per_rpk_unit": RPK_WHITE_EFFICACY})
    results = {"machine": os.uname().nodename, "rays": args.rays, "seeds": args.seeds,
               "scenes": []}
    for scene in scenes:
        result = noise_scene(args, rpk, scene, work)
        print_noise(result)
        results["scenes"].append(result)
        if args.json:
            with open(args.json, "w") as f:
                json.dump(results, f, indent=1)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--hmcr", default=os.path.join(HERE, "..", "build", "hmcr"))
    ap.add_argument("--rpk-source", default=os.environ.get("RPK_SOURCE"),
                    help="rpkCpp's git directory or source folder on this machine (default: "
                    "$RPK_SOURCE, else download the pinned commit's tarball from GitHub)")
    ap.add_argument("--rpk-commit", default=RPK_COMMIT)
    ap.add_argument("--rpk", help="an rpkCpp binary this script built before (skips the build)")
    ap.add_argument("--work", help="working folder (default: a temporary one, removed)")
    ap.add_argument("--pairs", type=int, default=7)
    ap.add_argument("--clustering", default="oriented,isotropic",
                    help="rpkCpp's -srr-clustering modes to measure, comma-separated")
    ap.add_argument("--iterations", type=int, default=6)
    ap.add_argument("--ray-units", type=int, default=3464,
                    help="rpkCpp's -srr-ray-units: 3464 shoots hmcr's 2.684 M rays")
    ap.add_argument("--rpk-epsilon", type=float, default=1.82e-6,
                    help="rpkCpp's -srr-epsilon: 1.82e-6 gives hmcr's element count")
    ap.add_argument("--hmcr-epsilon", type=float, default=1.18e-6,
                    help="hmcr's power epsilon (the bench's: about 19,000 leaves)")
    ap.add_argument("--rays", type=int, default=2684000)
    ap.add_argument("--jobs", type=int, default=2, help="build jobs")
    ap.add_argument("--json", help="write every time and count here")
    ap.add_argument("--error", action="store_true",
                    help="measure object errors against a point reference instead of times")
    ap.add_argument("--reference", help="--error: an hmcr reference of cornell (default: make "
                    "one in the working folder)")
    ap.add_argument("--sequence", help="hmcr's ray sequence in the timed and --error solves "
                    "(default: hmcr's)")
    ap.add_argument("--reference-points", type=int, default=200000)
    ap.add_argument("--reference-paths", type=int, default=64)
    ap.add_argument("--reference-spp", type=float, default=16)
    ap.add_argument("--seeds", type=int, help="--error: hmcr's seeds 1..k (default 3); "
                    "--noise: seeds 1..k of each random row and k points of rpkCpp's "
                    "Niederreiter curve (default 8)")
    ap.add_argument("--noise", action="store_true",
                    help="measure per-patch noise per CPU second on fixed meshes instead")
    ap.add_argument("--mgf", help="--noise: RenderPark MGF scenes beside the Cornell box, "
                    "comma-separated (default: etc/cube.mgf of rpkCpp's source)")
    ap.add_argument("--variants", default="random,sobol,sobol+both,sobol+cv",
                    help="--noise: hmcr's rows: a sequence, then +both (--bidirectional yes) "
                    "and +cv (--control-variate constant) if wanted")
    ap.add_argument("--converged-factor", type=int, default=100,
                    help="--noise: the references' rays over the measured rays")
    ap.add_argument("--curve-step", type=float, default=0.03,
                    help="--noise: relative step of rpkCpp's Niederreiter ray units")
    ap.add_argument("--repeats", type=int, default=3,
                    help="--error: runs whose median CPU time is each solve's time")
    args = ap.parse_args()
    args.hmcr = os.path.abspath(args.hmcr)

    work = os.path.abspath(args.work) if args.work else tempfile.mkdtemp(prefix="rpk-compare-")
    os.makedirs(work, exist_ok=True)
    try:
        mgf = os.path.join(work, "cornell.mgf")
        write_mgf(CORNELL_OBJ, mgf)
        rpk = os.path.abspath(args.rpk) if args.rpk else None
        if rpk is None:
            how = fetch_rpk_source(args.rpk_source, args.rpk_commit, os.path.join(work, "rpkCpp"))
            rpk_leaves.add_leaf_writer(os.path.join(work, "rpkCpp"))
            rpk_leaves.add_noise_hooks(os.path.join(work, "rpkCpp"))
            print(f"building rpkCpp from {how}, with a leaf writer and the noise mode's "
                  "hooks ...", flush=True)
            rpk = build_rpk(os.path.join(work, "rpkCpp"), args.jobs)
        if args.noise:
            args.seeds = args.seeds or 8
            if not args.mgf:
                args.mgf = rpk_etc_scene(args, work, "cube.mgf")
            main_noise(args, work, rpk)
            return
        args.seeds = args.seeds or 3
        if args.error:
            main_error(args, work, rpk, mgf)
            return
        hmcr_out = os.path.join(work, "hmcr")
        os.makedirs(hmcr_out, exist_ok=True)
        results = {"machine": os.uname().nodename, "hmcr_command": hmcr_command(args, hmcr_out)}

        timed(hmcr_command(args, hmcr_out), work)
        results["hmcr_counts"] = hmcr_counts(hmcr_out)
        print("hmcr:", " ".join(hmcr_command(args, "OUT")), "\n ", results["hmcr_counts"])
        for clustering in args.clustering.split(","):
            command = rpk_command(rpk, mgf, args, clustering)
            counts = rpk_counts(timed(command, work)[3], len(read_obj(CORNELL_OBJ)[1]))
            print("rpkCpp:", " ".join(["rpk", "cornell.mgf"] + command[2:]), "\n ", counts)
            results[clustering] = {"rpk_command": command[2:], "rpk_counts": counts,
                                   **compare(f"hmcr / rpkCpp ({clustering})",
                                             {"hmcr": hmcr_command(args, hmcr_out),
                                              "rpkCpp": command}, work, args.pairs)}
        if args.json:
            with open(args.json, "w") as f:
                json.dump(results, f, indent=1)
    finally:
        if not args.work:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
