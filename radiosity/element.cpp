// SPDX-License-Identifier: Apache-2.0
#include "radiosity/element.h"

namespace hmcr {

std::string ElementId::to_string() const {
    if (side == 2) return std::string(1, 'c').append(std::to_string(patch));  // a cluster (§2.7)
    std::string s = std::to_string(patch) + (side ? "b/" : "/");
    for (int level = depth - 1; level >= 0; --level) s += char('0' + ((path >> (2 * level)) & 3));
    return s;
}

}  // namespace hmcr
