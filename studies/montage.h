// Figures of a study: equal-sized images shrunk by an integer factor (box filter on the 8-bit
// values) and laid out left to right, top to bottom, with a 2-pixel white gap.
#pragma once

#include <vector>

#include "image/image.h"

namespace hmcr {

// Throws std::invalid_argument when the tiles differ in size, or columns or shrink < 1.
Image8 montage(const std::vector<Image8>& tiles, int columns, int shrink);

}  // namespace hmcr
