// SPDX-License-Identifier: Apache-2.0
#include "radiosity/solver.h"

#include <fmt/format.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>

#include "common/error.h"
#include "common/interrupt.h"
#include "common/stopwatch.h"
#include "radiosity/clusters.h"
#include "radiosity/control_variate.h"
#include "radiosity/link_cache.h"
#include "radiosity/rank_merge.h"
#include "radiosity/ray_schedule.h"
#include "radiosity/sequence_cursors.h"
#include "radiosity/shooting.h"
#include "radiosity/solve_passes.h"
#include "radiosity/view_importance.h"
#include "rays/embree_scene.h"

namespace hmcr {
namespace {

using Clock = std::chrono::steady_clock;
// Pilot rays per iteration for the ray schedule's decay estimate: a standard error of about
// 0.005 on the reflected fraction, for well under a millisecond.
constexpr std::uint64_t kPilotRays = 4096;

// The link cache of the line-based oracles; none for power.
std::unique_ptr<LinkCache> make_link_cache(const Oracle& oracle, const SolverOptions& o) {
    if (!oracle.uses_lines() || o.cache_mb <= 0) return nullptr;
    return std::make_unique<LinkCache>(std::size_t(o.cache_mb * (1 << 20)));
}

// `shifted`: the iteration shot Delta B - beta (§3.11); its signed powers stay out of the power
// balance, which keeps the iterations that shot the unshot power itself (the first always).
void add_iteration(SolveStats& st, const IterationOutcome& out, bool shifted) {
    st.rays += out.rays;
    st.oracle_calls += out.counters.oracle_calls;
    st.oracle_evaluations += out.counters.oracle_evaluations;
    st.cache_hits += out.counters.cache_hits;
    st.lines_cast += out.counters.lines_cast;
    st.oracle_seconds += 1e-9 * double(out.counters.oracle_nanoseconds);
    if (shifted) return;
    st.shot_power += out.quantum.power(out.shot_power);
    st.escaped_power += out.quantum.power(out.escaped_power);
    st.back_face_power += out.quantum.power(out.back_face_power);
}

// The quantum of an iteration shot in two parts: bounds every ray of both (§9.3).
PowerQuantum common_quantum(const IterationSources& a, std::uint64_t a_rays,
                            const IterationSources& b, std::uint64_t b_rays) {
    Rgb bound = Rgb::Zero();
    if (a_rays > 0) bound = bound.max(a.total / double(a_rays) * a.max_share);
    if (b_rays > 0) bound = bound.max(b.total / double(b_rays) * b.max_share);
    return PowerQuantum::for_iteration(bound, a_rays + b_rays);
}

// This rank's slice of an iteration's `rays`: all from `sources`, or with the control variate
// the last `zero_rays` of them from the zero surfaces' sources, in one quantum (§3.11).
// `on_batch` gets the rays this rank has shot so far.
IterationOutcome shoot_on_rank(const RefinementContext& ctx, const IterationSources& sources,
                               const IterationSources* zero, std::uint32_t it, std::uint64_t rays,
                               std::uint64_t zero_rays, const Ranks& ranks,
                               const std::function<void(std::uint64_t)>& on_batch,
                               ShootingBuffers& buffers) {
    const auto slice = [&](std::uint64_t n) { return slice_of(n, ranks.rank(), ranks.size()); };
    if (!zero) return shoot_iteration(ctx, sources, it, rays, slice(rays), on_batch, &buffers);
    const std::uint64_t side_rays = rays - zero_rays;
    const RayPart sides{0, common_quantum(sources, side_rays, *zero, zero_rays)};
    IterationOutcome out =
        shoot_iteration(ctx, sources, it, side_rays, slice(side_rays), on_batch, &buffers, sides);
    const std::uint64_t done = out.rays;
    add_part(out, shoot_iteration(ctx, *zero, it, zero_rays, slice(zero_rays),
                                  [&](std::uint64_t n) {
                                      if (on_batch) on_batch(done + n);
                                  },
                                  &buffers, {side_rays, sides.quantum}));
    return out;
}

// Push-pull through the clusters, if any, then the sides' trees (docs/design.md §2.7, §3.6).
void push_pull(Hierarchy& h, ClusterTree* clusters, const PowerQuantum& quantum) {
    if (!clusters) return h.push_pull(quantum);
    std::vector<Rgb> from_above;
    clusters->push(quantum, from_above);
    h.push_pull(quantum, from_above);
    clusters->pull();
}

}  // namespace

const std::vector<std::int32_t>& Solution::cluster_of_side() const {
    static const std::vector<std::int32_t> none;
    return clusters ? clusters->leaf_of_side() : none;
}

double SolveStats::back_face_fraction() const {
    const double shot = channel_sum(shot_power);
    return shot > 0 ? channel_sum(back_face_power) / shot : 0;
}

std::span<const IterationRecord> SolveStats::value_iterations() const {
    const auto first = std::find_if(iterations.begin(), iterations.end(),
                                    [](const IterationRecord& it) { return it.frozen; });
    const std::span<const IterationRecord> all(iterations);
    return first == iterations.end() ? all : all.subspan(std::size_t(first - iterations.begin()));
}

void SolveStats::join_refining_pass(const SolveStats& refining) {
#define HMCR_JOIN_both(name) name += refining.name;
#define HMCR_JOIN_refining(name) name = refining.name;
#define HMCR_JOIN_frozen(name)
#define HMCR_JOIN(type, name, zero, join) HMCR_JOIN_##join(name)
    HMCR_SOLVE_STATS(HMCR_JOIN)
#undef HMCR_JOIN
#undef HMCR_JOIN_frozen
#undef HMCR_JOIN_refining
#undef HMCR_JOIN_both
    iterations.insert(iterations.begin(), refining.iterations.begin(), refining.iterations.end());
}

namespace {

// The mesh a solve starts from: a refining solve's roots (or a fixed one: the uniform mesh of
// uniform_max_area, or the roots that nothing may split), or a solution's leaves to solve again,
// frozen, with the clusters its shape had open.
struct StartMesh {
    std::unique_ptr<Hierarchy> hierarchy;
    std::unique_ptr<ClusterTree> clusters;  // a frozen mesh's only
    bool frozen = false;
};

// The element roots of `patches`, after their Embree scene (built here if `scene` is none):
// the BVH build's working memory is let go before the roots take theirs, which lowers the
// peak of a scene of many patches (docs/performance.md).
std::unique_ptr<Hierarchy> roots(PatchSet patches, const SolverOptions& o,
                                 std::shared_ptr<const EmbreeScene>& scene) {
    check_root_count(root_count(patches), element_limit(o));  // before the BVH's memory
    if (!scene) scene = std::make_shared<const EmbreeScene>(patches);
    return std::make_unique<Hierarchy>(std::move(patches),
                                       HierarchyLimits{o.min_area, o.max_depth, element_limit(o)});
}

// A refining solve's mesh (or the fixed one) over `patches`.
StartMesh roots_of(PatchSet patches, const SolverOptions& o,
                   std::shared_ptr<const EmbreeScene>& scene) {
    StartMesh mesh{roots(std::move(patches), o, scene), nullptr, fixed_from_start(o)};
    if (o.uniform_max_area > 0) mesh.hierarchy->subdivide_uniformly(o.uniform_max_area);
    return mesh;
}

// Clusters over `h` of a shape's model, open where its tree was (its ClusterTree::open_flags).
std::unique_ptr<ClusterTree> clusters_opened(Hierarchy& h, std::span<const std::int64_t> open,
                                             Clustering model) {
    auto clusters = std::make_unique<ClusterTree>(h, std::span<const Rgb>{}, model);
    clusters->set_open_flags(open);
    return clusters;
}

// The frozen pass's mesh: the refining pass's own tree, reset, so that one tree and one copy
// of the patches are alive at a time; of its clusters only the open flags outlive it.
StartMesh frozen_in_place(Solution& refined) {
    StartMesh mesh{std::move(refined.hierarchy), nullptr, true};
    mesh.hierarchy->reset_values();
    if (refined.clusters) {
        const std::vector<std::int64_t> open = refined.clusters->open_flags();
        const Clustering model = refined.clusters->model();
        refined.clusters.reset();
        mesh.clusters = clusters_opened(*mesh.hierarchy, open, model);
    }
    return mesh;
}

// A solution's mesh on patches of its own, frozen.
StartMesh frozen_like(PatchSet patches, const SolverOptions& o, const Solution& shape,
                      std::shared_ptr<const EmbreeScene>& scene) {
    StartMesh mesh{roots(std::move(patches), o, scene), nullptr, true};
    mesh.hierarchy->subdivide_like(*shape.hierarchy);
    if (shape.clusters) {
        mesh.clusters =
            clusters_opened(*mesh.hierarchy, shape.clusters->open_flags(), shape.clusters->model());
    }
    return mesh;
}

// The scene's figures every solve reports.
void record_scene(SolveStats& st, const PatchSet& patches) {
    st.emitted_power = patches.emitted_power;
    st.total_area = patches.total_area;
    st.max_emitted_power = patches.max_emitted_power;
    st.patches = patches.patches.size();
    for (std::size_t i = 0; i < st.patches; ++i) st.two_sided_patches += patches.two_sided(i);
}

// The receiver weights of view importance (§3.12), empty where the solve has none: shooting's
// importance, solved first (from the pass's `rays`) where it has none. Importance weighs the
// oracle's decisions, so a fixed mesh has no use for it.
std::span<const Rgb> importance_weights(const SolverOptions& options, std::uint64_t rays,
                                        std::span<const View> views, bool fixed_mesh,
                                        const Hierarchy& h, ShootingSetup& shooting, SolveStats& st,
                                        Progress& progress, const Ranks& ranks) {
    std::shared_ptr<const ViewImportance>& importance = shooting.importance;
    if (fixed_mesh || options.importance == Importance::none) {
        importance.reset();
        return {};
    }
    if (!importance) {
        importance = std::make_shared<const ViewImportance>(
            solve_view_importance(h.patch_set(), *shooting.scene, views, options, rays, ranks));
        progress.note(fmt::format("view importance of {} view(s): {} rays, {:.2f} s", views.size(),
                                  importance->rays, importance->seconds));
    }
    st.importance_rays = importance->rays;
    st.importance_seconds = importance->seconds;
    return importance->receiver_weights;
}

// What a pass reports of its mesh, its link cache and its time once its rays are shot.
void record_end(SolveStats& st, const Hierarchy& h, const ClusterTree* clusters,
                const LinkCache* cache, bool fixed_mesh, Clock::time_point start) {
    st.elements = h.element_count();
    st.faces = h.leaf_count();
    if (clusters) st.cluster_leaves = clusters->cluster_leaves();
    st.hierarchy_bytes = h.bytes();
    if (cache) {
        st.cache_bytes = cache->bytes();
        st.cache_capacity = cache->capacity();
        st.cache_evictions = cache->evictions();
    }
    st.total_seconds = seconds_since(start);
    if (!fixed_mesh) {
        st.refining_rays = st.rays;
        st.refining_seconds = st.total_seconds;
    }
}

// The control variate's zero surfaces (§3.11): it needs every side that may receive light to
// exist from the start (it adds rho beta to each), and every deposit on the leaf at its hit
// point, which a fixed mesh's context gives.
ZeroSurfaces control_variate_surfaces(const RefinementContext& ctx, Hierarchy& h) {
    ZeroSurfaces zero(h.patch_set());
    zero.seen = zero_surfaces_seen(ctx, zero, kPilotRays);
    for (std::size_t p = 0; p < h.patch_count(); ++p) {
        if (h.patch_set().two_sided(p)) h.root(p, kBack);
    }
    return zero;
}

// An iteration's constant beta of the control variate (0: none) and, where it is not 0, its
// `rays` split between the shifted leaves (`shifted`, rebuilt) and the zero surfaces
// (`zero_sources`, rebuilt, the last `zero_rays`).
struct Shift {
    Rgb beta = Rgb::Zero();
    bool on = false;
    std::uint64_t zero_rays = 0;
};
Shift shift_for(const Hierarchy& h, const std::optional<ZeroSurfaces>& zero, std::uint64_t rays,
                IterationSources& shifted, IterationSources& zero_sources) {
    Shift s;
    // A shifted iteration needs a ray for each of its two parts.
    if (!zero || rays < 2) return s;
    s.beta = control_constant(h, *zero);
    s.on = (s.beta != 0).any();
    if (!s.on) return s;
    shifted.rebuild(h, s.beta);
    zero_sources.rebuild(*zero, -s.beta);
    s.zero_rays = zero_surface_rays(rays, shifted.total, zero_sources.total, zero->seen);
    return s;
}

// The leaves once the clusters, if any, have settled.
std::size_t settled_leaves(const Hierarchy& h, ClusterTree* clusters) {
    return clusters ? clusters->settle() : h.leaf_count();
}

// A solve's iterations: each shoots the unshot power from the sources it rebuilds, then pushes
// and pulls, until the unshot power falls below the stop or the rays run out.
struct Shooter {
    const SolverOptions& options;
    std::uint64_t rays;  // the pass's
    const RefinementContext& ctx;
    ClusterTree* clusters;
    bool fixed_mesh;
    const std::optional<ZeroSurfaces>& zero;
    ShootingBuffers& buffers;
    Progress& progress;
    const Ranks& ranks;
    SolveStats& st;
    // An iteration's sources, and with the control variate their shifted and zero parts.
    struct Sources {
        IterationSources all, shifted, zero;
    };

