// SPDX-License-Identifier: Apache-2.0
#include "bench/embree_floor.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "radiosity/shooting.h"
#include "rays/element_sampler.h"
#include "rays/rng.h"
#include "rays/sampling.h"

namespace hmcr::bench {
namespace {

constexpr std::uint64_t kChunk = std::uint64_t(1) << 22;

double median_of(int runs, const std::function<void()>& run) {
    std::vector<double> t(std::size_t(runs), 0.0);
    for (double& s : t) {
        const auto start = std::chrono::steady_clock::now();
        run();
        s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return median(std::move(t));
}

double trace_first_hits(const EmbreeScene& scene, const GeneratedRays& rays, std::size_t n,
                        int runs) {
    std::vector<BatchHit> hits(n);
    return median_of(runs, [&] {
        // The solve's chunks of rays, and its query: first_hits() in packets.
        tbb::parallel_for(std::size_t(0), (n + kChunkRays - 1) / kChunkRays, [&](std::size_t c) {
            set_tracing_float_mode();
            scene.first_hits(rays, c * kChunkRays, std::min<std::size_t>(n, (c + 1) * kChunkRays),
                             hits);
        });
    });
}

double trace_occlusions(const EmbreeScene& scene, const std::vector<Segment>& segments, int lines,
                        int runs) {
    const std::size_t pairs = segments.size() / std::size_t(lines);
    return median_of(runs, [&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pairs, 1024), [&](auto r) {
            set_tracing_float_mode();
            const std::size_t n = std::size_t(lines);
            std::vector<Vec3> from(n), to(n);
            const auto visible = std::make_unique<bool[]>(n);
            for (std::size_t k = r.begin(); k < r.end(); ++k) {
                for (int l = 0; l < lines; ++l) {
                    from[std::size_t(l)] = segments[k * std::size_t(lines) + std::size_t(l)].from;
                    to[std::size_t(l)] = segments[k * std::size_t(lines) + std::size_t(l)].to;
                }
                // One pair's lines together, as the line sampler casts them.
                scene.visible_many(from, to, {visible.get(), n});
            }
        });
    });
}

}  // namespace

double median(std::vector<double> seconds) {
    std::sort(seconds.begin(), seconds.end());
    return seconds[seconds.size() / 2];
}

GeneratedRays first_hit_rays(const PatchSet& set, std::uint64_t n, std::uint64_t stream,
                             bool dealt) {
    std::vector<double> cumulative;
    double total = 0;
    for (const Patch& p : set.patches) cumulative.push_back(total += p.area);
    Rng rng(1234, stream);
    std::vector<std::size_t> source(n);
    for (std::size_t& s : source) {
        const auto it =
            std::upper_bound(cumulative.begin(), cumulative.end(), rng.uniform() * total);
        s = std::min<std::size_t>(std::size_t(it - cumulative.begin()), set.patches.size() - 1);
    }
    if (dealt) std::sort(source.begin(), source.end());
    GeneratedRays rays;
    rays.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const Patch& p = set.patches[source[k]];
        const Vec3 o = p.point(sample_element(p, Domain::root(), rng.uniform(), rng.uniform()));
        const Vec3 d = sample_cosine_hemisphere(p.normal, rng.uniform(), rng.uniform());
        for (int c = 0; c < 3; ++c) {
            rays.origin[c][k] = float(o[c]);
            rays.direction[c][k] = float(d[c]);
        }
    }
    return rays;
}

std::vector<Segment> pair_segments(const Hierarchy& h, const std::vector<const Element*>& leaves,
                                   std::uint64_t n_pairs, int lines, std::uint64_t stream) {
    std::vector<Segment> out;
    out.reserve(n_pairs * std::uint64_t(lines));
    Rng rng(4321, stream);
    auto point_on = [&](const Element& e) {
        const Patch& p = h.patch(e);
        return p.point(sample_element(p, e.domain, rng.uniform(), rng.uniform()));
    };
    for (std::uint64_t k = 0; k < n_pairs; ++k) {
        const Element& a = *leaves[std::size_t(rng.uniform() * double(leaves.size()))];
        const Element& b = *leaves[std::size_t(rng.uniform() * double(leaves.size()))];
        for (int l = 0; l < lines; ++l) out.push_back({point_on(a), point_on(b)});
    }
    return out;
}

double solve_floor_seconds(const EmbreeScene& scene, const Hierarchy& h, std::uint64_t rays,
                           std::uint64_t lines_cast, int lines, bool dealt) {
    const int runs = rays + lines_cast > kChunk ? 1 : 3;
    double seconds = 0;
    for (std::uint64_t done = 0, k = 0; done < rays; done += kChunk, ++k) {
        const std::uint64_t n = std::min(kChunk, rays - done);
        seconds += trace_first_hits(scene, first_hit_rays(h.patch_set(), n, k, dealt), n, runs);
    }
    const std::uint64_t pairs = lines_cast / std::uint64_t(lines), chunk_pairs = kChunk / lines;
    std::vector<const Element*> leaves;
    if (pairs > 0) h.for_each_leaf([&](const Element& e) { leaves.push_back(&e); });
    for (std::uint64_t done = 0, k = 0; done < pairs; done += chunk_pairs, ++k) {
        const auto chunk = pair_segments(h, leaves, std::min(chunk_pairs, pairs - done), lines, k);
        seconds += trace_occlusions(scene, chunk, lines, runs);
    }
    return seconds;
}

}  // namespace hmcr::bench
