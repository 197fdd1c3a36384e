#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Noise per CPU second of hmcr's sequences, one way and both ways, on a fixed mesh
(docs/performance.md, "The Sobol sequence" and "Lines used both ways").

Solves a scene on its patches alone (`--max-depth 0`: no element is split, so every solve has
the same leaves) with each sequence over several seeds, one thread, and a converged solve of the
same leaves with `--converged-rays`. A variant is a sequence, or a sequence and `+both` for
`--bidirectional yes` (`sobol+both`). Prints, per variant, the per-patch relative RMS deviation
from the converged solve (over the lit patches and the three channels), the median CPU seconds
of one solve (the whole process: user + system), and the efficiency 1 / (deviation^2 x seconds)
relative to the first variant's.

Needs VTK's Python module (Debian's python3-vtk9).  Usage:
    scripts/fixed_mesh_noise.py --hmcr build/hmcr [--scene cornell] [--rays 2.684e6] \\
        [--seeds 8] [--variants random,sobol,sobol+both] [--converged-rays 2.684e8] [--work DIR]
"""

import argparse
import math
import os
import statistics
import subprocess
import sys
import tempfile

import numpy
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def radiosity(path):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return vtk_to_numpy(reader.GetOutput().GetCellData().GetArray("ElementRadiosity")).astype(float)


def solve(args, out, seed, variant, rays):
    """Solves once; returns the process's CPU seconds."""
    sequence, _, ways = variant.partition("+")
    if ways not in ("", "both"):
        sys.exit(f"fixed_mesh_noise.py: variant {variant!r} is a sequence or sequence+both")
    command = [args.hmcr, "solve", args.scene, "--max-depth", "0", "--threads", "1", "--seed",
               str(seed), "--sequence", sequence, "--rays", str(rays), "-q", "-o", out]
    if ways:
        command += ["--bidirectional", "yes"]
    process = subprocess.Popen(command)
    _, status, usage = os.wait4(process.pid, 0)
    if status != 0:
        sys.exit(f"fixed_mesh_noise.py: {' '.join(command)} failed")
    return usage.ru_utime + usage.ru_stime


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--hmcr", required=True)
    parser.add_argument("--scene", default="cornell")
    parser.add_argument("--rays", default="2.684e6")
    parser.add_argument("--seeds", type=int, default=8)
    parser.add_argument("--variants", default="random,sobol")
    parser.add_argument("--converged-rays", default="2.684e8")
    parser.add_argument("--work", help="keep the solutions here (default: a temporary folder)")
    args = parser.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="hmcr-noise-")
    converged_path = os.path.join(work, "converged.vtp")
    if not os.path.exists(converged_path):
        solve(args, converged_path, 1000, "sobol", args.converged_rays)
    converged = radiosity(converged_path)
    lit = converged > 0
    rows = []
    for variant in args.variants.split(","):
        squares, seconds = [], []
        for seed in range(1, args.seeds + 1):
            path = os.path.join(work, f"{variant}-{seed}.vtp")
            seconds.append(solve(args, path, seed, variant, args.rays))
            relative = (radiosity(path) - converged)[lit] / converged[lit]
            squares.append(float(numpy.mean(relative**2)))
        rms = math.sqrt(statistics.fmean(squares))
        rows.append((variant, rms, statistics.median(seconds)))
    print(f"{args.scene}, {int(lit.sum())} lit patch channels, {args.rays} rays, {args.seeds} seeds, "
          f"converged at {args.converged_rays}")
    print("| variant | per-patch RMS deviation | CPU s | efficiency |")
    print("|:--|--:|--:|--:|")
    base = 1 / (rows[0][1] ** 2 * rows[0][2])
    for variant, rms, cpu in rows:
        print(f"| `{variant}` | {100 * rms:.3f}% | {cpu:.2f} | {1 / (rms**2 * cpu) / base:.1f}× |")


if __name__ == "__main__":
    main()
