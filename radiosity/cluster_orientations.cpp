// SPDX-License-Identifier: Apache-2.0
#include "radiosity/cluster_orientations.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "rays/rng.h"

namespace hmcr {
namespace {

// The key of the stream a deposit's rounding draws from, beside the ray's dither.
constexpr std::uint64_t kSplitKey = 0x6f7269656e746564ULL;

std::uint32_t grid_cell(double x) {
    const auto i = std::int64_t(std::floor((x + 1) * 0.5 * ClusterOrientations::kGrid));
    return std::uint32_t(std::clamp<std::int64_t>(i, 0, ClusterOrientations::kGrid - 1));
}

}  // namespace

// The octahedral map: n / |n|_1 projected on the plane z = 0, the upper hemisphere onto the
// square's inner diamond and the lower one folded out over its edges onto the corners; the
// square is a kGrid x kGrid grid.
std::uint16_t ClusterOrientations::bin(const Vec3& n) {
    const double l1 = std::abs(n.x()) + std::abs(n.y()) + std::abs(n.z());
    double x = n.x() / l1, y = n.y() / l1;
    const bool lower = n.z() < 0;
    if (lower) {
        const double fx = (1 - std::abs(y)) * (x < 0 ? -1 : 1);
        const double fy = (1 - std::abs(x)) * (y < 0 ? -1 : 1);
        x = fx;
        y = fy;
    }
    return std::uint16_t(grid_cell(x) * kGrid + grid_cell(y));
}

ClusterOrientations::ClusterOrientations(std::size_t clusters, std::size_t side_values)
    : m_begin(clusters, 0), m_end(clusters, 0), m_side_class(side_values, kNone) {}

void ClusterOrientations::parts_of(const Child& k) {
    if (!k.cluster) {
        m_parts.push_back({bin(k.normal), k.area, k.area * k.normal, kNone, k.index});
        return;
    }
    for (std::uint32_t i = m_begin[k.index]; i < m_end[k.index]; ++i) {
        m_parts.push_back({m_bin[i], m_area[i], m_normal_sum[i], i, kNone});
    }
}

void ClusterOrientations::add_cluster(std::uint32_t c, const Child& first, const Child& second) {
    std::vector<Part>& parts = m_parts;
    parts.clear();
    parts_of(first);
    parts_of(second);
    // By bin, then as the children list them: the same classes for any sort.
    std::stable_sort(parts.begin(), parts.end(),
                     [](const Part& a, const Part& b) { return a.bin < b.bin; });
    m_begin[c] = std::uint32_t(m_bin.size());
    for (std::size_t i = 0; i < parts.size();) {
        const auto k = std::uint32_t(m_bin.size());
        double area = 0;
        Vec3 sum = Vec3::Zero();
        std::size_t j = i;
        for (; j < parts.size() && parts[j].bin == parts[i].bin; ++j) {
            area += parts[j].area;
            sum += parts[j].normal_sum;
            if (parts[j].from != kNone) m_parent[parts[j].from] = k;
            if (parts[j].side != kNone) m_side_class[parts[j].side] = k;
        }
        m_bin.push_back(parts[i].bin);
        m_area.push_back(area);
        m_normal_sum.push_back(sum);
        const double norm = sum.norm();
        m_scale.push_back(norm > 0 ? area / norm : 0);
        m_parent.push_back(kNone);
        m_received.push_back({});
        i = j;
    }
    m_end[c] = std::uint32_t(m_bin.size());
}

double ClusterOrientations::facing(std::size_t k, const Vec3& direction) const {
    return m_scale[k] * std::max(0.0, -direction.dot(m_normal_sum[k]));
}

void ClusterOrientations::deposit(std::uint32_t c, const Vec3& direction, const Quanta& incident,
                                  double dither) {
    const std::uint32_t begin = m_begin[c], end = m_end[c];
    double total = 0;
    for (std::uint32_t k = begin; k < end; ++k) total += facing(k, direction);
    const bool by_area = !(total > 0);
    if (by_area) {
        total = 0;
        for (std::uint32_t k = begin; k < end; ++k) total += m_area[k];
    }
    // Class k takes floor(q W_k + u) - floor(q W_(k-1) + u) of a channel's q quanta, W the
    // cumulative share: unbiased for a uniform u, and the parts sum to q.
    const double u = Rng(std::bit_cast<std::uint64_t>(dither), kSplitKey).uniform();
    Quanta before{};
    double cumulative = 0;
    for (std::uint32_t k = begin; k < end; ++k) {
        cumulative += by_area ? m_area[k] : facing(k, direction);
        const bool last = k + 1 == end;
        for (int ch = 0; ch < 3; ++ch) {
            const std::int64_t upto =
                last ? incident[ch] : floor_to_int(double(incident[ch]) * (cumulative / total) + u);
            m_received[k][ch] += upto - before[ch];
            before[ch] = upto;
        }
    }
}

double ClusterOrientations::projected_fraction(std::uint32_t c, const Vec3& d) const {
    double projected = 0, area = 0;
    for (std::uint32_t k = m_begin[c]; k < m_end[c]; ++k) {
        projected += facing(k, -d);
        area += m_area[k];
    }
    return area > 0 ? projected / area : 0;
}

void ClusterOrientations::push(const PowerQuantum& quantum, std::vector<Rgb>& irradiance) {
    m_irradiance.resize(m_bin.size());
    // A parent cluster's classes come after its children's: the reverse order visits parents
    // first.
    for (std::size_t k = m_bin.size(); k-- > 0;) {
        const Rgb above = m_parent[k] == kNone ? Rgb::Zero() : m_irradiance[m_parent[k]];
        m_irradiance[k] = above + quantum.power(m_received[k]) / m_area[k];
        m_received[k] = {};
    }
    for (std::size_t s = 0; s < m_side_class.size(); ++s) {
        if (m_side_class[s] != kNone) irradiance[s] = m_irradiance[m_side_class[s]];
    }
}

}  // namespace hmcr
