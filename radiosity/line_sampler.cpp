#include "radiosity/line_sampler.h"

#include <array>

#include "rays/element_sampler.h"
#include "rays/point_kernel.h"

namespace hmcr {

void sample_kernel(const EmbreeScene& scene, const Hierarchy& hierarchy, const Element& i,
                   const Element& j, Rng& rng, std::span<double> out) {
    const Patch& pi = hierarchy.patch(i);
    const Patch& pj = hierarchy.patch(j);
    const Vec3 ni = hierarchy.normal(i), nj = hierarchy.normal(j);
    const ElementSampler on_i(pi, i.domain), on_j(pj, j.domain);
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
            const Vec3 x = pi.point(on_i(xu, xv));
            const double yv = rng.uniform(), yu = rng.uniform();
            const Vec3 y = pj.point(on_j(yu, yv));
            out[first + k] = point_kernel(x, ni, y, nj);
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

}  // namespace hmcr
