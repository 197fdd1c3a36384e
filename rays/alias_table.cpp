#include "rays/alias_table.h"

#include <stdexcept>

namespace hmcr {

AliasTable::AliasTable(const std::vector<double>& weights) { assign(weights); }

void AliasTable::assign(const std::vector<double>& weights) {
    const std::size_t n = weights.size();
    if (n == 0) throw std::invalid_argument("alias table needs at least one weight");
    double total = 0;
    for (double w : weights) total += w;
    m_bins.resize(n);
    std::vector<double> scaled(n);
    std::vector<std::uint32_t> small, large;
    for (std::size_t i = 0; i < n; ++i) {
        scaled[i] = weights[i] * double(n) / total;
        (scaled[i] < 1 ? small : large).push_back(std::uint32_t(i));
    }
    // Pair each under-full bin with an over-full one, which gives it the rest of its mass.
    while (!small.empty() && !large.empty()) {
        const std::uint32_t s = small.back(), l = large.back();
        small.pop_back();
        m_bins[s] = {scaled[s], l};
        scaled[l] -= 1 - scaled[s];
        if (scaled[l] < 1) {
            large.pop_back();
            small.push_back(l);
        }
    }
    // What is left is full up to rounding.
    for (std::uint32_t i : small) m_bins[i] = {1, i};
    for (std::uint32_t i : large) m_bins[i] = {1, i};
}

std::size_t AliasTable::sample(double xi) const {
    const double x = xi * double(m_bins.size());
    const std::size_t i = std::min(std::size_t(x), m_bins.size() - 1);
    const Bin& b = m_bins[i];
    return x - double(i) < b.keep ? i : b.alias;
}

}  // namespace hmcr
