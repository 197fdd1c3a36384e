// SPDX-License-Identifier: Apache-2.0
#include "information/channel_samples.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "common/error.h"
#include "common/interrupt.h"
#include "rays/point_kernel.h"

namespace hmcr {

LineMethod parse_line_method(const std::string& name) {
    if (name == "local") return LineMethod::local;
    if (name == "global") return LineMethod::global;
    throw InputError("unknown line method " + quote(name) + " (local or global)");
}

const char* line_method_name(LineMethod method) {
    return method == LineMethod::local ? "local" : "global";
}

ChannelSamples trace_lines(const PatchSet& patches, const EmbreeScene& scene,
                           const LineOptions& options, Progress& progress, const BackSides* backs) {
    return options.method == LineMethod::local
               ? trace_local_lines(patches, scene, options, progress, backs)
               : trace_global_lines(patches, scene, options, progress, backs);
}

void parallel_blocks(std::uint64_t blocks, Progress& progress,
                     const std::function<void(std::uint64_t)>& f) {
    constexpr std::uint64_t kRound = 256;  // blocks between two reports
    for (std::uint64_t first = 0; first < blocks; first += kRound) {
        const std::uint64_t last = std::min(blocks, first + kRound);
        tbb::parallel_for(first, last, [&](std::uint64_t block) { f(block); });
        progress.advance(double(last) / double(blocks));
        throw_if_interrupted();
    }
}

double log_kernel(const Patch& p, const Vec3& x, const Patch& q, const Vec3& y, double total_area) {
    const double f = point_kernel(x, p.normal, y, q.normal);
    return f > 0 ? std::log2(total_area * f) : std::nan("");
}

double log_kernel_along(const Patch& p, const Vec3& x, const Patch& q, const Vec3& d,
                        double total_area) {
    const double t = q.normal.dot(q.corner[0] - x) / q.normal.dot(d);
    return log_kernel(p, x, q, x + t * d, total_area);
}

void KernelTally::merge_into(ChannelSamples& out) const {
    out.log_kernel_sum.resize(sum.size(), 0.0);
    out.log_kernel_count.resize(count.size(), 0);
    for (std::size_t b = 0; b < sum.size(); ++b) {
        out.log_kernel_sum[b] += sum[b];
        out.log_kernel_count[b] += count[b];
    }
}

std::uint32_t batch_count(const LineOptions& options) {
    return std::max<std::uint32_t>(1, options.batches);
}

}  // namespace hmcr
