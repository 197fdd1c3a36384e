// Plots without a display (docs/design.md §6): a small rasteriser drawing straight into an Image8
// (lines, square markers, a built-in 5x7 bitmap font), so that a study can write its PNG plots
// on a headless machine with no plotting library.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "image/image.h"

namespace hmcr {

struct PlotSeries {
    std::string name;                               // legend entry
    std::vector<std::pair<double, double>> points;  // (x, y), drawn in order; non-positive skipped
};

struct LogLogPlot {
    std::string x_label, y_label;
    std::vector<PlotSeries> series;  // each a polyline with square markers in its own colour
    int width = 800, height = 560;
};

// Both axes logarithmic, spanning whole decades around the data, with a labelled tick and a
// grid line at every decade, minor ticks at 2..9, and a legend on the right. Characters the font
// lacks are drawn as blanks. Throws std::invalid_argument when the size is too small to fit.
Image8 draw_log_log(const LogLogPlot& plot);

// Exposed for tests: the width in pixels of `text` at the given scale.
int text_width(const std::string& text, int scale);

}  // namespace hmcr
