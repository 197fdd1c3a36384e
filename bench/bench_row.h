// SPDX-License-Identifier: Apache-2.0
// One benchmark row: a scene solved with one oracle, epsilon, ray count and thread count, its
// times, and the Embree floor of the same work measured right after it.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "radiosity/solver_options.h"

namespace hmcr::bench {

// Rays of the benchmark solves (the Cornell and cube-room rows, the scaling points).
inline constexpr std::uint64_t kBenchRays = 2'684'000;

struct RowSpec {
    std::string scene;  // a bundled name or a mesh/scene file
    std::string oracle;
    double epsilon;  // NaN: the oracle's default
    std::uint64_t rays;
    int threads;
    // 1: every ray refines (what the oracle rows bound); below 1, the solve users run: a
    // refining pass, then the frozen pass (docs/design.md §3.10).
    double refine_share = 1;
    RaySequence sequence = SolverOptions{}.sequence;  // the shooting rays' (design §3.2)
};

struct RowResult {
    RowSpec spec;
    std::size_t patches = 0, leaves = 0, elements = 0;
    std::uint64_t rays = 0, oracle_evaluations = 0, lines_cast = 0;
    double cache_hit_rate = 0, oracle_seconds = 0;
    double load_seconds = 0, setup_seconds = 0, shooting_seconds = 0, floor_seconds = 0;
    std::uint64_t solver_bytes = 0;  // hierarchy and link cache
    std::uint64_t peak_bytes = 0;    // this process's peak so far
    double floor_x() const { return shooting_seconds / floor_seconds; }
};

RowResult run_row(const RowSpec& spec);
nlohmann::json to_json(const RowResult& r);

// `hmcr_bench --row SCENE ORACLE EPSILON RAYS THREADS`: one row, its JSON on stdout.
int run_row_process(char** args);

}  // namespace hmcr::bench
