// SPDX-License-Identifier: Apache-2.0
// Sorting many (key, value) records by an integer key in linear time: a stable least-
// significant-digit radix sort, 8 bits per pass, only over the bits the largest key uses.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <vector>

#include "common/populated.h"

namespace hmcr {

template <class Value>
struct Keyed {
    std::uint64_t key;
    Value value;
};

// Sorts `records` by key, equal keys in their input order; `scratch` is resized and reused.
template <class Value>
void radix_sort(std::vector<Keyed<Value>>& records, std::vector<Keyed<Value>>& scratch) {
    std::uint64_t max_key = 0;
    for (const auto& r : records) max_key = std::max(max_key, r.key);
    resize_populated(scratch, records.size());
    for (std::uint64_t shift = 0; shift < std::uint64_t(std::bit_width(max_key)); shift += 8) {
        std::array<std::size_t, 257> start{};
        for (const auto& r : records) ++start[((r.key >> shift) & 0xff) + 1];
        for (std::size_t d = 1; d < start.size(); ++d) start[d] += start[d - 1];
        for (const auto& r : records) scratch[start[(r.key >> shift) & 0xff]++] = r;
        records.swap(scratch);
    }
}

}  // namespace hmcr
