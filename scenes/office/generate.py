#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Generate an open-plan office floor as OBJ + MTL (deterministic, standard library only).

    /usr/bin/python3 scenes/office/generate.py                  # office.obj, about 10^6 faces
    /usr/bin/python3 scenes/office/generate.py --bays 4 --tile 0.4 --name office-small --out DIR

The floor is a grid of BAYS x BAYS bays of 3.2 x 3.2 m under a 3.2 m ceiling (x, y up, z),
closed by four outer walls. Floor, ceiling and walls are conforming grids of square tiles of
TILE metres (TILE divides 3.2), facing inward. Each bay has a desk (a slab on four legs), a
chair (seat, four legs, backrest), a cabinet, and a ceiling light made of the ceiling tiles
around the bay's centre; the light's radiance is scaled so that every bay emits the same power
whatever the tile size. Furniture boxes face outward and leave out the faces that touch another
surface. The default (42 x 42 bays, 0.2 m tiles) has about 1.04 million faces: the large scene
of `make bench`'s scaling study, generated on demand and kept out of git (about 60 MB).
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from obj_mesh import box_quads  # noqa: E402  (scenes/obj_mesh.py)

BAY = 3.2        # bay size and ceiling height, metres
BAY_POWER = 60.0  # emitted power per bay, W (E = pi * Ke over the light's area)

MATERIALS = [
    # name, Kd, emitting
    ('floor', (0.35, 0.33, 0.30), False),
    ('ceiling', (0.80, 0.80, 0.80), False),
    ('wall', (0.65, 0.66, 0.68), False),
    ('light', (0.80, 0.80, 0.80), True),
    ('desk', (0.60, 0.45, 0.30), False),
    ('chair', (0.15, 0.15, 0.20), False),
    ('cabinet', (0.50, 0.52, 0.55), False),
]


class Obj:
    """Faces grouped by material; vertices shared by exact position (micrometres)."""

    def __init__(self):
        self.vertex_lines = []
        self.index = {}
        self.faces = {name: [] for name, _, _ in MATERIALS}

    def v(self, x, y, z):
        key = (round(x * 1e6), round(y * 1e6), round(z * 1e6))
        i = self.index.get(key)
        if i is None:
            self.vertex_lines.append('v %.6g %.6g %.6g' % (x, y, z))
            i = self.index[key] = len(self.vertex_lines)
        return i

    def quad(self, material, corners):
        self.faces[material].append('f %d %d %d %d' % tuple(self.v(*c) for c in corners))


def grid(obj, material_of, origin, du, dv, nu, nv):
    """nu x nv tiles from origin along du and dv (3-vectors of one tile); the normal is
    du x dv. material_of(a, b) names the material of tile (a, b), or None for no tile."""
    for a in range(nu):
        for b in range(nv):
            m = material_of(a, b)
            if m is None:
                continue
            p = [origin[c] + a * du[c] + b * dv[c] for c in range(3)]
            obj.quad(m, [p, [p[c] + du[c] for c in range(3)],
                         [p[c] + du[c] + dv[c] for c in range(3)], [p[c] + dv[c] for c in range(3)]])


def box(obj, material, lo, hi, omit=()):
    """Axis-aligned box with outward normals, without the faces named in omit."""
    for quad in box_quads(lo, hi, omit):
        obj.quad(material, quad)


def legs(obj, material, x0, x1, z0, z1, top, size, inset):
    for lx in (x0 + inset, x1 - inset - size):
        for lz in (z0 + inset, z1 - inset - size):
            box(obj, material, (lx, 0.0, lz), (lx + size, top, lz + size), omit=('-y', '+y'))


def furniture(obj, x0, z0):
    """The desk, chair and cabinet of the bay whose corner is (x0, z0)."""
    dx0, dx1, dz0, dz1 = x0 + 0.9, x0 + 2.3, z0 + 0.85, z0 + 1.55
    box(obj, 'desk', (dx0, 0.72, dz0), (dx1, 0.75, dz1))
    legs(obj, 'desk', dx0, dx1, dz0, dz1, 0.72, 0.05, 0.04)
    cx0, cx1, cz0, cz1 = x0 + 1.375, x0 + 1.825, z0 + 1.7, z0 + 2.15
    box(obj, 'chair', (cx0, 0.42, cz0), (cx1, 0.46, cz1))
    legs(obj, 'chair', cx0, cx1, cz0, cz1, 0.42, 0.04, 0.02)
    box(obj, 'chair', (cx0 + 0.02, 0.46, cz1 - 0.06), (cx1 - 0.02, 0.95, cz1 - 0.02), omit=('-y',))
    box(obj, 'cabinet', (x0 + 0.3, 0.0, z0 + 2.7), (x0 + 1.3, 1.8, z0 + 3.05), omit=('-y',))


