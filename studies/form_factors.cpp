#include "studies/form_factors.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "radiosity/kernel.h"
#include "radiosity/rng.h"
#include "radiosity/sampling.h"

namespace hmcr {
namespace {

constexpr std::uint64_t kBlock = 4096;  // rays per parallel task (fixed: results are too)

struct RayOutcome {
    std::uint32_t target = LocalLines::kNoPatch;
    double log_kernel = 0;  // log2(A_T F(x, y)), valid when target is a patch
};

// Ray k of patch i: an area-uniform origin, a cosine direction, its first front-face hit.
RayOutcome trace_ray(const PatchSet& set, const EmbreeScene& scene, std::uint64_t seed,
                     std::uint32_t i, std::uint64_t k) {
    const Patch& p = set.patches[i];
    Rng rng(seed, i, k);
    const double xi1 = rng.uniform(), xi2 = rng.uniform();
    const Vec3 x = p.point(sample_element(p, Domain::root(), xi1, xi2));
    const double xi3 = rng.uniform(), xi4 = rng.uniform();
    const Vec3 d = sample_cosine_hemisphere(p.normal, xi3, xi4);
    const auto hit = scene.first_hit(x, d);
    if (!hit) return {};
    const Patch& q = set.patches[hit->patch];
    if (q.normal.dot(d) >= 0) return {};  // back face
    // The hit point on q's plane in double precision (Embree's distance is a float): keeps the
    // kernel accurate near edges and the estimates scale-equivariant.
    const double t = q.normal.dot(q.corner[0] - x) / q.normal.dot(d);
    const double f = point_kernel(x, p.normal, x + t * d, q.normal);
    if (!(f > 0)) return {};
    return {hit->patch, std::log2(set.total_area * f)};
}

}  // namespace

std::vector<std::uint64_t> local_line_counts(const PatchSet& patches,
                                             const LocalLineOptions& options) {
    const double per_batch = double(options.lines) / double(options.batches);
    std::vector<std::uint64_t> n(patches.patches.size());
    for (std::size_t i = 0; i < n.size(); ++i) {
        const double share = per_batch * patches.patches[i].area / patches.total_area;
        n[i] = options.batches * std::max<std::uint64_t>(1, std::llround(share));
    }
    return n;
}

LocalLines trace_local_lines(const PatchSet& patches, const EmbreeScene& scene,
                             const LocalLineOptions& options) {
    LocalLines out;
    out.batches = std::max<std::uint32_t>(1, options.batches);
    const auto counts = local_line_counts(patches, {options.lines, out.batches, options.seed});
    out.first.assign(counts.size() + 1, 0);
    for (std::size_t i = 0; i < counts.size(); ++i) out.first[i + 1] = out.first[i] + counts[i];
    out.target.assign(out.first.back(), LocalLines::kNoPatch);

    // Per block and batch partial sums, reduced in block order afterwards (deterministic).
    const std::uint64_t blocks = (out.lines() + kBlock - 1) / kBlock, b = out.batches;
    std::vector<double> sums(blocks * b, 0.0);
    std::vector<std::uint64_t> hits(blocks * b, 0);
    tbb::parallel_for(std::uint64_t(0), blocks, [&](std::uint64_t block) {
        set_tracing_float_mode();
        const std::uint64_t g0 = block * kBlock, g1 = std::min(out.lines(), g0 + kBlock);
        auto i = std::uint32_t(std::upper_bound(out.first.begin(), out.first.end(), g0) -
                               out.first.begin() - 1);
        for (std::uint64_t g = g0; g < g1; ++g) {
            while (g >= out.first[i + 1]) ++i;
            const std::uint64_t k = g - out.first[i];
            const RayOutcome r = trace_ray(patches, scene, options.seed, i, k);
            out.target[g] = r.target;
            if (r.target == LocalLines::kNoPatch) continue;
            sums[block * b + k % b] += r.log_kernel;
            ++hits[block * b + k % b];
        }
    });
    out.log_kernel_sum.assign(b, 0.0);
    out.log_kernel_count.assign(b, 0);
    for (std::uint64_t block = 0; block < blocks; ++block) {
        for (std::uint64_t j = 0; j < b; ++j) {
            out.log_kernel_sum[j] += sums[block * b + j];
            out.log_kernel_count[j] += hits[block * b + j];
        }
    }
    return out;
}

double SparseFormFactors::operator()(std::size_t i, std::size_t j) const {
    const auto& row = rows[i];
    const auto it =
        std::lower_bound(row.begin(), row.end(), j,
                         [](const FormFactorEntry& e, std::size_t p) { return e.patch < p; });
    if (it == row.end() || it->patch != j) return 0.0;
    return double(it->count) / double(rays[i]);
}

std::vector<FormFactorEntry> form_factor_row(std::span<const std::uint32_t> targets,
                                             std::uint32_t batches, std::uint32_t batch) {
    std::vector<std::uint32_t> hit;
    hit.reserve(targets.size() / batches + 1);
    for (std::size_t k = batch; k < targets.size(); k += batches) {
        if (targets[k] != LocalLines::kNoPatch) hit.push_back(targets[k]);
    }
    std::sort(hit.begin(), hit.end());
    std::vector<FormFactorEntry> row;
    for (std::size_t k = 0; k < hit.size(); ++k) {
        if (row.empty() || row.back().patch != hit[k]) row.push_back({hit[k], 0});
        ++row.back().count;
    }
    return row;
}

SparseFormFactors form_factors(const LocalLines& lines) {
    SparseFormFactors f;
    const std::size_t n = lines.first.size() - 1;
    f.rows.resize(n);
    f.rays.resize(n);
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
        f.rows[i] = form_factor_row(lines.targets(i));
        f.rays[i] = lines.rays(i);
    });
    return f;
}

}  // namespace hmcr
