#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""scripts/plot_study.py draws figures a paper can take as they are: for the figures of a
sampling study of every sampler at two spp values (error_by_sampler, error_vs_spp) and of a
meshing study of every oracle (error_vs_elements, error_by_patch), everything drawn lies inside
the figure (legends included), and no two tick labels of a panel touch (their boxes, turned as
the labels are, do not intersect).
Usage: check_plot_study.py REPO_ROOT. Prints one line per problem; exit code 1 if any."""
import math
import pathlib
import sys

root = pathlib.Path(sys.argv[1]).resolve()
sys.path.insert(0, str(root / "scripts"))
import system_python  # noqa: E402

system_python.need("matplotlib")
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import ticker  # noqa: E402

import plot_study  # noqa: E402

SAMPLERS = ["uniform", "cc", "var", "entropy", "binary-entropy", "kl", "cs", "he", "srkl",
            "srcs", "srhe", "half-difference"]
ORACLES = ["power", "ks", "mi", "kl", "cs", "hl", "vt"]
problems = []


def point(x, y, se):
    return {"x": x, "x_se": se * x, "y": y, "y_se": se * y, "n": 3}


def bars(title, categories, groups):
    return {"type": "bars", "title": title, "y_label": "RMSEp (0–255)", "categories": categories,
            "groups": [{"name": g, "values": [{"y": 5 + (i * 7 + k) % 9, "y_se": 0.3, "n": 3}
                                              for i in range(len(categories))]}
                       for k, g in enumerate(groups)]}


def lines(title, names, xs, x_label):
    return {"type": "lines", "title": title, "x_label": x_label, "y_label": "RMSEp (0–255)",
            "x_ticks": xs,
            "series": [{"name": n, "points": [point(x * (1 + 0.01 * i), 14 - i * 0.6 - 2 * j, 0.02)
                                              for j, x in enumerate(xs)]}
                       for i, n in enumerate(names)]}


FIGURES = [
    {"name": "error_by_sampler", "panels": [bars(f"{s} spp", SAMPLERS, ["RMSEp", "bias", "noise"])
                                            for s in (16, 32)]},
    {"name": "error_vs_spp", "panels": [lines("RMSEp against samples per pixel", SAMPLERS,
                                              [16, 32], "samples per pixel")]},
    {"name": "error_vs_elements", "panels": [lines(t, ORACLES, [5000, 19000], "leaves")
                                             for t in ("solution", "mesh (frozen re-solve)")]},
    {"name": "error_by_patch", "panels": [
        dict(bars(f"{b} leaves", ["0", "10", "19", "13 back", "6", "5", "11", "14"], ORACLES),
             x_label="patch (PatchId)") for b in (5000, 19000)]},
]


def corners(label, renderer):
    """The four corners of a tick label's box, turned as it is drawn (display pixels)."""
    box = label.get_window_extent(renderer)
    angle = math.radians(label.get_rotation())
    if angle == 0:
        return [(box.x0, box.y0), (box.x1, box.y0), (box.x1, box.y1), (box.x0, box.y1)]
    # Unturned size, and the box's corners about the box's centre, turned.
    flat = label.get_fontproperties()
    w, h, _ = renderer.get_text_width_height_descent(label.get_text(), flat, ismath=False)
    cx, cy = (box.x0 + box.x1) / 2, (box.y0 + box.y1) / 2
    c, s = math.cos(angle), math.sin(angle)
    return [(cx + x * c - y * s, cy + x * s + y * c)
            for x, y in ((-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2))]


def intersect(a, b):
    """Whether two convex polygons overlap (separating axis theorem), by more than a pixel."""
    for poly in (a, b):
        for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1]):
            nx, ny = y0 - y1, x1 - x0
            norm = math.hypot(nx, ny)
            pa = [(x * nx + y * ny) / norm for x, y in a]
            pb = [(x * nx + y * ny) / norm for x, y in b]
            if max(pa) <= min(pb) + 1 or max(pb) <= min(pa) + 1:
                return False
    return True


plt.rcParams.update({"font.size": 8, "axes.titlesize": 9, "axes.labelsize": 8,
                     "legend.fontsize": 8})
for spec in FIGURES:
    fig = plot_study.figure_of(spec, plt, ticker)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    whole, drawn = fig.bbox, fig.get_tightbbox(renderer).transformed(fig.dpi_scale_trans)
    if (drawn.x0 < whole.x0 - 1 or drawn.y0 < whole.y0 - 1 or drawn.x1 > whole.x1 + 1
            or drawn.y1 > whole.y1 + 1):
        problems.append(f"{spec['name']}: drawn beyond the figure: {drawn.bounds} outside "
                        f"{whole.bounds}")
    legends = list(fig.legends) + [ax.get_legend() for ax in fig.axes if ax.get_legend()]
    for legend in legends:
        box = legend.get_window_extent(renderer)
        if box.x0 < -1 or box.y0 < -1 or box.x1 > whole.x1 + 1 or box.y1 > whole.y1 + 1:
            problems.append(f"{spec['name']}: a legend at {box.bounds} is not inside the figure "
                            f"{whole.bounds}")
    if not legends:
        problems.append(f"{spec['name']}: no legend")
    for k, ax in enumerate(fig.axes):
        labels = [t for t in ax.get_xticklabels() if t.get_text() and t.get_visible()]
        boxes = [corners(t, renderer) for t in labels]
        for (ta, a), (tb, b) in zip(zip(labels, boxes), zip(labels[1:], boxes[1:])):
            if intersect(a, b):
                problems.append(f"{spec['name']}, panel {k + 1}: tick labels "
                                f"{ta.get_text()!r} and {tb.get_text()!r} touch")
    plt.close(fig)

for p in problems:
    print(p)
sys.exit(1 if problems else 0)
