// SPDX-License-Identifier: Apache-2.0
#include "rays/alias_table.h"

#include <stdexcept>

namespace hmcr {

AliasTable::AliasTable(const std::vector<double>& weights) { assign(weights); }

void AliasTable::assign(const std::vector<double>& weights) {
    const std::size_t n = weights.size();
    if (n == 0) throw std::invalid_argument("alias table needs at least one weight");
    double total = 0;
    for (double w : weights) total += w;
    // Each bin's keep holds its scaled weight until the bin is paired. The under-full bins wait
    // at the front of `waiting`, the over-full at its back (each bin is in one of the two, so
    // they never meet), both taken last in, first out.
    if (n > m_bins.capacity()) m_bins.clear();  // what it holds is not copied to the new block
    m_bins.resize(n);
    std::vector<std::uint32_t> waiting(n);
    std::size_t small = 0, large = n;
    for (std::size_t i = 0; i < n; ++i) {
        m_bins[i] = {weights[i] * double(n) / total, i};
        if (m_bins[i].keep < 1) {
            waiting[small++] = std::uint32_t(i);
        } else {
            waiting[--large] = std::uint32_t(i);
        }
    }
    // Pair each under-full bin with an over-full one, which gives it the rest of its mass.
    while (small > 0 && large < n) {
        const std::uint32_t s = waiting[--small], l = waiting[large];
        m_bins[s].alias = l;
        m_bins[l].keep -= 1 - m_bins[s].keep;
        if (m_bins[l].keep < 1) {
            ++large;
            waiting[small++] = l;
        }
    }
    // What is left is full up to rounding.
    for (std::size_t k = 0; k < small; ++k) m_bins[waiting[k]].keep = 1;
    for (std::size_t k = large; k < n; ++k) m_bins[waiting[k]].keep = 1;
}

std::size_t AliasTable::sample(double xi) const {
    const double x = xi * double(m_bins.size());
    const std::size_t i = std::min(std::size_t(x), m_bins.size() - 1);
    const Bin& b = m_bins[i];
    return x - double(i) < b.keep ? i : b.alias;
}

}  // namespace hmcr
