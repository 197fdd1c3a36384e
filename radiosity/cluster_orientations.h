// SPDX-License-Identifier: Apache-2.0
// The orientations of a cluster tree's sides, for oriented clusters (docs/design.md §2.7): each
// cluster's sides grouped by the direction they face, so that a deposit reaches the sides that
// face the ray, in proportion to their projected area, and push-pull carries each group's
// irradiance down to its own sides.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "common/types.h"
#include "radiosity/power_quanta.h"

namespace hmcr {

class ClusterOrientations {
public:
    // The orientation class of a facing normal: a cell of the octahedral map of directions,
    // kBins of them, each some 13 degrees across.
    static constexpr std::uint32_t kGrid = 16;
    static constexpr std::uint32_t kBins = kGrid * kGrid;
    static std::uint16_t bin(const Vec3& n);  // n: a facing normal, of any length

    // One child of a cluster as add_cluster takes it: a cluster (by index) or a side (by its
    // value 2 * patch + side, with its area and the normal it faces by).
    struct Child {
        bool cluster = false;
        std::uint32_t index = 0;  // the cluster's index, or the side's value
        double area = 0;
        Vec3 normal{0, 0, 0};  // a side's
    };

    // `clusters` clusters over sides of values below `side_values`.
    ClusterOrientations(std::size_t clusters, std::size_t side_values);
    // Cluster c's classes from its two children's; every cluster after the clusters among its
    // children.
    void add_cluster(std::uint32_t c, const Child& first, const Child& second);

    // Ray power Phi (in quanta) arriving along `direction` (unit, from the source) on cluster
    // c: split among c's classes by their projected area toward the ray, max(0, -d . n) A, and
    // rounded so that the parts sum to Phi exactly; `dither` (uniform, the ray's) keys the
    // rounding. A cluster none of whose classes faces the ray (grazing incidence, where a
    // class's mean normal and the side hit differ) takes it by area.
    void deposit(std::uint32_t c, const Vec3& direction, const Quanta& incident, double dither);
    // The fraction of cluster c's area projected toward unit d: sum max(0, d . n) A / A_c, the
    // cosine the power oracle takes at a cluster's end.
    double projected_fraction(std::uint32_t c, const Vec3& d) const;

    // Push-pull's first half (docs/design.md §2.7): each class's received power over its area,
    // plus what its parent class carries, down to the sides: irradiance[s] is the irradiance
    // side value s's class holds (sides outside the tree are left as they are). Clears what
    // was received.
    void push(const PowerQuantum& quantum, std::vector<Rgb>& irradiance);

    // What the classes received, in a fixed order (the ranks' sum, rank_merge.h).
    std::span<Quanta> received() { return m_received; }
    std::size_t classes() const { return m_bin.size(); }
    std::size_t classes_of(std::uint32_t c) const { return m_end[c] - m_begin[c]; }

private:
    static constexpr std::uint32_t kNone = ~std::uint32_t(0);
    // One class being merged: its bin, area, area-weighted normal sum, and where it came from.
    struct Part {
        std::uint16_t bin = 0;
        double area = 0;
        Vec3 normal_sum{0, 0, 0};
        std::uint32_t from = kNone;  // a child's class index, or kNone for a side
        std::uint32_t side = kNone;  // the side value, for a side
    };
    void parts_of(const Child& k);  // appended to m_parts
    // A class's weight toward a ray along `direction`: its projected area.
    double facing(std::size_t k, const Vec3& direction) const;

    std::vector<std::uint32_t> m_begin, m_end;  // per cluster, its classes
    std::vector<std::uint32_t> m_side_class;    // per side value, its class in its parent
    // Per class:
    std::vector<std::uint16_t> m_bin;
    std::vector<double> m_area;
    std::vector<Vec3> m_normal_sum;  // sum of A n over its sides
    std::vector<double> m_scale;     // A / |sum A n|: projected area = scale * max(0, n_sum . d)
    std::vector<std::uint32_t> m_parent;  // the class of the parent cluster it belongs to
    std::vector<Quanta> m_received;
    std::vector<Rgb> m_irradiance;  // push()'s scratch
    std::vector<Part> m_parts;      // add_cluster()'s scratch
};

}  // namespace hmcr
