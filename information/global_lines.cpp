// SPDX-License-Identifier: Apache-2.0
// Global lines: uniformly distributed lines through the scene's bounding sphere (a uniform
// direction, then a uniform point of the disk across the sphere perpendicular to it). Each
// line is followed through every surface it crosses.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/memory.h"
#include "information/back_sides.h"
#include "information/channel_samples.h"
#include "rays/rng.h"
#include "rays/sampling.h"

namespace hmcr {
namespace {

constexpr std::uint64_t kLinesPerTask = 1024;  // lines per parallel task (fixed: results are too)
constexpr std::uint64_t kGlobalKey = 0x676c6f62616cULL;  // beyond every patch index
constexpr int kMaxHits = 1 << 16;  // a line crossing more surfaces is cut (never in practice)

struct Sphere {
    Vec3 centre = Vec3::Zero();
    double radius = 0;
};

Sphere bounding_sphere(const PatchSet& set) {
    Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
    for (const Patch& p : set.patches) {
        for (int k = 0; k < p.corner_count; ++k) {
            lo = lo.cwiseMin(p.corner[k]);
            hi = hi.cwiseMax(p.corner[k]);
        }
    }
    Sphere s{(lo + hi) / 2, 0};
    for (const Patch& p : set.patches) {
        for (int k = 0; k < p.corner_count; ++k) {
            s.radius = std::max(s.radius, (p.corner[k] - s.centre).norm());
        }
    }
    return s;
}

struct LineHit {
    std::uint32_t patch = 0;  // the front state
    Vec3 point;
    double facing = 0;  // n . direction: > 0 when the front faces forward along the line
    std::uint32_t back = ChannelSamples::kNoPatch;  // the back state there, if any

