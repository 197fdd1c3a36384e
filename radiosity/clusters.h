// SPDX-License-Identifier: Apache-2.0
// Clusters of patches above the patch roots, each receiving as an isotropic cloud of surfaces or
// by its sides' orientations (docs/design.md §2.7): binary trees built once from the patches'
// centres, one over the fronts and one over the backs, whose nodes are elements the descent
// links like any other.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "radiosity/cluster_orientations.h"
#include "radiosity/hierarchy.h"
#include "radiosity/solver_options.h"

namespace hmcr {

// The side value of a cluster's ElementId: no patch side has it, so its lines' streams are its
// own (its id.patch is the cluster's index, in depth-first order).
inline constexpr std::uint8_t kClusterSide = 2;
inline bool is_cluster(const Element& e) { return e.id.side == kClusterSide; }

class ClusterTree {
public:
    // The trees over h's sides. Makes every two-sided patch's back root, which the clusters
    // hold from the start. receiver_weights (per side value) are what a link's weight takes
    // for each side instead of its reflectance (view importance, docs/design.md §3.12); empty:
    // the reflectances. `model`: how a cluster receives, isotropic or oriented.
    explicit ClusterTree(Hierarchy& h, std::span<const Rgb> receiver_weights = {},
                         Clustering model = Clustering::isotropic);
    ClusterTree(const ClusterTree&) = delete;
    ClusterTree& operator=(const ClusterTree&) = delete;

    // Where every descent starts: a cluster, or the only patch's front root.
    Element& top() const { return *m_top; }
    std::size_t size() const { return m_elements.size(); }
    Clustering model() const {
        return m_orientations ? Clustering::oriented : Clustering::isotropic;
    }
    // Whether cluster c may take a ray's deposit: every cluster but the one joining the fronts'
    // tree and the backs' (docs/design.md §2.7), which a descent always splits.
    bool may_receive(const Element& c) const { return &c != m_join; }

    // The child of cluster c that holds the side `side_value` (2 * patch + side).
    Element& child_toward(const Element& c, std::uint32_t side_value) const {
        const Node& n = m_nodes[c.id.patch];
        return *n.child[m_position[side_value] < n.mid ? 0 : 1];
    }
    // What a link's weight takes for cluster c as a receiver: the area-weighted mean of its
    // sides' reflectances (rho_C), or of their receiver weights.
    const Rgb& receiver_weight(const Element& c) const { return m_nodes[c.id.patch].weight; }
    // The geometric factor of the link (c, top), kept once found within an iteration: the top's
    // points follow the iteration's frozen power, and a descent links a receiver cluster to the
    // top alone (docs/design.md §2.7). NaN until set; any thread may set it, to the one value
    // it has.
    double top_factor(const Element& c) const {
        return m_top_factor[c.id.patch].load(std::memory_order_relaxed);
    }
    void set_top_factor(const Element& c, double factor) const {
        m_top_factor[c.id.patch].store(factor, std::memory_order_relaxed);
    }
    // A point uniform by area on cluster c and the normal of the side it lies on, from two
    // uniform numbers.
    std::pair<Vec3, Vec3> point(const Element& c, double xu, double xv) const {
        return point_by(m_cumulative, c, xu, xv);
    }
    // A point of the top as a source (docs/design.md §2.7): each side chosen in proportion to
    // the power it shoots this iteration (as of begin_iteration; by area before the first),
    // uniform by area within it.
    std::pair<Vec3, Vec3> source_point(double xu, double xv) const {
        return point_by(m_power_cumulative, *m_top, xu, xv);
    }
    // At the start of an iteration, the values frozen for it: what each side shoots (A Delta B,
    // or A B under LinkWeight::total, summed over channels), and every top factor forgotten.
    void begin_iteration(LinkWeight weight);

    // A ray's incident power Phi (in quanta), arriving along unit `direction` on cluster c:
    // all of it to c (isotropic), or split among c's sides by their projected area toward the
    // ray (oriented; `dither`, the ray's, keys the rounding).
    void receive(Element& c, const Vec3& direction, const Quanta& incident, double dither) {
        if (m_orientations) {
            m_orientations->deposit(c.id.patch, direction, incident, dither);
        } else {
            add(c.received, incident);
        }
    }
    // The cosine the power oracle takes at cluster c's end of a centre line along unit d: 1/4
    // (isotropic), or the fraction of c's area projected toward d (oriented).
    double end_cosine(const Element& c, const Vec3& d) const {
        return m_orientations ? m_orientations->projected_fraction(c.id.patch, d) : 0.25;
    }
    // What the orientation classes received, for the ranks' sum; empty when isotropic.
    std::span<Quanta> class_received() {
        return m_orientations ? m_orientations->received() : std::span<Quanta>{};
    }

