#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""A meshing study's cells measured against other references: does its verdict depend on the
reference? (docs/results.md, "Does the verdict depend on the reference?")

For every cell of the study (its `cells/CELL.json`) and every reference folder given, runs
`hmcr error` on the cell's solution (`meshes/CELL.vtp`) and on its frozen mesh
(`meshes/CELL-mesh.vtp`, where the study measured one), then prints, per budget and per
measure (the solution's object error, the mesh's), one row per oracle: the mean over the seeds
with its standard error and the oracle's rank under each reference. Below each table it lists
the pairs of oracles that two references order differently with both orders significant: the
difference of their means larger than 2 standard errors under each (the seeds' standard error
of the difference, which pairs the oracles' cells of the same seed, and each reference's own
standard error of its object errors, combined). "Same ranking" means no such pair.

Standard library only.  Usage:
    scripts/study_against.py --hmcr build/hmcr --study studies/office2 --scene SCENE \\
        REF_A REF_B ... [--names a,b,...] [--work DIR] [--markdown]

The `hmcr error` results are kept in WORK (default: STUDY/against/NAME/CELL[-mesh].json) and
reused on a rerun.
"""

import argparse
import json
import math
import os
import subprocess
import sys


def mean_se(values):
    n = len(values)
    if n == 0:
        return float("nan"), float("nan")
    m = sum(values) / n
    if n < 2:
        return m, float("nan")
    var = sum((v - m) ** 2 for v in values) / (n - 1)
    return m, math.sqrt(var / n)


def measure(hmcr, scene, vtp, reference, out):
    """The object error and its standard error of one solution against one reference."""
    if not os.path.exists(out):
        os.makedirs(os.path.dirname(out), exist_ok=True)
        subprocess.run([hmcr, "error", vtp, "--reference", reference, "--scene", scene, "-q",
                        "-o", out], check=True)
    with open(out) as f:
        e = json.load(f)["object_error"]
    se = e.get("standard_error")
    return e["relative_l2"], (se if se is not None else 0.0)


def ranks(means):
    order = sorted(means, key=lambda o: means[o])
    return {o: order.index(o) + 1 for o in means}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--hmcr", required=True)
    parser.add_argument("--study", required=True)
    parser.add_argument("--scene", required=True)
    parser.add_argument("--names", help="a short name per reference (default: folder names)")
    parser.add_argument("--work", help="where the hmcr error results go")
    parser.add_argument("references", nargs="+")
    args = parser.parse_args()
    names = args.names.split(",") if args.names else [os.path.basename(os.path.normpath(r))
                                                       for r in args.references]
    if len(names) != len(args.references):
        sys.exit("study_against.py: one name per reference")
    work = args.work or os.path.join(args.study, "against")
    cells = []
    cells_dir = os.path.join(args.study, "cells")
    for name in sorted(os.listdir(cells_dir)):
        with open(os.path.join(cells_dir, name)) as f:
            c = json.load(f)
        if c["status"] == "ok":
            cells.append(c)
    # errors[measure][ref][budget][oracle][seed] = (e, se)
    errors = {"solution": {}, "mesh": {}}
    for ref, ref_name in zip(args.references, names):
        for c in cells:
            cell = f"{c['scene']}-{c['oracle']}-B{c['budget']}-s{c['seed']}"
            for what, suffix in (("solution", ""), ("mesh", "-mesh")):
                vtp = os.path.join(args.study, "meshes", cell + suffix + ".vtp")
                if not os.path.exists(vtp):
                    continue
                out = os.path.join(work, ref_name, cell + suffix + ".json")
                e = measure(args.hmcr, args.scene, vtp, ref, out)
                (errors[what].setdefault(ref_name, {}).setdefault(c["budget"], {})
                 .setdefault(c["oracle"], {}))[c["seed"]] = e
    oracles = []
    for c in cells:
        if c["oracle"] not in oracles:
            oracles.append(c["oracle"])
    budgets = sorted({c["budget"] for c in cells})
    for what in ("solution", "mesh"):
        if not errors[what]:
            continue
        for b in budgets:
            print(f"\n**{b} leaves, the {what}'s object error**\n")
            print("| oracle | " + " | ".join(names) + " |")
            print("|:--|" + "--:|" * len(names))
            stats = {}
            for r in names:
                stats[r] = {}
                for o in oracles:
                    by_seed = errors[what].get(r, {}).get(b, {}).get(o, {})
                    m, se = mean_se([e for e, _ in by_seed.values()])
                    ref_se = (sum(s for _, s in by_seed.values()) / len(by_seed)) if by_seed else 0
                    stats[r][o] = (m, se, ref_se, by_seed)
            rank = {r: ranks({o: stats[r][o][0] for o in oracles}) for r in names}
            for o in oracles:
                row = []
                for r in names:
                    m, se, ref_se, _ = stats[r][o]
                    row.append(f"{m:.4f} ± {se:.4f} ({rank[r][o]})")
                print(f"| `{o}` | " + " | ".join(row) + " |")
            contradictions = []
            for i, a in enumerate(oracles):
                for bo in oracles[i + 1:]:
                    signs = {}
                    for r in names:
                        sa, sb = stats[r][a][3], stats[r][bo][3]
                        seeds = sorted(set(sa) & set(sb))
                        d = [sa[s][0] - sb[s][0] for s in seeds]
                        dm, dse = mean_se(d)
                        ref = math.hypot(stats[r][a][2], stats[r][bo][2])
                        total = math.hypot(dse if not math.isnan(dse) else 0.0, ref)
                        if abs(dm) > 2 * total:
                            signs[r] = 1 if dm > 0 else -1
                    if len(set(signs.values())) > 1:
                        contradictions.append(
                            f"`{a}` and `{bo}`: " + ", ".join(
                                f"{r} {'>' if s > 0 else '<'}" for r, s in signs.items()))
            print()
            print("Same ranking within the standard errors." if not contradictions
                  else "Ordered differently: " + "; ".join(contradictions) + ".")


if __name__ == "__main__":
    main()
