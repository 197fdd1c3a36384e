#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Object error per CPU second of hmcr's default solve (refine, then freeze) with each
combination of the solver options that change its noise (docs/results.md, "Object error per
second").

For each scene and budget, a first solve with the first variant and `--budget` finds the
oracle's threshold; every variant and seed then solves with that threshold (`--epsilon`), one
thread, and `hmcr error` measures the solution against the scene's reference. A variant is
`+`-joined words: a sequence (`random`, `sobol`: `--sequence`; without one, hmcr's default),
`both` (`--bidirectional yes`), `cv` (`--control-variate constant`), a basis (`linear`,
`bilinear`, `quadratic`, `cubic`: `--basis`). Prints, per scene, budget and
variant, the mean leaves, the mean object error with its standard error over the seeds, the
median CPU seconds of one solve (the whole process: user + system), and the efficiency
1 / (error^2 x seconds) relative to the first variant's.

Usage:
    scripts/options_error_per_second.py --hmcr build/hmcr --scene cornell \\
        --reference ref/cornell-points --budgets 5000,19000 --seeds 3 \\
        [--budget-tolerance 0.01] [--variants random,sobol,random+both,sobol+both,...] [--work DIR]
"""

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile

FLAGS = {"sobol": ["--sequence", "sobol"], "both": ["--bidirectional", "yes"],
         "cv": ["--control-variate", "constant"], "random": ["--sequence", "random"],
         **{basis: ["--basis", basis] for basis in ("linear", "bilinear", "quadratic", "cubic")}}


def variant_flags(variant):
    flags = []
    for word in variant.split("+"):
        if word not in FLAGS:
            sys.exit(f"options_error_per_second.py: unknown variant word {word!r} "
                     f"(one of {', '.join(FLAGS)})")
        flags += FLAGS[word]
    return flags


def run(command):
    """Runs hmcr; on a failure, hmcr has said why: stops with its exit code."""
    done = subprocess.run(command)
    if done.returncode != 0:
        sys.exit(done.returncode)


def solve(args, out, extra):
    """Solves once; returns the summary and the process's CPU seconds."""
    before = os.times()
    run([args.hmcr, "solve", args.scene, "--threads", "1", "-q", "-o", out] + extra)
    after = os.times()
    seconds = (after.children_user - before.children_user) + \
        (after.children_system - before.children_system)
    with open(out[:-4] + ".json") as f:
        return json.load(f), seconds


def object_error(args, solution, out):
    run([args.hmcr, "error", solution, "--reference", args.reference, "-q", "-o", out])
    with open(out) as f:
        return json.load(f)["object_error"]["relative_l2"]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--hmcr", required=True)
    p.add_argument("--scene", required=True)
    p.add_argument("--reference", required=True)
    p.add_argument("--budgets", default="5000,19000")
    p.add_argument("--budget-tolerance", default="0.01")
    p.add_argument("--seeds", type=int, default=3)
    p.add_argument("--variants",
                   default="random,sobol,random+both,sobol+both,random+cv,sobol+cv,sobol+both+cv")
    p.add_argument("--work", help="keep the solutions here (default: a temporary folder)")
    args = p.parse_args()
    variants = args.variants.split(",")
    for v in variants:
        variant_flags(v)
    work = args.work or tempfile.mkdtemp(prefix="hmcr-options-")
    os.makedirs(work, exist_ok=True)
    print(f"{args.scene}, one thread, {args.seeds} seeds, against {args.reference}")
    print(f"{'budget':>7} {'variant':<16} {'leaves':>7} {'object error':>18} {'CPU s':>6} "
          f"{'efficiency':>10}")
    for budget in [int(b) for b in args.budgets.split(",")]:
        found, _ = solve(args, os.path.join(work, f"budget-{budget}.vtp"),
                         ["--budget", str(budget), "--budget-tolerance", args.budget_tolerance]
                         + variant_flags(variants[0]))
        epsilon = found["options"]["epsilon"]
        first = None
        for v in variants:
            errors, seconds, leaves = [], [], []
            for seed in range(1, args.seeds + 1):
                name = os.path.join(work, f"{budget}-{v}-s{seed}")
                summary, s = solve(args, name + ".vtp", ["--epsilon", repr(epsilon), "--seed",
                                                         str(seed)] + variant_flags(v))
                errors.append(object_error(args, name + ".vtp", name + "-error.json"))
                seconds.append(s)
                leaves.append(summary["counts"]["leaves"])
            mean = statistics.fmean(errors)
            se = statistics.stdev(errors) / math.sqrt(len(errors)) if len(errors) > 1 else 0
            cpu = statistics.median(seconds)
            efficiency = 1 / (mean * mean * cpu)
            first = first or efficiency
            print(f"{budget:>7} {v:<16} {statistics.fmean(leaves):>7.0f} "
                  f"{mean:>10.4f} ± {se:.4f} {cpu:>6.2f} {efficiency / first:>10.2f}", flush=True)


if __name__ == "__main__":
    main()
