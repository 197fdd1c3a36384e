// The headless plot rasteriser (studies/plot.h): series land where the log-log axes put them,
// in distinct colours, and the picture has the requested size.
#include "studies/plot.h"

#include <gtest/gtest.h>

#include <set>

namespace hmcr::test {
namespace {

// Pixels whose colour is neither white, black nor grey (series and legend colours).
std::set<Srgb8> colours_of(const Image8& image) {
    std::set<Srgb8> out;
    for (const Srgb8& p : image.pixels)
        if (!(p[0] == p[1] && p[1] == p[2])) out.insert(p);
    return out;
}

TEST(Plot, DrawsEachSeriesInItsOwnColourOnDecadeAxes) {
    LogLogPlot plot;
    plot.x_label = "leaves";
    plot.y_label = "object error";
    plot.series = {{"power", {{1e3, 0.2}, {1e4, 0.05}}}, {"kl", {{2e3, 0.1}, {2e4, 0.02}}}};
    const Image8 image = draw_log_log(plot);
    EXPECT_EQ(image.width, plot.width);
    EXPECT_EQ(image.height, plot.height);
    EXPECT_EQ(colours_of(image).size(), 2u);
    // The axes span 1e3..1e5 and 1e-2..1; the first series' upper marker sits at x = 1e3 (the
    // left edge of the data area), and its colour is found there.
    int found = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 96; x <= 104; ++x) found += !(image.at(x, y)[0] == image.at(x, y)[1]);
    EXPECT_GT(found, 0);
}

TEST(Plot, SkipsPointsALogAxisCannotShowAndRejectsTinyImages) {
    LogLogPlot plot;
    plot.series = {{"zero", {{0, 1}, {10, -1}}}};
    EXPECT_TRUE(colours_of(draw_log_log(plot)).size() == 1u);  // only the legend
    plot.width = 100;
    EXPECT_THROW(draw_log_log(plot), std::invalid_argument);
    EXPECT_EQ(text_width("10", 1), 11);
}

}  // namespace
}  // namespace hmcr::test
