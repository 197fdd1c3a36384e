#include "studies/cell_files.h"

namespace hmcr {

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
