// SPDX-License-Identifier: Apache-2.0
// Next-event estimation's light sampler: an emitting side of a patch (its front, or the back of
// a two-sided patch, docs/design.md §1.3) chosen with probability proportional to its power
// A_j |E_j| (|c| the channel sum, as everywhere in hmcr), then a point uniformly by area on it,
// so the density of a point y of side j is P_j / A_j per m^2. A point of a back emits into the
// back's hemisphere, around the reversed normal.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "rays/alias_table.h"
#include "rays/patch.h"

namespace hmcr {

struct EmitterPoint {
    std::uint32_t patch = 0;
    std::uint8_t side = kFront;
    Vec3 point;
    double pdf_area = 0;  // P_j / A_j, per m^2
};

class EmitterSampler {
public:
    // Throws std::invalid_argument when nothing emits.
    explicit EmitterSampler(const PatchSet& set);

    // A point from three uniforms in [0, 1): the side, then two for the point.
    EmitterPoint sample(const std::vector<Patch>& patches, double xi_patch, double xi1,
                        double xi2) const;
    // The density sample() gives a point of this side, per m^2 (0 for a side that does not
    // emit): what multiple importance sampling weighs an emitter found by a bounce with.
    double pdf_area(std::uint32_t patch, std::uint8_t side) const {
        return side == kFront ? m_pdf_area[patch] : m_back_pdf_area[patch];
    }

private:
    struct Entry {
        std::uint32_t patch = 0;
        std::uint8_t side = kFront;
    };
    std::vector<Entry> m_emitters;  // the side of each table entry
    std::optional<AliasTable> m_table;
    std::vector<double> m_pdf_area;       // per patch, of its front
    std::vector<double> m_back_pdf_area;  // per patch, of its back (empty without backs)
};

}  // namespace hmcr
