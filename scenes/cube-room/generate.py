#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Generate cube-room.obj and cube-room.mtl (deterministic, standard library only).

    /usr/bin/python3 scenes/cube-room/generate.py

A closed 6 m (x) x 3 m (y, up) x 4 m (z) room. The shell (floor, ceiling, four walls, normals
facing inward) is a conforming grid of 0.25 m square tiles; two 1.0 m x 0.5 m ceiling lights are
made of 2 x 4 ceiling tiles each (so the ceiling stays conforming), facing down. Furniture is
built from axis-aligned boxes with outward normals, one quad per box face: a table (top slab +
4 legs), four chairs (seat, 4 legs, backrest) and five cubes (three on the floor, one of them
against the back wall, two attached to walls). A box face that touches another surface (floor,
wall, the underside of a slab or seat) is left out. The cubes are aligned with the tile grid
and the shell tiles they cover are left out too (their sides close the hole exactly), so no
shell tile is hidden; only the small footprints of the table and chair legs hide parts of floor
tiles. Legs and backrests are inset from the edges of the slab/seat they touch so that no two
coplanar faces of different boxes are neighbours (no T-junctions).

Output of the current version: 1853 faces (1699 shell tiles incl. 16 light tiles, 154 furniture
faces), 1970 vertices.
"""

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from obj_mesh import Mesh, fmt  # noqa: E402  (scenes/obj_mesh.py)

LX, LY, LZ = 6.0, 3.0, 4.0    # room size (x, y up, z), metres
TILE = 0.25                    # shell tile size: 24 x 16 x 12 tiles
NX, NY, NZ = int(round(LX / TILE)), int(round(LY / TILE)), int(round(LZ / TILE))

# Lights: ranges of ceiling tile indices (i along x, k along z), each 4 x 2 tiles = 1.0 x 0.5 m.
LIGHTS = [(range(6, 10), range(7, 9)), (range(14, 18), range(7, 9))]

MATERIALS = [
    # name, Kd, Ke, comment
    ('wall', (0.70, 0.70, 0.68), None, 'light grey walls'),
    ('floor', (0.45, 0.30, 0.18), None, 'wooden floor, brown'),
    ('ceiling', (0.80, 0.80, 0.80), None, 'white ceiling'),
    ('light', (0.78, 0.78, 0.78), (8.0, 8.0, 7.0), 'ceiling lights, E = pi*Ke'),
    ('table', (0.55, 0.38, 0.22), None, 'table, light wood'),
    ('chair', (0.30, 0.20, 0.12), None, 'chairs, dark wood'),
    ('cube_red', (0.65, 0.10, 0.08), None, 'red cube'),
    ('cube_blue', (0.10, 0.20, 0.60), None, 'blue cube'),
    ('cube_yellow', (0.75, 0.65, 0.12), None, 'yellow cube'),
    ('cube_green', (0.12, 0.50, 0.15), None, 'green cube'),
    ('cube_teal', (0.10, 0.50, 0.50), None, 'teal cube'),
]


def shell(m):
    """Floor, ceiling and walls as conforming grids, normals inward."""
    xs = [i * TILE for i in range(NX + 1)]
    ys = [j * TILE for j in range(NY + 1)]
    zs = [k * TILE for k in range(NZ + 1)]
    light_tiles = {(i, k) for ri, rk in LIGHTS for i in ri for k in rk}
    hole = covered_tiles()

    floor = m.group('floor', 'floor')
    for i in range(NX):
        for k in range(NZ):   # normal +y: (x0,z0) (x0,z1) (x1,z1) (x1,z0)
            if ('floor', i, k) in hole:
                continue
            floor.append([m.v((xs[i], 0, zs[k])), m.v((xs[i], 0, zs[k + 1])),
                              m.v((xs[i + 1], 0, zs[k + 1])), m.v((xs[i + 1], 0, zs[k]))])
    ceiling = m.group('ceiling', 'ceiling')
    lights = m.group('lights', 'light')
    for i in range(NX):
        for k in range(NZ):   # normal -y
            f = [m.v((xs[i], LY, zs[k])), m.v((xs[i + 1], LY, zs[k])),
                 m.v((xs[i + 1], LY, zs[k + 1])), m.v((xs[i], LY, zs[k + 1]))]
            (lights if (i, k) in light_tiles else ceiling).append(f)
    walls = m.group('walls', 'wall')
    for i in range(NX):
        for j in range(NY):
            # z = 0, normal +z
            if ('z0', i, j) not in hole:
                walls.append([m.v((xs[i], ys[j], 0)), m.v((xs[i + 1], ys[j], 0)),
                              m.v((xs[i + 1], ys[j + 1], 0)), m.v((xs[i], ys[j + 1], 0))])
            # z = LZ, normal -z
            if ('z1', i, j) not in hole:
                walls.append([m.v((xs[i], ys[j], LZ)), m.v((xs[i], ys[j + 1], LZ)),
                              m.v((xs[i + 1], ys[j + 1], LZ)), m.v((xs[i + 1], ys[j], LZ))])
    for k in range(NZ):
        for j in range(NY):
            # x = 0, normal +x
            if ('x0', k, j) not in hole:
                walls.append([m.v((0, ys[j], zs[k])), m.v((0, ys[j + 1], zs[k])),
                              m.v((0, ys[j + 1], zs[k + 1])), m.v((0, ys[j], zs[k + 1]))])
            # x = LX, normal -x
            if ('x1', k, j) not in hole:
                walls.append([m.v((LX, ys[j], zs[k])), m.v((LX, ys[j], zs[k + 1])),
                              m.v((LX, ys[j + 1], zs[k + 1])), m.v((LX, ys[j + 1], zs[k]))])


# every box, kept for the intersection check below: (lo, hi)
BOXES = []


def add_box(faces, m, lo, hi, omit=()):
    BOXES.append((lo, hi))
    m.box(faces, lo, hi, omit)


def legs(faces, m, x0, x1, z0, z1, top, size, inset):
    """Four square legs from the floor up to height `top` under the rectangle
    [x0,x1] x [z0,z1], inset from its edges; no bottom (floor) and no top (underside)."""
    for lx in (x0 + inset, x1 - inset - size):
        for lz in (z0 + inset, z1 - inset - size):
            add_box(faces, m, (lx, 0.0, lz), (lx + size, top, lz + size), omit=('-y', '+y'))


def table(m):
    f = m.group('table', 'table')
    cx, cz = 3.0, 2.0
    w, d = 1.6, 0.9           # slab size in x and z
    y0, y1 = 0.70, 0.75       # slab bottom and top
    x0, x1, z0, z1 = cx - w / 2, cx + w / 2, cz - d / 2, cz + d / 2
    add_box(f, m, (x0, y0, z0), (x1, y1, z1))
    legs(f, m, x0, x1, z0, z1, y0, 0.06, 0.05)


def chair(m, name, cx, cz, back):
    """Chair centred at (cx, cz); back in '-z', '+z', '-x', '+x' is the side of the backrest."""
    f = m.group(name, 'chair')
    s = 0.45                  # seat size
    y0, y1 = 0.40, 0.45       # seat bottom and top
    x0, x1, z0, z1 = cx - s / 2, cx + s / 2, cz - s / 2, cz + s / 2
    add_box(f, m, (x0, y0, z0), (x1, y1, z1))
    legs(f, m, x0, x1, z0, z1, y0, 0.04, 0.02)
    t, ins, top = 0.04, 0.02, 0.95   # backrest thickness, inset from the seat edges, height
    if back == '-z':
        lo, hi = (x0 + ins, y1, z0 + ins), (x1 - ins, top, z0 + ins + t)
    elif back == '+z':
        lo, hi = (x0 + ins, y1, z1 - ins - t), (x1 - ins, top, z1 - ins)
    elif back == '-x':
        lo, hi = (x0 + ins, y1, z0 + ins), (x0 + ins + t, top, z1 - ins)
    else:
        lo, hi = (x1 - ins - t, y1, z0 + ins), (x1 - ins, top, z1 - ins)
    add_box(f, m, lo, hi, omit=('-y',))   # stands on the seat


# Cubes: (group/material, lo, hi, omitted faces). They are aligned with the shell tile grid,
# and the shell tiles they cover (under a cube on the floor, behind a cube on a wall) are left
# out of the shell, so no shell face is hidden and the cube's sides close the hole exactly.
CUBES = [
    # standing on the floor (no bottom face)
    ('cube_red', (4.75, 0.0, 0.5), (5.5, 0.75, 1.25), ('-y',)),
    ('cube_blue', (0.5, 0.0, 3.0), (1.0, 0.5, 3.5), ('-y',)),
    # on the floor against the back wall z = LZ (no bottom, no back face)
    ('cube_yellow', (4.75, 0.0, 3.5), (5.25, 0.5, LZ), ('-y', '+z')),
    # attached to the walls, floating (no face against the wall)
    ('cube_green', (0.0, 1.5, 2.5), (0.5, 2.0, 3.0), ('-x',)),
    ('cube_teal', (5.5, 1.5, 1.75), (LX, 2.0, 2.25), ('+x',)),
]


def covered_tiles():
    """Shell tiles covered by a cube: set of (plane, a, b) with plane in 'floor', 'x0', 'x1',
    'z0', 'z1' and (a, b) the tile indices in the plane's two directions."""
    out = set()
    for name, lo, hi, omit in CUBES:
        for c in range(3):
            assert abs(lo[c] / TILE - round(lo[c] / TILE)) < 1e-9, name
            assert abs(hi[c] / TILE - round(hi[c] / TILE)) < 1e-9, name
        i0, j0, k0 = (int(round(c / TILE)) for c in lo)
        i1, j1, k1 = (int(round(c / TILE)) for c in hi)
        for side, plane, r0, r1 in (('-y', 'floor', range(i0, i1), range(k0, k1)),
                                    ('-x', 'x0', range(k0, k1), range(j0, j1)),
                                    ('+x', 'x1', range(k0, k1), range(j0, j1)),
                                    ('-z', 'z0', range(i0, i1), range(j0, j1)),
                                    ('+z', 'z1', range(i0, i1), range(j0, j1))):
            if side in omit:
                out.update((plane, a, b) for a in r0 for b in r1)
    return out


