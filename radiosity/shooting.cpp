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

// What generating a ray decided that later stages need: its source leaf, its origin's
// parameter point there, and the ray's last uniform, which dithers its power's rounding.
struct RayStart {
    std::uint32_t leaf = 0;
    Vec2f x_uv{0, 0};
    double dither = 0;
};

namespace {

// Step 3: a source leaf by unshot power, a uniform point on it, a cosine direction. The draws
// of ray `index` of iteration `iteration`, in this order: leaf, point (2), direction (2),
// dither.
void start_ray(const Hierarchy& h, const IterationSources& sources, std::uint64_t seed,
               std::uint32_t iteration, std::uint64_t index, RayStart& start, BatchRay& ray) {
    Rng rng(seed, iteration, index);
    const double xi_leaf = rng.uniform();
    const double xi_u = rng.uniform(), xi_v = rng.uniform();
    const double xi_r = rng.uniform(), xi_phi = rng.uniform();
    start.dither = rng.uniform();
    start.leaf = sources.pick_index(xi_leaf);
    const IterationSources::Leaf& leaf = sources.leaves[start.leaf];
    const Patch& src = h.patch_set().patches[leaf.patch];
    const Vec2 x_uv = sample_element(src, leaf.domain, xi_u, xi_v);
    start.x_uv = x_uv.cast<float>();
    const Vec3 x = src.point(x_uv);
    const Vec3 dir = sample_cosine_hemisphere(src.normal, xi_r, xi_phi);
    for (int c = 0; c < 3; ++c) {
        ray.origin[c] = float(x[c]);
        ray.direction[c] = float(dir[c]);
    }
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
    // The stages pass each chunk of rays on in these arrays: generated (starts, rays), traced
    // (hits), and turned into deposits and the queries of their descents.
    struct Batch {
        std::uint64_t first = 0, n = 0;
        std::vector<Chunk> chunks;
        std::vector<RayStart> starts;
        std::vector<BatchRay> rays;
        std::vector<BatchHit> hits;
        std::vector<Deposit> deposits;
        std::vector<LinkQuery> queries;
        std::vector<Element*> receivers;
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

// The cosine of the receiver's front with the ray direction: negative on a front face.
double facing(const Patch& receiver, const BatchRay& ray) {
    return receiver.normal.x() * double(ray.direction[0]) +
           receiver.normal.y() * double(ray.direction[1]) +
           receiver.normal.z() * double(ray.direction[2]);
}

}  // namespace

double reflected_fraction(const RefinementContext& ctx, const IterationSources& sources,
                          std::uint32_t iteration, std::uint64_t rays) {
    const Hierarchy& h = ctx.hierarchy;
    if (sources.total <= 0 || rays == 0) return 0;
    set_tracing_float_mode();
    std::vector<RayStart> starts(rays);
    std::vector<BatchRay> batch(rays);
    std::vector<BatchHit> hits(rays);
    for (std::uint64_t k = 0; k < rays; ++k) {
        start_ray(h, sources, ctx.seed, iteration, kPilotStream + k, starts[k], batch[k]);
    }
    ctx.scene.first_hits(batch, hits);
    double reflected = 0;
    for (std::uint64_t k = 0; k < rays; ++k) {
        if (hits[k].patch == BatchHit::kNoHit) continue;
        const Patch& rcv = h.patch_set().patches[hits[k].patch];
        if (facing(rcv, batch[k]) >= 0) continue;
        const IterationSources::Leaf& leaf = sources.leaves[starts[k].leaf];
        reflected += channel_sum(h.patch_set().reflectance(rcv) * leaf.unshot / leaf.unshot_sum);
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
        b.starts.resize(batch_rays);
        b.rays.resize(batch_rays);
        b.hits.resize(batch_rays);
        b.deposits.resize(batch_rays);
        b.queries.resize(batch_rays);
        b.receivers.resize(batch_rays);
        if (!overlap) break;
    }
    const Hierarchy& h = ctx.hierarchy;
    const PatchSet& ps = h.patch_set();
    // One chunk of rays through the stages: generated, traced, then each ray's power and fate
    // (steps 3 and 4) and, for a ray that lands, its deposit and the query of its descent.
    auto trace_chunk = [&](Batch& b, std::uint64_t begin, std::uint64_t end,
                           ShootingBuffers::Impl::Chunk& chunk) {
        for (std::uint64_t k = begin; k < end; ++k) {
            start_ray(h, sources, ctx.seed, iteration, b.first + k, b.starts[k], b.rays[k]);
        }
        ctx.scene.first_hits({b.rays.data() + begin, end - begin},
                             {b.hits.data() + begin, end - begin});
        for (std::uint64_t k = begin; k < end; ++k) {
            const RayStart& start = b.starts[k];
            const IterationSources::Leaf& leaf = sources.leaves[start.leaf];
            const Rgb power = power_scale * leaf.unshot / leaf.unshot_sum;
            const Quanta quanta = out.quantum.count(power, start.dither);
            add(chunk.shot, quanta);
            b.deposits[k] = {};
            const BatchHit& hit = b.hits[k];
            if (hit.patch == BatchHit::kNoHit) {
                add(chunk.escaped, quanta);
                continue;
            }
            const Patch& rcv = ps.patches[hit.patch];
            const BatchRay& ray = b.rays[k];
            if (facing(rcv, ray) >= 0) {
                add(chunk.back_face, quanta);
                continue;
            }
            const Vec3 y(double(ray.origin[0]) + double(hit.distance) * ray.direction[0],
                         double(ray.origin[1]) + double(hit.distance) * ray.direction[1],
                         double(ray.origin[2]) + double(hit.distance) * ray.direction[2]);
            b.queries[k] = {hit.patch, leaf.patch,
                            rcv.param_of_hit(hit.second_triangle != 0, hit.b1, hit.b2, y),
                            start.x_uv};
            // docs/design.md §3: received += rho * Phi (over A when pushed).
            b.deposits[k] = {out.quantum.count(ps.reflectance(rcv) * power, start.dither), true};
        }
    };
    auto trace = [&](Batch& b, std::uint64_t first) {
        b.first = first;
        b.n = std::min(kBatchRays, slice.end - first);
        b.chunks.assign((b.n + kGrain - 1) / kGrain, {});
        tbb::parallel_for(std::uint64_t(0), b.chunks.size(), [&](std::uint64_t c) {
            set_tracing_float_mode();
            trace_chunk(b, c * kGrain, std::min(b.n, (c + 1) * kGrain), b.chunks[c]);
        });
    };
    DescentScratch& scratch = buffers->impl().descent;
    auto finish = [&](Batch& b) {
        std::size_t landed = 0;
        for (std::uint64_t k = 0; k < b.n; ++k) {
            if (b.deposits[k].lands) b.queries[landed++] = b.queries[k];
        }
        RefinementCounters counters;
        refine_links(ctx, {b.queries.data(), landed}, {b.receivers.data(), landed}, counters,
                     scratch);
        out.counters += counters;
        for (std::uint64_t k = 0, q = 0; k < b.n; ++k) {
            if (!b.deposits[k].lands) continue;
            add(b.receivers[q++]->received, b.deposits[k].quanta);
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