    // The state facing forward along the line, and the one facing back, or kNoPatch.
    std::uint32_t forward() const { return facing > 0 ? patch : (facing < 0 ? back : kNone); }
    std::uint32_t backward() const { return facing < 0 ? patch : (facing > 0 ? back : kNone); }
    static constexpr std::uint32_t kNone = ChannelSamples::kNoPatch;
};

// The surfaces crossed by line k, in order along its direction (into `hits`, reused).
Vec3 trace_line(const PatchSet& set, const EmbreeScene& scene, const BackSides* backs,
                const Sphere& s, std::uint64_t seed, std::uint64_t k, std::vector<LineHit>& hits) {
    Rng rng(seed, kGlobalKey, k);
    const double xi1 = rng.uniform(), xi2 = rng.uniform();
    Vec3 direction = sample_uniform_sphere(xi1, xi2);
    const double xi3 = rng.uniform(), xi4 = rng.uniform();
    const Vec2 disk = sample_uniform_disk(xi3, xi4) * s.radius;
    Vec3 t, b;
    tangent_frame(direction, t, b);
    const Vec3 origin = s.centre + disk.x() * t + disk.y() * b - 2 * s.radius * direction;
    hits.clear();
    Vec3 from = origin;
    while (hits.size() < kMaxHits) {
        const auto hit = scene.first_hit(from, direction);
        if (!hit) break;
        const std::uint32_t back =
            backs ? backs->at(hit->patch, from, direction, hit->distance) : LineHit::kNone;
        from += hit->distance * direction;  // march on Embree's points: never re-hit, never skip
        const Patch& q = set.patches[hit->patch];
        const double facing = q.normal.dot(direction);
        // The point itself on q's plane, from the line's origin in double precision.
        const double along = q.normal.dot(q.corner[0] - origin) / facing;
        hits.push_back({hit->patch, std::isfinite(along) ? origin + along * direction : from,
                        facing, back == BackSides::kNoState ? LineHit::kNone : back});
    }
    return direction;
}

struct Record {
    std::uint32_t slot = 0;  // patch * batches + batch
    std::uint32_t target = ChannelSamples::kNoPatch;
};

struct Block {
    std::vector<Record> records;
    KernelTally tally;
    std::vector<LineHit> hits;  // scratch, reused line after line
    std::vector<char> joined;   // scratch: segment k is open with a non-zero kernel
};

// The samples of one line (block.hits): one per side of each crossed surface, from that side
// to the neighbouring hit it faces (when that hit has a side facing back along the segment).
void add_line(const PatchSet& set, std::uint32_t batches, std::uint32_t batch, Block& block) {
    const std::vector<LineHit>& hits = block.hits;
    // Segment k joins hits k and k + 1; it carries a ray both ways when a side faces it at both.
    block.joined.assign(hits.size(), 0);
    for (std::size_t k = 0; k + 1 < hits.size(); ++k) {
        const std::uint32_t from = hits[k].forward(), to = hits[k + 1].backward();
        if (from == LineHit::kNone || to == LineHit::kNone) continue;
        const double v = log_kernel(set.patches[from], hits[k].point, set.patches[to],
                                    hits[k + 1].point, set.total_area);
        if (std::isnan(v)) continue;
        block.joined[k] = 1;
        block.tally.add(batch, v);
    }
    for (std::size_t k = 0; k < hits.size(); ++k) {
        const LineHit& h = hits[k];
        if (h.facing == 0) continue;  // grazing: measure zero
        for (const std::uint32_t state : {h.patch, h.back}) {
            if (state == LineHit::kNone) continue;
            std::uint32_t target = ChannelSamples::kNoPatch;
            if (state == h.forward() && k + 1 < hits.size() && block.joined[k]) {
                target = hits[k + 1].backward();
            }
            if (state == h.backward() && k > 0 && block.joined[k - 1]) {
                target = hits[k - 1].forward();
            }
            block.records.push_back({state * batches + batch, target});
        }
    }
}

// Gathers the blocks' records by slot, in block order (so independent of the thread count).
void gather(std::vector<Block>& blocks, std::size_t slots, ChannelSamples& out) {
    out.first.assign(slots + 1, 0);
    for (const Block& block : blocks) {
        for (const Record& r : block.records) ++out.first[r.slot + 1];
    }
    for (std::size_t s = 0; s < slots; ++s) out.first[s + 1] += out.first[s];
    out.target.assign(out.first.back(), ChannelSamples::kNoPatch);
    std::vector<std::uint64_t> cursor(out.first.begin(), out.first.end() - 1);
    for (Block& block : blocks) {
        for (const Record& r : block.records) out.target[cursor[r.slot]++] = r.target;
        block.records = {};
        block.tally.merge_into(out);
    }
}

}  // namespace

ChannelSamples trace_global_lines(const PatchSet& patches, const EmbreeScene& scene,
                                  const LineOptions& options, Progress& progress,
                                  const BackSides* backs) {
    ChannelSamples out;
    const std::uint32_t b = out.batches = batch_count(options);
    if (double(patches.patches.size()) * b >= double(ChannelSamples::kNoPatch)) {
        throw std::invalid_argument("too many patches x batches for global lines");
    }
    out.lines = options.lines;
    // About two samples a line in a closed scene (four where surfaces have backs), each a record
    // (8 bytes) and a target (4): refused before it is allocated.
    require_memory((backs ? 48.0 : 24.0) * double(options.lines),
                   fmt::format("{} global lines", options.lines));
    const Sphere sphere = bounding_sphere(patches);
    std::vector<Block> blocks((options.lines + kLinesPerTask - 1) / kLinesPerTask);
    parallel_blocks(blocks.size(), progress, [&](std::uint64_t i) {
        set_tracing_float_mode();
        Block& block = blocks[i];
        block.tally = KernelTally(b);
        const std::uint64_t k1 = std::min<std::uint64_t>(options.lines, (i + 1) * kLinesPerTask);
        for (std::uint64_t k = i * kLinesPerTask; k < k1; ++k) {
            trace_line(patches, scene, backs, sphere, options.seed, k, block.hits);
            add_line(patches, b, std::uint32_t(k % b), block);
        }
        block.hits = {};
        block.joined = {};
    });
    gather(blocks, patches.patches.size() * b, out);
    return out;
}

}  // namespace hmcr
