#include "trace/criteria/registry.h"

#include <memory>

#include "common/error.h"

namespace hmcr {

// The registered criteria, in `hmcr samplers` order: adding one is its file plus one line here.
// viz/sampling/NAME.cpp defines make_NAME_criterion().
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
    X(srhe)

#define HMCR_DECLARE_CRITERION(name) std::unique_ptr<Criterion> make_##name##_criterion();
HMCR_CRITERIA(HMCR_DECLARE_CRITERION)
#undef HMCR_DECLARE_CRITERION

namespace {

std::vector<std::unique_ptr<Criterion>> make_all() {
    std::vector<std::unique_ptr<Criterion>> list;
#define HMCR_MAKE_CRITERION(name) list.push_back(make_##name##_criterion());
    HMCR_CRITERIA(HMCR_MAKE_CRITERION)
#undef HMCR_MAKE_CRITERION
    return list;
}

}  // namespace

const std::vector<const Criterion*>& all_criteria() {
    static const auto owned = make_all();
    static const auto view = [] {
        std::vector<const Criterion*> v;
        for (const auto& c : owned) v.push_back(c.get());
        return v;
    }();
    return view;
}

const Criterion* criterion_named(std::string_view name) {
    for (const Criterion* c : all_criteria()) {
        if (c->name() == name) return c;
    }
    return nullptr;
}

std::string criterion_names() {
    std::string names;
    for (const Criterion* c : all_criteria()) {
        names += (names.empty() ? "" : ", ") + std::string(c->name());
    }
    return names;
}

const Criterion& find_criterion(std::string_view name) {
    if (const Criterion* c = criterion_named(name)) return *c;
    throw InputError("unknown sampler " + quote(name) + " (valid: " + criterion_names() + ")");
}

}  // namespace hmcr
