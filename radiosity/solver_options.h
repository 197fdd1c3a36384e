// Everything a solve can be told; the command line fills it.
#pragma once

#include <cstdint>
#include <limits>
#include <string>

namespace hmcr {

struct SolverOptions {
    std::string oracle = "kl";     // refinement oracle (`hmcr oracles` lists them)
    double epsilon = std::numeric_limits<double>::quiet_NaN();  // NaN: the oracle's default
    int lines = 10;                   // N_s, kernel lines per link for line-based oracles
    std::uint64_t rays = 2'684'000;   // shooting rays over the whole solve (within 2%)
    std::uint64_t seed = 1;           // keys every random stream
    int threads = 0;                  // 0: all cores
    double min_area = 1e-6;           // relative to A_T: elements at or below are not split
    int max_depth = 16;               // quadtree depth limit (at most 24)
    double stop = 0.01;               // stop when unshot power < stop * emitted power
    double uniform_max_area = 0;      // > 0: a fixed uniform mesh of elements <= this (m^2),
                                      // no oracle (converged references); 0: adaptive
    double cache_mb = 32;             // link cache size for line-based oracles (0: no cache)
};

}  // namespace hmcr
