// SPDX-License-Identifier: Apache-2.0
#include "radiosity/clusters.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rays/element_sampler.h"

namespace hmcr {

ClusterTree::ClusterTree(Hierarchy& h, std::span<const Rgb> receiver_weights, Clustering model)
    : m_h(h), m_weights(receiver_weights) {
    const PatchSet& ps = h.patch_set();
    const auto patches = std::uint32_t(h.patch_count());
    std::uint32_t two_sided = 0;
    for (std::uint32_t p = 0; p < patches; ++p) {
        if (ps.two_sided(p)) {
            h.root(p, kBack);
            ++two_sided;
        }
    }
    // A binary tree over the fronts has patches - 1 inner clusters, one over the backs
    // two_sided - 1, and the top joining them one more.
    m_elements = std::vector<Element>(patches - 1 + two_sided);
    m_nodes.resize(m_elements.size());
    m_top_factor = std::make_unique<std::atomic<double>[]>(m_elements.size());
    m_open = std::make_unique<std::atomic<std::uint8_t>[]>(m_elements.size());
    for (std::size_t k = 0; k < m_elements.size(); ++k) {
        m_top_factor[k].store(std::numeric_limits<double>::quiet_NaN());
        m_open[k].store(0);
    }
    m_position.assign(2 * std::size_t(patches), 0);
    m_side_parent.assign(2 * std::size_t(patches), kNoParent);
    m_leaf_of_side.assign(2 * std::size_t(patches), -1);
    m_side.reserve(patches + two_sided);
    m_cumulative.assign(1, 0.0);
    std::vector<std::uint32_t> fronts(patches), backs;
    backs.reserve(two_sided);
    for (std::uint32_t p = 0; p < patches; ++p) {
        fronts[p] = p;
        if (ps.two_sided(p)) backs.push_back(p);
    }
    if (backs.empty()) {
        m_top = build(fronts, kFront);
        m_power_cumulative = m_cumulative;  // by area until an iteration begins
        if (model == Clustering::oriented) orient();
        return;
    }
    // docs/design.md §2.7: fronts and backs meet only in the top cluster, which never receives.
    Element& top = new_cluster(0);
    Node& n = m_nodes[top.id.patch];
    n.child[0] = build(fronts, kFront);
    n.mid = std::uint32_t(m_side.size());
    n.child[1] = build(backs, kBack);
    adopt(top);
    finish(top);
    m_top = m_join = &top;
    m_power_cumulative = m_cumulative;
    if (model == Clustering::oriented) orient();
}

// Children have larger indices than their parent (depth-first numbering): the reverse index
// order gives every cluster's classes after its children's.
void ClusterTree::orient() {
    m_orientations = std::make_unique<ClusterOrientations>(m_elements.size(), m_position.size());
    const PatchSet& ps = m_h.patch_set();
    const auto child = [&](const Element& k) {
        if (is_cluster(k)) return ClusterOrientations::Child{true, k.id.patch, k.area, {}};
        return ClusterOrientations::Child{false, 2 * k.id.patch + k.id.side, k.area,
                                          side_normal(ps.patches[k.id.patch], k.id.side)};
    };
    for (std::size_t k = m_elements.size(); k-- > 0;) {
        const Node& n = m_nodes[k];
        m_orientations->add_cluster(std::uint32_t(k), child(*n.child[0]), child(*n.child[1]));
    }
}

Element& ClusterTree::new_cluster(std::uint32_t first) {
    Element& c = m_elements[m_used];
    c.id = {std::uint32_t(m_used), 0, kClusterSide, 0};
    m_nodes[m_used].first = first;
    ++m_used;
    return c;
}

// The side of one patch: its root, and its place in the tree's order.
Element* ClusterTree::leaf(std::uint32_t patch, std::uint8_t side) {
    Element& root = m_h.root(patch, side);
    const std::uint32_t value = 2 * patch + side;
    m_position[value] = std::uint32_t(m_side.size());
    m_side.push_back(value);
    m_cumulative.push_back(m_cumulative.back() + root.area);
    return &root;
}

// docs/design.md §2.7: the median of the centres along the longest side of their bounding box,
// ordered by that coordinate, then by index, so that each half is one set whatever the sort.
Element* ClusterTree::build(std::span<std::uint32_t> patches, std::uint8_t side) {
    if (patches.size() == 1) return leaf(patches[0], side);
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const std::uint32_t p : patches) {
        lo = lo.cwiseMin(m_h.root(p).centre);
        hi = hi.cwiseMax(m_h.root(p).centre);
    }
    const Vec3 extent = hi - lo;
    int axis = 0;
    for (int a = 1; a < 3; ++a) {
        if (extent[a] > extent[axis]) axis = a;
    }
    const std::size_t half = patches.size() / 2;
    std::nth_element(patches.begin(), patches.begin() + std::ptrdiff_t(half), patches.end(),
                     [&](std::uint32_t a, std::uint32_t b) {
                         const double ca = m_h.root(a).centre[axis], cb = m_h.root(b).centre[axis];
                         return ca < cb || (ca == cb && a < b);
                     });
    Element& c = new_cluster(std::uint32_t(m_side.size()));
    const std::size_t index = c.id.patch;
    Element* first = build(patches.first(half), side);
    m_nodes[index].mid = std::uint32_t(m_side.size());
    Element* second = build(patches.subspan(half), side);
    m_nodes[index].child = {first, second};
    adopt(c);
    finish(c);
    return &c;
}

