// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: a point reference's points.vtp as `study` and `hmcr error` read it.
//
// Input: the bytes of a points.vtp. Whatever read_point_radiosity returns must be what the
// object error may use: a value and a variance per point and seed, each finite and not
// negative, patch ids below the patch count, sides 0 or 1, weights positive.
#include <cmath>
#include <cstdint>

#include "tests/fuzz/fuzz_support.h"
#include "viz/point_radiosity_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hmcr::fuzz;
    const auto file = write("points.vtp", std::string(reinterpret_cast<const char*>(data), size));
    expect_only_input_errors([&] {
        const hmcr::PointRadiosity r = hmcr::read_point_radiosity(file);
        const std::size_t n = r.points.size();
        for (int s = 0; s < 2; ++s) {
            if (r.radiosity[s].size() != n || r.variance[s].size() != n)
                crash("a value is missing");
            for (std::size_t i = 0; i < n; ++i) {
                if (!(r.radiosity[s][i] >= 0).all() || !r.radiosity[s][i].isFinite().all() ||
                    !(r.variance[s][i] >= 0).all() || !r.variance[s][i].isFinite().all()) {
                    crash("a radiosity or variance that is negative or not finite");
                }
            }
        }
        for (const hmcr::SurfacePoint& p : r.points) {
            if (p.patch >= r.patch_count || p.side > hmcr::kBack || !(p.weight > 0) ||
                !std::isfinite(p.weight)) {
                crash("a point out of range");
            }
        }
    });
    return 0;
}
