# SPDX-License-Identifier: Apache-2.0
"""rpkCpp's final leaf elements, written by a few lines added to a copy of rpkCpp, read back and
turned into a foreign solution that `hmcr error --foreign` measures (docs/design.md §11.4).

rpkCpp writes no mesh of its own (its VRML writer is empty), so `add_leaf_writer` inserts into
a copy of its source, in src/app/batch.cpp, a function of this project's (`LEAF_WRITER`) that
runs after the last iteration and writes, when the environment names a file in
`HMCR_RPK_LEAVES`, one line a vertex and one a leaf of every patch's quadtree:

    rpk-leaves 1
    v ID X Y Z                       a vertex, before the first leaf naming it
    l PATCH LEVEL N C1..CN M1..MN AREA  RAD(3) SRC(3) ED(3)

PATCH is the patch's index in rpkCpp's patch list, LEVEL the leaf's depth below it, C the
corners, M the vertex in the middle of each edge where the neighbour across it is subdivided
(-1 where none: rpkCpp's T-vertices), AREA rpkCpp's area; RAD the leaf's radiance (its
`radiance[0]`, self-emission included), SRC its self-emitted radiance (`sourceRad`) and ED its
`Ed`, all W sr^-1 m^-2 per channel of rpkCpp's RGB.

Units, as rpkCpp's source has them: a patch's Ed is its emittance over pi, a radiance; the
radiosity is pi times the radiance (its total flux is the sum of pi A radiance). A sub-element's
Ed is sampled from the emittance again and is not divided by pi, so it is pi times its parent's;
rpkCpp reads no sub-element's Ed in the solve (the pushed `sourceRad` carries the emission), and
neither does this reader: B = pi RAD, E = pi SRC. `check_units` reports both.

Two solutions are made from one file:
- constant: every leaf a polygon of its own corners at its B;
- Gouraud: rpkCpp's own display of the same leaves (render.cpp with its defaults, smooth
  shading and T-vertex elimination on): a vertex's value is the mean B of the leaves with a
  corner there, a T-vertex's is then averaged with the B of the coarser leaf it lies on, and a
  leaf with T-vertices is cut into rpkCpp's triangles and quadrilaterals through them.

Each leaf's scene patch (for `PatchId`) is the face of hmcr's scene that holds its centroid, on
the face's plane and on its front (one-sided faces).

`add_noise_hooks` inserts, for renderpark_compare.py's noise mode, a few more lines of this
project's into the copy's stochjacobi.cpp (NOISE_EDITS): -srr-sampling-sequence honoured by the
stochastic Jacobi's sample points, drand48 seeded from $HMCR_RPK_SEED, and double sums of the
received radiance with $HMCR_RPK_DOUBLE. Standard library only.
"""

import math
import os

LEAF_FILE_VERSION = "rpk-leaves 1"
LEAF_FILE_VARIABLE = "HMCR_RPK_LEAVES"

# The code inserted into the copy of rpkCpp's src/app/batch.cpp: the includes after its last
# include, the writer after the includes, the call before the batch run's last message.
LEAF_WRITER_INCLUDES = """
#include <cstdlib>
#include <map>
#include "raycasting/stochasticRaytracing/mcradP.h"
"""

