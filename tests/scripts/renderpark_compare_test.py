#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""scripts/rpk_leaves.py on a small synthetic leaf file, as rpkCpp's inserted writer writes one:
the leaves' patches, areas, units (B = pi x radiance, a sub-element's Ed an exitance) and power
balance, rpkCpp's Gouraud values at a T-vertex, the .vtp's arrays and one-line errors; and the
noise mode's pure parts (renderpark_compare.py --noise) on synthetic patches: the per-patch
deviation and the variants' hmcr commands (scripts/patch_noise.py, fixed_mesh_noise.py's too),
the patch matching, the ray-unit curve and the hooks' insertion.

Usage: renderpark_compare_test.py SOURCE_DIR (no rpkCpp, no network, no hmcr binary)."""

import math
import os
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.join(sys.argv.pop(1) if len(sys.argv) > 1 else ".", "scripts"))
import rpk_leaves  # noqa: E402
import patch_noise  # noqa: E402
import renderpark_compare  # noqa: E402

# hmcr's scene, in its patch order: face 0 the unit square of z = 0 facing +z, face 1 a light
# triangle of area 1/2 at z = 1 facing down, face 2 a second light of area 1/2 beside the square.
FACES = [[(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [(0, 0, 1), (0, 1, 1), (1, 0, 1)],
         [(2, 0, 0), (3, 0, 0), (2, 1, 0)]]
EMITTED_B = 5.0  # the first light's emitted radiosity, W/m^2 (rpkCpp's sourceRad 5 / pi)
SMALL_B = 2.0  # the second's, on a leaf that is its patch (rpkCpp's Ed a radiance there)


class LeafFile:
    """Writes a leaf file line by line: vertices by their coordinates, leaves by corners."""

    def __init__(self):
        self.lines, self.ids = [rpk_leaves.LEAF_FILE_VERSION], {}

    def vertex(self, p):
        if p is None:
            return -1
        if p not in self.ids:
            self.ids[p] = len(self.ids)
            self.lines.append("v %d %r %r %r" % ((self.ids[p],) + p))
        return self.ids[p]

    def leaf(self, patch, level, corners, rad, src=(0, 0, 0), ed=(0, 0, 0), middles=None):
        middles = middles or [None] * len(corners)
        ids = [self.vertex(p) for p in corners] + [self.vertex(p) for p in middles]
        area = rpk_leaves.polygon_area(corners)
        numbers = [area] + list(rad) + list(src) + list(ed)
        self.lines.append(f"l {patch} {level} {len(corners)} " + " ".join(map(str, ids)) + " "
                          + " ".join(repr(float(x)) for x in numbers))

    def write(self, folder):
        path = os.path.join(folder, "leaves.txt")
        with open(path, "w") as f:
            f.write("\n".join(self.lines) + "\n")
        return path


def square(x, y, s):
    return [(x, y, 0.0), (x + s, y, 0.0), (x + s, y + s, 0.0), (x, y + s, 0.0)]


def square_b(x, y):
    """The radiosity of the square's leaf at (x, y): different per leaf and channel."""
    return (1.0 + 4 * x * x + 2 * y, 2.0 + 3 * x, 0.5 + y)


