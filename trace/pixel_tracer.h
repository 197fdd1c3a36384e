// SPDX-License-Identifier: Apache-2.0
// One camera sample of one pixel: a jittered point of a stratum of the pixel, its primary ray
// and the path tracer's estimate along it. Every sample draws from its own keyed stream
// Rng(seed, pixel index, sample key) (rays/rng.h), the jitter first and then the path, so a
// sample is the same whichever thread, order or threshold asks for it.
#pragma once

#include <cstdint>

#include "rays/camera.h"
#include "trace/criteria/criterion.h"
#include "trace/path_tracer.h"

namespace hmcr {

// A rectangle of a pixel, in pixel units relative to its top left corner.
struct Stratum {
    double u0 = 0, v0 = 0, du = 1, dv = 1;
};

// A sample as the pixel runs keep it: floats, 16 bytes (a 512 x 512 image at 60 samples per
// pixel keeps 15.7 million of them during the threshold search).
struct StoredSample {
    float radiance[3] = {0, 0, 0};
    float geometry = 0;

    PixelSample expand() const {
        return {Rgb(radiance[0], radiance[1], radiance[2]), double(geometry)};
    }
};

struct TracedSample {
    PixelSample sample;
    double u = 0, v = 0;     // where in the pixel, pixel units
    std::uint32_t rays = 0;  // Embree queries of its path
};

class PixelTracer {
public:
    PixelTracer(const PathTracer& tracer, const Camera& camera, std::uint64_t seed)
        : m_tracer(tracer), m_camera(camera), m_seed(seed) {}

    TracedSample sample(int x, int y, std::uint64_t key, const Stratum& stratum) const;
    // A stream of pixel (x, y) for what is not a sample (a batch's stratum order).
    Rng stream(int x, int y, std::uint64_t key) const { return Rng(m_seed, pixel_key(x, y), key); }
    int width() const { return m_camera.width; }
    int height() const { return m_camera.height; }

private:
    std::uint64_t pixel_key(int x, int y) const {
        return std::uint64_t(y) * std::uint64_t(m_camera.width) + std::uint64_t(x);
    }

    const PathTracer& m_tracer;
    const Camera& m_camera;
    std::uint64_t m_seed;
};

StoredSample store(const PixelSample& s);

}  // namespace hmcr