LEAF_WRITER = r"""
// Inserted by hmcr's scripts/renderpark_compare.py (not part of rpkCpp): writes the final
// leaves of the stochastic radiosity hierarchy to the file named by $HMCR_RPK_LEAVES.
static int
hmcrVertexId(FILE *file, std::map<const Vertex *, int> *ids, const Vertex *vertex) {
    if ( vertex == nullptr ) {
        return -1;
    }
    std::map<const Vertex *, int>::const_iterator found = ids->find(vertex);
    if ( found != ids->end() ) {
        return found->second;
    }
    const int id = (int)ids->size();
    (*ids)[vertex] = id;
    fprintf(file, "v %d %.9g %.9g %.9g\n", id, vertex->point->x, vertex->point->y,
            vertex->point->z);
    return id;
}

static void
hmcrWriteLeaves(FILE *file, std::map<const Vertex *, int> *ids,
                const StochasticRadiosityElement *element, int patch, int level) {
    if ( element->regularSubElements != nullptr ) {
        for ( int k = 0; k < 4; k++ ) {
            hmcrWriteLeaves(file, ids,
                            (const StochasticRadiosityElement *)element->regularSubElements[k],
                            patch, level + 1);
        }
        return;
    }
    const int n = element->numberOfVertices;
    int corner[4];
    int middle[4];
    for ( int k = 0; k < n; k++ ) {
        corner[k] = hmcrVertexId(file, ids, element->vertices[k]);
        middle[k] = hmcrVertexId(file, ids,
                                 stochasticRadiosityElementEdgeMidpointVertex(element, k));
    }
    fprintf(file, "l %d %d %d", patch, level, n);
    for ( int k = 0; k < n; k++ ) {
        fprintf(file, " %d", corner[k]);
    }
    for ( int k = 0; k < n; k++ ) {
        fprintf(file, " %d", middle[k]);
    }
    fprintf(file, " %.9g", element->area);
    const ColorRgb *colours[3] = {&element->radiance[0], &element->sourceRad, &element->Ed};
    for ( int k = 0; k < 3; k++ ) {
        fprintf(file, " %.9g %.9g %.9g", colours[k]->r, colours[k]->g, colours[k]->b);
    }
    fprintf(file, "\n");
}

static void
hmcrWriteLeafFile(const Scene *scene) {
    const char *name = getenv("HMCR_RPK_LEAVES");
    if ( name == nullptr || scene->patchList == nullptr ) {
        return;
    }
    FILE *file = fopen(name, "w");
    if ( file == nullptr ) {
        fprintf(stderr, "cannot write the leaves to %s\n", name);
        exit(2);
    }
    fprintf(file, "rpk-leaves 1\n");
    std::map<const Vertex *, int> ids;
    for ( int i = 0; i < scene->patchList->size(); i++ ) {
        const Element *top = scene->patchList->get(i)->radianceData;
        if ( top == nullptr || top->className != ElementTypes::ELEMENT_STOCHASTIC_RADIOSITY ||
             ((const StochasticRadiosityElement *)top)->basis->size != 1 ) {
            fprintf(stderr, "%s: patch %d has no constant stochastic radiosity element\n", name, i);
            exit(2);
        }
        hmcrWriteLeaves(file, &ids, (const StochasticRadiosityElement *)top, i, 0);
    }
    fclose(file);
}
"""

LEAF_WRITER_CALL = "    hmcrWriteLeafFile(scene);\n"
BATCH_FILE = os.path.join("src", "app", "batch.cpp")
BATCH_ANCHOR = '    printf("Computations finished.\\n");'


def add_leaf_writer(source_dir):
    """Inserts the leaf writer into the copy of rpkCpp in source_dir (its src/app/batch.cpp)."""
    path = os.path.join(source_dir, BATCH_FILE)
    with open(path) as f:
        text = f.read()
    last_include = text.rfind("\n#include ")
    if last_include < 0 or text.count(BATCH_ANCHOR) != 1:
        raise ValueError(f"{path}: not the batch.cpp this script knows (no includes, or not one "
                         f"'{BATCH_ANCHOR.strip()}')")
    end = text.index("\n", last_include + 1) + 1
    text = text[:end] + LEAF_WRITER_INCLUDES + LEAF_WRITER + text[end:]
    text = text.replace(BATCH_ANCHOR, LEAF_WRITER_CALL + BATCH_ANCHOR)
    with open(path, "w") as f:
        f.write(text)


# The code inserted into the copy of rpkCpp's src/raycasting/stochasticRaytracing/stochjacobi.cpp
# for the noise mode (renderpark_compare.py --noise), each piece before or after an anchor line of
# that file (NOISE_EDITS): the stochastic Jacobi draws its sample points from
# NextNiedInRange whatever -srr-sampling-sequence says, so the inserted lines honour that option
# (another sequence is drawn by rpkCpp's sample4D, PseudoRandom by drand48); $HMCR_RPK_SEED seeds
# drand48 before the first iteration; with $HMCR_RPK_DOUBLE set, the radiance a surface receives
# in one iteration is summed in double and rounded once into rpkCpp's float accumulator.
SEED_VARIABLE = "HMCR_RPK_SEED"
DOUBLE_VARIABLE = "HMCR_RPK_DOUBLE"
JACOBI_FILE = os.path.join("src", "raycasting", "stochasticRaytracing", "stochjacobi.cpp")

