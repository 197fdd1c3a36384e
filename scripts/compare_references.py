#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""A radiosity reference against a traced reference, per view, in luminance.

It prints the table of docs/results.md#radiosity-against-the-path-tracer ("The references").  The
two systems solve the same light transport independently, so their references should agree
within the trace's noise and the radiosity mesh's error; this measures by how much they differ and
how much of it the trace's noise explains.  Needs Debian's python3 with python3-numpy.

    scripts/compare_references.py TRACED RADIOSITY NOISE_A NOISE_B

TRACED is a folder of `hmcr trace-reference`, RADIOSITY one of `hmcr reference`, NOISE_A and
NOISE_B two more traced folders of the same views with independent seeds (`hmcr trace-reference
--seed`), usually at far fewer samples per pixel.  Each holds views/VIEW.pfm (linear radiance)
and reference.json (a view's exposure, a trace's spp).  The radiosity images may be an integer
multiple of the traced size (`hmcr reference` renders the scene's view size): they are
box-filtered down to it.  Per view, in linear Rec. 709 luminance, with "difference" meaning
radiosity - traced, every figure but RMSEp relative to the traced image's mean luminance over the
compared pixels (a relative difference per pixel would be ruled by the dark pixels at the box's
silhouette, partly outside it):

- **mean difference**: the radiosity image's luminance summed over the compared pixels, over the
  traced one's, minus 1;
- **RMS per pixel**: the RMS over the compared pixels of radiosity - traced;
- **trace noise per pixel**: the RMS of the traced reference's own standard deviation, from
  NOISE_A - NOISE_B: a pixel's variance at the noise traces' spp is (a - b)^2 / 2, and at the
  reference's spp that times spp_noise / spp_reference (uniform sampling, independent samples);
- **trace s.e. of mean**: the standard error of the traced sum, sqrt(sum of those variances),
  over the traced sum (pixels are independent): the noise per pixel over sqrt(pixels);
- **RMSEp**: as a study computes it (studies/metrics.cpp): both images at the traced reference's
  exposure, clamped, sRGB-encoded and rounded to 0-255, then the square root of the mean over all
  pixels of the Rec. 709-weighted sum of the channels' squared differences.

The compared pixels are all but the light and the 3 pixels around it: a pixel that straddles the
light's edge mixes the emitter's radiance with the ceiling's in proportions each image estimates
with its own subpixel samples, and its relative difference says nothing about the transport.  The
light's pixels are found in the traced reference by the emitters' radiance, read from the
scene's MTL files (`Ke`, docs/design.md §1): those whose luminance is at least half the dimmest
emitter's.  No reflected radiance comes near that, and pixels partly covered by the light fall
within the 3-pixel margin.  A view that does not see the light compares every pixel.
"""

import argparse
import json
import math
import os
import sys

import system_python

system_python.need("numpy")  # before cycles_compare, which imports it

from cycles_compare import LUMINANCE, box_reduce, luminance, read_pfm  # noqa: E402

SCENES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes")
sys.path.insert(0, SCENES)
from check_scene import parse_mtl, parse_obj  # noqa: E402 (needs the path above)

LIGHT_FRACTION = 0.5  # a pixel at least this fraction of the dimmest emitter's luminance is light
LIGHT_MARGIN = 3  # pixels around the light left out (Chebyshev distance)


def read_json(folder):
    with open(os.path.join(folder, "reference.json")) as f:
        return json.load(f)["reference"]


def view_image(folder, view):
    return read_pfm(os.path.join(folder, "views", f"{view}.pfm"))


def emitter_luminance(scene_json):
    """The luminance of the dimmest emitted radiance (MTL `Ke`) of the scene's faces."""
    with open(scene_json) as f:
        obj = os.path.join(os.path.dirname(scene_json), json.load(f)["mesh"])
    errors = []
    _, faces, mtllibs = parse_obj(obj, errors)
    materials = {}
    for lib in mtllibs:
        materials.update(parse_mtl(os.path.join(os.path.dirname(obj), lib), errors))
    used = {f["mtl"] for f in faces}
    emitted = [sum(w * k for w, k in zip(LUMINANCE, m["Ke"]))
               for name, m in materials.items() if name in used and max(m["Ke"]) > 0]
    if errors or not emitted:
        sys.exit(f"{obj}: " + ("; ".join(errors) if errors else "no emitting face"))
    return min(emitted)


def compared_pixels(traced_luminance, light_luminance):
    """True where a pixel is compared: farther than LIGHT_MARGIN from every light pixel."""
    import numpy as np
    light = traced_luminance >= LIGHT_FRACTION * light_luminance
    m = LIGHT_MARGIN
    padded = np.pad(light, m)
    h, w = light.shape
    near = np.zeros_like(light)
    for dy in range(2 * m + 1):
        for dx in range(2 * m + 1):
            near |= padded[dy:dy + h, dx:dx + w]
    return ~near, int(light.sum())


def srgb8(rgb, exposure):
    """As image/tone_map.cpp's to_srgb8: exposure x radiance, clamped, sRGB, rounded to 0-255."""
    import numpy as np
    v = np.clip(rgb * exposure, 0.0, 1.0)
    s = np.where(v <= 0.0031308, 12.92 * v, 1.055 * np.power(v, 1 / 2.4) - 0.055)
    return np.floor(255 * s + 0.5)  # std::lround: halves away from zero


def rmse_p(a, b, exposure):
    """studies/metrics.cpp's rmse_p of the two images quantised at the exposure."""
    import numpy as np
    d = srgb8(a, exposure) - srgb8(b, exposure)
    return math.sqrt(float(np.mean((d ** 2) @ np.array(LUMINANCE))))


def compare_view(traced, radiosity, noise, spp_ratio, exposure, light_luminance):
    """One view's row: traced and radiosity images (the latter box-filtered already), the two
    noise traces, their spp over the reference's, the reference's exposure and the emitters'
    luminance."""
    import numpy as np
    t, r = luminance(traced), luminance(radiosity)
    keep, light = compared_pixels(t, light_luminance)
    var = (luminance(noise[0]) - luminance(noise[1])) ** 2 / 2 * spp_ratio
    t, r, var = t[keep], r[keep], var[keep]
    mean = t.mean()
    return {"pixels": int(keep.sum()), "light_pixels": light,
            "mean_difference": r.sum() / t.sum() - 1,
            "rms_per_pixel": math.sqrt(float(np.mean((r - t) ** 2))) / mean,
            "trace_noise_per_pixel": math.sqrt(float(np.mean(var))) / mean,
            "trace_se_of_mean": math.sqrt(float(var.sum())) / t.sum(),
            "rmse_p": rmse_p(radiosity, traced, exposure)}


def percent(x, digits):
    """A percentage as docs/results.md writes it: a true minus sign, no plus."""
    return f"{100 * x:.{digits}f}%".replace("-", "\u2212")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("traced", help="folder of hmcr trace-reference")
    ap.add_argument("radiosity", help="folder of hmcr reference")
    ap.add_argument("noise", nargs=2, help="two folders of hmcr trace-reference, other seeds")
    ap.add_argument("--scene", help="the scene's .json (default: scenes/NAME/NAME.json, NAME "
                    "the traced reference's scene)")
    ap.add_argument("--views", help="comma-separated (default: every view of TRACED)")
    ap.add_argument("--json", help="also write the rows and pixel counts to this file")
    args = ap.parse_args()
    traced_json = read_json(args.traced)
    noise_spp = [read_json(f)["spp"] for f in args.noise]
    if noise_spp[0] != noise_spp[1]:
        sys.exit(f"the noise traces have different spp: {noise_spp[0]} and {noise_spp[1]}")
    spp_ratio = noise_spp[0] / traced_json["spp"]
    views = args.views.split(",") if args.views else sorted(traced_json["views"])
    name = traced_json["scene"]
    light = emitter_luminance(args.scene or os.path.join(SCENES, name, f"{name}.json"))

    rows = {}
    for view in views:
        traced = view_image(args.traced, view)
        radiosity = view_image(args.radiosity, view)
        factor = radiosity.shape[1] // traced.shape[1]
        if radiosity.shape[:2] != (traced.shape[0] * factor, traced.shape[1] * factor):
            sys.exit(f"view {view}: radiosity {radiosity.shape[1]} x {radiosity.shape[0]} is not "
                     f"a multiple of traced {traced.shape[1]} x {traced.shape[0]}")
        noise = [view_image(f, view) for f in args.noise]
        if any(n.shape != traced.shape for n in noise):
            sys.exit(f"view {view}: the noise traces' size differs from the traced reference's")
        rows[view] = compare_view(traced, box_reduce(radiosity, factor), noise, spp_ratio,
                                  traced_json["views"][view]["exposure"], light)

    print("| view | mean difference | RMS per pixel | trace noise per pixel "
          "| trace s.e. of mean | RMSEp |")
    print("|---|--:|--:|--:|--:|--:|")
    for view, r in rows.items():
        print(f"| {view} | {percent(r['mean_difference'], 2)} | {percent(r['rms_per_pixel'], 2)} "
              f"| {percent(r['trace_noise_per_pixel'], 2)} | {percent(r['trace_se_of_mean'], 3)} "
              f"| {r['rmse_p']:.2f} |")
    print()
    for view, r in rows.items():
        print(f"{view}: {r['pixels']} pixels compared, {r['light_pixels']} light pixels")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
