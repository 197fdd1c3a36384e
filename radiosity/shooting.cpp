#include "radiosity/shooting.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include "rays/element_sampler.h"
#include "rays/rng.h"
#include "rays/sampling.h"

namespace hmcr {

void IterationSources::rebuild(const Hierarchy& h) {
    leaves.clear();
    m_weights.clear();
    total = 0;
    max_share = Rgb::Zero();
    h.for_each_leaf([&](const Element& e) {
        const double w = e.area * channel_sum(e.unshot);
        if (w <= 0) return;
        total += w;
        max_share = max_share.max(e.unshot / channel_sum(e.unshot));
        leaves.push_back({e.unshot, channel_sum(e.unshot), e.domain, e.id.patch});
        m_weights.push_back(w);
    });
    if (leaves.empty()) {
        alias.reset();
    } else if (alias) {
        alias->assign(m_weights);
    } else {
        alias.emplace(m_weights);
    }
}

namespace {

enum class Fate : std::uint8_t { deposited, escaped, back_face };

struct RayResult {
    Rgb power = Rgb::Zero();  // the ray's power (deposited: rho * power / A was added later)
    Fate fate = Fate::escaped;
};

// Step 3: a source leaf by unshot power, a uniform point on it, a cosine direction.
struct RayStart {
    const IterationSources::Leaf* leaf;
    Vec2 x_uv;
    Vec3 x, direction;
};

RayStart start_ray(const Hierarchy& h, const IterationSources& sources, Rng& rng) {
    const IterationSources::Leaf& leaf = sources.pick(rng.uniform());
    const Patch& src = h.patch_set().patches[leaf.patch];
    const Vec2 x_uv = sample_element(src, leaf.domain, rng.uniform(), rng.uniform());
    const Vec3 dir = sample_cosine_hemisphere(src.normal, rng.uniform(), rng.uniform());
    return {&leaf, x_uv, src.point(x_uv), dir};
}

// Steps 3 and 4; a deposited ray's descent (step 5) is written to `query`, for refine_links.
RayResult trace_ray(const RefinementContext& ctx, const IterationSources& sources,
                    double power_scale, Rng& rng, LinkQuery& query) {
    const Hierarchy& h = ctx.hierarchy;
    const RayStart start = start_ray(h, sources, rng);
    RayResult r;
    r.power = power_scale * start.leaf->unshot / start.leaf->unshot_sum;
    const auto hit = ctx.scene.first_hit(start.x, start.direction);
    if (!hit) return r;
    const Patch& rcv = h.patch_set().patches[hit->patch];
    if (rcv.normal.dot(start.direction) >= 0) {
        r.fate = Fate::back_face;
        return r;
    }
    query.receiver_patch = hit->patch;
    query.source_patch = start.leaf->patch;
    query.y_uv = rcv.param(start.x + hit->distance * start.direction);
    query.x_uv = start.x_uv;
    r.fate = Fate::deposited;
    return r;
}

}  // namespace

struct ShootingBuffers::Impl {
    struct Chunk {
        Quanta shot{}, escaped{}, back_face{};
    };
    // Each ray's deposit, added after the batch by one thread: atomic adds from both threads
    // onto the few hot elements of a small scene made 2 threads 20% slower.
    struct Deposit {
        Quanta quanta{};
        bool lands = false;  // on a front face: the descent finds its element
    };
    // The batch's descents are made together, after its rays are traced, so that rays between
    // the same patches decide their shared links once (refine_links).
    struct Batch {
        std::uint64_t first = 0, n = 0;
        std::vector<Chunk> chunks;
        std::vector<Deposit> deposits;
        std::vector<LinkQuery> queries;
    };
    std::array<Batch, 2> batches;  // the second while the first descends (2 threads or more)
    DescentScratch descent;
};

ShootingBuffers::ShootingBuffers() : m_impl(std::make_unique<Impl>()) {}
ShootingBuffers::~ShootingBuffers() = default;

namespace {

constexpr std::uint64_t kBatchRays = 1 << 16;
constexpr std::uint64_t kGrain = 256;

// Pilot rays draw from streams of their own, apart from the iteration's rays.
constexpr std::uint64_t kPilotStream = std::uint64_t(1) << 62;

}  // namespace

double reflected_fraction(const RefinementContext& ctx, const IterationSources& sources,
                          std::uint32_t iteration, std::uint64_t rays) {
    const Hierarchy& h = ctx.hierarchy;
    if (sources.total <= 0 || rays == 0) return 0;
    set_tracing_float_mode();
    double reflected = 0;
    for (std::uint64_t k = 0; k < rays; ++k) {
        Rng rng(ctx.seed, iteration, kPilotStream + k);
        const RayStart start = start_ray(h, sources, rng);
        const auto hit = ctx.scene.first_hit(start.x, start.direction);
        if (!hit) continue;
        const Patch& rcv = h.patch_set().patches[hit->patch];
        if (rcv.normal.dot(start.direction) >= 0) continue;
        const Rgb unit = start.leaf->unshot / start.leaf->unshot_sum;
        reflected += channel_sum(h.patch_set().reflectance(rcv) * unit);
    }
    return reflected / double(rays);
}

IterationOutcome shoot_iteration(const RefinementContext& ctx, const IterationSources& sources,
                                 std::uint32_t iteration, std::uint64_t rays, RaySlice slice,
                                 const std::function<void(std::uint64_t)>& on_batch,
                                 ShootingBuffers* buffers) {
    IterationOutcome out;
    if (rays == 0 || sources.total <= 0) return out;
    slice.end = std::min(slice.end, rays);
    const double power_scale = sources.total / double(rays);  // S / N_iter
    out.quantum = PowerQuantum::for_iteration(power_scale * sources.max_share, rays);
    if (slice.begin >= slice.end) return out;
    const std::uint64_t batch_rays = std::min(slice.end - slice.begin, kBatchRays);
    // One thread cannot overlap anything: it reuses one batch's buffers, which stay in cache.
    const auto threads = std::min<std::size_t>(
        tbb::this_task_arena::max_concurrency(),
        tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
    const bool overlap = threads > 1;
    std::optional<ShootingBuffers> own;
    if (!buffers) buffers = &own.emplace();
    using Batch = ShootingBuffers::Impl::Batch;
    std::array<Batch, 2>& batches = buffers->impl().batches;
    for (Batch& b : batches) {
        b.deposits.resize(batch_rays);
        b.queries.resize(batch_rays);
        if (!overlap) break;
    }
    auto trace = [&](Batch& b, std::uint64_t first) {
        b.first = first;
        b.n = std::min(kBatchRays, slice.end - first);
        b.chunks.assign((b.n + kGrain - 1) / kGrain, {});
        tbb::parallel_for(std::uint64_t(0), b.chunks.size(), [&](std::uint64_t c) {
            set_tracing_float_mode();
            ShootingBuffers::Impl::Chunk& chunk = b.chunks[c];
            for (std::uint64_t k = c * kGrain; k < std::min(b.n, (c + 1) * kGrain); ++k) {
                Rng rng(ctx.seed, iteration, first + k);
                const RayResult r = trace_ray(ctx, sources, power_scale, rng, b.queries[k]);
                const double dither = rng.uniform();
                const Quanta power = out.quantum.count(r.power, dither);
                add(chunk.shot, power);
                if (r.fate == Fate::escaped) add(chunk.escaped, power);
                if (r.fate == Fate::back_face) add(chunk.back_face, power);
                b.deposits[k] = {};
                if (r.fate != Fate::deposited) continue;
                // docs/design.md §3: received += rho * Phi (over A when pushed).
                const PatchSet& ps = ctx.hierarchy.patch_set();
                const Rgb& rho = ps.reflectance(ps.patches[b.queries[k].receiver_patch]);
                b.deposits[k] = {out.quantum.count(rho * r.power, dither), true};
            }
        });
    };
    DescentScratch& scratch = buffers->impl().descent;
    auto finish = [&](Batch& b) {
        std::size_t landed = 0;
        for (std::uint64_t k = 0; k < b.n; ++k) {
            if (b.deposits[k].lands) b.queries[landed++] = b.queries[k];
        }
        RefinementCounters counters;
        refine_links(ctx, {b.queries.data(), landed}, counters, scratch);
        out.counters += counters;
        for (std::uint64_t k = 0, q = 0; k < b.n; ++k) {
            if (!b.deposits[k].lands) continue;
            add(b.queries[q++].receiver->received, b.deposits[k].quanta);
        }
        for (const auto& c : b.chunks) {
            add(out.shot_power, c.shot);
            add(out.escaped_power, c.escaped);
            add(out.back_face_power, c.back_face);
        }
        out.rays += b.n;
        if (on_batch) on_batch(out.rays);
    };
    // Tracing reads only the patches, the sources and the Embree scene, never the hierarchy, so
    // the next batch is traced while this one descends and deposits: the batch's sequential
    // steps (compaction, sort, deposits) then overlap the next batch's rays on other threads.
    // The batches still descend and deposit in order, so the bits are the same.
    trace(batches[0], slice.begin);
    for (std::size_t current = 0;;) {
        Batch& b = batches[current];
        const std::uint64_t next = b.first + b.n;
        if (next >= slice.end) {
            finish(b);
            break;
        }
        if (!overlap) {
            finish(b);
            trace(b, next);
            continue;
        }
        Batch& following = batches[current ^ 1];
        tbb::task_group tracing;
        tracing.run([&trace, &following, next] { trace(following, next); });
        try {
            finish(b);
        } catch (...) {  // an interrupt from on_batch: the tracing task must end first
            tracing.cancel();
            tracing.wait();
            throw;
        }
        tracing.wait();
        current ^= 1;
    }
    return out;
}

}  // namespace hmcr
