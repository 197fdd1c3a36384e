#include "studies/montage.h"

#include <cmath>
#include <stdexcept>

namespace hmcr {
namespace {

constexpr int kGap = 2;

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

}  // namespace

Image8 montage(const std::vector<Image8>& tiles, int columns, int shrink) {
    if (tiles.empty() || columns < 1 || shrink < 1) throw std::invalid_argument("bad montage");
    const int w = tiles[0].width / shrink, h = tiles[0].height / shrink;
    for (const Image8& t : tiles) {
        if (t.width != tiles[0].width || t.height != tiles[0].height || w < 1 || h < 1) {
            throw std::invalid_argument("montage tiles must share one size");
        }
    }
    const int rows = (int(tiles.size()) + columns - 1) / columns;
    const int cols = std::min(columns, int(tiles.size()));
    Image8 out(cols * w + (cols - 1) * kGap, rows * h + (rows - 1) * kGap);
    for (Srgb8& p : out.pixels) p = {255, 255, 255};
    for (std::size_t k = 0; k < tiles.size(); ++k) {
        const int ox = int(k) % columns * (w + kGap), oy = int(k) / columns * (h + kGap);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                out.at(ox + x, oy + y) = box_average(tiles[k], x * shrink, y * shrink, shrink);
    }
    return out;
}

}  // namespace hmcr
