// SPDX-License-Identifier: Apache-2.0
#include "radiosity/oracle_registry.h"

namespace hmcr {

// The registered oracles, in `hmcr oracles` order: adding one is its file plus one line here.
// oracles/NAME.cpp defines make_NAME_oracle().
#define HMCR_ORACLES(X) \
    X(power)            \
    X(ks)               \
    X(mi)               \
    X(kl)               \
    X(cs)               \
    X(hl)               \
    X(vt)

#define HMCR_DECLARE(name) std::unique_ptr<Oracle> make_##name##_oracle();
HMCR_ORACLES(HMCR_DECLARE)
#undef HMCR_DECLARE

const Registry<Oracle>& oracle_registry() {
#define HMCR_MAKER(name) make_##name##_oracle,
    static const Registry<Oracle> registry("oracle", {HMCR_ORACLES(HMCR_MAKER)});
#undef HMCR_MAKER
    return registry;
}

}  // namespace hmcr
