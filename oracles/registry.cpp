#include "oracles/registry.h"

#include <memory>
#include <stdexcept>
#include <string>

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

#define HMCR_DECLARE_ORACLE(name) std::unique_ptr<Oracle> make_##name##_oracle();
HMCR_ORACLES(HMCR_DECLARE_ORACLE)
#undef HMCR_DECLARE_ORACLE

namespace {

std::vector<std::unique_ptr<Oracle>> make_all() {
    std::vector<std::unique_ptr<Oracle>> list;
#define HMCR_MAKE_ORACLE(name) list.push_back(make_##name##_oracle());
    HMCR_ORACLES(HMCR_MAKE_ORACLE)
#undef HMCR_MAKE_ORACLE
    return list;
}

}  // namespace

const std::vector<const Oracle*>& all_oracles() {
    static const auto owned = make_all();
    static const auto view = [] {
        std::vector<const Oracle*> v;
        for (const auto& o : owned) v.push_back(o.get());
        return v;
    }();
    return view;
}

const Oracle* oracle_named(std::string_view name) {
    for (const Oracle* o : all_oracles()) {
        if (o->name() == name) return o;
    }
    return nullptr;
}

std::vector<std::string> oracle_name_list() {
    std::vector<std::string> names;
    for (const Oracle* o : all_oracles()) names.emplace_back(o->name());
    return names;
}

std::string oracle_names() {
    std::string names;
    for (const std::string& name : oracle_name_list()) names += (names.empty() ? "" : ", ") + name;
    return names;
}

const Oracle& find_oracle(std::string_view name) {
    if (const Oracle* o = oracle_named(name)) return *o;
    throw std::invalid_argument("unknown oracle '" + std::string(name) + "' (valid: " +
                                oracle_names() + ")");
}

}  // namespace hmcr
