// SPDX-License-Identifier: Apache-2.0
// Memory of this machine and of this process, for sizing defaults and refusing work that could
// not fit before it starts.
#pragma once

#include <cstdint>
#include <string>

namespace hmcr {

std::uint64_t physical_memory_bytes();  // installed RAM (0 if unknown)
std::uint64_t peak_memory_bytes();      // peak resident memory of this process so far (its own,
                                        // not its parent's: see memory.cpp)

// Gives the pages of freed heap memory back to the system. After loading a large scene, the
// allocator keeps the pages of the load's freed temporaries (100 MB at 10^6 patches), and the
// solve reuses only part of them.
void return_freed_memory();

// "1.5 GB": a byte count for messages.
std::string human_bytes(double bytes);

// Throws InputError "WHAT would need about X of memory; this machine has Y[: REMEDY]" when
// `bytes` is more than the machine can hold (three quarters of its RAM).
void require_memory(double bytes, const std::string& what, const std::string& remedy = "");

}  // namespace hmcr