// Records c as its children's parent.
void ClusterTree::adopt(const Element& c) {
    for (const Element* k : m_nodes[c.id.patch].child) {
        if (is_cluster(*k)) {
            m_nodes[k->id.patch].parent = c.id.patch;
        } else {
            m_side_parent[2 * std::size_t(k->id.patch) + k->id.side] = c.id.patch;
        }
    }
}

// Area, centre, receiver weight, B and Delta B from the finished children.
void ClusterTree::finish(Element& c) {
    Node& n = m_nodes[c.id.patch];
    n.end = std::uint32_t(m_side.size());
    c.area = 0;
    c.centre = Vec3::Zero();
    n.weight = Rgb::Zero();
    for (const Element* k : n.child) {
        c.area += k->area;
        c.centre += k->area * k->centre;
        n.weight += k->area * (is_cluster(*k) ? m_nodes[k->id.patch].weight : side_weight(*k));
    }
    c.centre /= c.area;
    n.weight /= c.area;
    average(c);
}

Rgb ClusterTree::side_weight(const Element& root) const {
    if (m_weights.empty()) return m_h.material(root).reflectance;
    return m_weights[2 * std::size_t(root.id.patch) + root.id.side];
}

void ClusterTree::average(Element& c) const {
    const Node& n = m_nodes[c.id.patch];
    c.radiosity =
        (n.child[0]->area * n.child[0]->radiosity + n.child[1]->area * n.child[1]->radiosity) /
        c.area;
    c.unshot =
        (n.child[0]->area * n.child[0]->unshot + n.child[1]->area * n.child[1]->unshot) / c.area;
}

std::pair<Vec3, Vec3> ClusterTree::point_by(const std::vector<double>& cumulative, const Element& c,
                                            double xu, double xv) const {
    const Node& n = m_nodes[c.id.patch];
    const double base = cumulative[n.first], total = cumulative[n.end] - base;
    const double a = base + xu * total;
    // The side whose share of [base, base + total) holds a (none is empty: it is never chosen).
    const auto it =
        std::upper_bound(cumulative.begin() + n.first + 1, cumulative.begin() + n.end, a);
    const auto pos = std::size_t(it - cumulative.begin()) - 1;
    const double lo = cumulative[pos], width = cumulative[pos + 1] - lo;
    const double u = std::clamp((a - lo) / width, 0.0, std::nextafter(1.0, 0.0));
    const std::uint32_t side = m_side[pos];
    const Patch& p = m_h.patch_set().patches[side >> 1];
    return {p.point(sample_element(p, Domain{}, u, xv)), side_normal(p, std::uint8_t(side & 1))};
}