NOISE_HOOKS = r"""
// Inserted by hmcr's scripts/renderpark_compare.py (not part of rpkCpp), for its noise mode:
// the -srr-sampling-sequence option for the sample points, $HMCR_RPK_SEED for drand48, and
// double sums of the received radiance with $HMCR_RPK_DOUBLE.
#include <cstdlib>
#include <unordered_map>
#include "raycasting/stochasticRaytracing/sample4d.h"

static bool
hmcrOtherSequence(const StochasticRadiosityElement *elem, NiederreiterIndex *rayIndex,
                  double *zeta) {
    if ( GLOBAL_stochasticRaytracing_monteCarloRadiosityState.sequence ==
         Sampler4DSequence::NIEDERREITER ) {
        return false;
    }
    const double *xi = sample4D((unsigned)*rayIndex);
    (*rayIndex)++;
    for ( int k = 0; k < 4; k++ ) {
        zeta[k] = xi[k];
    }
    if ( elem->numberOfVertices == 3 ) {
        foldSampleF(&zeta[0], &zeta[1]);
    }
    return true;
}

static void
hmcrSeedOnce() {
    static bool done = false;
    if ( !done ) {
        done = true;
        const char *seed = getenv("HMCR_RPK_SEED");
        if ( seed != nullptr ) {
            srand48(atol(seed));
        }
    }
}

struct HmcrSum {
    double c[3];
};

static std::unordered_map<const StochasticRadiosityElement *, HmcrSum> hmcrSums;

static bool
hmcrDoubleSums() {
    static const bool on = getenv("HMCR_RPK_DOUBLE") != nullptr;
    return on;
}

static bool
hmcrAddDouble(const StochasticRadiosityElement *rcv, int i, double w, const ColorRgb &power) {
    if ( !hmcrDoubleSums() ) {
        return false;
    }
    if ( i != 0 || rcv->basis->size != 1 ) {
        fprintf(stderr, "HMCR_RPK_DOUBLE: for the constant basis only\n");
        exit(2);
    }
    HmcrSum &sum = hmcrSums[rcv];
    sum.c[0] += w * power.r;
    sum.c[1] += w * power.g;
    sum.c[2] += w * power.b;
    return true;
}

static void
hmcrFlushDouble(StochasticRadiosityElement *elem) {
    if ( !hmcrDoubleSums() ) {
        return;
    }
    std::unordered_map<const StochasticRadiosityElement *, HmcrSum>::iterator found =
        hmcrSums.find(elem);
    if ( found == hmcrSums.end() ) {
        return;
    }
    ColorRgb &received = elem->receivedRadiance[0];
    received.r = (float)((double)received.r + found->second.c[0]);
    received.g = (float)((double)received.g + found->second.c[1]);
    received.b = (float)((double)received.b + found->second.c[2]);
    hmcrSums.erase(found);
}
"""

# (anchor, text, where): the anchor must be in stochjacobi.cpp once; the text goes before or
# after its line.
NOISE_EDITS = [
    ('#include "raycasting/stochasticRaytracing/StochasticRelaxation.h"\n', NOISE_HOOKS,
     "after"),
    ("    globalNumberOfRays = numberOfRays;\n", "    hmcrSeedOnce();\n", "after"),
    ("    globalSumOfProbabilities = 0.0;\n    stochasticJacobiElementSetup(",
     "    hmcrSums.clear();\n", "before"),
    ("    xi = NextNiedInRange(ray_index, +1, nMostSignificantBit, mostSignificantBit1, "
     "rMostSignificantBit2);\n",
     "    if ( hmcrOtherSequence(elem, ray_index, zeta) ) {\n        return zeta;\n    }\n",
     "before"),
    ("        rcv->receivedRadiance[i].addScaled(rcv->receivedRadiance[i], (float) w, rayPower);\n",
     "        if ( hmcrAddDouble(rcv, i, w, rayPower) ) {\n            continue;\n        }\n",
     "before"),
    ("stochasticJacobiUpdateElement(StochasticRadiosityElement *elem) {\n"
     "    if ( globalGetRadianceCallback ) {\n", "        hmcrFlushDouble(elem);\n", "after"),
]


