#include "oracles/registry.h"

#include <memory>
#include <stdexcept>
#include <string>

namespace hmcr {

std::unique_ptr<Oracle> make_power_oracle();
std::unique_ptr<Oracle> make_ks_oracle();
std::unique_ptr<Oracle> make_mi_oracle();
std::unique_ptr<Oracle> make_kl_oracle();
std::unique_ptr<Oracle> make_cs_oracle();
std::unique_ptr<Oracle> make_hl_oracle();
std::unique_ptr<Oracle> make_vt_oracle();

namespace {

std::vector<std::unique_ptr<Oracle>> make_all() {
    std::vector<std::unique_ptr<Oracle>> list;
    list.push_back(make_power_oracle());
    list.push_back(make_ks_oracle());
    list.push_back(make_mi_oracle());
    list.push_back(make_kl_oracle());
    list.push_back(make_cs_oracle());
    list.push_back(make_hl_oracle());
    list.push_back(make_vt_oracle());
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

const Oracle& find_oracle(std::string_view name) {
    std::string valid;
    for (const Oracle* o : all_oracles()) {
        if (o->name() == name) return *o;
        valid += (valid.empty() ? "" : ", ") + std::string(o->name());
    }
    throw std::invalid_argument("unknown oracle '" + std::string(name) + "' (valid: " + valid +
                                ")");
}

}  // namespace hmcr
