#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Builds the docs' study figures from a finished study and its reference.

    /usr/bin/python3 scripts/make_figures.py studies/cornell ref/cornell cornell 19000 camera corner

For each view: one strip, left to right the reference, power, ks and kl (seed 1 of the given
budget), each halved to 256 x 256; and a copy of the study's error plot (PNG). Written to
docs/images/. Needs matplotlib (Debian: python3-matplotlib, which `make deps` installs for the
studies' plots), for its PNG input and output and numpy.
"""
import os
import shutil
import sys

import system_python

system_python.need("matplotlib", "numpy")

import matplotlib.image  # noqa: E402
import numpy as np  # noqa: E402


def read_png(path):
    """8-bit RGB rows, top first (matplotlib reads a PNG as floats in [0, 1])."""
    a = matplotlib.image.imread(path)[:, :, :3]
    return (a * 255).round().astype(np.uint8)


def halve(a):
    a = a[: a.shape[0] // 2 * 2, : a.shape[1] // 2 * 2].astype(np.float64)
    return ((a[0::2, 0::2] + a[1::2, 0::2] + a[0::2, 1::2] + a[1::2, 1::2]) / 4).round().astype(np.uint8)


def main(study, ref, scene, budget, views):
    os.makedirs("docs/images", exist_ok=True)
    for view in views:
        panels = [read_png(f"{ref}/views/{view}.png")]
        for oracle in ("power", "ks", "kl"):
            panels.append(read_png(f"{study}/images/{scene}-{oracle}-B{budget}-s1-{view}.png"))
        strip = [halve(p) for p in panels]
        gap = np.zeros((strip[0].shape[0], 4, 3), np.uint8)
        out = np.concatenate(sum([[s, gap] for s in strip], [])[:-1], axis=1)
        matplotlib.image.imsave(f"docs/images/{scene}-{view}.png", out)
    shutil.copy(f"{study}/plots/error_vs_elements.png", f"docs/images/{scene}-error.png")


if __name__ == "__main__":
    if len(sys.argv) < 6:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5:])
