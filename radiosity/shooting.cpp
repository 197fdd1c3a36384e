// SPDX-License-Identifier: Apache-2.0
#include "radiosity/shooting.h"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include "common/populated.h"
#include "radiosity/control_variate.h"
#include "radiosity/sequence_cursors.h"
#include "rays/element_sampler.h"
#include "rays/embree_scene.h"
#include "rays/rng.h"
#include "rays/sampling.h"

namespace hmcr {

void IterationSources::add(const RayRegion& region, double area, const Rgb& shot) {
    const double sum = shot.cwiseAbs().sum();
    if (!(area * sum > 0)) return;
    push(region, area, sum, shot / sum, (shot / sum).cwiseAbs());
}

void IterationSources::push(const RayRegion& region, double area, double sum, const Rgb& unit,
                            const Rgb& most) {
    const double w = area * sum;
    total += w;
    max_share = max_share.max(most);
    regions.push_back(region);
    share.push_back(unit);
    strength.push_back(sum);
    m_weights.push_back(w);
}

// A leaf of a higher basis: its strength is the root mean square of its Delta B - beta over its
// domain, sum_c sqrt(sum_k Delta b_kc^2) for an orthonormal basis, and a ray's share can reach
// |share| + sum_k |terms_k| bound_k.
void IterationSources::add_with_terms(const RayRegion& region, double area, const Rgb& shot,
                                      const TermSlot* slots, const PolynomialBasis& functions) {
    Rgb squares = shot.square();
    for (int j = 1; j < functions.size(); ++j) squares += slots[j - 1].unshot.square();
    const double sum = squares.sqrt().sum();
    if (!(area * sum > 0)) return;
    const Rgb unit = shot / sum;
    Rgb most = unit.cwiseAbs();
    for (int j = 1; j < functions.size(); ++j) {
        terms.emplace_back(slots[j - 1].unshot / sum);
        most += terms.back().cwiseAbs() * functions.bound(j);
    }
    push(region, area, sum, unit, most);
}

void IterationSources::finish() {
    if (regions.empty()) {
        alias.reset();
    } else if (alias) {
        alias->assign(m_weights);
    } else {
        alias.emplace(m_weights);
    }
}

void IterationSources::rebuild(const Hierarchy& h, const Rgb& beta) {
    clear(h.leaf_count());
    const std::vector<Patch>& ps = h.patch_set().patches;
    patches = &ps;
    shift = beta;
    leaves = true;
    basis = h.basis();
    term_count = basis_size(basis) - 1;
    if (term_count > 0) terms.reserve(h.leaf_count() * std::size_t(term_count));
    h.for_each_leaf([&](const Element& e) {
        const RayRegion region{
            e.domain.u0, e.domain.v0, e.domain.s, e.id.patch, region_map(ps[e.id.patch]),
            e.id.side};
        if (term_count > 0) {
            add_with_terms(region, e.area, e.unshot - beta, h.terms(e), h.polynomial(e));
        } else {
            add(region, e.area, e.unshot - beta);
        }
    });
    finish();
}

// The backs of one-sided patches and the background's faces, whole, at radiosity 0.
void IterationSources::rebuild(const ZeroSurfaces& zero, const Rgb& shot) {
    const std::vector<Patch>& ps = zero.patches;
    clear(zero.backs.size() + (ps.size() - zero.scene_patches));
    patches = &ps;
    for (const std::uint32_t p : zero.backs) {
        add({0, 0, 1, p, region_map(ps[p]), kBack}, ps[p].area, shot);
    }
    for (std::size_t p = zero.scene_patches; p < ps.size(); ++p) {
        add({0, 0, 1, std::uint32_t(p), region_map(ps[p]), kFront}, ps[p].area, shot);
    }
    finish();
}

void IterationSources::clear(std::size_t most) {
    regions.clear();
    share.clear();
    strength.clear();
    m_weights.clear();
    terms.clear();
    basis = Basis::constant;
    term_count = 0;
    // Room for every leaf at once: grown a leaf at a time, a vector doubles and holds its old
    // block and the new one together while it copies, which raised a large scene's peak.
    regions.reserve(most);
    share.reserve(most);
    strength.reserve(most);
    m_weights.reserve(most);
    total = 0;
    max_share = Rgb::Zero();
    shift = Rgb::Zero();
    leaves = false;
}

struct ShootingBuffers::Impl {
    struct Chunk {
        Quanta shot{}, escaped{}, back_face{};
    };
    // Each ray's deposit, added after the batch by one thread: atomic adds from both threads
    // onto the few hot elements of a small scene made 2 threads 20% slower.
    struct Deposit {
        Quanta quanta{};     // rho * Phi, for an element
        Quanta incident{};   // Phi, for a cluster (docs/design.md §2.7)
        bool lands = false;  // on a front face: the descent finds its element
    };
    // What a line used both ways carries back to its source (docs/design.md §3.13), kept apart
    // so that one-way rays, the default, neither write nor carry it.
    struct BackDeposit {
        Element* receiver = nullptr;  // none: nothing comes back
        Quanta quanta{}, incident{};
    };
    struct TermHit {
        Rgb reflected = Rgb::Zero();  // rho * Phi
        Vec2f y_uv{0, 0};
    };
    // The batch's descents are made together, after its rays are traced, so that rays between
    // the same patches decide their shared links once (refine_links).
    // The stages pass each chunk of rays on in these arrays: generated (starts, rays), traced
    // (hits), and turned into deposits and the queries of their descents.
    struct Batch {
        std::uint64_t first = 0, n = 0;
        std::vector<Chunk> chunks;
        GeneratedRays rays;
        std::vector<BatchHit> hits;
        std::vector<Deposit> deposits;
        std::vector<BackDeposit> backs;  // lines used both ways only
        std::vector<LinkQuery> queries;
        std::vector<Element*> receivers;
        // A higher basis only (docs/design.md §3.14): each landed ray's reflected power and
        // point, and its deposits toward its receiver's coefficients 1 .. K-1 (K - 1 per ray),
        // and toward its source's for a line used both ways.
        std::vector<TermHit> term_hits;
        std::vector<Quanta> term_quanta, back_term_quanta;
        std::vector<std::uint32_t> landed;  // a refined mesh's landed rays, in order
    };
    std::array<Batch, 2> batches;  // the second while the first descends (2 threads or more)
    DescentScratch descent;
    RayStrata strata;
};

ShootingBuffers::ShootingBuffers() : m_impl(std::make_unique<Impl>()) {}
ShootingBuffers::~ShootingBuffers() = default;

namespace {

constexpr std::uint64_t kBatchRays = 1 << 16;
// Batches and chunks of whole packets: a packet's rays follow from the slice's numbering alone.
static_assert(kChunkRays % EmbreeScene::kPacketRays == 0 && kBatchRays % kChunkRays == 0);

// Pilot rays draw from streams of their own, apart from the iteration's rays.
constexpr std::uint64_t kPilotStream = std::uint64_t(1) << 62;
// The zero surfaces' pilot rays (§3.11): the pilot streams of an iteration no solve reaches.
constexpr std::uint32_t kZeroPilotKey = UINT32_MAX;
// The strata's offset of a part whose first ray is F: stream 2^63 + 2^62 + F, beyond the
// rays' (below 2^62) and the Sobol scrambles' (rays/sobol.h).
constexpr std::uint64_t kStrataStream = (std::uint64_t(1) << 63) + (std::uint64_t(1) << 62);

// The side of its patch that ray k hit: the front when the ray meets the front's normal, the
// back when it comes from behind a two-sided patch; none when it escaped or met the back of a
// one-sided patch, which absorbs it.
std::optional<std::uint8_t> hit_side(const PatchSet& ps, const BatchHit& hit,
                                     const GeneratedRays& rays, std::size_t k) {
    if (hit.patch == BatchHit::kNoHit) return std::nullopt;
    const Vec3& n = ps.patches[hit.patch].normal;
    const double facing = n.x() * double(rays.direction[0][k]) +
                          n.y() * double(rays.direction[1][k]) +
                          n.z() * double(rays.direction[2][k]);
    if (facing < 0) return kFront;
    if (ps.two_sided(hit.patch)) return kBack;
    return std::nullopt;
}

// A line from source leaf l that lands in leaf r, used both ways (docs/design.md §3.13): with
// s_l and s_r the leaves' strengths, it carries Phi s_l / (s_l + s_r) forward and
// (S / N) (Delta B_r - beta) / (s_l + s_r) back. With s_r = 0 that is Phi forward, bit for bit,
// and nothing back.
struct BothWays {
    Rgb forward, back;
};
// On a higher basis s_r is the landed leaf's root mean square (IterationSources::add_with_terms)
// and what comes back is its Delta B - beta at the hit, y_uv.
BothWays both_ways(const IterationSources& sources, std::uint32_t leaf, const Rgb& power,
                   double power_scale, const Hierarchy& h, const Element& landed,
                   const Vec2f& y_uv) {
    Rgb back_shot = landed.unshot - sources.shift;
    double s_r = 0;
    if (const TermSlot* t = sources.term_count > 0 ? h.terms(landed) : nullptr) {
        const PolynomialBasis& basis = h.polynomial(landed);
        const auto psi = basis.evaluate(landed.domain.local(y_uv.cast<double>()));
        Rgb squares = back_shot.square();
        for (int j = 1; j < basis.size(); ++j) {
            squares += t[j - 1].unshot.square();
            back_shot += psi[j] * t[j - 1].unshot;
        }
        s_r = squares.sqrt().sum();
    } else {
        s_r = back_shot.cwiseAbs().sum();
    }
    const double s_l = sources.strength[leaf];
    if (!(s_r > 0)) return {power, Rgb::Zero()};
    return {power * (s_l / (s_l + s_r)), power_scale / (s_l + s_r) * back_shot};
}

// Ray k's direction, from its source (an oriented cluster's deposit takes its ratios alone).
Vec3 ray_direction(const GeneratedRays& rays, std::size_t k) {
    return {double(rays.direction[0][k]), double(rays.direction[1][k]),
            double(rays.direction[2][k])};
}

Vec3 hit_point(const GeneratedRays& rays, std::size_t k, float distance) {
    Vec3 y;
    for (int c = 0; c < 3; ++c) {
        y[c] = double(rays.origin[c][k]) + double(distance) * double(rays.direction[c][k]);
    }
    return y;
}

}  // namespace

// `rays` pilot rays from `sources` on the pilot streams of `key`, traced without descent or
// deposit: visit(material, region) for each that lands on a side, with the side's material and
// the source region the ray left.
template <class Visit>
void trace_pilots(const RefinementContext& ctx, const IterationSources& sources, std::uint32_t key,
                  std::uint64_t rays, Visit visit) {
    set_tracing_float_mode();
    GeneratedRays batch;
    batch.resize(rays);
    std::vector<BatchHit> hits(rays);
    // Pseudo-random whatever the shooting's sequence: the pilots estimate a share, not the field.
    generate_rays(*sources.patches, sources.regions, *sources.alias, ctx.seed, key, kPilotStream,
                  rays, batch, 0, RaySequence::random, nullptr);
    ctx.scene.first_hits(batch, 0, rays, hits);
    const PatchSet& ps = ctx.hierarchy.patch_set();
    for (std::uint64_t k = 0; k < rays; ++k) {
        const std::optional<std::uint8_t> side = hit_side(ps, hits[k], batch, k);
        if (side) visit(ps.material(hits[k].patch, *side), batch.region[k]);
    }
}

double reflected_fraction(const RefinementContext& ctx, const IterationSources& sources,
                          std::uint32_t iteration, std::uint64_t rays) {
    if (sources.total <= 0 || rays == 0) return 0;
    double reflected = 0;
    trace_pilots(ctx, sources, iteration, rays, [&](const PatchMaterial& m, std::uint32_t region) {
        reflected += channel_sum(m.reflectance * sources.share[region]);
    });
    return reflected / double(rays);
}

void add_part(IterationOutcome& whole, const IterationOutcome& part) {
    whole.rays += part.rays;
    add(whole.shot_power, part.shot_power);
    add(whole.escaped_power, part.escaped_power);
    add(whole.back_face_power, part.back_face_power);
    whole.counters += part.counters;
}

double zero_surfaces_seen(const RefinementContext& ctx, const ZeroSurfaces& zero,
                          std::uint64_t rays) {
    IterationSources sources;
    sources.rebuild(zero, Rgb::Ones());
    if (sources.total <= 0 || rays == 0) return 1;
    std::uint64_t seen = 0;
    trace_pilots(ctx, sources, kZeroPilotKey, rays,
                 [&](const PatchMaterial& m, std::uint32_t) { seen += (m.reflectance > 0).any(); });
    return double(seen) / double(rays);
}

namespace {

using Batch = ShootingBuffers::Impl::Batch;
using Chunk = ShootingBuffers::Impl::Chunk;

// One iteration's rays in a slice, in batches: each batch generated and traced in chunks on
// every thread (trace, shoot_ray), then descended and deposited in ray order (finish).
class IterationShot {
public:
    IterationShot(const RefinementContext& ctx, const IterationSources& sources,
                  std::uint32_t iteration, std::uint64_t rays, RaySlice slice,
                  const std::function<void(std::uint64_t)>& on_batch, ShootingBuffers& buffers,
                  const RayPart& part, const RayStrata* strata, IterationOutcome& out)
        : m_ctx(ctx),
          m_sources(sources),
          m_iteration(iteration),
          m_slice(slice),
          m_on_batch(on_batch),
          m_buffers(buffers.impl()),
          m_part(part),
          m_out(out),
          m_ps(ctx.hierarchy.patch_set()),
          m_power_scale(sources.total / double(rays)),  // S / N_iter
          m_fixed(ctx.fixed_leaves != nullptr),
          // Lines both ways between the leaves (the zero surfaces' rays go one way: §3.13).
          m_both(m_fixed && ctx.bidirectional == Bidirectional::yes && sources.leaves),
          m_terms(basis_size(ctx.hierarchy.basis()) - 1),
          m_term_quantum(ctx.hierarchy.term_quantum(out.quantum)),
          m_strata(strata) {
        // One thread cannot overlap anything: it reuses one batch's buffers, which stay in
        // cache.
        const auto threads = std::min<std::size_t>(
            tbb::this_task_arena::max_concurrency(),
            tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
        m_overlap = threads > 1;
    }

    void run() {
        size_buffers(std::min(m_slice.end - m_slice.begin, kBatchRays));
        // Tracing reads only the patches, the sources and the Embree scene (and a fixed mesh's
        // leaf lookup, which reads no element's power), never what a descent or a deposit
        // writes, so the next batch is traced while this one descends and deposits: the
        // batch's sequential steps (compaction, sort, deposits) then overlap the next batch's
        // rays on other threads. The batches still descend and deposit in order, so the bits
        // are the same.
        std::array<Batch, 2>& batches = m_buffers.batches;
        trace(batches[0], m_slice.begin);
        for (std::size_t current = 0;;) {
            Batch& b = batches[current];
            const std::uint64_t next = b.first + b.n;
            if (next >= m_slice.end) {
                finish(b);
                break;
            }
            if (!m_overlap) {
                finish(b);
                trace(b, next);
                continue;
            }
            Batch& following = batches[current ^ 1];
            tbb::task_group tracing;
            tracing.run([this, &following, next] { trace(following, next); });
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
    }

private:
    void size_buffers(std::uint64_t batch_rays) {
        for (Batch& b : m_buffers.batches) {
            b.rays.resize(batch_rays);
            resize_populated(b.hits, batch_rays);
            resize_populated(b.deposits, batch_rays);
            resize_populated(b.backs, m_both ? batch_rays : 0);
            resize_populated(b.queries, m_fixed ? 0 : batch_rays);  // no descents: no queries
            resize_populated(b.receivers, batch_rays);
            const std::uint64_t terms = std::uint64_t(m_terms);
            resize_populated(b.term_hits, m_terms > 0 && !m_fixed ? batch_rays : 0);
            resize_populated(b.term_quanta, terms * batch_rays);
            resize_populated(b.back_term_quanta, m_both ? terms * batch_rays : 0);
            resize_populated(b.landed, m_terms > 0 && !m_fixed ? batch_rays : 0);
            if (!m_overlap) break;
        }
        if (!m_fixed) m_buffers.descent.reserve(batch_rays);
    }

    // The batch of rays from `first`, generated and traced in chunks on every thread.
    void trace(Batch& b, std::uint64_t first) {
        b.first = first;
        b.n = std::min(kBatchRays, m_slice.end - first);
        b.chunks.assign((b.n + kChunkRays - 1) / kChunkRays, {});
        tbb::parallel_for(std::uint64_t(0), b.chunks.size(), [&](std::uint64_t c) {
            set_tracing_float_mode();
            trace_chunk(b, c * kChunkRays, std::min(b.n, (c + 1) * kChunkRays), b.chunks[c]);
        });
    }

    // One chunk of rays through the stages: generated, traced, then each ray's power and fate
    // (steps 3 and 4).
    void trace_chunk(Batch& b, std::uint64_t begin, std::uint64_t end, Chunk& chunk) const {
        generate_rays(*m_sources.patches, m_sources.regions, *m_sources.alias, m_ctx.seed,
                      m_iteration, m_part.first_key + b.first + begin, end - begin, b.rays, begin,
                      m_ctx.sequence, m_strata);
        m_ctx.scene.first_hits(b.rays, begin, end, b.hits);
        for (std::uint64_t k = begin; k < end; ++k) shoot_ray(b, k, chunk);
    }

    // Ray k's power, and for a ray that lands, its deposit and the query of its descent (on a
    // fixed mesh, its receiver) and what it carries back.
    void shoot_ray(Batch& b, std::uint64_t k, Chunk& chunk) const {
        const std::uint32_t leaf = b.rays.region[k];
        Rgb power = source_power(b, k, leaf);
        const double dither = b.rays.dither[k];
        // Written field by field, once: a deposit built whole and copied in was read back
        // from the stack before its halves were stored there, a stall on every ray.
        ShootingBuffers::Impl::Deposit& deposit = b.deposits[k];
        const BatchHit& hit = b.hits[k];
        const std::optional<std::uint8_t> side = hit_side(m_ps, hit, b.rays, k);
        const PowerQuantum& quantum = m_out.quantum;
        if (!side) {
            const Quanta quanta = quantum.count(power, dither);
            add(chunk.shot, quanta);
            deposit.lands = false;  // all that is read of it
            add(hit.patch == BatchHit::kNoHit ? chunk.escaped : chunk.back_face, quanta);
            return;
        }
        const Patch& rcv = m_ps.patches[hit.patch];
        const Vec3 y = hit_point(b.rays, k, hit.distance);
        const RayRegion& source = m_sources.regions[leaf];
        const LinkQuery query{SideRef(hit.patch, *side),
                              SideRef(source.patch, std::uint8_t(source.side)),
                              rcv.param_of_hit(hit.second_triangle != 0, hit.b1, hit.b2, y),
                              Vec2f(b.rays.u[k], b.rays.v[k])};
        if (m_fixed) {
            b.receivers[k] = &fixed_receiver(m_ctx, query);
        } else {
            b.queries[k] = query;
        }
        if (m_both) power = shoot_back(b, k, chunk, query, source, leaf, power, dither);
        const Quanta quanta = quantum.count(power, dither);
        add(chunk.shot, quanta);
        // docs/design.md §3: received += rho * Phi (over A when pushed).
        const Rgb& rho = m_ps.material(hit.patch, *side).reflectance;
        deposit.quanta = quantum.count(rho * power, dither);
        deposit.incident = quanta;
        deposit.lands = true;
        if (m_terms == 0) return;
        if (m_fixed) {
            project(*b.receivers[k], query.y_uv, rho * power, dither, &b.term_quanta[k * m_terms]);
        } else {
            b.term_hits[k] = {rho * power, query.y_uv};
        }
    }

    // Ray k's power from its source leaf: (S / N) share, or on a higher basis (S / N) times the
    // leaf's Delta B - beta at the ray's origin over its strength.
    Rgb source_power(const Batch& b, std::uint64_t k, std::uint32_t leaf) const {
        Rgb unit = m_sources.share[leaf];
        if (m_sources.term_count > 0) {
            const RayRegion& r = m_sources.regions[leaf];
            const PolynomialBasis& basis =
                polynomial_basis(m_sources.basis, r.map != RegionMap::triangle);
            const auto psi = basis.evaluate((double(b.rays.u[k]) - r.u0) / r.s,
                                            (double(b.rays.v[k]) - r.v0) / r.s);
            const Rgb* t = &m_sources.terms[std::size_t(leaf) * std::size_t(m_sources.term_count)];
            for (int j = 1; j < basis.size(); ++j) unit += psi[j] * t[j - 1];
        }
        return m_power_scale * unit;
    }

    // The deposit of `reflected` at uv toward the receiver's coefficients 1 .. K-1, in the term
    // quantum: reflected psi_k(a, b) Jbar / J(uv), the receiver's mean Jacobian over the one at
    // the point (1 on triangles and parallelograms), so that each is an unbiased estimate of
    // A times the coefficient (docs/design.md §3.14). Nothing for a cluster, which is constant.
    void project(const Element& receiver, const Vec2f& uv, const Rgb& reflected, double dither,
                 Quanta* out) const {
        const Hierarchy& h = m_ctx.hierarchy;
        if (!h.terms(receiver)) return;
        const PolynomialBasis& basis = h.polynomial(receiver);
        const Vec2 at = uv.cast<double>();
        const auto psi = basis.evaluate(receiver.domain.local(at));
        const Patch& p = m_ps.patches[receiver.id.patch];
        double ratio = 1;
        if (p.is_quad() && !p.is_parallelogram()) {
            const double s = receiver.domain.s;
            ratio = receiver.area / (s * s * p.jacobian(at));
        }
        for (int j = 1; j < basis.size(); ++j) {
            out[j - 1] = m_term_quantum.count(reflected * (psi[j] * ratio), dither);
        }
    }

    // A line used both ways: what ray k carries back from the leaf it landed on to its source
    // leaf, kept in its back deposit; returns the power it carries forward.
    Rgb shoot_back(Batch& b, std::uint64_t k, Chunk& chunk, const LinkQuery& query,
                   const RayRegion& source, std::uint32_t leaf, const Rgb& power,
                   double dither) const {
        ShootingBuffers::Impl::BackDeposit& back_deposit = b.backs[k];
        back_deposit.receiver = nullptr;
        // The leaf at the hit is a source of this iteration (its receiver may be the cluster
        // above it); what it shoots back lands where a ray to x would.
        const Element& landed = m_ctx.clusters ? m_ctx.fixed_leaves->locate(
                                                     query.receiver.patch(), query.receiver.side(),
                                                     query.y_uv.cast<double>())
                                               : *b.receivers[k];
        const BothWays split =
            both_ways(m_sources, leaf, power, m_power_scale, m_ctx.hierarchy, landed, query.y_uv);
        if ((split.back != 0).any()) {
            const LinkQuery back{query.source, query.receiver, query.x_uv, query.y_uv};
            Element& to = fixed_receiver(m_ctx, back);
            const Quanta back_quanta = m_out.quantum.count(split.back, dither);
            add(chunk.shot, back_quanta);
            const Rgb& rho_x = m_ps.material(source.patch, source.side).reflectance;
            back_deposit.quanta = m_out.quantum.count(rho_x * split.back, dither);
            back_deposit.incident = back_quanta;
            back_deposit.receiver = &to;
            if (m_terms > 0) {
                project(to, query.x_uv, rho_x * split.back, dither,
                        &b.back_term_quanta[k * m_terms]);
            }
        }
        return split.forward;
    }

    // The batch's descents, then its deposits in ray order, whichever thread traced the ray:
    // the same bits for any thread count.
    void finish(Batch& b) {
        std::size_t landed = 0;
        if (!m_fixed) {
            for (std::uint64_t k = 0; k < b.n; ++k) {
                if (!b.deposits[k].lands) continue;
                if (m_terms > 0) b.landed[landed] = std::uint32_t(k);
                b.queries[landed++] = b.queries[k];
            }
            RefinementCounters counters;
            refine_links(m_ctx, {b.queries.data(), landed}, {b.receivers.data(), landed}, counters,
                         m_buffers.descent);
            m_out.counters += counters;
            if (m_terms > 0) project_landed(b, landed);
        }
        for (std::uint64_t k = 0, q = 0; k < b.n; ++k) {
            if (!b.deposits[k].lands) continue;
            const ShootingBuffers::Impl::Deposit& d = b.deposits[k];
            Element& receiver = *b.receivers[m_fixed ? k : q++];
            const double dither = b.rays.dither[k];
            if (is_cluster(receiver)) {
                m_ctx.clusters->receive(receiver, ray_direction(b.rays, k), d.incident, dither);
            } else {
                add(receiver.received, d.quanta);
                add_terms(receiver, b.term_quanta, k);
            }
            if (!m_both) continue;
            const ShootingBuffers::Impl::BackDeposit& back = b.backs[k];
            if (Element* to = back.receiver) {
                if (is_cluster(*to)) {
                    m_ctx.clusters->receive(*to, -ray_direction(b.rays, k), back.incident, dither);
                } else {
                    add(to->received, back.quanta);
                    add_terms(*to, b.back_term_quanta, k);
                }
            }
        }
        for (const auto& c : b.chunks) {
            add(m_out.shot_power, c.shot);
            add(m_out.escaped_power, c.escaped);
            add(m_out.back_face_power, c.back_face);
        }
        m_out.rays += b.n;
        if (m_on_batch) m_on_batch(m_out.rays);
    }

    // A refined mesh's landed rays' deposits toward their receivers' coefficients beyond the
    // mean, once the descents have found the receivers: on every thread, as the tracing.
    void project_landed(Batch& b, std::size_t landed) const {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, landed, kChunkRays),
                          [&](const tbb::blocked_range<std::size_t>& range) {
                              for (std::size_t q = range.begin(); q != range.end(); ++q) {
                                  const std::uint32_t k = b.landed[q];
                                  const ShootingBuffers::Impl::TermHit& t = b.term_hits[k];
                                  project(*b.receivers[q], t.y_uv, t.reflected, b.rays.dither[k],
                                          &b.term_quanta[std::size_t(k) * m_terms]);
                              }
                          });
    }

