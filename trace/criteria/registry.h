// The list of pixel sampling criteria, by name (`hmcr trace --sampler NAME`).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "trace/criteria/criterion.h"

namespace hmcr {

// Every registered criterion, in the order `hmcr samplers` lists them.
const std::vector<const Criterion*>& all_criteria();
// The criterion called name, or none.
const Criterion* criterion_named(std::string_view name);
// The criterion called name; throws InputError naming the valid ones.
const Criterion& find_criterion(std::string_view name);
// "uniform, cc, ...": every name, for messages.
std::string criterion_names();

}  // namespace hmcr
