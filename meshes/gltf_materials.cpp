// SPDX-License-Identifier: Apache-2.0
// read_gltf_materials (gltf_materials.h).
#include "meshes/gltf_materials.h"

#include <fmt/format.h>
#include <tiny_gltf.h>

#include <cmath>
#include <vector>

namespace hmcr {
namespace {

constexpr const char* kEmissiveStrength = "KHR_materials_emissive_strength";

Eigen::Vector3d rgb(const std::vector<double>& factor, std::size_t size, const std::string& where,
                    const char* name) {
    if (factor.size() != size) {
        throw InputError(where,
                         fmt::format("{} has {} numbers, not {}", name, factor.size(), size));
    }
    for (const double x : factor) {
        if (!std::isfinite(x)) throw InputError(where, fmt::format("{} is not finite", name));
    }
    return {factor[0], factor[1], factor[2]};
}

double emissive_strength(const tinygltf::Material& m, const std::string& where) {
    const auto it = m.extensions.find(kEmissiveStrength);
    if (it == m.extensions.end() || !it->second.Has("emissiveStrength")) return 1;
    const tinygltf::Value& strength = it->second.Get("emissiveStrength");
    const double value = strength.IsNumber() ? strength.GetNumberAsDouble() : -1;
    if (!(value >= 0 && std::isfinite(value))) {
        throw InputError(where, fmt::format("{}: emissiveStrength must be a number of at least 0",
                                            kEmissiveStrength));
    }
    return value;
}

// What the material sets that hmcr does not read, for one warning.
std::vector<std::string> ignored(const tinygltf::Material& m) {
    std::vector<std::string> names;
    const auto& pbr = m.pbrMetallicRoughness;
    if (pbr.baseColorTexture.index >= 0) names.emplace_back("baseColorTexture");
    if (m.emissiveTexture.index >= 0) names.emplace_back("emissiveTexture");
    if (pbr.baseColorFactor.size() == 4 && pbr.baseColorFactor[3] != 1) {
        names.emplace_back("alpha");
    }
    for (const auto& [name, value] : m.extensions) {
        if (name != kEmissiveStrength) names.push_back(name);
    }
    return names;
}

}  // namespace

void read_gltf_materials(const tinygltf::Model& model, std::uint32_t file, PolygonSoup& soup) {
    const std::string path = soup.files[file].string();
    const SourcePlace place{file, 0};
    for (std::size_t k = 0; k < model.materials.size(); ++k) {
        const tinygltf::Material& m = model.materials[k];
        const std::string where = fmt::format("{}: materials[{}]", path, k);
        const std::string name = m.name.empty() ? fmt::format("materials[{}]", k) : m.name;
        const double metallic = m.pbrMetallicRoughness.metallicFactor;
        if (!(metallic >= 0 && metallic <= 1)) {
            throw InputError(where, "metallicFactor must be in [0, 1]");
        }
        const Eigen::Vector3d base =
            rgb(m.pbrMetallicRoughness.baseColorFactor, 4, where, "baseColorFactor");
        Material material{
            name, base * (1 - metallic),
            rgb(m.emissiveFactor, 3, where, "emissiveFactor") * emissive_strength(m, where)};
        if (metallic > 0) {
            soup.warnings.push_back(fmt::format(
                "{} ({}): metallicFactor {} (1 unless the file says): hmcr absorbs the metal "
                "part, its reflectance is the base colour times {}",
                where, quote(name), metallic, 1 - metallic));
        }
        if (const auto names = ignored(m); !names.empty()) {
            soup.warnings.push_back(fmt::format("{} ({}): {} ignored: hmcr reads the factors",
                                                where, quote(name), fmt::join(names, ", ")));
        }
        SoupMaterial soup_material{std::move(material), true, place, place, place};
        soup_material.sides = m.doubleSided ? 2 : 1;
        soup.materials.push_back(std::move(soup_material));
    }
}

}  // namespace hmcr
