// SPDX-License-Identifier: Apache-2.0
// A study's figures (studies/montage.h): tiles shrunk and laid out 4 a row, each label centred in
// a strip under its tile, a long label widening every column, and bad input refused.
#include "studies/montage.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "image/label.h"

namespace hmcr {
namespace {

Image8 grey(int w, int h, std::uint8_t v) {
    Image8 im(w, h);
    for (Srgb8& p : im.pixels) p = {v, v, v};
    return im;
}

// Dark pixels in a box of the image.
int ink(const Image8& im, int x0, int y0, int x1, int y1) {
    int n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) n += im.at(x, y)[0] < 128;
    return n;
}

TEST(Montage, TilesWithoutLabelsAreLaidOutWithGaps) {
    const Image8 m = montage({grey(8, 6, 10), grey(8, 6, 20), grey(8, 6, 30)}, 2, 2);
    EXPECT_EQ(m.width, 2 * 4 + 2);
    EXPECT_EQ(m.height, 2 * 3 + 2);
    EXPECT_EQ(m.at(0, 0)[0], 10);
    EXPECT_EQ(m.at(6, 0)[0], 20);
    EXPECT_EQ(m.at(0, 5)[0], 30);
    EXPECT_EQ(m.at(5, 5)[0], 255);  // the missing fourth tile
}

TEST(Montage, EachLabelIsCentredUnderItsTile) {
    const std::vector<Image8> tiles(5, grey(256, 64, 200));
    const Image8 m = montage(tiles, 4, 1, {"reference", "kl", "", "srhe", "cc"});
    // 256-pixel tiles: 2 font pixels per font pixel; strips of (7 + 4) x 2 under each tile.
    const int strip = (kGlyphHeight + 4) * 2, cell_h = 64 + strip;
    EXPECT_EQ(m.width, 4 * 256 + 3 * 2);
    EXPECT_EQ(m.height, 2 * cell_h + 2);
    // "kl" is 22 pixels wide, centred: ink only within (256 - 22) / 2 ... + 22 of its column.
    const int kl = 258 + (256 - text_width("kl", 2)) / 2;
    EXPECT_GT(ink(m, kl, 64, kl + text_width("kl", 2), cell_h), 0);
    EXPECT_EQ(ink(m, 258, 64, kl, cell_h), 0);
    EXPECT_EQ(ink(m, kl + text_width("kl", 2), 64, 514, cell_h), 0);
    EXPECT_EQ(ink(m, 516, 64, 772, cell_h), 0);               // an empty label
    EXPECT_GT(ink(m, 0, cell_h + 2 + 64, 256, m.height), 0);  // the second row's label
    EXPECT_EQ(ink(m, 0, 0, m.width, 64), 0);                  // the tiles are untouched
}

TEST(Montage, ALabelWiderThanItsTileWidensEveryColumn) {
    const Image8 m = montage({grey(12, 12, 0), grey(12, 12, 0)}, 4, 1, {"half-difference", "cc"});
    const int cell = text_width("half-difference", 1) + 2;
    EXPECT_EQ(m.width, 2 * cell + 2);
    EXPECT_EQ(m.at((cell - 12) / 2, 0)[0], 0);  // the tile centred in its column
    EXPECT_EQ(m.at((cell - 12) / 2 - 1, 0)[0], 255);
}

TEST(Montage, BadInputIsRefused) {
    EXPECT_THROW(montage({}, 4, 1), std::invalid_argument);
    EXPECT_THROW(montage({grey(4, 4, 0), grey(5, 4, 0)}, 4, 1), std::invalid_argument);
    EXPECT_THROW(montage({grey(4, 4, 0)}, 4, 1, {"a", "b"}), std::invalid_argument);
    EXPECT_THROW(montage({grey(4, 4, 0)}, 0, 1), std::invalid_argument);
    EXPECT_THROW(montage({grey(4, 4, 0)}, 4, 5), std::invalid_argument);
}

}  // namespace
}  // namespace hmcr