    // Ray k's deposits toward e's coefficients beyond the mean, from `quanta` (K - 1 per ray).
    void add_terms(Element& e, const std::vector<Quanta>& quanta, std::uint64_t k) const {
        if (m_terms == 0) return;
        TermSlot* t = m_ctx.hierarchy.terms(e);
        if (!t) return;
        for (int j = 0; j < m_terms; ++j) add(t[j].received, quanta[k * m_terms + j]);
    }

    const RefinementContext& m_ctx;
    const IterationSources& m_sources;
    std::uint32_t m_iteration;
    RaySlice m_slice;
    const std::function<void(std::uint64_t)>& m_on_batch;
    ShootingBuffers::Impl& m_buffers;
    const RayPart& m_part;
    IterationOutcome& m_out;
    const PatchSet& m_ps;
    double m_power_scale;
    bool m_fixed;  // a fixed mesh: deposits on its leaves, no descents
    bool m_both;
    int m_terms;                  // K - 1: a higher basis's coefficients beyond the mean
    PowerQuantum m_term_quantum;  // what deposits toward them are counted in
    bool m_overlap = false;       // the next batch is traced while this one finishes
    const RayStrata* m_strata;    // a Sobol shot's rays dealt to their sources; null otherwise
};

// A Sobol shot's rays dealt to their sources, into `strata`; on a fixed mesh each source leaf's
// sequence then goes on from where its rays stopped. Every rank deals all the iteration's rays,
// its slice empty or not, so that the sequences' cursors stay the same on every rank.
const RayStrata* deal_rays(const RefinementContext& ctx, const IterationSources& sources,
                           std::uint32_t iteration, std::uint64_t rays, const RayPart& part,
                           RayStrata& strata) {
    if (ctx.sequence != RaySequence::sobol) return nullptr;  // pseudo-random rays pick theirs
    strata.assign(sources.weights(), rays,
                  Rng(ctx.seed, iteration, kStrataStream + part.first_key).uniform(),
                  part.first_key);
    if (ctx.sequence_cursors && sources.leaves) {
        ctx.sequence_cursors->advance(sources.regions, strata);
    }
    return &strata;
}

}  // namespace

IterationOutcome shoot_iteration(const RefinementContext& ctx, const IterationSources& sources,
                                 std::uint32_t iteration, std::uint64_t rays, RaySlice slice,
                                 const std::function<void(std::uint64_t)>& on_batch,
                                 ShootingBuffers* buffers, const RayPart& part) {
    IterationOutcome out;
    if (part.quantum) out.quantum = *part.quantum;
    if (rays == 0 || sources.total <= 0) return out;
    slice.end = std::min(slice.end, rays);
    if (!part.quantum) {
        const double power_scale = sources.total / double(rays);  // S / N_iter
        out.quantum = PowerQuantum::for_iteration(power_scale * sources.max_share, rays);
    }
    std::optional<ShootingBuffers> own;
    if (!buffers) buffers = &own.emplace();
    const RayStrata* strata =
        deal_rays(ctx, sources, iteration, rays, part, buffers->impl().strata);
    if (slice.begin >= slice.end) return out;
    IterationShot(ctx, sources, iteration, rays, slice, on_batch, *buffers, part, strata, out)
        .run();
    return out;
}

}  // namespace hmcr