    // The iterations' rays are keyed from `first_iteration` on; returns the unshot power left.
    Rgb run(std::uint32_t first_iteration) {
        Hierarchy& h = ctx.hierarchy;
        const double emitted = channel_sum(st.emitted_power);
        RaySchedule schedule(rays, options.stop * emitted);
        Rgb unshot = h.unshot_power();
        Sources sources;
        // The cap only guards against a scene that never converges; stop ends real solves.
        for (std::uint32_t k = 0; channel_sum(unshot) >= options.stop * emitted && k < 10'000;
             ++k) {
            if (!iteration(first_iteration + k, schedule, unshot, sources)) break;
        }
        return unshot;
    }

    // Iteration `it`; false, having changed nothing, when the schedule has no rays for it.
    bool iteration(std::uint32_t it, RaySchedule& schedule, Rgb& unshot, Sources& sources) {
        Hierarchy& h = ctx.hierarchy;
        const auto t0 = Clock::now();
        IterationRecord rec;
        rec.unshot_before = unshot;
        sources.all.rebuild(h);
        // A fixed mesh's clusters take deposits only: no decision samples the top.
        if (clusters && !fixed_mesh) clusters->begin_iteration(options.link_weight);
        // The schedule and its pilot rays follow the true unshot power, with or without the
        // control variate; the rays shoot it minus beta where beta is not 0.
        const double ratio = reflected_fraction(ctx, sources.all, it, kPilotRays);
        rec.rays = schedule.next(channel_sum(unshot), ratio);
        // Out of rays before the stop criterion: what is unshot stays unshot (an iteration of
        // no rays would push zero received radiosity over it and lose that power).
        if (rec.rays == 0) return false;
        const Shift split = shift_for(h, zero, rec.rays, sources.shifted, sources.zero);
        const Rgb beta = rec.control_constant = split.beta;
        IterationOutcome out = shoot(it, rec.rays, split, sources);
        merge_iteration(h, out, ranks, !fixed_mesh, clusters);
        st.shooting_seconds += seconds_since(t0);
        const auto t1 = Clock::now();
        push_pull(h, clusters, out.quantum);
        if (split.on) add_constant(h, beta);
        st.push_pull_seconds += seconds_since(t1);
        unshot = rec.unshot_after = h.unshot_power();
        if (!unshot.isFinite().all()) throw std::runtime_error("the unshot power is not finite");
        rec.leaves_after = settled_leaves(h, clusters);
        rec.seconds = seconds_since(t0);
        schedule.record(rec.rays);
        add_iteration(st, out, split.on);
        st.iterations.push_back(rec);
        return true;
    }

