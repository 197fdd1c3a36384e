// SPDX-License-Identifier: Apache-2.0
#include "trace/threshold_search.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace hmcr {
namespace {

// The probes so far and the bracket [lo, hi] in log threshold: more samples than the target at
// lo, fewer at hi.
class Search {
public:
    Search(const std::function<double(double)>& spp_at, const SppTarget& target,
           std::vector<ThresholdProbe>& probes)
        : m_spp_at(spp_at), m_target(target), m_probes(probes) {}

    double run(double start);

private:
    double probe(double x);  // the mean at log threshold x
    bool within(double spp) const {
        return std::abs(spp - m_target.spp) <= m_target.tolerance * m_target.spp;
    }
    double next_point(double x, double spp) const;
    double step_down(double x, double spp) const;
    [[noreturn]] void fail(const std::string& why) const {
        throw SppNotReached(fmt::format("{} samples per pixel (+-{}%) not reached: {}",
                                        m_target.spp, 100 * m_target.tolerance, why));
    }

    const std::function<double(double)>& m_spp_at;
    SppTarget m_target;
    std::vector<ThresholdProbe>& m_probes;
    std::optional<double> m_lo, m_hi;  // log thresholds
    double m_lo_spp = 0, m_hi_spp = 0;
};

double Search::probe(double x) {
    const double spp = m_spp_at(std::exp(x));
    m_probes.push_back({std::exp(x), spp});
    if (spp > m_target.spp) {
        m_lo = x;
        m_lo_spp = spp;
    } else {
        m_hi = x;
        m_hi_spp = spp;
    }
    return spp;
}

// Downwards (more samples): the secant of the last two probes in log-log, a factor 1.5 without
// one (spp goes as 1 / threshold for the divergences, 1 / threshold^2 for var), never more than
// a factor 4 nor less than 1.1 at once.
double Search::step_down(double x, double spp) const {
    double step = std::log(1.5);
    if (m_probes.size() >= 2) {
        const ThresholdProbe& a = m_probes[m_probes.size() - 2];
        const double slope = (std::log(spp) - std::log(a.spp)) / (x - std::log(a.threshold));
        if (slope < 0) step = (std::log(spp) - std::log(m_target.spp)) / slope;
    }
    return x - std::clamp(step, std::log(1.1), std::log(4.0));
}

// Inside a bracket: the log-log interpolation of its ends, kept in the middle 80% so that the
// bracket always shrinks.
double Search::next_point(double x, double spp) const {
    if (!m_lo) return step_down(x, spp);
    if (!m_hi) return *m_lo + std::log(10.0);
    const double a = std::log(m_lo_spp), b = std::log(std::max(m_hi_spp, 1e-300));
    const double t = (a - std::log(m_target.spp)) / (a - b);
    return *m_lo + std::clamp(t, 0.1, 0.9) * (*m_hi - *m_lo);
}

double Search::run(double start) {
    double x = std::log(start);
    for (int k = 0; k < m_target.max_probes; ++k) {
        const double spp = probe(x);
        if (within(spp)) return std::exp(x);
        if (m_lo && m_hi && *m_hi - *m_lo < 1e-9) {
            fail(fmt::format("the mean jumps from {:.2f} to {:.2f} at threshold {:.6g}", m_lo_spp,
                             m_hi_spp, std::exp(*m_hi)));
        }
        x = next_point(x, spp);
    }
    fail(fmt::format(
        "closest after {} probes: {:.2f}", m_probes.size(),
        std::min_element(m_probes.begin(), m_probes.end(), [&](const auto& a, const auto& b) {
            return std::abs(a.spp - m_target.spp) < std::abs(b.spp - m_target.spp);
        })->spp));
}

}  // namespace

double search_threshold(const std::function<double(double)>& spp_at, double start,
                        const SppTarget& target, std::vector<ThresholdProbe>& probes) {
    if (!(start > 0) || !std::isfinite(start)) {
        throw std::invalid_argument(fmt::format("threshold search: bad start {}", start));
    }
    return Search(spp_at, target, probes).run(start);
}

}  // namespace hmcr
