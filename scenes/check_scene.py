#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Check a Wavefront OBJ + MTL scene against the hmcr scene conventions (docs/design.md §1).

An author's aid, not the authority: hmcr's own loader decides validity (some tolerances here
differ from it). What this adds: T-junctions, orientation by rays, --room.

Standard library only.  Usage:

    /usr/bin/python3 scenes/check_scene.py SCENE.obj [--room] [--closed]

Checks (each reported as a count; any error makes the exit status 1):
  * every face has 3 or 4 vertices (no polygon with more than 4 vertices)
  * no zero-area / degenerate face (area <= 1e-12 * bbox diagonal^2, or a repeated vertex)
  * every quad is planar (max distance of a vertex from the Newell plane
    <= 1e-4 * the quad's longest diagonal) and strictly convex
  * no duplicate faces (same vertex positions, any order or orientation)
  * every face has a material (usemtl) that the MTL file defines
  * every Kd channel in [0, 1), every Ke channel >= 0, at least one emitting face
  * no NaN/Inf coordinates
  * no T-junction between coplanar neighbouring faces (a vertex of one face lying strictly
    inside an edge of a coplanar face)
  * orientation by rays: from the centroid of every face, offset along its normal, a ray along
    the normal must not hit a back face first (a back-face hit means a flipped normal or
    geometry leaking into a closed object).  With --closed it must also hit something.
  * --room: every shell face (a face whose normal is within ~25 degrees of a bounding-box axis
    and whose centroid lies within 2% of the bbox diagonal of the corresponding bbox side)
    must face the inside: normal . (bbox centre - face centroid) > 0.
"""

import math
import os
import sys


# ----------------------------------------------------------------------------- vector helpers
def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def mul(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(dot(a, a))


def newell(pts):
    n = [0.0, 0.0, 0.0]
    for i, p in enumerate(pts):
        q = pts[(i + 1) % len(pts)]
        n[0] += (p[1] - q[1]) * (p[2] + q[2])
        n[1] += (p[2] - q[2]) * (p[0] + q[0])
        n[2] += (p[0] - q[0]) * (p[1] + q[1])
    return tuple(n)  # length = 2 * area for a planar polygon


# ----------------------------------------------------------------------------- parsing
def parse_mtl(path, errors):
    mats = {}
    cur = None
    with open(path) as f:
        for ln, line in enumerate(f, 1):
            t = line.split('#', 1)[0].split()
            if not t:
                continue
            if t[0] == 'newmtl':
                cur = t[1]
                if cur in mats:
                    errors.append('%s:%d: material %s defined twice' % (path, ln, cur))
                mats[cur] = {'Kd': (0.0, 0.0, 0.0), 'Ke': (0.0, 0.0, 0.0), 'line': ln}
            elif t[0] in ('Kd', 'Ke') and cur is not None:
                vals = [float(x) for x in t[1:4]]
                if len(vals) == 1:
                    vals = vals * 3
                mats[cur][t[0]] = tuple(vals)
    return mats


def parse_obj(path, errors):
    verts, faces, mtllibs = [], [], []
    cur = None
    with open(path) as f:
        for ln, line in enumerate(f, 1):
            t = line.split('#', 1)[0].split()
            if not t:
                continue
            if t[0] == 'v':
                p = tuple(float(x) for x in t[1:4])
                if not all(math.isfinite(c) for c in p):
                    errors.append('%s:%d: non-finite vertex' % (path, ln))
                verts.append(p)
            elif t[0] == 'f':
                idx = []
                for tok in t[1:]:
                    i = int(tok.split('/')[0])
                    idx.append(i - 1 if i > 0 else len(verts) + i)
                faces.append({'idx': idx, 'mtl': cur, 'line': ln})
            elif t[0] == 'usemtl':
                cur = t[1] if len(t) > 1 else None
            elif t[0] == 'mtllib':
                mtllibs.append(' '.join(t[1:]))
    return verts, faces, mtllibs


# ----------------------------------------------------------------------------- ray casting
def ray_polygon(o, d, pts, n_unit):
    """Distance t>0 along the ray to the planar convex polygon, or None."""
    den = dot(d, n_unit)
    if abs(den) < 1e-12:
        return None
    t = dot(sub(pts[0], o), n_unit) / den
    if t <= 0:
        return None
    x = add(o, mul(d, t))
    k = len(pts)
    for i in range(k):
        e = sub(pts[(i + 1) % k], pts[i])
        if dot(cross(e, sub(x, pts[i])), n_unit) < -1e-12:
            return None
    return t


def main(argv):
    args = [a for a in argv[1:] if not a.startswith('--')]
    flags = [a for a in argv[1:] if a.startswith('--')]
    if len(args) != 1:
        print(__doc__)
        return 2
    room = '--room' in flags
    closed = '--closed' in flags
    obj = args[0]
    errors = []
    verts, faces, mtllibs = parse_obj(obj, errors)
    mats = {}
    for lib in mtllibs:
        mats.update(parse_mtl(os.path.join(os.path.dirname(obj), lib), errors))
    if not mtllibs:
        errors.append('no mtllib')

    lo = tuple(min(v[i] for v in verts) for i in range(3))
    hi = tuple(max(v[i] for v in verts) for i in range(3))
    diag = norm(sub(hi, lo))
    centre = mul(add(lo, hi), 0.5)

    counts = {'triangles': 0, 'quads': 0, 'more_than_4': 0, 'zero_area': 0, 'non_planar': 0,
              'non_convex': 0, 'duplicates': 0, 'no_material': 0, 'unknown_material': 0,
              'emitting_faces': 0, 't_junctions': 0, 'back_face_hits': 0, 'escaped_rays': 0,
              'shell_faces': 0, 'shell_facing_out': 0}
    info = []  # per face: (pts, unit normal, centroid, area)
    seen = {}
    total_area = 0.0
    emitted_area = 0.0
    for fi, f in enumerate(faces):
        where = '%s:%d' % (obj, f['line'])
        idx = f['idx']
        pts = [verts[i] for i in idx]
        n = len(idx)
        if n == 3:
            counts['triangles'] += 1
        elif n == 4:
            counts['quads'] += 1
        else:
            counts['more_than_4'] += 1
            errors.append('%s: face with %d vertices' % (where, n))
        nv = newell(pts)
        area = 0.5 * norm(nv)
        if area <= 1e-12 * diag * diag or len(set(idx)) != n or len(set(pts)) != n:
            counts['zero_area'] += 1
            errors.append('%s: zero-area or degenerate face' % where)
            info.append(None)
            continue
        nu = mul(nv, 0.5 / area)
        c = mul(pts[0], 0.0)
        for p in pts:
            c = add(c, p)
        c = mul(c, 1.0 / n)
        total_area += area
        if n == 4:
            dmax = max(norm(sub(pts[2], pts[0])), norm(sub(pts[3], pts[1])))
            dev = max(abs(dot(sub(p, c), nu)) for p in pts)
            if dev > 1e-4 * dmax:
                counts['non_planar'] += 1
                errors.append('%s: non-planar quad (%.3g off, diagonal %.3g)' % (where, dev, dmax))
            for i in range(4):
                e0 = sub(pts[(i + 1) % 4], pts[i])
                e1 = sub(pts[(i + 2) % 4], pts[(i + 1) % 4])
                if dot(cross(e0, e1), nu) <= 1e-12 * dmax * dmax:
                    counts['non_convex'] += 1
                    errors.append('%s: non-convex quad' % where)
                    break
        key = tuple(sorted(tuple(round(x, 9) for x in p) for p in pts))
        if key in seen:
            counts['duplicates'] += 1
            errors.append('%s: duplicate of face at line %d' % (where, seen[key]))
        else:
            seen[key] = f['line']
        m = f['mtl']
        if m is None:
            counts['no_material'] += 1
            errors.append('%s: face without material' % where)
        elif m not in mats:
            counts['unknown_material'] += 1
            errors.append('%s: unknown material %s' % (where, m))
        elif max(mats[m]['Ke']) > 0:
            counts['emitting_faces'] += 1
            emitted_area += area
        info.append((pts, nu, c, area))

    for name, m in mats.items():
        if not all(0.0 <= k < 1.0 for k in m['Kd']):
            errors.append('material %s: Kd %s outside [0, 1)' % (name, m['Kd']))
        if not all(k >= 0.0 for k in m['Ke']):
            errors.append('material %s: negative Ke %s' % (name, m['Ke']))
    if counts['emitting_faces'] == 0:
        errors.append('no emitter')

    # ------------------------------------------------------------------ T-junctions per plane
    planes = {}
    for fi, it in enumerate(info):
        if it is None:
            continue
        pts, nu, c, area = it
        d = dot(nu, c)
        key = (round(nu[0], 4), round(nu[1], 4), round(nu[2], 4), round(d / diag, 5))
        planes.setdefault(key, []).append(fi)
    tol = 1e-7 * diag
    for key, fis in planes.items():
        # vertices of the plane (by position) and edges
        vset = {}
        edges = []
        for fi in fis:
            pts = info[fi][0]
            for i, p in enumerate(pts):
                vset[p] = faces[fi]['line']
                edges.append((p, pts[(i + 1) % len(pts)], faces[fi]['line']))
        # grid bucketing would be faster; the scenes are small enough for a plain loop per edge
        vlist = list(vset.items())
        for a, b, line in edges:
            ab = sub(b, a)
            L2 = dot(ab, ab)
            mn = tuple(min(a[i], b[i]) - tol for i in range(3))
            mx = tuple(max(a[i], b[i]) + tol for i in range(3))
            for p, pline in vlist:
                if not (mn[0] <= p[0] <= mx[0] and mn[1] <= p[1] <= mx[1] and mn[2] <= p[2] <= mx[2]):
                    continue
                if p == a or p == b:
                    continue
                s = dot(sub(p, a), ab) / L2
                if s <= 1e-9 or s >= 1 - 1e-9:
                    continue
                off = sub(sub(p, a), mul(ab, s))
                if norm(off) < tol:
                    counts['t_junctions'] += 1
                    errors.append('%s:%d: vertex %s of face at line %d lies inside this edge '
                                  '(T-junction)' % (obj, line, p, pline))

    # ------------------------------------------------------------------ orientation by rays
    valid = [i for i, it in enumerate(info) if it is not None]
    boxes = {}
    for i in valid:
        pts = info[i][0]
        boxes[i] = (tuple(min(p[k] for p in pts) for k in range(3)),
                    tuple(max(p[k] for p in pts) for k in range(3)))
    eps = 1e-6 * diag
    for i in valid:
        pts, nu, c, area = info[i]
        o = add(c, mul(nu, eps))
        best, best_j = None, None
        for j in valid:
            if j == i:
                continue
            bl, bh = boxes[j]
            # slab test against the face's bounding box
            t0, t1, ok = 0.0, float('inf'), True
            for k in range(3):
                if abs(nu[k]) < 1e-15:
                    if o[k] < bl[k] - eps or o[k] > bh[k] + eps:
                        ok = False
                        break
                else:
                    ta = (bl[k] - eps - o[k]) / nu[k]
                    tb = (bh[k] + eps - o[k]) / nu[k]
                    if ta > tb:
                        ta, tb = tb, ta
                    t0, t1 = max(t0, ta), min(t1, tb)
                    if t0 > t1:
                        ok = False
                        break
            if not ok or (best is not None and t0 > best):
                continue
            t = ray_polygon(o, nu, info[j][0], info[j][1])
            if t is not None and (best is None or t < best):
                best, best_j = t, j
        if best is None:
            if closed:
                counts['escaped_rays'] += 1
                errors.append('%s:%d: ray along the normal escapes the closed scene'
                              % (obj, faces[i]['line']))
        elif dot(nu, info[best_j][1]) > 0:
            counts['back_face_hits'] += 1
            errors.append('%s:%d: ray along the normal hits the back of the face at line %d'
                          % (obj, faces[i]['line'], faces[best_j]['line']))

    # ------------------------------------------------------------------ room shell
    if room:
        margin = 0.02 * diag
        for i in valid:
            pts, nu, c, area = info[i]
            for k in range(3):
                if abs(nu[k]) < 0.9:
                    continue
                if abs(c[k] - lo[k]) < margin or abs(c[k] - hi[k]) < margin:
                    counts['shell_faces'] += 1
                    if dot(nu, sub(centre, c)) <= 0:
                        counts['shell_facing_out'] += 1
                        errors.append('%s:%d: shell face faces outward'
                                      % (obj, faces[i]['line']))
        if counts['shell_faces'] == 0:
            errors.append('--room given but no shell faces found')

    print('%s: %d vertices, %d faces (%d triangles, %d quads), %d materials'
          % (obj, len(verts), len(faces), counts['triangles'], counts['quads'], len(mats)))
    print('  bbox %s .. %s, total area %.6g m^2, emitting area %.6g m^2'
          % (tuple(round(x, 6) for x in lo), tuple(round(x, 6) for x in hi), total_area,
             emitted_area))
    for k in ('more_than_4', 'zero_area', 'non_planar', 'non_convex', 'duplicates',
              'no_material', 'unknown_material', 'emitting_faces', 't_junctions',
              'back_face_hits', 'escaped_rays', 'shell_faces', 'shell_facing_out'):
        print('  %-18s %d' % (k, counts[k]))
    for e in errors[:50]:
        print('  ERROR: ' + e)
    if len(errors) > 50:
        print('  ... %d more errors' % (len(errors) - 50))
    print('  %s' % ('OK' if not errors else 'FAILED (%d errors)' % len(errors)))
    return 0 if not errors else 1


if __name__ == '__main__':
    sys.exit(main(sys.argv))
