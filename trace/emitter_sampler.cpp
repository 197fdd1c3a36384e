// SPDX-License-Identifier: Apache-2.0
#include "trace/emitter_sampler.h"

#include <stdexcept>

#include "rays/domain.h"
#include "rays/element_sampler.h"

namespace hmcr {

// Sides in patch order, a patch's front before its back: a scene without backs has the table
// it had when every patch was one-sided, so it samples the same points.
EmitterSampler::EmitterSampler(const PatchSet& set) : m_pdf_area(set.patches.size(), 0.0) {
    const std::vector<Patch>& patches = set.patches;
    if (!set.back_materials.empty()) m_back_pdf_area.assign(patches.size(), 0.0);
    std::vector<double> power;
    double total = 0;
    for (std::uint32_t i = 0; i < patches.size(); ++i) {
        for (const std::uint8_t side : {kFront, kBack}) {
            if (side == kBack && !set.two_sided(i)) continue;
            const double w = patches[i].area * channel_sum(set.material(i, side).emission);
            if (!(w > 0)) continue;
            m_emitters.push_back({i, side});
            power.push_back(w);
            total += w;
        }
    }
    if (m_emitters.empty()) throw std::invalid_argument("the scene has no emitter to sample");
    m_table.emplace(power);
    for (std::size_t k = 0; k < m_emitters.size(); ++k) {
        const Entry& e = m_emitters[k];
        (e.side == kFront ? m_pdf_area : m_back_pdf_area)[e.patch] =
            power[k] / total / patches[e.patch].area;
    }
}

EmitterPoint EmitterSampler::sample(const std::vector<Patch>& patches, double xi_patch, double xi1,
                                    double xi2) const {
    const Entry& e = m_emitters[m_table->sample(xi_patch)];
    const Patch& p = patches[e.patch];
    return {e.patch, e.side, p.point(sample_element(p, Domain::root(), xi1, xi2)),
            pdf_area(e.patch, e.side)};
}

}  // namespace hmcr
