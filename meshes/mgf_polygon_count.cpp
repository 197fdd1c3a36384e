// SPDX-License-Identifier: Apache-2.0
#include "meshes/mgf_polygon_count.h"

#include <algorithm>
#include <limits>
#include <string_view>

#include "common/error.h"
#include "meshes/mgf_transform.h"

namespace hmcr {
namespace {

constexpr std::uint64_t kMany = std::numeric_limits<std::uint64_t>::max();

std::uint64_t plus(std::uint64_t a, std::uint64_t b) { return a > kMany - b ? kMany : a + b; }
std::uint64_t times(std::uint64_t a, std::uint64_t b) {
    return b != 0 && a > kMany / b ? kMany : a * b;
}

// The instances of the transformation in words[from..].
std::uint64_t instances(const MgfStatement& s, std::size_t from, const std::string& where) {
    const std::vector<std::string_view> args(s.words.begin() + std::ptrdiff_t(from), s.words.end());
    return std::uint64_t(parse_mgf_xf(args, where).instances());
}

}  // namespace

// The counts of the tessellations of mgf_shapes.cpp: a circle of `segments` points makes one
// band of `segments` polygons; a sphere is max(2, segments / 2) bands, a torus `segments` bands.
std::uint64_t mgf_entity_polygons(const std::vector<std::string>& words, int segments) {
    const std::string& e = words[0];
    const auto n = std::uint64_t(segments);
    if (e == "f") return 1;
    if (e == "sph") return std::max<std::uint64_t>(2, n / 2) * n;
    if (e == "cyl" || e == "cone" || e == "ring") return n;
    if (e == "torus") return n * n;
    if (e == "prism") return words.size();  // the base's corners (all but the length), + 2
    return 0;
}

std::uint64_t MgfPolygonCount::block(const MgfFile& file, std::size_t begin, std::size_t end) {
    m_open.assign(1, file.path);
    return count(file, begin, end);
}

std::uint64_t MgfPolygonCount::count(const MgfFile& file, std::size_t begin, std::size_t end) {
    const auto key = std::make_pair(&file, begin);
    if (auto it = m_counted.find(key); it != m_counted.end()) return it->second;
    // The polygons of each open xf block so far and its instances; [0] is the block itself.
    struct Open {
        std::uint64_t polygons = 0, instances = 1;
    };
    std::vector<Open> open(1);
    for (std::size_t k = begin; k < end; ++k) {
        const MgfStatement& s = file.statements[k];
        const std::string& e = s.words[0];
        std::uint64_t made = 0;
        if (e == "xf" && s.words.size() > 1) {
            open.push_back({0, instances(s, 1, at(file.path, s.line))});
            continue;
        } else if (e == "xf") {
            made = times(open.back().polygons, open.back().instances);
            open.pop_back();
        } else if (e == "i") {
            made = included(file, s);
        } else {
            made = mgf_entity_polygons(s.words, m_segments);
        }
        open.back().polygons = plus(open.back().polygons, made);
    }
    return m_counted[key] = open.front().polygons;
}

// The polygons of all instances of the file an `i` statement includes.
std::uint64_t MgfPolygonCount::included(const MgfFile& from, const MgfStatement& i) {
    const std::string where = at(from.path, i.line);
    const MgfFile& file = m_include(from, i, where);
    const std::uint64_t n = instances(i, 2, where);
    check_mgf_include(m_open, file.path, where);
    m_open.push_back(file.path);
    const std::uint64_t polygons = count(file, 0, file.statements.size());
    m_open.pop_back();
    return times(polygons, n);
}

}  // namespace hmcr
