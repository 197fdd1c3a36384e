// SPDX-License-Identifier: Apache-2.0
#include "trace/pixel_tracer.h"

namespace hmcr {

TracedSample PixelTracer::sample(int x, int y, std::uint64_t key, const Stratum& stratum) const {
    Rng rng = stream(x, y, key);
    TracedSample out;
    out.u = stratum.u0 + stratum.du * rng.uniform();
    out.v = stratum.v0 + stratum.dv * rng.uniform();
    const CameraSample c =
        m_tracer.trace(m_camera.origin, m_camera.direction(x + out.u, y + out.v), rng);
    out.sample = {c.radiance, c.geometry};
    out.rays = c.rays;
    return out;
}

StoredSample store(const PixelSample& s) {
    return {{float(s.radiance[0]), float(s.radiance[1]), float(s.radiance[2])}, float(s.geometry)};
}

}  // namespace hmcr
