// SPDX-License-Identifier: Apache-2.0
#include "radiosity/view_importance.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "common/error.h"
#include "common/interrupt.h"
#include "common/stopwatch.h"
#include "radiosity/solver.h"
#include "rays/camera.h"
#include "rays/rng.h"

namespace hmcr {
namespace {

// The pixels traced at once: the sides they meet are kept until the batch is summed, 4 bytes
// each (4 MiB), whatever the views' size.
constexpr std::int64_t kBatchPixels = std::int64_t(1) << 20;

// Keys the importance solve's streams apart from the radiance solve of the same seed.
constexpr std::uint64_t kImportanceKey = 0x696d706f7274616eULL;  // "importan"

// The side a ray along `direction` meets on patch p: the front when it arrives against the
// normal; the back of a two-sided patch; none (-1) for a one-sided patch's back.
int side_met(const PatchSet& ps, std::size_t p, const Vec3& direction) {
    if (direction.dot(ps.patches[p].normal) < 0) return kFront;
    return ps.two_sided(p) ? kBack : -1;
}

// The importance scene: the patches with each seen side emitting rho V (its own material),
// every other side its material, so that its radiosity solution is K = rho I.
PatchSet importance_patches(const PatchSet& patches, std::span<const double> shares) {
    PatchSet out;
    out.patches = patches.patches;
    out.vertices = patches.vertices;
    out.materials = patches.materials;
    out.back_materials = patches.back_materials;
    out.total_area = patches.total_area;
    for (PatchMaterial& m : out.materials) m.emission = Rgb::Zero();
    for (std::size_t p = 0; p < out.patches.size(); ++p) {
        for (std::uint8_t side : {kFront, kBack}) {
            const double share = shares[2 * p + side];
            if (share <= 0) continue;
            PatchMaterial m = patches.material(p, side);
            const double area = patches.patches[p].area;
            m.emission = m.reflectance * (share / area);
            m.specular = Rgb::Zero();
            const Rgb power = area * m.emission;
            out.emitted_power += power;
            out.max_emitted_power = std::max(out.max_emitted_power, power.maxCoeff());
            out.materials.push_back(m);
            const auto index = std::uint32_t(out.materials.size() - 1);
            if (side == kFront) {
                out.patches[p].material = index;
            } else {
                out.back_materials[p] = index;
            }
        }
    }
    return out;
}

}  // namespace

std::vector<double> view_pixel_shares(const PatchSet& patches, const EmbreeScene& scene,
                                      std::span<const View> views) {
    std::vector<double> shares(2 * patches.patches.size(), 0.0);
    for (const View& view : views) {
        const Camera camera = make_camera(view);
        const double weight = 1.0 / (double(camera.width) * camera.height * views.size());
        // Rows in batches of about kBatchPixels pixels: the rows of a batch in parallel, each
        // row's sides summed in order, then the rows in order (the same sums for any thread
        // count); a signal is heard between batches.
        const int rows = int(std::max<std::int64_t>(1, kBatchPixels / camera.width));
        std::vector<std::vector<std::uint32_t>> row_sides(
            std::size_t(std::min(rows, camera.height)));
        for (int first = 0; first < camera.height; first += rows) {
            throw_if_interrupted();
            const int end = std::min(camera.height, first + rows);
            tbb::parallel_for(first, end, [&](int y) {
                set_tracing_float_mode();
                auto& sides = row_sides[std::size_t(y - first)];
                sides.clear();
                for (int x = 0; x < camera.width; ++x) {
                    const Vec3 d = camera.direction(x + 0.5, y + 0.5);
                    const std::optional<Hit> hit = scene.first_hit(camera.origin, d);
                    if (!hit) continue;
                    const int side = side_met(patches, hit->patch, d);
                    if (side >= 0) sides.push_back(2 * hit->patch + std::uint32_t(side));
                }
            });
            for (int y = first; y < end; ++y) {
                for (const std::uint32_t s : row_sides[std::size_t(y - first)]) shares[s] += weight;
            }
        }
    }
    throw_if_interrupted();
    return shares;
}

ViewImportance solve_view_importance(const PatchSet& patches, const EmbreeScene& scene,
                                     std::span<const View> views, const SolverOptions& options,
                                     std::uint64_t rays, const Ranks& ranks) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<double> shares;
    try {
        shares = view_pixel_shares(patches, scene, views);
    } catch (const std::invalid_argument& e) {
        throw InputError(std::string("view importance: ") + e.what());
    }
    PatchSet adjoint = importance_patches(patches, shares);
    if (adjoint.max_emitted_power <= 0) {
        throw InputError("view importance: the views see no side that reflects light");
    }
    // The adjoint solve's own settings, from the radiance solve's.
    SolverOptions o = options;
    o.rays = rays;
    o.importance = Importance::none;
    o.control_variate = ControlVariate::none;
    o.refine_share = 1;
    o.uniform_max_area = patches.total_area;  // every patch one element
    o.seed = Rng(options.seed, kImportanceKey).next_u64();
    const Solution sol = solve(std::move(adjoint), o, {}, no_progress(), ranks);

    // K = rho I per side; the weights are K / mean I, the mean over the area that reflects
    // each channel (where rho is 0 the weight is 0 whatever I is).
    const Hierarchy& h = *sol.hierarchy;
    ViewImportance out;
    out.receiver_weights.assign(2 * h.patch_count(), Rgb::Zero());
    out.importance.assign(2 * h.patch_count(), Rgb::Zero());
    Rgb weighted = Rgb::Zero(), area = Rgb::Zero();
    for (std::size_t p = 0; p < h.patch_count(); ++p) {
        for (std::uint8_t side : {kFront, kBack}) {
            if (side == kBack && !patches.two_sided(p)) continue;
            const Element* root = h.made_root(p, side);
            const Rgb rho = patches.material(p, side).reflectance;
            const Rgb k = root ? root->radiosity : Rgb::Zero();
            const double a = patches.patches[p].area;
            for (int c = 0; c < 3; ++c) {
                if (rho[c] <= 0) continue;
                out.importance[2 * p + side][c] = k[c] / rho[c];
                weighted[c] += a * out.importance[2 * p + side][c];
                area[c] += a;
            }
            out.receiver_weights[2 * p + side] = k;
        }
    }
    Rgb mean = Rgb::Zero();
    for (int c = 0; c < 3; ++c) mean[c] = area[c] > 0 ? weighted[c] / area[c] : 0;
    for (Rgb& w : out.receiver_weights) {
        for (int c = 0; c < 3; ++c) w[c] = mean[c] > 0 ? w[c] / mean[c] : 0;
    }
    out.rays = sol.stats.rays;
    out.iterations = sol.stats.iterations.size();
    out.seconds = seconds_since(start);
    return out;
}

}  // namespace hmcr