def insert_at_anchors(text, edits, path):
    """text with every edit's lines put before or after its anchor; a ValueError unless each
    anchor is there exactly once."""
    for anchor, lines, where in edits:
        if text.count(anchor) != 1:
            raise ValueError(f"{path}: not the file this script knows ('{anchor.strip()[:60]}' "
                             f"is there {text.count(anchor)} times, not once)")
        text = text.replace(anchor, lines + anchor if where == "before" else anchor + lines)
    return text


def add_noise_hooks(source_dir):
    """Inserts the noise mode's hooks into the copy of rpkCpp in source_dir."""
    path = os.path.join(source_dir, JACOBI_FILE)
    with open(path) as f:
        text = f.read()
    text = insert_at_anchors(text, NOISE_EDITS, path)
    with open(path, "w") as f:
        f.write(text)


# ---------------------------------------------------------------- reading the leaf file


class Leaves:
    """The vertices (id -> (x, y, z)) and leaves of one leaf file, in the file's order."""

    def __init__(self):
        self.vertices = {}
        self.leaves = []  # dicts: patch, level, corners, middles, area, rad, src, ed


def _bad(path, line, what):
    return ValueError(f"{path}:{line}: {what}")


def _finite(path, line, words):
    try:
        values = [float(w) for w in words]
    except ValueError:
        raise _bad(path, line, f"'{' '.join(words)}' is not a list of numbers") from None
    if not all(math.isfinite(v) for v in values):
        raise _bad(path, line, "a value is not finite")
    return values


def _integers(path, line, words):
    try:
        return [int(w) for w in words]
    except ValueError:
        raise _bad(path, line, f"'{' '.join(words)}' is not a list of vertex ids") from None


def _leaf(path, line, words, vertices):
    try:
        patch, level, n = int(words[1]), int(words[2]), int(words[3])
    except (ValueError, IndexError):
        raise _bad(path, line, "a leaf line starts 'l PATCH LEVEL N'") from None
    if n not in (3, 4) or patch < 0 or level < 0:
        raise _bad(path, line, f"patch {patch}, level {level}, {n} corners: not a leaf")
    if len(words) != 4 + 2 * n + 10:
        raise _bad(path, line, f"a leaf of {n} corners has {4 + 2 * n + 10} words, not "
                   f"{len(words)}")
    ids = _integers(path, line, words[4:4 + 2 * n])
    for k, v in enumerate(ids):
        if (v < 0 and k < n) or (v >= 0 and v not in vertices):
            raise _bad(path, line, f"vertex {v} is not defined above")
    values = _finite(path, line, words[4 + 2 * n:])
    if values[0] <= 0 or any(v < 0 for v in values[1:7]):
        raise _bad(path, line, "a negative area or radiance")
    return {"patch": patch, "level": level, "corners": ids[:n], "middles": ids[n:],
            "area": values[0], "rad": values[1:4], "src": values[4:7], "ed": values[7:10]}


def read_leaves(path):
    """The leaf file; a ValueError naming file:line for anything else."""
    out = Leaves()
    with open(path) as f:
        first = f.readline().strip()
        if first != LEAF_FILE_VERSION:
            raise _bad(path, 1, f"'{first[:40]}' is not '{LEAF_FILE_VERSION}'")
        for line, text in enumerate(f, start=2):
            words = text.split()
            if not words:
                continue
            if words[0] == "v" and len(words) == 5:
                out.vertices[_integers(path, line, words[1:2])[0]] = tuple(
                    _finite(path, line, words[2:]))
            elif words[0] == "l":
                out.leaves.append(_leaf(path, line, words, out.vertices))
            else:
                raise _bad(path, line, f"'{words[0]}' with {len(words)} words is not a vertex "
                           "or a leaf line")
    if not out.leaves:
        raise _bad(path, 1, "holds no leaves")
    return out


