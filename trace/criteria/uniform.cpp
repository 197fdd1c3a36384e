// uniform: no adaptivity; every pixel gets exactly the target number of samples, in stratified
// batches of 8 (2 x 4). The baseline the adaptive criteria have to beat, and the sampler of
// traced references.
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
