// SPDX-License-Identifier: Apache-2.0
// The labels' bitmap font (image/label.h): widths, a glyph's pixels at scale 1 and 2, upper case
// as lower case, an unknown character as '?', and text beyond the image's edge left out.
#include "image/label.h"

#include <gtest/gtest.h>

namespace hmcr {
namespace {

constexpr Srgb8 kInk{0, 0, 0};

// The image's pixels as rows of '#' (ink) and '.' (white).
std::vector<std::string> rows(const Image8& im) {
    std::vector<std::string> out;
    for (int y = 0; y < im.height; ++y) {
        std::string row;
        for (int x = 0; x < im.width; ++x) row += im.at(x, y) == kInk ? '#' : '.';
        out.push_back(row);
    }
    return out;
}

Image8 white(int w, int h) {
    Image8 im(w, h);
    for (Srgb8& p : im.pixels) p = {255, 255, 255};
    return im;
}

TEST(Label, WidthIsSixPixelsAGlyphLessTheLastSpace) {
    EXPECT_EQ(text_width("", 1), 0);
    EXPECT_EQ(text_width("l", 1), 5);
    EXPECT_EQ(text_width("half-difference", 1), 89);
    EXPECT_EQ(text_width("kl", 3), 33);
}

TEST(Label, GlyphsAreDrawnAtTheirScale) {
    Image8 im = white(11, 7);
    draw_text(im, 0, 0, "l1", 1, kInk);
    const std::vector<std::string> expected = {
        ".##.....#..",  //
        "..#....##..",  //
        "..#.....#..",  //
        "..#.....#..",  //
        "..#.....#..",  //
        "..#.....#..",  //
        ".###...###.",
    };
    EXPECT_EQ(rows(im), expected);
    Image8 big = white(10, 14);
    draw_text(big, 0, 0, "-", 2, kInk);
    for (int y = 0; y < 14; ++y)
        EXPECT_EQ(rows(big)[y], y == 6 || y == 7 ? "##########" : "..........");
}

TEST(Label, UpperCaseIsLowerCaseAndUnknownIsAQuestionMark) {
    Image8 a = white(5, 7), b = white(5, 7), q = white(5, 7), u = white(5, 7);
    draw_text(a, 0, 0, "K", 1, kInk);
    draw_text(b, 0, 0, "k", 1, kInk);
    draw_text(q, 0, 0, "?", 1, kInk);
    draw_text(u, 0, 0, "\xce\xb5", 1, kInk);  // UTF-8 epsilon: two unknown bytes, '?' twice
    EXPECT_EQ(rows(a), rows(b));
    EXPECT_EQ(rows(u), rows(q));
    EXPECT_NE(rows(q), rows(white(5, 7)));
}

TEST(Label, TextBeyondTheEdgeIsLeftOut) {
    Image8 im = white(4, 4);
    draw_text(im, -3, -3, "half-difference", 2, kInk);  // no write outside the image
    EXPECT_EQ(im.width, 4);
    draw_text(im, 10, 10, "kl", 1, kInk);
    EXPECT_EQ(rows(im).size(), 4u);
}

}  // namespace
}  // namespace hmcr
