#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""scripts/render_vtp.py draws a two-sided patch as its .pvsm has ParaView draw it: from either
side, the side that faces the viewer. The scene: a closed room of one-sided walls with a light in
its ceiling and a two-sided shelf in the middle, lit from above by the light and from below by
the floor, so that both of its sides have cells, coincident. Each view of the shelf (from above,
from below) drawn by render_vtp.py must match `hmcr render` of the same view: unculled, the dark
side fights the lit one in the depth buffer and shows through in stripes.

Usage: xvfb-run -a /usr/bin/python3 render_vtp_test.py HMCR SOURCE_DIR. Exit code 1 on failure."""
import json
import os
import subprocess
import sys
import tempfile

import vtk
from vtk.util import numpy_support

HMCR, SOURCE = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])


def write_scene(folder):
    """room.obj, room.mtl and shelf.json in the folder."""
    lo, hi, n = (0, 0, 0), (4, 3, 2.5), 3
    lines, count = ["mtllib room.mtl"], 0

    def polygon(points, material):
        nonlocal count
        lines.append("usemtl " + material)
        lines.extend("v %r %r %r" % tuple(p) for p in points)
        lines.append("f " + " ".join(str(count + k + 1) for k in range(len(points))))
        count += len(points)

    for axis in range(3):  # each wall in n x n quads, facing in
        a, b = (axis + 1) % 3, (axis + 2) % 3
        for side in range(2):
            for i in range(n):
                for j in range(n):
                    def at(s, t):
                        p = [0.0, 0.0, 0.0]
                        p[axis], p[a], p[b] = (hi if side else lo)[axis], s, t
                        return p
                    cut = lambda k, c: lo[k] + (hi[k] - lo[k]) * c / n
                    quad = [at(cut(a, i), cut(b, j)), at(cut(a, i + 1), cut(b, j)),
                            at(cut(a, i + 1), cut(b, j + 1)), at(cut(a, i), cut(b, j + 1))]
                    if side:
                        quad.reverse()
                    light = axis == 2 and side and i == 1 and j == 1
                    polygon(quad, "light" if light else "wall")
    polygon([(1, 0.8, 1), (3, 0.8, 1), (3, 2.2, 1), (1, 2.2, 1)], "shelf")
    with open(os.path.join(folder, "room.obj"), "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(os.path.join(folder, "room.mtl"), "w") as f:
        f.write("newmtl wall\nKd 0.6 0.6 0.6\nnewmtl shelf\nKd 0.7 0.5 0.3\n"
                "newmtl light\nKd 0 0 0\nKe 5 5 5\n")
    view = {"up": [0, 0, 1], "fov": 60, "width": 160, "height": 120}
    scene = {"mesh": "room.obj", "sides": 1, "material_sides": {"shelf": 2},
             "views": [{"name": "above", "position": [2, 0.2, 2.2], "look_at": [2, 1.5, 1.0],
                        **view},
                       {"name": "below", "position": [2, 0.2, 0.3], "look_at": [2, 1.5, 1.0],
                        **view}]}
    with open(os.path.join(folder, "shelf.json"), "w") as f:
        json.dump(scene, f)


def grey(png):
    """The PNG's pixels as a flat array of channel means, 0-255."""
    reader = vtk.vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    data = reader.GetOutput().GetPointData().GetScalars()
    pixels = numpy_support.vtk_to_numpy(data).astype(float)
    return pixels[:, :3].mean(axis=1)


def run(*args, cwd):
    subprocess.run(args, cwd=cwd, check=True, stdout=subprocess.DEVNULL)


def main():
    failures = []
    with tempfile.TemporaryDirectory() as folder:
        write_scene(folder)
        run(HMCR, "solve", "shelf.json", "--rays", "200000", "-q", "-o", "solution.vtp",
            cwd=folder)
        with open(os.path.join(folder, "solution.vtp"), "rb") as f:
            if b'Name="Side"' not in f.read():
                sys.exit("the solution has no back cells: the test would test nothing")
        for view in ("above", "below"):
            run(HMCR, "render", "solution.vtp", "--scene", "shelf.json", "--view", view, "-q",
                "-o", f"hmcr-{view}.png", cwd=folder)
            run(sys.executable, os.path.join(SOURCE, "scripts", "render_vtp.py"), "solution.vtp",
                "shelf.json", view, f"vtk-{view}.png", cwd=folder)
            ours = grey(os.path.join(folder, f"hmcr-{view}.png"))
            theirs = grey(os.path.join(folder, f"vtk-{view}.png"))
            # Rasterised and ray-cast edges differ by a pixel: allow 2% of the pixels to differ.
            differing = ((theirs - ours) ** 2 > (0.25 * ours + 8) ** 2).mean()
            if differing > 0.02:
                failures.append(f"view {view}: {100 * differing:.1f}% of render_vtp.py's pixels "
                                f"differ from hmcr render's by more than a quarter")
    for f in failures:
        print(f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
