// SPDX-License-Identifier: Apache-2.0
#include "trace/criteria/display_values.h"

#include <vector>

namespace hmcr {
namespace {

class DisplayValues final : public Criterion {
public:
    DisplayValues(const Criterion& inner, double exposure) : m_inner(inner), m_exposure(exposure) {}
    std::string_view name() const override { return m_inner.name(); }
    std::string_view description() const override { return m_inner.description(); }
    Scheme scheme() const override { return m_inner.scheme(); }

    double value(std::span<const PixelSample> samples, double area) const override {
        std::vector<PixelSample> shown(samples.begin(), samples.end());
        for (PixelSample& s : shown) s.radiance = (m_exposure * s.radiance).min(1.0);
        return m_inner.value(shown, area);
    }

private:
    const Criterion& m_inner;
    double m_exposure;
};

}  // namespace

std::unique_ptr<Criterion> on_display_values(const Criterion& inner, double exposure) {
    return std::make_unique<DisplayValues>(inner, exposure);
}

}  // namespace hmcr
