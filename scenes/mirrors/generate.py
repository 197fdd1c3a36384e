#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Generate mirrors.obj and mirrors.mtl (deterministic, standard library only).

    /usr/bin/python3 scenes/mirrors/generate.py

The test scene of the adaptive supersampling papers in hmcr's terms (Rigau, Feixas, Sbert,
"Refinement criteria based on f-divergences", EGSR 2003, Figs. 3-5, and "Entropy-based adaptive
supersampling", 2003): a closed 5 m (x) x 3 m (y, up) x 5 m (z) room with a table on which stand
a mirrored pyramid and a mirrored sphere. Two ceiling lights make each object cast a shadow on
the table top and on the other object, and the mirrors show those shadows again: the variance
of a traced image sits in a few pixels, the reflected shadows and the light the mirrors throw
onto the table.

Materials: the mirrors reflect Ks = 0.85 as ideal mirrors (MTL `illum 3`) and Kd = 0.05
diffusely, so a shadow falling on them stays faintly visible. The walls differ in colour so that
reflections show which way they look. Everything else is diffuse.

Geometry: the shell is one quad per wall, facing inward, with the lights cut conformingly out of
the ceiling (8 quads around 2 light quads); the table is a slab on four legs; a cube stands in a
corner and another hangs on the left wall; the pyramid is four triangles on a square base (no
bottom face: it stands on the table); the sphere is a UV sphere of 64 x 32 facets touching the
table at its lowest point. Boxes are axis-aligned with outward normals and no face where they
touch another surface.

