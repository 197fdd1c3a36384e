// Embree behind a small RAII facade: the rest of hmcr asks for first hits and visibility and
// never touches RTC types. Quads are traced as two triangles; hits report the patch index.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "radiosity/patch.h"

namespace hmcr {

struct Hit {
    std::uint32_t patch = 0;
    double distance = 0;  // along the (unit) direction
};

class EmbreeScene {
public:
    explicit EmbreeScene(const std::vector<Patch>& patches);
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    // First surface hit along a unit direction, ignoring hits closer than the self-hit offset.
    std::optional<Hit> first_hit(const Vec3& origin, const Vec3& direction) const;
    // Whether the open segment between two surface points is unoccluded.
    bool visible(const Vec3& p, const Vec3& q) const;
    // visible() for many segments at once, 16 per coherent packet (the segments of one element
    // pair are coherent: SPEC section 4 line sampling).
    void visible_many(std::span<const Vec3> p, std::span<const Vec3> q, std::span<bool> out) const;

    double offset() const { return m_offset; }  // self-hit offset, metres

    struct Impl;  // opaque: keeps RTC types out of this header

private:
    Impl* m_impl;
    std::vector<std::uint32_t> m_triangle_patch;
    double m_offset = 0;
};

// Sets flush-to-zero and denormals-are-zero in the calling thread, as Embree recommends for
// every thread that traces.
void set_tracing_float_mode();

}  // namespace hmcr
