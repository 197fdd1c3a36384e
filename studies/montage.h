// SPDX-License-Identifier: Apache-2.0
// Figures of a study: equal-sized images shrunk by an integer factor (box filter on the 8-bit
// values) and laid out left to right, top to bottom, with a 2-pixel white gap; each tile may have
// a label (its sampler or oracle) centred in a white strip under it.
#pragma once

#include <string>
#include <vector>

#include "image/image.h"

namespace hmcr {

// With `labels` (one per tile, or none) the labels are drawn in black, one font pixel
// (image/label.h) per 128 pixels of tile width and at least one; a label wider than its tile
// widens every column to hold it. Throws std::invalid_argument when the tiles differ in size,
// columns or shrink < 1, or the labels are neither none nor one per tile.
Image8 montage(const std::vector<Image8>& tiles, int columns, int shrink,
               const std::vector<std::string>& labels = {});

}  // namespace hmcr