void ClusterTree::begin_iteration(LinkWeight weight) {
    m_power_cumulative.assign(1, 0.0);
    for (const std::uint32_t side : m_side) {
        const Element& root = m_h.root(side >> 1, std::uint8_t(side & 1));
        const Rgb& b = weight == LinkWeight::total ? root.radiosity : root.unshot;
        m_power_cumulative.push_back(m_power_cumulative.back() +
                                     root.area * std::max(0.0, b.sum()));
    }
    // A scene that shoots nothing is never sampled; the areas keep point_by well defined.
    if (!(m_power_cumulative.back() > 0)) m_power_cumulative = m_cumulative;
    for (std::size_t k = 0; k < m_elements.size(); ++k) {
        m_top_factor[k].store(std::numeric_limits<double>::quiet_NaN());
    }
}

void ClusterTree::push(const PowerQuantum& quantum, std::vector<Rgb>& from_above) {
    from_above.assign(m_position.size(), Rgb::Zero());
    if (!is_cluster(*m_top)) return;
    if (!m_orientations) return push_node(*m_top, Rgb::Zero(), quantum, from_above);
    m_orientations->push(quantum, from_above);
    for (const std::uint32_t side : m_side) {
        from_above[side] = m_h.patch_set().material(side >> 1, std::uint8_t(side & 1)).reflectance *
                           from_above[side];
    }
}

void ClusterTree::push_node(Element& c, const Rgb& above, const PowerQuantum& quantum,
                            std::vector<Rgb>& from_above) {
    const Rgb h = above + quantum.power(c.received) / c.area;
    c.received = {};
    for (Element* k : m_nodes[c.id.patch].child) {
        if (is_cluster(*k)) {
            push_node(*k, h, quantum, from_above);
        } else {
            from_above[2 * std::size_t(k->id.patch) + k->id.side] =
                m_h.material(*k).reflectance * h;
        }
    }
}

void ClusterTree::pull() {
    // Children have larger indices than their parent (depth-first numbering): the reverse
    // index order visits children first.
    for (std::size_t k = m_elements.size(); k-- > 0;) average(m_elements[k]);
}

void ClusterTree::open_above(std::uint32_t side_value) const {
    // Opening is upward closed: above an open cluster every cluster is open.
    for (std::uint32_t c = m_side_parent[side_value];
         c != kNoParent && !m_open[c].load(std::memory_order_relaxed); c = m_nodes[c].parent) {
        mark(c);
    }
}

std::vector<std::int64_t> ClusterTree::open_flags() const {
    std::vector<std::int64_t> flags(m_elements.size());
    for (std::size_t k = 0; k < flags.size(); ++k) flags[k] = m_open[k].load();
    return flags;
}

void ClusterTree::set_open_flags(std::span<const std::int64_t> flags) {
    for (std::size_t k = 0; k < m_elements.size(); ++k) m_open[k].store(flags[k] != 0 ? 1 : 0);
}

std::size_t ClusterTree::settle() {
    std::fill(m_leaf_of_side.begin(), m_leaf_of_side.end(), -1);
    m_cluster_leaves = 0;
    std::size_t hidden = 0;  // sides under closed clusters, each a leaf of m_h
    // Parents come before their children in index order.
    for (std::size_t k = 0; k < m_elements.size(); ++k) {
        const Node& n = m_nodes[k];
        const bool parent_open = n.parent == kNoParent || m_open[n.parent].load() != 0;
        if (m_open[k].load() != 0 || !parent_open) continue;
        ++m_cluster_leaves;
        hidden += n.end - n.first;
        for (std::uint32_t pos = n.first; pos < n.end; ++pos) {
            m_leaf_of_side[m_side[pos]] = std::int32_t(k);
        }
    }
    return m_h.leaf_count() - hidden + m_cluster_leaves;
}

}  // namespace hmcr
