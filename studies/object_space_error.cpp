#include "studies/object_space_error.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "rays/embree_scene.h"
#include "viz/shaded_tracer.h"

namespace hmcr {
namespace {

// Sums of one block of reference triangles; blocks are fixed, so the total is deterministic.
struct Partial {
    double squared_error = 0, squared_reference = 0;
    std::size_t samples = 0, unmatched = 0, nearest = 0;

    void add(const Partial& o) {
        squared_error += o.squared_error;
        squared_reference += o.squared_reference;
        samples += o.samples;
        unmatched += o.unmatched;
        nearest += o.nearest;
    }
};

// The closest point of triangle (a, b, c) to p as barycentric weights of b and c (Ericson,
// Real-Time Collision Detection, 5.1.5: the Voronoi regions of vertices, edges and face).
Vec2 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return {0, 0};
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return {1, 0};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return {d1 / (d1 - d3), 0};
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return {0, 1};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return {0, d2 / (d2 - d6)};
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {1 - w, w};
    }
    const double denominator = va + vb + vc;
    return {vb / denominator, vc / denominator};
}

// Looks up the solution's Gouraud radiosity at a point of a given patch (see the header).
struct SolutionProbe {
    const ShadedTracer& tracer;
    const ShadedMesh& solution;
    double delta;
    // The solution's cells of each (patch, side), for points the rays do not find.
    std::vector<std::size_t> first;  // by 2 * patch + side, into `cells`
    std::vector<std::size_t> cells;

    SolutionProbe(const ShadedTracer& t, const ShadedMesh& s, double d)
        : tracer(t), solution(s), delta(d) {
        std::size_t keys = 0;
        for (std::size_t c = 0; c < s.cell_count(); ++c) {
            keys = std::max(keys, key(s.patch_id[c], cell_side(s, c)) + 1);
        }
        first.assign(keys + 1, 0);
        for (std::size_t c = 0; c < s.cell_count(); ++c)
            ++first[key(s.patch_id[c], cell_side(s, c)) + 1];
        for (std::size_t k = 0; k < keys; ++k) first[k + 1] += first[k];
        cells.resize(s.cell_count());
        std::vector<std::size_t> next(first.begin(), first.end() - 1);
        for (std::size_t c = 0; c < s.cell_count(); ++c)
            cells[next[key(s.patch_id[c], cell_side(s, c))]++] = c;
    }
    static std::size_t key(int patch, std::uint8_t side) { return 2 * std::size_t(patch) + side; }

    // `normal` points out of the reference cell's side, so the ray from in front meets the
    // solution's cell of that side.
    std::optional<Rgb> at(const Vec3& p, const Vec3& normal, int patch, std::uint8_t side,
                          bool& by_ray) const {
        by_ray = true;
        for (const double from : {1.0, -1.0}) {
            const auto hit = tracer.hit_along(p + from * delta * normal, -from * normal);
            if (hit && solution.patch_id[hit->cell] == patch &&
                cell_side(solution, hit->cell) == side) {
                return hit->radiosity;
            }
        }
        by_ray = false;
        return nearest(p, patch, side);
    }

