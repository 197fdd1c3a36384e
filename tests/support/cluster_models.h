// SPDX-License-Identifier: Apache-2.0
// The clustering models a clustered test runs under, as a value-parameterised suite's values and
// names: the isotropic and the oriented cluster (docs/design.md §2.7).
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "radiosity/solver_options.h"

namespace hmcr::test {

inline auto cluster_models() {
    return testing::Values(Clustering::isotropic, Clustering::oriented);
}

inline std::string cluster_model_name(const testing::TestParamInfo<Clustering>& p) {
    return std::string(name(p.param));
}

}  // namespace hmcr::test
