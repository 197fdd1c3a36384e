// SPDX-License-Identifier: Apache-2.0
// The radiosity a solution shows at a point of a given patch side, for the object error against
// either kind of reference (studies/object_space_error.h, studies/point_error.h;
// docs/design.md §6.6).
//
// A ray from delta in front of the point (along the side's normal) back along minus the normal
// must hit a solution cell of the same patch and side; where a closer surface is hit instead (an
// object resting on the floor), the ray is cast from behind the point. A point neither ray finds
// on its patch (one within the tracer's float precision of an edge to another patch, such as a
// light tile's in a ceiling) takes the Gouraud value at the closest point of its patch side's
// solution cells within delta (`by_ray` false). A point with no such cell has no value: the
// solution does not cover that surface.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "radiosity/shaded_mesh.h"
#include "viz/shaded_tracer.h"

namespace hmcr {

class SolutionProbe {
public:
    // delta: ten times the tracer's self-hit offset.
    SolutionProbe(const ShadedTracer& tracer, const ShadedMesh& solution);

    // `normal` points out of the side the point is on, so the ray from in front meets the
    // solution's cell of that side.
    std::optional<Rgb> at(const Vec3& p, const Vec3& normal, int patch, std::uint8_t side,
                          bool& by_ray) const;

    // Whether the solution has any cell on this patch side.
    bool covers(int patch, std::uint8_t side) const;

    // What an object error takes at a point (docs/design.md §6.6): at(), or, on a side the
    // solution has no cell of while the patch's other side has some (a back its light never
    // reached), the side's emission E; 0 where the solution does not cover the patch at all.
    enum class Found : std::uint8_t { ray, nearest, unlit, unmatched };
    struct Value {
        Rgb radiosity = Rgb::Zero();
        Found found = Found::ray;
    };
    Value value(const Vec3& p, const Vec3& normal, int patch, std::uint8_t side,
                const Rgb& emission) const;

private:
    std::optional<Rgb> nearest(const Vec3& p, int patch, std::uint8_t side) const;
    static std::size_t key(int patch, std::uint8_t side) { return 2 * std::size_t(patch) + side; }

    const ShadedTracer& m_tracer;
    const ShadedMesh& m_solution;
    double m_delta;
    // The solution's cells of each (patch, side), for points the rays do not find.
    std::vector<std::size_t> m_first;  // by key(patch, side), into m_cells
    std::vector<std::size_t> m_cells;
};

}  // namespace hmcr
