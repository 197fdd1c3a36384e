#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Render an hmcr solution (.vtp) to a PNG with VTK, the way ParaView shows it.

    xvfb-run -a /usr/bin/python3 scripts/render_vtp.py out/cornell.vtp scenes/cornell/cornell.json camera out/cornell.png [--edges]

Colours are the solution's own RadiosityColor (tone-mapped sRGB bytes, not re-mapped through a
colour table) with Gouraud interpolation and lighting off, as in ParaView with "Map Scalars"
unchecked and the light kit off: what you see is the radiosity. --edges draws the element
boundaries (the mesh the oracle made). --clusters colours a clustered solution's cells by their
ClusterId instead: each cluster leaf one colour, its faces shaded by their radiosity, and the
cells outside cluster leaves grey by theirs. A solution with two-sided patches (its cells have a
Side array) is drawn with back faces culled, as its .pvsm has ParaView draw it: a patch's two
sides are coincident polygons facing away from each other, and each viewer sees the one that
faces it (unculled, the two fight in the depth buffer and the dark side shows through). Needs
Debian's python3-vtk9 (`/usr/bin/python3`).
"""
import colorsys
import json
import sys

import vtk


# The optional keys of a view and their defaults, as hmcr's scene loader has them.
VIEW_DEFAULTS = {"up": [0, 1, 0], "fov": 40, "width": 512, "height": 512}


def load_view(scene_json, name):
    views = {v["name"]: v for v in json.load(open(scene_json)).get("views", [])}
    if name not in views:
        sys.exit(f"{scene_json}: no view '{name}' (views: {', '.join(views) or 'none'})")
    return {**VIEW_DEFAULTS, **views[name]}


def cluster_colours(polydata):
    """A cell array ClusterColor: a hue per cluster leaf, grey outside them, each cell's
    brightness its radiosity's (the cell-averaged RadiosityColor)."""
    cells = polydata.GetCellData()
    ids = cells.GetArray("ClusterId")
    if ids is None:
        sys.exit("the solution has no ClusterId: it was solved without --clustering isotropic")
    points = vtk.vtkPointDataToCellData()
    points.SetInputData(polydata)
    points.Update()
    shade = points.GetOutput().GetCellData().GetArray("RadiosityColor")
    colours = vtk.vtkUnsignedCharArray()
    colours.SetName("ClusterColor")
    colours.SetNumberOfComponents(3)
    for c in range(polydata.GetNumberOfCells()):
        k = int(ids.GetTuple1(c))
        brightness = 0.35 + 0.65 * max(shade.GetTuple3(c)) / 255
        if k < 0:
            base = (0.8, 0.8, 0.8)
        else:
            golden = (k * 0.6180339887) % 1.0  # hues far apart for neighbouring indices
            base = colorsys.hsv_to_rgb(golden, 0.65, 1.0)
        colours.InsertNextTuple3(*(255 * brightness * x for x in base))
    out = vtk.vtkPolyData()
    out.ShallowCopy(polydata)
    out.GetCellData().AddArray(colours)
    return out


def main(argv):
    args = [a for a in argv[1:] if not a.startswith("--")]
    if len(args) != 4:
        sys.exit(__doc__)
    vtp, scene_json, view_name, png = args
    v = load_view(scene_json, view_name)

    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(vtp)
    reader.Update()
    mapper = vtk.vtkPolyDataMapper()
    if "--clusters" in argv:
        mapper.SetInputData(cluster_colours(reader.GetOutput()))
        mapper.SetScalarModeToUseCellFieldData()
        mapper.SelectColorArray("ClusterColor")
    else:
        mapper.SetInputConnection(reader.GetOutputPort())
        mapper.SetScalarModeToUsePointFieldData()
        mapper.SelectColorArray("RadiosityColor")
    mapper.SetColorModeToDirectScalars()
    mapper.ScalarVisibilityOn()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    prop = actor.GetProperty()
    prop.SetInterpolationToGouraud()
    prop.SetAmbient(1.0)
    prop.SetDiffuse(0.0)
    prop.SetSpecular(0.0)
    if reader.GetOutput().GetCellData().GetArray("Side") is not None:
        prop.BackfaceCullingOn()
    if "--edges" in argv:
        prop.EdgeVisibilityOn()
        prop.SetEdgeColor(0.1, 0.1, 0.1)
        prop.SetLineWidth(0.5)

    renderer = vtk.vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0, 0, 0)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(*v["position"])
    camera.SetFocalPoint(*v["look_at"])
    camera.SetViewUp(*v["up"])
    camera.SetViewAngle(v["fov"])
    renderer.ResetCameraClippingRange()

    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(v["width"], v["height"])
    window.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(png)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


if __name__ == "__main__":
    main(sys.argv)
