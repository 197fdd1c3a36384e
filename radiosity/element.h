// SPDX-License-Identifier: Apache-2.0
// A node of a patch's quadtree (docs/design.md §2). The root element is the patch itself.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>

#include "common/types.h"
#include "radiosity/power_quanta.h"
#include "rays/domain.h"

namespace hmcr {

// Deterministic identity: the patch, its side and the path of child indices from its root.
struct ElementId {
    std::uint32_t patch = 0;
    std::uint8_t depth = 0;
    std::uint8_t side = 0;   // kFront or kBack (rays/patch.h), or a cluster's (clusters.h)
    std::uint64_t path = 0;  // 2 bits per level, the root's child index most significant

    ElementId child(int k) const {
        return {patch, std::uint8_t(depth + 1), side, (path << 2) | unsigned(k)};
    }
    auto operator<=>(const ElementId&) const = default;
    std::string to_string() const;  // "patch/0312", a back side's "patchb/0312"
};

struct Element {
    ElementId id;
    Domain domain;
    // A higher-order element's first slot of its coefficients beyond the mean (TermStore,
    // element_terms.h); none on the constant basis. It fills the padding after the domain.
    std::uint32_t terms = UINT32_MAX;
    double area = 0;
    Vec3 centre{0, 0, 0};  // the image of the domain's centre, kept for the oracles' geometry
    Rgb radiosity = Rgb::Zero();  // B
    Rgb unshot = Rgb::Zero();     // Delta B, shot in the next iteration
    Quanta received{};            // power received in the current iteration, in its quanta
    std::atomic<Element*> first_child{nullptr};  // 4 consecutive children, or none

    Element() = default;
    Element(const Element&) = delete;
    Element& operator=(const Element&) = delete;

    Element* children() const { return first_child.load(std::memory_order_acquire); }
    bool is_leaf() const { return children() == nullptr; }
};

}  // namespace hmcr