    // Iteration `it`'s rays, on every rank, with progress and interruption per batch.
    IterationOutcome shoot(std::uint32_t it, std::uint64_t it_rays, const Shift& split,
                           const Sources& sources) {
        const std::uint64_t done_before = st.rays;
        IterationOutcome out;
        together(ranks, [&] {
            out = shoot_on_rank(
                ctx, split.on ? sources.shifted : sources.all, split.on ? &sources.zero : nullptr,
                it, it_rays, split.zero_rays, ranks,
                [&](std::uint64_t n) {
                    const double done = double(done_before) + double(n) * ranks.size();
                    progress.advance(std::min(1.0, done / double(rays)));
                    throw_if_interrupted();
                },
                buffers);
        });
        return out;
    }
};

// make_mesh() builds the mesh once the threads are limited, and the
// scene before its roots when shooting.scene is none; the solve shoots in shooting.scene
// (building it, as part of its setup, if make_mesh did not) through shooting.buffers (made
// here if none), with shooting.importance where a refining solve weighs by it (solved here if
// none).
// The iterations' rays are keyed from `first_iteration` on: a frozen pass starts after its
// refining pass's, so that its rays are not theirs again. Runs in the calling thread's task
// arena, which solve_with() sizes to the solve's threads.
Solution solve_in_arena(const SolverOptions& options, const Pass& pass, const SolveInputs& inputs,
                        const std::function<StartMesh()>& make_mesh, ShootingSetup& shooting,
                        Progress& progress, const Ranks& ranks, std::uint32_t first_iteration,
                        int threads) {
    const auto start = Clock::now();

    Solution sol;
    sol.options = options;
    SolveStats& st = sol.stats;
    const Oracle& oracle = *options.oracle;
    st.epsilon = pass.epsilon;
    st.threads = threads;
    st.ranks = ranks.size();

    StartMesh mesh = make_mesh();
    sol.hierarchy = std::move(mesh.hierarchy);
    Hierarchy& h = *sol.hierarchy;
    h.set_basis(options.basis);
    const PatchSet& patches = h.patch_set();
    if (patches.max_emitted_power <= 0) throw InputError("the scene emits no light");
    record_scene(st, patches);
    if (!shooting.scene) shooting.scene = std::make_shared<const EmbreeScene>(patches);
    const EmbreeScene& scene = *shooting.scene;
    const bool fixed_mesh = mesh.frozen;
    const std::unique_ptr<LinkCache> cache =
        fixed_mesh ? nullptr : make_link_cache(oracle, options);
    const std::span<const Rgb> receiver_weights = importance_weights(
        options, pass.rays, inputs.views, fixed_mesh, h, shooting, st, progress, ranks);
    // A fixed mesh has clusters only where its shape has cluster leaves (§2.7).
    std::unique_ptr<ClusterTree>& clusters = sol.clusters;
    if (mesh.clusters) {
        clusters = std::move(mesh.clusters);
    } else if (!fixed_mesh && options.clustering != Clustering::none) {
        clusters = std::make_unique<ClusterTree>(h, receiver_weights, options.clustering);
    }
    settled_leaves(h, clusters.get());
    // A fixed mesh's leaves by parameter point, where its rays deposit.
    const std::unique_ptr<const LeafIndex> leaf_index =
        fixed_mesh ? std::make_unique<const LeafIndex>(h) : nullptr;
    // A fixed mesh's leaves keep their Sobol sequences through the pass, scrambled by a key
    // above every iteration's.
    std::optional<SequenceCursors> cursors;
    if (fixed_mesh && options.sequence == RaySequence::sobol) {
        cursors.emplace(*leaf_index, (std::uint64_t(1) << 32) + first_iteration);
    }
    const RefinementContext ctx{
        .hierarchy = h,
        .oracle = oracle,
        .scene = scene,
        .threshold = st.epsilon * h.patch_set().max_emitted_power,
        .lines = options.lines,
        .seed = options.seed,
        .cache = cache.get(),
        .fixed_leaves = leaf_index.get(),
        .link_weight = options.link_weight,
        .sequence = options.sequence,
        .sequence_cursors = cursors ? &*cursors : nullptr,
        .bidirectional = fixed_mesh ? options.bidirectional : Bidirectional::no,
        .clusters = clusters.get(),
        .receiver_weights = receiver_weights};
    st.setup_seconds = seconds_since(start);

    const std::optional<ZeroSurfaces> zero =
        fixed_mesh && options.control_variate == ControlVariate::constant
            ? std::optional<ZeroSurfaces>(control_variate_surfaces(ctx, h))
            : std::nullopt;
    if (!shooting.buffers) shooting.buffers = std::make_shared<ShootingBuffers>();
    Shooter shooter{options, pass.rays,         ctx,      clusters.get(), fixed_mesh,
                    zero,    *shooting.buffers, progress, ranks,          st};
    const Rgb unshot = shooter.run(first_iteration);
    st.unshot_power = unshot;
    progress.advance(1.0);
    st.leaves = settled_leaves(h, clusters.get());
    record_end(st, h, clusters.get(), cache.get(), fixed_mesh, start);
    return sol;
}

// A solve in a task arena of its own threads: the caller's other work, and TBB's process-wide
// settings, are left as they were.
Solution solve_with(const SolverOptions& options, const Pass& pass, const SolveInputs& inputs,
                    const std::function<StartMesh()>& make_mesh, ShootingSetup& shooting,
                    Progress& progress, const Ranks& ranks, std::uint32_t first_iteration = 0) {
    const int threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
    tbb::task_arena arena(threads);
    Solution sol;
    arena.execute([&] {
        sol = solve_in_arena(options, pass, inputs, make_mesh, shooting, progress, ranks,
                             first_iteration, threads);
    });
    return sol;
}

// The threshold the options ask for: theirs, or the oracle's default where they give none.
double resolved_epsilon(const SolverOptions& o) {
    return std::isnan(o.epsilon) ? o.oracle->default_epsilon() : o.epsilon;
}

// One pass's fractions as a part [start, start + share] of the whole solve's.
class PartProgress final : public Progress {
public:
    PartProgress(Progress& outer, double start, double share)
        : m_outer(outer), m_start(start), m_share(share) {}
    void stage(std::string_view label) override { m_outer.stage(label); }
    void advance(double fraction) override { m_outer.advance(m_start + m_share * fraction); }
    void note(std::string_view line) override { m_outer.note(line); }

private:
    Progress& m_outer;
    double m_start, m_share;
};

}  // namespace

Passes passes_of(const SolverOptions& options) {
    const Pass whole = whole_solve(options);
    // Refine-then-freeze applies to a refined mesh of at least two rays; a fixed mesh (a
    // reference's uniform one, or unsplittable patches) has nothing to refine, so all its rays
    // solve it.
    if (!(options.refine_share < 1 && !fixed_from_start(options) && options.rays >= 2)) {
        return {whole, {whole.epsilon, 0}};
    }
    // The refining pass's share, at least one ray, leaving one for the frozen pass.
    const auto n = std::uint64_t(std::llround(options.refine_share * double(options.rays)));
    const std::uint64_t refining = std::clamp<std::uint64_t>(n, 1, options.rays - 1);
    return {{whole.epsilon, refining}, {whole.epsilon, options.rays - refining}};
}

Pass whole_solve(const SolverOptions& options) { return {resolved_epsilon(options), options.rays}; }

Solution refine_pass(PatchSet patches, const SolverOptions& options, const Pass& pass,
                     const SolveInputs& inputs, ShootingSetup& shooting, Progress& progress,
                     const Ranks& ranks) {
    return solve_with(
        options, pass, inputs,
        [&] { return roots_of(std::move(patches), options, shooting.scene); }, shooting, progress,
        ranks);
}

Solution freeze_pass(Solution refined, const Pass& pass, ShootingSetup shooting, Progress& progress,
                     const Ranks& ranks) {
    if (pass.rays == 0) return refined;
    Solution sol = solve_with(
        refined.options, pass, {}, [&] { return frozen_in_place(refined); }, shooting, progress,
        ranks, std::uint32_t(refined.stats.iterations.size()));
    for (IterationRecord& it : sol.stats.iterations) it.frozen = true;
    sol.stats.join_refining_pass(refined.stats);
    return sol;
}

Solution solve(const PatchMesh& mesh, const SolverOptions& options, const SolveInputs& inputs,
               Progress& progress, const Ranks& ranks) {
    return solve(build_patch_set(mesh), options, inputs, progress, ranks);
}

Solution solve(PatchSet patches, const SolverOptions& options, const SolveInputs& inputs,
               Progress& progress, const Ranks& ranks) {
    const Passes passes = passes_of(options);
    ShootingSetup shooting;
    if (passes.frozen.rays == 0) {
        return refine_pass(std::move(patches), options, passes.refining, inputs, shooting, progress,
                           ranks);
    }
    const double share = double(passes.refining.rays) / double(options.rays);
    PartProgress first(progress, 0, share), second(progress, share, 1 - share);
    Solution refined =
        refine_pass(std::move(patches), options, passes.refining, inputs, shooting, first, ranks);
    return freeze_pass(std::move(refined), passes.frozen, std::move(shooting), second, ranks);
}

Solution solve_on_mesh(const PatchMesh& mesh, const SolverOptions& options, const Solution& shape,
                       Progress& progress) {
    ShootingSetup shooting;
    return solve_with(
        options, whole_solve(options), {},
        [&] { return frozen_like(build_patch_set(mesh), options, shape, shooting.scene); },
        shooting, progress, Ranks::single());
}

}  // namespace hmcr
