// SPDX-License-Identifier: Apache-2.0
// Tessellation of MGF's curved primitives into bands of quads between circles (mgf_shapes.h).
#include "meshes/mgf_shapes.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace hmcr {
namespace {

// `segments` points of the circle of the radius around the centre, in the plane normal to the
// axis, counter-clockwise seen from the axis' tip. A radius of 0 gives the centre exactly.
std::vector<Eigen::Vector3d> circle(const Eigen::Vector3d& centre, const Eigen::Vector3d& axis,
                                    double radius, int segments) {
    const Eigen::Vector3d a = axis.normalized();
    const Eigen::Vector3d u = a.unitOrthogonal(), w = a.cross(u);
    std::vector<Eigen::Vector3d> points;
    for (int k = 0; k < segments; ++k) {
        const double angle = 2 * std::numbers::pi * k / segments;
        points.push_back(
            radius == 0 ? centre : centre + radius * (std::cos(angle) * u + std::sin(angle) * w));
    }
    return points;
}

// The quads between two circles of equal point count, facing away from the axis when `upper`
// lies further along it than `lower`; a corner repeated (a circle of radius 0) is left out.
void add_band(const std::vector<Eigen::Vector3d>& lower, const std::vector<Eigen::Vector3d>& upper,
              std::vector<MgfPolygon>& out) {
    const std::size_t n = lower.size();
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t next = (k + 1) % n;
        MgfPolygon quad;
        for (const Eigen::Vector3d& p : {lower[k], lower[next], upper[next], upper[k]}) {
            if (quad.empty() || quad.back() != p) quad.push_back(p);
        }
        if (quad.size() > 1 && quad.back() == quad.front()) quad.pop_back();
        if (quad.size() >= 3) out.push_back(std::move(quad));
    }
}

}  // namespace

std::vector<MgfPolygon> tessellate_sphere(const Eigen::Vector3d& centre, double radius,
                                          int segments) {
    const int bands = std::max(2, segments / 2);
    const Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
    std::vector<std::vector<Eigen::Vector3d>> rings;
    for (int i = 0; i <= bands; ++i) {  // from the north pole down
        const double polar = std::numbers::pi * i / bands;
        const double r = (i == 0 || i == bands) ? 0.0 : radius * std::sin(polar);
        rings.push_back(circle(centre + radius * std::cos(polar) * axis, axis, r, segments));
    }
    std::vector<MgfPolygon> out;
    for (int i = 0; i < bands; ++i) add_band(rings[std::size_t(i) + 1], rings[std::size_t(i)], out);
    return out;
}

std::vector<MgfPolygon> tessellate_cone(const Eigen::Vector3d& a, double ra,
                                        const Eigen::Vector3d& b, double rb, int segments) {
    const Eigen::Vector3d axis = b - a;
    std::vector<MgfPolygon> out;
    add_band(circle(a, axis, ra, segments), circle(b, axis, rb, segments), out);
    return out;
}

std::vector<MgfPolygon> tessellate_ring(const Eigen::Vector3d& centre,
                                        const Eigen::Vector3d& normal, double rmin, double rmax,
                                        int segments) {
    // A band whose "upper" circle is the outer one: in the plane, facing along the normal.
    const std::vector<Eigen::Vector3d> inner = circle(centre, normal, rmin, segments);
    const std::vector<Eigen::Vector3d> outer = circle(centre, normal, rmax, segments);
    std::vector<MgfPolygon> out;
    for (std::size_t k = 0; k < inner.size(); ++k) {
        const std::size_t next = (k + 1) % inner.size();
        MgfPolygon quad{inner[k], outer[k], outer[next]};
        if (inner[next] != inner[k]) quad.push_back(inner[next]);
        out.push_back(std::move(quad));
    }
    return out;
}

std::vector<MgfPolygon> tessellate_torus(const Eigen::Vector3d& centre,
                                         const Eigen::Vector3d& normal, double rmin, double rmax,
                                         int segments) {
    const double major = 0.5 * (rmax + rmin), minor = 0.5 * (rmax - rmin);
    const Eigen::Vector3d axis = normal.normalized();
    std::vector<std::vector<Eigen::Vector3d>> rings;
    for (int j = 0; j < segments; ++j) {  // around the tube, from its outermost circle upwards
        const double angle = 2 * std::numbers::pi * j / segments;
        const double r = major + minor * std::cos(angle);
        rings.push_back(circle(centre + minor * std::sin(angle) * axis, axis,
                               std::abs(r) < 1e-12 * rmax ? 0.0 : r, segments));
    }
    std::vector<MgfPolygon> out;
    for (std::size_t j = 0; j < rings.size(); ++j)
        add_band(rings[j], rings[(j + 1) % rings.size()], out);
    return out;
}

std::vector<MgfPolygon> extrude_prism(const MgfPolygon& base, double length) {
    Eigen::Vector3d newell = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < base.size(); ++i)
        newell += base[i].cross(base[(i + 1) % base.size()]);
    const Eigen::Vector3d d = length * newell.normalized();
    std::vector<MgfPolygon> out{base, {}};
    for (auto it = base.rbegin(); it != base.rend(); ++it) out[1].push_back(*it - d);
    for (std::size_t i = 0; i < base.size(); ++i) {
        const Eigen::Vector3d& p = base[i];
        const Eigen::Vector3d& q = base[(i + 1) % base.size()];
        out.push_back({q, p, p - d, q - d});
    }
    return out;
}

}  // namespace hmcr
