// The list of refinement oracles, by name.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "oracles/oracle.h"

namespace hmcr {

// Every registered oracle, in the order `hmcr oracles` lists them.
const std::vector<const Oracle*>& all_oracles();
// The oracle called name, or none.
const Oracle* oracle_named(std::string_view name);
// The oracle called name; throws std::invalid_argument naming the valid ones.
const Oracle& find_oracle(std::string_view name);
// Every name, in the same order.
std::vector<std::string> oracle_name_list();
// "power, ks, ...": every name, for messages.
std::string oracle_names();

}  // namespace hmcr
