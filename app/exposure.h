// SPDX-License-Identifier: Apache-2.0
// The exposure rule of every image command (`render`, `trace`): a fixed --exposure, else the one
// a reference folder (`hmcr reference` or `hmcr trace-reference`) fixed for the view, else one
// from the image itself (exposure_from: its mean non-background luminance to middle grey).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "image/image.h"

namespace CLI {
class App;
}

namespace hmcr {

struct ExposureChoice {
    double exposure = 0;    // the fixed exposure, when given
    bool given = false;     // --exposure was on the command line
    std::string reference;  // a reference folder, or empty
};

// Adds --exposure and --reference (which exclude each other) to `command`; call
// note_exposure_given(command, choice) when the command runs.
void add_exposure_flags(CLI::App& command, ExposureChoice& choice);
void note_exposure_given(const CLI::App& command, ExposureChoice& choice);

// Throws InputError unless a given exposure is a positive finite number.
void check_exposure(const ExposureChoice& choice);
// The file the choice reads (the reference folder's reference.json), for refuse_overwriting.
std::vector<std::filesystem::path> exposure_inputs(const ExposureChoice& choice);

// The fixed exposure of the view, or 0 when the image is to choose its own. Asked before the
// image is made, so that a bad reference folder fails at once; throws InputError naming
// reference.json when it has no such view.
double fixed_exposure(const ExposureChoice& choice, const std::string& view);
// `fixed` when positive, else exposure_from(image).
double image_exposure(double fixed, const Image& image);

// One warning line, unless quiet, when every pixel of the image at this exposure is black (0 in
// all 8 bits): the view sees no lit surface (or the exposure hides it). `png` is the image's
// file, `scene` the scene as the user named it, for the `hmcr info --bounds` to run.
void warn_if_black(const Image& image, double exposure, const std::string& png,
                   const std::string& scene, const std::string& view, bool quiet);

}  // namespace hmcr
