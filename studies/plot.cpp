#include "studies/plot.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace hmcr {
namespace {

// 5x7 glyphs, rows top to bottom, '#' set. Upper case is drawn as lower case.
struct Glyph {
    char c;
    const char* rows;  // 35 characters
};

constexpr Glyph kFont[] = {
    {'0', ".###.#...##..###.#.###..##...#.###."}, {'1', "..#...##....#....#....#....#...###."},
    {'2', ".###.#...#....#...#...#...#...#####"}, {'3', "####.....#....#.###.....#....#####."},
    {'4', "...#...##..#.#.#..#.#####...#....#."}, {'5', "######....####.....#....##...#.###."},
    {'6', "..##..#...#....####.#...##...#.###."}, {'7', "#####....#...#...#...#....#....#..."},
    {'8', ".###.#...##...#.###.#...##...#.###."}, {'9', ".###.#...##...#.####....#...#..##.."},
    {'-', "................###................"}, {'.', "..........................##...##.."},
    {'+', ".......#....#..#####..#....#......."}, {'(', "...#...#...#....#....#.....#.....#."},
    {')', ".#.....#.....#....#....#...#...#..."}, {'_', "..............................#####"},
    {'a', "...........###.....#.#####...#.####"}, {'b', "#....#....#.##.##..##...##...#####."},
    {'c', "...........###.#....#....#...#.###."}, {'d', "....#....#.##.##..###...##...#.####"},
    {'e', "...........###.#...#######.....###."}, {'f', "..##..#..#.#...###...#....#....#..."},
    {'g', ".....####.#...##...#.####....#.###."}, {'h', "#....#....#.##.##..##...##...##...#"},
    {'i', "..#........##....#....#....#...###."}, {'j', "...#........##....#....#.#..#..##.."},
    {'k', "#....#....#..#.#.#..##...#.#..#..#."}, {'l', ".##....#....#....#....#....#...###."},
    {'m', "..........##.#.#.#.##.#.##...##...#"}, {'n', "..........#.##.##..##...##...##...#"},
    {'o', "...........###.#...##...##...#.###."}, {'p', "..........####.#...#####.#....#...."},
    {'q', "...........##.##..##.####....#....#"}, {'r', "..........#.##.##..##....#....#...."},
    {'s', "...........###.#.....###.....#####."}, {'t', ".#....#...###...#....#....#..#..##."},
    {'u', "..........#...##...##...##..##.##.#"}, {'v', "..........#...##...##...#.#.#...#.."},
    {'w', "..........#...##...##.#.##.#.#.#.#."}, {'x', "..........#...#.#.#...#...#.#.#...#"},
    {'y', "..........#...##...#.####....#.###."}, {'z', "..........#####...#...#...#...#####"},
};

const char* glyph(char c) {
    const char lower = char(std::tolower(static_cast<unsigned char>(c)));
    for (const Glyph& g : kFont)
        if (g.c == lower) return g.rows;
    return nullptr;
}

constexpr int kAdvance = 6;  // glyph width 5 plus one column of spacing

using Colour = Srgb8;
constexpr Colour kBlack{0, 0, 0}, kWhite{255, 255, 255}, kGrid{220, 220, 220};
constexpr std::array<Colour, 10> kPalette{{{31, 119, 180},
                                           {255, 127, 14},
                                           {44, 160, 44},
                                           {214, 39, 40},
                                           {148, 103, 189},
                                           {140, 86, 75},
                                           {227, 119, 194},
                                           {127, 127, 127},
                                           {188, 189, 34},
                                           {23, 190, 207}}};

class Canvas {
public:
    Canvas(int w, int h) : m_image(w, h) {
        std::fill(m_image.pixels.begin(), m_image.pixels.end(), kWhite);
    }