    // The first half of push-pull: the clusters' received power, as irradiance carried down,
    // becomes for each side the radiosity rho_q h its root starts its own push-pull with
    // (from_above[2 * patch + side], resized and zeroed here).
    void push(const PowerQuantum& quantum, std::vector<Rgb>& from_above);
    // The last half: every cluster takes the area-weighted averages of its children's B and
    // Delta B, children first.
    void pull();

    // Every cluster, in index order (the order every rank shares).
    template <class F>
    void for_each_cluster(F&& f) {
        for (Element& e : m_elements) f(e);
    }

    // The mesh (docs/design.md §2.7): a cluster is open once a descent has gone below it, as a
    // receiver split or through an element of its sides subdivided. The mesh's leaves are the
    // closed clusters whose parent is open, and the leaves of the sides below open clusters.
    // Any thread may open; opening is idempotent, so the open set is the same for any order.
    void open(const Element& c) const { mark(c.id.patch); }
    // Opens every cluster holding the side side_value, before an element of it is subdivided.
    void open_above(std::uint32_t side_value) const;
    bool is_open(const Element& c) const {
        return m_open[c.id.patch].load(std::memory_order_relaxed) != 0;
    }
    // The open flags as integers, for the ranks' union (rank_merge.h) and a frozen mesh's
    // clusters (opened as its shape's were), and back.
    std::vector<std::int64_t> open_flags() const;
    void set_open_flags(std::span<const std::int64_t> flags);
    // After the subdivisions of an iteration: finds the clusters that are leaves of the mesh and
    // returns its leaf count (h's leaves less the sides under closed clusters, plus those).
    std::size_t settle();
    // The cluster leaf holding side side_value, or none (as of the last settle()).
    Element* closed_leaf(std::uint32_t side_value) {
        const std::int32_t c = m_leaf_of_side[side_value];
        return c < 0 ? nullptr : &m_elements[std::size_t(c)];
    }
    // Each side value's cluster leaf index, -1 where the side is in the mesh itself.
    const std::vector<std::int32_t>& leaf_of_side() const { return m_leaf_of_side; }
    std::size_t cluster_leaves() const { return m_cluster_leaves; }

private:
    static constexpr std::uint32_t kNoParent = ~std::uint32_t(0);
    struct Node {
        std::array<Element*, 2> child{};
        std::uint32_t first = 0, mid = 0, end = 0;  // its sides' positions, child 1's from mid
        std::uint32_t parent = kNoParent;
        Rgb weight = Rgb::Zero();  // receiver_weight()
    };

    Element* build(std::span<std::uint32_t> patches, std::uint8_t side);  // over these sides
    Element* leaf(std::uint32_t patch, std::uint8_t side);
    Element& new_cluster(std::uint32_t first);
    void mark(std::uint32_t cluster) const {
        if (!m_open[cluster].load(std::memory_order_relaxed)) {
            m_open[cluster].store(1, std::memory_order_relaxed);
        }
    }
    void adopt(const Element& c);
    void finish(Element& c);
    Rgb side_weight(const Element& root) const;  // a side root's receiver weight
    std::pair<Vec3, Vec3> point_by(const std::vector<double>& cumulative, const Element& c,
                                   double xu, double xv) const;
    void average(Element& c) const;  // B and Delta B from the children's
    void orient();                   // m_orientations, from the finished tree
    void push_node(Element& c, const Rgb& above, const PowerQuantum& quantum,
                   std::vector<Rgb>& from_above);

    Hierarchy& m_h;
    std::span<const Rgb> m_weights;   // per side value; empty: the reflectances
    std::vector<Element> m_elements;  // sized once: clusters never move
    std::vector<Node> m_nodes;
    std::unique_ptr<std::atomic<double>[]> m_top_factor;  // top_factor(), per cluster
    std::size_t m_used = 0;
    std::unique_ptr<std::atomic<std::uint8_t>[]> m_open;  // is_open(), per cluster
    std::vector<std::uint32_t> m_side_parent;  // the cluster holding each side value's root
    std::vector<std::int32_t> m_leaf_of_side;  // closed_leaf(), per side value
    std::size_t m_cluster_leaves = 0;
    std::vector<std::uint32_t> m_position;   // of each side value, in the tree's order
    std::vector<std::uint32_t> m_side;       // the side value at each position
    std::vector<double> m_cumulative;        // areas of the sides before each position
    std::vector<double> m_power_cumulative;  // their shot power, as of begin_iteration
    Element* m_top = nullptr;
    Element* m_join = nullptr;  // the top, when it joins the fronts' tree and the backs'; none
    std::unique_ptr<ClusterOrientations> m_orientations;  // oriented clusters only
};

}  // namespace hmcr
