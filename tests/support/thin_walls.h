// SPDX-License-Identifier: Apache-2.0
// A thin wall of N corners between two lamps, written in MGF as two faces facing away from each
// other (paint up, tiles down), whole or as a fan of quads: one surface with two sides either
// way (docs/design.md §1.6).
#pragma once

#include <cmath>
#include <numbers>
#include <string>

namespace hmcr::test {

// How the wall is written: its N-gon whole (the tiles from `tile_start`, another corner than
// the paint's), or the same N-gon as a fan of quads from corner 0, a triangle last for odd N.
enum class WallFaces { polygon, quads };

// Lines 1-16: the materials and lamps; then the wall's corners w0..w(N-1), a regular N-gon of
// radius 1 at z = 0 counter-clockwise seen from +z, then its faces.
inline std::string thin_wall_mgf(int corners, WallFaces faces, int tile_start = 2) {
    std::string s =
        "m lamp =\n ed 100\n sides 1\nm dim =\n ed 40\n sides 1\n"
        "m paint =\n rd 0.8\n sides 1\nm tile =\n rd 0.3\n sides 1\n"
        "v l1 =\n p -2 -2 2\nv l2 =\n p 2 -2 2\nv l3 =\n p 2 2 2\nv l4 =\n p -2 2 2\n"
        "v k1 =\n p -2 -2 -2\nv k2 =\n p 2 -2 -2\nv k3 =\n p 2 2 -2\nv k4 =\n p -2 2 -2\n"
        "m lamp\nf l1 l4 l3 l2\nm dim\nf k1 k2 k3 k4\n";
    for (int i = 0; i < corners; ++i) {
        const double a = 2 * std::numbers::pi * i / corners;
        s += "v w" + std::to_string(i) + " =\n p " + std::to_string(std::cos(a)) + " " +
             std::to_string(std::sin(a)) + " 0\n";
    }
    const auto w = [](int i) { return " w" + std::to_string(i); };
    if (faces == WallFaces::polygon) {
        s += "m paint\nf";
        for (int i = 0; i < corners; ++i) s += w(i);
        s += "\nm tile\nf";
        for (int i = 0; i < corners; ++i) s += w(((tile_start - i) % corners + corners) % corners);
        return s + "\n";
    }
    for (int k = 1; k + 1 < corners; k += 2) {
        const bool quad = k + 2 < corners;
        s += "m paint\nf w0" + w(k) + w(k + 1) + (quad ? w(k + 2) : "") + "\n";
        s += "m tile\nf" + (quad ? w(k + 2) : "") + w(k + 1) + w(k) + " w0\n";
    }
    return s;
}

}  // namespace hmcr::test