Output of the current version: 2,104 faces, 2,075 vertices.
"""

import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from obj_mesh import Mesh, fmt  # noqa: E402  (scenes/obj_mesh.py)

LX, LY, LZ = 5.0, 3.0, 5.0  # room size (x, y up, z), metres
# Lights: two 0.8 x 0.4 m ceiling panels, (x0, x1, z0, z1), over either side of the table.
LIGHTS = [(1.3, 2.1, 2.3, 2.7), (2.9, 3.7, 2.3, 2.7)]
TABLE = (1.7, 3.3, 2.0, 3.0, 0.72, 0.76)  # x0, x1, z0, z1, slab bottom, top
PYRAMID = (2.1, 2.4, 0.5, 0.55)  # centre x, centre z, base side, height
SPHERE = (2.85, 2.6, 0.24, 64)  # centre x, centre z, radius, segments around

MATERIALS = [
    # name, Kd, Ks (illum 3 when given), Ke, comment
    ('floor', (0.50, 0.40, 0.30), None, None, 'floor, light wood'),
    ('ceiling', (0.80, 0.80, 0.80), None, None, 'white ceiling'),
    ('wall', (0.70, 0.70, 0.66), None, None, 'back and front walls, warm grey'),
    ('wall_left', (0.70, 0.35, 0.30), None, None, 'left wall (x = 0), red'),
    ('wall_right', (0.35, 0.50, 0.70), None, None, 'right wall (x = 5), blue'),
    ('light', (0.78, 0.78, 0.78), None, (12.0, 12.0, 11.0), 'ceiling lights, E = pi*Ke'),
    ('table', (0.60, 0.55, 0.45), None, None, 'table, pale wood'),
    ('cube_green', (0.15, 0.55, 0.20), None, None, 'green cube in a corner'),
    ('cube_yellow', (0.75, 0.65, 0.15), None, None, 'yellow cube on the left wall'),
    ('mirror', (0.05, 0.05, 0.05), (0.85, 0.85, 0.85), None,
     'mirrored pyramid and sphere: an ideal mirror of 0.85 over 0.05 diffuse'),
]


def quad_y(m, faces, x0, x1, z0, z1, y, down):
    """A horizontal rectangle at height y facing down (-y) or up (+y)."""
    if down:
        faces.append([m.v((x0, y, z0)), m.v((x1, y, z0)), m.v((x1, y, z1)), m.v((x0, y, z1))])
    else:
        faces.append([m.v((x0, y, z0)), m.v((x0, y, z1)), m.v((x1, y, z1)), m.v((x1, y, z0))])


def shell(m):
    """Floor, walls and a ceiling cut around the lights; every face looks inward."""
    quad_y(m, m.group('floor', 'floor'), 0, LX, 0, LZ, 0, down=False)
    # The ceiling: a grid over the lights' x and z edges, every cell a quad (conforming).
    xs = sorted({0.0, LX} | {x for l in LIGHTS for x in l[:2]})
    zs = sorted({0.0, LZ} | {z for l in LIGHTS for z in l[2:]})
    ceiling, lights = m.group('ceiling', 'ceiling'), m.group('lights', 'light')
    for i in range(len(xs) - 1):
        for k in range(len(zs) - 1):
            cell = (xs[i], xs[i + 1], zs[k], zs[k + 1])
            quad_y(m, lights if cell in LIGHTS else ceiling, *cell, LY, down=True)
    back = m.group('walls', 'wall')
    back.append([m.v((0, 0, 0)), m.v((LX, 0, 0)), m.v((LX, LY, 0)), m.v((0, LY, 0))])      # z=0
    back.append([m.v((0, 0, LZ)), m.v((0, LY, LZ)), m.v((LX, LY, LZ)), m.v((LX, 0, LZ))])  # z=LZ
    left = m.group('wall_left', 'wall_left')   # x = 0, normal +x
    left.append([m.v((0, 0, 0)), m.v((0, LY, 0)), m.v((0, LY, LZ)), m.v((0, 0, LZ))])
    right = m.group('wall_right', 'wall_right')  # x = LX, normal -x
    right.append([m.v((LX, 0, 0)), m.v((LX, 0, LZ)), m.v((LX, LY, LZ)), m.v((LX, LY, 0))])


def table(m):
    f = m.group('table', 'table')
    x0, x1, z0, z1, y0, y1 = TABLE
    m.box(f, (x0, y0, z0), (x1, y1, z1))
    size, inset = 0.06, 0.05
    for lx in (x0 + inset, x1 - inset - size):
        for lz in (z0 + inset, z1 - inset - size):
            m.box(f, (lx, 0, lz), (lx + size, y0, lz + size), omit=('-y', '+y'))


def cubes(m):
    m.box(m.group('cube_green', 'cube_green'), (4.2, 0, 4.2), (4.8, 0.6, 4.8), omit=('-y',))
    m.box(m.group('cube_yellow', 'cube_yellow'), (0, 1.4, 1.8), (0.4, 1.8, 2.2), omit=('-x',))


def pyramid(m):
    """Four mirrored triangles over a square base on the table top, facing out."""
    f = m.group('pyramid', 'mirror')
    cx, cz, side, height = PYRAMID
    y = TABLE[5]
    h = side / 2
    base = [(cx - h, y, cz - h), (cx + h, y, cz - h), (cx + h, y, cz + h), (cx - h, y, cz + h)]
    apex = (cx, y + height, cz)
    for i in range(4):  # base corners clockwise seen from above: each side turns outward
        f.append([m.v(base[i]), m.v(apex), m.v(base[(i + 1) % 4])])


def sphere(m):
    """A UV sphere resting on the table top: quads between latitude rings (planar isosceles
    trapezoids), triangles at the poles, corners on the true sphere, facing out."""
    f = m.group('sphere', 'mirror')
    cx, cz, r, n = SPHERE
    cy = TABLE[5] + r
    rings = n // 2

    def point(i, j):  # ring i from the top pole (0) to the bottom (rings), meridian j
        theta, phi = math.pi * i / rings, 2 * math.pi * j / n
        return (cx + r * math.sin(theta) * math.cos(phi), cy + r * math.cos(theta),
                cz + r * math.sin(theta) * math.sin(phi))

    for i in range(rings):
        for j in range(n):
            a, b = point(i, j), point(i, j + 1)
            c, d = point(i + 1, j + 1), point(i + 1, j)
            if i == 0:
                f.append([m.v(a), m.v(c), m.v(d)])
            elif i == rings - 1:
                f.append([m.v(a), m.v(b), m.v(d)])
            else:
                f.append([m.v(a), m.v(b), m.v(c), m.v(d)])


def main():
    m = Mesh()
    shell(m)
    table(m)
    cubes(m)
    pyramid(m)
    sphere(m)

    lines = ['# mirrors: a 5 x 3 x 5 m room (x, y up, z) with a mirrored pyramid and a mirrored',
             '# sphere on a table, lit by two ceiling panels.',
             '# Generated by generate.py (deterministic); do not edit by hand.',
             'mtllib mirrors.mtl', '']
    lines += ['v %s %s %s' % tuple(fmt(c) for c in p) for p in m.verts]
    for name, mtl, faces in m.groups:
        lines += ['', 'g ' + name, 'usemtl ' + mtl]
        lines += ['f ' + ' '.join(str(i) for i in f) for f in faces]
    with open(os.path.join(HERE, 'mirrors.obj'), 'w') as fh:
        fh.write('\n'.join(lines) + '\n')

    mtl = ['# mirrors materials. Kd = diffuse reflectance, Ks = mirror reflectance (illum 3),',
           '# Ke = emitted radiance (W sr^-1 m^-2), E = pi * Ke. Generated by generate.py.']
    for name, kd, ks, ke, comment in MATERIALS:
        mtl += ['', '# ' + comment, 'newmtl ' + name, 'Kd %s %s %s' % tuple(fmt(c) for c in kd),
                'Ke %s %s %s' % tuple(fmt(c) for c in (ke or (0, 0, 0)))]
        if ks:
            mtl += ['Ks %s %s %s' % tuple(fmt(c) for c in ks), 'illum 3']
    with open(os.path.join(HERE, 'mirrors.mtl'), 'w') as fh:
        fh.write('\n'.join(mtl) + '\n')

    print('mirrors: %d faces, %d vertices' % (m.face_count(), len(m.verts)))


if __name__ == '__main__':
    main()
