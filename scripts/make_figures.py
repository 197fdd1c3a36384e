#!/usr/bin/python3
"""Builds the docs' study figures from a finished study and its reference.

    /usr/bin/python3 docs/make_figures.py studies/cornell ref/cornell cornell 19000 camera corner

For each view: one strip, left to right the reference, power, ks and kl (seed 1 of the given
budget), each halved to 256 x 256; and a copy of the study's error plot. Written to
docs/images/. Needs Debian's python3-vtk9 (for PNG input and output) and numpy.
"""
import os
import shutil
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy


def read_png(path):
    r = vtk.vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    img = r.GetOutput()
    w, h, _ = img.GetDimensions()
    a = vtk_to_numpy(img.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3]
    return a[::-1]  # VTK's rows start at the bottom


def write_png(path, a):
    h, w, _ = a.shape
    img = vtk.vtkImageData()
    img.SetDimensions(w, h, 1)
    img.GetPointData().SetScalars(numpy_to_vtk(np.ascontiguousarray(a[::-1]).reshape(-1, 3)))
    wr = vtk.vtkPNGWriter()
    wr.SetFileName(path)
    wr.SetInputData(img)
    wr.Write()


def halve(a):
    a = a[: a.shape[0] // 2 * 2, : a.shape[1] // 2 * 2].astype(np.float64)
    return ((a[0::2, 0::2] + a[1::2, 0::2] + a[0::2, 1::2] + a[1::2, 1::2]) / 4).round().astype(np.uint8)


def main(study, ref, scene, budget, views):
    os.makedirs("docs/images", exist_ok=True)
    for view in views:
        panels = [read_png(f"{ref}/views/{view}.png")]
        for oracle in ("power", "ks", "kl"):
            panels.append(read_png(f"{study}/images/{scene}-{oracle}-B{budget}-s1-{view}.png"))
        gap = np.zeros((256, 4, 3), np.uint8)
        strip = [halve(p) for p in panels]
        out = np.concatenate(sum([[s, gap] for s in strip], [])[:-1], axis=1)
        write_png(f"docs/images/{scene}-{view}.png", out)
    shutil.copy(f"{study}/plots/error_vs_elements.png", f"docs/images/{scene}-error.png")


if __name__ == "__main__":
    if len(sys.argv) < 6:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5:])
