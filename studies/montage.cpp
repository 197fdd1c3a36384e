// SPDX-License-Identifier: Apache-2.0
#include "studies/montage.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "image/label.h"

namespace hmcr {
namespace {

constexpr int kGap = 2;
constexpr Srgb8 kWhite{255, 255, 255}, kBlack{0, 0, 0};

Srgb8 box_average(const Image8& im, int x0, int y0, int shrink) {
    Srgb8 out;
    for (int c = 0; c < 3; ++c) {
        double sum = 0;
        for (int y = y0; y < y0 + shrink; ++y)
            for (int x = x0; x < x0 + shrink; ++x) sum += im.at(x, y)[c];
        out[c] = std::uint8_t(std::lround(sum / (shrink * shrink)));
    }
    return out;
}

void check(const std::vector<Image8>& tiles, int columns, int shrink,
           const std::vector<std::string>& labels) {
    if (tiles.empty() || columns < 1 || shrink < 1) throw std::invalid_argument("bad montage");
    if (!labels.empty() && labels.size() != tiles.size()) {
        throw std::invalid_argument("a montage's labels must be one per tile");
    }
    for (const Image8& t : tiles) {
        if (t.width != tiles[0].width || t.height != tiles[0].height || t.width < shrink ||
            t.height < shrink) {
            throw std::invalid_argument("montage tiles must share one size");
        }
    }
}

}  // namespace

Image8 montage(const std::vector<Image8>& tiles, int columns, int shrink,
               const std::vector<std::string>& labels) {
    check(tiles, columns, shrink, labels);
    const int w = tiles[0].width / shrink, h = tiles[0].height / shrink;
    const int scale = std::max(1, w / 128);
    int cell_w = w;
    for (const std::string& l : labels) cell_w = std::max(cell_w, text_width(l, scale) + 2 * scale);
    const int strip = labels.empty() ? 0 : (kGlyphHeight + 4) * scale;
    const int cell_h = h + strip;
    const int rows = (int(tiles.size()) + columns - 1) / columns;
    const int cols = std::min(columns, int(tiles.size()));
    Image8 out(cols * cell_w + (cols - 1) * kGap, rows * cell_h + (rows - 1) * kGap);
    for (Srgb8& p : out.pixels) p = kWhite;
    for (std::size_t k = 0; k < tiles.size(); ++k) {
        const int ox = int(k) % columns * (cell_w + kGap), oy = int(k) / columns * (cell_h + kGap);
        const int tx = ox + (cell_w - w) / 2;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                out.at(tx + x, oy + y) = box_average(tiles[k], x * shrink, y * shrink, shrink);
        if (!labels.empty()) {
            draw_text(out, ox + (cell_w - text_width(labels[k], scale)) / 2, oy + h + 2 * scale,
                      labels[k], scale, kBlack);
        }
    }
    return out;
}

}  // namespace hmcr
