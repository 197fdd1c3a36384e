// SPDX-License-Identifier: Apache-2.0
// read_mtl: MTL statements -> the soup's materials (mtl_reader.h).
#include "meshes/mtl_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <vector>

#include "meshes/obj_lines.h"

namespace hmcr {
namespace {

// The MTL statements of the common readers that hmcr has no use for.
bool is_ignored_mtl_statement(std::string_view key) {
    static constexpr std::string_view kIgnored[] = {
        "Ka",    "Kt",   "Tf",   "Ns", "Ni", "d",  "Tr", "sharpness", "bump",  "disp",
        "decal", "refl", "norm", "Pr", "Pm", "Ps", "Pc", "Pcr",       "aniso", "anisor"};
    if (key.rfind("map_", 0) == 0) return true;
    return std::find(std::begin(kIgnored), std::end(kIgnored), key) != std::end(kIgnored);
}

// Unknown statements by name: how often, and the line of the first.
struct UnknownStatements {
    struct Seen {
        std::size_t count = 0;
        int first_line = 0;
    };
    std::map<std::string, Seen, std::less<>> by_name;

    void add(std::string_view name, int line) {
        auto it = by_name.find(name);
        if (it == by_name.end()) it = by_name.emplace(std::string(name), Seen{0, line}).first;
        ++it->second.count;
    }

    // One warning per name, in the order of their first lines.
    void report(const std::string& path, std::vector<std::string>& warnings) const {
        std::vector<std::pair<int, const std::string*>> order;
        for (const auto& [name, seen] : by_name) order.emplace_back(seen.first_line, &name);
        std::sort(order.begin(), order.end());
        for (const auto& [line, name] : order) {
            const std::size_t count = by_name.find(*name)->second.count;
            warnings.push_back(fmt::format("{}: unknown MTL statement {} ignored{}", at(path, line),
                                           quote(*name),
                                           count > 1 ? fmt::format(" ({} times)", count) : ""));
        }
    }
};

// The illumination models hmcr reads: 0, 1 and 2 reflect diffusely (Ks, 2's highlight, is not
// used), 3 adds Ks as an ideal mirror ("reflection on, ray trace on"). The others (glass,
// refraction, Fresnel, invisible shadow catchers) would be drawn wrongly, so they are refused.
constexpr int kMirrorIllum = 3;

// Ks and illum of a material as read: Ks becomes its mirror when the material ends with illum 3,
// whatever the order of the two statements.
struct SpecularStatements {
    Eigen::Vector3d ks{0, 0, 0};
    SourcePlace ks_at;
    int illum = 0;
};

// The MTL being read: the material its statements set (none before the first newmtl).
class MtlReader {
public:
    MtlReader(std::uint32_t file, PolygonSoup& soup, MaterialNames& names)
        : m_file(file), m_path(soup.files[file].string()), m_soup(soup), m_names(names) {}

    void statement(int line, Statement& s) {
        const std::string_view key = s.keyword();
        if (key == "newmtl") {
            define(line, s.rest_trimmed());
        } else if (key == "Kd" || key == "Ke" || key == "Ks") {
            colour(key, line, s);
        } else if (key == "illum") {
            illum(line, s);
        } else if (!is_ignored_mtl_statement(key)) {
            m_unknown.add(key, line);
        }
    }

    void finish() {
        for (const auto& [index, read] : m_specular) {
            if (read.illum != kMirrorIllum) continue;
            SoupMaterial& m = m_soup.materials[std::size_t(index)];
            m.material.ks = read.ks;
            m.ks = read.ks_at;
        }
        m_unknown.report(m_path, m_soup.warnings);
    }

private:
    // A name defined twice is refused: which of the two a face means is not known.
    void define(int line, std::string_view name) {
        if (name.empty()) fail_at_line(m_path, line, "newmtl needs a material name");
        const SourcePlace place{m_file, std::uint32_t(line)};
        const std::int32_t index = std::int32_t(m_soup.materials.size());
        auto [it, inserted] = m_names.try_emplace(std::string(name), MaterialName{index, place});
        if (!inserted) {
            fail_at_line(m_path, line,
                         fmt::format("material {} is defined again (first at {})", quote(name),
                                     m_soup.where(it->second.defined)));
        }
        m_current = index;
        m_soup.materials.push_back(
            {Material{std::string(name), {0, 0, 0}, {0, 0, 0}}, true, place, place, place});
        m_specular[index].ks_at = place;
    }

    void illum(int line, Statement& s) {
        const std::string_view token = s.next();
        if (token.empty() || !s.next().empty())
            fail_at_line(m_path, line, "'illum' needs one number");
        const double model = parse_obj_number(token, m_path, line);
        if (!(model == 0 || model == 1 || model == 2 || model == kMirrorIllum)) {
            fail_at_line(m_path, line,
                         fmt::format("illum {} is not supported: hmcr reads illum 0, 1 and 2 "
                                     "(diffuse; Ks unused) and 3 (Ks an ideal mirror)",
                                     token));
        }
        if (m_current >= 0) m_specular[m_current].illum = int(model);
    }

    // Kd, Ke or Ks of the current material (checked, then dropped, before the first newmtl).
    void colour(std::string_view key, int line, Statement& s) {
        std::array<std::string_view, 4> tokens;
        std::size_t n = 0;
        for (std::string_view t = s.next(); !t.empty(); t = s.next()) {
            if (n == tokens.size()) break;
            tokens[n++] = t;
        }
        if (n != 3)
            fail_at_line(m_path, line, fmt::format("'{}' needs three numbers (r g b)", key));
        Eigen::Vector3d value;
        for (int c = 0; c < 3; ++c)
            value[c] = parse_obj_number(tokens[std::size_t(c)], m_path, line);
        if (m_current < 0) return;
        const SourcePlace place{m_file, std::uint32_t(line)};
        if (key == "Ks") {
            m_specular[m_current].ks = value;
            m_specular[m_current].ks_at = place;
            return;
        }
        SoupMaterial& m = m_soup.materials[std::size_t(m_current)];
        (key == "Kd" ? m.material.kd : m.material.ke) = value;
        (key == "Kd" ? m.kd : m.ke) = place;
    }

    std::uint32_t m_file;
    std::string m_path;
    PolygonSoup& m_soup;
    MaterialNames& m_names;
    std::int32_t m_current = -1;                            // index in m_soup.materials
    std::map<std::int32_t, SpecularStatements> m_specular;  // by index in m_soup.materials
    UnknownStatements m_unknown;
};

}  // namespace

void read_mtl(std::string_view text, std::uint32_t file, PolygonSoup& soup, MaterialNames& names) {
    MtlReader reader(file, soup, names);
    for_each_statement(text, soup.files[file].string(),
                       [&](int line, Statement& s) { reader.statement(line, s); });
    reader.finish();
}

}  // namespace hmcr
