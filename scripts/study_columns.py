#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Meshing studies of one scene under different solver settings, side by side, as markdown.

Each study folder (`hmcr study ... -o DIR`) holds a table.json whose options name its refine
share, control variate and importance, and whose cells carry their object error and the PSNRp
of every view. For every budget this prints one table: a row per oracle, a column per study
(named by its settings: "F = 0.1, CV, importance"), each entry the mean +- standard error
over the seeds whose budget search succeeded of the object error, then of the PSNRp (the mean
over the views of each cell), and a last row with the mean seconds of a cell's budget search.
The lowest object error and the highest PSNRp of each row are in bold.

With --against K (a column, from 1) it then prints, for every other column and budget, the
differences paired by cell (oracle, budget, seed) against column K, mean +- standard error over
the cells both hold: the PSNRp's in dB and the object error's in percent. Cells of the same seed
share their refining pass when only the frozen pass's settings differ, so a pairing removes the
spread of the meshes.

    scripts/study_columns.py studies/cornell-unshot studies/cornell-freeze-0.5 ...
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
    """(column name, cells) of a study folder."""
    table = json.loads((Path(folder) / "table.json").read_text())
    options = table["options"]
    name = f"F = {options.get('refine_share', 1):g}"
    if options.get("control_variate", "none") != "none":
        name += ", CV"
    if options.get("importance", "none") != "none":
        name += ", importance"
    return name, table["cells"]


def summary(cells, budget, oracle):
    """Object error, PSNRp and seconds of the cells of one budget and oracle that succeeded."""
    ok = [c for c in cells if c["budget"] == budget and c["oracle"] == oracle and c["status"] == "ok"]
    errors = [c["object_error"]["relative_l2"] for c in ok]
    psnr = [cell_psnr(c) for c in ok]
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
    head = "| oracle | " + " | ".join(name for name, _ in studies) + " |"
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


def cell_psnr(c):
    return statistics.fmean(v["psnr_p"] for v in c["views"].values())


def paired_lines(studies, against):
    """One line per other column and budget: the paired differences against column `against`."""
    base_name, base_cells = studies[against]
    base = {(c["oracle"], c["budget"], c["seed"]): c for c in base_cells if c["status"] == "ok"}
    lines = []
    for k, (name, cells) in enumerate(studies):
        if k == against:
            continue
        for budget in sorted({c["budget"] for c in cells}):
            pairs = [(base[key], c) for c in cells if c["status"] == "ok"
                     for key in [(c["oracle"], c["budget"], c["seed"])]
                     if c["budget"] == budget and key in base]
            psnr = mean_se([cell_psnr(c) - cell_psnr(b) for b, c in pairs])
            error = mean_se([100 * (c["object_error"]["relative_l2"] /
                                    b["object_error"]["relative_l2"] - 1) for b, c in pairs])
            lines.append(f"- {name} against {base_name}, {budget:,} leaves ({len(pairs)} cells): "
                         f"PSNRp {psnr[0]:+.2f} ± {psnr[1]:.2f} dB, "
                         f"object error {error[0]:+.1f} ± {error[1]:.1f}%")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("studies", nargs="+", help="study folders, in the column order")
    parser.add_argument("--against", type=int, default=0,
                        help="also print paired differences against this column (from 1)")
    args = parser.parse_args()
    studies = [load(f) for f in args.studies]
    budgets = sorted({c["budget"] for _, cells in studies for c in cells})
    for b in budgets:
        print(f"**{b:,} leaves** (object error / PSNRp in dB)\n")
        print(budget_table(studies, b))
        print()
    failed = [(name, c["oracle"], c["budget"], c["seed"]) for name, cells in studies
              for c in cells if c["status"] != "ok"]
    if failed:
        print("Budget not reached: " + ", ".join(
            f"{n} `{o}` {b} s{seed}" for n, o, b, seed in failed) + ".")
    if args.against:
        if not 1 <= args.against <= len(studies):
            parser.error(f"--against must be a column from 1 to {len(studies)}")
        print()
        print("\n".join(paired_lines(studies, args.against - 1)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
