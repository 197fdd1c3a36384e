#include "app/exposure.h"

#include <algorithm>

#include "common/error.h"
#include "studies/reference.h"
#include "viz/renderer.h"

namespace hmcr {

double fixed_exposure(const ExposureChoice& choice, const std::string& view) {
    if (!choice.reference.empty()) {
        const std::filesystem::path dir(choice.reference);
        const auto exposure = read_reference_exposures(dir);
        if (!exposure.count(view)) {
            throw InputError((dir / "reference.json").string(), "no view " + quote(view));
        }
        return exposure.at(view);
    }
    return std::max(0.0, choice.exposure);
}

double image_exposure(double fixed, const Image& image) {
    return fixed > 0 ? fixed : exposure_from(image);
}

}  // namespace hmcr
