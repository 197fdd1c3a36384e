// The exposure rule of every image command (`render`, `trace`): a fixed --exposure, else the one
// a reference folder (`hmcr reference` or `hmcr trace-reference`) fixed for the view, else one
// from the image itself (exposure_from: its mean non-background luminance to middle grey).
#pragma once

#include <string>

#include "viz/image.h"

namespace hmcr {

struct ExposureChoice {
    double exposure = 0;    // > 0: fixed
    std::string reference;  // a reference folder, or empty
};

// The fixed exposure of the view, or 0 when the image is to choose its own. Asked before the
// image is made, so that a bad reference folder fails at once; throws InputError naming
// reference.json when it has no such view.
double fixed_exposure(const ExposureChoice& choice, const std::string& view);
// `fixed` when positive, else exposure_from(image).
double image_exposure(double fixed, const Image& image);

}  // namespace hmcr
