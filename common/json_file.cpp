#include "common/json_file.h"

#include <fstream>
#include <stdexcept>

namespace hmcr {

nlohmann::json read_json_file(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw std::invalid_argument(path.string() + ": cannot open");
    try {
        return nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        throw std::invalid_argument(path.string() + ": " + e.what());
    }
}

}  // namespace hmcr
