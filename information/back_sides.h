// SPDX-License-Identifier: Apache-2.0
// The states of a channel whose surfaces may have two sides (docs/design.md §7.7): the fronts of
// the patches (or of a solution's front leaves), which the rays meet, then the backs of the
// two-sided ones, each a patch whose normal points out of the back. A ray that meets a front
// from behind lands on the back state lying there, if the surface has a back.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "radiosity/shaded_mesh.h"
#include "rays/embree_scene.h"
#include "rays/patch.h"

namespace hmcr {

class BackSides {
public:
    // `states`: fronts [0, fronts), then backs; `surface`: per state, the surface (scene patch)
    // it lies on. A back state that covers its surface whole (a scene's patch) is found by its
    // surface alone, the others (a solution's back leaves) by a ray into a scene of the backs.
    BackSides(const PatchSet& states, std::size_t fronts, std::vector<std::uint32_t> surface);

    std::size_t fronts() const { return m_fronts; }
    // The back state at the hit of the ray (origin, direction) on front state `front`, `distance`
    // along it, or kNoState where the surface has no back there.
    std::uint32_t at(std::uint32_t front, const Vec3& origin, const Vec3& direction,
                     double distance) const;

    static constexpr std::uint32_t kNoState = 0xffffffff;

private:
    std::size_t m_fronts = 0;
    std::vector<std::uint32_t> m_surface;     // per state
    std::vector<std::uint32_t> m_whole_back;  // per surface: its one back state, or kNoState
    std::vector<std::uint8_t> m_has_back;     // per surface
    std::unique_ptr<EmbreeScene> m_backs;     // the back states, when some cover part of one
};

// The states of a discretisation and, when it has backs, how to find them.
struct ChannelStates {
    PatchSet states;                         // patches and total_area: fronts, then backs
    std::shared_ptr<const BackSides> backs;  // null without backs
    std::size_t fronts() const { return backs ? backs->fronts() : states.patches.size(); }
};

// A scene's patches: a front each, then a back for each two-sided patch (its corners reversed).
ChannelStates patch_states(const PatchSet& set);
// A solution's leaves (information/leaf_patches.h): its front cells, then its back cells.
ChannelStates leaf_states(const ShadedMesh& mesh);

}  // namespace hmcr