def synthetic():
    """rpkCpp patch 0 is the light (scene face 1), patch 1 the square (face 0): the order
    differs from hmcr's. The square is cut in four, its lower left quarter in four again, so its
    right and upper neighbours hold T-vertices at (0.5, 0.25) and (0.25, 0.5). The light is cut
    in four with rpkCpp's sub-element Ed, pi times the radiance it emits; the second light
    (patch 2) is one leaf, its Ed the radiance."""
    f = LeafFile()
    small = [SMALL_B / math.pi] * 3
    f.leaf(2, 0, FACES[2], small, small, small)
    a, b, c = FACES[1]
    mid = [tuple((p[k] + q[k]) / 2 for k in range(3)) for p, q in ((a, b), (b, c), (c, a))]
    src = [EMITTED_B / math.pi] * 3
    for k, tri in enumerate([[a, mid[0], mid[2]], [mid[0], b, mid[1]], [mid[2], mid[1], c],
                             [mid[1], mid[2], mid[0]]]):
        rad = [s + 0.1 * (k + 1) / math.pi for s in src]
        f.leaf(0, 1, tri, rad, src, [EMITTED_B] * 3)
    for x in (0.0, 0.25):
        for y in (0.0, 0.25):
            f.leaf(1, 2, square(x, y, 0.25), [v / math.pi for v in square_b(x, y)])
    t_right, t_up = (0.5, 0.25, 0.0), (0.25, 0.5, 0.0)
    f.leaf(1, 1, square(0.5, 0.0, 0.5), [v / math.pi for v in square_b(0.5, 0.0)],
           middles=[None, None, None, t_right])
    f.leaf(1, 1, square(0.5, 0.5, 0.5), [v / math.pi for v in square_b(0.5, 0.5)])
    f.leaf(1, 1, square(0.0, 0.5, 0.5), [v / math.pi for v in square_b(0.0, 0.5)],
           middles=[t_up, None, None, None])
    return f


class ConverterTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.path = synthetic().write(self.tmp.name)
        self.leaves = rpk_leaves.read_leaves(self.path)
        self.patches = rpk_leaves.leaf_patches(self.leaves, rpk_leaves.FaceFinder(FACES))

    def tearDown(self):
        self.tmp.cleanup()

    def cell_area(self, s, c):
        return rpk_leaves.polygon_area([s.points[i] for i in s.polygons[c]])

    def test_leaves_find_their_scene_faces_whatever_rpk_patch_order(self):
        self.assertEqual(self.patches, [2] + [1] * 4 + [0] * 7)

    def test_every_face_is_covered_by_its_cells_area(self):
        for make in (rpk_leaves.constant_solution, rpk_leaves.gouraud_solution):
            s = make(self.leaves, self.patches)
            for face in (0, 1, 2):
                area = sum(self.cell_area(s, c) for c, p in enumerate(s.patch_ids) if p == face)
                self.assertAlmostEqual(area, rpk_leaves.polygon_area(FACES[face]), places=12)

    def test_radiosity_is_pi_times_the_radiance(self):
        s = rpk_leaves.constant_solution(self.leaves, self.patches)
        cell = s.polygons[5]  # the square's first leaf, at (0, 0)
        for i in cell:
            for got, want in zip(s.radiosity[i], square_b(0.0, 0.0)):
                self.assertAlmostEqual(got, want, places=12)
        light = s.polygons[1]  # the light's first leaf: 5 W/m^2 emitted, 0.1 reflected
        self.assertAlmostEqual(s.radiosity[light[0]][1], EMITTED_B + 0.1, places=12)

    def test_power_balances_and_sub_element_ed_is_seen_as_an_exitance(self):
        checks = rpk_leaves.check_units(self.leaves, FACES, self.patches)
        for c in range(3):
            self.assertAlmostEqual(checks["emitted_w"][c], (EMITTED_B + SMALL_B) * 0.5,
                                   places=12)
        total = [(EMITTED_B + SMALL_B) * 0.5 + 0.125 * 0.1 * (1 + 2 + 3 + 4)] * 3
        for (x, y, s) in [(0, 0, .25), (.25, 0, .25), (0, .25, .25), (.25, .25, .25),
                          (.5, 0, .5), (.5, .5, .5), (0, .5, .5)]:
            for c in range(3):
                total[c] += square_b(x, y)[c] * s * s
        for c in range(3):
            self.assertAlmostEqual(checks["total_w"][c], total[c], places=12)
        s = rpk_leaves.constant_solution(self.leaves, self.patches)
        for got, want in zip(rpk_leaves.solution_power(s), total):
            self.assertAlmostEqual(got, want, places=12)
        self.assertEqual(checks["ed_over_src"]["patch_level"], [1.0, 1.0])
        for r in checks["ed_over_src"]["sub_elements"]:
            self.assertAlmostEqual(r, math.pi, places=12)
        self.assertAlmostEqual(checks["face_area_vs_scene"], 0.0, places=12)
        self.assertEqual(checks["uncovered_faces"], 0)

    def test_gouraud_values_are_rpks_vertex_means_and_t_vertex_averages(self):
        values = rpk_leaves.vertex_radiosity(self.leaves)
        ids = {p: i for i, p in self.leaves.vertices.items()}
        corner = values[ids[(0.0, 0.0, 0.0)]]  # one leaf's corner
        self.assertAlmostEqual(corner[0], square_b(0.0, 0.0)[0], places=12)
        inner = values[ids[(0.25, 0.25, 0.0)]]  # four leaves' corner
        want = sum(square_b(x, y)[0] for x in (0, .25) for y in (0, .25)) / 4
        self.assertAlmostEqual(inner[0], want, places=12)
        # the T-vertex at (0.5, 0.25): corner of two fine leaves, on the coarse right leaf
        t = values[ids[(0.5, 0.25, 0.0)]]
        want = ((square_b(.25, 0)[0] + square_b(.25, .25)[0]) / 2 + square_b(.5, 0)[0]) / 2
        self.assertAlmostEqual(t[0], want, places=12)

    def test_a_leaf_with_a_t_vertex_is_cut_through_it(self):
        s = rpk_leaves.gouraud_solution(self.leaves, self.patches)
        # the lights' 1 + 4 + the square's 4 fine leaves, 3 triangles, 1 quad, 3 triangles
        self.assertEqual([len(p) for p in s.polygons], [3] * 5 + [4] * 4 + [3] * 3 + [4]
                         + [3] * 3)
        t = (0.5, 0.25, 0.0)
        self.assertEqual(sum(1 for p in s.polygons[9:12] if t in [s.points[i] for i in p]), 3)

    def test_the_vtp_holds_the_arrays_a_foreign_solution_needs(self):
        s = rpk_leaves.gouraud_solution(self.leaves, self.patches)
        out = os.path.join(self.tmp.name, "s.vtp")
        rpk_leaves.write_vtp(s, out)
        piece = ET.parse(out).getroot().find("PolyData/Piece")
        self.assertEqual(int(piece.get("NumberOfPolys")), len(s.polygons))
        arrays = {a.get("Name"): a.text.split() for a in piece.iter("DataArray")}
        self.assertEqual(len(arrays["Radiosity"]), 3 * int(piece.get("NumberOfPoints")))
        self.assertEqual([int(p) for p in arrays["PatchId"]], s.patch_ids)
        self.assertEqual(int(arrays["offsets"][-1]), len(arrays["connectivity"]))


