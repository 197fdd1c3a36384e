#!/usr/bin/env python3
"""Meshing studies of one scene at several refine shares, side by side, as markdown.

Each study folder (`hmcr study ... --refine-share F -o DIR`) holds a table.json whose cells
carry their object error and the PSNRp of every view. For every budget this prints one table:
a row per oracle, a column per study (its refine share), each entry the mean +- standard error
over the seeds whose budget search succeeded of the object error, then of the PSNRp (the mean
over the views of each cell), and a last row with the mean seconds of a cell's budget search.
The lowest object error and the highest PSNRp of each row are in bold.

    scripts/refine_share_table.py studies/cornell-unshot studies/cornell-freeze-0.5 ...
"""

import argparse
import json
import math
import statistics
import sys
from pathlib import Path


def mean_se(values):
    """(mean, standard error) of a list; the error is nan for fewer than two values."""
    if not values:
        return math.nan, math.nan
    m = statistics.fmean(values)
    se = statistics.stdev(values) / math.sqrt(len(values)) if len(values) > 1 else math.nan
    return m, se


def load(folder):
    table = json.loads((Path(folder) / "table.json").read_text())
    share = table["options"].get("refine_share", 1)
    return share, table["cells"]


def summary(cells, budget, oracle):
    """Object error, PSNRp and seconds of the cells of one budget and oracle that succeeded."""
    ok = [c for c in cells if c["budget"] == budget and c["oracle"] == oracle and c["status"] == "ok"]
    errors = [c["object_error"]["relative_l2"] for c in ok]
    psnr = [statistics.fmean(v["psnr_p"] for v in c["views"].values()) for c in ok]
    return mean_se(errors), mean_se(psnr), [c["seconds"] for c in ok]


def entry(stat, digits, bold):
    m, se = stat
    if math.isnan(m):
        return "–"
    text = f"{m:.{digits}f} ± {se:.{digits}f}" if not math.isnan(se) else f"{m:.{digits}f}"
    return f"**{text}**" if bold else text


def budget_table(studies, budget):
    oracles = []
    for _, cells in studies:
        for c in cells:
            if c["oracle"] not in oracles:
                oracles.append(c["oracle"])
    head = "| oracle | " + " | ".join(f"F = {share:g}" for share, _ in studies) + " |"
    lines = [head, "|:--|" + "--:|" * len(studies)]
    seconds = [[] for _ in studies]
    for oracle in oracles:
        rows = [summary(cells, budget, oracle) for _, cells in studies]
        best_error = min((r[0][0] for r in rows if not math.isnan(r[0][0])), default=math.nan)
        best_psnr = max((r[1][0] for r in rows if not math.isnan(r[1][0])), default=math.nan)
        out = []
        for k, (error, psnr, secs) in enumerate(rows):
            seconds[k] += secs
            out.append(entry(error, 4, error[0] == best_error) + " / " +
                       entry(psnr, 2, psnr[0] == best_psnr))
        lines.append(f"| `{oracle}` | " + " | ".join(out) + " |")
    lines.append("| seconds per cell | " +
                 " | ".join(f"{statistics.fmean(s):.1f}" if s else "–" for s in seconds) + " |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("studies", nargs="+", help="study folders, in the column order")
    args = parser.parse_args()
    studies = [load(f) for f in args.studies]
    budgets = sorted({c["budget"] for _, cells in studies for c in cells})
    for b in budgets:
        print(f"**{b:,} leaves** (object error / PSNRp in dB)\n")
        print(budget_table(studies, b))
        print()
    failed = [(share, c["oracle"], c["budget"], c["seed"]) for share, cells in studies
              for c in cells if c["status"] != "ok"]
    if failed:
        print("Budget not reached: " + ", ".join(
            f"F = {s:g} `{o}` {b} s{seed}" for s, o, b, seed in failed) + ".")
    return 0


if __name__ == "__main__":
    sys.exit(main())
