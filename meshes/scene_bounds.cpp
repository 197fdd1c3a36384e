// SPDX-License-Identifier: Apache-2.0
#include "meshes/scene_bounds.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

namespace hmcr {
namespace {

// A patch as the view choice needs it: corners, unit normal, area, which sides have a material.
struct BoundsFace {
    std::array<Eigen::Vector3d, 4> corner;
    int corners = 0;
    Eigen::Vector3d normal{0, 0, 0};
    double area = 0;
    bool two_sided = false;
};

std::vector<BoundsFace> bounds_faces(const PatchMesh& mesh) {
    const FaceMaterials materials(mesh);
    std::vector<BoundsFace> out;
    out.reserve(mesh.n_faces());
    for (const auto f : mesh.faces()) {
        BoundsFace face;
        for (const auto v : mesh.fv_range(f)) {
            if (face.corners == 4) break;  // patches are triangles and quads
            const auto& p = mesh.point(v);
            face.corner[face.corners++] = Eigen::Vector3d(p[0], p[1], p[2]);
        }
        Eigen::Vector3d area = Eigen::Vector3d::Zero();  // Newell's vector area
        for (int k = 0; k < face.corners; ++k) {
            area += 0.5 * face.corner[k].cross(face.corner[(k + 1) % face.corners]);
        }
        face.area = area.norm();
        if (face.area > 0) face.normal = area / face.area;
        face.two_sided = materials.back_index(f) != kOneSided;
        out.push_back(face);
    }
    return out;
}

// The nearest hit of the ray o + t d (t > 0) on the face's triangles, or nullopt.
std::optional<double> bounds_face_hit(const BoundsFace& f, const Eigen::Vector3d& o,
                                      const Eigen::Vector3d& d) {
    std::optional<double> best;
    for (int k = 1; k + 1 < f.corners; ++k) {
        const Eigen::Vector3d e1 = f.corner[k] - f.corner[0], e2 = f.corner[k + 1] - f.corner[0];
        const Eigen::Vector3d p = d.cross(e2);
        const double det = e1.dot(p);
        if (std::abs(det) < 1e-300) continue;
        const Eigen::Vector3d s = o - f.corner[0];
        const double u = s.dot(p) / det;
        const Eigen::Vector3d q = s.cross(e1);
        const double v = d.dot(q) / det, t = e2.dot(q) / det;
        if (u >= 0 && v >= 0 && u + v <= 1 && t > 0 && (!best || t < *best)) best = t;
    }
    return best;
}

// The distance to the first patch along the ray, when the side it meets has a material.
std::optional<double> lit_distance(const std::vector<BoundsFace>& faces, const Eigen::Vector3d& o,
                                   const Eigen::Vector3d& d) {
    double nearest = std::numeric_limits<double>::infinity();
    const BoundsFace* first = nullptr;
    for (const BoundsFace& f : faces) {
        if (const auto t = bounds_face_hit(f, o, d); t && *t < nearest) {
            nearest = *t;
            first = &f;
        }
    }
    if (!first || !(first->two_sided || first->normal.dot(d) < 0)) return std::nullopt;
    return nearest;
}

int main_axis(const Eigen::Vector3d& direction) {
    int a = 0;
    direction.cwiseAbs().maxCoeff(&a);
    return a;
}

bool enclosed_position(const std::vector<BoundsFace>& faces, const SceneBounds& b,
                       const Eigen::Vector3d& p) {
    const int up = main_axis(b.up);
    for (int a = 0; a < 3; ++a) {
        const Eigen::Vector3d e = Eigen::Vector3d::Unit(a);
        const auto plus = lit_distance(faces, p, e), minus = lit_distance(faces, p, -e);
        if (!plus || !minus) return false;
        if (a == up && *plus + *minus < 0.5 * (b.hi[a] - b.lo[a])) return false;
    }
    return true;
}

// How much lit room a view sees: the free distance to a lit side summed over a 3 x 3 grid of rays
// across its field (a ray that leaves or meets an unlit back adds nothing).
double seen_depth(const std::vector<BoundsFace>& faces, const View& v) {
    const Eigen::Vector3d forward = (v.look_at - v.position).normalized();
    const Eigen::Vector3d right = forward.cross(v.up).normalized(), up = right.cross(forward);
    const double spread = std::tan(0.3 * v.fov_degrees * std::numbers::pi / 180);
    double depth = 0;
    for (const int i : {-1, 0, 1}) {
        for (const int j : {-1, 0, 1}) {
            const Eigen::Vector3d d = (forward + spread * (i * right + j * up)).normalized();
            depth += lit_distance(faces, v.position, d).value_or(0);
        }
    }
    return depth;
}

// The enclosed view that sees the most (see the opening comment), if any position is enclosed.
std::optional<View> inside_view(const std::vector<BoundsFace>& faces, const SceneBounds& b) {
    const int up = main_axis(b.up), h1 = (up + 1) % 3, h2 = (up + 2) % 3;
    const Eigen::Vector3d middle = 0.5 * (b.lo + b.hi);
    // Half the floor plan's diagonals, towards its four corners.
    std::vector<Eigen::Vector3d> corners;
    for (const double s1 : {1.0, -1.0}) {
        for (const double s2 : {1.0, -1.0}) {
            Eigen::Vector3d half = Eigen::Vector3d::Zero();
            half[h1] = 0.5 * s1 * (b.hi[h1] - b.lo[h1]);
            half[h2] = 0.5 * s2 * (b.hi[h2] - b.lo[h2]);
            corners.push_back(half);
        }
    }
    if (corners[0].norm() <= 0) return std::nullopt;
    // From 35% of the way to each corner across the middle, and from the middle to each corner.
    std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> candidates;
    candidates.reserve(2 * corners.size());
    for (const Eigen::Vector3d& half : corners) {
        candidates.emplace_back(middle + 0.35 * half, middle - 0.35 * half);
    }
    for (const Eigen::Vector3d& half : corners) candidates.emplace_back(middle, middle + half);
    std::optional<View> best;
    double best_depth = 0;
    for (const auto& [position, look_at] : candidates) {
        if (!enclosed_position(faces, b, position)) continue;
        View v;
        v.name = "default";
        v.position = position;
        v.look_at = look_at;
        v.up = b.up;
        v.fov_degrees = 60;
        if (const double depth = seen_depth(faces, v); !best || depth > best_depth) {
            best = v;
            best_depth = depth;
        }
    }
    return best;
}

View outside_view(const std::vector<BoundsFace>& faces, const SceneBounds& b) {
    // The six sides, +z first (where a bare mesh was seen from before the up axis was guessed).
    const Eigen::Vector3d sides[] = {{0, 0, 1},  {0, 0, -1}, {1, 0, 0},
                                     {-1, 0, 0}, {0, 1, 0},  {0, -1, 0}};
    Eigen::Vector3d best = sides[0];
    double best_area = -1;
    for (const Eigen::Vector3d& s : sides) {
        double area = 0;  // lit area facing the side, projected, occlusion ignored
        for (const BoundsFace& f : faces) {
            const double c = f.normal.dot(s);
            if (c > 0 || f.two_sided) area += f.area * std::abs(c);
        }
        if (area > 1.01 * best_area) {  // clearly more: among near equals the earlier side
            best_area = area;
            best = s;
        }
    }
    View v;
    v.name = "default";
    const double radius = std::max(0.5 * (b.hi - b.lo).norm(), 1e-3);
    const double half_fov = 0.5 * v.fov_degrees * std::numbers::pi / 180;
    v.look_at = 0.5 * (b.lo + b.hi);
    v.position = v.look_at + best * (radius / std::sin(half_fov));
    const int view_axis = main_axis(best);  // up along it: +y, or +z looking along y
    v.up = main_axis(b.up) != view_axis ? b.up : Eigen::Vector3d::Unit(view_axis == 1 ? 2 : 1);
    return v;
}

}  // namespace

std::string axis_name(const Eigen::Vector3d& axis) {
    const int a = main_axis(axis);
    return std::string(axis[a] < 0 ? "-" : "+") + "xyz"[a];
}

SceneBounds scene_bounds(const PatchMesh& mesh) {
    SceneBounds b;
    b.lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    b.hi = -b.lo;
    for (const auto v : mesh.vertices()) {
        const auto& p = mesh.point(v);
        b.lo = b.lo.cwiseMin(Eigen::Vector3d(p[0], p[1], p[2]));
        b.hi = b.hi.cwiseMax(Eigen::Vector3d(p[0], p[1], p[2]));
    }
    if (mesh.n_vertices() == 0) b.lo = b.hi = Eigen::Vector3d::Zero();
    const FaceMaterials materials(mesh);
    const std::vector<BoundsFace> faces = bounds_faces(mesh);
    // Over the emitting sides: their vector area and their area-weighted centre.
    Eigen::Vector3d facing = Eigen::Vector3d::Zero(), centre = facing;
    std::size_t k = 0;
    for (const auto f : mesh.faces()) {
        const BoundsFace& face = faces[k++];
        ++b.patches;
        b.two_sided += face.two_sided;
        const OpenMesh::Vec3d none(0, 0, 0);
        const std::uint32_t back = materials.back_index(f);
        const OpenMesh::Vec3d& front_e = materials[f].emission;
        const OpenMesh::Vec3d& back_e = back == kOneSided ? none : materials.table()[back].emission;
        if (front_e.max() <= 0 && back_e.max() <= 0) continue;
        ++b.emitters;
        Eigen::Vector3d middle = Eigen::Vector3d::Zero();
        for (int c = 0; c < face.corners; ++c) middle += face.corner[c] / face.corners;
        for (const auto& [e, sign] : {std::pair{front_e, 1.0}, std::pair{back_e, -1.0}}) {
            if (e.max() <= 0) continue;
            b.emitting_area += face.area;
            b.emitted_power += face.area * Eigen::Vector3d(e[0], e[1], e[2]);
            facing += sign * face.area * face.normal;
            centre += face.area * middle;
        }
    }
    if (b.emitting_area > 0) {
        // Lights hang high: up along the axis where the emitters' centre is farthest from the
        // box's middle, towards it.
        const Eigen::Vector3d extent = (b.hi - b.lo).cwiseMax(1e-300);
        const Eigen::Vector3d height =
            (centre / b.emitting_area - 0.5 * (b.lo + b.hi)).cwiseQuotient(extent);
        int a = 0;
        if (height.cwiseAbs().maxCoeff(&a) > 0.1) {
            b.up = Eigen::Vector3d::Unit(a) * (height[a] > 0 ? 1 : -1);
            b.up_reason = fmt::format("the emitters' centre is at {:.0f}% of the box along {}",
                                      100 * (0.5 + height[a]), "xyz"[a]);
            return b;
        }
        // Else they shine down: against the way most of their area faces.
        facing.cwiseAbs().maxCoeff(&a);
        if (std::abs(facing[a]) > 0.5 * b.emitting_area) {
            b.up = Eigen::Vector3d::Unit(a) * (facing[a] > 0 ? -1 : 1);
            b.up_reason = "the emitters face " + axis_name(-b.up);
            return b;
        }
    }
    b.up_reason = b.emitters == 0 ? "no emitters: OBJ's convention"
                                  : "the emitters say nothing of it: OBJ's convention";
    return b;
}

DefaultView default_view(const PatchMesh& mesh, const SceneBounds& bounds) {
    const std::vector<BoundsFace> faces = bounds_faces(mesh);
    if (auto inside = inside_view(faces, bounds)) return {*inside, true};
    return {outside_view(faces, bounds), false};
}

}  // namespace hmcr
