// Next-event estimation's light sampler: an emitting patch chosen with probability proportional
// to its power A_j |E_j| (|c| the channel sum, as everywhere in hmcr), then a point uniformly by
// area on it, so the density of a point y of patch j is P_j / A_j per m^2.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "rays/alias_table.h"
#include "rays/patch.h"

namespace hmcr {

struct EmitterPoint {
    std::uint32_t patch = 0;
    Vec3 point;
    double pdf_area = 0;  // P_j / A_j, per m^2
};

class EmitterSampler {
public:
    // Throws std::invalid_argument when nothing emits.
    explicit EmitterSampler(const PatchSet& set);

    // A point from three uniforms in [0, 1): the patch, then two for the point.
    EmitterPoint sample(const std::vector<Patch>& patches, double xi_patch, double xi1,
                        double xi2) const;
    // The density sample() gives a point of this patch, per m^2 (0 for a patch that does not
    // emit): what multiple importance sampling weighs an emitter found by a bounce with.
    double pdf_area(std::uint32_t patch) const { return m_pdf_area[patch]; }

private:
    std::vector<std::uint32_t> m_emitters;  // patch index of each table entry
    std::optional<AliasTable> m_table;
    std::vector<double> m_pdf_area;  // per patch
};

}  // namespace hmcr
