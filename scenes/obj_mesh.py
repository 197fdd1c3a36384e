# SPDX-License-Identifier: Apache-2.0
"""What the scene generators share (standard library only): numbers as OBJ writes them, a
mesh of vertices shared by position with faces in named groups, and the quads of a box.

A generator in scenes/NAME/ imports it with its parent folder on the path:

    sys.path.insert(0, os.path.dirname(HERE))
    from obj_mesh import Mesh, box_quads, fmt
"""


def fmt(x):
    """A coordinate with at most 6 decimals and no trailing zeros ('0', never '-0')."""
    s = ('%.6f' % x).rstrip('0').rstrip('.')
    return '0' if s in ('', '-0') else s


class Mesh:
    """Vertices shared by position (to 1e-6), faces as 1-based vertex lists in groups."""

    def __init__(self):
        self.verts = []
        self.vid = {}
        self.groups = []  # (name, material, [faces])

    def v(self, p):
        key = tuple(round(c, 6) for c in p)
        if key not in self.vid:
            self.verts.append(key)
            self.vid[key] = len(self.verts)
        return self.vid[key]

    def group(self, name, mtl):
        self.groups.append((name, mtl, []))
        return self.groups[-1][2]

    def face_count(self):
        return sum(len(g[2]) for g in self.groups)

    def box(self, faces, lo, hi, omit=()):
        """Appends box_quads(lo, hi, omit) to faces."""
        faces.extend([self.v(p) for p in q] for q in box_quads(lo, hi, omit))


def box_quads(lo, hi, omit=()):
    """The faces of the axis-aligned box [lo, hi] with outward normals, each 4 corners
    counter-clockwise seen from outside, in the order -y, +y, -x, +x, -z, +z; omit: the sides
    ('-x', ..., '+z') that touch another surface."""
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    quads = {
        '-x': [(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)],
        '+x': [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)],
        '-y': [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)],
        '+y': [(x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)],
        '-z': [(x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)],
        '+z': [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)],
    }
    return [quads[side] for side in ('-y', '+y', '-x', '+x', '-z', '+z') if side not in omit]