    // The Gouraud value at the closest point of the patch side's cells within delta of p: a
    // point at an edge between patches, which the tracer's float arithmetic may put on the
    // neighbour (a light tile in a ceiling), is still its own patch's.
    std::optional<Rgb> nearest(const Vec3& p, int patch, std::uint8_t side) const {
        const std::size_t k = key(patch, side);
        if (k + 1 >= first.size()) return std::nullopt;
        double best = delta * delta;
        std::optional<Rgb> value;
        for (std::size_t i = first[k]; i < first[k + 1]; ++i) {
            const std::size_t c = cells[i];
            const auto v0 = solution.offsets[c], end = solution.offsets[c + 1];
            const auto corner = [&](std::int64_t s) { return solution.connectivity[s]; };
            for (auto s = v0 + 1; s + 1 < end; ++s) {
                const Vec3 &a = solution.points[corner(v0)], &b = solution.points[corner(s)],
                           &d = solution.points[corner(s + 1)];
                const Vec2 w = closest_on_triangle(p, a, b, d);
                const Vec3 q = (1 - w.x() - w.y()) * a + w.x() * b + w.y() * d;
                const double distance = (q - p).squaredNorm();
                if (distance >= best) continue;
                best = distance;
                value = Rgb((1 - w.x() - w.y()) * solution.point_radiosity[corner(v0)] +
                            w.x() * solution.point_radiosity[corner(s)] +
                            w.y() * solution.point_radiosity[corner(s + 1)]);
            }
        }
        return value;
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
            out.push_back((4 * x + y + z) / (6.0 * k));  // (2/3, 1/6, 1/6), in units of 1/k
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

Partial integrate_triangle(const ShadedMesh& ref, const FanTriangle& tri, const Vec3& normal,
                           const SolutionProbe& probe, const std::vector<Vec2>& points,
                           const ObjectErrorOptions& options) {
    const Vec3& p0 = ref.points[tri.points[0]];
    const Vec3 e1 = ref.points[tri.points[1]] - p0, e2 = ref.points[tri.points[2]] - p0;
    const double area = 0.5 * e1.cross(e2).norm();
    Partial sum;
    if (!(area > 0)) return sum;  // the fan's zero-area triangles cover nothing
    const Rgb& b0 = ref.point_radiosity[tri.points[0]];
    const Rgb& b1 = ref.point_radiosity[tri.points[1]];
    const Rgb& b2 = ref.point_radiosity[tri.points[2]];
    const double weight = area / double(points.size());
    const int patch = ref.patch_id[tri.cell];
    const std::uint8_t side = cell_side(ref, tri.cell);
    const std::vector<Rgb>& emission = side == kBack ? options.back_emission : options.emission;
    for (const Vec2& st : points) {
        const Rgb b_ref = (1 - st.x() - st.y()) * b0 + st.x() * b1 + st.y() * b2;
        bool by_ray = true;
        const auto b_sol = probe.at(p0 + st.x() * e1 + st.y() * e2, normal, patch, side, by_ray);
        if (!b_sol) ++sum.unmatched;
        if (b_sol && !by_ray) ++sum.nearest;
        sum.squared_error += weight * (b_sol.value_or(Rgb::Zero()) - b_ref).matrix().squaredNorm();
        const Rgb reflected = emission.empty() ? b_ref : Rgb(b_ref - emission[std::size_t(patch)]);
        sum.squared_reference += weight * reflected.matrix().squaredNorm();
        ++sum.samples;
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
    s << "ObjectError{relative_l2=" << relative_l2 << ", samples=" << samples
      << ", unmatched=" << unmatched << ", nearest=" << nearest << "}";
    return s.str();
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
    const std::vector<FanTriangle> triangles = fan_triangulate(reference);
    std::vector<Vec3> normals(reference.cell_count());
    for (std::size_t c = 0; c < normals.size(); ++c) normals[c] = cell_normal(reference, c);
    const SolutionProbe probe{tracer, solution, 10 * tracer.offset()};
    const std::vector<Vec2> points = quadrature_points(options.subdivisions);

    constexpr std::size_t kBlock = 256;
    std::vector<Partial> blocks((triangles.size() + kBlock - 1) / kBlock);
    tbb::parallel_for(std::size_t(0), blocks.size(), [&](std::size_t b) {
        set_tracing_float_mode();
        const std::size_t end = std::min(triangles.size(), (b + 1) * kBlock);
        for (std::size_t t = b * kBlock; t < end; ++t) {
            const FanTriangle& tri = triangles[t];
            blocks[b].add(
                integrate_triangle(reference, tri, normals[tri.cell], probe, points, options));
        }
    });
    Partial total;
    for (const Partial& p : blocks) total.add(p);

    ObjectError out{0, total.samples, total.unmatched, total.nearest};
    if (total.squared_reference > 0) {
        out.relative_l2 = std::sqrt(total.squared_error / total.squared_reference);
    } else if (total.squared_error > 0) {
        out.relative_l2 = std::numeric_limits<double>::infinity();
    }
    return out;
}

}  // namespace hmcr