def generate(bays, tile):
    n = round(BAY / tile)
    if n < 1 or abs(n * tile - BAY) > 1e-9:
        raise SystemExit('generate.py: --tile must divide %g m' % BAY)
    size = bays * BAY
    count = bays * n
    obj = Obj()

    def in_light(i):  # tile i (along x or z) touches the middle 0.4 m of its bay
        a = (i % n) * tile
        return a < BAY / 2 + 0.2 - 1e-9 and a + tile > BAY / 2 - 0.2 + 1e-9

    light_tiles = sum(1 for i in range(n) if in_light(i)) ** 2
    # floor (normal +y), ceiling (normal -y), the four walls (normals inward)
    grid(obj, lambda a, b: 'floor', (0, 0, 0), (0, 0, tile), (tile, 0, 0), count, count)
    grid(obj, lambda a, b: 'light' if in_light(a) and in_light(b) else 'ceiling',
         (0, BAY, 0), (tile, 0, 0), (0, 0, tile), count, count)
    wall = lambda a, b: 'wall'
    grid(obj, wall, (0, 0, 0), (tile, 0, 0), (0, tile, 0), count, n)          # z = 0
    grid(obj, wall, (0, 0, size), (0, tile, 0), (tile, 0, 0), n, count)       # z = size
    grid(obj, wall, (0, 0, 0), (0, tile, 0), (0, 0, tile), n, count)          # x = 0
    grid(obj, wall, (size, 0, 0), (0, 0, tile), (0, tile, 0), count, n)       # x = size
    for bx in range(bays):
        for bz in range(bays):
            furniture(obj, bx * BAY, bz * BAY)
    radiance = BAY_POWER / (math.pi * light_tiles * tile * tile)
    return obj, radiance


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--bays', type=int, default=42, help='bays along each side (42)')
    parser.add_argument('--tile', type=float, default=0.2, help='tile size, m; divides 3.2 (0.2)')
    parser.add_argument('--name', default='office', help='file name without extension (office)')
    parser.add_argument('--out', default=os.path.dirname(os.path.abspath(__file__)),
                        help='output folder (this script\'s)')
    args = parser.parse_args()
    if args.bays < 1:
        raise SystemExit('generate.py: --bays must be at least 1')
    obj, radiance = generate(args.bays, args.tile)
    os.makedirs(args.out, exist_ok=True)
    faces = sum(len(f) for f in obj.faces.values())
    # Written under temporary names and renamed: an interrupted run leaves no half scene.
    base = os.path.join(args.out, args.name)
    with open(base + '.mtl.tmp', 'w') as fh:
        fh.write('# Office materials (generate.py). Kd: reflectance; Ke: radiance, E = pi Ke.\n')
        for name, kd, emitting in MATERIALS:
            ke = (radiance,) * 3 if emitting else (0, 0, 0)
            fh.write('\nnewmtl %s\nKd %g %g %g\nKe %.6g %.6g %.6g\n' % ((name,) + kd + ke))
    with open(base + '.obj.tmp', 'w') as fh:
        fh.write('# Office floor: %d x %d bays of %g m, %g m tiles, %d faces (generate.py).\n'
                 % (args.bays, args.bays, BAY, args.tile, faces))
        fh.write('mtllib %s.mtl\n' % args.name)
        fh.write('\n'.join(obj.vertex_lines))
        for name, lines in obj.faces.items():
            if lines:
                fh.write('\n\ng %s\nusemtl %s\n' % (name, name))
                fh.write('\n'.join(lines))
        fh.write('\n')
    os.replace(base + '.mtl.tmp', base + '.mtl')
    os.replace(base + '.obj.tmp', base + '.obj')
    print('%s.obj: %d faces, %d vertices' % (args.name, faces, len(obj.vertex_lines)))


if __name__ == '__main__':
    main()
