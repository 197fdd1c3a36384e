// SPDX-License-Identifier: Apache-2.0
// Text in a bitmap font of 5 x 7 pixels a glyph, to label the tiles of a study's figures without
// a font library: lower-case letters, digits, space and - + . _ : ( ); upper case is drawn as
// lower case and anything else as '?'.
#pragma once

#include <string>

#include "image/image.h"

namespace hmcr {

inline constexpr int kGlyphWidth = 5, kGlyphHeight = 7;
inline constexpr int kGlyphAdvance = kGlyphWidth + 1;  // a column of space between glyphs

// Width in pixels of `text` drawn at an integer scale (0 for no text).
int text_width(const std::string& text, int scale);

// Draws `text` with its top-left corner at (x, y), each pixel of the font a scale x scale square
// of `colour`; what falls outside the image is left out.
void draw_text(Image8& image, int x, int y, const std::string& text, int scale, Srgb8 colour);

}  // namespace hmcr
