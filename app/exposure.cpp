// SPDX-License-Identifier: Apache-2.0
#include "app/exposure.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>

#include "common/error.h"
#include "studies/reference.h"
#include "viz/renderer.h"

namespace hmcr {

void add_exposure_flags(CLI::App& command, ExposureChoice& choice) {
    auto* exposure = command.add_option("--exposure", choice.exposure,
                                        "fixed exposure (default: from this image)");
    command
        .add_option("--reference", choice.reference, "use the exposure of this reference folder")
        ->excludes(exposure);
}

void note_exposure_given(const CLI::App& command, ExposureChoice& choice) {
    choice.given = command.count("--exposure") > 0;
}

void check_exposure(const ExposureChoice& choice) {
    if (choice.given && !(choice.exposure > 0 && std::isfinite(choice.exposure))) {
        throw InputError(
            fmt::format("exposure must be a positive number, got {}", choice.exposure));
    }
}

std::vector<std::filesystem::path> exposure_inputs(const ExposureChoice& choice) {
    if (choice.reference.empty()) return {};
    return {std::filesystem::path(choice.reference) / "reference.json"};
}

double fixed_exposure(const ExposureChoice& choice, const std::string& view) {
    if (!choice.reference.empty()) {
        const std::filesystem::path dir(choice.reference);
        const auto exposure = read_reference_exposures(dir);
        if (!exposure.count(view)) {
            throw InputError((dir / "reference.json").string(), "no view " + quote(view));
        }
        return exposure.at(view);
    }
    return choice.given ? choice.exposure : 0.0;
}

double image_exposure(double fixed, const Image& image) {
    return fixed > 0 ? fixed : exposure_from(image);
}

void warn_if_black(const Image& image, double exposure, const std::string& png,
                   const std::string& scene, const std::string& view, bool quiet) {
    if (quiet) return;
    const Image8 bytes = quantise(image, exposure);
    for (const Srgb8& p : bytes.pixels) {
        if (p[0] > 0 || p[1] > 0 || p[2] > 0) return;
    }
    fmt::print(stderr,
               "hmcr: warning: {} is black: view {} sees no lit surface (`hmcr info --bounds {}` "
               "prints the scene's bounding box, up axis and views)\n",
               png, quote(view), scene);
}

}  // namespace hmcr