    void set(int x, int y, Colour c) {
        if (x >= 0 && y >= 0 && x < m_image.width && y < m_image.height) m_image.at(x, y) = c;
    }
    void square(int cx, int cy, int half, Colour c) {
        for (int y = cy - half; y <= cy + half; ++y)
            for (int x = cx - half; x <= cx + half; ++x) set(x, y, c);
    }
    // Bresenham, each step stamped with a square of the given half width (0: one pixel).
    void line(int x0, int y0, int x1, int y1, Colour c, int half = 0) {
        const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
        const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
        for (int err = dx + dy;;) {
            square(x0, y0, half, c);
            if (x0 == x1 && y0 == y1) return;
            const int e2 = 2 * err;
            if (e2 >= dy) {
                err += dy;
                x0 += sx;
            }
            if (e2 <= dx) {
                err += dx;
                y0 += sy;
            }
        }
    }
    // Text with its top-left corner at (x, y), each font pixel a scale x scale block.
    void text(int x, int y, const std::string& s, Colour c, int scale) {
        for (char ch : s) {
            if (const char* rows = glyph(ch)) {
                for (int r = 0; r < 7; ++r)
                    for (int k = 0; k < 5; ++k)
                        if (rows[r * 5 + k] == '#')
                            for (int v = 0; v < scale * scale; ++v)
                                set(x + k * scale + v % scale, y + r * scale + v / scale, c);
            }
            x += kAdvance * scale;
        }
    }
    Image8 take() { return std::move(m_image); }

private:
    Image8 m_image;
};

// Whole decades [lo, hi] (log10) covering the values, at least one decade wide.
std::pair<int, int> decades(std::vector<double> v) {
    if (v.empty()) return {0, 1};
    const auto [mn, mx] = std::minmax_element(v.begin(), v.end());
    const int lo = int(std::floor(std::log10(*mn))), hi = int(std::ceil(std::log10(*mx)));
    return {lo, std::max(hi, lo + 1)};
}

// Pixel rectangle of the data area and the decades it shows.
struct Frame {
    int left, top, right, bottom;
    std::pair<int, int> x, y;
    int px(double v) const {
        const double t = (std::log10(v) - x.first) / double(x.second - x.first);
        return left + int(std::lround(t * (right - left)));
    }
    int py(double v) const {
        const double t = (std::log10(v) - y.first) / double(y.second - y.first);
        return bottom - int(std::lround(t * (bottom - top)));
    }
};

// "10" with the exponent raised after it, right-aligned at x (y axis) or centred (x axis).
void decade_label(Canvas& c, int x, int y, int k, bool centred) {
    const std::string e = std::to_string(k);
    const int w = text_width("10", 2) + 2 + text_width(e, 1);
    const int x0 = centred ? x - w / 2 : x - w;
    c.text(x0, y, "10", kBlack, 2);
    c.text(x0 + text_width("10", 2) + 2, y - 4, e, kBlack, 1);
}

void draw_axes(Canvas& c, const Frame& f) {
    for (int k = f.x.first; k <= f.x.second; ++k) {
        for (int m = 1; m <= 9 && (m == 1 || k < f.x.second); ++m) {
            const int x = f.px(m * std::pow(10.0, k));
            if (m == 1) c.line(x, f.top, x, f.bottom, kGrid);
            c.line(x, f.bottom, x, f.bottom + (m == 1 ? 8 : 4), kBlack);
        }
        decade_label(c, f.px(std::pow(10.0, k)), f.bottom + 16, k, true);
    }
    for (int k = f.y.first; k <= f.y.second; ++k) {
        for (int m = 1; m <= 9 && (m == 1 || k < f.y.second); ++m) {
            const int y = f.py(m * std::pow(10.0, k));
            if (m == 1) c.line(f.left, y, f.right, y, kGrid);
            c.line(f.left - (m == 1 ? 8 : 4), y, f.left, y, kBlack);
        }
        decade_label(c, f.left - 12, f.py(std::pow(10.0, k)) - 7, k, false);
    }
    c.line(f.left, f.bottom, f.right, f.bottom, kBlack);
    c.line(f.left, f.top, f.left, f.bottom, kBlack);
    c.line(f.right, f.top, f.right, f.bottom, kBlack);
    c.line(f.left, f.top, f.right, f.top, kBlack);
}

void draw_series(Canvas& c, const Frame& f, const PlotSeries& s, Colour colour) {
    std::vector<std::pair<int, int>> px;
    for (const auto& [x, y] : s.points)
        if (x > 0 && y > 0 && std::isfinite(x) && std::isfinite(y))
            px.push_back({f.px(x), f.py(y)});
    for (std::size_t i = 1; i < px.size(); ++i)
        c.line(px[i - 1].first, px[i - 1].second, px[i].first, px[i].second, colour, 1);
    for (const auto& [x, y] : px) c.square(x, y, 4, colour);
}

void draw_legend(Canvas& c, const Frame& f, const std::vector<PlotSeries>& series) {
    int y = f.top + 8;
    for (std::size_t i = 0; i < series.size(); ++i, y += 24) {
        const Colour colour = kPalette[i % kPalette.size()];
        const int x = f.right + 16;
        c.line(x, y + 7, x + 28, y + 7, colour, 1);
        c.square(x + 14, y + 7, 4, colour);
        c.text(x + 36, y, series[i].name, kBlack, 2);
    }
}

}  // namespace

int text_width(const std::string& text, int scale) {
    return text.empty() ? 0 : (int(text.size()) * kAdvance - 1) * scale;
}

Image8 draw_log_log(const LogLogPlot& plot) {
    if (plot.width < 400 || plot.height < 300)
        throw std::invalid_argument("plot: at least 400 x 300 pixels are needed");
    std::vector<double> xs, ys;
    for (const PlotSeries& s : plot.series)
        for (const auto& [x, y] : s.points)
            if (x > 0 && y > 0 && std::isfinite(x) && std::isfinite(y)) {
                xs.push_back(x);
                ys.push_back(y);
            }
    const Frame f{100, 40, plot.width - 180, plot.height - 70, decades(xs), decades(ys)};
    Canvas c(plot.width, plot.height);
    draw_axes(c, f);
    for (std::size_t i = 0; i < plot.series.size(); ++i)
        draw_series(c, f, plot.series[i], kPalette[i % kPalette.size()]);
    draw_legend(c, f, plot.series);
    c.text((f.left + f.right - text_width(plot.x_label, 2)) / 2, plot.height - 24, plot.x_label,
           kBlack, 2);
    c.text(f.left - 40, f.top - 28, plot.y_label, kBlack, 2);
    return c.take();
}

}  // namespace hmcr
