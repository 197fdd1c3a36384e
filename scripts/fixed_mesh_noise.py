#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Noise per CPU second of hmcr's sequences, one way and both ways, on a fixed mesh
(docs/performance.md, "The Sobol sequence" and "Lines used both ways").

Solves a scene on its patches alone (`--max-depth 0`: no element is split, so every solve has
the same leaves) with each sequence over several seeds, one thread, and a converged solve of the
same leaves with `--converged-rays`. A variant is a sequence, then `+both` for
`--bidirectional yes`, `+cv` for `--control-variate constant` and `+BASIS` for `--basis BASIS` if
wanted (`sobol+both`, `sobol+linear`; scripts/patch_noise.py):
a basis's per-patch values are its leaves' means, the patches' first coefficients. Prints, per variant, the per-patch relative RMS deviation
from the converged solve of its basis (over the lit patches and the three channels), the median CPU seconds
of one solve (the whole process: user + system), and the efficiency 1 / (deviation^2 x seconds)
relative to the first variant's.

Needs VTK's Python module (Debian's python3-vtk9).  Usage:
    scripts/fixed_mesh_noise.py --hmcr build/hmcr [--scene cornell] [--rays 2.684e6] \\
        [--seeds 8] [--variants random,sobol,sobol+both] [--converged-rays 2.684e8] [--work DIR]
"""

import argparse
import os
import statistics
import subprocess
import sys
import tempfile

import numpy
import vtk
from vtk.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import patch_noise  # noqa: E402  (beside this script)


def radiosity(path):
    """Each patch's mean B (area-weighted over its cells: a higher basis draws a leaf as several
    cells, each with the leaf's mean), patch by patch."""
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    cells = reader.GetOutput().GetCellData()
    b = vtk_to_numpy(cells.GetArray("ElementRadiosity")).astype(float)
    patch = vtk_to_numpy(cells.GetArray("PatchId")).astype(int)
    area = vtk_to_numpy(cells.GetArray("ElementArea")).astype(float)
    patches = patch.max() + 1
    weights = numpy.bincount(patch, weights=area, minlength=patches)
    return numpy.stack([numpy.bincount(patch, weights=area * b[:, c], minlength=patches)
                        for c in range(3)], axis=1) / weights[:, None]


def solve(args, out, seed, variant, rays):
    """Solves once; returns the process's CPU seconds."""
    try:
        command = patch_noise.hmcr_command(args.hmcr, args.scene, variant, seed, rays, out)
    except ValueError as e:
        sys.exit(f"fixed_mesh_noise.py: {e}")
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
    def converged_for(variant):
        """The converged solve of the variant's basis: another basis converges to another
        solution of the same leaves."""
        basis = patch_noise.variant_basis(variant)
        path = os.path.join(work, f"converged{'-' + basis if basis else ''}.vtp")
        if not os.path.exists(path):
            solve(args, path, 1000, "sobol" + ("+" + basis if basis else ""), args.converged_rays)
        return radiosity(path)

    lit = patch_noise.lit_channels(converged_for("sobol"))
    rows = []
    for variant in args.variants.split(","):
        converged = converged_for(variant)
        runs, seconds = [], []
        for seed in range(1, args.seeds + 1):
            path = os.path.join(work, f"{variant}-{seed}.vtp")
            seconds.append(solve(args, path, seed, variant, args.rays))
            runs.append(radiosity(path))
        rms = patch_noise.relative_rms(runs, converged, lit)
        rows.append((variant, rms, statistics.median(seconds)))
    print(f"{args.scene}, {len(lit)} lit patch channels, {args.rays} rays, {args.seeds} seeds, "
          f"converged at {args.converged_rays}")
    print("| variant | per-patch RMS deviation | CPU s | efficiency |")
    print("|:--|--:|--:|--:|")
    base = 1 / (rows[0][1] ** 2 * rows[0][2])
    for variant, rms, cpu in rows:
        print(f"| `{variant}` | {100 * rms:.3f}% | {cpu:.2f} | {1 / (rms**2 * cpu) / base:.1f}× |")


if __name__ == "__main__":
    main()
