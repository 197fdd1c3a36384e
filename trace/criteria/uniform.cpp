// SPDX-License-Identifier: Apache-2.0
// uniform: every pixel gets exactly the target number of samples, in stratified batches of 8.
// No paper: no adaptivity, the baseline the adaptive criteria have to beat.
//
// The batches are 2 x 4 strata, as the adaptive criteria's first batch; the sampler of traced
// references.
#include <memory>

#include "trace/criteria/criterion.h"

namespace hmcr {
namespace {

class UniformCriterion final : public NamedCriterion {
public:
    UniformCriterion()
        : NamedCriterion("uniform", "the same number of samples in every pixel", Scheme::uniform) {}

    double value(std::span<const PixelSample>, double) const override { return 0; }
};

}  // namespace

std::unique_ptr<Criterion> make_uniform_criterion() { return std::make_unique<UniformCriterion>(); }

}  // namespace hmcr
