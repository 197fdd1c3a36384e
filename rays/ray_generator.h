// SPDX-License-Identifier: Apache-2.0
// Where the rays of a batch start (docs/design.md §3.1): a region of a patch (a parameter-space
// domain) picked by an alias table, a uniform point of the region and a cosine-distributed
// direction around the patch's normal. Generated in SIMD lanes (Highway, the widest vectors
// the machine has), in double precision with no fused multiply-adds, so that every vector
// width gives the same bits as one lane at a time (scalar_ray, the reference the tests hold the
// lanes to).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "rays/alias_table.h"
#include "rays/patch.h"
#include "rays/ray_strata.h"
#include "rays/sobol.h"

namespace hmcr {

// How a region's points are drawn: the patch's map from its domain to 3D.
enum class RegionMap : std::uint16_t { triangle, parallelogram, bilinear };
RegionMap region_map(const Patch& patch);

// One region rays start from (32 bytes, read by vector gathers): a domain of one side of a
// patch; rays from the back side leave around the reversed normal.
struct RayRegion {
    double u0 = 0, v0 = 0, s = 1;  // the domain (rays/domain.h)
    std::uint32_t patch = 0;
    RegionMap map = RegionMap::triangle;
    std::uint16_t side = 0;  // kFront or kBack (rays/patch.h)
};
static_assert(sizeof(RayRegion) == 32);

// The rays [first, first + n) of a batch, structure of arrays: origin and unit direction in the
// single precision Embree takes; the region each starts from and its parameter point there;
// and the ray's last uniform, which dithers the rounding of its power (docs/design.md §9.3).
struct GeneratedRays {
    std::vector<float> origin[3], direction[3];
    std::vector<std::uint32_t> region;
    std::vector<float> u, v;
    std::vector<double> dither;

    void resize(std::size_t n);
};

// One ray's draws, in this order from the stream keyed (seed, key, index) (rays/rng.h), or from
// that stream's scrambled Sobol sequence (rays/sobol.h): the region (one uniform for the alias
// table), the point (two), the direction (two), the dither. With the Sobol sequence the region
// is the one `strata` deals the ray to (rays/ray_strata.h) and its uniform goes unused.
struct RayStartSample {
    std::uint32_t region = 0;
    Vec2 uv{0, 0};
    Vec3 origin{0, 0, 0}, direction{0, 0, 1};
    double dither = 0;
};

// The same ray one lane at a time, with the arithmetic of the vector code: the reference.
RayStartSample scalar_ray(const std::vector<Patch>& patches, std::span<const RayRegion> regions,
                          const AliasTable& table, std::uint64_t seed, std::uint64_t key,
                          std::uint64_t index, RaySequence sequence, const RayStrata* strata);

// Fills out[offset, offset + n) with the rays first, first + 1, ... of the stream (seed, key).
// `table` picks among `regions` (at least one), whose patches are `patches`, each pseudo-random
// ray's; a Sobol ray starts from the region `strata` (over the regions, required) deals it to.
void generate_rays(const std::vector<Patch>& patches, std::span<const RayRegion> regions,
                   const AliasTable& table, std::uint64_t seed, std::uint64_t key,
                   std::uint64_t first, std::size_t n, GeneratedRays& out, std::size_t offset,
                   RaySequence sequence, const RayStrata* strata);

}  // namespace hmcr