class BadInputTest(unittest.TestCase):
    def read(self, text):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "bad.txt")
            with open(path, "w") as f:
                f.write(text)
            with self.assertRaises(ValueError) as e:
                rpk_leaves.read_leaves(path)
            return str(e.exception).replace(path, "FILE")

    def test_each_error_names_its_line(self):
        self.assertTrue(self.read("hello\n").startswith("FILE:1: "))
        v = "v 0 0 0 0\nv 1 1 0 0\nv 2 0 1 0\n"
        ok = "l 0 0 3 0 1 2 -1 -1 -1 0.5 1 1 1 0 0 0 0 0 0\n"
        with tempfile.TemporaryDirectory() as tmp:  # the control: the good file reads
            path = os.path.join(tmp, "good.txt")
            with open(path, "w") as f:
                f.write(rpk_leaves.LEAF_FILE_VERSION + "\n" + v + ok)
            self.assertEqual(len(rpk_leaves.read_leaves(path).leaves), 1)
        self.assertEqual(self.read(rpk_leaves.LEAF_FILE_VERSION + "\n" + v
                                   + ok.replace("0 1 2", "0 1 7")),
                         "FILE:5: vertex 7 is not defined above")
        self.assertTrue(self.read(rpk_leaves.LEAF_FILE_VERSION + "\n" + v
                                  + ok.replace(" 0.5 ", " nan ")).startswith("FILE:5: "))
        self.assertTrue(self.read(rpk_leaves.LEAF_FILE_VERSION + "\n").startswith("FILE:1: "))
        self.assertTrue(self.read(rpk_leaves.LEAF_FILE_VERSION + "\n" + v
                                  + ok.replace("0 1 2", "0 x 2")).startswith("FILE:5: "))
        self.assertTrue(self.read(rpk_leaves.LEAF_FILE_VERSION + "\nv a 0 0 0\n")
                        .startswith("FILE:2: "))

    def test_a_leaf_on_no_face_or_on_a_back_is_refused(self):
        for corners in ([(0, 0, 0.5), (1, 0, 0.5), (0, 1, 0.5)],  # between the faces
                        [(0, 0, 0), (0, 1, 0), (1, 0, 0)]):  # on the square, facing -z
            f = LeafFile()
            f.leaf(0, 0, corners, (1, 1, 1))
            with tempfile.TemporaryDirectory() as tmp:
                leaves = rpk_leaves.read_leaves(f.write(tmp))
            with self.assertRaises(ValueError):
                rpk_leaves.leaf_patches(leaves, rpk_leaves.FaceFinder(FACES))

    def test_the_writer_goes_into_batch_cpp_once(self):
        with tempfile.TemporaryDirectory() as tmp:
            os.makedirs(os.path.join(tmp, "src", "app"))
            path = os.path.join(tmp, rpk_leaves.BATCH_FILE)
            with open(path, "w") as f:
                f.write('#include <ctime>\n#include "app/batch.h"\n\nvoid f() {\n'
                        + rpk_leaves.BATCH_ANCHOR + "\n}\n")
            rpk_leaves.add_leaf_writer(tmp)
            with open(path) as f:
                text = f.read()
            self.assertEqual(text.count(rpk_leaves.LEAF_WRITER_CALL), 1)
            self.assertLess(text.index("static void\nhmcrWriteLeafFile"),
                            text.index(rpk_leaves.LEAF_WRITER_CALL))
            with self.assertRaises(ValueError):  # the anchor is not there once now
                with open(path, "w") as f:
                    f.write('#include <ctime>\nvoid f() {}\n')
                rpk_leaves.add_leaf_writer(tmp)


