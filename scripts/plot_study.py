#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Draws a study's plots from the numbers hmcr wrote for them (docs/studies.md, "Plots").

    /usr/bin/python3 plot_study.py STUDY/plots/plot_data.json

`hmcr study` runs it at the end and `hmcr plot STUDY` runs it again; run by hand, it is a
starting point for restyling a figure. For each figure of the data it writes NAME.pdf (vector,
fonts embedded as TrueType) and NAME.png beside the data file, each atomically. A `lines`
panel is log-log with error bars both ways (± one standard error over the seeds), a marker,
line style and colour per series, hollow markers of decreasing size and the series set a
little apart along x (DODGE) so that coinciding series stay visible, and axes fitted to the data; a `bars` panel has one bar per category and group
with its error bar. Needs matplotlib (Debian: python3-matplotlib).

Exit status: 0 drawn; 2 the data file is not plot data (one line on stderr); 3 no matplotlib.
"""
import json
import math
import os
import re
import sys
import tempfile

MISSING_MATPLOTLIB = 3
BAD_INPUT = 2

# Okabe and Ito's colour-blind-safe palette (yellow left out: too faint on white).
COLOURS = ["#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000"]
MARKERS = ["o", "s", "^", "D", "v", "P", "X", "<", ">", "h"]
LINE_STYLES = ["-", "--", "-.", ":", (0, (5, 1.5)), (0, (3, 1, 1, 1, 1, 1)), (0, (1, 2))]
PANEL_SIZE = (3.6, 2.9)  # inches: two panels fill a two-column paper's text width
LEGEND_COLUMNS = 7  # at most, in a legend shared by the panels
DODGE = 0.012  # series k apart are drawn k x DODGE of the x axis's span apart (log scale)
# The values an axis draws: matplotlib's tick locators overflow, or take the log of 0, near the
# ends of double's range (an object error of 1e308, a value of 5e-324 are a study's to write).
DRAWABLE = (1e-300, 1e300)


def style(i):
    """Colour, marker, line style and marker size of series i: no two of the first 7 share any."""
    return {
        "color": COLOURS[i % len(COLOURS)],
        "marker": MARKERS[i % len(MARKERS)],
        "linestyle": LINE_STYLES[i % len(LINE_STYLES)],
        "markersize": max(5.0, 8.0 - 0.5 * i),
    }


def finite(v):
    return isinstance(v, (int, float)) and math.isfinite(v)


def drawable(v):
    """A value a log axis can show: finite and within DRAWABLE."""
    return finite(v) and DRAWABLE[0] <= v <= DRAWABLE[1]


def se_or_zero(v):
    return v if drawable(v) else 0.0


def log_limits(lows, highs):
    """Limits of a log axis holding [min(lows), max(highs)] with a margin of 6% of its span,
    within DRAWABLE."""
    lo = math.log10(max(min(lows), DRAWABLE[0]))
    hi = math.log10(min(max(highs), DRAWABLE[1]))
    pad = max(0.06 * (hi - lo), 0.02)
    return (max(10 ** (lo - pad), DRAWABLE[0]), min(10 ** (hi + pad), DRAWABLE[1]))


def plain_number(v, _pos=None):
    """19000 -> '19,000', 0.025 -> '0.025', 2e6 -> '2×10⁶' (mathtext): labels read at a glance."""
    if not (finite(v) and v > 0):
        return ""
    if v >= 1e5:
        e = math.floor(math.log10(v) + 1e-9)
        m = v / 10 ** e
        return f"$10^{{{e}}}$" if abs(m - 1) < 1e-6 else f"${m:g}\\times10^{{{e}}}$"
    if v >= 1000:
        return f"{v:,.0f}"
    return f"{v:.3g}"


def label_log_axis(axis, lo, hi, ticker):
    """Under two decades a log axis has few decade ticks: the ticks at 1, 2 and 5 of each decade
    are labelled too (and 3 under a decade), in plain numbers; under half a decade, where a
    decade's ticks may leave most of the axis bare (7 to 15: 7, 8, 9, 10), about five evenly
    spaced round values instead."""
    span = math.log10(hi / lo)
    if span >= 2:
        return
    if span < 0.5:
        axis.set_major_locator(ticker.MaxNLocator(nbins=5, steps=[1, 2, 2.5, 5, 10]))
        axis.set_minor_locator(ticker.NullLocator())
        axis.set_major_formatter(ticker.FuncFormatter(plain_number))
        return
    keep = None if span < 0.5 else (1, 2, 3, 5) if span < 1 else (1, 2, 5)

    def label(v, pos=None):
        if not (finite(v) and v > 0):
            return ""
        m = v / 10 ** math.floor(math.log10(v) + 1e-9)
        if keep is not None and not any(abs(m - k) < 1e-6 for k in keep):
            return ""
        return plain_number(v)

    axis.set_major_formatter(ticker.FuncFormatter(label))
    axis.set_minor_formatter(ticker.FuncFormatter(label))


def dodge_factors(panel):
    """Per series, a factor on x that sets series apart by DODGE of the x axis's decades: the
    error bars of series at the same x would otherwise hide one another."""
    xs = [p["x"] for s in panel["series"] for p in s["points"] if drawable(p["x"])]
    if not xs:
        return [1.0] * len(panel["series"])
    span = max(math.log10(max(xs) / min(xs)), 0.3)
    k = len(panel["series"])
    return [10 ** (DODGE * span * (i - (k - 1) / 2)) for i in range(k)]


def draw_lines(ax, panel, ticker):
    xs_lo, xs_hi, ys_lo, ys_hi = [], [], [], []
    drawn = 0
    for i, (series, dodge) in enumerate(zip(panel["series"], dodge_factors(panel))):
        pts = [p for p in series["points"] if drawable(p["x"]) and drawable(p["y"])]
        if not pts:
            continue
        x = [p["x"] * dodge for p in pts]
        y = [p["y"] for p in pts]
        xerr = [se_or_zero(p["x_se"]) for p in pts]
        yerr = [se_or_zero(p["y_se"]) for p in pts]
        s = style(i)
        ax.errorbar(x, y, xerr=xerr if any(xerr) else None, yerr=yerr if any(yerr) else None,
                    label=series["name"], color=s["color"],
                    marker=s["marker"], linestyle=s["linestyle"], markersize=s["markersize"],
                    markerfacecolor="none", markeredgewidth=1.1, linewidth=1.1,
                    elinewidth=0.8, capsize=2.5, capthick=0.8, zorder=3 + i)
        xs_lo += [max(a - e, a * 0.5) for a, e in zip(x, xerr)]
        xs_hi += [a + e for a, e in zip(x, xerr)]
        ys_lo += [max(a - e, a * 0.5) for a, e in zip(y, yerr)]
        ys_hi += [a + e for a, e in zip(y, yerr)]
        drawn += 1
    ax.set_xscale("log")
    ax.set_yscale("log")
    if drawn == 0:
        beyond = any(finite(p["x"]) and finite(p["y"]) and p["x"] > 0 and p["y"] > 0
                     for series in panel["series"] for p in series["points"])
        text = "values beyond 1e-300..1e300: not drawn" if beyond else "no successful cell"
        ax.text(0.5, 0.5, text, transform=ax.transAxes, ha="center")
        return
    ax.set_xlim(*log_limits(xs_lo, xs_hi))
    ax.set_ylim(*log_limits(ys_lo, ys_hi))
    lo, hi = ax.get_xlim()
    ticks = [t for t in panel.get("x_ticks", []) if finite(t) and lo <= t <= hi]
    if ticks:  # the budgets (or target spp) that have data, as the x ticks, in plain numbers
        ax.xaxis.set_major_locator(ticker.FixedLocator(ticks))
        ax.xaxis.set_minor_locator(ticker.NullLocator())
        ax.xaxis.set_major_formatter(ticker.FuncFormatter(plain_number))
    if not ticks:
        label_log_axis(ax.xaxis, *ax.get_xlim(), ticker)
    label_log_axis(ax.yaxis, *ax.get_ylim(), ticker)
    ax.grid(True, which="major", color="0.88", linewidth=0.6)
    ax.grid(True, which="minor", color="0.94", linewidth=0.4)


def draw_bars(ax, panel):
    categories = panel["categories"]
    groups = panel["groups"]
    width = 0.8 / max(len(groups), 1)
    for g, group in enumerate(groups):
        xs = [c + (g - (len(groups) - 1) / 2) * width for c in range(len(categories))]
        ys = [v["y"] if drawable(v["y"]) else 0.0 for v in group["values"]]
        ax.bar(xs, ys, width, label=group["name"], color=COLOURS[g % len(COLOURS)],
               hatch=["", "//", ".."][g % 3], edgecolor="white", linewidth=0.5, zorder=3)
        # Error bars where there is a standard error (two seeds or more) only.
        bars = [(x, y, v["y_se"]) for x, y, v in zip(xs, ys, group["values"])
                if drawable(v["y_se"])]
        if bars:
            ax.errorbar([b[0] for b in bars], [b[1] for b in bars], yerr=[b[2] for b in bars],
                        fmt="none", ecolor="black", elinewidth=0.8, capsize=2.5, capthick=0.8,
                        zorder=4)
    ax.set_xticks(range(len(categories)))
    ax.set_xticklabels(categories)  # turned by fit_tick_labels where they would touch
    ax.set_xlim(-0.6, len(categories) - 0.4)
    ax.grid(True, axis="y", color="0.88", linewidth=0.6)


def fit_tick_labels(ax, renderer):
    """A bars panel's category labels side by side where they fit between their ticks; else
    turned by the least of 30, 45, 60 and 90 degrees at which neighbours, a tick apart, clear
    each other (parallel boxes a tick apart are separated by the tick spacing x sin(angle))."""
    labels = [t for t in ax.get_xticklabels() if t.get_text()]
    if len(labels) < 2:
        return
    for label in labels:
        label.set_rotation(0)
        label.set_ha("center")
    xs = [ax.transData.transform((t, 0))[0] for t in ax.get_xticks()]
    spacing = min(b - a for a, b in zip(xs, xs[1:]))
    boxes = [label.get_window_extent(renderer) for label in labels]
    pad = 0.4 * max(b.height for b in boxes)
    if all((a.width + b.width) / 2 + pad <= spacing for a, b in zip(boxes, boxes[1:])):
        return
    height = max(b.height for b in boxes) + pad
    angle = next((a for a in (30, 45, 60) if spacing * math.sin(math.radians(a)) >= height), 90)
    for label in labels:
        label.set_rotation(angle)
        label.set_ha("right" if angle < 90 else "center")
        label.set_rotation_mode("anchor" if angle < 90 else "default")


def shared_legend(fig, handles, labels):
    """The panels' one legend, centred below them, in as many columns as fit the figure's width
    (at most LEGEND_COLUMNS): the figure grows by its height. Returns that height (inches)."""
    renderer = fig.canvas.get_renderer()
    for ncol in range(min(len(labels), LEGEND_COLUMNS), 0, -1):
        legend = fig.legend(handles, labels, loc="lower center", ncol=ncol, frameon=False,
                            bbox_to_anchor=(0.5, 0.0))
        box = legend.get_window_extent(renderer)
        if box.width <= 0.98 * fig.bbox.width or ncol == 1:
            break
        legend.remove()
    height = box.height / fig.dpi + 0.08
    fig.set_figheight(fig.get_figheight() + height)
    return height


def figure_of(spec, plt, ticker):
    """The figure of one spec: its panels in a row, or in rows of spec["columns"]. Everything
    drawn lies inside it: legends, and tick labels that do not touch."""
    panels = spec["panels"]
    columns = min(spec.get("columns", len(panels)), len(panels))
    rows = -(-len(panels) // columns)
    fig, axes = plt.subplots(rows, columns, squeeze=False,
                             figsize=(PANEL_SIZE[0] * columns, PANEL_SIZE[1] * rows + 0.2))
    axes = axes.ravel()
    for ax in axes[len(panels):]:
        ax.set_visible(False)
    for ax, panel in zip(axes, panels):
        if panel["type"] == "lines":
            draw_lines(ax, panel, ticker)
            ax.set_xlabel(panel["x_label"])
        elif panel["type"] == "bars":
            draw_bars(ax, panel)
            if "x_label" in panel:
                ax.set_xlabel(panel["x_label"])
        else:
            raise ValueError(f"unknown panel type {panel['type']!r}")
        ax.set_ylabel(panel["y_label"])
        ax.set_title(panel["title"])
    # Panels of the same series share one legend, below them; otherwise each has its own.
    per_panel = [ax.get_legend_handles_labels() for ax in axes[:len(panels)]]
    shared = all(labels == per_panel[0][1] for _, labels in per_panel)
    handles, labels = per_panel[0] if shared else ([], [])
    if not shared:
        for ax, (h, l) in zip(axes, per_panel):
            if h:
                ax.legend(h, l, frameon=False)
    renderer = fig.canvas.get_renderer()
    bars = [ax for ax, panel in zip(axes, panels) if panel["type"] == "bars"]
    fig.tight_layout()
    for ax in bars:  # the spacing of the ticks is known once the panels are laid out
        fit_tick_labels(ax, renderer)
    legend = shared_legend(fig, handles, labels) if shared and handles else 0
    for _ in range(2):  # turned labels take more height, and leave the panels narrower
        fig.tight_layout(rect=(0, legend / fig.get_figheight(), 1, 1))
        for ax in bars:
            fit_tick_labels(ax, renderer)
    return fig


def save_atomically(fig, path, **options):
    folder, name = os.path.split(path)
    fd, tmp = tempfile.mkstemp(prefix="." + name + ".", suffix=".tmp", dir=folder)
    try:
        with os.fdopen(fd, "wb") as out:
            fig.savefig(out, format=os.path.splitext(name)[1][1:], **options)
        os.chmod(tmp, 0o644)
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise


def main(argv):
    if len(argv) != 2:
        sys.stderr.write(__doc__)
        return BAD_INPUT
    try:  # run again in /usr/bin/python3 where this Python lacks matplotlib
        import system_python
        system_python.run_where_importable("matplotlib")
    except ImportError:  # the script copied alone, to restyle a figure
        pass
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib import ticker
    except ImportError:
        sys.stderr.write("plot_study.py: no matplotlib (Debian: apt-get install "
                         "python3-matplotlib)\n")
        return MISSING_MATPLOTLIB
    path = argv[1]
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
        figures = [(spec["name"], spec) for spec in data["figures"]]
        for name, _ in figures:  # a file name beside the data, never a path
            if not (isinstance(name, str) and re.fullmatch(r"[a-z0-9_]{1,64}", name)):
                raise ValueError(f"figure name {name!r} is not [a-z0-9_]{{1,64}}")
    except (OSError, ValueError, KeyError, TypeError) as e:
        sys.stderr.write(f"{path}: not a study's plot data ({e})\n")
        return BAD_INPUT
    matplotlib.rcParams.update({
        "font.size": 8, "axes.titlesize": 9, "axes.labelsize": 8, "legend.fontsize": 8,
        "pdf.fonttype": 42,  # TrueType: text stays text, editable in a paper's figure
        "axes.spines.top": False, "axes.spines.right": False,
    })
    # Every figure is made before any is written: a failure writes nothing.
    made = [(name, figure_of(spec, plt, ticker)) for name, spec in figures]
    folder = os.path.dirname(os.path.abspath(path))
    for name, fig in made:
        # No dates in the files: the same data gives the same bytes.
        save_atomically(fig, os.path.join(folder, name + ".pdf"),
                        metadata={"CreationDate": None, "ModDate": None})
        save_atomically(fig, os.path.join(folder, name + ".png"), dpi=200,
                        metadata={"Software": None})
        plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