# ---------------------------------------------------------------- geometry


def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def newell(points):
    """Twice the vector area of a polygon (Newell's normal)."""
    n = [0.0, 0.0, 0.0]
    for i, p in enumerate(points):
        q = points[(i + 1) % len(points)]
        n[0] += (p[1] - q[1]) * (p[2] + q[2])
        n[1] += (p[2] - q[2]) * (p[0] + q[0])
        n[2] += (p[0] - q[0]) * (p[1] + q[1])
    return tuple(n)


def polygon_area(points):
    return 0.5 * math.sqrt(_dot(newell(points), newell(points)))


def centroid(points):
    return tuple(sum(p[k] for p in points) / len(points) for k in range(3))


def _unit(v):
    length = math.sqrt(_dot(v, v))
    return tuple(c / length for c in v)


def _inside(point, polygon, normal):
    """Whether point (on the polygon's plane) lies in the polygon: a crossing count in the
    plane of the two axes the normal leans on least."""
    drop = max(range(3), key=lambda k: abs(normal[k]))
    u, v = [k for k in range(3) if k != drop]
    x, y, inside = point[u], point[v], False
    for i, p in enumerate(polygon):
        q = polygon[i - 1]
        if (p[v] > y) != (q[v] > y):
            if x < p[u] + (y - p[v]) * (q[u] - p[u]) / (q[v] - p[v]):
                inside = not inside
    return inside


class FaceFinder:
    """The scene face holding a point, on the face's plane and its front."""

    def __init__(self, faces):
        """faces: each a list of (x, y, z) corners, in hmcr's patch order."""
        self.faces = [list(f) for f in faces]
        self.normals = [_unit(newell(f)) for f in self.faces]
        lo = [min(p[k] for f in self.faces for p in f) for k in range(3)]
        hi = [max(p[k] for f in self.faces for p in f) for k in range(3)]
        self.tolerance = 1e-3 * math.sqrt(_dot(_sub(hi, lo), _sub(hi, lo)))  # off the plane
        self.last = {}  # rpkCpp patch -> the face its previous leaf was found in

    def _holds(self, f, point, normal):
        n = self.normals[f]
        return (_dot(n, normal) > 0.99
                and abs(_dot(n, _sub(point, self.faces[f][0]))) < self.tolerance
                and _inside(point, self.faces[f], n))

    def find(self, point, normal, patch):
        """The index of the face holding point (normal: the leaf's unit normal), or None."""
        f = self.last.get(patch)
        if f is not None and self._holds(f, point, normal):
            return f
        best = None
        for f, n in enumerate(self.normals):
            if self._holds(f, point, normal):
                d = abs(_dot(n, _sub(point, self.faces[f][0])))
                if best is None or d < best[0]:
                    best = (d, f)
        if best is not None:
            self.last[patch] = best[1]
        return None if best is None else best[1]


# ---------------------------------------------------------------- the two solutions


def leaf_radiosity(leaf):
    """B = pi times the leaf's radiance, W/m^2."""
    return [math.pi * c for c in leaf["rad"]]


def vertex_radiosity(leaves):
    """rpkCpp's Gouraud vertex values: the mean B of the leaves with a corner at the vertex,
    a T-vertex's then averaged with the B of the leaf whose edge it lies on."""
    sums, counts = {}, {}
    for leaf in leaves.leaves:
        b = leaf_radiosity(leaf)
        for v in leaf["corners"]:
            s = sums.setdefault(v, [0.0, 0.0, 0.0])
            for k in range(3):
                s[k] += b[k]
            counts[v] = counts.get(v, 0) + 1
    values = {v: [c / counts[v] for c in s] for v, s in sums.items()}
    for leaf in leaves.leaves:
        b = leaf_radiosity(leaf)
        for m in leaf["middles"]:
            if m >= 0:
                old = values.get(m, [0.0, 0.0, 0.0])
                values[m] = [(old[k] + b[k]) * 0.5 for k in range(3)]
    return values


