// SPDX-License-Identifier: Apache-2.0
#include "information/back_sides.h"

#include <algorithm>

#include "information/leaf_patches.h"

namespace hmcr {
namespace {

Patch reversed(const Patch& p) {
    Patch r = p;
    std::reverse(r.corner.begin(), r.corner.begin() + p.corner_count);
    r.finalize();
    return r;
}

}  // namespace

BackSides::BackSides(const PatchSet& states, std::size_t fronts, std::vector<std::uint32_t> surface)
    : m_fronts(fronts), m_surface(std::move(surface)) {
    const std::uint32_t surfaces =
        m_surface.empty() ? 0 : *std::max_element(m_surface.begin(), m_surface.end()) + 1;
    m_whole_back.assign(surfaces, kNoState);
    m_has_back.assign(surfaces, 0);
    std::vector<std::uint32_t> backs_on(surfaces, 0);
    for (std::size_t s = fronts; s < m_surface.size(); ++s) ++backs_on[m_surface[s]];
    for (std::size_t s = fronts; s < m_surface.size(); ++s) {
        const std::uint32_t on = m_surface[s];
        m_has_back[on] = 1;
        if (backs_on[on] == 1) m_whole_back[on] = std::uint32_t(s);
    }
    if (std::any_of(backs_on.begin(), backs_on.end(), [](std::uint32_t n) { return n > 1; })) {
        const std::vector<Patch> backs(states.patches.begin() + std::ptrdiff_t(fronts),
                                       states.patches.end());
        m_backs = std::make_unique<EmbreeScene>(backs);
    }
}

std::uint32_t BackSides::at(std::uint32_t front, const Vec3& origin, const Vec3& direction,
                            double distance) const {
    const std::uint32_t on = m_surface[front];
    if (!m_has_back[on]) return kNoState;
    if (m_whole_back[on] != kNoState) return m_whole_back[on];
    // The back leaf on the same surface, as far as the front's within the self-hit offset.
    const auto hit = m_backs->first_hit(origin, direction);
    if (!hit || hit->distance > distance + m_backs->offset()) return kNoState;
    const auto state = std::uint32_t(m_fronts + hit->patch);
    return m_surface[state] == on ? state : kNoState;
}

ChannelStates patch_states(const PatchSet& set) {
    ChannelStates c;
    c.states.patches = set.patches;
    std::vector<std::uint32_t> surface(set.patches.size());
    for (std::uint32_t i = 0; i < set.patches.size(); ++i) surface[i] = i;
    for (std::uint32_t i = 0; i < set.patches.size(); ++i) {
        if (!set.two_sided(i)) continue;
        c.states.patches.push_back(reversed(set.patches[i]));
        surface.push_back(i);
    }
    c.states.total_area = set.total_area;  // a two-sided patch's area counts twice there too
    if (c.states.patches.size() > set.patches.size()) {
        c.backs = std::make_shared<BackSides>(c.states, set.patches.size(), std::move(surface));
    }
    return c;
}

ChannelStates leaf_states(const ShadedMesh& mesh) {
    const PatchSet cells = leaf_patches(mesh);
    const std::vector<std::size_t> first = leaf_first_cells(mesh);  // of each leaf
    ChannelStates c;
    std::vector<std::uint32_t> surface;
    std::size_t fronts = 0;
    for (const std::uint8_t side : {kFront, kBack}) {
        for (std::size_t k = 0; k < cells.patches.size(); ++k) {
            if ((mesh.side.empty() ? kFront : mesh.side[first[k]]) != side) continue;
            c.states.patches.push_back(cells.patches[k]);
            surface.push_back(std::uint32_t(mesh.patch_id[first[k]]));
        }
        if (side == kFront) fronts = c.states.patches.size();
    }
    for (const Patch& p : c.states.patches) c.states.total_area += p.area;
    if (fronts < c.states.patches.size()) {
        // Patch ids numbered densely: a file's ids may be anything up to 2^31.
        std::vector<std::uint32_t> ids = surface;
        std::sort(ids.begin(), ids.end());
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
        for (std::uint32_t& s : surface) {
            s = std::uint32_t(std::lower_bound(ids.begin(), ids.end(), s) - ids.begin());
        }
        c.backs = std::make_shared<BackSides>(c.states, fronts, std::move(surface));
    }
    return c;
}

}  // namespace hmcr
