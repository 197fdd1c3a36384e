#include "trace/emitter_sampler.h"

#include <stdexcept>

#include "rays/domain.h"
#include "rays/element_sampler.h"

namespace hmcr {

EmitterSampler::EmitterSampler(const PatchSet& set) : m_pdf_area(set.patches.size(), 0.0) {
    const std::vector<Patch>& patches = set.patches;
    std::vector<double> power;
    double total = 0;
    for (std::uint32_t i = 0; i < patches.size(); ++i) {
        const double w = patches[i].area * channel_sum(set.emission(patches[i]));
        if (!(w > 0)) continue;
        m_emitters.push_back(i);
        power.push_back(w);
        total += w;
    }
    if (m_emitters.empty()) throw std::invalid_argument("the scene has no emitter to sample");
    m_table.emplace(power);
    for (std::size_t k = 0; k < m_emitters.size(); ++k) {
        m_pdf_area[m_emitters[k]] = power[k] / total / patches[m_emitters[k]].area;
    }
}

EmitterPoint EmitterSampler::sample(const std::vector<Patch>& patches, double xi_patch, double xi1,
                                    double xi2) const {
    const std::uint32_t j = m_emitters[m_table->sample(xi_patch)];
    const Patch& p = patches[j];
    return {j, p.point(sample_element(p, Domain::root(), xi1, xi2)), m_pdf_area[j]};
}

}  // namespace hmcr
