// SPDX-License-Identifier: Apache-2.0
#include "common/hash.h"

#include <fmt/format.h>

namespace hmcr {

std::string Fnv1a::hex() const { return fmt::format("{:016x}", m_state); }

}  // namespace hmcr