def _triangle_pieces(v, m):
    """rpkCpp's T-vertex elimination of a triangle (render.cpp): its pieces as vertex lists."""
    t = [k for k in range(3) if m[k] >= 0]
    if not t:
        return [[v[0], v[1], v[2]]]
    if len(t) == 1:
        a = t[0]
        b, c = (a + 1) % 3, (a + 2) % 3
        return [[m[a], v[c], v[a]], [m[a], v[b], v[c]]]
    if len(t) == 2:
        a = next(k for k in range(3) if m[k] < 0)
        b, c = (a + 1) % 3, (a + 2) % 3
        return [[m[b], v[a], v[b]], [m[b], m[c], v[a]], [m[b], v[c], m[c]]]
    return [[v[0], m[0], m[2]], [v[1], m[1], m[0]], [v[2], m[2], m[1]], [m[0], m[1], m[2]]]


def _quad_pieces(v, m):
    """rpkCpp's T-vertex elimination of a quadrilateral (render.cpp)."""
    t = [k for k in range(4) if m[k] >= 0]
    if not t:
        return [[v[0], v[1], v[2], v[3]]]
    if len(t) == 1:
        a = t[0]
        b, c, d = (a + 1) % 4, (a + 2) % 4, (a + 3) % 4
        return [[m[a], v[d], v[a]], [m[a], v[c], v[d]], [m[a], v[b], v[c]]]
    if len(t) == 2:
        a = t[0]
        if m[(a + 3) % 4] >= 0:
            a = (a + 3) % 4
        b, c, d = (a + 1) % 4, (a + 2) % 4, (a + 3) % 4
        if m[b] >= 0:
            return [[m[a], v[b], m[b]], [m[b], v[c], v[d]], [v[d], m[a], m[b]],
                    [v[d], v[a], m[a]]]
        return [[v[a], m[a], m[c], v[d]], [m[a], v[b], v[c], m[c]]]
    if len(t) == 3:
        a = next(k for k in range(4) if m[k] < 0)
        b, c, d = (a + 1) % 4, (a + 2) % 4, (a + 3) % 4
        return [[v[a], v[b], m[b], m[d]], [m[b], v[c], m[c]], [m[c], v[d], m[d]],
                [m[b], m[c], m[d]]]
    return [[v[0], m[0], m[3]], [v[1], m[1], m[0]], [v[2], m[2], m[1]], [v[3], m[3], m[2]],
            [m[0], m[1], m[2], m[3]]]


def gouraud_pieces(leaf):
    """The polygons rpkCpp draws for one leaf, as vertex ids."""
    pieces = _triangle_pieces if len(leaf["corners"]) == 3 else _quad_pieces
    return pieces(leaf["corners"], leaf["middles"])


class Solution:
    """A foreign solution: points with their B, polygons (point indices) and their patches."""

    def __init__(self):
        self.points, self.radiosity, self.polygons, self.patch_ids = [], [], [], []

    def add(self, corners, values, patch):
        first = len(self.points)
        self.points += corners
        self.radiosity += values
        self.polygons.append(list(range(first, first + len(corners))))
        self.patch_ids.append(patch)


def leaf_patches(leaves, finder, path="leaves"):
    """The scene face of every leaf; a ValueError for a leaf on no face."""
    out = []
    for i, leaf in enumerate(leaves.leaves):
        corners = [leaves.vertices[v] for v in leaf["corners"]]
        face = finder.find(centroid(corners), _unit(newell(corners)), leaf["patch"])
        if face is None:
            raise ValueError(f"{path}: leaf {i} (rpkCpp patch {leaf['patch']}, centroid "
                             f"{centroid(corners)}) lies on the front of no face of the scene")
        out.append(face)
    return out


def constant_solution(leaves, patches):
    s = Solution()
    for leaf, patch in zip(leaves.leaves, patches):
        corners = [leaves.vertices[v] for v in leaf["corners"]]
        s.add(corners, [leaf_radiosity(leaf)] * len(corners), patch)
    return s


def gouraud_solution(leaves, patches):
    s, values = Solution(), vertex_radiosity(leaves)
    for leaf, patch in zip(leaves.leaves, patches):
        for piece in gouraud_pieces(leaf):
            s.add([leaves.vertices[v] for v in piece], [values[v] for v in piece], patch)
    return s


