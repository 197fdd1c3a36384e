// SPDX-License-Identifier: Apache-2.0
#include "radiosity/line_sampler.h"

#include <array>
#include <utility>

#include "rays/element_sampler.h"
#include "rays/point_kernel.h"

namespace hmcr {
namespace {

// The lines between the points on_i(u, v) and on_j(u, v), each a (point, normal) pair.
template <class OnI, class OnJ>
void kernel_lines(const EmbreeScene& scene, Rng& rng, std::span<double> out, const OnI& on_i,
                  const OnJ& on_j) {
    constexpr std::size_t kBatch = 64;
    std::array<Vec3, kBatch> xs, ys;
    std::array<std::size_t, kBatch> slot;
    std::array<bool, kBatch> vis;
    for (std::size_t first = 0; first < out.size(); first += kBatch) {
        const std::size_t n = std::min(kBatch, out.size() - first);
        std::size_t cast = 0;  // only lines with a non-zero kernel need a visibility query
        for (std::size_t k = 0; k < n; ++k) {
            // The draws in a fixed order, each point's v before its u (an argument list's order
            // would be the compiler's): the same lines from every compiler.
            const double xv = rng.uniform(), xu = rng.uniform();
            const auto [x, nx] = on_i(xu, xv);
            const double yv = rng.uniform(), yu = rng.uniform();
            const auto [y, ny] = on_j(yu, yv);
            out[first + k] = point_kernel(x, nx, y, ny);
            if (out[first + k] > 0) {
                xs[cast] = x;
                ys[cast] = y;
                slot[cast++] = first + k;
            }
        }
        scene.visible_many({xs.data(), cast}, {ys.data(), cast}, {vis.data(), cast});
        for (std::size_t k = 0; k < cast; ++k) {
            if (!vis[k]) out[slot[k]] = 0;
        }
    }
}

// Points uniform on an element of a patch, all with the patch side's normal.
struct OnElement {
    OnElement(const Hierarchy& h, const Element& e)
        : patch(h.patch(e)), normal(h.normal(e)), sampler(patch, e.domain) {}
    std::pair<Vec3, Vec3> operator()(double u, double v) const {
        return {patch.point(sampler(u, v)), normal};
    }
    const Patch& patch;
    const Vec3 normal;
    const ElementSampler sampler;
};

struct OnCluster {
    std::pair<Vec3, Vec3> operator()(double u, double v) const {
        return clusters.point(cluster, u, v);
    }
    const ClusterTree& clusters;
    const Element& cluster;
};

// The top cluster as a source: its points where its light leaves it.
struct FromTop {
    std::pair<Vec3, Vec3> operator()(double u, double v) const {
        return clusters.source_point(u, v);
    }
    const ClusterTree& clusters;
};

}  // namespace

void sample_kernel(const EmbreeScene& scene, const Hierarchy& hierarchy, const Element& i,
                   const Element& j, Rng& rng, std::span<double> out, const ClusterTree* clusters) {
    const bool ci = is_cluster(i), cj = is_cluster(j);
    if (!ci && !cj) {
        kernel_lines(scene, rng, out, OnElement(hierarchy, i), OnElement(hierarchy, j));
    } else if (ci && cj && &j == &clusters->top()) {
        kernel_lines(scene, rng, out, OnCluster{*clusters, i}, FromTop{*clusters});
    } else if (ci && cj) {
        kernel_lines(scene, rng, out, OnCluster{*clusters, i}, OnCluster{*clusters, j});
    } else if (ci) {
        kernel_lines(scene, rng, out, OnCluster{*clusters, i}, OnElement(hierarchy, j));
    } else {
        kernel_lines(scene, rng, out, OnElement(hierarchy, i), OnCluster{*clusters, j});
    }
}

}  // namespace hmcr