def cubes(m):
    for name, lo, hi, omit in CUBES:
        add_box(m.group(name, name), m, lo, hi, omit=omit)


def check_boxes():
    """Boxes must not overlap each other (touching is fine) and must stay inside the room."""
    e = 1e-9
    for a, (lo, hi) in enumerate(BOXES):
        for c in range(3):
            assert -e <= lo[c] < hi[c] <= (LX, LY, LZ)[c] + e, (lo, hi)
        for lo2, hi2 in BOXES[a + 1:]:
            overlap = all(min(hi[c], hi2[c]) - max(lo[c], lo2[c]) > e for c in range(3))
            assert not overlap, ('boxes intersect', (lo, hi), (lo2, hi2))


def main():
    m = Mesh()
    shell(m)
    table(m)
    # one chair on each side of the table, backrest away from the table
    chair(m, 'chair_front', 3.0, 1.175, '-z')
    chair(m, 'chair_back', 3.0, 2.825, '+z')
    chair(m, 'chair_left', 1.925, 2.0, '-x')
    chair(m, 'chair_right', 4.075, 2.0, '+x')
    cubes(m)
    check_boxes()

    lines = ['# cube-room: a 6 x 3 x 4 m room (x, y up, z) with a table, four chairs and cubes.',
             '# Generated by generate.py (deterministic); do not edit by hand.',
             '# Shell: conforming %g m tiles facing inward; lights are ceiling tiles facing down.'
             % TILE,
             '# Furniture: axis-aligned boxes facing outward, no face where a box touches'
             ' another surface.',
             'mtllib cube-room.mtl', '']
    lines += ['v %s %s %s' % tuple(fmt(c) for c in p) for p in m.verts]
    for name, mtl, faces in m.groups:
        lines += ['', 'g ' + name, 'usemtl ' + mtl]
        lines += ['f ' + ' '.join(str(i) for i in f) for f in faces]
    with open(os.path.join(HERE, 'cube-room.obj'), 'w') as fh:
        fh.write('\n'.join(lines) + '\n')

    mtl = ['# cube-room materials. Kd = diffuse reflectance, Ke = emitted radiance '
           '(W sr^-1 m^-2), E = pi * Ke.', '# Generated by generate.py.']
    for name, kd, ke, comment in MATERIALS:
        mtl += ['', '# ' + comment, 'newmtl ' + name, 'Kd %s %s %s' % tuple(fmt(c) for c in kd),
                'Ke %s %s %s' % tuple(fmt(c) for c in (ke or (0, 0, 0)))]
    with open(os.path.join(HERE, 'cube-room.mtl'), 'w') as fh:
        fh.write('\n'.join(mtl) + '\n')

    n_light = sum(len(g[2]) for g in m.groups if g[1] == 'light')
    print('cube-room: %d faces (%d light tiles), %d vertices'
          % (m.face_count(), n_light, len(m.verts)))


if __name__ == '__main__':
    main()
