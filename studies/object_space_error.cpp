// SPDX-License-Identifier: Apache-2.0
#include "studies/object_space_error.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "radiosity/polynomial_mesh.h"
#include "rays/embree_scene.h"
#include "studies/solution_probe.h"
#include "viz/cell_triangles.h"
#include "viz/shaded_tracer.h"

namespace hmcr {
namespace {

// Sums of one block of reference triangles; blocks are fixed, so the total is deterministic.
struct Partial {
    double squared_error = 0, squared_reference = 0;
    std::size_t samples = 0, unmatched = 0, nearest = 0, unlit = 0;

    void add(const Partial& o) {
        squared_error += o.squared_error;
        squared_reference += o.squared_reference;
        samples += o.samples;
        unmatched += o.unmatched;
        nearest += o.nearest;
        unlit += o.unlit;
    }
    void count(SolutionProbe::Found found) {
        ++samples;
        unmatched += found == SolutionProbe::Found::unmatched;
        nearest += found == SolutionProbe::Found::nearest;
        unlit += found == SolutionProbe::Found::unlit;
    }
};

// Unit normal of a planar polygon (Newell's method), zero for a degenerate one.
Vec3 cell_normal(const ShadedMesh& m, std::size_t cell) {
    Vec3 sum = Vec3::Zero();
    const auto first = m.offsets[cell], last = m.offsets[cell + 1];
    for (auto s = first; s < last; ++s) {
        const auto next = s + 1 < last ? s + 1 : first;
        sum += m.points[m.connectivity[s]].cross(m.points[m.connectivity[next]]);
    }
    const double n = sum.norm();
    return n > 0 ? Vec3(sum / n) : Vec3::Zero();
}

// The 3 k^2 quadrature points of a triangle as the weights (s, t) of its second and third
// vertex; each carries 1 / (3 k^2) of the triangle's area.
std::vector<Vec2> quadrature_points(int k) {
    std::vector<Vec2> out;
    const auto add_rule = [&](const Vec2& a, const Vec2& b, const Vec2& c) {
        for (const auto& [x, y, z] :
             {std::tuple(a, b, c), std::tuple(b, c, a), std::tuple(c, a, b)}) {
            out.emplace_back((4 * x + y + z) / (6.0 * k));  // (2/3, 1/6, 1/6), in units of 1/k
        }
    };
    for (int i = 0; i < k; ++i) {
        for (int j = 0; i + j < k; ++j) {
            add_rule(Vec2(i, j), Vec2(i + 1, j), Vec2(i, j + 1));  // the upward sub-triangle
            if (i + j + 2 <= k) add_rule(Vec2(i + 1, j), Vec2(i + 1, j + 1), Vec2(i, j + 1));
        }
    }
    return out;
}

Partial integrate_triangle(const ShadedMesh& ref, const CellTriangle& tri, const Vec3& normal,
                           const SolutionProbe& probe, const std::vector<Vec2>& points,
                           const ObjectErrorOptions& options) {
    const Vec3& p0 = ref.points[tri.points[0]];
    const Vec3 e1 = ref.points[tri.points[1]] - p0, e2 = ref.points[tri.points[2]] - p0;
    const double area = 0.5 * e1.cross(e2).norm();
    Partial sum;
    if (!(area > 0)) return sum;  // a polygon that is not convex may leave one
    const double weight = area / double(points.size());
    const int patch = ref.patch_id[tri.cell];
    const std::uint8_t side = cell_side(ref, tri.cell);
    const std::vector<Rgb>& emission = side == kBack ? options.back_emission : options.emission;
    const Rgb e = emission.empty() ? Rgb::Zero() : emission[std::size_t(patch)];
    const std::array<std::size_t, 3> corners = {tri.points[0], tri.points[1], tri.points[2]};
    for (const Vec2& st : points) {
        const Rgb b_ref = radiosity_at(ref, tri.cell, corners, st.x(), st.y());
        const auto b_sol = probe.value(p0 + st.x() * e1 + st.y() * e2, normal, patch, side, e);
        sum.count(b_sol.found);
        sum.squared_error += weight * (b_sol.radiosity - b_ref).matrix().squaredNorm();
        sum.squared_reference += weight * (b_ref - e).matrix().squaredNorm();
    }
    return sum;
}

void check_patch_ids(const ShadedMesh& m, const char* which) {
    if (m.patch_id.size() != m.cell_count()) {
        throw std::invalid_argument(std::string("the ") + which + " needs one patch_id per cell");
    }
}

}  // namespace

std::string ObjectErrorOptions::to_string() const {
    return "ObjectErrorOptions{subdivisions=" + std::to_string(subdivisions) + "}";
}

std::string ObjectError::to_string() const {
    std::ostringstream s;
    s << "ObjectError{relative_l2=" << relative_l2 << ", standard_error=" << standard_error
      << ", samples=" << samples << ", unmatched=" << unmatched << ", nearest=" << nearest
      << ", unlit=" << unlit << "}";
    return s.str();
}

void SideErrors::add(std::uint32_t patch, std::uint8_t side, double squared_error) {
    const std::size_t key = 2 * std::size_t(patch) + side;
    if (key >= m_sum.size()) m_sum.resize(key + 1, 0.0);
    m_sum[key] += squared_error;
}

std::vector<PatchError> SideErrors::largest(double total) const {
    std::vector<PatchError> all;
    if (!(total > 0)) return all;
    for (std::size_t k = 0; k < m_sum.size(); ++k) {
        if (m_sum[k] != 0)
            all.push_back({std::uint32_t(k / 2), std::uint8_t(k % 2), m_sum[k] / total});
    }
    // Largest first; ties by patch and side, so the list is the same for any order of adding.
    const auto before = [](const PatchError& a, const PatchError& b) {
        if (a.share != b.share) return a.share > b.share;
        return std::pair(a.patch, a.side) < std::pair(b.patch, b.side);
    };
    const std::size_t n = std::min(all.size(), kLargestPatches);
    std::partial_sort(all.begin(), all.begin() + std::ptrdiff_t(n), all.end(), before);
    all.resize(n);
    return all;
}

ObjectError object_space_error(const ShadedMesh& solution, const ShadedMesh& reference,
                               const ObjectErrorOptions& options) {
    return object_space_error(ShadedTracer(solution), solution, reference, options);
}

ObjectError object_space_error(const ShadedTracer& tracer, const ShadedMesh& solution,
                               const ShadedMesh& reference, const ObjectErrorOptions& options) {
    if (options.subdivisions < 1 || options.subdivisions > 64) {
        throw std::invalid_argument("subdivisions must be in [1, 64]: " + options.to_string());
    }
    check_patch_ids(solution, "solution");
    check_patch_ids(reference, "reference");
    for (std::size_t c = 0; c < reference.cell_count(); ++c) {
        const auto p = std::size_t(reference.patch_id[c]);
        const bool back = cell_side(reference, c) == kBack;
        const std::vector<Rgb>& e = back ? options.back_emission : options.emission;
        if (!options.emission.empty() && p >= e.size()) {
            throw std::invalid_argument(std::string(back ? "back " : "") +
                                        "emission has no entry for patch " + std::to_string(p));
        }
    }
    const std::vector<CellTriangle> triangles = triangulate_cells(reference);
    std::vector<Vec3> normals(reference.cell_count());
    for (std::size_t c = 0; c < normals.size(); ++c) normals[c] = cell_normal(reference, c);
    const SolutionProbe probe(tracer, solution);
    const std::vector<Vec2> points = quadrature_points(options.subdivisions);

    constexpr std::size_t kBlock = 256;
    std::vector<Partial> blocks((triangles.size() + kBlock - 1) / kBlock);
    std::vector<double> triangle_error(triangles.size(), 0.0);
    tbb::parallel_for(std::size_t(0), blocks.size(), [&](std::size_t b) {
        set_tracing_float_mode();
        const std::size_t end = std::min(triangles.size(), (b + 1) * kBlock);
        for (std::size_t t = b * kBlock; t < end; ++t) {
            const CellTriangle& tri = triangles[t];
            const Partial p =
                integrate_triangle(reference, tri, normals[tri.cell], probe, points, options);
            triangle_error[t] = p.squared_error;
            blocks[b].add(p);
        }
    });
    Partial total;
    for (const Partial& p : blocks) total.add(p);
    SideErrors by_side;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const std::uint32_t cell = triangles[t].cell;
        by_side.add(std::uint32_t(reference.patch_id[cell]), cell_side(reference, cell),
                    triangle_error[t]);
    }

    ObjectError out;
    out.samples = total.samples;
    out.unmatched = total.unmatched;
    out.nearest = total.nearest;
    out.unlit = total.unlit;
    out.largest = by_side.largest(total.squared_error);
    if (total.squared_reference > 0) {
        out.relative_l2 = std::sqrt(total.squared_error / total.squared_reference);
    } else if (total.squared_error > 0) {
        out.relative_l2 = std::numeric_limits<double>::infinity();
    }
    return out;
}

}  // namespace hmcr
