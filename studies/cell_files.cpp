// SPDX-License-Identifier: Apache-2.0
#include "studies/cell_files.h"

#include <limits>

namespace hmcr {

void check_study_size(std::uint64_t per_seed, int seeds, std::uint64_t first_seed) {
    // In floating point: the product of a long list and a billion seeds cannot wrap.
    const double cells = double(per_seed) * double(seeds);
    if (cells > double(kMaxStudyCells)) {
        throw InputError(
            fmt::format("study: {} x {} seeds = {:.0f} cells, more than the {} a "
                        "study may have",
                        per_seed, seeds, cells, kMaxStudyCells));
    }
    if (std::uint64_t(seeds - 1) > std::numeric_limits<std::uint64_t>::max() - first_seed) {
        throw InputError(fmt::format("study: seeds {} to {} + {} pass the largest seed, 2^64 - 1",
                                     first_seed, first_seed, seeds - 1));
    }
}

std::string settings_difference(const nlohmann::json& old_settings, const nlohmann::json& now) {
    if (!old_settings.is_object()) return "the file records none";
    std::string out;
    for (const auto& entry : nlohmann::json::diff(old_settings, now)) {
        const std::string path = entry.value("path", "");
        out += (out.empty() ? "" : ", ") + path.substr(1) + " is " +
               (entry.contains("value") ? entry["value"].dump() : "(none)") + " now";
    }
    return out;
}

}  // namespace hmcr