def write_vtp(solution, path):
    """The solution as a VTK XML PolyData file (ASCII) with the arrays a foreign solution needs:
    point Radiosity and cell PatchId (docs/design.md §11.4)."""
    offsets, total = [], 0
    for p in solution.polygons:
        total += len(p)
        offsets.append(total)

    def rows(values):
        return "\n".join(" ".join(repr(float(c)) for c in v) for v in values)

    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n'
                '<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">\n'
                '<PolyData>\n'
                f'<Piece NumberOfPoints="{len(solution.points)}" NumberOfVerts="0" '
                f'NumberOfLines="0" NumberOfStrips="0" NumberOfPolys="{len(solution.polygons)}">\n'
                '<PointData>\n'
                '<DataArray type="Float64" Name="Radiosity" NumberOfComponents="3" '
                f'format="ascii">\n{rows(solution.radiosity)}\n</DataArray>\n'
                '</PointData>\n<CellData>\n'
                '<DataArray type="Int64" Name="PatchId" format="ascii">\n'
                + " ".join(str(p) for p in solution.patch_ids) + '\n</DataArray>\n'
                '</CellData>\n<Points>\n'
                '<DataArray type="Float64" Name="Points" NumberOfComponents="3" format="ascii">\n'
                f'{rows(solution.points)}\n</DataArray>\n</Points>\n<Polys>\n'
                '<DataArray type="Int64" Name="connectivity" format="ascii">\n'
                + " ".join(str(i) for p in solution.polygons for i in p) + '\n</DataArray>\n'
                '<DataArray type="Int64" Name="offsets" format="ascii">\n'
                + " ".join(str(o) for o in offsets) + '\n</DataArray>\n'
                '</Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n')


# ---------------------------------------------------------------- checks


def solution_power(solution):
    """Integral of B over the solution, W per channel: each polygon's fan of triangles from its
    first point, a triangle's mean the mean of its corners (rpkCpp's pieces have no point on an
    edge, so this is how hmcr reads them)."""
    out = [0.0, 0.0, 0.0]
    for poly in solution.polygons:
        for k in range(1, len(poly) - 1):
            tri = [poly[0], poly[k], poly[k + 1]]
            a = polygon_area([solution.points[i] for i in tri])
            for c in range(3):
                out[c] += a * sum(solution.radiosity[i][c] for i in tri) / 3.0
    return out


def check_units(leaves, faces, patches):
    """Areas, units and the power balance of a leaf file (every figure per channel):

    - area: the leaves' polygon areas against rpkCpp's and, summed per face, against the
      face's (the largest relative differences);
    - emitted_w = sum pi SRC A and total_w = sum pi RAD A (rpkCpp's own total flux);
    - ed_over_src: Ed / SRC on emitting leaves, at the patch level (1: Ed a radiance) and below
      it (pi: a sub-element's Ed is an exitance), so the file shows which it is.
    """
    area_rel, face_area = 0.0, [0.0] * len(faces)
    emitted, total = [0.0] * 3, [0.0] * 3
    ratios = {"patch_level": [], "sub_elements": []}
    for leaf, face in zip(leaves.leaves, patches):
        a = polygon_area([leaves.vertices[v] for v in leaf["corners"]])
        area_rel = max(area_rel, abs(a - leaf["area"]) / a)
        face_area[face] += a
        for c in range(3):
            emitted[c] += math.pi * leaf["src"][c] * a
            total[c] += math.pi * leaf["rad"][c] * a
        s = sum(leaf["src"])
        if s > 0:
            ratios["patch_level" if leaf["level"] == 0 else "sub_elements"].append(
                sum(leaf["ed"]) / s)
    face_rel = max(abs(face_area[f] - polygon_area(faces[f])) / polygon_area(faces[f])
                   for f in set(patches))
    return {"leaves": len(leaves.leaves), "leaf_area_vs_rpk": area_rel,
            "face_area_vs_scene": face_rel, "uncovered_faces": len(faces) - len(set(patches)),
            "emitted_w": emitted, "total_w": total,
            "ed_over_src": {k: [min(v), max(v)] if v else None for k, v in ratios.items()}}