def patch(centroid, normal=(0, 0, 1), area=1.0, b=(1, 1, 1)):
    return renderpark_compare.Patch(area, list(centroid), list(normal), b)


class NoiseTest(unittest.TestCase):
    def test_relative_rms_is_fixed_mesh_noises_deviation_over_lit_channels(self):
        reference = [[2.0, 1.0, 0.0], [4.0, 4.0, 4.0]]
        lit = patch_noise.lit_channels(reference)
        self.assertEqual(lit, [(0, 0), (0, 1), (1, 0), (1, 1), (1, 2)])  # not the black one
        # run 1: +10% on one channel of five; run 2: -20% on another (the black one ignored)
        runs = [[[2.2, 1.0, 5.0], [4.0, 4.0, 4.0]], [[2.0, 1.0, 0.0], [4.0, 3.2, 4.0]]]
        want = math.sqrt((0.01 / 5 + 0.04 / 5) / 2)
        self.assertAlmostEqual(patch_noise.relative_rms(runs, reference, lit), want,
                               places=12)
        self.assertEqual(patch_noise.relative_rms([reference], reference, lit), 0.0)

    def test_a_variants_words_are_its_options(self):
        command = patch_noise.hmcr_command("hmcr", "room.mgf", "sobol+both+cv+linear", 3, 2684000,
                                           "o.vtp", ["--sides", "1"])
        self.assertEqual(command[:2], ["hmcr", "solve"])
        words = " ".join(command)
        for wanted in ("--max-depth 0", "--threads 1", "--seed 3", "--sequence sobol",
                       "--rays 2684000", "-o o.vtp", "--sides 1", "--bidirectional yes",
                       "--control-variate constant", "--basis linear"):
            self.assertIn(wanted, words)
        self.assertEqual(patch_noise.variant_basis("sobol+both+cubic"), "cubic")
        self.assertEqual(patch_noise.variant_basis("random"), "")
        with self.assertRaises(ValueError):
            patch_noise.hmcr_command("hmcr", "cornell", "sobol+twice", 1, 10, "o.vtp")

    def test_a_channel_black_in_either_reference_is_not_lit(self):
        a, b = [[1.0, 0.0, 1.0]], [[1.0, 1.0, 0.0]]
        self.assertEqual(patch_noise.lit_channels(a, b), [(0, 0)])

    def test_patches_match_by_geometry_whatever_their_order(self):
        ours = [patch((0, 0, 0)), patch((1, 0, 0)), patch((0, 0, 0), normal=(0, 0, -1)),
                patch((2, 0, 0), area=2.0)]
        theirs = [patch((2, 0, 0), area=2.0), patch((0, 0, 0), normal=(0, 0, -1)),
                  patch((1, 0, 1e-6)), patch((0, 0, 0))]
        self.assertEqual(renderpark_compare.match_patches(ours, theirs), [3, 2, 1, 0])

    def test_a_patch_of_another_area_or_place_matches_nothing(self):
        ours = [patch((0, 0, 0)), patch((1, 0, 0))]
        for other in (patch((0, 0, 0), area=1.01), patch((0.5, 0, 0)),
                      patch((1, 0, 0), normal=(0, 1, 0))):
            with self.assertRaises(ValueError):
                renderpark_compare.match_patches(ours, [other])
        with self.assertRaises(ValueError):  # two of theirs on one of ours
            renderpark_compare.match_patches(ours, [patch((0, 0, 0)), patch((0, 0, 0))])

    def test_a_patch_of_two_polygons_has_their_area_weighted_centroid_and_value(self):
        p = renderpark_compare._patch([[(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)],
                                       [(1, 0, 0), (3, 0, 0), (3, 1, 0), (1, 1, 0)]],
                                      [(3.0, 0.0, 1.0), (6.0, 3.0, 1.0)])
        self.assertAlmostEqual(p.area, 3.0, places=12)
        for got, want in zip(p.centroid, (1.5, 0.5, 0.0)):
            self.assertAlmostEqual(got, want, places=12)
        for got, want in zip(p.b, (5.0, 2.0, 1.0)):
            self.assertAlmostEqual(got, want, places=12)
        self.assertEqual(p.normal, [0.0, 0.0, 1.0])

    def test_the_curve_of_ray_units_is_centred_on_the_measured_units(self):
        curve = renderpark_compare.ray_unit_curve(1000, 8, 0.03)
        self.assertEqual(curve, [895, 925, 955, 985, 1015, 1045, 1075, 1105])
        self.assertEqual(renderpark_compare.ray_unit_curve(1000, 3, 0.1), [900, 1000, 1100])

    def test_efficiency_is_one_over_variance_times_seconds(self):
        self.assertAlmostEqual(renderpark_compare.efficiency(0.01, 2.0), 5000.0, places=9)

    def test_each_hook_goes_in_once_at_its_anchor_or_the_copy_is_refused(self):
        edits = [("b\n", "B\n", "before"), ("c\n", "C\n", "after")]
        self.assertEqual(rpk_leaves.insert_at_anchors("a\nb\nc\nd\n", edits, "f"),
                         "a\nB\nb\nc\nC\nd\n")
        for text in ("a\nc\n", "b\nb\nc\n"):  # an anchor missing, an anchor twice
            with self.assertRaises(ValueError):
                rpk_leaves.insert_at_anchors(text, edits, "f")
        for anchor, _, _ in rpk_leaves.NOISE_EDITS:
            self.assertTrue(anchor.endswith("\n") or anchor.endswith("("), anchor)


if __name__ == "__main__":
    unittest.main()
