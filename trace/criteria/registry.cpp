// SPDX-License-Identifier: Apache-2.0
#include "trace/criteria/registry.h"

namespace hmcr {

// The registered criteria, in `hmcr samplers` order: adding one is its file plus one line
// here. trace/criteria/NAME.cpp defines make_NAME_criterion().
#define HMCR_CRITERIA(X) \
    X(uniform)           \
    X(cc)                \
    X(var)               \
    X(entropy)           \
    X(binary_entropy)    \
    X(kl)                \
    X(cs)                \
    X(he)                \
    X(srkl)              \
    X(srcs)              \
    X(srhe)              \
    X(half_difference)

#define HMCR_DECLARE(name) std::unique_ptr<Criterion> make_##name##_criterion();
HMCR_CRITERIA(HMCR_DECLARE)
#undef HMCR_DECLARE

const Registry<Criterion>& criterion_registry() {
#define HMCR_MAKER(name) make_##name##_criterion,
    static const Registry<Criterion> registry("sampler", {HMCR_CRITERIA(HMCR_MAKER)});
#undef HMCR_MAKER
    return registry;
}

const Criterion& uniform_criterion() { return *criterion_registry().find("uniform"); }

}  // namespace hmcr
