// SPDX-License-Identifier: Apache-2.0
// The scaling study of `make bench`: kl on the generated office at 10^2 ... 10^6
// patches (2,684,000 rays), on the 10^6-patch office at 10^6 ... 10^8 rays, and on 1 and 2
// threads, each point in a fresh process (`hmcr_bench --row`) that reports its own peak memory.
// Prints a table and the growth rate of each curve, and writes the curves as plot data for
// scripts/plot_study.py.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace hmcr::bench {

// `self`: this program; `scenes`: the folder of the generated office instances (make bench);
// `plot_data`: the JSON to write.
std::vector<nlohmann::json> run_scaling_study(const std::string& self,
                                              const std::filesystem::path& scenes,
                                              const std::filesystem::path& plot_data);

}  // namespace hmcr::bench
