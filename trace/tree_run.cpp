// SPDX-License-Identifier: Apache-2.0
// TreeRun of trace/pixel_run.h: the subpixel quadtree of the entropy criteria (Rigau, Feixas,
// Sbert, "Entropy-based adaptive supersampling", 2003, Figure 5).
#include <array>
#include <vector>

#include "common/interrupt.h"
#include "trace/pixel_run.h"

namespace hmcr {
namespace {

// Sample keys of the tree: node id and quadrant, apart from the batch runs' keys.
constexpr std::uint64_t kTreeKey = std::uint64_t(1) << 62;

// A node's square of the pixel and its place in the tree, derived on the way down (not stored:
// a 512 x 512 image holds millions of nodes).
struct Region {
    double u0 = 0, v0 = 0, size = 1;
    std::uint64_t id = 0;  // root 0, child q of node k: 4k + 1 + q
    int depth = 0;

    // Quadrant q: (q & 1) the right half, (q >> 1) the lower half.
    Region child(int q) const {
        const double h = size / 2;
        return {u0 + (q & 1) * h, v0 + (q >> 1) * h, h, 4 * id + 1 + std::uint64_t(q), depth + 1};
    }
    Stratum quadrant(int q) const {
        const Region c = child(q);
        return {c.u0, c.v0, c.size, c.size};
    }
    int quadrant_of(double u, double v) const {
        return (u >= u0 + size / 2 ? 1 : 0) + (v >= v0 + size / 2 ? 2 : 0);
    }
};

struct Node {
    std::array<StoredSample, kNodeSamples> samples;  // samples[q] lies in quadrant q
    std::array<float, 2 * kNodeSamples> uv;          // where, for handing them down
    double value = 0;
    std::int32_t first_child = -1;  // its four children are consecutive; -1: none yet
    std::uint32_t rays = 0;         // of the node's own new samples
};

// What a subtree holds at a threshold.
struct Tally {
    std::uint64_t samples = 0, rays = 0;
    Rgb radiance = Rgb::Zero();  // the mean over the subtree's region
};

class TreeRun final : public PixelRun {
public:
    TreeRun(const Criterion& criterion, int max_depth, int x, int y)
        : m_criterion(criterion), m_max_depth(max_depth), m_x(x), m_y(y) {}

    void extend(double threshold, const PixelTracer& tracer) override {
        if (m_nodes.empty()) m_nodes.push_back(make_node(Region{}, nullptr, tracer));
        extend(0, Region{}, threshold, tracer);
    }
    std::uint32_t samples(double threshold) const override {
        return std::uint32_t(tally(0, Region{}, threshold).samples);
    }
    Rgb radiance(double threshold) const override { return tally(0, Region{}, threshold).radiance; }
    std::uint64_t rays(double threshold) const override {
        return tally(0, Region{}, threshold).rays;
    }
    std::uint64_t rays_traced() const override {
        std::uint64_t r = 0;
        for (const Node& n : m_nodes) r += n.rays;
        return r;
    }
    double first_value() const override { return m_nodes.front().value; }

private:
    bool refines(const Node& n, const Region& r, double threshold) const {
        return r.depth < m_max_depth && n.value > threshold;
    }
    Node make_node(const Region& r, const Node* parent, const PixelTracer& tracer) const;
    void extend(std::size_t i, const Region& r, double threshold, const PixelTracer& tracer);
    Tally tally(std::size_t i, const Region& r, double threshold) const;

    const Criterion& m_criterion;
    int m_max_depth;
    int m_x, m_y;
    std::vector<Node> m_nodes;  // m_nodes[0] is the pixel
};

// The node of region r: the parent's sample that lies in r (none for the pixel) and a new
// sample in each other quadrant.
Node TreeRun::make_node(const Region& r, const Node* parent, const PixelTracer& tracer) const {
    Node n;
    int inherited = -1;
    if (parent) {
        const int q = int(r.id - 1) & 3;  // r is child q of its parent
        inherited = r.quadrant_of(parent->uv[2 * q], parent->uv[2 * q + 1]);
        n.samples[inherited] = parent->samples[q];
        n.uv[2 * inherited] = parent->uv[2 * q];
        n.uv[2 * inherited + 1] = parent->uv[2 * q + 1];
    }
    for (int j = 0; j < int(kNodeSamples); ++j) {
        if (j == inherited) continue;
        const TracedSample t =
            tracer.sample(m_x, m_y, kTreeKey | (r.id << 2 | std::uint64_t(j)), r.quadrant(j));
        n.samples[j] = store(t.sample);
        n.uv[2 * j] = float(t.u);
        n.uv[2 * j + 1] = float(t.v);
        n.rays += t.rays;
    }
    std::array<PixelSample, kNodeSamples> expanded;
    for (std::size_t j = 0; j < kNodeSamples; ++j) expanded[j] = n.samples[j].expand();
    n.value = m_criterion.value(expanded, r.size * r.size);
    return n;
}

void TreeRun::extend(std::size_t i, const Region& r, double threshold, const PixelTracer& tracer) {
    if (!refines(m_nodes[i], r, threshold)) return;
    if (m_nodes[i].first_child < 0) {
        throw_if_interrupted();
        const Node parent = m_nodes[i];  // push_back may move the nodes
        m_nodes[i].first_child = std::int32_t(m_nodes.size());
        for (int q = 0; q < 4; ++q) m_nodes.push_back(make_node(r.child(q), &parent, tracer));
    }
    for (int q = 0; q < 4; ++q) {
        extend(std::size_t(m_nodes[i].first_child) + std::size_t(q), r.child(q), threshold, tracer);
    }
}

Tally TreeRun::tally(std::size_t i, const Region& r, double threshold) const {
    const Node& n = m_nodes[i];
    Tally t;
    t.samples = r.depth == 0 ? kNodeSamples : kNodeSamples - 1;  // one is the parent's
    t.rays = n.rays;
    if (!refines(n, r, threshold)) {
        for (const StoredSample& s : n.samples) t.radiance += s.expand().radiance;
        t.radiance /= double(kNodeSamples);
        return t;
    }
    for (int q = 0; q < 4; ++q) {
        const Tally c = tally(std::size_t(n.first_child) + std::size_t(q), r.child(q), threshold);
        t.samples += c.samples;
        t.rays += c.rays;
        t.radiance += c.radiance / 4;  // children weighed by their area
    }
    return t;
}

}  // namespace

std::uint64_t tree_run_bytes(int max_depth) {
    const std::uint64_t nodes = ((std::uint64_t(1) << (2 * (max_depth + 1))) - 1) / 3;
    return sizeof(TreeRun) + 2 * nodes * sizeof(Node);  // capacity up to twice the size
}

std::unique_ptr<PixelRun> make_tree_run(const Criterion& criterion, int max_depth, int x, int y) {
    return std::make_unique<TreeRun>(criterion, max_depth, x, y);
}

}  // namespace hmcr
